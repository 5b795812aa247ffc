"""White text panels as printed (SSV 4.29, 4.30, 4.33): black letters set in a real font on white sheeting.

The panel's size follows its wording, as on the road: the letters have the height the layout gives them
and the width their font gives them, plus margins, so the width in metres (clamped to the kind's range in
``catalogue.text_panels``) is known before any pixel is drawn and goes into the truth as it is. The face is
drawn at twice its pixel size and reduced, so the outline, frame and bar have smooth edges like the text.

Layouts (heights in metres):

* 4.29 place name: one line (cap height 30 % of the panel), or the name over a smaller canton line "(ZH)";
* 4.30 place ends: the name small on top, a black bar across the inner width, the next place and its
  distance ("Rüti 14 km") below, sometimes a second one;
* 4.33 direction panel: a pointer (one end pointed, left or right), one to three destinations set left.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Sequence, Tuple

import cv2
import numpy as np

from ..catalogue.text_panels import DIRECTION, PLACE_END, PLACE_NAME, TEXT_PANELS
from .plate_faces import INK, PAPER, text_font

SUPERSAMPLE = 2
FRAME_INSET = 0.025  # gap between the panel's edge and its frame, share of the panel height
FRAME_LINE = 0.018  # the frame's line width, share of the panel height
CORNER_RADIUS = 0.06  # rounded corners, share of the panel height
POINT_LENGTH = 0.6  # 4.33: length of the pointed end, share of the panel height
_REF_PX = 400  # font size the letters are measured at

# rows of each layout, by number of lines: (panel height, ((row, centre from the top, size), ...)), metres;
# a "text" row's size is its cap height, a "bar" row's its thickness
_LAYOUTS = {
    PLACE_NAME: {
        1: (0.42, (("text", 0.21, 0.126),)),
        2: (0.56, (("text", 0.215, 0.126), ("text", 0.415, 0.07))),
    },
    PLACE_END: {
        2: (0.60, (("text", 0.11, 0.06), ("bar", 0.235, 0.066), ("text", 0.42, 0.08))),
        3: (0.76, (("text", 0.11, 0.06), ("bar", 0.24, 0.08), ("text", 0.42, 0.08), ("text", 0.58, 0.08))),
    },
    DIRECTION: {
        n: (0.215 + 0.14 * (n - 1), tuple(("text", 0.1075 + 0.14 * k, 0.075) for k in range(n)))
        for n in (1, 2, 3)
    },
}


@dataclass(frozen=True)
class Row:
    """One row of a panel: a line of text (``size_m`` its cap height) or the black bar (its thickness)."""

    what: str  # "text" or "bar"
    y_m: float  # centre, from the panel's top edge
    size_m: float
    text: str = ""


@dataclass(frozen=True)
class PanelPlan:
    """Everything about a panel's face but its pixels: size in metres, rows, alignment and pointer."""

    kind_id: str
    width_m: float
    height_m: float
    rows: Tuple[Row, ...]
    point: str  # "left" or "right" for a pointer (4.33), "" for a rectangle
    point_m: float  # length of the pointed end
    margin_m: float  # between the panel's edge (or the pointer's base) and the text on its set side

    @property
    def lines(self) -> Tuple[str, ...]:
        return tuple(r.text for r in self.rows if r.what == "text")

    def size_px(self, px_per_m: float) -> Tuple[int, int]:
        """(width, height) in pixels of the face at ``px_per_m``."""
        return max(8, int(round(self.width_m * px_per_m))), max(8, int(round(self.height_m * px_per_m)))


@lru_cache(maxsize=1)
def _cap_per_em() -> float:
    """Cap height of the font as a share of its size (the em): sets letters by their cap height."""
    top = text_font(_REF_PX).getbbox("H", anchor="ls")[1]
    return -top / _REF_PX


def text_width_m(text: str, cap_m: float) -> float:
    """Width of ``text`` set with a cap height of ``cap_m`` metres."""
    return text_font(_REF_PX).getlength(text) / _REF_PX * cap_m / _cap_per_em()


def plan_panel(kind_id: str, lines: Sequence[str], point: str = "right") -> PanelPlan:
    """The panel of kind ``kind_id`` carrying ``lines`` (``point``: 4.33's pointed side, else ignored).

    The width is the longest line plus margins (and the pointer), clamped to the kind's range; where the
    text is too long for the largest panel, all its letters are set smaller.
    """
    kind = TEXT_PANELS[kind_id]
    lines = [str(t) for t in lines]
    layouts = _LAYOUTS[kind.layout]
    if len(lines) not in layouts:
        raise ValueError(f"a {kind_id} panel has {' or '.join(map(str, sorted(layouts)))} lines, not {len(lines)}")
    height_m, spec = layouts[len(lines)]
    texts = iter(lines)
    rows = [Row(what, y, size, next(texts) if what == "text" else "") for what, y, size in spec]
    frame_m = (FRAME_INSET + FRAME_LINE) * height_m
    caps = [r.size_m for r in rows if r.what == "text"]
    margin_m = frame_m + 0.6 * max(caps)
    pointer = kind.layout == DIRECTION
    if pointer and point not in ("left", "right"):
        raise ValueError(f"a {kind_id} panel points 'left' or 'right', not {point!r}")
    point_m = POINT_LENGTH * height_m if pointer else 0.0
    text_m = max(text_width_m(r.text, r.size_m) for r in rows if r.what == "text")
    need_m = text_m + 2 * margin_m + point_m
    (w_lo, _), (w_hi, _) = kind.smallest, kind.largest
    width_m = float(np.clip(need_m, w_lo, w_hi))
    if need_m > w_hi:  # set the letters smaller, the rows where they were
        scale = 0.97 * (w_hi - 2 * margin_m - point_m) / text_m
        rows = [Row(r.what, r.y_m, r.size_m * scale, r.text) if r.what == "text" else r for r in rows]
    return PanelPlan(kind_id, width_m, float(height_m), tuple(rows), point if pointer else "", point_m, margin_m)


