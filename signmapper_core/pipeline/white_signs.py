"""White and grey signs from their outline candidates (``white_outlines``), judged by depth and templates.

A candidate is a white sign when it stands where signs stand and is what signs are: inside the search
space, of a standard white format at its depth, planar and upright (the detection indicator, as for
every sign), standing free (its sides at its own depth are not a wall or a van's body: windows, shop
signs and house numbers sit in a façade), held by a support below it (a pole, seen as straight vertical
edges or at its depth, or the sign under it on the same pole; without one it must resemble its template
more clearly), and resembling a white template (the paper's template matching, NCC, among the white
entries). Its id is then read by the pipeline's classifier where that knows every white candidate (a network
trained on them), else it is the template matching's.
"""

from __future__ import annotations

from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from ..catalogue.model import MEASURED
from ..fusion.face_normal import world_face_normal
from ..output.review_reasons import WHITE_UNREAD
from ..statuses import ACCEPTED, REVIEW
from .boxes import centre_inside, share_inside
from .classifiers import accept_threshold
from .classify import ClassificationResult, classify_segment
from .colour import Segment, inscribed_disc
from .detection import Detection
from .hough import band_colour_shares, outer_ring, weak_colour
from .locate import bbox_centre, locate
from .pair_context import PairContext
from .search_range import face_depth, face_depth_limits, face_in_range
from .search_space import valid_depth
from .shape import catalogue_shapes
from .sizing import measure_segment, metric_size, round_to_format
from .white_outlines import (
    WhiteCandidate,
    face_side_range_px,
    format_outline,
    panel_around,
    ring_around,
    scan_scale,
    white_formats,
)


def _same_depth(values: np.ndarray, z: float, config) -> np.ndarray:
    """Which of ``values`` lie at depth ``z`` (within ``white_same_depth_m`` or ``white_same_depth_share``)."""
    tol = max(config.white.white_same_depth_m, config.white.white_same_depth_share * z)
    with np.errstate(invalid="ignore"):
        return valid_depth(values) & (np.abs(values - z) <= tol)


def _side_bands(depth: np.ndarray, bbox, config) -> Tuple[np.ndarray, np.ndarray]:
    """The depths of the band left and of the band right of the face at its rows (a gap left out)."""
    x, y, w, h = bbox
    width = depth.shape[1]
    gap, band = int(round(config.white.white_side_gap * w)), max(1, int(round(config.white.white_side_band * w)))
    rows = depth[y : y + h]
    return (rows[:, max(0, x - gap - band) : max(0, x - gap)].ravel(),
            rows[:, min(width, x + w + gap) : min(width, x + w + gap + band)].ravel())


def _share_at_depth(values: np.ndarray, z: float, config) -> Optional[float]:
    """Share of ``values`` with a depth that lie at depth ``z``; None where too few have a depth to tell."""
    valid = valid_depth(values)
    if values.size == 0 or np.count_nonzero(valid) < config.white.white_min_side_valid * values.size:
        return None
    return float(np.count_nonzero(_same_depth(values, z, config))) / np.count_nonzero(valid)


def side_share(depth: np.ndarray, bbox, z: float, config) -> Optional[float]:
    """Share of the pixels with depth beside the face (left and right bands at its rows, a gap left out) that
    lie at the face's depth; None where too few have a depth to tell."""
    return _share_at_depth(np.concatenate(_side_bands(depth, bbox, config)), z, config)


def side_shares(depth: np.ndarray, bbox, z: float, config) -> Tuple[Optional[float], Optional[float]]:
    """:func:`side_share` of the band left and of the band right of the face, each alone."""
    left, right = _side_bands(depth, bbox, config)
    return _share_at_depth(left, z, config), _share_at_depth(right, z, config)


def support_share(depth: np.ndarray, bbox, z: float, config) -> float:
    """Share of the rows of a strip below the face (its middle, ``white_support_width`` of its width) that hold
    a pixel at the face's depth: a pole, or the next sign on the same pole."""
    x, y, w, h = bbox
    height = depth.shape[0]
    top = y + h + int(round(config.white.white_support_gap * h))
    bottom = min(height, top + max(1, int(round(config.white.white_support_length * h))))
    half = max(1, int(round(config.white.white_support_width * w / 2)))
    cx = x + w // 2
    strip = depth[top:bottom, max(0, cx - half) : cx + half + 1]
    if strip.size == 0:
        return 0.0
    return float(np.count_nonzero(_same_depth(strip, z, config).any(axis=1))) / strip.shape[0]


