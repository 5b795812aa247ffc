"""Plane geometry for sign drawings: rounded convex polygons, insets, arcs.

Everything works on float arrays of (x, y) points in drawing units (y down), so
the raster and the SVG writer consume exactly the same outlines.
"""

from __future__ import annotations

import math

import numpy as np

SQRT3_2 = math.sqrt(3.0) / 2.0


def as_points(points) -> np.ndarray:
    return np.asarray(points, dtype=np.float64).reshape(-1, 2)


def regular_polygon(n: int, cx: float, cy: float, radius: float, rotation_deg: float = 0.0) -> np.ndarray:
    """Vertices of a regular n-gon with circumradius ``radius``; rotation 0 puts a vertex at the top."""
    angles = np.radians(rotation_deg) - np.pi / 2 + np.arange(n) * 2 * np.pi / n
    return np.stack([cx + radius * np.cos(angles), cy + radius * np.sin(angles)], axis=1)


def signed_area(points) -> float:
    p = as_points(points)
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def inset_convex(points, distance: float) -> np.ndarray:
    """Move every edge of a convex polygon inwards by ``distance`` (sharp corners kept)."""
    p = as_points(points)
    if distance == 0:
        return p.copy()
    sign = 1.0 if signed_area(p) > 0 else -1.0
    n = len(p)
    lines = []
    for i in range(n):
        a, b = p[i], p[(i + 1) % n]
        d = (b - a) / np.linalg.norm(b - a)
        normal = sign * np.array([-d[1], d[0]])  # points inside for either orientation
        lines.append((a + normal * distance, d))
    out = []
    for i in range(n):
        (p1, d1), (p2, d2) = lines[i - 1], lines[i]
        m = np.array([d1, -d2]).T
        t = np.linalg.solve(m, p2 - p1)
        out.append(p1 + d1 * t[0])
    return np.array(out)


def rounded_polygon(points, radius: float, segments: int = 10) -> np.ndarray:
    """Replace every corner of a convex polygon by a circular arc of ``radius``."""
    p = as_points(points)
    if radius <= 0:
        return p.copy()
    n = len(p)
    out = []
    for i in range(n):
        v, a, b = p[i], p[i - 1], p[(i + 1) % n]
        u1 = (a - v) / np.linalg.norm(a - v)
        u2 = (b - v) / np.linalg.norm(b - v)
        half = math.acos(float(np.clip(np.dot(u1, u2), -1.0, 1.0))) / 2.0
        bis = u1 + u2
        bis /= np.linalg.norm(bis)
        centre = v + bis * radius / math.sin(half)
        t1 = v + u1 * radius / math.tan(half)
        t2 = v + u2 * radius / math.tan(half)
        a1 = math.atan2(t1[1] - centre[1], t1[0] - centre[0])
        a2 = math.atan2(t2[1] - centre[1], t2[0] - centre[0])
        delta = (a2 - a1 + math.pi) % (2 * math.pi) - math.pi
        for k in range(segments + 1):
            ang = a1 + delta * k / segments
            out.append((centre[0] + radius * math.cos(ang), centre[1] + radius * math.sin(ang)))
    return np.array(out)


def rounded_inset(points, corner_radius: float, distance: float, segments: int = 10) -> np.ndarray:
    """The outline ``distance`` inside a rounded polygon (itself rounded, radius shrinks)."""
    sharp = inset_convex(points, distance)
    return rounded_polygon(sharp, max(corner_radius - distance, 0.0), segments)


def arc(cx: float, cy: float, radius: float, start_deg: float, end_deg: float, n: int = 24) -> np.ndarray:
    """Points on a circular arc; angles in degrees, 0 = +x, positive turns towards +y (clockwise on screen)."""
    t = np.radians(np.linspace(start_deg, end_deg, n))
    return np.stack([cx + radius * np.cos(t), cy + radius * np.sin(t)], axis=1)


def bbox(points) -> tuple[float, float, float, float]:
    p = as_points(points)
    return float(p[:, 0].min()), float(p[:, 1].min()), float(p[:, 0].max()), float(p[:, 1].max())


def clip_segment_to_convex(a, b, polygon) -> np.ndarray | None:
    """Cyrus-Beck clipping of segment a-b to a convex polygon; None when outside."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    poly = as_points(polygon)
    sign = 1.0 if signed_area(poly) > 0 else -1.0
    t0, t1 = 0.0, 1.0
    d = b - a
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        e = q - p
        normal = sign * np.array([-e[1], e[0]])  # inward
        num = float(np.dot(normal, a - p))
        den = float(np.dot(normal, d))
        if abs(den) < 1e-12:
            if num < 0:
                return None
            continue
        t = -num / den
        if den > 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return None
    return np.array([a + d * t0, a + d * t1])
