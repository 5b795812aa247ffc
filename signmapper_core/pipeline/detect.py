"""Orchestration of the detection steps for one stereo pair or a window of it.

depth -> search space -> colour segments -> shape -> metric size and format ->
planarity (detection indicator) -> template NCC (classification indicator) ->
3D position; then the Hough fallback for faded round signs the colour step missed, and the white
step for white and grey signs, found by outline over the whole window (``white_outlines``,
``white_signs``).
"""

from __future__ import annotations

import math
import time
from contextlib import contextmanager
from dataclasses import replace
from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from ..catalogue.model import MEASURED, STANDARD, UNKNOWN_ID
from ..fusion.face_normal import world_face_normal
from ..geometry import Camera, Pose
from ..output.review_reasons import FAINT_HOUGH_RING, NO_ENTRY_MATCHES, OFF_FORMAT, ZONE_PANEL_BY_DEPTH, ZONE_PANEL_DISC
from ..plates.printed_numbers import number_band, printed_number
from ..plates.zone_panels import may_be_a_panels_disc
from ..statuses import ACCEPTED, REVIEW
from .boxes import box_iou, centre_inside, smaller_box_cover
from .classifiers import accept_threshold, marginal_min_score, min_score
from .classify import surround_score
from .colour import (
    ColourFrame,
    Segment,
    board_merges,
    find_colour_segments,
    merge_candidates,
    split_face_merges,
)
from .config import PipelineConfig, with_settings
from .depth_sources import depth_source_for
from .detection import Detection
from .face_extent import (
    FULL,
    candidate_entries,
    carried_discs,
    face_bbox,
    frame_candidates,
    hole_candidates,
    reads_as,
    rim_face_bboxes,
    ring_edge_bbox,
)
from .face_print import print_share
from .half_discs import with_half_discs
from .hidden_apex import apex_completed_face
from .hough import find_circles, hough_scale, hough_segments, radius_range_px, ring_colour_share, ringed_field
from .locate import bbox_centre, locate
from .pair_context import PairContext
from .plates import find_plates
from .search_range import edge_share_image, face_depth, face_depth_limits, face_in_range, in_search_range
from .shape import IDEAL_FILL, catalogue_shape, catalogue_shapes, plausible_outlines
from .sizing import measure_segment, metric_size, size_readings
from .text_lines import typed_by_lines
from .text_panels import context_boxes as panel_context_boxes
from .text_panels import text_panel_detections, text_panel_fields
from .white_outlines import (
    WhiteCandidate,
    WhiteScan,
    context_boxes,
    face_side_range_px,
    scan_image,
    white_candidates,
    white_formats,
)
from .white_signs import white_detections
from .zone_panel_surround import inside_white_panel

Box = Tuple[int, int, int, int]  # x, y, w, h


def _entry_name(entry) -> str:
    names = getattr(entry, "names", None) or {}
    return names.get("de") or next(iter(names.values()), None) or entry.id


def _shift_segment(seg: Segment, dx: int, dy: int) -> Segment:
    x, y, w, h = seg.bbox
    return replace(seg, bbox=(x + dx, y + dy, w, h), contour=seg.contour + np.array([dx, dy]))


def colour_segments(pair: PairContext, search: Optional[np.ndarray], frame: ColourFrame) -> List[Segment]:
    """Colour segments inside the pair's roi in full-image coordinates; cut ones are flagged ``touches_border``.

    ``search``: the search-space mask that cuts the colour masks (None: the whole roi).
    The small-ring pass looks for the smallest face the search space can hold.
    ``frame``: the :class:`ColourFrame` of the roi.
    """
    x0, y0, x1, y1 = pair.roi
    crop = pair.left[y0:y1, x0:x1]
    segs = find_colour_segments(crop, None if search is None else search[y0:y1, x0:x1], pair.config,
                                pair.smallest_face_px, frame)
    return [_shift_segment(seg, x0, y0) for seg in segs]


def stereo_candidate_boxes(pair: PairContext, frame: ColourFrame) -> List[Box]:
    """Boxes of the colour segments, found before depth, that could be a face (or half of one, a coloured
    part of a panel) somewhere in the search space: where stereo matching is worth running."""
    config, camera = pair.config, pair.camera
    heights = [h for e in pair.catalogue for (_, h) in e.formats.values()] or list(config.size.fallback_face_sides_m)
    max_px = config.depth.sgbm_band_max_height * max(heights) * camera.fy / config.depth.near_m
    min_px = config.depth.sgbm_band_min_height * min(heights) * camera.fy / config.depth.farthest_m
    return [s.bbox for s in colour_segments(pair, None, frame) if min_px <= s.bbox[3] <= max_px]