def pole_share(grey: np.ndarray, bbox, config) -> float:
    """Largest share of the rows of the strip below the face (its middle, ``white_support_width`` of its width)
    in which one column (give or take one) carries a strong vertical edge: the edges of a pole run straight
    down through every row, where grass, paving or a wall behind give scattered ones. Thin uniform poles often
    get no depth from matching, so the image speaks for them."""
    x, y, w, h = bbox
    height, width = grey.shape[:2]
    top = y + h + int(round(config.white.white_support_gap * h))
    bottom = min(height, top + max(1, int(round(config.white.white_support_length * h))))
    half = max(2, int(round(config.white.white_support_width * w / 2)))
    cx = x + w // 2
    x0, x1 = max(0, cx - half), min(width, cx + half + 1)
    if bottom - top < 3 or x1 - x0 < 3:
        return 0.0
    strip = cv2.blur(grey[top:bottom, x0:x1], (1, config.white.white_pole_blur_rows))  # along the pole
    gx = np.abs(cv2.Sobel(strip, cv2.CV_32F, 1, 0, ksize=3))
    strong = cv2.dilate((gx >= config.white.white_pole_edge).astype(np.uint8), np.ones((1, 3), np.uint8))
    return float(strong.mean(axis=0).max())


def coloured_rim(bgr: np.ndarray, mask: np.ndarray, config) -> bool:
    """Whether a disc's outer ring carries a weak colour of its own (a faded red or blue rim), not merely the
    tint of the light on a white face: the ring names a colour (:func:`.hough.weak_colour`) and is more
    saturated than the field inside it by ``white_rim_saturation_step``. Warm façades and a low sun tint a
    whole white face pink or yellow alike (ring and field within a few levels); a faded rim stands out."""
    if weak_colour(bgr, mask, config) == "white":
        return False
    ring = outer_ring(mask, config) > 0
    inner = cv2.erode(mask, np.ones((3, 3), np.uint8),
                      iterations=max(1, int(mask.shape[0] * config.white.white_rim_field_depth))) > 0
    if not ring.any() or not inner.any():
        return True
    saturation = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)[:, :, 1]
    step = float(np.median(saturation[ring])) - float(np.median(saturation[inner]))
    return step >= config.white.white_rim_saturation_step


def in_coloured_ring(bgr: np.ndarray, bbox, config) -> bool:
    """Whether the disc ``bbox`` is the white field of a red or blue ring: the band ``white_ring_band`` times its
    radius out is at least ``white_min_ring_share`` one of those colours (the colour step's ranges, pixels in the
    image only), and the band ``white_beyond_band`` out less than half as much (a ring ends; a red wall or a
    blue sky behind a white disc goes on). The colour step drops a ring the image edge cuts; its field stays a
    white candidate and must not be read as a white sign."""
    white = config.white
    ranges = [config.colour.hsv_ranges[colour] for colour in ("red", "blue")]
    (near_seen, near), (beyond_seen, beyond) = band_colour_shares(
        bgr, bbox, (white.white_ring_band, white.white_beyond_band), ranges)
    if not near_seen or not beyond_seen:
        return False
    return any(share >= white.white_min_ring_share and farther < share / 2.0 for share, farther in zip(near, beyond))


def coloured_share(bgr: np.ndarray, bbox, config) -> float:
    """Share of the pixels in ``bbox`` more saturated than an achromatic pixel (``white_max_saturation``)."""
    x, y, w, h = bbox
    saturation = cv2.cvtColor(bgr[y : y + h, x : x + w], cv2.COLOR_BGR2HSV)[:, :, 1]
    return float(np.count_nonzero(saturation > config.white.white_max_saturation)) / max(1, saturation.size)


def white_template_ids(catalogue, shape: str, bbox, config) -> List[str]:
    """Ids of the white entries a ``shape`` outline of box ``bbox`` may be."""
    shapes = catalogue_shapes(shape, bbox[2], bbox[3])
    exclude = tuple(config.classification.exclude)
    return [e.id for e in catalogue.filter(colours=["white"], shapes=list(shapes), exclude=exclude)]


def _format_sizes_px(pair: PairContext, depth_m: float) -> List[Tuple[str, float, float]]:
    """(shape, width, height) in pixels at ``depth_m`` of the white entries' formats the white step seeks."""
    camera, config = pair.camera, pair.config
    exclude = tuple(config.classification.exclude)
    return sorted({(e.shape if e.shape == "circle" else "rectangle", fw * camera.fx / depth_m,
                    fh * camera.fy / depth_m)
                   for e in pair.catalogue.filter(colours=["white"], exclude=exclude) for fw, fh in e.formats.values()
                   if max(fw, fh) <= config.white.white_max_side_m})


