"""Contact sheet of every sign the procedural drawer knows: the official drawing beside a procedural one.

``python -m signmapper_core.simulate.artwork_sheet OUT.png [--size 80] [--seed 3]``
The sheet :data:`.face_artwork.OTHER_PICTOGRAM` was judged on: signs listed
there are labelled "other" in red.
"""

from __future__ import annotations

import argparse
import sys

import cv2
import numpy as np

from ..catalogue import load_catalogue
from .face_artwork import OTHER_PICTOGRAM, has_procedural, master_face, procedural_face
from .sheet_grid import tile_grid

PER_ROW = 6


def _on_grey(bgr: np.ndarray, alpha: np.ndarray) -> np.ndarray:
    a = alpha[..., None].astype(np.float32) / 255.0
    return (bgr * a + 200.0 * (1.0 - a)).astype(np.uint8)


def artwork_sheet(template_ids, size_px: int, rng: np.random.Generator) -> np.ndarray:
    """BGR sheet: per sign, a label, then its master face and a procedural face on grey."""
    tiles = []
    for tid in template_ids:
        pair = [_on_grey(*make(tid, (size_px, size_px), rng)) for make in (master_face, procedural_face)]
        tile = np.hstack(pair + [np.full((size_px, 4, 3), 255, np.uint8)])
        head = np.full((14, tile.shape[1], 3), 255, np.uint8)
        other = tid in OTHER_PICTOGRAM
        cv2.putText(head, tid + (" other" if other else ""), (2, 11), cv2.FONT_HERSHEY_SIMPLEX, 0.4,
                    (0, 0, 200) if other else (0, 0, 0), 1, cv2.LINE_AA)
        tiles.append(np.vstack([head, tile]))
    if not tiles:
        raise ValueError("no signs to draw")
    return tile_grid(tiles, PER_ROW, 255)


def main(argv=None) -> int:

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="PNG to write")
    parser.add_argument("--size", type=int, default=80, help="face size in pixels")
    parser.add_argument("--seed", type=int, default=3, help="seed of the procedural styles")
    args = parser.parse_args(argv)
    ids = [e.id for e in load_catalogue() if has_procedural(e.id)]
    sheet = artwork_sheet(ids, args.size, np.random.default_rng(args.seed))
    if not cv2.imwrite(args.out, sheet):
        raise SystemExit(f"{args.out}: could not write the PNG")
    print(f"{args.out}: {len(ids)} signs, {len(OTHER_PICTOGRAM)} marked as another pictogram")
    return 0


if __name__ == "__main__":
    sys.exit(main())
