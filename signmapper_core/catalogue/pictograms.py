"""Stylised pictograms built from primitives, in a local [-1, 1] frame (y down).

They are deliberately simple silhouettes (the matcher compares small, blurred
templates), but keep the parts that tell signs apart: a bicycle's two wheels, a
lorry's box, a child's size, an arrow's direction.
"""

from __future__ import annotations

import numpy as np

from . import shapes
from .pen import Pen


# --------------------------------------------------------------------------- people
def pedestrian(p: Pen, c: str = "black", stride: float = 1.0):
    """Walking person facing right."""
    p.circle(0.12, -0.80, 0.17, c)
    p.line([(0.06, -0.52), (-0.02, 0.08)], 0.27, c)
    p.line([(-0.38, -0.02), (-0.14, -0.38), (0.05, -0.48), (0.30, -0.22), (0.42, -0.02)], 0.12, c)
    p.line([(-0.02, 0.10), (-0.22 * stride, 0.50), (-0.48 * stride, 0.93)], 0.15, c)
    p.line([(-0.02, 0.10), (0.22 * stride, 0.50), (0.36 * stride, 0.95)], 0.15, c)


def children(p: Pen, c: str = "black"):
    """Two running children, the larger one in front."""
    pedestrian(p.sub(0.32, 0.10, 0.9), c, 1.2)
    pedestrian(p.sub(-0.45, 0.30, 0.7), c, 1.2)


def adult_and_child(p: Pen, c: str = "white"):
    pedestrian(p.sub(-0.25, -0.05, 0.95), c)
    pedestrian(p.sub(0.45, 0.30, 0.65), c)
    p.line([(0.2, -0.05), (0.32, 0.05)], 0.08, c)


def worker(p: Pen, c: str = "black"):
    """Road worker with a shovel at a heap."""
    p.circle(-0.28, -0.62, 0.15, c)
    p.line([(-0.25, -0.40), (-0.05, 0.10)], 0.25, c)
    p.line([(-0.05, 0.12), (-0.35, 0.45), (-0.45, 0.9)], 0.14, c)
    p.line([(-0.05, 0.12), (0.15, 0.55), (0.05, 0.9)], 0.14, c)
    p.line([(-0.18, -0.28), (0.10, -0.05), (0.30, 0.15)], 0.11, c)
    p.line([(0.05, -0.30), (0.55, 0.55)], 0.07, c)
    p.poly([(0.45, 0.50), (0.70, 0.48), (0.62, 0.70)], c)
    p.poly(shapes.arc(0.72, 0.95, 0.32, 180, 360, 16), c)


# --------------------------------------------------------------------------- vehicles
def car_side(p: Pen, c: str = "black", windows: str = "white"):
    p.poly([(-1.0, 0.28), (-1.0, -0.05), (-0.9, -0.18), (-0.50, -0.22), (-0.30, -0.55), (0.38, -0.55),
            (0.62, -0.20), (0.95, -0.12), (1.0, 0.05), (1.0, 0.28)], c, 0.05)
    if p.detailed:
        p.poly([(-0.22, -0.45), (0.02, -0.45), (0.02, -0.24), (-0.38, -0.24)], windows, 0.02)
        p.poly([(0.10, -0.45), (0.33, -0.45), (0.48, -0.24), (0.10, -0.24)], windows, 0.02)
    for x in (-0.55, 0.58):
        p.circle(x, 0.30, 0.22, windows)
        p.circle(x, 0.30, 0.17, c)


def car_rear(p: Pen, c: str = "black", windows: str = "white"):
    """Car seen from behind (slippery road, gravel, queue, overtaking)."""
    p.poly([(-0.55, -0.62), (0.55, -0.62), (0.75, -0.12), (-0.75, -0.12)], c, 0.08)
    p.rect(-0.92, -0.2, 0.92, 0.35, c, 0.08)
    p.rect(-0.85, 0.2, -0.48, 0.58, c, 0.05)
    p.rect(0.48, 0.2, 0.85, 0.58, c, 0.05)
    if p.detailed:
        p.poly([(-0.45, -0.52), (0.45, -0.52), (0.58, -0.2), (-0.58, -0.2)], windows, 0.04)
        p.circle(-0.62, 0.05, 0.1, windows)
        p.circle(0.62, 0.05, 0.1, windows)