def _scan_scale(pair: PairContext) -> float:
    """The reduction at which the white step scans the image (its smallest face keeps ``white_scan_side_px``)."""
    return scan_scale(face_side_range_px(pair.camera, white_formats(pair.catalogue, pair.config), pair.config)[0],
                      pair.config)


def format_candidates(cand: WhiteCandidate, pair: PairContext, depth_m: float, grey: np.ndarray
                      ) -> List[WhiteCandidate]:
    """``cand`` read again as the outline of a white format at ``depth_m`` that lies best on strong edges near
    it (:func:`.white_outlines.format_outline`): of its own shape, and of the other (a disc above its plate
    read as a panel; a panel cut short holds its zone's disc, whose outline may lie on stronger edges). None
    with ``white_format_fit`` off. ``grey``: the left image in grey levels."""
    if not pair.config.white.white_format_fit or not depth_m > 0:
        return []
    sizes, scale = _format_sizes_px(pair, depth_m), _scan_scale(pair)
    out = []
    for same in (True, False):
        found = format_outline(grey, cand.segment.bbox, [s for s in sizes if (s[0] == cand.shape) == same],
                               scale, pair.config)
        if found is not None:
            out += _outline_candidate(found[0], found[1], grey.shape[:2], cand.segment.touches_border)
    return out


def panel_candidates(cand: WhiteCandidate, pair: PairContext, depth_m: float, grey: np.ndarray
                     ) -> List[WhiteCandidate]:
    """The outline of a white panel format at ``depth_m`` around the disc ``cand``, as a candidate
    (:func:`.white_outlines.panel_around`); none without one, or with ``white_panel_around`` off."""
    if not pair.config.white.white_panel_around or cand.shape != "circle" or not depth_m > 0:
        return []
    sizes = [(w, h) for shape, w, h in _format_sizes_px(pair, depth_m) if shape == "rectangle"]
    found = panel_around(grey, cand.segment.bbox, sizes, _scan_scale(pair), pair.config)
    return _outline_candidate(found[0], found[1], grey.shape[:2], cand.segment.touches_border) if found else []


def _outline_candidate(shape: str, box, image_shape, touches_border: bool) -> List[WhiteCandidate]:
    """A candidate of ``shape`` filling ``box`` (none when the box leaves the image)."""
    x, y, w, h = box
    height, width = image_shape
    if x < 0 or y < 0 or x + w > width or y + h > height or w < 2 or h < 2:
        return []
    if shape == "circle":
        mask, contour = inscribed_disc(w)
        h = w
    else:
        mask = np.full((h, w), 255, np.uint8)
        contour = np.array([[[0, 0]], [[w - 1, 0]], [[w - 1, h - 1]], [[0, h - 1]]], np.int32)
    seg = Segment("white", (x, y, w, h), mask, contour + np.array([x, y]), int(np.count_nonzero(mask)),
                  touches_border, source="white")
    return [WhiteCandidate(seg, shape)]


def _network_read(pair: PairContext, bbox, ids: Sequence[str]) -> Optional[Tuple[ClassificationResult, float]]:
    """(reading, acceptance threshold) of the pipeline's classifier among ``ids`` where it knows every one of
    them; None where only template matching does (a network trained before entries were catalogued)."""
    reader = pair.classifier_knowing(ids)
    if reader is pair.template_matcher:
        return None
    return reader.classify(pair.left, bbox, ids), accept_threshold(reader, pair.config)


def read_white_face(pair: PairContext, bbox, ids: Sequence[str], matched: ClassificationResult
                    ) -> Tuple[ClassificationResult, str, str]:
    """(classification, status, review reason) of a white face that resembles a white template (``matched``:
    template matching among ``ids``). The pipeline's classifier reads it when it knows every one of ``ids`` (a
    network trained on the white family reads pictograms, not the correlation of pale faces, and its indicator
    is calibrated like every other sign's); otherwise, or when it reads no id, the template matching stands."""
    known = _network_read(pair, bbox, ids)
    if known is None:
        return matched, ACCEPTED if matched.score >= pair.config.white.white_accept_score else REVIEW, ""
    read, accept = known
    if read.template_id is None:
        return matched, REVIEW, WHITE_UNREAD  # resembles a white template, but the network reads none of them
    return read, ACCEPTED if read.score >= accept else REVIEW, ""


