"""Build the plate templates (``templates/ch/plates/``) from the official drawings.

    python -m signmapper_core.catalogue.plate_build --svg DIR [--out templates/ch/plates]

Each drawing of :func:`plates_ch.plate_drawings` (every plate of Signalo's table)
is rendered with ``rsvg-convert`` (deterministic), cut to the plate's outline (its
alpha), set on white and reduced to ``MASTER_PX`` on its longer side;
``plates.json`` lists id, variant, kind, names, printed words, text field and
aspect of each. A layout plate's text field must hold its drawing's text and
cut no stroke of the fixed drawing (else the build stops, naming the plate).
Like ``make catalogue``, only the renderings enter the repository, not the
drawings.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import cv2
import numpy as np

from .model import DEFAULT_CATALOGUE_DIR
from .plates_ch import LAYOUT, plate_drawings
from .svg_render import render_svg

MASTER_PX = 256  # the longer side
INK_GREY = 128  # darker is print (text, pictogram, frame), for the text field's check
COLOUR_SATURATION = 60  # HSV saturation above which a pixel is coloured print (a blue P, a red disc) ...
COLOUR_MIN_SHARE = 0.005  # ... and a drawing with this share of such pixels is coloured
RENDER_ZOOM = 8.0
FORMAT = "signmapper-plates/1"
DEFAULT_OUT = DEFAULT_CATALOGUE_DIR / "plates"


def plate_master(svg_path: Path) -> np.ndarray:
    """BGR master of one plate drawing: cut to its outline, on white, MASTER_PX on its longer side."""
    bgra = render_svg(svg_path.read_bytes(), RENDER_ZOOM, str(svg_path))
    alpha = bgra[:, :, 3]
    ys, xs = np.nonzero(alpha > 127)
    if ys.size == 0:
        raise ValueError(f"{svg_path}: the drawing is empty")
    bgra = bgra[ys.min():ys.max() + 1, xs.min():xs.max() + 1]
    a = bgra[:, :, 3:4].astype(np.float32) / 255.0
    bgr = bgra[:, :, :3].astype(np.float32) * a + 255.0 * (1.0 - a)
    scale = MASTER_PX / max(bgr.shape[:2])
    size = (max(1, round(bgr.shape[1] * scale)), max(1, round(bgr.shape[0] * scale)))
    return cv2.resize(np.clip(bgr, 0, 255).astype(np.uint8), size, interpolation=cv2.INTER_AREA)


def field_pixels(shape, field) -> tuple:
    """(x0, y0, x1, y1) pixels of a text field (shares of the plate) in an image of ``shape``."""
    h, w = shape[:2]
    return (int(round(field[0] * w)), int(round(field[1] * h)), int(round(field[2] * w)), int(round(field[3] * h)))


def is_coloured(master: np.ndarray) -> bool:
    """Whether a plate's drawing prints in colour (5.10's red and blue, 5.17's blue pump), not only black."""
    saturation = cv2.cvtColor(master, cv2.COLOR_BGR2HSV)[:, :, 1]
    return bool((saturation > COLOUR_SATURATION).mean() >= COLOUR_MIN_SHARE)


def check_field(master: np.ndarray, field, name: str) -> None:
    """ValueError unless the text ``field`` of a layout plate's ``master`` holds print and every stroke of the
    drawing lies wholly inside or wholly outside it (the fixed drawing and the free text are apart)."""
    grey = cv2.cvtColor(master, cv2.COLOR_BGR2GRAY)
    count, labels = cv2.connectedComponents((grey < INK_GREY).astype(np.uint8), connectivity=8)
    x0, y0, x1, y1 = field_pixels(grey.shape, field)
    inside = np.zeros(grey.shape, bool)
    inside[y0:y1, x0:x1] = True
    within = np.bincount(labels[inside], minlength=count)
    total = np.bincount(labels.ravel(), minlength=count)
    cut = [k for k in range(1, count) if 0 < within[k] < total[k]]
    if cut:
        raise ValueError(f"{name}: its text field {field} cuts {len(cut)} strokes of the drawing")
    if not within[1:].any():
        raise ValueError(f"{name}: its text field {field} holds no print")


def build(svg_dir: Path, out: Path = DEFAULT_OUT) -> list:
    """Render every plate drawing of ``svg_dir`` into ``out``; returns the entries written."""
    svg_dir, out = Path(svg_dir), Path(out)
    (out / "png").mkdir(parents=True, exist_ok=True)
    for old in (out / "png").glob("*.png"):
        old.unlink()
    entries = []
    for plate in plate_drawings():
        path = svg_dir / plate.drawing
        if not path.is_file():
            raise FileNotFoundError(f"{path}: official drawing of plate {plate.id} ({plate.variant}) not found")
        master = plate_master(path)
        if plate.kind == LAYOUT:
            check_field(master, plate.field, f"plate {plate.id} ({plate.drawing})")
        name = f"{plate.id}_{plate.variant}.png"
        cv2.imwrite(str(out / "png" / name), master, [cv2.IMWRITE_PNG_COMPRESSION, 9])
        entry = {"id": plate.id, "variant": plate.variant, "kind": plate.kind, "names": plate.names,
                 "text": plate.words, "aspect": round(master.shape[1] / master.shape[0], 4), "png": f"png/{name}",
                 "artwork": f"ASTRA {plate.drawing}"}
        if plate.field:
            entry["field"] = list(plate.field)
        if is_coloured(master):
            entry["coloured"] = True
        entries.append(entry)
    (out / "plates.json").write_text(json.dumps({"format": FORMAT, "plates": entries}, ensure_ascii=False,
                                                indent=1) + "\n", encoding="utf-8")
    return entries


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--svg", type=Path, required=True, help="folder of the official drawings")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT)
    args = parser.parse_args(argv)
    entries = build(args.svg, args.out)
    print(f"{len(entries)} plate templates written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
