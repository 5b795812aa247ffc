"""Supplementary plates: a white rectangle of a standard plate size right below (or above) a detected sign.

A step after detection: it takes the pair, its depth map and the signs found in
it, and looks only around each sign, on the same support. A plate is a bright,
unsaturated region (its black text and frame closed over), as wide as a plate
format at the sign's depth, within a few centimetres of the sign's lower (or
upper) edge and centred under it. Where the depth map covers it, the region must
lie in the sign's depth (a white wall behind is not a plate); where it does not
(stereo matching runs only around colour candidates), the plate is taken to be
in the sign's plane, as it is mounted on the same pole. Each plate is a
:class:`Detection` with ``plate_of`` = its sign's detection and the crop its text
is read from after fusion (``plate_fusion``); a plate that shows the drawing of
a pictogram or layout plate (``plate_classify``) takes that plate's id, name and
size, and the crop of a layout plate is only its text field.
"""

from __future__ import annotations

import math
import threading
from typing import List, Optional, Sequence

import cv2
import numpy as np

from ..plates.catalogue import load_plate_templates, pictogram_formats
from ..plates.formats import PLATE_FORMATS, PLATE_ID, PLATE_NAMES
from ..statuses import ACCEPTED, REVIEW
from .boxes import touches_border
from .detection import Detection
from .locate import bbox_centre, locate
from .pair_context import PairContext
from .plate_classify import classify_plate, crossing_occluders

BELOW, ABOVE = 1, -1


def depth_tolerance_m(z: float, config) -> float:
    """How far from a sign's depth ``z`` a plate's pixels may lie: the fixed tolerance, or a share of the depth
    where SGBM's error has grown beyond it."""
    return max(config.plates.plate_depth_tolerance_m, config.plates.plate_depth_tolerance_share * z)


def plate_templates(pair: PairContext) -> tuple:
    """The pictogram plate templates of the pair's catalogue (none for a catalogue without ``plates/``)."""
    folder = getattr(pair.catalogue, "folder", None)
    return load_plate_templates(folder) if folder is not None else ()


def all_plate_formats(templates) -> dict:
    """Every plate size: the text plates' formats and those the pictogram plates ``templates`` add."""
    return {**PLATE_FORMATS, **pictogram_formats(templates)}


def fitting_plate_formats(width_m: float, height_m: float, tolerance: float, formats=None) -> list:
    """[(format name, (width_m, height_m), log error)] of the plate formats (``formats``, default the text plates')
    within ``tolerance`` of the size, nearest first."""
    fits = []
    for name, (w, h) in (formats or PLATE_FORMATS).items():
        error = max(abs(math.log(width_m / w)), abs(math.log(height_m / h)))
        if error <= math.log(1.0 + tolerance):
            fits.append((name, (w, h), error))
    return sorted(fits, key=lambda fit: fit[2])


def nearest_plate_format(width_m: float, height_m: float, tolerance: float, formats=None):
    """(format name, (width_m, height_m), log error) of the nearest plate format (``formats``, default the text
    plates'), or None beyond ``tolerance``."""
    fits = fitting_plate_formats(width_m, height_m, tolerance, formats)
    return fits[0] if fits else None


def white_masks(bgr: np.ndarray, config) -> List[np.ndarray]:
    """Bright unsaturated pixels at rising brightness floors: from Otsu's split of the window (or
    ``plate_min_value``) up by each of ``plate_value_steps`` (below ``plate_max_value_floor``). A white plate
    before a pale wall or sky is one region only at a floor between the two, so each floor is looked at (the
    stable bright regions of MSER, a few levels only)."""
    plates = config.plates
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    value = hsv[:, :, 2]
    otsu, _ = cv2.threshold(value, 0, 255, cv2.THRESH_BINARY + cv2.THRESH_OTSU)
    floor = max(plates.plate_min_value, int(otsu))
    grey = hsv[:, :, 1] <= plates.plate_max_saturation
    masks = [(grey & (value >= floor + step)).astype(np.uint8) for step in plates.plate_value_steps
             if floor + step < plates.plate_max_value_floor]
    if masks and plates.plate_edge_cut:
        # a plate before a wall only a little darker than its paper (a pale façade) is brighter than the wall
        # at every floor: the step in brightness along its outline still parts them
        lo, hi = plates.plate_edge_thresholds
        edges = cv2.dilate(cv2.Canny(value, lo, hi), np.ones((3, 3), np.uint8))
        masks.append(_inner_regions(masks[0] & (edges == 0).astype(np.uint8)))
    return masks