def round_face_diameter_px(seg: Segment, max_axis_scale: float) -> float:
    """Diameter of a round face from its outline: the larger axis of the fitted ellipse.

    A disc seen at an angle is an ellipse whose larger axis is the true diameter.
    Limited to ``max_axis_scale`` x the larger box side (an ellipse fitted to a cut outline
    overshoots) and never below that side (a disc cut by an occluder keeps its full extent on one axis).
    """
    side = float(max(seg.bbox[2], seg.bbox[3]))
    points = cv2.convexHull(seg.contour.reshape(-1, 1, 2).astype(np.int32))
    if len(points) < 5:
        return side
    (_, _), axes, _ = cv2.fitEllipse(points)
    return float(np.clip(max(axes), side, max_axis_scale * side))


ROUND_SHAPES = ("circle", "octagon")


READING_TIE = 0.005  # classification scores this close are a tie between readings of one face


def size_to_format(seg: Segment, candidates, depth_m: float, shape: Optional[str], pair: PairContext):
    """[(SizeMatch, face bbox, candidate ids, extent)] of every face reading whose size fits a format.

    A round ``shape`` is sized by its diameter (:func:`round_face_diameter_px`), so a disc
    seen at an angle still fits its format. A face whose coloured part sits inside a white
    rim is also read with the rim measured in the left image (:func:`.face_extent.rim_face_bboxes`), a field
    inside a ring with the ring's outer edge (:func:`.face_extent.ring_edge_bbox`, as the colour step
    without depth does: other print runs and designs draw the ring wider or narrower). A
    triangle too low for its width is also read as the whole triangle on its base where its top is hidden
    (:func:`.hidden_apex.apex_completed_face`).

    ``candidates``: (entry, colour extent) pairs, grouped by extent so that a
    coloured part inside a white rim or panel is sized as the whole face. Each
    group is a different reading of where the face is; classification decides.
    """
    camera, catalogue, config = pair.camera, pair.catalogue, pair.config
    groups = {}
    for entry, ext in candidates:
        groups.setdefault(tuple(round(v, 2) for v in ext), (ext, []))[1].append(entry)
    fits = []
    x, y, w, h = seg.bbox
    round_face = shape in ROUND_SHAPES and min(w, h) >= config.size.min_round_axis_ratio * max(w, h)
    # a field inside a ring drawn wider or narrower than the template's: the ring's outer edge in the image,
    # sought only where some candidate has the field's shape (the readings it could join)
    hole_of_shape = seg.source == "hole" and any(entry.shape == shape for entry, _ in candidates)
    ring = ring_edge_bbox(pair.left, seg.bbox, shape, config) if hole_of_shape else None
    diameter = round_face_diameter_px(seg, config.size.round_face_max_axis_scale) if round_face else None
    for ext, group in groups.values():
        readings = [(face_bbox(seg.bbox, ext), group)]  # (face box, the entries it may be)
        rimmed = [e for e in group if e.shape == shape]
        if ext != FULL and rimmed and seg.source == "colour":  # rims drawn otherwise
            readings += [(f, rimmed) for f in rim_face_bboxes(pair.left, seg.bbox, seg.mask, ext, shape, config)]
        if rimmed and ring is not None and box_iou(ring, readings[0][0]) < config.rims.rim_same_iou:
            readings += [(ring, rimmed)]
        triangles = [e for e in group if e.shape == "triangle"]
        if shape == "triangle" and ext == FULL and triangles and config.size.apex_completion:
            whole = apex_completed_face(pair.left, seg.bbox, triangles[0].aspect, config)  # its top hidden by leaves
            readings += [(whole, triangles)] if whole is not None else []
        for face, entries in readings:
            if diameter is not None and ext == FULL:  # an oblique disc: both axes are its diameter
                width_m, height_m = metric_size(camera, (x, y, diameter, diameter), depth_m)
            else:
                width_m, height_m = metric_size(camera, face, depth_m)
            allowed = {e.id for e in entries}
            for match in size_readings(catalogue, entries, width_m, height_m, config.size.size_tolerance,
                                       config.size.off_format_factor):
                ids = [t for t in match.template_ids if t in allowed]
                if ids:
                    fits.append((match, face, ids, ext))
    return fits


def segment_outline(seg: Segment, config: PipelineConfig) -> Tuple[Tuple[str, ...], bool]:
    """(outline shapes the segment may have, best first; whether the outline is only a marginal fit).

    Shapes are () when none fits (not a sign). Marginal: the best fit is below
    ``confident_shape_fit`` or the fill ratio is outside the usual window of its shape;
    such outlines (real signs with rounded corners, blur, perspective) need a clearer
    template match to be reported.
    """
    if seg.source == "hough":
        return ("circle",), False
    if seg.source == "half":  # the disc was read from its half: a guess that a clear match must confirm
        return ("circle",), True
    result, shapes = plausible_outlines(seg.mask, config)
    marginal = bool(shapes) and (result.fit < config.shape.confident_shape_fit
                                 or abs(result.fill_ratio - IDEAL_FILL[shapes[0]]) > config.shape.confident_fill_window)
    return shapes, marginal


def segment_shapes(seg: Segment, config: PipelineConfig) -> Tuple[str, ...]:
    """Outline shapes a segment may have, best first; () when none fits (not a sign)."""
    return segment_outline(seg, config)[0]


