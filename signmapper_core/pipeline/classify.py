"""Step 7: hierarchical classification by normalised cross-correlation.

Colour and shape have already cut the catalogue to a few candidates; each is
rendered at the segment's size (a small scale and shift search absorbs the
segment's outline error) and compared with TM_CCOEFF_NORMED, masked with the
template's alpha so the background around the face does not count. The best
score is the classification indicator.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Dict, Optional, Sequence, Tuple

import cv2
import numpy as np

CANONICAL_PX = 128  # templates are rendered once at this size and resized per segment

_render_cache: Dict[Tuple[int, str], tuple] = {}


@dataclass(frozen=True)
class ClassificationResult:
    template_id: Optional[str]
    score: float  # best NCC, the classification indicator (clipped to 0..1)
    scores: Dict[str, float] = field(default_factory=dict)
    # a learned classifier's raw view: its largest logit for a candidate (how well the face matches the candidate
    # it resembles most) and, over every class it knows, its probability that the face is no sign
    fit: float = math.inf
    background: float = 0.0


def canonical_template(catalogue, template_id: str) -> tuple:
    """(bgr, alpha) of a template cropped to its face, rendered once per catalogue."""
    key = (id(catalogue), template_id)
    hit = _render_cache.get(key)
    if hit is not None and hit[0] is catalogue:
        return hit[1], hit[2]
    bgr, alpha = _cropped_to_face(*catalogue.render(template_id, CANONICAL_PX))
    _render_cache[key] = (catalogue, bgr, alpha)
    return bgr, alpha


def _cropped_to_face(bgr: np.ndarray, alpha: np.ndarray) -> tuple:
    ys, xs = np.nonzero(alpha > 127)
    if ys.size:
        y0, y1, x0, x1 = ys.min(), ys.max() + 1, xs.min(), xs.max() + 1
        bgr, alpha = bgr[y0:y1, x0:x1], alpha[y0:y1, x0:x1]
    return bgr, alpha


def canonical_drawings(catalogue, template_id: str) -> list:
    """:func:`canonical_template` of the entry and of each of its further drawings (a pointer pointing the other
    way, another language), each cropped to its face; the further ones rendered once per catalogue."""
    key = (id(catalogue), template_id + "~variants")
    hit = _render_cache.get(key)
    if hit is None or hit[0] is not catalogue:
        hit = (catalogue, [_cropped_to_face(*drawn) for drawn in catalogue.render_variants(template_id, CANONICAL_PX)])
        _render_cache[key] = hit
    return [canonical_template(catalogue, template_id)] + hit[1]


def drawings_at(catalogue, template_id: str, width: int, height: int) -> list:
    """:func:`template_at` of the entry's master and of each of its further drawings (:func:`canonical_drawings`)."""
    return [_sized(bgr, alpha, width, height) for bgr, alpha in canonical_drawings(catalogue, template_id)]


def canonical_templates(catalogue, threads: int = 1) -> Dict[str, tuple]:
    """:func:`canonical_template` of every template, without keeping the full-size images.

    For worker processes (:func:`seed_canonical_templates`): decoding the catalogue's PNGs once for all
    of them instead of once in each (~0.6 s of CPU and ~100 MB of full-size images a process).
    ``threads``: PNGs decoded side by side (OpenCV releases the GIL while it decodes and resizes).
    """
    def rendered(entry):
        return entry.id, _cropped_to_face(*catalogue.render(entry.id, CANONICAL_PX, keep_master=False))

    if threads <= 1:
        return dict(map(rendered, catalogue))
    with ThreadPoolExecutor(threads) as pool:
        return dict(pool.map(rendered, catalogue))


def seed_canonical_templates(catalogue, templates: Dict[str, tuple]) -> None:
    """Make ``templates`` (from :func:`canonical_templates` of an equal catalogue) ``catalogue``'s renderings."""
    for template_id, (bgr, alpha) in templates.items():
        _render_cache[(id(catalogue), template_id)] = (catalogue, bgr, alpha)


def template_at(catalogue, template_id: str, width: int, height: int) -> tuple:
    """Template (bgr, binary alpha) resized so its face fills width x height pixels."""
    return _sized(*canonical_template(catalogue, template_id), width, height)


def _sized(bgr: np.ndarray, alpha: np.ndarray, width: int, height: int) -> tuple:
    interp = cv2.INTER_AREA if width < bgr.shape[1] else cv2.INTER_LINEAR
    bgr = cv2.resize(bgr, (width, height), interpolation=interp)
    alpha = cv2.resize(alpha, (width, height), interpolation=cv2.INTER_LINEAR)
    return bgr, np.where(alpha > 127, 255, 0).astype(np.uint8)


