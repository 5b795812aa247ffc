"""White text panels (SSV 4.29, 4.30, 4.33): place-name and direction panels, found by their framed field.

A text panel is white sheeting with a thin black frame inset from its edge and black lettering. Its wording,
and with it its width, changes from panel to panel, so no template matches it. It is found as the bright,
achromatic field the frame encloses (a cell between strong edges, its letters holes in it) of a panel's
height at some depth of the search space, with the dark frame line seen around it; depth then decides as for
every white sign (size, planarity, standing free, a support below). Its layout names the kind: a field that
ends in a point is a direction panel (4.33), two fields of one width stacked on a black bar are the end of a
place (4.30), any other a place-name panel (4.29). The share of the field's outline on which the frame is
seen is the classification indicator. Its text is read after fusion from the field's crops (``crop``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from ..catalogue.text_panels import DIRECTION, PLACE_END, PLACE_NAME, TEXT_PANELS
from ..fusion.face_normal import world_face_normal
from ..geometry import Camera
from ..statuses import ACCEPTED, REVIEW
from .boxes import centre_inside
from .detection import Detection
from .locate import bbox_centre, locate
from .pair_context import PairContext
from .scene_colour import median_u8
from .search_range import face_depth, face_depth_limits, face_in_range
from .sizing import measure_segment, metric_size
from .white_outlines import bright_achromatic, filled
from .white_signs import coloured_share, network_reading, pole_share, side_shares, support_share

Box = Tuple[int, int, int, int]  # x, y, w, h
PAPER = 230  # the paper of a 4.30's two fields, evened out before they are set one over the other


@dataclass(frozen=True)
class PanelField:
    """A framed white field that may be a text panel's: its box and filled mask (in that box), full-image
    pixels, its layout and how much of a frame is seen around it."""

    box: Box
    mask: np.ndarray  # uint8 0/1, the field with its lettering (holes filled)
    layout: str
    frame_share: float  # share of its outline with dark beside it
    line_share: float  # share of its top and bottom edges where that dark is a thin line (the frame)
    bar_rows: Tuple[int, int] = (0, 0)  # a 4.30's bar, rows within the box (end exclusive); (0, 0) for none
    lettered: bool = True  # holds lettering (holes in the field)


def catalogued_kinds(catalogue, config) -> dict:
    """layout -> text panel kind, for the kinds the catalogue holds and the run does not exclude."""
    exclude = set(config.classification.exclude)
    return {k.layout: k for k in TEXT_PANELS.values() if k.id in catalogue and k.id not in exclude}


def field_height_range_px(camera: Camera, kinds: Sequence, config) -> Tuple[float, float]:
    """(lowest, highest) height in pixels of a field (the face less its frame margin) of ``kinds`` anywhere in
    near..far, widened by the size tolerance. A 4.30's fields are each about half its height."""
    if not kinds:
        return 0.0, 0.0
    tol, share = config.size.size_tolerance, 1.0 - 2.0 * config.white.panel_frame_margin
    halves = [0.5 if k.layout == PLACE_END else 1.0 for k in kinds]
    lo = min(k.smallest[1] * h for k, h in zip(kinds, halves)) * share * camera.fy / config.depth.far_m
    hi = max(k.largest[1] for k in kinds) * share * camera.fy / config.depth.near_m
    return lo * (1.0 - tol), hi * (1.0 + tol)