def _outline(w: int, h: int, plan: PanelPlan, k: float) -> np.ndarray:
    """uint8 mask (h, w) of the panel's outline: a rounded rectangle, or a pointer with rounded blunt end."""
    from PIL import Image, ImageDraw

    image = Image.new("L", (w, h), 0)
    draw = ImageDraw.Draw(image)
    radius = max(1, int(round(CORNER_RADIUS * plan.height_m * k)))
    if not plan.point:
        draw.rounded_rectangle([0, 0, w - 1, h - 1], radius=radius, fill=255)
        return np.asarray(image).copy()
    base = w - 1 - int(round(plan.point_m * k))  # drawn pointing right, mirrored for left
    draw.rounded_rectangle([0, 0, base, h - 1], radius=radius, fill=255)
    draw.rectangle([base // 2, 0, base, h - 1], fill=255)  # no rounding where the point begins
    draw.polygon([(base, 0), (w - 1, (h - 1) / 2.0), (base, h - 1)], fill=255)
    mask = np.asarray(image).copy()
    return mask[:, ::-1].copy() if plan.point == "left" else mask


def _frame(mask: np.ndarray, plan: PanelPlan, k: float) -> np.ndarray:
    """Bool mask of the thin frame: a band at a fixed distance inside the outline, following its shape."""
    pad = 4
    inside = np.pad((mask > 127).astype(np.uint8), pad)
    dist = cv2.distanceTransform(inside, cv2.DIST_L2, 5)[pad:-pad, pad:-pad]
    inset, line = FRAME_INSET * plan.height_m * k, FRAME_LINE * plan.height_m * k
    return (dist > inset) & (dist <= inset + line)


def draw_text_panel(plan: PanelPlan, px_per_m: float) -> Tuple[np.ndarray, np.ndarray]:
    """(bgr uint8, alpha uint8) of the clean face of ``plan`` at ``px_per_m`` (size: ``plan.size_px``)."""
    from PIL import Image, ImageDraw

    w_px, h_px = plan.size_px(px_per_m)
    w, h = w_px * SUPERSAMPLE, h_px * SUPERSAMPLE
    kx, ky = w / plan.width_m, h / plan.height_m
    mask = _outline(w, h, plan, ky)
    bgr = np.empty((h, w, 3), np.uint8)
    bgr[:] = PAPER
    bgr[_frame(mask, plan, ky)] = INK
    inner = (FRAME_INSET + FRAME_LINE) * plan.height_m * kx
    blunt = plan.point_m * kx if plan.point == "left" else 0.0  # x where the rectangular part begins
    for row in plan.rows:
        if row.what == "bar":
            y0, y1 = int(round((row.y_m - row.size_m / 2) * ky)), int(round((row.y_m + row.size_m / 2) * ky))
            bgr[y0:y1, int(inner):int(np.ceil(w - inner))] = INK
    image = Image.fromarray(np.ascontiguousarray(bgr[:, :, ::-1]))
    draw = ImageDraw.Draw(image)
    for row in plan.rows:
        if row.what != "text":
            continue
        font = text_font(max(6, int(round(row.size_m * ky / _cap_per_em()))))
        baseline = (row.y_m + row.size_m / 2) * ky
        if plan.point:
            draw.text((blunt + plan.margin_m * kx, baseline), row.text, fill=INK[::-1], font=font, anchor="ls")
        else:
            draw.text((w / 2, baseline), row.text, fill=INK[::-1], font=font, anchor="ms")
    big = np.asarray(image)[:, :, ::-1]
    bgr = cv2.resize(big, (w_px, h_px), interpolation=cv2.INTER_AREA)
    alpha = cv2.resize(mask, (w_px, h_px), interpolation=cv2.INTER_AREA)
    return np.ascontiguousarray(bgr), np.ascontiguousarray(alpha)


def text_panel_face(kind_id: str, lines: Sequence[str], px_per_m: float, point: str = "right"
                    ) -> Tuple[np.ndarray, np.ndarray]:
    """(bgr, alpha) of a clean ``kind_id`` panel carrying ``lines``: :func:`plan_panel`, then drawn."""
    return draw_text_panel(plan_panel(kind_id, lines, point), px_per_m)
