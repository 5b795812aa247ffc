"""Axis-aligned pixel boxes (x, y, w, h) shared by the pipeline's steps."""

from __future__ import annotations


def box_iou(a, b) -> float:
    """Intersection over union of two boxes; 0.0 when they do not overlap."""
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    iw = max(0, min(ax + aw, bx + bw) - max(ax, bx))
    ih = max(0, min(ay + ah, by + bh) - max(ay, by))
    inter = iw * ih
    return inter / float(aw * ah + bw * bh - inter) if inter else 0.0
