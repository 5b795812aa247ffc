"""What years on a pole and a different print run do to a sign face, applied to a master image in face space.

Each step takes the face as float32 BGR 0..255 and the outline alpha, and a
seeded generator; strengths are drawn wide on purpose (training must cover
more than any one street shows), but a person could still read the sign.
"""

from __future__ import annotations

import cv2
import numpy as np

from signmapper_core.sign_colours import DRAWING_RED_HUES, DRAWING_RED_MIN_SATURATION, in_hue_bands


def smooth_field(rng: np.random.Generator, h: int, w: int, cell: float) -> np.ndarray:
    """Band-limited noise in about [-1, 1] with features ``cell`` pixels large."""
    gh, gw = max(2, int(h / cell) + 2), max(2, int(w / cell) + 2)
    grid = rng.standard_normal((gh, gw)).astype(np.float32)
    return cv2.resize(grid, (w, h), interpolation=cv2.INTER_CUBIC) * 0.6


def ink_variation(face: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Another print run: hue, saturation and value of the inks shifted a little."""
    hsv = cv2.cvtColor(np.clip(face, 0, 255).astype(np.uint8), cv2.COLOR_BGR2HSV).astype(np.float32)
    hsv[..., 0] = (hsv[..., 0] + rng.normal(0, 4.0)) % 180
    hsv[..., 1] *= rng.uniform(0.7, 1.1)
    hsv[..., 2] *= rng.uniform(0.7, 1.05)  # darker inks too: a dark red rim must not mean one class
    return cv2.cvtColor(np.clip(hsv, 0, 255).astype(np.uint8), cv2.COLOR_HSV2BGR).astype(np.float32)


def stroke_weight(face: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Thinner or bolder dark strokes (other font weight, ink spread): grey morphology by one pixel."""
    k = np.ones((3, 3), np.uint8) if rng.random() < 0.5 else cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))
    return cv2.erode(face, k) if rng.random() < 0.5 else cv2.dilate(face, k)