def lorry_side(p: Pen, c: str = "black", windows: str = "white"):
    p.rect(-1.0, -0.75, 0.35, 0.25, c, 0.03)
    p.poly([(0.42, -0.5), (0.80, -0.5), (1.0, -0.12), (1.0, 0.25), (0.42, 0.25)], c, 0.04)
    if p.detailed:
        p.poly([(0.52, -0.42), (0.76, -0.42), (0.88, -0.15), (0.52, -0.15)], windows, 0.02)
    for x in (-0.68, -0.28, 0.70):
        p.circle(x, 0.32, 0.2, windows)
        p.circle(x, 0.32, 0.16, c)


def lorry_rear(p: Pen, c: str = "black"):
    p.rect(-0.8, -0.75, 0.8, 0.3, c, 0.04)
    p.rect(-0.8, 0.3, -0.4, 0.6, c, 0.04)
    p.rect(0.4, 0.3, 0.8, 0.6, c, 0.04)


def bus_side(p: Pen, c: str = "black", windows: str = "white"):
    p.rect(-1.0, -0.6, 1.0, 0.28, c, 0.1)
    if p.detailed:
        for x in np.linspace(-0.82, 0.58, 5):
            p.rect(x, -0.48, x + 0.26, -0.15, windows, 0.02)
        p.rect(0.74, -0.48, 0.9, 0.12, windows, 0.02)
    for x in (-0.6, 0.6):
        p.circle(x, 0.3, 0.2, windows)
        p.circle(x, 0.3, 0.16, c)


def bicycle(p: Pen, c: str = "black", w: float = 0.09):
    for x in (-0.58, 0.58):
        p.ring(x, 0.38, 0.36, w, c)
    p.line([(-0.58, 0.38), (-0.05, 0.38), (-0.22, -0.22), (-0.58, 0.38)], w, c)
    p.line([(-0.05, 0.38), (0.45, -0.22), (-0.22, -0.22)], w, c)
    p.line([(0.58, 0.38), (0.40, -0.40), (0.25, -0.45)], w, c)
    p.line([(-0.36, -0.30), (-0.10, -0.30)], w * 1.3, c)


def cyclist(p: Pen, c: str = "black"):
    bicycle(p.sub(0, 0.25, 0.85, jitter=False), c)
    p.circle(0.25, -0.95, 0.14, c)
    p.line([(-0.12, -0.08), (0.12, -0.72)], 0.2, c)
    p.line([(0.12, -0.62), (0.34, -0.18)], 0.1, c)
    p.line([(-0.12, -0.08), (0.15, 0.12), (-0.03, 0.55)], 0.12, c)


def moped(p: Pen, c: str = "black"):
    """Small thick wheels and a solid body from the rear wheel to the fork: a moped, not a bicycle with a box."""
    for x in (-0.58, 0.58):
        p.ring(x, 0.42, 0.3, 0.12, c)
    p.poly([(-0.62, 0.12), (-0.5, -0.2), (-0.05, -0.2), (0.1, 0.0), (0.32, -0.1), (0.2, 0.32), (-0.3, 0.32)],
           c, 0.05)
    p.line([(0.58, 0.42), (0.38, -0.38), (0.2, -0.45)], 0.1, c)
    p.line([(-0.45, -0.28), (-0.1, -0.28)], 0.12, c)


def motorcycle(p: Pen, c: str = "black"):
    for x in (-0.6, 0.62):
        p.ring(x, 0.35, 0.3, 0.13, c)
    p.poly([(-0.6, 0.3), (-0.45, -0.12), (-0.05, -0.22), (0.35, -0.32), (0.48, -0.05), (0.15, 0.35),
            (-0.3, 0.35)], c, 0.05)
    p.line([(0.62, 0.35), (0.42, -0.42), (0.25, -0.5)], 0.1, c)
    p.circle(-0.05, -0.85, 0.14, c)
    p.line([(-0.2, -0.2), (-0.05, -0.65), (0.3, -0.45)], 0.16, c)


