"""Other designs of the same sign: mirrored pictograms, pictograms redrawn (size, place, stroke, detail), fonts.

The official drawing is one design of each sign; other print runs and other
Vienna-convention countries draw the same meaning differently (children and a
skidding car running the other way, larger pictograms, wider and bolder speed
digits, heavier or lighter strokes, simpler outlines). A network that has seen
only one design reads such faces by their details, so training shows it these
variants, generated here from the official drawings and system fonts by generic
image operations (affine and smooth elastic warps, grey morphology, blur), never
from photographs and never from another program's drawings of the signs.
"""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np

from .face_wear import colour_masks, smooth_field

# Pictograms whose mirror image means the same and is no other sign of the catalogue (not the curves
# 1.01-1.04, narrowing 1.08/1.09, descent and climb 1.10/1.11, oncoming traffic 1.26, overtaking
# 2.44/2.45, turns 2.42/2.43/2.46, entries 3.07/3.08, falling rocks 1.13/1.13a or the blue arrows).
MIRROR_SAFE = frozenset({
    "1.05", "1.06", "1.12", "1.14", "1.15", "1.16", "1.18", "1.22", "1.23", "1.24",
    "1.25", "1.27", "1.30", "1.31", "1.32",
    "2.03", "2.04", "2.05", "2.06", "2.07", "2.08", "2.09", "2.12", "2.13", "2.14", "2.15",
    "2.48", "2.60", "2.61", "2.62",
})

FONT_FILES = (  # Debian's fonts-dejavu-core; missing files are skipped, OpenCV's Hershey fonts always remain
    "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed-Bold.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed.ttf",
)
HERSHEY_FONTS = (cv2.FONT_HERSHEY_SIMPLEX, cv2.FONT_HERSHEY_DUPLEX)