def network_reading(pair: PairContext, bbox, ids: Sequence[str]) -> Optional[ClassificationResult]:
    """The pipeline's classifier's reading of a white face among ``ids`` where it knows them all (not template
    matching) and reads one of them at or above its acceptance threshold; else None."""
    known = _network_read(pair, bbox, ids)
    if known is None or known[0].template_id is None or known[0].score < known[1]:
        return None
    return known[0]


def judge_white(cand: WhiteCandidate, pair: PairContext, depth: np.ndarray, grey: np.ndarray,
                refit_format: bool = True, panels: Optional[list] = None) -> Optional[Detection]:
    """The white sign ``cand`` is, or None (cut, off the search space, no white format, not planar, not
    standing free, no support, no template resembling it). ``grey``: the left image in grey levels. A face
    whose size fits no white format is judged once more as the best outline of a format at its depth
    (:func:`format_candidates`), and a disc read as a sign once more as the zone disc of a panel around it
    (:func:`panel_candidates`), unless ``refit_format`` is off. ``panels``: a list that receives the box of
    every rectangle standing free with a white panel's format and planarity, whatever its template scores."""
    found = _judge_face(cand, pair, depth, grey, refit_format, panels)
    if found is None or cand.shape != "circle" or not refit_format:
        return found
    # sought only around a disc read as a sign: around every disc candidate, mapping took 40 % longer (tune
    # drives 1700-1702, white step on)
    around = [judge_white(c, pair, depth, grey, False, panels)
              for c in panel_candidates(cand, pair, found.depth_m, grey)]
    return max((d for d in around if d is not None), key=lambda d: d.classification_indicator, default=found)


def _judge_face(cand: WhiteCandidate, pair: PairContext, depth: np.ndarray, grey: np.ndarray,
                refit_format: bool, panels: Optional[list]) -> Optional[Detection]:
    """:func:`judge_white` of ``cand`` itself and of the formats refitted to it."""
    camera, catalogue, config = pair.camera, pair.catalogue, pair.config
    white = config.white
    seg = cand.segment
    if seg.touches_border:
        return None
    x, y, w, h = seg.bbox
    if cand.shape == "circle" and coloured_rim(pair.left[y : y + h, x : x + w], seg.mask, config):
        return None  # a faded red or blue ring: the Hough fallback reads it as its colour
    if cand.shape == "circle" and in_coloured_ring(pair.left, seg.bbox, config):
        return None  # the field of a red or blue ring (cut by the image edge, so no colour sign)
    ids = white_template_ids(catalogue, cand.shape, seg.bbox, config)
    if not ids:
        return None
    size = measure_segment(camera, depth, seg.bbox, seg.mask, *face_depth_limits(camera, seg.bbox, config.depth))
    if size is None or size.coverage < config.planarity.min_depth_coverage or \
            not face_in_range(camera, seg.bbox, size.depth_m, config.depth):
        return None
    if cand.shape == "circle":  # a disc seen at an angle: its larger axis is the diameter
        side = max(w, h)
        width_m, height_m = metric_size(camera, (x, y, side, side), size.depth_m)
    else:
        width_m, height_m = size.width_m, size.height_m
    match = round_to_format(catalogue, [catalogue[t] for t in ids], width_m, height_m, config.size.size_tolerance)
    ids = [t for t in match.template_ids if t in ids] if match is not None else []
    if not ids:
        refits = format_candidates(cand, pair, size.depth_m, grey) if refit_format else []
        found = [d for d in (judge_white(c, pair, depth, grey, False, panels) for c in refits) if d is not None]
        return max(found, key=lambda d: d.classification_indicator, default=None)
    planarity = pair.planarity(depth, seg.bbox, seg.mask)
    if planarity.indicator < config.planarity.detection_threshold:
        return None
    u, v = bbox_centre(seg.bbox)
    z = face_depth(planarity.depth_at(camera, u, v), size.depth_m, camera, u, v, config.depth,
                   config.depth.face_depth_slack)
    beside = side_share(depth, seg.bbox, z, config)
    if beside is not None and beside > config.white.white_max_side_share:
        return None
    if cand.shape == "rectangle" and coloured_share(pair.left, seg.bbox, config) > white.white_max_coloured_share:
        return None  # a coloured zone panel (2.59.5's red ring) read by its outline: the colour step's sign
    # a rectangle of a panel's standard format is a panel whatever its template scores; one of a size only a
    # measured entry takes (any white rectangle: a disc above its plate) only where it is read as that entry
    is_panel = panels is not None and cand.shape == "rectangle"
    if is_panel and match.format != MEASURED:
        panels.append(seg.bbox)
    supported = support_share(depth, seg.bbox, z, config) >= config.white.white_min_support or \
        pole_share(grey, seg.bbox, config) >= config.white.white_min_pole_rows
    cls = classify_segment(pair.left, seg.bbox, catalogue, ids, config)
    # a face without a support in view (a pole too pale to see or to match) must resemble its template clearly
    floor = config.white.white_min_score if supported else config.white.white_unsupported_min_score
    if cls.template_id is None or cls.score < floor:
        # a face in tinted light or worn correlates weakly with its drawing; where the network knows every
        # white candidate, its own clear reading of a supported face stands for the resemblance
        read = network_reading(pair, seg.bbox, ids) if supported and config.white.white_network_gate else None
        if read is None:
            return None
        cls, status, reason = read, ACCEPTED, ""
    else:
        cls, status, reason = read_white_face(pair, seg.bbox, ids, cls)
    if is_panel and match.format == MEASURED and status == ACCEPTED:
        panels.append(seg.bbox)
    entry = catalogue[cls.template_id]
    names = getattr(entry, "names", None) or {}
    return Detection(
        template_id=cls.template_id, name=names.get("de") or next(iter(names.values()), entry.id),
        colour="white", shape=entry.shape, width_m=match.width_m, height_m=match.height_m, format=match.format,
        detection_indicator=planarity.indicator, classification_indicator=cls.score,
        status=status, u=u, v=v, bbox=seg.bbox, depth_m=float(z), position=locate(camera, pair.pose, u, v, z),
        source="white",
        scores=cls.scores, normal_world=world_face_normal(camera, pair.pose, planarity.plane), review_reason=reason,
    )