def segment_candidates(seg: Segment, shape, catalogue, config: PipelineConfig, image: Optional[np.ndarray] = None):
    """(entry, extent) pairs the segment may be: colour and shape(s) cut the catalogue.

    ``shape``: one outline shape or several (:func:`segment_shapes`). With the left ``image``, a segment whose
    hue lies at the edge of a neighbouring colour's is also offered that colour's entries
    (``ColourConfig.also_offered``).
    """
    outlines = (shape,) if isinstance(shape, str) else tuple(shape)
    shapes = tuple(dict.fromkeys(c for s in outlines for c in catalogue_shapes(s, seg.bbox[2], seg.bbox[3])))
    exclude, hsv_ranges = config.classification.exclude, config.colour.hsv_ranges
    if seg.source in ("hough", "half"):  # the circle is the face's outline, whatever its weak colour
        return [(e, FULL) for e in catalogue.filter(colours=[seg.colour], shapes=shapes, exclude=exclude)]
    if seg.source == "frame":  # a white frame found by brightness: the face is grown from its bright part
        return frame_candidates(catalogue, seg.colour, shapes, exclude)
    if seg.source == "hole":  # the field inside a ring: the face is grown from it
        return hole_candidates(catalogue, seg.colour, shapes, hsv_ranges, tuple(config.colour.colours) + ("white",),
                               exclude)
    allowed = tuple(config.colour.colours) + ("white",)
    out = candidate_entries(catalogue, seg.colour, shapes, hsv_ranges, allowed, exclude)
    offered = {entry.id for entry, _ in out}
    for other in config.colour.also_offered.get(seg.colour, ()):
        if other in allowed and image is not None and _hue_near(image, seg, hsv_ranges.get(other, ()),
                                                                config.colour.offered_hue_drift):
            # its own entries, read as if segmented in their colour
            out += [(entry, ext) for entry, ext in candidate_entries(catalogue, other, shapes, hsv_ranges, allowed,
                                                                     exclude)
                    if entry.colour == other and entry.id not in offered]
    dusk_yellow = config.colour.red_diamonds_as_yellow and "yellow" in allowed
    if dusk_yellow and seg.colour == "red" and outlines[0] == "diamond":
        # a priority road's yellow turns dark orange at dusk and reads as red; no red sign is a diamond (only as
        # the best outline: a blob that fits a disc as well is no middle of a priority road)
        out += candidate_entries(catalogue, "yellow", ("diamond",), hsv_ranges, allowed, exclude)
    return out


def _hue_near(image: np.ndarray, seg: Segment, ranges, drift: int) -> bool:
    """Whether the median hue of the segment's pixels lies within ``drift`` of one of ``ranges``' hue bands."""
    x, y, w, h = seg.bbox
    hue = cv2.cvtColor(image[y : y + h, x : x + w], cv2.COLOR_BGR2HSV)[..., 0][seg.mask > 0]
    if hue.size == 0:
        return False
    median = float(np.median(hue))
    return any(lo - drift <= median <= hi + drift for lo, hi, *_ in ranges)


def _off_format(match, entry) -> bool:
    """Whether ``match`` sizes a sign of standard formats at a size none of them has."""
    return match.format == MEASURED and entry.sizing == STANDARD


def _without_unclear_off_format(readings: list, catalogue, accept: float) -> list:
    """``readings`` ((match, face, classification) each) without those of a standard sign at a size none of its
    formats has that are not clear (below ``accept``): such a reading maps nothing, so it must not hide another
    (a small stop sign, nearly round at 36 px, behind the round signs read off-format)."""
    return [r for r in readings if not (_off_format(r[0], catalogue[r[2].template_id]) and r[2].score < accept)]