def _inner_regions(mask: np.ndarray) -> np.ndarray:
    """``mask`` without its regions that touch the window's edge: the wall around a plate, which would otherwise
    swallow the plate as a hole when its outline is filled."""
    count, labels = cv2.connectedComponents(mask, connectivity=4)
    edge = np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]]))
    keep = np.ones(count, np.uint8)
    keep[edge] = 0
    keep[0] = 0
    return keep[labels]


def _filled(mask: np.ndarray, close_px: int) -> np.ndarray:
    """The mask with its letters and frame closed over and its holes filled: the plate's outline."""
    if close_px > 1:
        mask = cv2.morphologyEx(mask, cv2.MORPH_CLOSE, cv2.getStructuringElement(cv2.MORPH_RECT, (close_px, close_px)))
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    filled = np.zeros_like(mask)
    cv2.drawContours(filled, contours, -1, 1, thickness=cv2.FILLED)
    return filled


def without_necks(labels: np.ndarray, stats: np.ndarray, regions: Sequence[int], neck_px: int,
                  merged: np.ndarray) -> np.ndarray:
    """uint8 mask of the ``regions`` (labels in ``labels``, their ``stats``) with their necks cut: a pale pole that
    joins a plate to the sign above it or runs on below it is one region with the plate at every brightness floor
    that keeps the pole.

    Of every region, the rows whose whole extent is narrower than ``neck_px`` go (the pole; a panel's two narrow
    sides beside its ring, together as wide as the panel, stay). Of the regions ``merged`` (bool per label: those
    cut by the window, a plate run together with a wall or the ground beside it), every run narrower than
    ``neck_px`` goes (the strip of wall that joins it)."""
    out = np.zeros(labels.shape, np.uint8)
    for k in regions:
        bx, by, bw, bh = (int(v) for v in stats[k, :4])
        region = (labels[by:by + bh, bx:bx + bw] == k).astype(np.uint8)
        if merged[k]:
            region = cv2.morphologyEx(region, cv2.MORPH_OPEN, np.ones((1, neck_px), np.uint8))
        else:
            first = region.argmax(axis=1)
            last = bw - 1 - region[:, ::-1].argmax(axis=1)
            region[last - first + 1 < neck_px] = 0
        out[by:by + bh, bx:bx + bw] |= region
    return out


def goes_on_at_both_ends(filled: np.ndarray, row, side: int, end_share: float) -> bool:
    """Whether the regions of ``filled`` go on past the far edge (away from the sign) of the box ``row`` (x, y, w,
    h, window pixels) at both of its ends (its first and last ``end_share`` of columns): the sides of a larger
    white frame, a panel's, whose top a cut neck left as a plate-like band; a plate's pole goes on in its middle."""
    bx, by, bw, bh = (int(v) for v in row[:4])
    beyond = by + bh if side == BELOW else by - 1
    if not 0 <= beyond < filled.shape[0]:
        return False
    end = max(1, int(round(end_share * bw)))
    line = filled[beyond, bx:bx + bw]
    return bool(line[:end].any() and line[-end:].any())


def _clipped(box, shape):
    x, y, w, h = box
    x0, y0 = max(0, x), max(0, y)
    return x0, y0, min(shape[1], x + w) - x0, min(shape[0], y + h) - y0