def fading(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Sun-faded face: saturation lost unevenly, red drifting to pink or orange, contrast towards a pale grey."""
    strength = rng.uniform(0.1, 0.65)
    h, w = face.shape[:2]
    uneven = np.clip(strength * (1 + 0.5 * smooth_field(rng, h, w, max(4, w / 3))), 0, 0.9)[..., None]
    grey = face.mean(axis=2, keepdims=True)
    pale = np.array(rng.uniform(170, 235, 3), np.float32) * 0.3 + 0.7 * rng.uniform(170, 235)
    out = face * (1 - uneven) + (0.5 * grey + 0.5 * pale) * uneven
    if rng.random() < 0.5:  # UV shift of the red ink
        red = (face[..., 2] > face[..., 1] + 40)[..., None]
        shift = np.array([rng.uniform(0, 60), rng.uniform(0, 50), 0], np.float32)
        out = np.where(red, out + shift * strength, out)
    return out


def dirt(face: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Grime: blotches, a darker band from the bottom edge, rain streaks."""
    h, w = face.shape[:2]
    colour = np.array(rng.uniform([40, 50, 55], [110, 120, 130]), np.float32)
    amount = np.clip(smooth_field(rng, h, w, max(3, w / 8)) - rng.uniform(0.0, 0.5), 0, 1) * rng.uniform(0.2, 0.7)
    if rng.random() < 0.5:
        amount = amount + np.linspace(0, rng.uniform(0.1, 0.5), h, dtype=np.float32)[:, None] ** 2
    if rng.random() < 0.3:
        streaks = np.zeros((h, w), np.float32)
        for _ in range(int(rng.integers(3, 12))):
            x = int(rng.integers(0, w))
            cv2.line(streaks, (x, int(rng.integers(0, h // 2))), (x, h - 1), float(rng.uniform(0.2, 0.5)),
                     max(1, w // 60))
        amount = amount + cv2.GaussianBlur(streaks, (0, 0), max(0.5, w / 150))
    amount = np.clip(amount, 0, 0.85)[..., None]
    return face * (1 - amount) + colour * amount


def stickers(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """One to three stickers or tags stuck on the face (a few per cent of its area each)."""
    h, w = face.shape[:2]
    ys, xs = np.nonzero(alpha > 127)
    if ys.size == 0:
        return face
    out = face.copy()
    for _ in range(int(rng.integers(1, 4))):
        i = int(rng.integers(ys.size))
        cy, cx = int(ys[i]), int(xs[i])
        sw, sh = int(w * rng.uniform(0.06, 0.2)), int(h * rng.uniform(0.04, 0.14))
        colour = tuple(float(c) for c in rng.uniform(0, 255, 3))
        if rng.random() < 0.6:
            cv2.rectangle(out, (cx - sw // 2, cy - sh // 2), (cx + sw // 2, cy + sh // 2), colour, -1)
        else:  # a scribbled tag
            pts = np.stack([cx + rng.normal(0, sw / 2, 6), cy + rng.normal(0, sh / 2, 6)], 1).astype(np.int32)
            cv2.polylines(out, [pts], False, colour, max(1, w // 50))
    return out


def retroreflective_sheen(face: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Sheeting: fine sparkle and a broad bright sheen from a light source behind the camera."""
    h, w = face.shape[:2]
    sparkle = rng.normal(0, rng.uniform(2, 10), (h, w, 1)).astype(np.float32)
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    cx, cy = rng.uniform(0, w), rng.uniform(0, h)
    sheen = np.exp(-(((xx - cx) / (0.5 * w)) ** 2 + ((yy - cy) / (0.5 * h)) ** 2))[..., None]
    return face + sparkle + sheen * rng.uniform(0, 70)


def peeling(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Patches where the sheeting came off and the grey aluminium shows."""
    h, w = face.shape[:2]
    spots = smooth_field(rng, h, w, max(3, w / 10)) > rng.uniform(0.55, 0.8)
    metal = np.array([175, 178, 180], np.float32) + rng.normal(0, 10)
    return np.where(spots[..., None], metal, face)


def colour_masks(face: np.ndarray, alpha: np.ndarray):
    """(red, white) masks of a face: the rim colour of prohibition and danger signs and the field inside."""
    hsv = cv2.cvtColor(np.clip(face, 0, 255).astype(np.uint8), cv2.COLOR_BGR2HSV)
    inside = alpha > 127
    red = inside & in_hue_bands(hsv[..., 0], DRAWING_RED_HUES) & (hsv[..., 1] >= DRAWING_RED_MIN_SATURATION)
    white = inside & (hsv[..., 1] < 50) & (hsv[..., 2] > 170)
    return red, white


def rim_width(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, wider: bool = True) -> np.ndarray:
    """A thinner red rim, as other countries and older print runs have it: the white field grown into the rim;
    sometimes a wider one, the red grown into the white field.

    Without this the width of the rim alone tells classes apart that differ in
    their text (a Swiss speed limit's rim is wider than most), which no real
    sign of another print run respects.
    """
    red, white = colour_masks(face, alpha)
    if red.sum() < 0.05 * alpha.size or white.sum() < 0.02 * alpha.size:
        return face
    if wider and rng.random() < 0.3:  # a wider rim (other print runs): red grown into the field by 1-4 % of the face
        return _grown_into(face, red, white, max(1, int(round(rng.uniform(0.01, 0.04) * max(face.shape[:2])))))
    # the Swiss speed-limit rim is ~17 % of the diameter, Germany's ~9 %: thin by up to ~10 % of the face
    return _grown_into(face, white, red, max(1, int(round(rng.uniform(0.015, 0.1) * max(face.shape[:2])))))


def _grown_into(face: np.ndarray, source: np.ndarray, target: np.ndarray, k: int) -> np.ndarray:
    """A copy of ``face`` whose ``target`` pixels within ``k`` px of ``source`` take ``source``'s median colour."""
    grown = cv2.dilate(source.astype(np.uint8), cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * k + 1, 2 * k + 1)))
    out = face.copy()
    out[(grown > 0) & target] = np.median(face[source], axis=0)
    return out


def white_edge(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """A white edge around the whole face (German and Austrian signs): the drawing shrunk inside its outline."""
    h, w = face.shape[:2]
    f = rng.uniform(0.9, 0.97)
    m = cv2.getRotationMatrix2D((w / 2, h / 2), 0, f)
    inner = cv2.warpAffine(face, m, (w, h), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
    inner_alpha = cv2.warpAffine(alpha, m, (w, h), flags=cv2.INTER_LINEAR).astype(np.float32)[..., None] / 255
    edge = np.array([rng.uniform(215, 250)] * 3, np.float32)
    return inner * inner_alpha + edge * (1 - inner_alpha)


def wear_face(face_bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator,
              wider_rims: bool = False) -> np.ndarray:
    """A randomly worn copy of a face (uint8 BGR), each effect switched on with its own probability.

    ``wider_rims`` lets rims grow as well as thin (False: thinner only, as the shipped model was trained).
    """
    face = face_bgr.astype(np.float32)
    if rng.random() < 0.45:
        face = rim_width(face, alpha, rng, wider=wider_rims)
    if rng.random() < 0.25:
        face = white_edge(face, alpha, rng)
    if rng.random() < 0.7:
        face = ink_variation(face, rng)
    if rng.random() < 0.25:
        face = stroke_weight(face, rng)
    if rng.random() < 0.4:
        face = fading(face, alpha, rng)
    if rng.random() < 0.35:
        face = dirt(face, rng)
    if rng.random() < 0.12:
        face = stickers(face, alpha, rng)
    if rng.random() < 0.3:
        face = retroreflective_sheen(face, rng)
    if rng.random() < 0.06:
        face = peeling(face, alpha, rng)
    return np.clip(face, 0, 255).astype(np.uint8)