def trailer(p: Pen, c: str = "black"):
    p.rect(-0.9, -0.55, 0.45, 0.22, c, 0.04)
    p.circle(-0.2, 0.3, 0.22, c)
    p.line([(0.45, 0.05), (0.95, 0.1)], 0.09, c)


def tram(p: Pen, c: str = "black"):
    p.rect(-0.95, -0.45, 0.95, 0.35, c, 0.12)
    if p.detailed:
        for x in (-0.75, -0.3, 0.15):
            p.rect(x, -0.32, x + 0.35, -0.05, "white", 0.02)
    p.line([(0, -0.45), (-0.25, -0.75), (0.25, -0.9)], 0.06, c)
    p.line([(-0.3, -0.92), (0.45, -0.92)], 0.06, c)
    for x in (-0.6, 0.6):
        p.circle(x, 0.42, 0.14, c)


def locomotive(p: Pen, c: str = "black"):
    p.rect(-0.9, -0.25, 0.35, 0.3, c, 0.04)
    p.rect(0.3, -0.7, 0.9, 0.3, c, 0.04)
    p.rect(-0.75, -0.6, -0.5, -0.2, c, 0.02)
    if p.detailed:
        p.rect(0.45, -0.58, 0.75, -0.35, "white", 0.02)
    for x in (-0.55, -0.05, 0.55):
        p.circle(x, 0.45, 0.2, c)


# --------------------------------------------------------------------------- animals
def cow(p: Pen, c: str = "black"):
    p.rect(-0.8, -0.35, 0.5, 0.2, c, 0.1)
    p.poly([(0.42, -0.45), (0.92, -0.28), (0.88, -0.02), (0.5, 0.02)], c, 0.06)
    p.line([(0.55, -0.48), (0.6, -0.65)], 0.07, c)
    for x in (-0.7, -0.5, 0.2, 0.4):
        p.line([(x, 0.1), (x, 0.72)], 0.12, c)
    p.line([(-0.8, -0.3), (-0.95, 0.3)], 0.06, c)


def deer(p: Pen, c: str = "black"):
    """Leaping deer."""
    p.ellipse(-0.05, 0.0, 0.55, 0.22, c, -18)
    p.line([(0.4, -0.2), (0.62, -0.55)], 0.17, c)
    p.ellipse(0.72, -0.58, 0.17, 0.09, c, 25)
    p.line([(0.6, -0.66), (0.5, -0.95), (0.35, -1.0)], 0.05, c)
    p.line([(0.55, -0.85), (0.7, -1.0)], 0.05, c)
    p.line([(0.35, -0.05), (0.7, 0.35), (0.85, 0.3)], 0.09, c)
    p.line([(0.25, 0.0), (0.45, 0.45)], 0.09, c)
    p.line([(-0.45, 0.12), (-0.8, 0.55), (-0.95, 0.5)], 0.09, c)
    p.line([(-0.5, 0.15), (-0.6, 0.7)], 0.09, c)


def horse_rider(p: Pen, c: str = "white"):
    p.ellipse(-0.05, 0.12, 0.55, 0.22, c)
    p.line([(0.38, 0.02), (0.62, -0.38)], 0.18, c)
    p.ellipse(0.74, -0.38, 0.2, 0.09, c, 30)
    for x0, x1 in ((-0.45, -0.55), (-0.3, -0.25), (0.22, 0.12), (0.38, 0.45)):
        p.line([(x0, 0.2), (x1, 0.85)], 0.1, c)
    p.line([(-0.58, 0.05), (-0.85, 0.45)], 0.08, c)
    p.circle(0.0, -0.78, 0.13, c)
    p.line([(-0.03, -0.6), (-0.08, -0.15)], 0.18, c)
    p.line([(-0.05, -0.5), (0.25, -0.25)], 0.08, c)
    p.line([(-0.08, -0.15), (0.08, 0.15), (0.0, 0.4)], 0.1, c)


# --------------------------------------------------------------------------- symbols
def exclamation(p: Pen, c: str = "black"):
    p.poly([(-0.17, -0.95), (0.17, -0.95), (0.09, 0.35), (-0.09, 0.35)], c, 0.06)
    p.circle(0, 0.7, 0.17, c)