def padded_crop(image: np.ndarray, x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """``image[y0:y1, x0:x1]`` with the part beyond the image border filled by replicating its edge.

    Any box works, also one partly or wholly outside the image (a face grown from a
    segment at the border): the result always has (y1 - y0, x1 - x0) pixels.
    """
    height, width = image.shape[:2]
    x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)
    if 0 <= x0 and 0 <= y0 and x1 <= width and y1 <= height:
        return image[y0:y1, x0:x1]
    rows = np.clip(np.arange(y0, y1), 0, height - 1)
    cols = np.clip(np.arange(x0, x1), 0, width - 1)
    return image[rows[:, None], cols[None, :]]


def crop_for_matching(image: np.ndarray, bbox, scales: Sequence[float], shift_fraction: float, max_px: int):
    """Region around ``bbox`` big enough for the scale and shift search, downscaled to ``max_px``.

    Returns (region, factor, (w, h) of the bbox at that factor). Pixels beyond the
    image border are replicated so the search never runs off the image, wherever the box lies.
    """
    x, y, w, h = (int(v) for v in bbox)
    w, h = max(1, w), max(1, h)
    side = max(w, h)
    factor = min(1.0, max_px / float(side))
    margin = int(math.ceil((max(scales) - 1.0) / 2.0 * side + shift_fraction * side)) + 2
    region = padded_crop(image, x - margin, y - margin, x + w + margin, y + h + margin)
    if factor < 1.0:
        region = cv2.resize(region, None, fx=factor, fy=factor, interpolation=cv2.INTER_AREA)
    return region, factor, (max(3, int(round(w * factor))), max(3, int(round(h * factor))))


def match_score(region: np.ndarray, tmpl: np.ndarray, alpha: np.ndarray) -> tuple:
    """Best masked TM_CCOEFF_NORMED of ``tmpl`` in ``region``: (score, (dx, dy) of the best offset)."""
    if tmpl.shape[0] > region.shape[0] or tmpl.shape[1] > region.shape[1] or not alpha.any():
        return -1.0, (0, 0)
    result = cv2.matchTemplate(region, tmpl, cv2.TM_CCOEFF_NORMED, mask=alpha)
    result = np.nan_to_num(result, nan=-1.0, posinf=-1.0, neginf=-1.0)
    _, best, _, loc = cv2.minMaxLoc(result)
    return float(best), loc


def _inner_mask(alpha: np.ndarray, fraction: float) -> np.ndarray:
    """The alpha eroded by ``fraction`` of the template size: the pictogram field without the rim."""
    k = max(1, int(round(fraction * min(alpha.shape))))
    return cv2.erode(alpha, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * k + 1, 2 * k + 1)))


def inner_field_distance(region: np.ndarray, catalogue, template_id: str, size, loc, inner_fraction: float) -> float:
    """Mean squared difference of the pictogram fields, both normalised over the whole face.

    Decides close calls. Unlike NCC on the inner field alone it is defined for a
    flat field (3.03's plain yellow against 3.04's stripes), and an occluder (a
    pole across the face) costs every candidate alike instead of looking like
    the stripes of one of them.
    """
    tw, th = size
    x, y = loc
    patch = region[y : y + th, x : x + tw].astype(np.float32)
    tmpl, alpha = template_at(catalogue, template_id, tw, th)
    if patch.shape[:2] != tmpl.shape[:2]:
        return float("inf")
    face = alpha > 0
    inner = _inner_mask(alpha, inner_fraction) > 0
    if not inner.any():
        return float("inf")

    def normalised(img):
        img = img.astype(np.float32)
        mean, std = img[face].mean(axis=0), img[face].std(axis=0) + 1e-3
        return (img - mean) / std

    return float(np.mean((normalised(patch)[inner] - normalised(tmpl)[inner]) ** 2))


def _best_over_scales(region, w, h, catalogue, tid, scales, inner_fraction=0.0):
    """(score, scale, location) of one template's best masked match in ``region``."""
    best = (-1.0, 1.0, (0, 0), (w, h))
    for s in scales:
        tw, th = max(3, int(round(w * s))), max(3, int(round(h * s)))
        tmpl, alpha = template_at(catalogue, tid, tw, th)
        tmpl = cv2.GaussianBlur(tmpl, (3, 3), 0)
        if inner_fraction > 0:
            alpha = _inner_mask(alpha, inner_fraction)
        score, loc = match_score(region, tmpl, alpha)
        if score > best[0]:
            best = (score, s, loc, (tw, th))
    return best


