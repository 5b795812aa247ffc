"""The two artworks a synthetic sign face is printed from.

* ``master``: the catalogue's master image (``templates/ch/png``, the official
  drawings) or one of the entry's variant drawings, resampled to the face size
  with a small random placement of the print on the blank (shift, scale,
  rotation), so even a face at the master's own size is a resampling, never a
  pixel copy.
* ``procedural``: the catalogue's procedural drawer with a random FaceStyle
  (pen widths, palette, font, details), an independent drawing of the sign.

Which of the two a sign gets is a seeded choice per sign (``choose_artwork``).
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import cv2
import numpy as np

from ..catalogue import FaceStyle, load_catalogue, render_face
from ..catalogue.model import DEFAULT_CATALOGUE_DIR, Catalogue
from ..catalogue.signs_ch import SIGNS

MASTER, PROCEDURAL = "master", "procedural"
MASTER_CACHE_PX = 800  # masters are kept at most this large: faces are at most 640 px
POINTED_END = 0.8  # a panel's end whose outline covers less than this share of the other end's is its point


# Signs whose procedural drawing shows another pictogram than the official drawing: another object, another
# view of it, or elements added or missing; judged by looking at both side by side for every sign the drawer
# knows (``python -m signmapper_core.simulate.artwork_sheet``), not from recognition results. Pens, proportions,
# fonts, a simpler or bolder outline of the same object do not count. Faces of these signs ask a reader to know
# a design the official drawing does not show, like the real photographs' "differs" group; the evaluation
# reports them apart.
OTHER_PICTOGRAM = {
    "1.05": "a car from behind over two wavy tracks; official: a skidding car from the side",
    "1.06": "one hump; official: two",
    "1.12": "a car from the front over dots; official: a car from the side throwing gravel",
    "1.18": "a tram from the front; official: from the side",
    "1.31": "two cars from the front, one above the other; official: a queue of three",
    "1.32": "a cyclist; official: a bicycle alone",
    "2.03": "a car from the side; official: from the front",
    "2.10.1": "a lorry carrying the orange plate; official: the plate alone",
    "2.11": "a lorry over drops; official: a tanker over waves",
    "2.12": "a rider on a horse; official: a horse alone",
    "2.13": "car and motorcycle without the bar between them",
    "2.14": "three vehicles stacked; official: three in a Y parted by red bars",
    "2.20-10": "a lorry over a line and the length, no arrows",
    "2.48": "a wheel with spikes from the front; official: a chained tyre",
    "4.18": "a clock; official: a parking disc",
}

OFFICIAL_PICTOGRAM, OTHER = "official pictogram", "other pictogram"


def pictogram_group(template_id: str, artwork: str) -> str:
    """The face's pictogram group: ``official pictogram`` for master faces and procedural drawings of the same
    object, ``other pictogram`` for the procedural drawings of :data:`OTHER_PICTOGRAM`; "" where the artwork is
    unknown."""
    if not artwork:
        return ""
    return OTHER if artwork == PROCEDURAL and template_id in OTHER_PICTOGRAM else OFFICIAL_PICTOGRAM


def choose_artwork(rng: np.random.Generator, master_share: float) -> str:
    """``master`` with probability ``master_share``, else ``procedural``."""
    return MASTER if rng.random() < master_share else PROCEDURAL


def has_procedural(template_id: str) -> bool:
    """Whether the catalogue's procedural drawer knows the sign (a catalogue may carry others)."""

    return template_id in SIGNS


@lru_cache(maxsize=1)
def _entries() -> dict:
    """The bundled catalogue's entries (their drawings' paths), read once."""

    return load_catalogue().entries


def drawing_stems(template_id: str) -> tuple[str, ...]:
    """File stems of the official drawings a master face of the sign can be printed from: the entry's master,
    then its variants (other language versions, the other pointing direction, the other boards of a row)."""
    entry = _entries()[template_id]
    return tuple(Path(png).stem for png in (entry.png, *entry.variants))


@lru_cache(maxsize=24)  # bounded: memory stays flat however many different signs a drive has
def _master(template_id: str, drawing: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """(bgr, alpha) of the bundled catalogue's master (``drawing`` 0) or its ``drawing``-th variant, reduced to
    MASTER_CACHE_PX on its longer side."""

    catalogue = Catalogue(DEFAULT_CATALOGUE_DIR, _entries())  # a fresh catalogue: its full-size cache is dropped
    bgr, alpha = catalogue.master(template_id) if drawing == 0 else catalogue.variant_masters(template_id)[drawing - 1]
    scale = MASTER_CACHE_PX / max(bgr.shape[:2])
    if scale < 1:
        size = (max(1, round(bgr.shape[1] * scale)), max(1, round(bgr.shape[0] * scale)))
        bgr = cv2.resize(bgr, size, interpolation=cv2.INTER_AREA)
        alpha = cv2.resize(alpha, size, interpolation=cv2.INTER_AREA)
    return bgr, alpha


def pointing(template_id: str, drawing: int = 0) -> int:
    """Which way a drawing's panel points: 1 right, -1 left (its pointed end is the narrower one), 0 neither
    (a rectangle, a disc). A direction sign stands on its pole at its blunt end."""
    alpha = _master(template_id, drawing)[1].astype(np.float32)
    band = max(1, alpha.shape[1] // 20)
    left, right = alpha[:, :band].mean(), alpha[:, -band:].mean()
    if right < POINTED_END * left:
        return 1
    if left < POINTED_END * right:
        return -1
    return 0


def master_face(template_id: str, size_wh: tuple[int, int], rng: np.random.Generator, drawing: int = 0
                ) -> tuple[np.ndarray, np.ndarray]:
    """Master artwork (or its ``drawing``-th variant) at (w, h): outline from the drawing's alpha, print placed
    with a small random error."""
    w, h = int(size_wh[0]), int(size_wh[1])
    src_bgr, src_alpha = _master(template_id, drawing)
    shrink = w <= src_bgr.shape[1] and h <= src_bgr.shape[0]
    interp = cv2.INTER_AREA if shrink else cv2.INTER_LINEAR
    bgr = cv2.resize(src_bgr, (w, h), interpolation=interp)
    alpha = cv2.resize(src_alpha, (w, h), interpolation=interp)
    # print placement tolerance on the blank: about +-0.4 % shift, +-0.5 % scale, +-0.4 degrees
    scale = 1.0 + rng.uniform(-0.005, 0.005)
    angle = rng.uniform(-0.4, 0.4)
    shift = rng.uniform(-0.004, 0.004, 2) * (w, h)
    matrix = cv2.getRotationMatrix2D(((w - 1) / 2.0, (h - 1) / 2.0), angle, scale)
    matrix[:, 2] += shift
    bgr = cv2.warpAffine(bgr, matrix, (w, h), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
    return np.ascontiguousarray(bgr), np.ascontiguousarray(alpha)


def procedural_face(template_id: str, size_wh: tuple[int, int], rng: np.random.Generator
                    ) -> tuple[np.ndarray, np.ndarray]:
    """The catalogue's procedural drawing at (w, h) with a random style drawn from ``rng``."""

    w, h = int(size_wh[0]), int(size_wh[1])
    style = FaceStyle.random(rng, strength=float(rng.uniform(0.5, 1.0)))
    bgr, alpha = render_face(template_id, (w, h), style=style)
    if bgr.shape[:2] != (h, w):
        bgr = cv2.resize(bgr, (w, h), interpolation=cv2.INTER_AREA)
        alpha = cv2.resize(alpha, (w, h), interpolation=cv2.INTER_AREA)
    return np.ascontiguousarray(bgr), np.ascontiguousarray(alpha)