def evaluate_segment(seg: Segment, pair: PairContext, depth: np.ndarray) -> Optional[Detection]:
    """Steps 4-8 for one segment; None when it is rejected (cut, no shape, no format, not planar).

    ``depth``: the pair's depth map; planarity allows for the noise of its depth source.
    """
    left, camera, pose, catalogue, config = pair.left, pair.camera, pair.pose, pair.catalogue, pair.config
    if seg.touches_border:
        return None
    shapes, marginal = segment_outline(seg, config)
    if not shapes:
        return None
    shape = shapes[0]
    candidates = segment_candidates(seg, shapes, catalogue, config, left)
    if not candidates:
        return None
    limits = face_depth_limits(camera, seg.bbox, config.depth)
    size = measure_segment(camera, depth, seg.bbox, seg.surface_mask, *limits)
    if size is None or not face_in_range(camera, seg.bbox, size.depth_m, config.depth):
        return None
    fits = size_to_format(seg, candidates, size.depth_m, shape, pair)
    if not fits:
        return None
    planarity = pair.planarity(depth, seg.bbox, seg.surface_mask)
    if planarity.indicator < config.planarity.detection_threshold:
        return None
    # A reading that grows the segment into a larger face (a zone panel around its red ring) wins
    # when the face's part outside the segment matches too: the bare ring alone would always score
    # higher, and the panel reading alone scores ~0.65 on any round sign. A zone panel whose white does not match
    # the official one (another design, a shadow) still wins where white lies at its disc's depth above and beside
    # it (zone_panel_surround), held for review.
    readings, panels, held_panels = [], [], []
    drawn_as = {}  # id(reading) -> (its id, its drawing's colour extent): one drawing placed by its colour or a rim
    zone_panels = carried_discs(catalogue, config.colour.hsv_ranges)
    same_shapes = {c for s in shapes for c in catalogue_shapes(s, seg.bbox[2], seg.bbox[3])}
    classifier = pair.classifier_knowing([i for *_, ids, _ in fits for i in ids])
    accept = accept_threshold(classifier, config)
    for match, face, ids, ext in fits:
        cls = classifier.classify(left, face, ids)
        if cls.template_id is None:
            continue
        # of a board without standard size, the share of its face the colour segment is
        board_part = (ext[2] - ext[0]) * (ext[3] - ext[1]) if match.format == MEASURED else 1.0
        reading = (match, face, cls)
        drawn_as[id(reading)] = (cls.template_id, ext)
        if catalogue[cls.template_id].shape in same_shapes and board_part >= config.classification.min_face_part:
            readings.append(reading)  # the face is the segment (maybe with a rim)
        elif surround_score(left, face, catalogue, cls.template_id, ext, config.classification.surround_grow,
                            config.white.white_max_saturation) >= config.classification.min_surround_score:
            panels.append(reading)
        elif cls.template_id in zone_panels and inside_white_panel(left, depth, seg.bbox, size.depth_m, config):
            held_panels.append(reading)
    # each reading's indicator is a probability over its own candidates, so readings of other shapes are not
    # ranked by it: the outline's best-fitting shape decides (a stop sign, its octagon the best fit, read as
    # 3.01 with its white rim at 0.98 and, as a disc of the red alone, as no entry 2.02 at 0.99; a disc read
    # doubtfully among the round signs and, with a rim, as the stop sign, its octagon reading's one candidate)
    best_fit_shapes = set(catalogue_shapes(shape, seg.bbox[2], seg.bbox[3]))
    readings, panels, held_panels = (
        most_evident_per_face(_without_unclear_off_format(found, catalogue, accept),
                              config.classification.same_sign_max_iou,
                              lambda tid: catalogue[tid].shape in best_fit_shapes, lambda r: drawn_as[id(r)])
        for found in (readings, panels, held_panels))
    good_panels = [r for r in panels + held_panels if r[2].score >= accept]
    of_best_fit = [r for r in readings if catalogue[r[2].template_id].shape in best_fit_shapes]
    of_outline = [r for r in of_best_fit if r[2].score >= accept]
    pool = good_panels or of_outline or of_best_fit or readings or panels
    # a face is the open set's only where no reading matches an entry: a reading's score is a probability among
    # its own candidates, so a reading of one candidate (a board grown by a rim it lacks, a pointer read off a
    # rectangle) scores high whatever it shows, and must not hide a reading that matches its entry (clearly
    # enough to be mapped: one that would not be must not turn the face from `unknown` into nothing)
    pool = [r for r in pool if matches_its_entry(r[2], classifier, config) and
            r[2].score >= min_score(classifier, config)] or pool
    # near-ties (a confident network reads the face and its rimless part alike) go to the earliest reading: the
    # face as the colour extent implies it comes before the rims measured in the image
    top = max((r[2].score for r in pool), default=0.0)
    tied = [r for r in pool if r[2].score >= top - READING_TIE]
    best = tied[0] if tied else None
    if best is not None and any(r[2].template_id != best[2].template_id for r in tied):
        # readings near 1 that name different signs (the square 4.08 and, grown by its white lower part, the
        # one-way street for cyclists 4.08.1) are told apart by how well each face matches its sign: the logit
        best = max(tied, key=lambda r: r[2].fit)
    # an outline that only fits loosely, or a round one sized as seen at an angle (its box alone fits no
    # format), must resemble its template clearly: a cut of something else fits those readings too easily
    w, h = seg.bbox[2], seg.bbox[3]
    oblique = shape in ROUND_SHAPES and min(w, h) < (1.0 - config.size.size_tolerance) * max(w, h)
    floor = marginal_min_score(classifier, config) if marginal or oblique else min_score(classifier, config)
    # a face no entry matches is the segment's own (a part grown into a board its surround does not match is none)
    own_face = any(best is r for r in readings)
    if best is not None and own_face and not (marginal or oblique) and matches_no_entry(best[2], classifier, config):
        if not _carries_print(left, seg.bbox, config.classification):
            return None
        return _unknown_detection(seg, best, shape, planarity, size, pair)
    if best is None or best[2].score < floor:
        return None
    match, face, cls = best
    if match.format == MEASURED and not _carries_print(left, seg.bbox, config.classification,
                                                       config.classification.measured_print_inset):
        return None
    cls = replace(cls, template_id=typed_by_lines(cls.template_id, left, face, catalogue, config.classification))
    off_format = _off_format(match, catalogue[cls.template_id])
    if off_format and cls.score < accept:  # a size no standard sign has needs a clear reading
        return None
    by_depth = any(best is r for r in held_panels)
    # a reading the network does not see clearly (a grown face's, or a loose outline's) is no sign to accept: its
    # score may be high among few candidates (a plate's parking pictogram read as 2.41.2b, its one candidate)
    unclear = matches_no_entry(cls, classifier, config)
    status = ACCEPTED if cls.score >= accept and not (by_depth or off_format or unclear) else REVIEW
    reason = ZONE_PANEL_BY_DEPTH if by_depth and cls.score >= accept else (
        OFF_FORMAT if off_format else NO_ENTRY_MATCHES if unclear else "")
    if seg.source == "hough" and status == ACCEPTED:
        # a circle with a full-colour ring is a colour find the colour step lost (an attachment
        # spoiled its outline); faded or white ones stay for review
        x, y, w, h = seg.bbox
        ranges = config.colour.hsv_ranges.get(seg.colour)
        strong = ranges is not None and ring_colour_share(left[y : y + h, x : x + w], seg.mask, ranges, config) >= \
            config.hough.hough_strong_ring_share
        status = status if strong else config.hough.hough_max_status
        reason = "" if status == ACCEPTED else FAINT_HOUGH_RING
    u, v = bbox_centre(face)
    z = face_depth(planarity.depth_at(camera, u, v), size.depth_m, camera, u, v, config.depth,
                   config.depth.face_depth_slack)
    if status == ACCEPTED and may_be_a_panels_disc(zone_panels, cls.template_id) and \
            inside_white_panel(left, depth, face, z, config):
        status, reason = REVIEW, ZONE_PANEL_DISC
    entry = catalogue[cls.template_id]
    # a sign whose colour the segmentation takes for another is reported, and fused, in its own colour
    colour = entry.colour if reads_as(catalogue, entry, seg.colour, config.colour.hsv_ranges) else seg.colour
    return Detection(
        template_id=cls.template_id, name=_entry_name(entry), colour=colour, shape=entry.shape,
        width_m=match.width_m, height_m=match.height_m, format=match.format,
        detection_indicator=planarity.indicator, classification_indicator=cls.score, status=status,
        u=u, v=v, bbox=face, depth_m=float(z),
        position=locate(camera, pose, u, v, z), source=seg.source, scores=cls.scores,
        normal_world=world_face_normal(camera, pose, planarity.plane), review_reason=reason,
    )


