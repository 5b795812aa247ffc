"""Contact sheet of a catalogue: every template on a grid with its id underneath.

``python -m signmapper_core.catalogue.sheet OUT.png [--catalogue DIR] [--cell PX] [--columns N]``
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import cv2
import numpy as np

from .model import Catalogue, load_catalogue


def contact_sheet(catalogue: Catalogue, cell: int = 96, columns: int = 12) -> np.ndarray:
    """A BGR image of all templates composited on light grey, id text under each."""
    entries = list(catalogue)
    rows = max(1, math.ceil(len(entries) / columns))
    label_h = max(14, cell // 5)
    pad = max(4, cell // 12)
    cw, ch = cell + 2 * pad, cell + label_h + 2 * pad
    sheet = np.full((rows * ch, columns * cw, 3), 235, np.uint8)
    font = cv2.FONT_HERSHEY_SIMPLEX
    for i, entry in enumerate(entries):
        r, c = divmod(i, columns)
        x0, y0 = c * cw + pad, r * ch + pad
        bgr, alpha = catalogue.render(entry.id, cell)
        h, w = alpha.shape
        ox, oy = x0 + (cell - w) // 2, y0 + (cell - h) // 2
        a = alpha[..., None].astype(np.float32) / 255.0
        roi = sheet[oy:oy + h, ox:ox + w].astype(np.float32)
        sheet[oy:oy + h, ox:ox + w] = np.round(bgr * a + roi * (1 - a)).astype(np.uint8)
        scale = label_h / 30.0
        (tw, th), _ = cv2.getTextSize(entry.id, font, scale, 1)
        tx = x0 + (cell - tw) // 2
        ty = y0 + cell + (label_h + th) // 2
        cv2.putText(sheet, entry.id, (tx, ty), font, scale, (30, 30, 30), 1, cv2.LINE_AA)
    return sheet


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="output PNG")
    parser.add_argument("--catalogue", default=None, help="catalogue folder (default: bundled Swiss)")
    parser.add_argument("--cell", type=int, default=96)
    parser.add_argument("--columns", type=int, default=12)
    args = parser.parse_args(argv)
    sheet = contact_sheet(load_catalogue(args.catalogue), args.cell, args.columns)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    cv2.imwrite(str(out), sheet, [cv2.IMWRITE_PNG_COMPRESSION, 9])
    print(f"wrote {out} ({sheet.shape[1]}x{sheet.shape[0]})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
