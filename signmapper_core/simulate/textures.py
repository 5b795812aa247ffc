"""Procedural textures of the street scene (asphalt, façades, foliage, cars, ...).

Every maker takes its own seeded generator so a texture is the same whenever
and in whichever order it is made. Texture detail matters beyond looks: the
plugin computes depth by stereo matching, which needs texture on every surface.
"""

from __future__ import annotations

import cv2
import numpy as np

from .surfaces import Texture


def smooth_noise(rng: np.random.Generator, h: int, w: int, cell_px: float) -> np.ndarray:
    """Band-limited noise in about [-1, 1], features ``cell_px`` pixels large (float32)."""
    gh = max(2, int(np.ceil(h / cell_px)) + 2)
    gw = max(2, int(np.ceil(w / cell_px)) + 2)
    grid = rng.standard_normal((gh, gw)).astype(np.float32)
    big = cv2.resize(grid, (int(gw * cell_px), int(gh * cell_px)), interpolation=cv2.INTER_CUBIC)
    return big[:h, :w] * 0.6


def grain(rng: np.random.Generator, h: int, w: int, octaves=((1.0, 0.5), (4.0, 0.35), (16.0, 0.25))) -> np.ndarray:
    """Sum of noise octaves (cell size, amplitude): a general-purpose surface grain."""
    out = np.zeros((h, w), np.float32)
    for cell, amp in octaves:
        if cell <= 1.0:
            out += amp * rng.standard_normal((h, w)).astype(np.float32)
        else:
            out += amp * smooth_noise(rng, h, w, cell)
    return out


def tint(base_bgr, variation: np.ndarray, scale: float) -> np.ndarray:
    """Colour image from a base colour modulated by a grey variation field."""
    img = np.asarray(base_bgr, np.float32)[None, None, :] + (variation * scale)[:, :, None]
    return np.clip(img, 0, 255).astype(np.uint8)


def asphalt(rng, h, w, px_m: float, base=(88, 90, 92)) -> np.ndarray:
    """Asphalt: fine aggregate speckle and large faint patches."""
    var = grain(rng, h, w, ((1.0, 0.55), (0.06 / px_m, 0.4), (1.5 / px_m, 0.5)))
    return tint(base, var, 16.0)


def paving(rng, h, w, px_m: float, base=(150, 152, 155), slab_m: float = 0.5) -> np.ndarray:
    """Sidewalk slabs with joints."""
    img = tint(base, grain(rng, h, w, ((1.0, 0.5), (0.1 / px_m, 0.4), (2.0 / px_m, 0.4))), 14.0)
    step = max(3, int(round(slab_m / px_m)))
    off = int(rng.integers(0, step))
    for x in range(off, w, step):
        cv2.line(img, (x, 0), (x, h - 1), (110, 112, 115), 1)
    for y in range(off, h, step):
        cv2.line(img, (0, y), (w - 1, y), (110, 112, 115), 1)
    return img


def foliage(rng, h, w, dark=False) -> Texture:
    """Leafy crown or hedge with a ragged alpha outline."""
    var = grain(rng, h, w, ((1.0, 0.5), (3.0, 0.6), (10.0, 0.5)))
    base = (40, 95, 55) if not dark else (35, 70, 40)
    img = tint(base, var, 35.0)
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    r = np.sqrt(((xx - w / 2) / (w / 2)) ** 2 + ((yy - h / 2) / (h / 2)) ** 2)
    edge = 1.0 - r + 0.25 * smooth_noise(rng, h, w, max(3.0, w / 10))
    holes = smooth_noise(rng, h, w, 4.0) > 0.45
    alpha = np.where((edge > 0) & ~holes, 255, 0).astype(np.uint8)
    return Texture(img, cv2.GaussianBlur(alpha, (3, 3), 0))


def bark(rng, h, w) -> np.ndarray:
    return tint((45, 60, 75), grain(rng, h, w, ((1.0, 0.5), (3.0, 0.5))), 18.0)


FACADE_COLOURS = [(200, 215, 225), (170, 190, 210), (150, 170, 185), (215, 215, 210), (120, 140, 160),
                  (185, 200, 200), (160, 160, 155), (140, 175, 205)]
SIGNAL_COLOURS = {"red": (40, 40, 200), "blue": (170, 80, 20), "yellow": (20, 190, 235)}