def _open_set_limit(classifier, config: PipelineConfig) -> Optional[float]:
    """The logit the network gives the signs it reads right (its model card's ``unknown_logit``), or None where the
    open set is off or not calibrated."""
    return getattr(classifier, "unknown_logit", None) if config.classification.open_set else None


def most_evident_per_face(readings: list, same_iou: float, shape_of=None, drawn_as=None) -> list:
    """``readings`` (match, face, classification) with, of those of one face, only the one whose sign the
    network sees most clearly (its logit), in their order; all of them where the classifier gives no logit
    (template matching). Boxes overlapping more than ``same_iou`` [IoU] are one face, as detections of a pair
    are one sign (entries whose colour lies elsewhere in their drawing place the same face a few pixels apart);
    with ``shape_of`` (template id -> a key: the shape, or whether it is the outline's best fit), only readings
    that name signs of one key (the outline decides between shapes, not the logit).

    Readings of one face saw the same pixels, but each score is a probability among that reading's own
    candidates: read among standard formats and among entries of measured size, the box goes to the reading
    with fewer good rivals (the parking-disc sign 4.18 at logit 3.8, 0.92, lost to 4.22, which the network
    sees less, at logit 2.6, 0.97, where 4.18 was no candidate; a mountain-bike pointer 4.50.3 at logit 5.2,
    0.78 among two cycle pointers, to the skating pointer 4.50.4 at logit 3.9, its box's one candidate).
    ``drawn_as`` (reading -> a key: its id and its drawing's colour extent) says which readings place one
    drawing, by its colour or by a rim measured around it: among those the logit does not decide (a tighter box
    can score higher), their :func:`best_placement` stands for them."""
    if not all(math.isfinite(cls.fit) for _, _, cls in readings):
        return list(readings)
    if drawn_as is not None:
        readings = best_placement(readings, same_iou, drawn_as)
    kind = (lambda r: shape_of(r[2].template_id)) if shape_of is not None else (lambda r: None)
    kept: list = []
    for k in sorted(range(len(readings)), key=lambda k: -readings[k][2].fit):
        if all(box_iou(readings[k][1], readings[j][1]) <= same_iou or kind(readings[k]) != kind(readings[j])
               for j in kept):
            kept.append(k)
    keep = set(kept)
    return [r for k, r in enumerate(readings) if k in keep]


