"""Contact sheet of generated sign faces in texture space, to check they stay readable.

``python -m signmapper_core.simulate.face_sheet OUT.png [--seed 0] [--count 24] [--columns 6] [--tile 200]``
Faces are drawn the way the generator draws them (random sign, format, artwork
and variations; same seed, same sheet), shown on grey with their id, artwork
and the variations applied. ``--only NAME`` switches all other variations off.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace

import cv2
import numpy as np

from .faces import FaceOptions, draw_sign_face, pick_format, sign_kinds
from .panels import face_shape
from .sheet_grid import write_sheet

VARIATIONS = ("face_print", "face_sheeting", "face_wear", "face_dirt", "face_marks", "face_dents")
FX = 1750.0


def sheet_faces(seed: int, count: int, options: FaceOptions, weathering: bool = True):
    """``count`` (template id, bgr, alpha, notes) drawn as the generator draws them."""
    kinds = sign_kinds()
    rng = np.random.default_rng([seed, 77])
    out = []
    for _ in range(count):
        kind = kinds[int(rng.integers(len(kinds)))]
        _name, w_m, h_m = pick_format(kind, rng)
        size_px = int(np.clip(FX * max(w_m, h_m) / 3.0, 48, 640))
        fh, fw = face_shape(size_px, w_m, h_m)
        face = draw_sign_face(kind.template_id, (fw, fh), w_m, rng, options, weathering, weathering)
        notes: list = []
        bgr, alpha = face.pixels(notes)
        out.append((kind.template_id, bgr, alpha, notes))
    return out


def tile_image(template_id: str, bgr: np.ndarray, alpha: np.ndarray, notes: list, tile: int) -> np.ndarray:
    """The face on grey, fitted into a tile, with two caption lines below."""
    caption_h = 48
    canvas = np.full((tile + caption_h, tile, 3), 128, np.uint8)
    h, w = bgr.shape[:2]
    scale = (tile - 8) / max(h, w)
    size = (max(1, round(w * scale)), max(1, round(h * scale)))
    small = cv2.resize(bgr, size, interpolation=cv2.INTER_AREA).astype(np.float32)
    a = cv2.resize(alpha, size, interpolation=cv2.INTER_AREA).astype(np.float32)[..., None] / 255.0
    y0, x0 = (tile - size[1]) // 2, (tile - size[0]) // 2
    region = canvas[y0:y0 + size[1], x0:x0 + size[0]].astype(np.float32)
    canvas[y0:y0 + size[1], x0:x0 + size[0]] = (small * a + region * (1 - a)).astype(np.uint8)
    lines = [f"{template_id} {notes[0] if notes else ''}", ""]
    for note in notes[1:]:
        if len(lines[-1]) + len(note) > tile // 6:
            lines.append("")
        lines[-1] += (", " if lines[-1] else "") + note
    for i, text in enumerate(lines[:3]):
        cv2.putText(canvas, text, (3, tile + 12 + 14 * i), cv2.FONT_HERSHEY_SIMPLEX, 0.34, (255, 255, 255), 1,
                    cv2.LINE_AA)
    return canvas


def face_sheet(out_png, seed: int = 0, count: int = 24, columns: int = 6, tile: int = 200,
               options: FaceOptions | None = None, weathering: bool = True) -> np.ndarray:
    faces = sheet_faces(seed, count, options or FaceOptions(), weathering)
    tiles = [tile_image(tid, bgr, alpha, notes, tile) for tid, bgr, alpha, notes in faces]
    return write_sheet(out_png, tiles, columns, 128)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m signmapper_core.simulate.face_sheet",
                                description="Draw generated sign faces (texture space) into one PNG.")
    p.add_argument("out", help="output PNG")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--count", type=int, default=24)
    p.add_argument("--columns", type=int, default=6)
    p.add_argument("--tile", type=int, default=200, help="tile size in pixels (default %(default)s)")
    p.add_argument("--artwork", choices=("mixed", "procedural"), default="mixed")
    p.add_argument("--master-share", type=float, default=FaceOptions().master_share)
    p.add_argument("--only", choices=[v.removeprefix("face_") for v in VARIATIONS],
                   help="show only this physical variation (and no older weathering)")
    args = p.parse_args(argv)
    options = FaceOptions(face_artwork=args.artwork, master_share=args.master_share)
    weathering = True
    if args.only:
        options = replace(options, **{v: v == f"face_{args.only}" for v in VARIATIONS})
        weathering = False
    face_sheet(args.out, args.seed, args.count, args.columns, args.tile, options, weathering)
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
