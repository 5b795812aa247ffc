"""Stickers and graffiti tags on a sign face.

Stickers are small (5-11 % of the face width), stuck anywhere but mostly off the
centre where the pictogram is; a tag is one sprayed scribble, a loop of a few
strokes about a third of the face wide.
"""

from __future__ import annotations

import cv2
import numpy as np

STICKER_BGR = ((245, 245, 245), (40, 200, 240), (60, 60, 220), (200, 120, 30), (40, 40, 40), (90, 170, 70))
SPRAY_BGR = ((25, 25, 25), (190, 190, 195), (180, 80, 230), (60, 180, 60), (200, 110, 40), (40, 40, 190))


def _off_centre_point(alpha: np.ndarray, rng: np.random.Generator, min_radius: float) -> tuple[int, int] | None:
    """(x, y) inside the outline at least ``min_radius`` (fraction of the width) from the centre."""
    h, w = alpha.shape
    inside = np.argwhere(cv2.erode((alpha > 200).astype(np.uint8), np.ones((5, 5), np.uint8)) > 0)
    if not len(inside):
        return None
    far = inside[np.hypot(inside[:, 0] - h / 2, inside[:, 1] - w / 2) >= min_radius * w]
    pool = far if len(far) else inside
    y, x = pool[int(rng.integers(len(pool)))]
    return int(x), int(y)


def _paint(img: np.ndarray, mask: np.ndarray, colour) -> np.ndarray:
    """``img`` with ``colour`` laid over it in the share ``mask`` (0..1) of each pixel: how every mark goes on."""
    return img * (1 - mask[..., None]) + colour * mask[..., None]


def _mark_start(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, min_radius: float):
    """(h, w, the face as float BGR, where the mark goes or None): what every mark starts from, ``min_radius`` as
    in :func:`_off_centre_point`."""
    h, w = bgr.shape[:2]
    return h, w, bgr.astype(np.float32), _off_centre_point(alpha, rng, min_radius)


def sticker(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Float BGR with one sticker: a rotated rectangle or a disc, some with a few lines of 'print'."""
    h, w, img, at = _mark_start(bgr, alpha, rng, 0.28)
    if at is None:
        return img
    size = rng.uniform(0.05, 0.11) * w
    colour = np.array(STICKER_BGR[int(rng.integers(len(STICKER_BGR)))], np.float32)
    mask = np.zeros((h, w), np.float32)
    if rng.random() < 0.6:
        box = ((float(at[0]), float(at[1])), (size, size * rng.uniform(0.45, 0.9)), float(rng.uniform(-40, 40)))
        corners = cv2.boxPoints(box)
        cv2.fillPoly(mask, [np.round(corners * 4).astype(np.int32)], 1.0, cv2.LINE_AA, shift=2)
    else:
        cv2.circle(mask, at, max(1, int(size / 2)), 1.0, -1, cv2.LINE_AA)
    mask *= alpha.astype(np.float32) / 255.0
    img = _paint(img, mask, colour)
    if rng.random() < 0.6:  # a few dark 'text' lines across the sticker
        lines = np.zeros((h, w), np.float32)
        thick = max(1, int(round(size * 0.07)))
        for k in range(int(rng.integers(1, 4))):
            y = int(at[1] - size * 0.2 + k * size * 0.15)
            half = size * rng.uniform(0.15, 0.35)
            cv2.line(lines, (int(at[0] - half), y), (int(at[0] + half), y), 1.0, thick, cv2.LINE_AA)
        lines *= mask
        ink = np.array((30.0, 30.0, 30.0)) if colour.mean() > 100 else np.array((235.0, 235.0, 235.0))
        img = _paint(img, lines, ink)
    return img


def graffiti_tag(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Float BGR with one sprayed tag: a smooth scribble with loops, soft-edged, clipped to the face."""
    h, w, img, at = _mark_start(bgr, alpha, rng, 0.2)
    if at is None:
        return img
    span = rng.uniform(0.2, 0.35) * w
    steps = 120
    heading = rng.uniform(-0.5, 0.5)
    turn = np.cumsum(rng.normal(0, 0.25, steps)) + 2.2 * np.sin(np.linspace(0, rng.uniform(6, 14), steps))
    angles = heading + turn
    step = span / steps * 2.2
    pts = np.cumsum(np.stack([np.cos(angles), np.sin(angles) * 0.8], axis=1) * step, axis=0)
    pts -= pts.mean(axis=0)
    pts = pts * min(1.0, span / max(np.ptp(pts[:, 0]), 1e-6)) + np.array(at, np.float64)
    mask = np.zeros((h, w), np.float32)
    thick = max(1, int(round(rng.uniform(0.008, 0.018) * w)))
    cv2.polylines(mask, [np.round(pts * 4).astype(np.int32)], False, 1.0, thick, cv2.LINE_AA, shift=2)
    mask = cv2.GaussianBlur(mask, (0, 0), max(0.6, thick * 0.3)) * rng.uniform(0.75, 0.95)
    mask = np.clip(mask * 1.3, 0, 1) * (alpha.astype(np.float32) / 255.0)
    colour = np.array(SPRAY_BGR[int(rng.integers(len(SPRAY_BGR)))], np.float32)
    return _paint(img, mask, colour)
