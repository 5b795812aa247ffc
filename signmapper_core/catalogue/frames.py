"""Sign frames: outline, rim and background of each sign family, with a pen for the content.

Each frame builds a ``Drawing`` in face units (the face's bounding box is the
drawing's view) and calls ``content(pen)`` with a pen whose local [-1, 1] box
is the family's pictogram area.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from . import shapes
from .drawing import Drawing, FillEllipse, FillPoly, StrokeLine
from .pen import Pen
from .style import FaceStyle

Content = Callable[[Pen], None]
H_TRI = shapes.SQRT3_2


def _poly_drawing(sharp, radius, background: str) -> tuple[Drawing, np.ndarray]:
    outer = shapes.rounded_polygon(sharp, radius)
    d = Drawing(view=shapes.bbox(outer), outline=FillPoly(outer, "white"), background=background)
    return d, outer


def _content(d: Drawing, style: FaceStyle, content: Content | None, cx, cy, scale):
    if content is not None:
        pen = Pen(d, style)
        content(pen.sub(cx, cy, scale, jitter=False))


def triangle(style: FaceStyle, content: Content | None = None, down: bool = False,
             rim_colour: str = "red", fill: str = "white") -> Drawing:
    """Danger triangle (point up) or give-way triangle (point down) with rounded corners."""
    sharp = [(0, 0), (1, 0), (0.5, H_TRI)] if down else [(0.5, 0), (1, H_TRI), (0, H_TRI)]
    r0 = 0.035 * style.corner_scale
    rim = (0.115 if down else 0.095) * style.rim_scale
    d, outer = _poly_drawing(sharp, r0, rim_colour)
    d.ops.append(FillPoly(outer, rim_colour))
    d.ops.append(FillPoly(shapes.rounded_inset(sharp, r0, rim), fill))
    _content(d, style, content, 0.5, 0.30 if down else 0.59, 0.2)
    return d


def disc(style: FaceStyle, content: Content | None = None, fill: str = "white", rim_colour: str | None = "red",
         rim: float = 0.095, edge: str | None = None) -> Drawing:
    """Round sign: coloured rim (prohibitions) or a thin edge (mandatory, end signs)."""
    d = Drawing(view=(0.0, 0.0, 1.0, 1.0), outline=FillEllipse(0.5, 0.5, 0.5, 0.5, 0.0, "white"),
                background=rim_colour or edge or fill)
    if rim_colour is not None:
        d.ops.append(FillEllipse(0.5, 0.5, 0.5, 0.5, 0.0, rim_colour))
        r_in = 0.5 - rim * style.rim_scale
    else:
        d.ops.append(FillEllipse(0.5, 0.5, 0.5, 0.5, 0.0, edge or fill))
        r_in = 0.5 - (0.016 * style.rim_scale if edge else 0.0)
    d.ops.append(FillEllipse(0.5, 0.5, r_in, r_in, 0.0, fill))
    _content(d, style, content, 0.5, 0.5, 0.3)
    return d


def octagon(style: FaceStyle, content: Content | None = None) -> Drawing:
    """Stop octagon, flat top, with a thin white edge."""
    radius = 0.5 / math.cos(math.radians(22.5))
    sharp = shapes.regular_polygon(8, 0.5, 0.5, radius, 22.5)
    r0 = 0.035 * style.corner_scale
    d, outer = _poly_drawing(sharp, r0, "white")
    d.ops.append(FillPoly(outer, "white"))
    d.ops.append(FillPoly(shapes.rounded_inset(sharp, r0, 0.028 * style.rim_scale), "red"))
    _content(d, style, content, 0.5, 0.5, 0.36)
    return d


def diamond(style: FaceStyle, content: Content | None = None) -> Drawing:
    """Priority-road diamond: thin black edge, white border, yellow square."""
    sharp = [(0.5, 0), (1, 0.5), (0.5, 1), (0, 0.5)]
    r0 = 0.035 * style.corner_scale
    d, outer = _poly_drawing(sharp, r0, "black")
    d.ops.append(FillPoly(outer, "black"))
    d.ops.append(FillPoly(shapes.rounded_inset(sharp, r0, 0.009), "white"))
    d.ops.append(FillPoly(shapes.rounded_inset(sharp, r0, 0.085 * style.rim_scale), "yellow"))
    _content(d, style, content, 0.5, 0.5, 0.3)
    return d


def panel(style: FaceStyle, content: Content | None = None, aspect: float = 1.0, fill: str = "blue",
          edge: str = "white", content_box: tuple[float, float, float] | None = None) -> Drawing:
    """Square or upright rectangular panel (width 1, height 1/aspect) with a thin edge."""
    h = 1.0 / aspect
    sharp = [(0, 0), (1, 0), (1, h), (0, h)]
    r0 = 0.05 * style.corner_scale
    d, outer = _poly_drawing(sharp, r0, edge)
    d.ops.append(FillPoly(outer, edge))
    d.ops.append(FillPoly(shapes.rounded_inset(sharp, r0, 0.018 * style.rim_scale), fill))
    cx, cy, s = content_box if content_box is not None else (0.5, h / 2, 0.38)
    _content(d, style, content, cx, cy, s)
    return d


def diagonal_stripes(pen_drawing: Drawing, clip_outline, colour: str = "black", n: int = 5,
                     spacing: float = 0.045, width: float = 0.014, angle_deg: float = -45.0,
                     centre=(0.5, 0.5)):
    """Thin parallel stripes (end-of-restriction band) clipped to a convex outline."""

    a = math.radians(angle_deg)
    d = np.array([math.cos(a), math.sin(a)])
    nrm = np.array([-d[1], d[0]])
    c = np.asarray(centre, float)
    for k in range(n):
        off = (k - (n - 1) / 2) * spacing
        p0 = c + nrm * off - d * 2.0
        p1 = c + nrm * off + d * 2.0
        seg = shapes.clip_segment_to_convex(p0, p1, clip_outline)
        if seg is not None:
            pen_drawing.ops.append(StrokeLine(seg, width, colour))