def white_detections(pair: PairContext, depth: np.ndarray, candidates: Sequence[WhiteCandidate],
                     found: Sequence[Detection], panel_boxes: Optional[list] = None) -> List[Detection]:
    """White and grey signs among ``candidates`` whose centre lies in no sign ``found`` already (a white rim
    or panel of a coloured sign). ``panel_boxes``: a list that receives the white panel outlines seen (their
    zone discs are no signs, for the Hough fallback either)."""
    taken = [d.bbox for d in found]
    grey = cv2.cvtColor(pair.left, cv2.COLOR_BGR2GRAY) if candidates else None
    out, panels = [], []
    for cand in candidates:
        if any(centre_inside(cand.segment.bbox, box) for box in taken):
            continue
        det = judge_white(cand, pair, depth, grey, panels=panels)
        ring = ring_candidate(cand, pair)
        outer = judge_white(ring, pair, depth, grey, panels=panels) if ring is not None else None
        if outer is not None and (det is None or outer.classification_indicator > det.classification_indicator):
            det = outer
        if det is not None:
            out.append(det)
    if panel_boxes is not None:
        panel_boxes += panels
    return without_panel_discs(out, panels, pair.config)


def ring_candidate(cand: WhiteCandidate, pair: PairContext) -> Optional[WhiteCandidate]:
    """The disc ``cand`` read as the outer outline of an achromatic ring around it
    (:func:`.white_outlines.ring_around`), or None (no ring, a panel, or ``white_ring_ratios`` empty)."""
    config = pair.config
    if cand.shape != "circle" or config.white.white_ring_min_support > 1.0:
        return None
    scale = scan_scale(face_side_range_px(pair.camera, white_formats(pair.catalogue, config), config)[0], config)
    box = ring_around(pair.left, cand.segment.bbox, scale, config)
    if box is None:
        return None
    x, y, side, _ = box
    height, width = pair.left.shape[:2]
    if x < 0 or y < 0 or x + side > width or y + side > height or side < 4:
        return None
    mask, contour = inscribed_disc(side)
    seg = Segment("white", box, mask, contour + np.array([x, y]), int(np.count_nonzero(mask)),
                  cand.segment.touches_border, source="white")
    return WhiteCandidate(seg, "circle")


def without_panel_discs(detections: Sequence[Detection], panels: Sequence, config) -> List[Detection]:
    """``detections`` without the discs that lie inside a white panel (``white_disc_in_panel`` of their box),
    detected or only of a panel's format, planar and standing free (``panels``): an end-of-zone panel carries
    its zone's disc or ring, which reads as a disc sign of its own and may resemble a disc template (2.53.1's
    grey ring, 2.58) more than the panel its template."""
    panels = list(panels) + [d.bbox for d in detections if d.shape != "circle"]
    return [d for d in detections if d.shape != "circle"
            or not any(share_inside(d.bbox, p) >= config.white.white_disc_in_panel for p in panels)]