def seen_share(box, hidden: Optional[np.ndarray], image_shape, edge_px: int) -> float:
    """Share of a plate's box seen whole: 0 when it comes within ``edge_px`` of the image's edge
    (:func:`.boxes.touches_border`: the plate may go on beyond it, its text with it), else the share of the box not
    ``hidden`` (uint8 mask of the clipped box, nonzero = covered by something in front; None: nothing hidden)."""
    if touches_border(box, image_shape[1], image_shape[0], edge_px):
        return 0.0
    if hidden is None or hidden.size == 0:
        return 1.0
    return 1.0 - float(np.count_nonzero(hidden)) / hidden.size


def _plate_reading(pair: PairContext, sign: Detection, box, z: float, side: int, touch_px: float,
                   hidden: Optional[np.ndarray] = None):
    """(score 0..1, plate format) of a box read as a plate of ``sign``, or None where it cannot be one.

    ``hidden``: the pair's mask of pixels hidden by something in front (image-sized or None); they count
    neither as ink nor as paper."""
    config, camera = pair.config, pair.camera
    x, y, w, h = sign.bbox
    bx, by, bw, bh = box
    px_per_m = camera.fy / z
    gap_px = (by - (y + h)) if side == BELOW else (y - (by + bh))
    if not -touch_px <= gap_px <= config.plates.plate_max_gap_m * px_per_m:
        return None  # reaching into the sign (its panel's white), or too far from it
    if abs(bx + bw / 2.0 - (x + w / 2.0)) > config.plates.plate_max_offset * max(w, bw):
        return None
    cx, cy, cw, ch = _clipped(box, pair.left.shape)
    if cw < 4 or ch < 4:
        return None
    size = (bw * z / camera.fx, bh * z / camera.fy)
    templates = plate_templates(pair)
    plates = config.plates
    fits = fitting_plate_formats(*size, plates.plate_size_tolerance, all_plate_formats(templates))
    fmt = fits[0] if fits else None
    if fmt is not None and "@" in fmt[0]:  # a drawn plate's size: if it shows one of the drawings of its size
        drawn = {name.split("@")[0]: (name, wh, error) for name, wh, error in fits if "@" in name}
        seen_crop = pair.left[cy:cy + ch, cx:cx + cw]
        part_hidden = None if hidden is None else hidden[cy:cy + ch, cx:cx + cw]
        shown = classify_plate(seen_crop, [t for t in templates if t.id in drawn], config, part_hidden)[0]
        fmt = drawn[shown.id] if shown is not None else nearest_plate_format(*size, plates.plate_size_tolerance)
    if fmt is None:
        return None
    grey = cv2.cvtColor(pair.left[cy:cy + ch, cx:cx + cw], cv2.COLOR_BGR2GRAY)
    seen = np.ones(grey.shape, bool) if hidden is None else ~hidden[cy:cy + ch, cx:cx + cw].astype(bool)
    if seen.sum() < config.plates.plate_min_seen * seen.size:
        return None
    ink = float(np.mean(grey[seen] < config.plates.plate_ink_darkness * np.median(grey[seen])))
    if not config.plates.plate_min_ink <= ink <= config.plates.plate_max_ink:
        return None
    misfit = min(fmt[2] / math.log(1.0 + config.plates.plate_size_tolerance), 1.0)
    return 1.0 - misfit * config.plates.plate_misfit_weight, fmt


def _box_of(stats_row, x0, y0, margin):
    bx, by, bw, bh = (int(v) for v in stats_row[:4])
    return (int(round(bx + x0 - margin)), int(round(by + y0 - margin)), int(round(bw + 2 * margin)),
            int(round(bh + 2 * margin)))