def zebra(p: Pen, c: str = "black", n: int = 5, y0: float = 0.62, y1: float = 0.95):
    xs = np.linspace(-0.95, 0.95, 2 * n)
    for i in range(0, 2 * n - 1, 2):
        a, b = xs[i], xs[i] + (xs[1] - xs[0]) * 0.9
        p.poly([(a + 0.1, y0), (b + 0.1, y0), (b, y1), (a, y1)], c)


def traffic_lights(p: Pen, c: str = "black"):
    p.rect(-0.38, -1.0, 0.38, 0.95, c, 0.12)
    for y, col in ((-0.6, "red"), (-0.02, "yellow"), (0.55, "green")):
        p.circle(0, y, 0.24, col)


def road_curve(p: Pen, c: str = "black", width: float = 0.3):
    """Bend to the right (mirror for left)."""
    pts = np.vstack([[(-0.25, 0.95)], shapes.arc(0.45, 0.1, 0.7, 180, 250, 10), [(0.55, -0.62)]])
    p.arrow(pts, width, c, head_length=0.38, head_width=0.36)


def road_double_curve(p: Pen, c: str = "black", width: float = 0.26):
    """Double bend, first to the right (mirror for first to the left)."""
    t = np.linspace(0.0, 1.0, 33)
    pts = np.stack([-0.05 + 0.36 * np.sin(2 * np.pi * t), 0.95 - 1.75 * t], axis=1)
    p.arrow(pts, width, c, head_length=0.36, head_width=0.34)


def narrowing(p: Pen, c: str = "black", left: bool = True, right: bool = True, width: float = 0.16):
    def edge(x_out, x_in, sign):
        return [(sign * x_out, 0.95), (sign * x_out, 0.25), (sign * x_in, -0.25), (sign * x_in, -0.95)]

    p.line(edge(0.62, 0.28 if left else 0.62, -1), width, c)
    p.line(edge(0.62, 0.28 if right else 0.62, 1), width, c)


def bumps(p: Pen, c: str = "black"):
    x = np.linspace(-0.95, 0.95, 41)
    y = 0.55 - 0.45 * np.clip(np.cos(x * np.pi * 1.05), 0, None) ** 1.5
    pts = np.vstack([np.stack([x, y], 1), [(0.95, 0.8), (-0.95, 0.8)]])
    p.poly(pts, c)


def skid_marks(p: Pen, c: str = "black"):
    for x0 in (-0.42, 0.42):
        t = np.linspace(0, 1, 20)
        pts = np.stack([x0 + 0.22 * np.sin(t * 2.6 * np.pi) * (0.3 + t), 0.1 + t * 0.85], 1)
        p.line(pts, 0.09, c)


def gradient(p: Pen, c: str = "black", text: str = "10%"):
    """Steep descent wedge (mirror for climb)."""
    p.poly([(-0.95, -0.25), (0.95, 0.75), (-0.95, 0.75)], c)
    p.text(text, -0.38, 0.42, 0.34, "white", max_width=0.9)


def gravel(p: Pen, c: str = "black"):
    car_rear(p.sub(0, -0.3, 0.6), c)
    rng = np.random.default_rng(3)
    for _ in range(14):
        x, y = rng.uniform(-0.9, 0.9), rng.uniform(0.25, 0.95)
        p.circle(x, y, rng.uniform(0.04, 0.08), c)


def rockfall(p: Pen, c: str = "black"):
    p.poly([(-0.95, -0.95), (-0.45, -0.95), (-0.05, 0.95), (-0.95, 0.95)], c)
    for x, y, r in ((0.15, -0.35, 0.14), (0.45, 0.05, 0.18), (0.3, 0.55, 0.2), (0.7, 0.65, 0.13)):
        p.circle(x, y, r, c)


def barrier(p: Pen, c: str = "black"):
    p.line([(-0.95, -0.3), (0.95, -0.3)], 0.12, c)
    p.line([(-0.95, 0.55), (0.95, 0.55)], 0.12, c)
    for x in np.linspace(-0.85, 0.85, 6):
        p.line([(x, -0.55), (x, 0.85)], 0.12, c)


