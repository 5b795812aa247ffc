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
    _set_lines(draw, lines, (2 * inset + 1, 2 * inset, width_px - 2 * inset - 1, height_px - 2 * inset))
    return np.ascontiguousarray(np.asarray(image)[:, :, ::-1])


def draw_in_field(bgr: np.ndarray, lines: Sequence[str], field: tuple, ink=INK) -> np.ndarray:
    """A copy of the plate ``bgr`` with its text field (x0, y0, x1, y1, shares of the plate) painted over with
    the paper's colour and ``lines`` set in it, centred, as large as fit (a layout plate's free text)."""
    from PIL import Image, ImageDraw

    h, w = bgr.shape[:2]
    x0, y0, x1, y1 = (int(round(f * n)) for f, n in zip(field, (w, h, w, h)))
    out = bgr.copy()
    paper = np.median(bgr.reshape(-1, 3), axis=0)  # the plate's paper: most of it
    out[y0:y1, x0:x1] = paper.astype(np.uint8)
    image = Image.fromarray(np.ascontiguousarray(out[:, :, ::-1]))
    _set_lines(ImageDraw.Draw(image), lines, (x0, y0, x1, y1), ink)
    return np.ascontiguousarray(np.asarray(image)[:, :, ::-1])


def _set_lines(draw, lines: Sequence[str], box: tuple, ink=INK) -> None:
    """Set ``lines`` of text centred in ``box`` (x0, y0, x1, y1 pixels) of a Pillow drawing, as large as fits."""
    x0, y0, x1, y1 = box
    lines = [t for t in lines if t] or [""]
    room_w, room_h = x1 - x0, (y1 - y0) / len(lines)
    size = max(6, int(room_h * 0.78))
    while size > 6:
        font = text_font(size)
        widest = max(draw.textlength(t, font=font) for t in lines)
        if widest <= room_w:
            break
        size -= 1
    font = text_font(size)
    for k, text in enumerate(lines):
        draw.text(((x0 + x1) / 2, y0 + room_h * (k + 0.5)), text, fill=tuple(ink[::-1]), font=font, anchor="mm")