def _best_region(pair: PairContext, sign: Detection, mask: np.ndarray, window, z: float, side: int,
                 touch_px: float, best, hidden: np.ndarray):
    """The best plate reading of the regions of ``mask`` (in the ``window`` x0, y0, x1, y1), or ``best`` if none
    is better: (score, box, format, fill).

    A region is read as a whole plate; and where something in front of a plate (a branch, a lamp post:
    ``hidden``, image-sized) hides part of it, its pieces are read together and completed under what hides
    them (``_hidden_reading``)."""
    config = pair.config
    plates = config.plates
    min_w, min_h = plates.plate_min_size_px
    x0, y0, x1, y1 = window
    filled = _filled(mask, int(round(config.plates.plate_close_m * pair.camera.fy / z)) | 1)
    count, labels, stats, _ = cv2.connectedComponentsWithStats(filled, connectivity=4)
    # a region's fill is measured with notches as thin as a wire or a pole's edge across the plate closed (they
    # are not its outline); the regions themselves stay as found, so a closed gap never joins plate and wall
    solid = None
    # the region is the whole plate, or the inside of its black frame (its white margin lost in a white
    # wall behind it, or in the sky): then the plate is that much larger
    grow = config.plates.plate_frame_share / (1.0 - 2.0 * config.plates.plate_frame_share)

    def read_whole(row, best):
        nonlocal solid
        bx, by, bw, bh, area = (int(v) for v in row)
        fill = area / float(bw * bh)
        if plates.plate_notched_min_fill <= fill < plates.plate_min_fill and bw >= min_w and bh >= min_h:
            if solid is None:
                solid = _filled(mask, int(round(config.plates.plate_notch_m * pair.camera.fy / z)) | 1)
            fill = max(fill, float(solid[by:by + bh, bx:bx + bw].mean()))
        if bw < min_w or bh < min_h or fill < plates.plate_min_fill:
            return best
        for margin in (0.0, grow * bh):
            box = _box_of(row, x0, y0, margin)
            reading = _plate_reading(pair, sign, box, z, side, touch_px)
            if reading is not None and (best is None or fill * reading[0] > best[0]):
                best = (fill * reading[0], box, reading[1], fill)
        return best

    def cut_by_window(row) -> bool:  # part of something larger (a wall, the sky)
        bx, by, bw, bh = (int(v) for v in row[:4])
        far_edge_cut = by + bh >= y1 - y0 if side == BELOW else by == 0
        return bw < 3 or bh < 3 or bx == 0 or bx + bw >= x1 - x0 or far_edge_cut

    pieces = []
    sign_edge = sign.bbox[1] + sign.bbox[3] - y0 if side == BELOW else sign.bbox[1] - y0
    for k in range(1, count):
        if cut_by_window(stats[k]):
            continue
        by, bh = int(stats[k, cv2.CC_STAT_TOP]), int(stats[k, cv2.CC_STAT_HEIGHT])
        if (by >= sign_edge - touch_px) if side == BELOW else (by + bh <= sign_edge + touch_px):
            pieces.append(k)  # off the sign's side: may be a piece of a plate
        best = read_whole(stats[k], best)
    # a plate joined to its sign, or running on down the pole, by a pale pole is read again with the pole cut off
    # (of the regions wide enough to hold the narrowest plate)
    neck_px = int(round(plates.plate_neck_m * pair.camera.fx / z))
    narrowest = min(w for w, _ in PLATE_FORMATS.values()) * pair.camera.fx / z * (1.0 - plates.plate_size_tolerance)
    wide = [k for k in range(1, count) if stats[k, cv2.CC_STAT_WIDTH] >= narrowest]
    if neck_px > 1 and wide:
        merged = np.zeros(count, bool)
        merged[wide] = [cut_by_window(stats[k]) for k in wide]
        found = {tuple(row) for row in stats[1:]}
        ends = plates.plate_neck_end_share
        necked = without_necks(labels, stats, wide, neck_px, merged)
        for row in cv2.connectedComponentsWithStats(necked, connectivity=4)[2][1:]:
            if tuple(row) not in found and not cut_by_window(row) and not goes_on_at_both_ends(filled, row, side, ends):
                best = read_whole(row, best)
    if not pieces or not hidden[y0:y1, x0:x1].any():
        return best
    # a plate partly hidden by something in front: its pieces together (a branch across it), and a piece or
    # those pieces completed sideways under what hides the rest (a lamp post over one end), to a plate's width
    px_per_m = pair.camera.fx / z
    # a piece alone is completed only if it can be the seen share of the smallest plate (not a speck)
    smallest = min(w * h for w, h in PLATE_FORMATS.values()) * px_per_m * pair.camera.fy / z
    alone = [k for k in pieces if stats[k, cv2.CC_STAT_AREA] >= config.plates.plate_min_visible * smallest]
    level = side_by_side(pieces, stats, plates.plate_split_min_overlap)
    groups = [[k] for k in alone] + level + ([pieces] if len(pieces) > 1 and pieces not in level else [])
    hidden_here = hidden[y0:y1, x0:x1].astype(bool)
    for group in groups:
        lo = np.min(stats[group, :2], axis=0)
        hi = np.max(stats[group, :2] + stats[group, 2:4], axis=0)
        bx, by, bw, bh = int(lo[0]), int(lo[1]), int(hi[0] - lo[0]), int(hi[1] - lo[1])
        boxes = [(bx, by, bw, bh)] if len(group) > 1 else []
        for width_m in sorted({w for w, h in PLATE_FORMATS.values()}):
            extra = int(round(width_m * px_per_m)) - bw
            if extra > plates.plate_min_widening * bw:
                boxes += [(bx - extra, by, bw + extra, bh), (bx, by, bw + extra, bh)]
        member = np.zeros(count, bool)
        member[group] = True
        for box in boxes:
            best = _hidden_reading(pair, sign, box, member, labels, window, z, side, touch_px, hidden, hidden_here,
                                   grow, best)
    return best