def classify_segment(
    image: np.ndarray,
    bbox,
    catalogue,
    template_ids: Sequence[str],
    config,
) -> ClassificationResult:
    """Best-matching template among ``template_ids`` for the face in ``bbox`` of ``image``.

    Coarse to fine (``config``, a PipelineConfig): all candidates are compared at
    ``coarse_template_px`` without scale search, the best ``coarse_keep`` at up
    to ``max_template_px`` with the scale and shift search. Candidates within
    ``tie_margin`` of the best are decided on the pictogram field alone, the
    face without its outer ``inner_fraction`` (:func:`inner_field_distance`).
    """
    settings = config.classification
    scales, shift_fraction, keep = settings.scales, settings.shift_fraction, settings.coarse_keep
    if not template_ids:
        return ClassificationResult(None, 0.0)
    ids = list(dict.fromkeys(template_ids))
    if len(ids) > keep:
        region, _, (w, h) = crop_for_matching(image, bbox, (1.0,), shift_fraction, settings.coarse_template_px)
        region = cv2.GaussianBlur(region, (3, 3), 0)
        coarse = {tid: _best_over_scales(region, w, h, catalogue, tid, (1.0,))[0] for tid in ids}
        ids = sorted(ids, key=coarse.get, reverse=True)[:keep]
    region, _, (w, h) = crop_for_matching(image, bbox, scales, shift_fraction, settings.max_template_px)
    region = cv2.GaussianBlur(region, (3, 3), 0)  # both sides slightly smoothed: less aliasing
    fine = {tid: _best_over_scales(region, w, h, catalogue, tid, scales) for tid in ids}
    scores = {tid: float(r[0]) for tid, r in fine.items()}
    ranked = sorted(ids, key=scores.get, reverse=True)
    best_id = ranked[0]
    close = [t for t in ranked if scores[t] >= scores[best_id] - settings.tie_margin]
    if len(close) > 1:
        distance = {t: inner_field_distance(region, catalogue, t, fine[t][3], fine[t][2], settings.inner_fraction)
                    for t in close}
        best_id = min(close, key=distance.get)
    return ClassificationResult(best_id, float(np.clip(fine[best_id][0], 0.0, 1.0)), scores)


def surround_score(image: np.ndarray, face, catalogue, template_id: str, extent, grow: float,
                   max_saturation: Optional[int] = None) -> float:
    """NCC of a template's face outside its coloured part, at the face box without search.

    Tells a zone panel (white field and text around the red ring) from a round
    sign on a wall: only the pixels outside the colour part, grown by ``grow`` of the face, count.
    With ``max_saturation``, a surround the drawing has achromatic (its median saturation at most that) must be
    so in the image too, else -1: the grey levels of a pale blue sky around a disc high on a pole match a zone
    panel's white. Each drawing of the entry is compared (a pointer is made pointing either way); the best counts.
    """
    x, y, w, h = face
    height, width = image.shape[:2]
    if w < 4 or h < 4 or x < 0 or y < 0 or x + w > width or y + h > height:
        return -1.0
    crop = image[y : y + h, x : x + w]
    return max(_surround_match(crop, tmpl, alpha, extent, grow, max_saturation)
               for tmpl, alpha in drawings_at(catalogue, template_id, w, h))


def _surround_match(crop: np.ndarray, tmpl: np.ndarray, alpha: np.ndarray, extent, grow: float,
                    max_saturation: Optional[int]) -> float:
    h, w = crop.shape[:2]
    fx0, fy0, fx1, fy1 = extent
    alpha[max(0, int((fy0 - grow) * h)) : int(np.ceil((fy1 + grow) * h)),
          max(0, int((fx0 - grow) * w)) : int(np.ceil((fx1 + grow) * w))] = 0
    if np.count_nonzero(alpha) < 16:
        return -1.0
    if max_saturation is not None:
        around = alpha > 0
        drawn = np.median(cv2.cvtColor(tmpl, cv2.COLOR_BGR2HSV)[..., 1][around])
        seen = np.median(cv2.cvtColor(crop, cv2.COLOR_BGR2HSV)[..., 1][around])
        if drawn <= max_saturation < seen:
            return -1.0
    score, _ = match_score(crop, tmpl, alpha)
    return score