def best_placement(readings: list, same_iou: float, drawn_as) -> list:
    """``readings`` with, of those of one face (boxes overlapping more than ``same_iou``) that place one drawing
    (equal ``drawn_as`` keys), only the best scored, near-ties (``READING_TIE``) to the earliest: the face as
    its colour extent implies comes before the rims measured in the image (a priority road's yellow diamond at
    70 px: its rim's inner edge, 5 px inside the face, read at logit 6.9 against the face's 6.3)."""
    kept: list = []
    for reading in readings:
        rival = next((k for k, other in enumerate(kept) if drawn_as(other) == drawn_as(reading)
                      and box_iou(other[1], reading[1]) > same_iou), None)
        if rival is None:
            kept.append(reading)
        elif reading[2].score > kept[rival][2].score + READING_TIE:
            kept[rival] = reading
    return kept


def matches_its_entry(cls, classifier, config: PipelineConfig) -> bool:
    """Whether a reading's best candidate has a logit as high as the network gives the signs it reads right (the
    open set's limit): a match whatever the number of candidates."""
    limit = _open_set_limit(classifier, config)
    return limit is not None and cls.fit >= limit


def matches_no_entry(cls, classifier, config: PipelineConfig) -> bool:
    """Whether a sign-like face's reading is the open set's: its network (where its model card calibrates this)
    gives none of its candidates a logit as high as it gives the signs it reads right, and does not call it no
    sign."""
    limit = _open_set_limit(classifier, config)
    if limit is None:
        return False
    return cls.fit < limit and cls.background < config.classification.unknown_max_background


def _carries_print(left: np.ndarray, bbox, classification, inset: Optional[float] = None) -> bool:
    """Whether the colour segment ``bbox`` shows print enough to be a sign no entry matches (inside ``inset`` of
    each side, by default ``unknown_print_inset``)."""
    low, high = classification.unknown_print_canny
    inset = classification.unknown_print_inset if inset is None else inset
    share = print_share(left, bbox, inset, low, high)
    return share >= classification.unknown_min_print


def _unknown_detection(seg: Segment, reading, shape: str, planarity, size, pair: PairContext) -> Detection:
    """A sign-like face no catalogue entry matches well: id ``unknown``, in review, with the readings it came
    closest to as its scores (the next choices), its size as measured or as the format it fits."""
    match, face, cls = reading
    camera = pair.camera
    u, v = bbox_centre(face)
    z = face_depth(planarity.depth_at(camera, u, v), size.depth_m, camera, u, v, pair.config.depth,
                   pair.config.depth.face_depth_slack)
    return Detection(
        template_id=UNKNOWN_ID, name=UNKNOWN_ID, colour=seg.colour, shape=catalogue_shape(shape),
        width_m=match.width_m, height_m=match.height_m, format=match.format, detection_indicator=planarity.indicator,
        classification_indicator=cls.score, status=REVIEW, u=u, v=v, bbox=face, depth_m=float(z),
        position=locate(camera, pair.pose, u, v, z), source=seg.source, scores=cls.scores,
        normal_world=world_face_normal(camera, pair.pose, planarity.plane), review_reason=NO_ENTRY_MATCHES,
    )


def with_number_band(detection: Detection, left: np.ndarray) -> Detection:
    """``detection`` carrying the digits' band of its face as ``crop`` when it reads a speed limit (fusion reads
    the digits of a sign's best views, ``number_check``); as it was otherwise."""
    if printed_number(detection.template_id) is None or detection.crop is not None:
        return detection
    band = number_band(left, detection.bbox)
    return detection if band is None else replace(detection, crop=band)


def _part_of(inner, outer, max_area_share: float) -> bool:
    """Whether box ``inner`` lies inside box ``outer`` (give or take 5 % of its size) and covers at most
    ``max_area_share`` of it."""
    x, y, w, h = inner
    ox, oy, ow, oh = outer
    sx, sy = 0.05 * ow, 0.05 * oh
    inside = x >= ox - sx and y >= oy - sy and x + w <= ox + ow + sx and y + h <= oy + oh + sy
    return inside and w * h <= max_area_share * ow * oh


def suppress_overlaps(detections: Sequence[Detection], max_iou: float,
                      part_max_area_share: float = 0.0) -> List[Detection]:
    """Keep the best of overlapping detections (one sign found twice, or a part of it found as a sign).

    A detection inside an accepted one's face, covering at most ``part_max_area_share`` of it, is a part of
    that sign read as a sign of its own (the blue field of a no-parking disc read as a blue disc): it goes
    whatever its indicators, which a small part inside a face can have higher than the whole (a flatter patch).
    """
    parts = {id(d) for d in detections for o in detections
             if o is not d and o.status == ACCEPTED and _part_of(d.bbox, o.bbox, part_max_area_share)}
    ranked = sorted((d for d in detections if id(d) not in parts),
                    key=lambda d: d.detection_indicator * d.classification_indicator, reverse=True)
    kept: List[Detection] = []
    for det in ranked:
        if all(box_iou(det.bbox, k.bbox) <= max_iou and not centre_inside(det.bbox, k.bbox)
               and not centre_inside(k.bbox, det.bbox) for k in kept):
            kept.append(det)
    return kept


