"""A pen that places pictogram primitives into a drawing through an affine frame.

Pictograms are written in a local frame of roughly [-1, 1] x [-1, 1] (y down);
sign frames hand out sub-pens for the content area. With a style's
``detail_jitter`` every sub-pen is shifted and scaled a little at random.
"""

from __future__ import annotations

import math

import numpy as np

from . import shapes
from .drawing import Drawing, FillEllipse, FillPoly, StrokeEllipse, StrokeLine, Text
from .style import FaceStyle


class Pen:
    def __init__(self, drawing: Drawing, style: FaceStyle, matrix: np.ndarray | None = None,
                 rng: np.random.Generator | None = None):
        self.drawing = drawing
        self.style = style
        self.m = np.array([[1.0, 0, 0], [0, 1.0, 0]]) if matrix is None else matrix
        self.rng = rng if rng is not None else np.random.default_rng(style.seed)

    # ------------------------------------------------------------------ frames
    @property
    def scale(self) -> float:
        return math.sqrt(abs(np.linalg.det(self.m[:, :2])))

    @property
    def mirrored(self) -> bool:
        return np.linalg.det(self.m[:, :2]) < 0

    @property
    def rotation(self) -> float:
        return math.degrees(math.atan2(self.m[1, 0], self.m[0, 0]))

    def sub(self, dx: float = 0.0, dy: float = 0.0, scale: float = 1.0, mirror: bool = False,
            angle: float = 0.0, jitter: bool = True) -> Pen:
        """A pen for a part placed at (dx, dy) with ``scale``, optionally mirrored left-right."""
        j = self.style.detail_jitter if jitter else 0.0
        if j > 0:
            dx += self.rng.uniform(-0.06, 0.06) * j * scale
            dy += self.rng.uniform(-0.06, 0.06) * j * scale
            scale *= 1.0 + self.rng.uniform(-0.07, 0.05) * j
            angle += self.rng.uniform(-3.0, 3.0) * j
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        mx = -1.0 if mirror else 1.0
        local = np.array([[c * scale * mx, -s * scale, dx], [s * scale * mx, c * scale, dy], [0, 0, 1.0]])
        m3 = np.vstack([self.m, [0, 0, 1.0]]) @ local
        return Pen(self.drawing, self.style, m3[:2], self.rng)

    def tf(self, points) -> np.ndarray:
        p = shapes.as_points(points)
        return p @ self.m[:, :2].T + self.m[:, 2]

    def _angle(self, a: float) -> float:
        return self.rotation + (-a if self.mirrored else a)

    # ------------------------------------------------------------------ primitives
    def poly(self, points, colour: str, radius: float = 0.0):
        pts = shapes.rounded_polygon(points, radius, 6) if radius > 0 else shapes.as_points(points)
        self.drawing.ops.append(FillPoly(self.tf(pts), colour))

    def rect(self, x0, y0, x1, y1, colour: str, radius: float = 0.0):
        self.poly([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], colour, radius)

    def circle(self, cx, cy, r, colour: str):
        (x, y), = self.tf([(cx, cy)])
        self.drawing.ops.append(FillEllipse(x, y, r * self.scale, r * self.scale, 0.0, colour))

    def ellipse(self, cx, cy, rx, ry, colour: str, angle: float = 0.0):
        (x, y), = self.tf([(cx, cy)])
        s = self.scale
        self.drawing.ops.append(FillEllipse(x, y, rx * s, ry * s, self._angle(angle), colour))

    def ring(self, cx, cy, r, width, colour: str):
        (x, y), = self.tf([(cx, cy)])
        s = self.scale
        w = width * s * self.style.stroke_scale
        self.drawing.ops.append(StrokeEllipse(x, y, r * s, r * s, 0.0, w, colour))

    def line(self, points, width: float, colour: str, closed: bool = False, scaled: bool = True):
        w = width * self.scale * (self.style.stroke_scale if scaled else 1.0)
        self.drawing.ops.append(StrokeLine(self.tf(points), w, colour, closed))

    def text(self, text: str, cx: float, cy: float, height: float, colour: str, max_width: float | None = None):
        (x, y), = self.tf([(cx, cy)])
        s = self.scale
        mw = None if max_width is None else max_width * s
        self.drawing.ops.append(Text(text, x, y, height * s * self.style.text_scale, colour, self.style.font,
                                     self.style.text_weight, mw))

    def arrow(self, points, width: float, colour: str, head_length: float | None = None,
              head_width: float | None = None):
        """A stroked shaft along ``points`` ending in a filled triangular head at the last point."""
        p = shapes.as_points(points)
        width_eff = width * self.style.stroke_scale
        hl = head_length if head_length is not None else width_eff * 1.6
        hw = head_width if head_width is not None else width_eff * 1.45
        tip = p[-1]
        # the head follows the chord over its own length, so heads on curved shafts stay aligned
        seg = np.linalg.norm(np.diff(p, axis=0), axis=1)
        from_tip = np.concatenate([np.cumsum(seg[::-1])[::-1], [0.0]])
        k = int(np.searchsorted(-from_tip, -hl)) if from_tip[0] > hl else 1
        k = min(max(k, 1), len(p) - 1)
        t = (from_tip[k - 1] - hl) / max(from_tip[k - 1] - from_tip[k], 1e-12)
        back = p[k - 1] + (p[k] - p[k - 1]) * min(max(t, 0.0), 1.0) if from_tip[0] > hl else p[0]
        d = tip - back
        d = d / np.linalg.norm(d)
        n = np.array([-d[1], d[0]])
        base = tip - d * hl
        keep = p[from_tip > hl * 1.05]
        end = base + d * 0.05 * hl
        shaft = np.vstack([keep, end]) if len(keep) else np.array([p[0], end])
        self.line(shaft, width, colour)
        self.poly([tip, base + n * hw, base - n * hw], colour)

    @property
    def detailed(self) -> bool:
        return not self.style.simplify
