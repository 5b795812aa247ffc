"""Build the pictogram plate templates (``templates/ch/plates/``) from the official drawings.

    python -m signmapper_core.catalogue.plate_build --svg DIR [--out templates/ch/plates]

Each drawing of :data:`plates_ch.PICTOGRAM_PLATES` is rendered with
``rsvg-convert`` (deterministic), cut to the plate's outline (its alpha), set on
white and reduced to ``MASTER_WIDTH_PX`` wide; ``plates.json`` lists id,
variant, names, printed words and aspect of each. Like ``make catalogue``, only
the renderings enter the repository, not the drawings.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import cv2
import numpy as np

from .model import DEFAULT_CATALOGUE_DIR
from .plates_ch import PICTOGRAM_PLATES
from .svg_render import render_svg

MASTER_WIDTH_PX = 256
RENDER_ZOOM = 8.0
FORMAT = "signmapper-plates/1"
DEFAULT_OUT = DEFAULT_CATALOGUE_DIR / "plates"


def plate_master(svg_path: Path) -> np.ndarray:
    """BGR master of one plate drawing: cut to its outline, on white, MASTER_WIDTH_PX wide."""
    bgra = render_svg(svg_path.read_bytes(), RENDER_ZOOM, str(svg_path))
    alpha = bgra[:, :, 3]
    ys, xs = np.nonzero(alpha > 127)
    if ys.size == 0:
        raise ValueError(f"{svg_path}: the drawing is empty")
    bgra = bgra[ys.min():ys.max() + 1, xs.min():xs.max() + 1]
    a = bgra[:, :, 3:4].astype(np.float32) / 255.0
    bgr = bgra[:, :, :3].astype(np.float32) * a + 255.0 * (1.0 - a)
    height = max(1, round(MASTER_WIDTH_PX * bgr.shape[0] / bgr.shape[1]))
    return cv2.resize(np.clip(bgr, 0, 255).astype(np.uint8), (MASTER_WIDTH_PX, height), interpolation=cv2.INTER_AREA)


def build(svg_dir: Path, out: Path = DEFAULT_OUT) -> list:
    """Render every pictogram plate drawing of ``svg_dir`` into ``out``; returns the entries written."""
    svg_dir, out = Path(svg_dir), Path(out)
    (out / "png").mkdir(parents=True, exist_ok=True)
    entries = []
    for plate in PICTOGRAM_PLATES:
        for variant, (drawing, words) in plate.drawings.items():
            path = svg_dir / drawing
            if not path.is_file():
                raise FileNotFoundError(f"{path}: official drawing of plate {plate.id} ({variant}) not found")
            master = plate_master(path)
            name = f"{plate.id}_{variant}.png"
            cv2.imwrite(str(out / "png" / name), master, [cv2.IMWRITE_PNG_COMPRESSION, 9])
            entries.append({"id": plate.id, "variant": variant, "names": plate.names, "text": words,
                            "aspect": round(master.shape[1] / master.shape[0], 4), "png": f"png/{name}",
                            "artwork": f"ASTRA {drawing}"})
    (out / "plates.json").write_text(json.dumps({"format": FORMAT, "plates": entries}, ensure_ascii=False,
                                                indent=1) + "\n", encoding="utf-8")
    return entries


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--svg", type=Path, required=True, help="folder of the official drawings")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT)
    args = parser.parse_args(argv)
    entries = build(args.svg, args.out)
    print(f"{len(entries)} pictogram plate templates written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