def side_by_side(pieces: Sequence[int], stats: np.ndarray, min_overlap: float) -> List[List[int]]:
    """Groups of the pieces of a plate cut by a lamp post or trunk in front: each two pieces level with each
    other (their rows overlap by ``min_overlap`` of the taller one's height), with every piece inside the box of
    the two (the wheels of a bicycle pictogram)."""
    groups = []
    for i, a in enumerate(pieces):
        for b in pieces[i + 1:]:
            (ax, ay, aw, ah), (bx, by, bw, bh) = stats[a, :4], stats[b, :4]
            if min(ay + ah, by + bh) - max(ay, by) < min_overlap * max(ah, bh):
                continue
            x0, y0, x1, y1 = min(ax, bx), min(ay, by), max(ax + aw, bx + bw), max(ay + ah, by + bh)
            groups.append([k for k in pieces if k in (a, b) or (stats[k, 0] >= x0 and stats[k, 1] >= y0 and
                                                                stats[k, 0] + stats[k, 2] <= x1 and
                                                                stats[k, 1] + stats[k, 3] <= y1)])
    return groups


def _hidden_reading(pair, sign, box, member, labels, window, z, side, touch_px, hidden, hidden_here, grow, best):
    """``best`` or the reading of ``box`` (window coordinates) as a plate whose pixels not in its pieces
    (``member[label]``) are hidden by something in front (``hidden_here``, window-sized): most of them must be
    (``plate_min_fill`` of the box seen or hidden), and ``plate_min_visible`` of it seen."""
    config = pair.config
    x0, y0, x1, y1 = window
    bx, by, bw, bh = box
    if bx < 0 or by < 0 or bx + bw > x1 - x0 or by + bh > y1 - y0:
        return best
    inside = member[labels[by:by + bh, bx:bx + bw]]
    # its print enclosed by pieces and what hides them is the plate's too (strokes cut open by a post in front)
    covered = _filled((inside | hidden_here[by:by + bh, bx:bx + bw]).astype(np.uint8), 1).astype(bool)
    seen_share, fill = float(inside.mean()), float(covered.mean())
    if fill < config.plates.plate_min_fill or seen_share < config.plates.plate_min_visible:
        return best
    for margin in (0.0, grow * bh):
        grown = (int(round(bx + x0 - margin)), int(round(by + y0 - margin)), int(round(bw + 2 * margin)),
                 int(round(bh + 2 * margin)))
        reading = _plate_reading(pair, sign, grown, z, side, touch_px, hidden)
        score = None if reading is None else fill * reading[0] * config.plates.plate_hidden_weight
        if score is not None and (best is None or score > best[0]):
            best = (score, grown, reading[1], fill)
    return best