def frame_share(grey: np.ndarray, box: Box, mask: np.ndarray, config) -> float:
    """Share of the points on the field's outline with a dark line within ``panel_frame_reach`` of its height
    outside it: the frame, or the dark surroundings of a white board. Darker than ``panel_frame_contrast`` x the
    field's median brightness."""
    x, y, w, h = box
    reach = max(2, int(round(config.white.panel_frame_reach * h)))
    height, width = grey.shape[:2]
    x0, y0, x1, y1 = max(0, x - reach), max(0, y - reach), min(width, x + w + reach), min(height, y + h + reach)
    patch = grey[y0:y1, x0:x1]
    field = np.zeros(patch.shape, np.uint8)
    field[y - y0 : y - y0 + h, x - x0 : x - x0 + w] = mask
    if not field.any():
        return 0.0
    paper = float(np.median(patch[field > 0]))
    # what lies within reach outside the field only (its own letters are inside): the field masked bright
    outside = np.where(field > 0, 255, patch).astype(np.uint8)
    darkest = cv2.erode(outside, np.ones((2 * reach + 1, 2 * reach + 1), np.uint8))
    contours, _ = cv2.findContours(field, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    points = np.concatenate([c.reshape(-1, 2) for c in contours]) if contours else np.zeros((0, 2), int)
    if len(points) == 0:
        return 0.0
    values = darkest[points[:, 1], points[:, 0]]
    return float(np.count_nonzero(values < config.white.panel_frame_contrast * paper)) / len(points)


def line_share(grey: np.ndarray, box: Box, mask: np.ndarray, config) -> float:
    """Share of the field's columns where, above its top or below its bottom edge (the better of the two: a
    4.30's fields meet its bar on one), the dark seen there is a line: darker than ``panel_frame_contrast`` x
    the paper within ``panel_frame_reach`` of its height (``panel_line_reach_px`` at least), then bright again
    (``panel_margin_brightness`` x the paper) before that reach ends, as the white margin outside a panel's
    frame is. A white board or a plain white field has dark surroundings all the way out."""
    white = config.white
    x, y, w, h = box
    reach = max(white.panel_line_reach_px, int(round(white.panel_frame_reach * h)))
    rows = np.arange(mask.shape[0])[:, None]
    has = mask.any(axis=0)
    if not has.any():
        return 0.0
    paper = float(np.median(grey[y : y + h, x : x + w][mask > 0]))
    first = np.where(mask > 0, rows, mask.shape[0]).min(axis=0)
    last = np.where(mask > 0, rows, -1).max(axis=0)
    cols = np.flatnonzero(has)
    seen = []
    for start, step in ((y + first[cols] - 1, -1), (y + last[cols] + 1, 1)):
        lines = start[None, :] + step * np.arange(reach)[:, None]  # reach x columns, outward
        inside = (lines >= 0) & (lines < grey.shape[0])
        profile = np.where(inside, grey[np.clip(lines, 0, grey.shape[0] - 1), x + cols[None, :]], 0) / paper
        below = profile < white.panel_frame_contrast
        dark = below.any(axis=0)
        first = below.argmax(axis=0)  # the first dark pixel out from the field: the frame, if it has one
        after = np.where(np.arange(reach)[:, None] >= first[None, :], profile, 0.0).max(axis=0)
        seen.append(float(np.mean(dark & (after >= white.panel_margin_brightness) & inside.all(axis=0))))
    return max(seen)


def pointed_end(mask: np.ndarray, config) -> Optional[str]:
    """'left' or 'right' when the field's convex hull narrows to a point at that end (its last columns,
    ``panel_end_share`` x its height, at most ``panel_point_ratio`` x its middle's height on average), else None.
    The hull, as letters running into the frame notch a small field's edge."""
    points = cv2.findNonZero(mask)
    if points is None:
        return None
    hull = np.zeros_like(mask)
    cv2.fillConvexPoly(hull, cv2.convexHull(points), 1)
    heights = hull.sum(axis=0).astype(np.float64)
    n = len(heights)
    k = min(max(1, int(round(config.white.panel_end_share * mask.shape[0]))), max(1, n // 4))
    middle = float(np.median(heights[n // 4 : max(n // 4 + 1, 3 * n // 4)]))
    if middle <= 0:
        return None
    left, right = heights[:k].mean() / middle, heights[-k:].mean() / middle
    ratio = config.white.panel_point_ratio
    if left <= ratio < right:
        return "left"
    if right <= ratio < left:
        return "right"
    return None


def panel_fields(bgr: np.ndarray, height_range_px: Tuple[float, float], config) -> List[PanelField]:
    """Framed white fields of a text panel's size in ``bgr`` (its own pixels), largest first.

    Cells enclosed by strong edges (Canny on the grey image), of a field's height and aspect, bright and
    achromatic, that fill their box once their lettering's holes are filled, hold some lettering, and have
    the dark frame around most of their outline. Two such fields of one width stacked on a dark bar are read
    as one (a 4.30), a field ending in a point as a direction panel."""
    white = config.white
    lo, hi = height_range_px
    if hi <= 0:
        return []
    grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)
    edges = cv2.dilate(cv2.Canny(cv2.GaussianBlur(grey, (3, 3), 0), *white.panel_canny), np.ones((2, 2), np.uint8))
    _, labels, stats, _ = cv2.connectedComponentsWithStatsWithAlgorithm((edges == 0).astype(np.uint8), 4, cv2.CV_32S,
                                                                      cv2.CCL_SPAGHETTI)
    w, h, area = stats[:, cv2.CC_STAT_WIDTH], stats[:, cv2.CC_STAT_HEIGHT], stats[:, cv2.CC_STAT_AREA]
    keep = ((h >= lo) & (h <= hi) & (w >= white.panel_min_aspect * h) & (w <= white.panel_max_aspect * h)
            & (area >= white.panel_min_cell_fill * w * h))
    keep[0] = False
    ids = np.flatnonzero(keep)
    if len(ids):  # brightness and colour only for the few of a field's size, each within its own box
        hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
        floor = white.white_min_brightness * median_u8(hsv[:, :, 2])
        ids = [i for i in ids if bright_achromatic(labels, hsv, i, stats[i], floor, config)]
    ids = sorted(ids, key=lambda i: -int(area[i]))[: white.panel_max_candidates]
    fields = []
    for i in ids:
        x, y, bw, bh = (int(v) for v in stats[i, :4])
        cell = (labels[y : y + bh, x : x + bw] == i).astype(np.uint8)
        mask = (filled(cell) > 0).astype(np.uint8)
        area_filled = int(mask.sum())
        ink = 1.0 - float(cell.sum()) / max(area_filled, 1)
        if area_filled < white.panel_min_fill * bw * bh or ink > white.panel_max_ink:
            continue
        share = frame_share(grey, (x, y, bw, bh), mask, config)
        if share < white.panel_min_frame:
            continue
        line = line_share(grey, (x, y, bw, bh), mask, config)
        pointed = pointed_end(mask, config)
        if line < white.panel_min_line and not pointed:
            continue  # a white board; a pointed field is a pointer, its dark frame maybe the sign's edge
        layout = DIRECTION if pointed else PLACE_NAME
        fields.append(PanelField((x, y, bw, bh), mask, layout, share, line, lettered=ink >= white.panel_min_ink))
    # a blank field is no panel alone (a white board), but may be the part of a 4.30 a dirt mark cut off
    return [f for f in stacked_on_bars(fields, grey, config) if f.lettered]


def stacked_on_bars(fields: Sequence[PanelField], grey: np.ndarray, config) -> List[PanelField]:
    """``fields`` with every two of one width stacked on a dark bar (a 4.30: the place left, the bar, the
    next place) joined into one; the pieces of a pair are dropped."""
    white = config.white
    out, used = [], set()
    for i, a in enumerate(fields):
        for j, b in enumerate(fields):
            if i == j or i in used or j in used or a.layout != PLACE_NAME or b.layout != PLACE_NAME:
                continue
            (ax, ay, aw, ah), (bx, by, bw, bh) = a.box, b.box
            width = max(aw, bw)
            gap = by - (ay + ah)
            if not (abs(ax - bx) <= white.panel_stack_align * width
                    and abs(ax + aw - bx - bw) <= white.panel_stack_align * width):
                continue
            total = by + bh - ay
            if not (0 < gap <= white.panel_bar_max_share * total):
                continue
            x0, x1 = max(ax, bx), min(ax + aw, bx + bw)
            bar = grey[ay + ah : by, x0:x1]
            paper = float(np.median(grey[ay : ay + ah, x0:x1]))
            if bar.size == 0 or float(np.median(bar)) >= white.panel_frame_contrast * paper:
                continue
            if not (a.lettered or b.lettered):
                continue
            x, y = min(ax, bx), ay
            w = max(ax + aw, bx + bw) - x
            mask = np.zeros((total, w), np.uint8)
            mask[ay - y : ay - y + ah, ax - x : ax - x + aw] |= a.mask
            mask[by - y : by - y + bh, bx - x : bx - x + bw] |= b.mask
            mask[ah : by - y, x0 - x : x1 - x] = 1
            out.append(PanelField((x, y, w, total), mask, PLACE_END, min(a.frame_share, b.frame_share),
                                  line_share(grey, (x, y, w, total), mask, config), (ah, by - y)))
            used.update((i, j))
    rest = [f for k, f in enumerate(fields) if k not in used]
    return out + [under_a_bar(f, grey, config) or f for f in rest]


def under_a_bar(field: PanelField, grey: np.ndarray, config) -> Optional[PanelField]:
    """The 4.30 whose lower field ``field`` is, when right above it lies a dark bar across its width (a run of
    dark rows ``panel_bar_rows`` x its height, darker than ``panel_frame_contrast`` x its paper) and above the
    bar a bright field up to a dark line (the frame): its upper field, blank or too faint to be a field of its
    own. None otherwise (a 4.29's frame is a thin line, not a bar)."""
    if field.layout != PLACE_NAME:
        return None
    white = config.white
    x, y, w, h = field.box
    lo, hi = white.panel_bar_rows
    cols = slice(x + w // 10, x + w - w // 10)  # the middle of its width: clear of rounded corners and posts
    paper = float(np.median(grey[y : y + h, x : x + w][field.mask > 0]))
    top = max(0, y - int(round((hi + 1.0) * h)))
    rows = np.median(grey[top:y, cols], axis=1)[::-1] / max(paper, 1.0)  # upward from the field's top
    dark = rows < white.panel_frame_contrast
    bar = int(np.argmin(dark)) if not dark.all() else len(dark)  # dark rows right above the field
    if not lo * h <= bar <= hi * h:
        return None
    above = rows[bar:]
    end = int(np.argmax(above < white.panel_frame_contrast)) if (above < white.panel_frame_contrast).any() else 0
    if end < lo * h or above[:end].min() < white.panel_margin_brightness:
        return None  # no bright upper field closed by a frame line above the bar
    total = h + bar + end
    mask = np.ones((total, w), np.uint8)
    return PanelField((x, y - bar - end, w, total), mask, PLACE_END, field.frame_share, field.line_share,
                      (end, end + bar), field.lettered)


def face_box(field: PanelField, config) -> Box:
    """The panel's face around its field: the frame and the white margin outside it (``panel_frame_margin`` of
    the face's height on every side)."""
    x, y, w, h = field.box
    m = config.white.panel_frame_margin
    grow = int(round(m * h / (1.0 - 2.0 * m)))
    return x - grow, y - grow, w + 2 * grow, h + 2 * grow


def _evened(part: np.ndarray) -> np.ndarray:
    """``part`` with its paper brought to ``PAPER``: a 4.30's two fields may lie in different light."""
    grey = part.mean(axis=2) if part.ndim == 3 else part
    paper = float(np.percentile(grey, 75)) if grey.size else PAPER
    return np.clip(part.astype(np.float32) * (PAPER / max(paper, 1.0)), 0, 255).astype(np.uint8)


def reading_crop(bgr: np.ndarray, field: PanelField) -> np.ndarray:
    """The field as OCR reads it: its lettering on its own paper, everything outside its outline (a pixel in
    from it: the frame's blur) and a 4.30's bar painted over with the paper. A 4.30's small top line is set
    over its lower lines at their letter size (a line a third of their height is below what OCR reads)."""
    x, y, w, h = field.box
    crop = bgr[y : y + h, x : x + w].copy()
    inner = cv2.erode(field.mask, np.ones((3, 3), np.uint8)) if min(w, h) > 8 else field.mask
    paper = np.median(crop[inner > 0], axis=0) if inner.any() else np.full(3, 255.0)
    crop[inner == 0] = paper
    top, bottom = field.bar_rows
    if bottom <= top:
        return crop
    upper, lower = _evened(crop[:top]), _evened(crop[bottom:])
    if upper.shape[0] < 2 or lower.shape[0] < 2:
        crop[top:bottom] = paper
        return crop
    # the upper line's letters at the size of the lower ones': the lower part holds one line per 1.6 x its height
    rows = max(1, int(round(lower.shape[0] / upper.shape[0] / 1.6)))
    scale = lower.shape[0] / rows / upper.shape[0]
    upper = cv2.resize(upper, (max(1, int(round(upper.shape[1] * scale))), max(1, lower.shape[0] // rows)),
                       interpolation=cv2.INTER_LINEAR)
    width = max(upper.shape[1], lower.shape[1])
    parts = [cv2.copyMakeBorder(part, 0, 0, 0, width - part.shape[1], cv2.BORDER_CONSTANT, value=[PAPER] * 3)
             for part in (upper, lower)]
    return np.vstack(parts)


def text_panel_fields(pair: PairContext) -> List[PanelField]:
    """Text panel fields in the pair's roi (full-image pixels); none when the white step is off or the
    catalogue holds no text panel."""
    config = pair.config
    kinds = catalogued_kinds(pair.catalogue, config)
    if not config.white.white_signs or not config.white.text_panels or not kinds:
        return []
    x0, y0, x1, y1 = pair.roi
    found = panel_fields(pair.left[y0:y1, x0:x1], field_height_range_px(pair.camera, list(kinds.values()), config),
                         config)
    return [replace(f, box=(f.box[0] + x0, f.box[1] + y0, f.box[2], f.box[3])) for f in found]


def context_boxes(fields: Sequence[PanelField], config) -> List[Box]:
    """Boxes depth is needed in around each field: its face, the bands beside it and the strip below it."""
    white = config.white
    out = []
    for f in fields:
        x, y, w, h = face_box(f, config)
        side = int(round((white.white_side_gap + white.white_side_band) * w))
        below = int(round((white.white_support_gap + white.white_support_length) * h))
        out.append((max(0, x - side), max(0, y), w + 2 * side, h + below))
    return out


def held(box: Box, depth: np.ndarray, grey: np.ndarray, z: float, config) -> Tuple[bool, bool]:
    """(by depth, in the image): whether something at the panel's depth stands below it, and whether a pole's
    straight edges run down below it; each looked for below its middle and below a quarter of its width from
    either side (a wide panel stands on two posts), by white_signs' support tests."""
    x, y, w, h = box
    by_depth = in_image = False
    for shift in (0, -w // 4, w // 4):  # the support tests look below the middle of the box they are given
        moved = (x + shift, y, w, h)
        by_depth = by_depth or support_share(depth, moved, z, config) >= config.white.white_min_support
        in_image = in_image or pole_share(grey, moved, config) >= config.white.white_min_pole_rows
    return by_depth, in_image


def frame_indicator(field: PanelField, config) -> float:
    """The classification indicator of a text panel: how clearly its frame is seen, the share of its outline
    with dark beside it, scaled down where less than ``panel_full_line`` of its top and bottom show that dark
    as a thin line (a white board before a dark wall has dark beside it, but no line). A pointer's point tells
    it from a board: its frame share alone (its dark edge may be the sign's own, no margin outside it)."""
    if field.layout == DIRECTION:
        return field.frame_share
    return field.frame_share * min(1.0, field.line_share / config.white.panel_full_line)


def judge_panel(field: PanelField, pair: PairContext, depth: np.ndarray, grey: np.ndarray) -> Optional[Detection]:
    """The text panel ``field`` belongs to, or None (cut by the image's edge, no depth, not of a panel's size at
    its depth, not planar, not standing free, coloured, or without a support and a clear frame)."""
    camera, config = pair.camera, pair.config
    white = config.white
    kind = catalogued_kinds(pair.catalogue, config).get(field.layout)
    if kind is None:
        return None
    x, y, w, h = box = face_box(field, config)
    height, width = grey.shape[:2]
    if x < 0 or y < 0 or x + w > width or y + h > height:
        return None
    size = measure_segment(camera, depth, field.box, field.mask, *face_depth_limits(camera, field.box, config.depth))
    if size is None or size.coverage < config.planarity.min_depth_coverage or \
            not face_in_range(camera, field.box, size.depth_m, config.depth):
        return None
    planarity = pair.planarity(depth, field.box, field.mask)
    if planarity.indicator < config.planarity.detection_threshold:
        return None
    u, v = bbox_centre(box)
    z = face_depth(planarity.depth_at(camera, u, v), size.depth_m, camera, u, v, config.depth, 0.0)
    width_m, height_m = metric_size(camera, box, z)
    if not kind.fits(width_m, height_m, config.size.size_tolerance):
        return None
    if coloured_share(pair.left, box, config) > white.white_max_coloured_share:
        return None
    by_depth, pole_seen = held(box, depth, grey, z, config)
    supported = by_depth or pole_seen
    beside = [share for share in side_shares(depth, box, z, config) if share is not None]
    if not pole_seen and beside and min(beside) > white.white_max_side_share:
        return None  # a shop sign or a window in a façade (a panel on its pole may stand just before a wall)
    indicator = frame_indicator(field, config)
    if not supported and indicator < white.panel_unsupported_frame:
        return None
    accepted = supported and indicator >= white.panel_accept_frame
    step = white.panel_size_step_m
    template_id = specific_pointer(pair, box, kind.id) if field.layout == DIRECTION else kind.id
    return Detection(
        template_id=template_id, name=pair.catalogue[template_id].name("de"), colour="white", shape="rectangle",
        width_m=round(width_m / step) * step, height_m=round(height_m / step) * step, format="measured",
        detection_indicator=planarity.indicator, classification_indicator=indicator,
        status=ACCEPTED if accepted else REVIEW, u=u, v=v, bbox=box, depth_m=float(z),
        position=locate(camera, pair.pose, u, v, z), source="text-panel",
        normal_world=world_face_normal(camera, pair.pose, planarity.plane),
        crop=reading_crop(pair.left, field),
    )


def specific_pointer(pair: PairContext, box: Box, generic: str) -> str:
    """The white pointer a direction panel's face shows: a catalogued pointer with a pictogram or fixed text
    (parking 4.46, lorries 4.45, a company 4.49, ...) where the network reads one clearly among them and the
    generic panel ``generic``; else ``generic``, the panel told by its layout."""
    ids = [e.id for e in pair.catalogue if e.colour == "white" and e.shape == "pointer"] + [generic]
    reading = network_reading(pair, box, ids)
    return reading.template_id if reading is not None else generic


def plate_of(box: Box, signs: Sequence[Detection], config) -> bool:
    """Whether ``box`` hangs right below or above one of ``signs`` on its support (half its width at least under
    the sign, at most ``panel_plate_gap`` x the sign's height from it): a supplementary plate, framed and
    lettered like a text panel, which the plate step reads."""
    x, y, w, h = box
    for d in signs:
        sx, sy, sw, sh = d.bbox
        overlap = min(x + w, sx + sw) - max(x, sx)
        gap = max(y - (sy + sh), sy - (y + h))
        if overlap >= 0.5 * min(w, sw) and gap <= config.white.panel_plate_gap * sh:
            return True
    return False


def text_panel_detections(pair: PairContext, depth: np.ndarray, fields: Sequence[PanelField],
                          found: Sequence[Detection]) -> List[Detection]:
    """Text panels among ``fields`` whose centre lies in no sign ``found`` already, and that are not a plate of
    one."""
    if not fields:
        return []
    taken = [d.bbox for d in found]
    grey = cv2.cvtColor(pair.left, cv2.COLOR_BGR2GRAY)
    out = []
    for f in fields:
        if any(centre_inside(f.box, box) for box in taken) or plate_of(face_box(f, pair.config), found, pair.config):
            continue
        det = judge_panel(f, pair, depth, grey)
        if det is not None:
            out.append(det)
            taken.append(det.bbox)
    return out
