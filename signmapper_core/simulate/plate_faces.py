"""Supplementary plates as printed: white, a thin black border, black text set in a real TrueType font.

The text is set with Pillow in DejaVu Sans (Debian's ``fonts-dejavu-core``), not
with the catalogue's own pictogram drawer: OCR is measured on letters shaped by a
font designer, as on a real plate (Swiss plates use a similar grotesque).
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Sequence

import numpy as np

FONT_FOLDERS = ("/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/TTF", "/usr/share/fonts/dejavu")
FONT_FILES = ("DejaVuSans-Bold.ttf", "DejaVuSansCondensed-Bold.ttf", "DejaVuSans.ttf")
INK = (25, 25, 25)
PAPER = (238, 240, 240)


class PlateFontMissing(RuntimeError):
    """No TrueType font to set plate texts in."""


@lru_cache(maxsize=1)
def font_path() -> Path:
    """The TrueType font plate texts are set in; :class:`PlateFontMissing` names the package when absent."""
    for folder in FONT_FOLDERS:
        for name in FONT_FILES:
            path = Path(folder) / name
            if path.is_file():
                return path
    raise PlateFontMissing(f"no DejaVu Sans font in {', '.join(FONT_FOLDERS)}: "
                           "on Debian: sudo apt-get install fonts-dejavu-core")


@lru_cache(maxsize=64)
def text_font(size: int):
    """The plate font (:func:`font_path`) at ``size`` pixels per em, for plates and the other text faces."""
    from PIL import ImageFont

    return ImageFont.truetype(str(font_path()), size)


def draw_plate(lines: Sequence[str], width_px: int, height_px: int, border: bool = True) -> np.ndarray:
    """BGR uint8 (height_px, width_px) of a white plate with ``lines`` of black text, centred, as large as fits."""
    from PIL import Image, ImageDraw

    image = Image.new("RGB", (width_px, height_px), PAPER[::-1])
    draw = ImageDraw.Draw(image)
    inset = max(1, round(0.05 * min(width_px, height_px)))
    if border:
        line = max(1, round(0.025 * min(width_px, height_px)))
        draw.rectangle([inset, inset, width_px - 1 - inset, height_px - 1 - inset], outline=INK[::-1], width=line)
    lines = [t for t in lines if t] or [""]
    room_w, room_h = width_px - 4 * inset - 2, (height_px - 4 * inset) / len(lines)
    size = max(6, int(room_h * 0.78))
    while size > 6:
        font = text_font(size)
        widest = max(draw.textlength(t, font=font) for t in lines)
        if widest <= room_w:
            break
        size -= 1
    font = text_font(size)
    top = (height_px - room_h * len(lines)) / 2
    for k, text in enumerate(lines):
        cy = top + room_h * (k + 0.5)
        draw.text((width_px / 2, cy), text, fill=INK[::-1], font=font, anchor="mm")
    return np.ascontiguousarray(np.asarray(image)[:, :, ::-1])
