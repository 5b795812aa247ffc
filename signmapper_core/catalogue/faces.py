"""Procedural sign faces: the project's own drawing of every Swiss sign, with styled variants.

``render_face`` draws a Swiss sign from its definition at any pixel size. The
Swiss catalogue masters are the official ASTRA drawings; entries without one use
``render_face(id, 512)`` with the reference style. The synthetic generator
passes a varied ``FaceStyle``: its faces are other artwork than the templates.
"""

from __future__ import annotations

import numpy as np

from .drawing import Drawing, rasterize
from .signs_ch import SIGNS, SignDef
from .style import FaceStyle


def sign_definition(template_id: str) -> SignDef:
    try:
        return SIGNS[template_id]
    except KeyError:
        raise KeyError(f"no procedural drawing for template {template_id!r} (only Swiss signs can be drawn)") \
            from None


def face_drawing(template_id: str, style: FaceStyle | None = None) -> Drawing:
    return sign_definition(template_id).draw(style or FaceStyle())


def pixel_size(aspect: float, size_px) -> tuple[int, int]:
    """(w, h) from an int (longer side, keeping ``aspect`` = w/h) or an explicit (w, h)."""
    if isinstance(size_px, (tuple, list)):
        w, h = int(size_px[0]), int(size_px[1])
    else:
        n = int(size_px)
        w, h = (n, max(1, round(n / aspect))) if aspect >= 1 else (max(1, round(n * aspect)), n)
    if w < 1 or h < 1:
        raise ValueError(f"size must be positive, got {size_px!r}")
    return w, h


def face_aspect(template_id: str) -> float:
    """Width / height of the face from its first standard format."""
    w, h = next(iter(sign_definition(template_id).formats.values()))
    return w / h


def render_face(template_id: str, size_px, style: FaceStyle | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(bgr, alpha) of a procedurally drawn face; ``size_px`` is the longer side or (w, h)."""
    style = style or FaceStyle()
    drawing = face_drawing(template_id, style)
    return rasterize(drawing, pixel_size(face_aspect(template_id), size_px), style)
