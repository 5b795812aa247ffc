"""Step 3: colour segmentation in HSV and connected segments with filled outlines.

Red signs are a red ring around a white field, so each segment is the filled
outer contour of its colour component, not the coloured pixels alone. Where
that outline is far from convex (a ring opened by an occluding pole or branch),
the convex hull is used instead: every sign outline is convex but the St
Andrew's cross's, which is kept where the outline fits one.

Segments come from up to three passes: the strong HSV classes with the speckle
opening (as in Cavegn 2011), the scene pass on the white-balanced image with
this scene's lowered saturation floors (faded rings, dull light; see
:mod:`.scene_colour`), and, where the smallest sign the search space can hold has a ring
thinner than the opening, a pass with an opening scaled to that ring, kept to
small segments. Only red faces have thin rings (blue and yellow faces are solid
fields), so with the scene pass on, the small-ring pass reads the scene classes
of the ring colours (``config.colour.hole_colours``: red); without it, the strong classes
of all colours. A last pass finds the white fields of red-ringed faces by their
brightness, where the ring has too little colour left (:mod:`.bright_fields`).
Segments of the scene classes must stand out of their surroundings and have a
sign's outline; no pass adds a segment an earlier pass found.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

import cv2
import numpy as np

from .boxes import box_iou, nonzero_box, touches_border, union_box
from .bright_fields import bright_faces
from .config import ColourConfig, HsvRange, PipelineConfig
from .scene_colour import apply_gains, chroma_at_least, scene_colour
from .shape import (
    CROSS_OUTLINES,
    DOUBLE_CROSS_OUTLINES,
    classify_shape,
    fill_ratio,
    plausible_outlines,
    shape_fits,
    shapes_tried,
)


@dataclass
class Segment:
    """One candidate sign face in the left image.

    ``mask`` is the filled outline inside ``bbox`` (uint8 0/255, shape (h, w)),
    ``contour`` the outer contour in full-image pixel coordinates.
    """

    colour: str
    bbox: Tuple[int, int, int, int]  # x, y, w, h
    mask: np.ndarray
    contour: np.ndarray
    area_px: int
    touches_border: bool
    source: str = "colour"
    solidity: float = 1.0  # filled outline area / convex hull area, before any hull filling
    depth_mask: Optional[np.ndarray] = None  # pixels for depth and planarity if not all of ``mask``

    @property
    def surface_mask(self) -> np.ndarray:
        """The pixels known to lie on the face: ``depth_mask`` if set, else ``mask``."""
        return self.mask if self.depth_mask is None else self.depth_mask


def inscribed_disc(size: int) -> Tuple[np.ndarray, np.ndarray]:
    """(uint8 0/255 mask, outer contour in box pixels) of the disc inscribed in a ``size`` x ``size`` box: the
    outline of a round face known by its circle (a Hough circle, the disc read from its half)."""
    mask = np.zeros((size, size), np.uint8)
    cv2.circle(mask, (size // 2, size // 2), size // 2, 255, thickness=cv2.FILLED)
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    return mask, contours[0]


def hsv_mask(hsv: np.ndarray, ranges: Sequence[HsvRange]) -> np.ndarray:
    """uint8 0/255 mask of pixels inside any of the HSV ranges."""
    out = None
    for h0, h1, s0, s1, v0, v1 in ranges:
        part = cv2.inRange(hsv, (h0, s0, v0), (h1, s1, v1))
        out = part if out is None else cv2.bitwise_or(out, part, dst=out)
    return np.zeros(hsv.shape[:2], dtype=np.uint8) if out is None else out


def _kernel(size: int) -> Optional[np.ndarray]:
    return cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (size, size)) if size > 1 else None


def clean_mask(mask: np.ndarray, open_px: int, close_px: int) -> np.ndarray:
    """Morphological opening (speckle) then closing (gaps in thin rings).

    Only the box around the mask's pixels is filtered (sign colours are sparse in most frames);
    the result is the same as filtering the whole mask.
    """
    part, (x0, y0) = cleaned_part(mask, open_px, close_px)
    out = np.zeros(mask.shape, np.uint8)
    out[y0 : y0 + part.shape[0], x0 : x0 + part.shape[1]] = part
    return out


def cleaned_part(mask: np.ndarray, open_px: int, close_px: int) -> Tuple[np.ndarray, Tuple[int, int]]:
    """(the part of :func:`clean_mask`'s result that can hold pixels, its top-left corner in ``mask``): the box
    around the mask's pixels grown by more than the filters reach, so that every pixel outside it, and the
    part's own edge unless it is the mask's, is 0 (an empty part when the mask has no pixels)."""
    x, y, w, h = nonzero_box(mask)
    if w == 0 or h == 0:
        return np.zeros((0, 0), np.uint8), (0, 0)
    pad = max(open_px, close_px) + 1
    x0, y0 = max(0, x - pad), max(0, y - pad)
    x1, y1 = min(mask.shape[1], x + w + pad), min(mask.shape[0], y + h + pad)
    part = mask[y0:y1, x0:x1]
    k_open, k_close = _kernel(open_px), _kernel(close_px)
    if k_open is not None:
        part = cv2.morphologyEx(part, cv2.MORPH_OPEN, k_open)
    if k_close is not None:
        part = cv2.morphologyEx(part, cv2.MORPH_CLOSE, k_close)
    return part, (x0, y0)


def colour_masks(bgr: np.ndarray, settings: ColourConfig, colours: Iterable[str],
                 search_mask: Optional[np.ndarray] = None) -> Dict[str, np.ndarray]:
    """Cleaned uint8 masks per colour (the colour section's thresholds and morphology), limited to
    ``search_mask`` (bool) when given."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    masks = {}
    for colour in colours:
        mask = hsv_mask(hsv, settings.hsv_ranges[colour])
        if search_mask is not None:
            mask[~search_mask] = 0
        masks[colour] = clean_mask(mask, settings.morph_open_px, settings.morph_close_px)
    return masks


CROSS_SOLIDITY = (0.4, 0.75)  # a St Andrew's cross fills about half of its hull
CROSS_MIN_FIT = 0.75  # a non-convex outline is kept as a cross only where it fits one this well
CROSS_FILL_WINDOW = 0.2  # the shapes it is compared with: those whose ideal fill is this close to its own


def is_cross(filled: np.ndarray, solidity: float) -> bool:
    """Whether a filled outline far from convex is a St Andrew's cross (``shape.CROSS_OUTLINES``)."""
    if not CROSS_SOLIDITY[0] <= solidity <= CROSS_SOLIDITY[1]:
        return False
    # most such outlines (foliage, façades) fit no cross: the other shapes are fitted only where one does
    crosses = [s for s in shapes_tried(fill_ratio(filled), CROSS_FILL_WINDOW) if s in CROSS_OUTLINES]
    if max(shape_fits(filled, crosses).values(), default=0.0) < CROSS_MIN_FIT:
        return False
    return classify_shape(filled, CROSS_MIN_FIT, CROSS_FILL_WINDOW).shape in CROSS_OUTLINES


def _filled_segment(contour, colour, width, height, border_margin_px, source, min_solidity, box):
    """Segment of one contour (its bounding ``box``): its filled outline (hull where far from convex) in its box."""
    x, y, w, h = box
    filled = np.zeros((h, w), dtype=np.uint8)
    cv2.drawContours(filled, [contour], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
    hull = cv2.convexHull(contour)
    hull_area = max(1.0, cv2.contourArea(hull))
    solidity = min(1.0, cv2.contourArea(contour) / hull_area)
    if solidity < min_solidity and not is_cross(filled, solidity):
        cv2.drawContours(filled, [hull], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
    touches = touches_border(box, width, height, border_margin_px)
    return Segment(colour, (x, y, w, h), filled, contour, int(np.count_nonzero(filled)), touches, source, solidity)


def segments_from_mask(mask: np.ndarray, colour: str, min_area_px: int, settings: ColourConfig,
                       holes: bool = False, offset: Tuple[int, int] = (0, 0),
                       image_size: Optional[Tuple[int, int]] = None) -> List[Segment]:
    """Connected segments of ``mask`` as filled outer contours with bounding boxes.

    ``settings``: the colour section of the config (``min_bbox_px``, ``border_margin_px``,
    ``min_solidity``, ``min_hole_px``, ``max_ring_ratio``). A component inside the hole of
    another is a segment of its own. Outlines with a solidity below ``min_solidity`` are
    replaced by their convex hull. With ``holes``, the enclosed fields of a segment (the
    white field inside a red ring or border) are segments too (source "hole"), unless the
    outer outline is just a ring around the field (box at most ``max_ring_ratio`` times the
    field's box): a ring that touches another red thing (a second sign, a roof) gives a
    useless outer outline, but its field still has the face's shape.

    ``mask`` may be a part of the image (:func:`cleaned_part`): ``offset`` is its top-left corner in the image,
    ``image_size`` the image's (height, width), and the part's edge is 0 unless it is the image's.
    """
    min_bbox_px, border_margin_px = settings.min_bbox_px, settings.border_margin_px
    min_solidity, min_hole_px, max_ring_ratio = settings.min_solidity, settings.min_hole_px, settings.max_ring_ratio
    height, width = image_size or mask.shape[:2]
    # two levels: outer outlines of every component, also of one inside another's hole (a sign's colour
    # inside its white rim, in front of background of the same colour), and the holes
    if not mask.size:
        return []
    contours, hierarchy = cv2.findContours(mask, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_NONE, offset=offset)
    # a closed outline of every pixel along it that spans min_bbox_px columns or rows walks there and back:
    # fewer points cannot make a box that large (most contours are speckle: skipped without measuring them)
    min_points = 2 * (min_bbox_px - 1)
    out = []
    for k, contour in enumerate(contours):
        if len(contour) < min_points:
            continue
        parent = hierarchy[0][k][3] if hierarchy is not None else -1
        if parent >= 0 and not holes:
            continue
        x, y, w, h = cv2.boundingRect(contour)
        if w < min_bbox_px or h < min_bbox_px:
            continue
        if parent < 0:
            seg = _filled_segment(contour, colour, width, height, border_margin_px, "colour", min_solidity,
                                  (x, y, w, h))
            if seg.area_px >= min_area_px:
                out.append(seg)
            continue
        _, _, pw, ph = cv2.boundingRect(contours[parent])
        if pw <= max_ring_ratio * w and ph <= max_ring_ratio * h or cv2.contourArea(contour) < min_hole_px:
            continue
        out.append(_filled_segment(contour, colour, width, height, border_margin_px, "hole", min_solidity,
                                   (x, y, w, h)))
    return out


def ring_open_px(face_px: float, config: PipelineConfig) -> int:
    """Opening that keeps the ring of a ``face_px`` face: at most ring width - 1, at most the usual one."""
    ring_px = config.colour.ring_fraction * face_px
    return int(np.clip(np.floor(ring_px) - 1, 1, config.colour.morph_open_px))


def _ring_safe_max_px(config: PipelineConfig) -> float:
    """Faces larger than this keep their ring under the usual opening: the small-ring pass ignores them."""
    return (config.colour.morph_open_px + 1) / config.colour.ring_fraction


def outline_surround_share(mask: np.ndarray, seg: Segment, grow: float) -> float:
    """Share of ``mask`` pixels in the band around the segment's filled outline, ``grow`` x its size wide.

    The band follows the outline, so a face whose coloured part sits in a white rim (a priority
    road's yellow diamond) is surrounded by the rim, whatever colour lies beyond the face.
    """
    height, width = mask.shape[:2]
    x, y, w, h = seg.bbox
    g = max(1, int(round(grow * max(w, h))))
    x0, y0, x1, y1 = max(0, x - g), max(0, y - g), min(width, x + w + g), min(height, y + h + g)
    # the band: pixels off the outline within g of it along rows, columns and diagonals (a square dilation), read
    # from the exact chessboard distance, whose cost does not grow with g as a (2g+1)-wide dilation's does
    off_outline = np.full((y1 - y0, x1 - x0), 255, np.uint8)
    off_outline[y - y0 : y - y0 + h, x - x0 : x - x0 + w] = cv2.bitwise_not(seg.mask)
    distance = cv2.distanceTransform(off_outline, cv2.DIST_C, 3)
    band = cv2.inRange(distance, 0.5, float(g))
    area = cv2.countNonZero(band)
    return cv2.countNonZero(cv2.bitwise_and(mask[y0:y1, x0:x1], band)) / float(area) if area else 0.0


@dataclass
class ColourFrame:
    """What the colour passes read from one image, computed once per image and shared by its passes
    (and by the two looks the pipeline takes: before depth for the stereo rows, then within the search space).
    """

    hsv: np.ndarray  # HSV of the image as it is: the strong pass
    hsv_weak: np.ndarray  # HSV of the white-balanced image (or ``hsv`` itself): the scene pass
    colourful: Optional[np.ndarray]  # uint8 0/255: chroma high enough for the scene pass
    weak_ranges: Dict[str, Tuple[HsvRange, ...]]
    masks: Dict[Tuple[str, bool], np.ndarray] = field(default_factory=dict)  # filled by colour_mask
    # filled by bright_segments: (fields in red rings, white-framed yellow diamonds) per smallest face
    fields: Dict[Optional[float], Tuple[List[Segment], List[Segment]]] = field(default_factory=dict)

    def bright_segments(self, image: np.ndarray, config: PipelineConfig,
                        small_face_px: Optional[float]) -> Tuple[List[Segment], List[Segment]]:
        """(white fields in red rings, white-framed yellow diamonds) of the whole image
        (:func:`bright_face_segments`); found once per image."""
        if small_face_px not in self.fields:
            self.fields[small_face_px] = bright_face_segments(image, None, config, small_face_px)
        return self.fields[small_face_px]

    def ring_fields(self, image: np.ndarray, config: PipelineConfig, small_face_px: Optional[float]) -> List[Segment]:
        """The image's white fields in red rings (:func:`field_segments` of the whole image); found once per image."""
        return self.bright_segments(image, config, small_face_px)[0]

    def colour_mask(self, colour: str, scene: bool, config: PipelineConfig) -> np.ndarray:
        """uint8 0/255 mask of one colour class, strong or of the scene pass; computed once per image."""
        key = (colour, scene)
        if key not in self.masks:
            if scene:
                mask = cv2.bitwise_and(hsv_mask(self.hsv_weak, self.weak_ranges[colour]), self.colourful)
            else:
                mask = hsv_mask(self.hsv, config.colour.hsv_ranges[colour])
            self.masks[key] = mask
        return self.masks[key]

    @classmethod
    def of(cls, image: np.ndarray, config: PipelineConfig) -> ColourFrame:
        hsv = cv2.cvtColor(image, cv2.COLOR_BGR2HSV)
        if not config.scene.weak_colour:
            return cls(hsv, hsv, None, {})
        scene = scene_colour(image, config)
        balanced = apply_gains(image, scene.gains, config.scene.white_balance_min_change)
        hsv_weak = hsv if balanced is image else cv2.cvtColor(balanced, cv2.COLOR_BGR2HSV)
        colourful = chroma_at_least(hsv_weak, config.scene.weak_min_chroma).view(np.uint8) * 255
        return cls(hsv, hsv_weak, colourful, scene.weak_ranges)


def _weak_outline(seg: Segment, colour: str, config: PipelineConfig) -> bool:
    """Whether a scene-pass segment has an outline a face of its colour has (``config.scene.weak_shapes``; any
    ideal outline for colours not listed there)."""
    result, shapes = plausible_outlines(seg.mask, config)
    allowed = config.scene.weak_shapes.get(colour)
    return (bool(shapes) and (allowed is None or any(s in allowed for s in shapes))
            and result.fit >= config.scene.weak_min_fit.get(colour, 0.0))


def _outline_lost(earlier: Segment, later: Segment, config: PipelineConfig) -> bool:
    """Whether an earlier pass's segment lost the outline that a later pass's segment of the same place has.

    The strong pass may keep only part of a faded ring (no ideal outline fits it) where the scene pass
    finds the whole disc: the later one is then a face of its own, not a duplicate. The earlier one stays
    too, as a piece a split face may still be merged from.
    """
    if earlier.source != "colour" or later.source != "colour":
        return False  # a field (hole) is the same field whichever pass found it
    shape = config.shape
    before = classify_shape(earlier.mask, shape.min_shape_fit, shape.shape_fill_window).fit
    after = classify_shape(later.mask, shape.min_shape_fit, shape.shape_fill_window).fit
    return after >= shape.confident_shape_fit and after > before + shape.shape_ambiguity


def find_colour_segments(image: np.ndarray, search: Optional[np.ndarray], config: PipelineConfig,
                         small_face_px: Optional[float] = None, frame: Optional[ColourFrame] = None) -> List[Segment]:
    """Colour segments of ``image`` (limited to the bool ``search`` mask when given), all passes.

    ``small_face_px``: the smallest face (pixels) worth finding; the ring of such a
    face sets the opening of the small-ring pass. None: ``config.colour.min_face_px``
    (no depth, so no size limit from a search space). ``frame``: the image's
    :class:`ColourFrame` if already computed.
    """
    segmenting, scene = config.colour, config.scene
    frame = frame or ColourFrame.of(image, config)
    inside = None if search is None else search.view(np.uint8) * 255  # bool bytes are 0/1: no copy first
    small_open = ring_open_px(segmenting.min_face_px if small_face_px is None else small_face_px, config)
    # (opening, largest side kept, scene classes, colours)
    passes = [(segmenting.morph_open_px, None, False, segmenting.colours)]
    if scene.weak_colour:
        passes.append((segmenting.morph_open_px, None, True, scene.weak_colours))
    if small_open < segmenting.morph_open_px:
        rings = ([c for c in scene.weak_colours if c in segmenting.hole_colours] if scene.weak_colour
                 else segmenting.colours)
        passes.append((small_open, _ring_safe_max_px(config), scene.weak_colour, rings))
    out: List[Segment] = []
    for open_px, max_side, weak, colours in passes:
        for colour in colours:
            if colour not in segmenting.colours:
                continue
            raw = frame.colour_mask(colour, weak, config)
            if inside is not None:
                raw = cv2.bitwise_and(raw, inside)
            part, offset = cleaned_part(raw, open_px, segmenting.morph_close_px)  # the rest of the frame is 0
            min_px = segmenting.min_part_px.get(colour, segmenting.min_segment_px)
            for seg in segments_from_mask(part, colour, min_px, segmenting, colour in segmenting.hole_colours,
                                          offset, raw.shape[:2]):
                if max_side is not None and max(seg.bbox[2], seg.bbox[3]) > max_side:
                    continue
                if weak and not _weak_outline(seg, colour, config):
                    continue  # the scene pass's extra segments must look like a face to be worth depth
                if weak and outline_surround_share(raw, seg, scene.weak_surround_px) > scene.weak_max_surround:
                    continue  # part of a larger coloured area (sky, hedge, façade), not a face of its own
                if any(o.colour == colour and box_iou(o.bbox, seg.bbox) >= scene.pass_duplicate_iou
                       and not _outline_lost(o, seg, config) for o in out):
                    continue  # an earlier pass outlined this face already
                out.append(seg)
    if config.bright_fields.field_pass and "red" in config.colour.colours:
        for seg in frame.ring_fields(image, config, small_face_px):
            if search is not None and inside_share(seg, search) < config.bright_fields.field_min_inside_share:
                continue  # a field mostly outside the search space
            # the same field from the colour passes' holes, or the field of a ring they outlined whole (a part of
            # a ring overlapping the field is no outline of it)
            if not any(o.colour == "red" and (o.source == "hole" and box_iou(o.bbox, seg.bbox)
                                              >= config.scene.pass_duplicate_iou
                                              or _field_of(seg.bbox, o.bbox, config)
                                              and _outlined_whole(seg, o, config))
                       for o in out):
                out.append(seg)
    if config.bright_fields.diamond_pass and "yellow" in config.colour.colours:
        for seg in frame.bright_segments(image, config, small_face_px)[1]:
            if search is not None and inside_share(seg, search) < config.bright_fields.field_min_inside_share:
                continue
            out.append(seg)  # a priority road's whole outline; its yellow part (if found) gives other readings
    return out


def _field_of(field, outline, config: PipelineConfig) -> bool:
    """Whether a field's box lies inside a segment's box and fills enough of it: the field of a ring the colour
    passes outlined already (``field_in_outline_slack_px``, ``field_in_outline_min_share``)."""
    fx, fy, fw, fh = field
    x, y, w, h = outline
    slack = config.bright_fields.field_in_outline_slack_px
    inside = fx >= x - slack and fy >= y - slack and fx + fw <= x + w + slack and fy + fh <= y + h + slack
    return inside and fw * fh >= config.bright_fields.field_in_outline_min_share * w * h


def _outlined_whole(field: Segment, outline: Segment, config: PipelineConfig) -> bool:
    """Whether a colour outline around a field may be its ring outlined whole: it may have a shape the field may
    have. A ring half lost in dim light reads as another shape (a triangle's two sides as a diamond), and then
    its field stands for the face."""
    _, field_shapes = plausible_outlines(field.mask, config)
    if not field_shapes:
        return True
    _, outline_shapes = plausible_outlines(outline.mask, config)
    return bool(set(field_shapes) & set(outline_shapes))


def inside_share(seg: Segment, search: np.ndarray) -> float:
    """Share of the segment's pixels inside the bool ``search`` mask."""
    x, y, w, h = seg.bbox
    mask = seg.mask > 0
    return float(np.count_nonzero(search[y : y + h, x : x + w][mask])) / max(1, np.count_nonzero(mask))


def field_segments(image: np.ndarray, search: Optional[np.ndarray], config: PipelineConfig,
                   small_face_px: Optional[float] = None) -> List[Segment]:
    """The white fields of red-ringed faces found by brightness (:mod:`.bright_fields`) as "hole" segments."""
    return bright_face_segments(image, search, config, small_face_px)[0]


def bright_face_segments(image: np.ndarray, search: Optional[np.ndarray], config: PipelineConfig,
                         small_face_px: Optional[float] = None) -> Tuple[List[Segment], List[Segment]]:
    """(the white fields of red-ringed faces as red "hole" segments, white-framed diamonds with a yellow middle
    as yellow "frame" segments, the face's whole outline), both found by brightness
    (:func:`.bright_fields.bright_faces`)."""
    height, width = image.shape[:2]
    found = bright_faces(image, search, config, small_face_px)

    def segment(part, colour: str, source: str) -> Segment:
        touches = touches_border(part.bbox, width, height, config.colour.border_margin_px)
        return Segment(colour, part.bbox, part.mask, part.contour, int(np.count_nonzero(part.mask)), touches, source)

    return ([segment(f, "red", "hole") for f in found.fields],
            [segment(d, "yellow", "frame") for d in found.diamonds])


def box_gap(a, b) -> float:
    """Pixels between two boxes (x, y, w, h); 0 when they touch or overlap."""
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    dx = max(0, max(ax, bx) - min(ax + aw, bx + bw))
    dy = max(0, max(ay, by) - min(ay + ah, by + bh))
    return float(max(dx, dy))


def merge_segments(a: Segment, b: Segment) -> Segment:
    """One segment from two pieces of the same face (a pole or branch cut it): the hull of both.

    Depth and planarity are taken on the pieces only, not on the occluder between them.
    """
    points = np.vstack([a.contour.reshape(-1, 2), b.contour.reshape(-1, 2)])
    hull = cv2.convexHull(points)
    x, y, w, h = cv2.boundingRect(hull)
    mask = np.zeros((h, w), np.uint8)
    cv2.drawContours(mask, [hull], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
    pieces = np.zeros((h, w), np.uint8)
    for seg in (a, b):
        sx, sy, sw, sh = seg.bbox
        pieces[sy - y : sy - y + sh, sx - x : sx - x + sw] |= seg.surface_mask
    return Segment(a.colour, (x, y, w, h), mask, hull, int(np.count_nonzero(mask)),
                   a.touches_border or b.touches_border, a.source, 1.0, pieces)


def union_segment(a: Segment, b: Segment) -> Segment:
    """One segment of two parts of one face whose outline is theirs together, not their hull: a double cross's
    cross and the chevron beneath it, whose hull would lose the cross's outline."""
    x0, y0, w, h = union_box(a.bbox, b.bbox)
    mask = np.zeros((h, w), np.uint8)
    for seg in (a, b):
        sx, sy, sw, sh = seg.bbox
        mask[sy - y0 : sy - y0 + sh, sx - x0 : sx - x0 + sw] |= seg.mask
    points = np.vstack([a.contour.reshape(-1, 2), b.contour.reshape(-1, 2)])
    area = int(np.count_nonzero(mask))
    solidity = min(1.0, area / max(1.0, cv2.contourArea(cv2.convexHull(points))))
    return Segment(a.colour, (x0, y0, w, h), mask, points, area, a.touches_border or b.touches_border, a.source,
                   solidity)


def double_cross(a: Segment, b: Segment, config) -> Optional[Segment]:
    """The two parts of a double St Andrew's cross (3.23, 3.25) as one face, or None: one part above the other,
    their columns overlapping by ``split_min_span_overlap``, a gap of at most ``merge_max_gap`` of their size,
    and together an outline of a double cross (``shape.CROSS_OUTLINES``) fitting as well as a cross must."""
    (ax, _, aw, _), (bx, _, bw, _), (_, _, w, h) = a.bbox, b.bbox, union_box(a.bbox, b.bbox)
    if _span_overlap(ax, ax + aw, bx, bx + bw) < config.colour.split_min_span_overlap \
            or box_gap(a.bbox, b.bbox) > config.colour.merge_max_gap * max(w, h):
        return None
    union = union_segment(a, b)
    result = classify_shape(union.mask, CROSS_MIN_FIT, config.shape.compare_fill_window)
    return union if result.shape in DOUBLE_CROSS_OUTLINES else None


def is_piece(seg: Segment) -> bool:
    """Whether a segment may be a piece of a face: not a face's whole outline found as such (a white frame, the
    disc read from its half), nor a ring's white field: a bar or pole splits a ring, and two fields close to each
    other are those of two signs stacked on one pole."""
    return seg.source not in ("frame", "half", "hole")


def merge_candidates(segments: Sequence[Segment], max_gap_fraction: float, max_aspect: float) -> List[Segment]:
    """Merged segments of same-coloured pieces close to each other, for faces split by an occluder.

    Two pieces qualify when the gap between their boxes is at most ``max_gap_fraction``
    of the merged box's size (``config.colour.merge_max_gap``) and the merged box is not
    longer than ``max_aspect`` x its width (``config.colour.merge_max_aspect``).
    """
    out = []
    for i, a in enumerate(segments):
        for b in segments[i + 1 :]:
            if a.colour != b.colour or not (is_piece(a) and is_piece(b)):
                continue
            _, _, w, h = union_box(a.bbox, b.bbox)
            if box_gap(a.bbox, b.bbox) > max_gap_fraction * max(w, h) or max(w, h) > max_aspect * min(w, h):
                continue
            out.append(merge_segments(a, b))
    return out


def _span_overlap(a0: int, a1: int, b0: int, b1: int) -> float:
    """Overlap of two 1-D spans as a fraction of the shorter one."""
    return max(0, min(a1, b1) - max(a0, b0)) / float(max(1, min(a1 - a0, b1 - b0)))


def split_face_merges(segments: Sequence[Segment], config) -> List[Tuple[Segment, int, int]]:
    """(merged, i, j) for pairs of pieces that together make a better sign outline than either alone.

    A white bar (no entry, 2.02) or a pole in front cuts a face into two pieces
    stacked along one axis: their boxes overlap along the other axis by at least
    ``config.colour.split_min_span_overlap`` and the gap between them is small (``merge_max_gap``).
    A bar along the diagonal (end of the priority road, 3.04) leaves two halves
    offset along both axes, overlapping along each by ``split_min_diagonal_overlap``.
    The hull of both is kept when its outline fits an ideal shape (``min_shape_fit``)
    better, by ``split_min_gain``, than each piece does: the whole face is then judged
    before its pieces. A double cross's two parts are kept as they are, together (:func:`double_cross`).
    """
    min_fit, max_gap_fraction = config.shape.min_shape_fit, config.colour.merge_max_gap
    max_aspect = config.colour.merge_max_aspect
    min_span_overlap, min_gain = config.colour.split_min_span_overlap, config.colour.split_min_gain
    min_diagonal, fill_window = config.colour.split_min_diagonal_overlap, config.shape.compare_fill_window
    fits: dict = {}

    def fit_of(k: int) -> float:
        if k not in fits:
            fits[k] = classify_shape(segments[k].mask, min_fit, fill_window).fit
        return fits[k]

    out = []
    for i, a, j, b in _piece_pairs(segments):
        crosses = double_cross(a, b, config)
        if crosses is not None:
            out.append((crosses, i, j))
            continue
        (ax, ay, aw, ah), (bx, by, bw, bh), (_, _, w, h) = a.bbox, b.bbox, union_box(a.bbox, b.bbox)
        if box_gap(a.bbox, b.bbox) > max_gap_fraction * max(w, h) or max(w, h) > max_aspect * min(w, h):
            continue
        across = _span_overlap(ax, ax + aw, bx, bx + bw)  # of the columns: one above the other
        along = _span_overlap(ay, ay + ah, by, by + bh)  # of the rows: side by side
        diagonal = min(across, along) >= min_diagonal
        if not (across >= min_span_overlap or along >= min_span_overlap or diagonal):
            continue
        merged = merge_segments(a, b)
        result = classify_shape(merged.mask, min_fit, fill_window)
        if result.shape is not None and result.fit >= max(fit_of(i), fit_of(j)) + min_gain:
            out.append((merged, i, j))
    return out


def _piece_pairs(segments: Sequence[Segment]):
    """(i, a, j, b), i < j, for every two segments of one colour that may be pieces of one face."""
    for i, a in enumerate(segments):
        for j in range(i + 1, len(segments)):
            b = segments[j]
            if a.colour == b.colour and not (a.touches_border or b.touches_border) and is_piece(a) and is_piece(b):
                yield i, a, j, b


def board_merges(segments: Sequence[Segment], config) -> List[Tuple[Segment, int, int]]:
    """(merged, i, j) for pairs of pieces of one wide board that a pole or post in front cut in two.

    Each piece of a direction board is a good rectangle by itself, so the outline gains nothing by merging
    (:func:`split_face_merges`): the pieces are one board when they stand side by side with their top and bottom
    edges level (within ``config.colour.board_edge_align`` of their height), a gap of at most
    ``board_max_gap`` of that height between them, and their merged box is a board's: at least
    ``board_min_aspect`` times as wide as high (narrower faces are merged as split faces).
    """
    align, max_gap, min_aspect = (config.colour.board_edge_align, config.colour.board_max_gap,
                                  config.colour.board_min_aspect)
    out = []
    for i, a, j, b in _piece_pairs(segments):
        (ax, ay, aw, ah), (bx, by, bw, bh), (_, _, width, height) = a.bbox, b.bbox, union_box(a.bbox, b.bbox)
        level = abs(ay - by) <= align * height and abs(ay + ah - by - bh) <= align * height
        gap = max(ax, bx) - min(ax + aw, bx + bw)
        if level and 0 <= gap <= max_gap * height and width >= min_aspect * height:
            out.append((merge_segments(a, b), i, j))
    return out


def faces_with_split_pieces_merged(segments: Sequence[Segment], config) -> List[Segment]:
    """The segments with each pair of pieces of one split face replaced by the merged face."""
    merges = split_face_merges(segments, config)
    used = {k for _, i, j in merges for k in (i, j)}
    return [m for m, _, _ in merges] + [s for k, s in enumerate(segments) if k not in used]