def hidden_mask(bgr: np.ndarray, depth: np.ndarray, z: float, config) -> np.ndarray:
    """Pixels of a window that something in front of a plate at depth ``z`` covers: coloured ones (foliage,
    never a white plate's paper or its black print) and, where depth is known, nearer ones (a lamp post)."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    coloured = hsv[:, :, 1] > config.plates.plate_max_saturation
    nearer = np.isfinite(depth) & (depth < z - depth_tolerance_m(z, config))
    return (coloured | nearer).astype(np.uint8)


class _HiddenCanvas:
    """One image-sized mask per image size and thread, reused by every window (allocating and zeroing a
    full-frame mask per sign and side cost more than the plate search itself)."""

    _local = threading.local()

    @classmethod
    def of(cls, shape) -> np.ndarray:
        canvas = getattr(cls._local, "canvas", None)
        if canvas is None or canvas.shape != tuple(shape):
            canvas = cls._local.canvas = np.zeros(shape, np.uint8)
        return canvas


def plates_of_sign(pair: PairContext, depth: np.ndarray, sign: Detection, side: int,
                   others: Sequence[Detection] = ()) -> Optional[Detection]:
    """The plate right below (``side`` BELOW) or above (ABOVE) one sign, or None. ``others``: the pair's other
    signs; no plate lies in them (the white inside of the next sign down is none), nor does their colour hide
    one."""
    config, camera = pair.config, pair.camera
    z = float(sign.depth_m)
    if not np.isfinite(z) or z <= 0:
        return None
    x, y, w, h = sign.bbox
    px_per_m = camera.fy / z
    # the window reaches as far as the largest plate, text or pictogram (a 5.31 under a 0.9 m sign is 0.62 m high)
    formats = all_plate_formats(plate_templates(pair)).values()
    largest_h = max(ph for _, ph in formats) * (1.0 + config.size.size_tolerance)
    largest_w = max(pw for pw, _ in formats) * (1.0 + config.size.size_tolerance)
    reach = int(round((config.plates.plate_max_gap_m + largest_h) * px_per_m))
    half_w = int(round(max(largest_w * camera.fx / z, w) / 2 + 2))
    cu = x + w / 2.0
    height, width = pair.left.shape[:2]
    x0, x1 = max(0, int(cu - half_w)), min(width, int(cu + half_w))
    # the window holds the sign too: a white region that goes on into the sign's box is part of its panel
    y0, y1 = (y, y + h + reach) if side == BELOW else (y - reach, y + h)
    y0, y1 = max(0, y0), min(height, y1)
    touch_px = max(2.0, config.plates.plate_min_gap_m * px_per_m, config.plates.plate_box_overshoot * h)
    if x1 - x0 < 8 or y1 - y0 < 8:
        return None
    window = pair.left[y0:y1, x0:x1]
    near = depth[y0:y1, x0:x1]
    elsewhere = np.isfinite(near) & (np.abs(near - z) > depth_tolerance_m(z, config))
    in_window = hidden_mask(window, near, z, config)
    for other in others:  # the window's part of the pair's other signs
        ox, oy, ow, oh = other.bbox
        ox0, oy0, ox1, oy1 = max(ox, x0) - x0, max(oy, y0) - y0, min(ox + ow, x1) - x0, min(oy + oh, y1) - y0
        if ox1 > ox0 and oy1 > oy0:
            in_window[oy0:oy1, ox0:ox1] = 0
            elsewhere[oy0:oy1, ox0:ox1] = True
    masks = white_masks(window, config)
    if masks:
        in_window |= crossing_occluders(1 - masks[0], (x - x0, x + w - x0), w, config.plates)
    hidden = _HiddenCanvas.of(pair.left.shape[:2])  # image-sized: the readings index it in image coordinates
    hidden[y0:y1, x0:x1] = in_window
    best = None
    try:
        for mask in masks:
            mask[elsewhere] = 0
            best = _best_region(pair, sign, mask, (x0, y0, x1, y1), z, side, touch_px, best, hidden)
        if best is not None:
            cx, cy, cw, ch = _clipped(best[1], pair.left.shape)
            crop_hidden = hidden[cy:cy + ch, cx:cx + cw].copy()
    finally:
        hidden[y0:y1, x0:x1] = 0  # the canvas is shared by the pair's windows
    if best is None:
        return None
    score, box, (name, (pw, ph), _), fill = best
    seen = seen_share(box, crop_hidden, pair.left.shape, config.plates.plate_edge_px)
    box = _clipped(box, pair.left.shape)
    u, v = bbox_centre(box)
    bx, by, bw, bh = box
    crop = np.ascontiguousarray(pair.left[by:by + bh, bx:bx + bw])
    template_id, label, printed = PLATE_ID, PLATE_NAMES["de"], None
    pictogram, likeness = classify_plate(crop, plate_templates(pair), config, crop_hidden)
    if pictogram is not None:  # its drawing's own size at the plate's span; its score is the likeness
        span = max(pw, ph)
        template_id, label, printed = pictogram.id, pictogram.name("de"), pictogram.text
        (pw, ph), name, score = pictogram.size_m(span), f"{pictogram.id}@{span:.2f}", min(score, likeness)
        if pictogram.field:  # a layout plate: OCR reads its text field alone
            crop, printed = text_field_only(crop, pictogram.field), None
    return Detection(
        template_id=template_id, name=label, colour="white", shape="rectangle", width_m=pw, height_m=ph,
        format=name, detection_indicator=float(fill), classification_indicator=float(score),
        status=ACCEPTED if score >= config.plates.plate_accept_score else REVIEW, u=u, v=v, bbox=box, depth_m=z,
        position=locate(camera, pair.pose, u, v, z), source="plate", normal_world=sign.normal_world,
        plate_of=sign, crop=crop, printed_text=printed, crop_seen=seen,
    )


def text_field_only(crop: np.ndarray, field: tuple) -> np.ndarray:
    """The part of a layout plate's crop that is its text ``field`` (x0, y0, x1, y1, shares of the plate): what
    OCR reads of it is the free text, not its arrows or pictogram, and at the size of a plate of its own (a text
    as small as 5.02's among much blank paper is read as nothing at all)."""
    h, w = crop.shape[:2]
    x0, y0, x1, y1 = (int(round(f * n)) for f, n in zip(field, (w, h, w, h)))
    return np.ascontiguousarray(crop[y0:max(y1, y0 + 1), x0:max(x1, x0 + 1)])


def find_plates(pair: PairContext, depth: np.ndarray, signs: Sequence[Detection]) -> List[Detection]:
    """The plates of the detected signs: at most one below and one above each."""
    if not pair.config.plates.find_plates:
        return []
    plates = []
    for sign in signs:
        others = [s for s in signs if s is not sign]
        for side in (BELOW, ABOVE):
            plate = plates_of_sign(pair, depth, sign, side, others)
            if plate is not None:
                plates.append(plate)
    return plates
