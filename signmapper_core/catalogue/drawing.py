"""A tiny vector drawing model rendered both to anti-aliased rasters and to SVG.

Signs are described once as a list of drawing operations in face units (y down);
``rasterize`` supersamples them with OpenCV and reduces with INTER_AREA, and
``to_svg`` writes the same operations as SVG elements, so map markers and
matching templates come from one description.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import cv2
import numpy as np

from . import shapes
from .style import PALETTE_RGB, FaceStyle

HERSHEY = {
    "simplex": cv2.FONT_HERSHEY_SIMPLEX,
    "duplex": cv2.FONT_HERSHEY_DUPLEX,
    "triplex": cv2.FONT_HERSHEY_TRIPLEX,
    "complex": cv2.FONT_HERSHEY_COMPLEX,
}
SHIFT = 4  # OpenCV fixed-point bits for sub-pixel vertices
ONE = 1 << SHIFT


@dataclass
class FillPoly:
    points: np.ndarray
    colour: str


@dataclass
class FillEllipse:
    cx: float
    cy: float
    rx: float
    ry: float
    angle: float
    colour: str


@dataclass
class StrokeEllipse:
    cx: float
    cy: float
    rx: float
    ry: float
    angle: float
    width: float
    colour: str


@dataclass
class StrokeLine:
    points: np.ndarray
    width: float
    colour: str
    closed: bool = False


@dataclass
class Text:
    text: str
    cx: float
    cy: float
    height: float  # cap height in face units
    colour: str
    font: str = "simplex"
    weight: float = 1.0
    max_width: float | None = None


@dataclass
class Drawing:
    """Operations in face units; ``view`` is the face bounding box, ``outline`` the sign's silhouette."""

    view: tuple[float, float, float, float]
    outline: FillPoly | FillEllipse
    background: str
    ops: list = field(default_factory=list)

    @property
    def aspect(self) -> float:
        x0, y0, x1, y1 = self.view
        return (x1 - x0) / (y1 - y0)


# --------------------------------------------------------------------------- text metrics


def _text_params(op: Text, px_per_unit: float):
    """Font scale, thickness and pixel size of a text op at a given resolution."""
    font = HERSHEY.get(op.font, cv2.FONT_HERSHEY_SIMPLEX)
    height_px = max(op.height * px_per_unit, 1.0)
    thickness = max(1, int(round(op.weight * 0.16 * height_px)))
    (_, h1), _ = cv2.getTextSize(op.text, font, 1.0, 1)
    scale = max((height_px - thickness * 0.5) / max(h1, 1), 0.05)
    (tw, _), _ = cv2.getTextSize(op.text, font, scale, thickness)
    tw += thickness
    if op.max_width is not None and tw > op.max_width * px_per_unit:
        factor = op.max_width * px_per_unit / tw
        scale *= factor
        thickness = max(1, int(round(thickness * math.sqrt(factor))))
        (tw, _), _ = cv2.getTextSize(op.text, font, scale, thickness)
        tw += thickness
    return font, scale, thickness, tw, h1 * scale


def text_width(op: Text) -> float:
    """Width of a text op in face units, measured with the Hershey font at a fine resolution."""
    px = 400.0 / max(op.height, 1e-6)
    return _text_params(op, px)[3] / px


# --------------------------------------------------------------------------- raster


class _Transform:
    def __init__(self, view, w, h):
        x0, y0, x1, y1 = view
        self.x0, self.y0 = x0, y0
        self.sx, self.sy = w / (x1 - x0), h / (y1 - y0)
        self.s = math.sqrt(self.sx * self.sy)

    def pts(self, points) -> np.ndarray:
        p = shapes.as_points(points)
        x = (p[:, 0] - self.x0) * self.sx
        y = (p[:, 1] - self.y0) * self.sy
        return np.round(np.stack([x, y], axis=1) * ONE).astype(np.int32)

    def xy(self, x, y):
        return (x - self.x0) * self.sx, (y - self.y0) * self.sy


def _draw_op(img, op, tf: _Transform, colour):
    aa = cv2.LINE_AA
    if isinstance(op, FillPoly):
        cv2.fillPoly(img, [tf.pts(op.points)], colour, aa, SHIFT)
    elif isinstance(op, (FillEllipse, StrokeEllipse)):
        x, y = tf.xy(op.cx, op.cy)
        centre = (int(round(x * ONE)), int(round(y * ONE)))
        axes = (max(int(round(op.rx * tf.sx * ONE)), 1), max(int(round(op.ry * tf.sy * ONE)), 1))
        if isinstance(op, FillEllipse):
            cv2.ellipse(img, centre, axes, op.angle, 0, 360, colour, -1, aa, SHIFT)
        else:
            width = max(1, int(round(op.width * tf.s)))
            cv2.ellipse(img, centre, axes, op.angle, 0, 360, colour, width, aa, SHIFT)
    elif isinstance(op, StrokeLine):
        width = max(1, int(round(op.width * tf.s)))
        pts = tf.pts(op.points)
        cv2.polylines(img, [pts], op.closed, colour, width, aa, SHIFT)
        # round joins and caps, as in the SVG (stroke-linecap/linejoin round)
        r = int(round(op.width * tf.s * ONE / 2))
        if r >= ONE:
            for p in pts:
                cv2.circle(img, (int(p[0]), int(p[1])), r, colour, -1, aa, SHIFT)
    elif isinstance(op, Text):
        font, scale, thickness, tw, th = _text_params(op, tf.s)
        x, y = tf.xy(op.cx, op.cy)
        org = (int(round(x - (tw - thickness) / 2)), int(round(y + th / 2)))
        cv2.putText(img, op.text, org, font, scale, colour, thickness, aa)
    else:  # pragma: no cover - programming error
        raise TypeError(f"unknown drawing op {op!r}")


