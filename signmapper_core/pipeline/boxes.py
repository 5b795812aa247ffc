"""Axis-aligned pixel boxes (x, y, w, h) shared by the pipeline's steps."""

from __future__ import annotations


def touches_border(box, width: int, height: int, margin: int) -> bool:
    """Whether a box comes within ``margin`` pixels of the border of a ``width`` x ``height`` image (a face cut
    by the border cannot be sized or matched)."""
    x, y, w, h = box
    return x <= margin or y <= margin or x + w >= width - margin or y + h >= height - margin


def box_iou(a, b) -> float:
    """Intersection over union of two boxes; 0.0 when they do not overlap."""
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    iw = max(0, min(ax + aw, bx + bw) - max(ax, bx))
    ih = max(0, min(ay + ah, by + bh) - max(ay, by))
    inter = iw * ih
    return inter / float(aw * ah + bw * bh - inter) if inter else 0.0