def mirrored(face: np.ndarray, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return np.ascontiguousarray(face[:, ::-1]), np.ascontiguousarray(alpha[:, ::-1])


def inner_field(face: np.ndarray, alpha: np.ndarray) -> np.ndarray | None:
    """Mask of everything inside the red rim (field and pictogram, red parts of the pictogram included).

    None when the face has no red rim around a field (blue, yellow, white faces).
    """
    red, _ = colour_masks(face, alpha)
    if red.sum() < 0.05 * alpha.size:
        return None
    not_red = ((alpha > 127) & ~red).astype(np.uint8)
    n, labels, stats, centroids = cv2.connectedComponentsWithStats(not_red, connectivity=4)
    if n < 2:
        return None
    h, w = alpha.shape
    # the field is the largest non-red part that does not touch the face's outline box
    best, best_area = 0, 0
    for i in range(1, n):
        x, y, bw, bh, area = stats[i]
        if x > 0 and y > 0 and x + bw < w and y + bh < h and area > best_area:
            best, best_area = i, area
    if best == 0 or best_area < 0.1 * alpha.size:
        return None
    contours, _ = cv2.findContours((labels == best).astype(np.uint8), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    filled = np.zeros((h, w), np.uint8)
    cv2.drawContours(filled, contours, -1, 1, thickness=-1)
    return filled.astype(bool)


def _field_colour(face: np.ndarray, field: np.ndarray) -> np.ndarray:
    values = face[field].reshape(-1, 3)
    bright = values[values.sum(axis=1) >= np.percentile(values.sum(axis=1), 60)]
    return np.median(bright, axis=0)


def pictogram_scaled(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The pictogram inside the red rim drawn larger or smaller (0.85-1.3), the rim unchanged."""
    field = inner_field(face, alpha)
    if field is None:
        return face
    ys, xs = np.nonzero(field)
    centre = (float(xs.mean()), float(ys.mean()))
    colour = _field_colour(face, field)
    plain = np.where(field[..., None], face, colour).astype(np.float32)
    m = cv2.getRotationMatrix2D(centre, 0, float(rng.uniform(0.85, 1.3)))
    h, w = alpha.shape
    scaled = cv2.warpAffine(plain, m, (w, h), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT,
                            borderValue=tuple(float(c) for c in colour))
    return np.where(field[..., None], scaled, face).astype(face.dtype)


def _available_fonts() -> list:
    fonts: list = [("hershey", f) for f in HERSHEY_FONTS]
    fonts += [("truetype", path) for path in FONT_FILES if Path(path).is_file()]
    return fonts


def _text_mask(number: str, font, height_px: int, rng: np.random.Generator) -> np.ndarray:
    """A tight uint8 mask (255 = ink) of ``number`` in ``font``, about ``height_px`` high."""
    kind, which = font
    if kind == "truetype":
        from PIL import Image, ImageDraw, ImageFont

        pil_font = ImageFont.truetype(which, size=int(height_px * 1.35))
        canvas = Image.new("L", (height_px * 4 * len(number), height_px * 3), 0)
        ImageDraw.Draw(canvas).text((height_px // 2, height_px // 2), number, fill=255, font=pil_font)
        mask = np.asarray(canvas)
    else:
        scale = height_px / 22.0
        thickness = max(1, int(round(height_px * rng.uniform(0.09, 0.17))))
        (tw, th), base = cv2.getTextSize(number, which, scale, thickness)
        mask = np.zeros((th + base + 4 * thickness, tw + 4 * thickness), np.uint8)
        cv2.putText(mask, number, (2 * thickness, th + 2 * thickness), which, scale, 255, thickness, cv2.LINE_AA)
    ys, xs = np.nonzero(mask > 64)
    if len(xs) == 0:
        return np.zeros((height_px, height_px), np.uint8)
    return mask[ys.min():ys.max() + 1, xs.min():xs.max() + 1]


def speed_limit_face(ring: np.ndarray, ring_alpha: np.ndarray, number: str,
                     rng: np.random.Generator) -> np.ndarray:
    """A speed-limit face in another font: ``number`` drawn into the empty field of the 2.01 ring.

    Digit height 45-68 % and text width up to 88 % of the field inside the
    ring, as the Swiss, German, Austrian and French designs span.
    """
    field = inner_field(ring, ring_alpha)
    if field is None:
        return ring
    h, w = ring_alpha.shape
    cols = np.nonzero(field.any(axis=0))[0]
    field_px = float(cols.max() - cols.min() + 1)
    fonts = _available_fonts()
    font = fonts[int(rng.integers(len(fonts)))]
    text = _text_mask(number, font, max(8, int(field_px * rng.uniform(0.45, 0.68))), rng).astype(np.float32)
    text /= 255.0
    th, tw = text.shape
    new_w = int(min(field_px * rng.uniform(0.6, 0.88), tw * rng.uniform(0.8, 1.2)))  # condensed or extended
    text = cv2.resize(text, (max(1, new_w), th), interpolation=cv2.INTER_AREA)
    th, tw = text.shape
    ys, xs = np.nonzero(field)
    cx, cy = xs.mean() + rng.normal(0, 0.01 * w), ys.mean() + rng.normal(0, 0.01 * h)
    x0, y0 = int(round(cx - tw / 2)), int(round(cy - th / 2))
    ink_colour = np.array([rng.uniform(0, 40)] * 3, np.float32)
    out = ring.astype(np.float32).copy()
    xa, ya, xb, yb = max(0, x0), max(0, y0), min(w, x0 + tw), min(h, y0 + th)
    if xb <= xa or yb <= ya:
        return ring
    a = text[ya - y0:yb - y0, xa - x0:xb - x0][..., None] * field[ya:yb, xa:xb, None]
    out[ya:yb, xa:xb] = out[ya:yb, xa:xb] * (1 - a) + ink_colour * a
    return out.astype(ring.dtype)


def _dominant_colour(face: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Median colour of the most frequent colour bin (32 levels a channel) under ``mask``: the field's paint."""
    values = face[mask].reshape(-1, 3).astype(np.int32)
    bins = (values[:, 0] // 32) * 64 + (values[:, 1] // 32) * 8 + values[:, 2] // 32
    common = np.bincount(bins).argmax()
    return np.median(values[bins == common], axis=0).astype(np.float32)


def design_field(face: np.ndarray, alpha: np.ndarray):
    """(mask, colour) of the part of a face a pictogram is drawn in, or (None, None).

    Inside the red rim where there is one; else (blue, white, yellow faces) the
    convex hull of the face's most common paint inside a 3 % border, so a white
    edge or black frame stays out of it. The colour is that paint, what a
    pictogram is drawn on.
    """
    field = inner_field(face, alpha)
    if field is not None:
        return field, _dominant_colour(face, field)
    k = max(1, int(round(0.03 * max(alpha.shape))))
    disc = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * k + 1, 2 * k + 1))
    inside = cv2.erode((alpha > 127).astype(np.uint8), disc) > 0
    if inside.sum() < 0.1 * alpha.size:
        return None, None
    colour = _dominant_colour(face, inside)
    paint = (inside & (np.abs(face.astype(np.float32) - colour).sum(axis=2) < 60)).astype(np.uint8)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(paint, connectivity=8)
    big = [i for i in range(1, n) if stats[i, cv2.CC_STAT_AREA] > 0.02 * alpha.size]
    if not big:
        return None, None
    ys, xs = np.nonzero(np.isin(labels, big))
    hull = cv2.convexHull(np.column_stack([xs, ys]).astype(np.int32))
    field = np.zeros(alpha.shape, np.uint8)
    cv2.fillConvexPoly(field, hull, 1)
    field = (field > 0) & inside
    if field.sum() < 0.1 * alpha.size:
        return None, None
    return field, colour


def _warp_matrix(field: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Affine map about the field's centre: scale 0.7-1.2, aspect +-12 %, rotation +-4 deg, shear, shift +-4 %."""
    ys, xs = np.nonzero(field)
    cx, cy = float(xs.mean()), float(ys.mean())
    side = float(max(xs.max() - xs.min(), ys.max() - ys.min()) + 1)
    s = rng.uniform(0.7, 1.2)  # other designs draw the pictogram down to about 70 % of the official size
    aspect = rng.uniform(0.88, 1.12)
    a = np.radians(rng.uniform(-4, 4))
    shear = rng.uniform(-0.08, 0.08)
    lin = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]) @ np.array([[1, shear], [0, 1]]) \
        @ np.diag([s * aspect, s / aspect])
    shift = rng.uniform(-0.04, 0.04, 2) * side
    t = np.array([cx, cy]) + shift - lin @ np.array([cx, cy])
    return np.hstack([lin, t[:, None]]).astype(np.float64)


def _elastic(img: np.ndarray, colour, rng: np.random.Generator) -> np.ndarray:
    """A smooth random displacement (up to ~2.5 % of the face, features a quarter of it large)."""
    h, w = img.shape[:2]
    amp = rng.uniform(0.008, 0.025) * max(h, w)
    dx = smooth_field(rng, h, w, max(4, w / 4)) * amp
    dy = smooth_field(rng, h, w, max(4, h / 4)) * amp
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    return cv2.remap(img, xx + dx, yy + dy, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT,
                     borderValue=tuple(float(c) for c in colour))


def _restroke(img: np.ndarray, field: np.ndarray, colour: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Strokes 1-2 px bolder or 1 px lighter (at the 192 px working size) by grey morphology.

    Ink darker than the field (black on white) grows by erosion, lighter ink
    (white on blue) by dilation.
    """
    grey = img.mean(axis=2)
    ink = _ink(img, field, colour)
    if ink.sum() < 20:
        return img
    dark_ink = grey[ink].mean() < float(colour.mean())
    bolder = rng.random() < 0.6
    r = int(rng.integers(1, 3)) if bolder else 1
    k = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * r + 1, 2 * r + 1))
    grow = cv2.erode if dark_ink else cv2.dilate
    shrink = cv2.dilate if dark_ink else cv2.erode
    return (grow if bolder else shrink)(img, k)


def _simplified(img: np.ndarray, colour: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Fine detail lost, corners rounded: the pictogram blurred, then its contrast to the field restored."""
    sigma = rng.uniform(1.2, 3.0)
    blurred = cv2.GaussianBlur(img, (0, 0), sigma)
    gain = rng.uniform(1.1, 1.6)
    return np.clip(colour + (blurred - colour) * gain, 0, 255)


def _ink(img: np.ndarray, field: np.ndarray, colour: np.ndarray) -> np.ndarray:
    """Mask of the pictogram's paint: what differs clearly from the field's colour inside the field."""
    return (np.abs(img - colour).sum(axis=2) > 90) & field


def _line_drawn(img: np.ndarray, field: np.ndarray, colour: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The pictogram drawn with a thin pen: strokes 30-70 % of their width, broad parts kept, smaller.

    Other print runs and countries draw many pictograms as lines of one pen
    (thin curves and lanes, a slim arrow with a small head) where the official
    drawing has broad shapes. Everything is eroded to the new pen's width;
    strokes thinner than the erosion (whose whole neighbourhood is thin)
    survive as their distance ridge drawn with the new pen, so no part of the
    pictogram disappears and broad corners grow no spurs. Only pictograms of
    one paint (black, or white on blue) are redrawn; a many-coloured one is
    returned as it is.
    """
    inside = cv2.erode(field.astype(np.uint8), np.ones((9, 9), np.uint8)) > 0  # not the rim's soft edge
    ink = _ink(img, inside, colour)
    if ink.sum() < 40 or ink.sum() > 0.4 * inside.sum():  # too little, or the "field" paint is the pictogram
        return img
    paint = np.median(img[ink], axis=0)
    if np.percentile(np.abs(img[ink] - paint).sum(axis=1), 80) > 90:
        return img
    dist = cv2.distanceTransform(ink.astype(np.uint8), cv2.DIST_L2, 5)
    ridge = ink & (dist >= cv2.dilate(dist, np.ones((3, 3), np.uint8)) - 0.5) & (dist >= 1.0)
    if not ridge.any():
        return img
    half = float(np.median(dist[ridge]))
    if half < 2.5:  # already a line drawing at the working size
        return img
    new_half = max(1.5, half * rng.uniform(0.3, 0.7))
    erosion = half - new_half
    k = 2 * int(np.ceil(2 * erosion)) + 1
    thin = ridge & (cv2.dilate(dist, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (k, k))) <= erosion + 1)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(thin.astype(np.uint8), connectivity=8)
    short = [i for i in range(1, n) if stats[i, cv2.CC_STAT_AREA] < 2 * half]  # the tips of a cut end's spurs
    thin &= ~np.isin(labels, short)
    to_thin = cv2.distanceTransform((~thin).astype(np.uint8), cv2.DIST_L2, 5)
    cover = np.maximum(np.clip(new_half + 0.5 - to_thin, 0, 1), np.clip(dist - erosion + 0.5, 0, 1))
    cover = np.where(inside, cover, 0.0)[..., None].astype(np.float32)
    out = np.where(ink[..., None], colour, img).astype(np.float32)
    return out * (1 - cover) + paint.astype(np.float32) * cover


def pictogram_variant(face: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The pictogram redrawn inside its field, the rim and outline unchanged.

    Generic design variation built from the drawing itself: moved, scaled,
    stretched, sheared and turned a little (always), bent by a smooth elastic
    warp, stroked bolder or lighter, simplified or drawn with a thin pen. Everything outside the field
    (rim, border, outline) keeps the official drawing's pixels.
    """
    field, colour = design_field(face, alpha)
    if field is None:
        return face
    h, w = alpha.shape
    img = np.where(field[..., None], face, colour).astype(np.float32)
    img = cv2.warpAffine(img, _warp_matrix(field, rng), (w, h), flags=cv2.INTER_LINEAR,
                         borderMode=cv2.BORDER_CONSTANT, borderValue=tuple(float(c) for c in colour))
    if rng.random() < 0.5:
        img = _elastic(img, colour, rng)
    detail = rng.random()
    if detail < 0.3:
        img = _restroke(img, field, colour, rng)
    elif detail < 0.5:  # not both: a bolder and blurred pictogram loses what tells it from its neighbours
        img = _simplified(img, colour, rng)
    elif detail < 0.8:
        img = _line_drawn(img, field, colour, rng)
    return np.where(field[..., None], img, face).astype(face.dtype)