def _round_diameters(catalogue, config: PipelineConfig) -> List[float]:
    entries = catalogue.filter(shapes=["circle"], exclude=tuple(config.classification.exclude))
    diam = [max(f) for e in entries for f in e.formats.values() if max(f) <= config.hough.hough_max_diameter_m]
    return diam or list(config.hough.hough_fallback_diameters_m)


class _Timer:
    """Accumulates seconds per step into a dict (or does nothing without one)."""

    def __init__(self, sink: Optional[dict]):
        self.sink = sink

    @contextmanager
    def __call__(self, step: str):
        if self.sink is None:
            yield
            return
        start = time.perf_counter()
        try:
            yield
        finally:
            self.sink[step] = self.sink.get(step, 0.0) + time.perf_counter() - start


def detect(pair: PairContext, timings: Optional[dict] = None) -> List[Detection]:
    timer = _Timer(timings)
    left, config, source = pair.left, pair.config, pair.depth_source
    x0, y0, x1, y1 = pair.roi
    with timer("colour"):
        frame = ColourFrame.of(left[y0:y1, x0:x1], config)
        # colour candidates before depth, for a source that matches only around them
        boxes = stereo_candidate_boxes(pair, frame) if source.wants_candidate_boxes(config) else None
    with timer("white"):  # white and grey outlines over the whole window; depth is matched around them too
        scan = white_scan(pair)
        whites = white_outline_candidates(pair, scan)
        panel_fields = text_panel_fields(pair)
        if boxes is not None:
            boxes = boxes + context_boxes(whites, config) + panel_context_boxes(panel_fields, config)
    with timer("depth"):
        depth = source.depth_map(left, pair.camera, config, pair.roi, boxes)
    search = in_search_range(depth, edge_share_image(pair.camera), config.depth)
    if not pair.is_whole_image:
        inside = np.zeros_like(search)
        inside[y0:y1, x0:x1] = True
        search &= inside
    detections = []
    with timer("colour"):
        cut = source.search_cut(search, config)
        segments = colour_segments(pair, cut, frame)
        # discs that kept their colour on one half only (not those the search space halved)
        segments = with_half_discs(segments, (left.shape[1], left.shape[0]), config, cut)
    with timer("segments"):
        # faces split by a bar (no entry) or a pole: the whole face is judged before its pieces
        taken = set()
        for seg, i, j in split_face_merges(segments, config):
            det = evaluate_segment(seg, pair, depth)
            if det is not None:
                detections.append(det)
                taken.update((i, j))
        for seg, i, j in board_merges(segments, config):  # a wide board a pole in front cut in two
            det = None if taken & {i, j} else evaluate_segment(seg, pair, depth)
            if det is not None:
                detections.append(det)
                taken.update((i, j))
        rejected = []
        for k, seg in enumerate(segments):
            if k in taken:
                continue
            det = evaluate_segment(seg, pair, depth)
            if det is not None:
                detections.append(det)
            elif not seg.touches_border:
                rejected.append(seg)
        # pieces that fail alone are also tried together when no whole outline formed (a branch cut them)
        for seg in merge_candidates(rejected[: config.colour.max_merge_pieces], config.colour.merge_max_gap,
                                    config.colour.merge_max_aspect):
            det = evaluate_segment(seg, pair, depth)
            if det is not None:
                detections.append(det)
    with timer("white"):  # before Hough: a white disc's ring would be read as a faded coloured one
        panels: List[Tuple[int, int, int, int]] = []  # white panel outlines: their zone discs are no signs
        detections += white_detections(pair, depth, whites, detections, panels)
        detections += text_panel_detections(pair, depth, panel_fields, detections)
    with timer("hough"):
        detections += _hough_detections(pair, depth, search, detections, panels)
    signs = [with_number_band(d, pair.left) for d in suppress_overlaps(
        detections, config.classification.same_sign_max_iou, config.classification.part_max_area_share)]
    if not pair.is_whole_image:  # a window around a click looks for the sign alone
        return signs
    with timer("plates"):
        return _signs_and_plates(pair, depth, signs, config.plates.plate_min_cover)


def _signs_and_plates(pair: PairContext, depth: np.ndarray, signs: List[Detection],
                      min_cover: float) -> List[Detection]:
    """``signs`` and their supplementary plates, without the white step's rectangles that are such a plate.

    A text plate is a white rectangle, as are many white entries: read alone, the plate may resemble one of them
    (a "Mo-Fr / 7-19 h" plate above a speed limit read as a police sign). Where the plate step, looking without
    those readings, finds a plate covering at least ``min_cover`` of one, the plate is what it is. The plates are
    looked for again only when some of those readings stay signs (their plates count too).
    """
    readings = [s for s in signs if s.source == "white" and s.shape == "rectangle"]
    if not readings:
        return signs + find_plates(pair, depth, signs)
    others = [s for s in signs if all(s is not r for r in readings)]
    plates = find_plates(pair, depth, others)
    taken = [r for r in readings if any(smaller_box_cover(p.bbox, r.bbox) >= min_cover for p in plates)]
    if len(taken) == len(readings):
        return others + plates
    kept = [s for s in signs if all(s is not t for t in taken)]
    return kept + find_plates(pair, depth, kept)


