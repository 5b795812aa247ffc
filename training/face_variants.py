"""Other designs of the same sign: mirrored pictograms, larger or smaller pictograms, other digit fonts.

The official drawing is one design of each sign; other print runs and other
Vienna-convention countries draw the same meaning differently (children and a
skidding car running the other way, larger pictograms, wider and bolder speed
digits). A network that has seen only one design reads such faces by their
details, so training shows it these variants, generated here from the official
drawings and system fonts, never from photographs.
"""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np

from .face_wear import colour_masks

# Pictograms whose mirror image means the same and is no other sign of the catalogue (not the curves
# 1.01-1.04, narrowing 1.08/1.09, descent and climb 1.10/1.11, oncoming traffic 1.26, overtaking
# 2.44/2.45, turns 2.42/2.43/2.46, entries 3.07/3.08 or the blue arrows).
MIRROR_SAFE = frozenset({
    "1.05", "1.06", "1.12", "1.13", "1.14", "1.15", "1.16", "1.18", "1.22", "1.23", "1.24",
    "1.25", "1.27", "1.30", "1.31", "1.32",
    "2.03", "2.04", "2.05", "2.06", "2.07", "2.08", "2.09", "2.12", "2.13", "2.14", "2.15",
    "2.48", "2.60", "2.61", "2.62",
})

SPEED_LIMIT_PREFIX = "2.30-"  # 2.30-20 ... 2.30-120: a number in the 2.01 ring

FONT_FILES = (  # Debian's fonts-dejavu-core; missing files are skipped, OpenCV's Hershey fonts always remain
    "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed-Bold.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/dejavu/DejaVuSansCondensed.ttf",
)
HERSHEY_FONTS = (cv2.FONT_HERSHEY_SIMPLEX, cv2.FONT_HERSHEY_DUPLEX)


def speed_limit_number(template_id: str) -> str | None:
    """'80' for 2.30-80; None for every other id (2.30.1's lettered ring is not a plain number)."""
    if not template_id.startswith(SPEED_LIMIT_PREFIX):
        return None
    number = template_id[len(SPEED_LIMIT_PREFIX):]
    return number if number.isdigit() else None


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