def facade(rng, width_m: float, height_m: float, px_m: float) -> np.ndarray:
    """Plastered façade with storeys of windows, a ground floor with doors or shop windows."""
    w, h = max(8, int(width_m / px_m)), max(8, int(height_m / px_m))
    base = FACADE_COLOURS[int(rng.integers(len(FACADE_COLOURS)))]
    img = tint(base, grain(rng, h, w, ((1.0, 0.4), (4.0, 0.4), (40.0, 0.5))), 10.0)
    storey = rng.uniform(2.8, 3.4)
    bay = rng.uniform(2.2, 3.6)
    win_w, win_h = rng.uniform(0.9, 1.4), rng.uniform(1.2, 1.7)
    frame = tuple(int(c) for c in rng.choice([[235, 235, 235], [60, 60, 70], [40, 70, 110]]))
    n_bays = max(1, int(width_m // bay))
    margin = (width_m - n_bays * bay) / 2
    ground = rng.uniform(3.2, 4.2)
    y_m = ground
    while y_m + storey <= height_m - 0.5:
        for b in range(n_bays):
            x_m = margin + b * bay + (bay - win_w) / 2
            _window(img, rng, x_m, height_m - (y_m + 0.9 + win_h), win_w, win_h, px_m, frame)
        y_m += storey
    # ground floor: shop windows and doors
    x_m = rng.uniform(0.3, 1.5)
    while x_m < width_m - 1.5:
        ww = min(rng.uniform(1.0, 4.0), width_m - x_m - 0.5)
        _window(img, rng, x_m, height_m - rng.uniform(2.3, 2.9), ww, rng.uniform(1.8, 2.4), px_m, frame)
        x_m += ww + rng.uniform(0.6, 2.0)
    # plinth
    y = int((height_m - 0.4) / px_m)
    img[y:] = (img[y:].astype(np.int16) * 0.75).astype(np.uint8)
    return img


def _window(img, rng, x_m, top_m, w_m, h_m, px_m, frame):
    x0, y0 = int(x_m / px_m), int(top_m / px_m)
    x1, y1 = int((x_m + w_m) / px_m), int((top_m + h_m) / px_m)
    if x1 - x0 < 2 or y1 - y0 < 2:
        return
    cv2.rectangle(img, (x0, y0), (x1, y1), frame, -1)
    b = max(1, int(0.08 / px_m))
    glass = np.array(rng.choice([[70, 60, 50], [90, 80, 70], [110, 100, 95], [50, 45, 45]]), np.float32)
    gh, gw = y1 - y0 - 2 * b, x1 - x0 - 2 * b
    if gh < 1 or gw < 1:
        return
    ramp = np.linspace(-25, 30, gh, dtype=np.float32)[:, None, None] * rng.uniform(0.3, 1.0)
    pane = np.clip(glass + ramp + 6 * rng.standard_normal((gh, gw, 1)).astype(np.float32), 0, 255)
    # a shop window may reach past the façade's foot (or top): only the part on the façade is painted
    top, left = max(y0 + b, 0), max(x0 + b, 0)
    target = img[top:y1 - b, left:x1 - b]
    target[...] = pane[top - (y0 + b):, left - (x0 + b):][:target.shape[0], :target.shape[1]].astype(np.uint8)
    if gw > 6:  # mullion
        xm = x0 + (x1 - x0) // 2
        cv2.line(img, (xm, y0), (xm, y1), frame, max(1, b // 2))


def shop_sign(rng, width_m, height_m, px_m, colour_name: str) -> np.ndarray:
    """Coloured shop sign with white lettering-like blocks: a colour distractor."""
    w, h = max(8, int(width_m / px_m)), max(4, int(height_m / px_m))
    base = SIGNAL_COLOURS[colour_name]
    img = tint(base, grain(rng, h, w, ((1.0, 0.3), (4.0, 0.3))), 8.0)
    x = int(0.1 * w)
    letter_h = int(0.5 * h)
    y0 = (h - letter_h) // 2
    while x < 0.9 * w:
        lw = int(rng.uniform(0.4, 0.8) * letter_h)
        cv2.rectangle(img, (x, y0), (x + lw, y0 + letter_h), (240, 240, 240), max(1, lw // 4))
        x += lw + max(2, letter_h // 4)
    return img


def emblem(rng, n: int, colour_name: str) -> Texture:
    """Round, triangular or square shop emblem in a sign colour with white marks: a shape distractor."""
    img = tint(SIGNAL_COLOURS[colour_name], grain(rng, n, n, ((1.0, 0.3), (4.0, 0.3))), 8.0)
    alpha = np.zeros((n, n), np.uint8)
    shape = int(rng.integers(3))
    c = n // 2
    if shape == 0:
        cv2.circle(alpha, (c, c), c - 1, 255, -1, cv2.LINE_AA)
    elif shape == 1:
        tri = np.array([[c, 1], [n - 2, n - 2], [1, n - 2]], np.int32)
        cv2.fillConvexPoly(alpha, tri, 255, cv2.LINE_AA)
    else:
        alpha[:] = 255
    white = (240, 240, 240)
    for _ in range(int(rng.integers(1, 4))):
        x, y = (int(v) for v in rng.uniform(0.3, 0.6, 2) * n)
        cv2.rectangle(img, (x, y), (x + int(rng.uniform(0.1, 0.3) * n), y + int(rng.uniform(0.05, 0.2) * n)),
                      white, -1)
    if rng.random() < 0.5:
        cv2.circle(img, (c, c), int(0.3 * n), white, max(1, n // 14), cv2.LINE_AA)
    return Texture(img, alpha)


def car_side(rng, length_m, height_m, px_m, body_bgr) -> Texture:
    """Side of a car: body colour, windows, wheels; alpha cuts the rounded outline."""
    w, h = max(8, int(length_m / px_m)), max(6, int(height_m / px_m))
    img = tint(body_bgr, grain(rng, h, w, ((1.0, 0.2), (20.0, 0.6))), 10.0)
    # shading: lighter roof line, darker sill
    shade = np.linspace(1.15, 0.75, h, dtype=np.float32)[:, None, None]
    img = np.clip(img * shade, 0, 255).astype(np.uint8)
    top = int(0.08 * h)
    win = np.array([[int(0.22 * w), top], [int(0.78 * w), top], [int(0.86 * w), int(0.45 * h)],
                    [int(0.12 * w), int(0.45 * h)]], np.int32)
    cv2.fillConvexPoly(img, win, (55, 45, 40))
    cv2.line(img, (int(0.52 * w), top), (int(0.52 * w), int(0.45 * h)), tuple(int(c) for c in body_bgr), 2)
    for cx in (0.2, 0.8):
        cv2.circle(img, (int(cx * w), int(0.82 * h)), int(0.19 * h), (25, 25, 25), -1)
        cv2.circle(img, (int(cx * w), int(0.82 * h)), int(0.09 * h), (150, 150, 150), -1)
    alpha = np.full((h, w), 255, np.uint8)
    cabin = np.array([[0, 0], [int(0.2 * w), 0], [0, int(0.4 * h)]], np.int32)
    cv2.fillConvexPoly(alpha, cabin, 0)
    cv2.fillConvexPoly(alpha, np.array([[w - 1, 0], [int(0.8 * w), 0], [w - 1, int(0.4 * h)]], np.int32), 0)
    return Texture(img, alpha)


def car_end(rng, width_m, height_m, px_m, body_bgr, front: bool) -> Texture:
    w, h = max(6, int(width_m / px_m)), max(6, int(height_m / px_m))
    img = tint(body_bgr, grain(rng, h, w, ((1.0, 0.2), (20.0, 0.6))), 10.0)
    cv2.rectangle(img, (int(0.1 * w), int(0.06 * h)), (int(0.9 * w), int(0.4 * h)), (55, 45, 40), -1)
    lamp = (200, 230, 240) if front else (30, 30, 170)
    for x in (0.12, 0.78):
        cv2.rectangle(img, (int(x * w), int(0.5 * h)), (int((x + 0.1) * w), int(0.58 * h)), lamp, -1)
    cv2.rectangle(img, (int(0.35 * w), int(0.6 * h)), (int(0.65 * w), int(0.7 * h)), (220, 220, 220), -1)
    alpha = np.full((h, w), 255, np.uint8)
    return Texture(img, alpha)


def cone(rng, h_px) -> Texture:
    """Orange-red traffic cone with white reflective bands."""
    w = max(4, int(h_px * 0.6))
    img = np.zeros((h_px, w, 3), np.uint8)
    img[:] = (30, 70, 230)
    for y0, y1 in ((0.3, 0.42), (0.55, 0.65)):
        img[int(y0 * h_px):int(y1 * h_px)] = (235, 235, 235)
    img[int(0.9 * h_px):] = (30, 30, 30)
    alpha = np.zeros((h_px, w), np.uint8)
    tri = np.array([[w // 2 - max(1, w // 12), 0], [w // 2 + max(1, w // 12), 0], [int(0.85 * w), int(0.9 * h_px)],
                    [int(0.15 * w), int(0.9 * h_px)]], np.int32)
    cv2.fillConvexPoly(alpha, tri, 255)
    alpha[int(0.9 * h_px):] = 255
    return Texture(img, alpha)


def metal(rng, h, w, base=(165, 165, 160)) -> np.ndarray:
    """Galvanised metal: the backs of signs, poles."""
    var = grain(rng, h, w, ((1.0, 0.3), (6.0, 0.4)))
    ramp = np.linspace(-12, 12, w, dtype=np.float32)[None, :]
    return tint(base, var + ramp / 8.0, 8.0)


def sky(height: int, width: int, horizon_v: float, fy: float, rng: np.random.Generator) -> np.ndarray:
    """Sky gradient by elevation above the horizon row, with faint clouds."""
    v = np.arange(height, dtype=np.float32)
    elev = np.clip((horizon_v - v) / fy, -0.2, 1.0)[:, None]
    zenith = np.array([200, 140, 80], np.float32)
    horizon = np.array([235, 220, 205], np.float32)
    t = np.clip(elev / 0.5, 0, 1)[..., None]
    img = np.broadcast_to(horizon * (1 - t) + zenith * t, (height, 1, 3))
    img = np.repeat(img, width, axis=1)
    clouds = smooth_noise(rng, height // 8 + 1, width // 8 + 1, 12.0)
    clouds = cv2.resize(np.clip(clouds, 0, None), (width, height), interpolation=cv2.INTER_LINEAR)[..., None]
    img = img + clouds * 60.0
    return np.clip(img, 0, 255).astype(np.uint8)