def white_scan(pair: PairContext) -> Optional[WhiteScan]:
    """The white step's reduced look at the pair's roi, shared by its searches; None with ``white.white_signs``
    off."""
    if not pair.config.white.white_signs:
        return None
    x0, y0, x1, y1 = pair.roi
    smallest = face_side_range_px(pair.camera, white_formats(pair.catalogue, pair.config), pair.config)[0]
    return scan_image(pair.left[y0:y1, x0:x1], smallest, pair.config) if smallest > 0 else None


def white_outline_candidates(pair: PairContext, scan: Optional[WhiteScan] = None) -> List[WhiteCandidate]:
    """White and grey sign candidates in the pair's roi (full-image pixels); none with ``white.white_signs`` off.
    ``scan``: the roi's :func:`white_scan`, when already made."""
    config = pair.config
    if not config.white.white_signs:
        return []
    x0, y0, x1, y1 = pair.roi
    sides = face_side_range_px(pair.camera, white_formats(pair.catalogue, config), config)
    return [WhiteCandidate(_shift_segment(c.segment, x0, y0), c.shape)
            for c in white_candidates(pair.left[y0:y1, x0:x1], sides, config, scan)]


def _hough_detections(pair: PairContext, depth: np.ndarray, search: np.ndarray,
                      found: Sequence[Detection], panels: Sequence[Tuple[int, int, int, int]] = ()
                      ) -> List[Detection]:
    """Round signs from Hough circles whose centre is not inside an already found sign or a white panel's
    outline (``panels``)."""
    config = pair.config
    x0, y0, x1, y1 = pair.roi
    detections: List[Detection] = []
    if config.hough.hough_enabled:
        r_min, r_max = radius_range_px(pair.camera.fx, config.depth.near_m, config.depth.far_m,
                                       _round_diameters(pair.catalogue, config), config.hough.hough_radius_slack)
        taken = [d.bbox for d in found] + list(panels)
        sub = search[y0:y1, x0:x1]
        scale = hough_scale(r_min, config.hough.hough_scale, config.hough.hough_min_radius_px)
        image = pair.left[y0:y1, x0:x1]
        for seg in hough_segments(image, find_circles(image, sub, r_min, r_max, scale, config), config):
            seg = _shift_segment(seg, x0, y0)
            seg = ringed_field(pair.left, seg, config) or seg
            if seg.colour == "white" and config.white.white_signs:  # the white step's discs
                continue
            if any(centre_inside(seg.bbox, box) for box in taken):
                continue
            det = evaluate_segment(seg, pair, depth)
            if det is not None:
                detections.append(det)
    return detections


def detect_pair(left, depth, right, camera: Camera, pose: Pose, catalogue,
                config: Optional[PipelineConfig] = None, timings: Optional[dict] = None) -> List[Detection]:
    """All signs detected in one stereo pair.

    ``depth``: float32 metres (NaN = none) or None to compute it by SGBM from
    ``left``/``right`` with the disparity range of the configured search space.
    ``timings``: optional dict that receives the seconds spent per step.
    """
    pair = PairContext.whole(left, camera, pose, catalogue, config or PipelineConfig(), depth_source_for(depth, right))
    return detect(pair, timings)


def detect_in_window(left, depth, right, camera: Camera, pose: Pose, catalogue, config: Optional[PipelineConfig],
                     click_uv, half_size_px: int) -> Optional[Detection]:
    """The sign nearest a clicked pixel: the same steps on a window of +-``half_size_px`` around it.

    A sign cut by the window is rejected like one cut by the image border, so the
    window should be larger than the sign. Returns None when nothing is found.
    """
    # depth by SGBM over the whole window's rows: a clicked sign may have no colour candidate
    config = with_settings(config or PipelineConfig(), {"depth": {"sgbm_rows_only": False}})
    height, width = left.shape[:2]
    cu, cv = float(click_uv[0]), float(click_uv[1])
    roi = (max(0, int(cu - half_size_px)), max(0, int(cv - half_size_px)),
           min(width, int(cu + half_size_px) + 1), min(height, int(cv + half_size_px) + 1))
    if roi[2] <= roi[0] or roi[3] <= roi[1]:
        return None
    found = detect(PairContext(left, camera, pose, catalogue, config, depth_source_for(depth, right), roi))
    if not found:
        return None

    def rank(det: Detection):
        x, y, w, h = det.bbox
        contains = x <= cu < x + w and y <= cv < y + h
        return (not contains, np.hypot(det.u - cu, det.v - cv))

    return min(found, key=rank)