def two_way(p: Pen, c: str = "black"):
    p.arrow([(0.35, 0.95), (0.35, -0.95)], 0.2, c, 0.4, 0.3)
    p.arrow([(-0.35, -0.95), (-0.35, 0.95)], 0.2, c, 0.4, 0.3)


def queue(p: Pen, c: str = "black"):
    car_rear(p.sub(0, -0.45, 0.55), c)
    car_rear(p.sub(0, 0.45, 0.75), c)


def junction(p: Pen, c: str = "black", kind: str = "cross"):
    """Intersection symbols: 'cross' (major road + side roads), 'right', 'left', 'x' (equal roads),
    'merge' (a road joining from the right)."""
    if kind == "merge":
        p.poly([(-0.42, 0.95), (-0.42, -0.55), (-0.16, -0.85), (0.1, -0.55), (0.1, 0.95)], c)
        p.line([(0.75, 0.8), (0.05, -0.15)], 0.26, c)
        return
    if kind == "x":
        p.line([(-0.75, -0.75), (0.75, 0.75)], 0.24, c)
        p.line([(-0.75, 0.75), (0.75, -0.75)], 0.24, c)
        return
    p.poly([(-0.18, -0.95), (0.18, -0.95), (0.18, 0.95), (-0.18, 0.95)], c)
    if kind in ("cross", "right"):
        p.rect(0.0, -0.06, 0.8, 0.06, c)
    if kind in ("cross", "left"):
        p.rect(-0.8, -0.06, 0.0, 0.06, c)


def bar(p: Pen, c: str = "red", width: float = 0.24):
    """Prohibition bar from top-left to bottom-right across the disc."""
    p.line([(-0.96, -0.96), (0.96, 0.96)], width, c, scaled=False)


def turn_arrow(p: Pen, c: str, width: float = 0.3, up: float = -0.95):
    """Arrow going straight up then turning right (mirror for left)."""
    bend = shapes.arc(0.35, -0.05, 0.45, 180, 270, 10)
    pts = np.vstack([[(-0.1, 0.95)], bend, [(0.85, -0.5)]])
    p.arrow(pts, width, c, 0.45, 0.42)


def u_turn(p: Pen, c: str = "black"):
    pts = np.vstack([[(0.4, 0.9)], shapes.arc(0.0, -0.2, 0.4, 0, -180, 16), [(-0.4, 0.35)]])
    p.arrow(pts, 0.2, c, 0.4, 0.34)


def roundabout(p: Pen, c: str = "white"):
    for start in (-90, 30, 150):
        pts = shapes.arc(0, 0, 0.66, start + 100, start, 20)
        p.arrow(pts, 0.22, c, 0.42, 0.36)


def tyre_with_chains(p: Pen, c: str = "white"):
    p.ring(0, 0, 0.72, 0.32, c)
    for a in np.arange(0, 360, 30):
        r0, r1 = 0.45, 0.98
        ca, sa = np.cos(np.radians(a)), np.sin(np.radians(a))
        p.line([(r0 * ca, r0 * sa), (r1 * ca, r1 * sa)], 0.07, c)


def width_marks(p: Pen, c: str = "black"):
    p.poly([(-0.98, -0.3), (-0.7, 0.0), (-0.98, 0.3)], c)
    p.poly([(0.98, -0.3), (0.7, 0.0), (0.98, 0.3)], c)


def height_marks(p: Pen, c: str = "black"):
    p.poly([(-0.3, -0.98), (0.0, -0.7), (0.3, -0.98)], c)
    p.poly([(-0.3, 0.98), (0.0, 0.7), (0.3, 0.98)], c)


def parking_disc(p: Pen, c: str = "white"):
    p.rect(-0.6, -0.45, 0.6, 0.45, c, 0.08)
    p.ring(0, 0, 0.3, 0.06, "blue")
    p.line([(0, 0), (0, -0.2), (0, 0), (0.15, 0.05)], 0.06, "blue")


def parking_meter(p: Pen, c: str = "white"):
    p.rect(-0.35, -0.8, 0.35, 0.1, c, 0.1)
    p.rect(-0.08, 0.1, 0.08, 0.9, c)
    p.rect(-0.2, -0.6, 0.2, -0.3, "blue", 0.03)