def supersample_for(w: int, h: int) -> int:
    longer = max(w, h)
    ss = 8 if longer < 128 else 4
    return max(1, min(ss, 4096 // max(longer, 1)))


def rasterize(drawing: Drawing, size: tuple[int, int], style: FaceStyle | None = None,
              supersample: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Render to (bgr, alpha) of ``size`` = (w, h); alpha is the anti-aliased sign outline."""
    w, h = int(size[0]), int(size[1])
    if w < 1 or h < 1:
        raise ValueError(f"size must be positive, got {size}")
    palette = (style or FaceStyle()).palette()
    ss = supersample or supersample_for(w, h)
    W, H = w * ss, h * ss
    tf = _Transform(drawing.view, W, H)
    canvas = np.empty((H, W, 3), np.uint8)
    canvas[:] = palette[drawing.background]
    for op in drawing.ops:
        _draw_op(canvas, op, tf, palette[op.colour])
    mask = np.zeros((H, W), np.uint8)
    _draw_op(mask, drawing.outline, tf, 255)
    if ss == 1:
        return canvas, mask
    bgr = cv2.resize(canvas, (w, h), interpolation=cv2.INTER_AREA)
    alpha = cv2.resize(mask, (w, h), interpolation=cv2.INTER_AREA)
    return bgr, alpha


# --------------------------------------------------------------------------- SVG


def _f(v: float) -> str:
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _hex(name: str) -> str:
    r, g, b = PALETTE_RGB[name]
    return f"#{r:02x}{g:02x}{b:02x}"


def _pts(points) -> str:
    return " ".join(f"{_f(x)},{_f(y)}" for x, y in shapes.as_points(points))


def _svg_op(op) -> str:
    if isinstance(op, FillPoly):
        return f'<polygon points="{_pts(op.points)}" fill="{_hex(op.colour)}"/>'
    if isinstance(op, (FillEllipse, StrokeEllipse)):
        rot = f' transform="rotate({_f(op.angle)} {_f(op.cx)} {_f(op.cy)})"' if op.angle else ""
        geo = f'cx="{_f(op.cx)}" cy="{_f(op.cy)}" rx="{_f(op.rx)}" ry="{_f(op.ry)}"'
        if isinstance(op, FillEllipse):
            return f'<ellipse {geo} fill="{_hex(op.colour)}"{rot}/>'
        return f'<ellipse {geo} fill="none" stroke="{_hex(op.colour)}" stroke-width="{_f(op.width)}"{rot}/>'
    if isinstance(op, StrokeLine):
        tag = "polygon" if op.closed else "polyline"
        return (f'<{tag} points="{_pts(op.points)}" fill="none" stroke="{_hex(op.colour)}" '
                f'stroke-width="{_f(op.width)}" stroke-linecap="round" stroke-linejoin="round"/>')
    if isinstance(op, Text):
        width = text_width(op)
        text = op.text.replace("&", "&amp;").replace("<", "&lt;")
        return (f'<text x="{_f(op.cx)}" y="{_f(op.cy + op.height / 2)}" font-family="DejaVu Sans, Arial, sans-serif" '
                f'font-weight="bold" font-size="{_f(op.height / 0.72)}" text-anchor="middle" '
                f'textLength="{_f(width)}" lengthAdjust="spacingAndGlyphs" fill="{_hex(op.colour)}">{text}</text>')
    raise TypeError(f"unknown drawing op {op!r}")  # pragma: no cover


def to_svg(drawing: Drawing, width_px: int, title: str = "") -> str:
    """SVG text of the drawing (reference palette); height follows the face aspect."""
    x0, y0, x1, y1 = drawing.view
    height_px = int(round(width_px / drawing.aspect))
    clip = FillPoly(drawing.outline.points, "white") if isinstance(drawing.outline, FillPoly) else None
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width_px}" height="{height_px}" '
        f'viewBox="{_f(x0)} {_f(y0)} {_f(x1 - x0)} {_f(y1 - y0)}" preserveAspectRatio="none">',
    ]
    if title:
        lines.append(f"<title>{title.replace('&', '&amp;').replace('<', '&lt;')}</title>")
    outline = drawing.outline
    if clip is not None:
        lines.append(f'<clipPath id="outline"><polygon points="{_pts(clip.points)}"/></clipPath>')
    else:
        lines.append(f'<clipPath id="outline"><ellipse cx="{_f(outline.cx)}" cy="{_f(outline.cy)}" '
                     f'rx="{_f(outline.rx)}" ry="{_f(outline.ry)}"/></clipPath>')
    lines.append('<g clip-path="url(#outline)">')
    lines.extend(_svg_op(op) for op in drawing.ops)
    lines.append("</g>")
    lines.append("</svg>")
    return "\n".join(lines) + "\n"
