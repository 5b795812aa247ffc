"""Faces found by their white: red rings by their field, priority roads by their frame (one grey ladder).

In dim light (dusk, shade, an overcast backlight) the red ring of a prohibition or
danger sign keeps hardly any saturation: its hue drifts with the camera's cast and
JPEG noise, and no colour threshold separates it from the dark trees around it.
What survives is the sign's structure: a field brighter than the ring enclosing it.
So this pass looks for fields by brightness, on a ladder of grey levels (at each,
the bright connected regions whose box and fill could be a face's field), and keeps
a field only when

- the band around it (where the ring is) is darker than the field, and
- that band is red *relative to the field*: the field is white by design, so the
  ring's colour is judged against it, a white balance local to the sign.

A kept field is a segment like the field the colour pass finds inside a red ring
(source ``"hole"``), so the face is grown from it by the templates' field extents.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Tuple

import cv2
import numpy as np

from .boxes import box_ious
from .config import PipelineConfig
from .framed_diamonds import box_yellow_against_frame, framed_diamond
from .shape import plausible_outlines

# shapes of the fields red rings and borders enclose (triangles, discs, the octagon's field is no field:
# STOP is a red field with white letters)
FIELD_SHAPES = ("circle", "triangle", "triangle-down")
DARK_RING_SHAPES = ("triangle", "triangle-down")  # outlines sharp enough to stand without the ring's colour


@dataclass(frozen=True)
class Field:
    """A white field inside a red ring, in full-image pixels."""

    bbox: Tuple[int, int, int, int]  # x, y, w, h
    mask: np.ndarray  # uint8 0/255 filled outline in ``bbox``
    contour: np.ndarray  # outer contour, full-image coordinates


def grey_levels(first: int, ratio: float) -> List[int]:
    """The ladder of grey thresholds: ``first``, then each ``ratio`` times the last, below 255.

    A geometric ladder: a field and its ring differ by a ratio of brightness (their
    reflectances), whatever the light.
    """
    if first < 1 or ratio <= 1.0:
        raise ValueError(f"grey levels need first >= 1 and ratio > 1, got {first}, {ratio}")
    levels, level = [], float(first)
    while level < 255:
        levels.append(int(round(level)))
        level = max(level * ratio, level + 1)
    return levels


def _same_component(box: np.ndarray, area: int, seen: np.ndarray, seen_areas: np.ndarray, fields) -> bool:
    """Whether a component was judged already at a lower level: nearly the same box and pixel count.

    A field whose ring's lighter pixels join it at one level has the same box one level up but
    fewer pixels; there it may be the field alone (a thin dusk ring around a speed limit), so it
    is judged again.
    """
    same_box = box_ious(box, seen) >= fields.field_same_iou
    return bool(np.any(same_box & (area >= (1.0 - fields.field_same_area_drop) * seen_areas)))


def ring_contrast(image: np.ndarray, bbox, field: np.ndarray, ring_fraction: float) -> Optional[Tuple[float, float,
                                                                                                      float]]:
    """(R/G, R/B, brightness) of the band around a field relative to the field itself; None if cut.

    ``field``: uint8 0/255 mask of the field in ``bbox`` (full-image pixels). The band is
    ``ring_fraction`` x the field's size wide, one pixel off the field's edge (edge pixels
    mix both). Each channel's band median is divided by its field median: a red ring around a
    white field gives R/G and R/B above 1 whatever the light's colour, and a brightness ratio
    below 1.
    """
    x, y, w, h = bbox
    ring = max(2, int(round(ring_fraction * max(w, h))))
    pad = ring + 2
    height, width = image.shape[:2]
    if x - pad < 0 or y - pad < 0 or x + w + pad > width or y + h + pad > height:
        return None
    crop = image[y - pad : y + h + pad, x - pad : x + w + pad]
    mask = np.zeros(crop.shape[:2], np.uint8)
    mask[pad : pad + h, pad : pad + w] = field
    edge = cv2.dilate(mask, np.ones((3, 3), np.uint8))
    outer = cv2.dilate(mask, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * ring + 3, 2 * ring + 3)))
    band = cv2.subtract(outer, edge)
    inner = cv2.erode(mask, np.ones((3, 3), np.uint8))
    if not cv2.countNonZero(band) or not cv2.countNonZero(inner):
        return None
    # medians: the field's pictogram (digits, a truck) and background past a thin ring are minorities
    b = np.median(crop[band > 0], axis=0) + 1.0
    f = np.median(crop[inner > 0], axis=0) + 1.0
    q = b / f  # B, G, R
    return float(q[2] / q[1]), float(q[2] / q[0]), float(b.sum() / f.sum())


def is_red_ring(contrast, config: PipelineConfig, share: float = 1.0) -> bool:
    """Whether ring-to-field ratios (:func:`ring_contrast`) are those of a red ring around a white field.

    ``share`` < 1 asks for that share of each margin over no contrast (ratios of 1) only: the
    coarse look at the reduced image, whose means blur ring and field together.
    """
    if contrast is None:
        return False
    red_green, red_blue, brightness = contrast
    return (red_green >= 1.0 + share * (config.bright_fields.field_ring_min_red_green - 1.0)
            and red_blue >= 1.0 + share * (config.bright_fields.field_ring_min_red_blue - 1.0)
            and brightness <= 1.0 - share * (1.0 - config.bright_fields.field_ring_max_brightness))


def is_dark_ring(contrast, config: PipelineConfig, share: float = 1.0) -> bool:
    """Whether ring-to-field ratios (:func:`ring_contrast`) are those of a much darker ring of no other colour:
    a red ring in the dark, whose colour the camera lost (only a sharp triangle is then taken for a face)."""
    if contrast is None:
        return False
    fields = config.bright_fields
    red_green, red_blue, brightness = contrast
    least = 1.0 - share * (1.0 - fields.dark_ring_min_ratio)
    return (red_green >= least and red_blue >= least
            and brightness <= 1.0 - share * (1.0 - fields.dark_ring_max_brightness))


def red_ring_fields(image: np.ndarray, search: Optional[np.ndarray], config: PipelineConfig,
                    min_face_px: Optional[float] = None) -> List[Field]:
    """White fields enclosed by a red ring, found by brightness (the colour step makes them "hole" segments).

    ``search`` (bool, image size) limits where fields may lie; ``min_face_px`` is the
    smallest face worth finding (its field ``field_of_face`` of it; never below ``field_min_px``).
    Each bright component is first judged on the reduced image by means (cheap, loose), then
    at full resolution by medians.
    """
    return bright_faces(image, search, config, min_face_px).fields


@dataclass(frozen=True)
class BrightFaces:
    """What the ladder of grey levels shows in one image: fields in red rings, white-framed yellow diamonds."""

    fields: List[Field]
    diamonds: List[Field]  # white-framed diamonds with a yellow middle (priority roads): their whole outline


def bright_faces(image: np.ndarray, search: Optional[np.ndarray], config: PipelineConfig,
                 min_face_px: Optional[float] = None) -> BrightFaces:
    """Faces that carry their own white reference, found on one ladder of grey levels (one labelling per level).

    - a white field enclosed by a red ring (:func:`red_ring_fields`);
    - a white-framed diamond whose middle is yellow relative to its frame (:mod:`.framed_diamonds`): a
      priority road in dim or washed-out light, whose yellow drifts to orange or to white and out of the hue
      band, or whose yellow joins yellow autumn leaves behind it (only with ``diamond_pass``).
    """
    fields = config.bright_fields
    min_field = max(fields.field_min_px, fields.field_of_face * (min_face_px or 0))
    # the reduced image keeps the smallest field field_min_side_px wide (labelling each level costs per pixel);
    # an integer reduction, which OpenCV averages fast
    scale = min(fields.field_scale, 1.0 / max(1, int(min_field // fields.field_min_side_px)))
    small = image if scale == 1.0 else cv2.resize(image, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA)
    grey = cv2.cvtColor(small, cv2.COLOR_BGR2GRAY)
    if search is not None:
        inside = cv2.resize(search.astype(np.uint8), (grey.shape[1], grey.shape[0]), interpolation=cv2.INTER_NEAREST)
        grey[inside == 0] = 0
    height, width = grey.shape
    min_side = max(3, int(np.floor(min_field * scale)))
    max_side = int(np.ceil(config.hough.max_face_px * scale))
    diamonds_wanted = fields.diamond_pass and "yellow" in config.colour.colours
    min_diamond = max(3, int(np.floor(max(fields.field_min_px, min_face_px or 0) * scale)))
    seen = np.zeros((0, 4), np.int64)  # boxes already judged (the same field recurs at neighbouring levels)
    seen_areas = np.zeros(0, np.int64)  # and their components' pixel counts
    seen_diamonds = np.zeros((0, 4), np.int64)
    out: List[Field] = []
    diamonds: List[Field] = []
    field_fill = min(fields.field_min_fill, fields.field_min_bitten_fill)
    min_fill = min(field_fill, fields.diamond_min_fill) if diamonds_wanted else field_fill
    # pixels at or below each grey value (OpenCV's histogram: float counts, exact below 2**24 pixels)
    counts = (cv2.calcHist([grey], [0], None, [256], [0, 256]).ravel().astype(np.int64) if grey.size < 1 << 24
              else np.bincount(grey.ravel(), minlength=256))
    at_most = counts.cumsum()
    for level in grey_levels(fields.field_first_level, fields.field_level_ratio):
        if grey.size - at_most[level] < min_fill * min_side * min_side or at_most[level] < 4 * min_side:
            continue  # too few pixels above the level for a field, or below it for a ring around one
        bright = cv2.compare(grey, level, cv2.CMP_GT)
        dark = level <= fields.dark_ring_max_level  # a ring may have lost its colour only in the dark
        # Spaghetti's 4-connected labelling: the same labels (raster order) and stats as the default, ~7 % faster
        n, labels, stats, _ = cv2.connectedComponentsWithStatsWithAlgorithm(bright, 4, cv2.CV_32S, cv2.CCL_SPAGHETTI)
        if n < 2:
            break
        xs, ys, ws, hs, areas = stats[1:].T
        short, long_ = np.minimum(ws, hs), np.maximum(ws, hs)
        inside_image = (xs > 0) & (ys > 0) & (xs + ws < width) & (ys + hs < height) & (long_ <= max_side)
        keep = ((short >= min_side) & (long_ <= fields.field_max_aspect * short)
                & (areas >= fields.field_min_bitten_fill * ws * hs) & (areas <= fields.field_max_fill * ws * hs)
                & inside_image)
        for k in np.flatnonzero(keep) + 1:
            box = stats[k, :4]
            if len(seen) and _same_component(box, areas[k - 1], seen, seen_areas, fields):
                continue  # the same field at a lower level
            seen = np.vstack([seen, box[None]])
            seen_areas = np.append(seen_areas, areas[k - 1])
            box = tuple(int(v) for v in box)
            coarse = _coarse_contrast(small, labels, k, box, fields.field_ring_fraction)
            red = is_red_ring(coarse, config, fields.field_coarse_share)
            if not (red or dark and is_dark_ring(coarse, config, fields.field_coarse_share)):
                continue
            bitten = areas[k - 1] < fields.field_min_fill * box[2] * box[3]
            field = _ring_field(image, labels, k, box, scale, config, dark, bitten)
            if field is not None and not any(box_ious(np.asarray(field.bbox), np.asarray([f.bbox]))[0]
                                             >= config.scene.pass_duplicate_iou for f in out):
                out.append(field)  # the first level that shows a field in its ring stands for it
        if not diamonds_wanted:
            continue
        framed = ((short >= min_diamond) & (long_ <= fields.diamond_max_aspect * short)
                  & (areas >= fields.diamond_min_fill * ws * hs) & (areas <= fields.diamond_max_fill * ws * hs)
                  & inside_image)
        for k in np.flatnonzero(framed) + 1:
            box = stats[k, :4]
            if not box_yellow_against_frame(small, labels, k, tuple(int(v) for v in box), config):
                continue  # most bright components (leaves, windows, sky) end here, before anything else is read
            if len(seen_diamonds) and box_ious(box, seen_diamonds).max() >= fields.field_same_iou:
                continue
            seen_diamonds = np.vstack([seen_diamonds, box[None]])
            diamond = framed_diamond(image, small, labels, k, tuple(int(v) for v in box), scale, config)
            if diamond is not None and not any(box_ious(np.asarray(diamond[0]), np.asarray([d.bbox]))[0]
                                               >= config.scene.pass_duplicate_iou for d in diamonds):
                diamonds.append(Field(*diamond))  # the first level that shows the diamond stands for it
    return BrightFaces(out, diamonds)


def _coarse_contrast(small: np.ndarray, labels: np.ndarray, label: int, box, ring_fraction: float):
    """:func:`ring_contrast` of component ``label`` on the reduced image, by means; None if cut."""
    x, y, w, h = box
    ring = max(1, int(round(ring_fraction * max(w, h))))
    if x - ring < 0 or y - ring < 0 or x + w + ring > labels.shape[1] or y + h + ring > labels.shape[0]:
        return None
    window = (slice(y - ring, y + h + ring), slice(x - ring, x + w + ring))
    field = cv2.compare(labels[window], float(label), cv2.CMP_EQ)
    grown = cv2.dilate(field, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * ring + 1, 2 * ring + 1)))
    b = np.asarray(cv2.mean(small[window], mask=cv2.subtract(grown, field))[:3]) + 1.0
    f = np.asarray(cv2.mean(small[window], mask=field)[:3]) + 1.0
    q = b / f  # B, G, R
    return float(q[2] / q[1]), float(q[2] / q[0]), float(b.sum() / f.sum())


def _ring_field(image, labels, label: int, box, scale: float, config: PipelineConfig,
                dark: bool = False, bitten: bool = False) -> Optional[Field]:
    """One bright component (``label`` in ``labels``, box ``box`` at ``scale``) if it is a field in a red ring
    (with ``dark``, also a triangle in a dark ring of no colour: :func:`is_dark_ring`).

    A field whose pictogram reaches its ring (a curve arrow, a worker, blurred at the reduced scale) is a field
    with a bite out of it: when the component itself is no field, its convex hull is judged in its place if the
    component fills ``field_min_solidity`` of the hull. A ``bitten`` component (filling less than
    ``field_min_fill`` of its box) is judged by its hull only.
    """
    x, y, w, h = box
    small = cv2.compare(labels[y : y + h, x : x + w], float(label), cv2.CMP_EQ)
    contours, _ = cv2.findContours(small, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE, offset=(x, y))
    contour = max(contours, key=cv2.contourArea)
    field = None if bitten else _field_at(image, contour, scale, config, dark)
    if field is not None or config.bright_fields.field_min_solidity >= 1.0:
        return field
    hull = cv2.convexHull(contour)
    if _filled_area(contour, x, y, w, h) < config.bright_fields.field_min_solidity * _filled_area(hull, x, y, w, h):
        return None  # a bright blot with a deep bay (leaves, a window frame), not a bitten field
    return _field_at(image, hull, scale, config, dark, config.bright_fields.field_hull_shapes)


def dark_ring_fit_floor(image: np.ndarray, bbox, field: np.ndarray, config: PipelineConfig) -> float:
    """The outline fit a field in a dark ring of no colour needs: ``dark_ring_min_fit``, or the looser
    ``dark_field_min_fit`` when the field itself (``field``, the filled mask in box ``bbox``) is dim (at dusk)."""
    fields = config.bright_fields
    if fields.dark_field_min_fit >= fields.dark_ring_min_fit:
        return fields.dark_ring_min_fit
    x, y, w, h = bbox
    brightness = float(np.mean(cv2.mean(image[y : y + h, x : x + w], mask=field)[:3]))
    return fields.dark_field_min_fit if brightness <= fields.dark_field_max_brightness else fields.dark_ring_min_fit


def _filled_area(contour: np.ndarray, x: int, y: int, w: int, h: int) -> float:
    """Pixels of ``contour`` filled, in the box (x, y, w, h) it lies in (the same count for an outline and its
    hull, so their ratio is the bite's share; holes inside, a pictogram not touching the ring, do not count)."""
    mask = np.zeros((h, w), np.uint8)
    cv2.drawContours(mask, [contour], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
    return float(cv2.countNonZero(mask))


def _field_at(image, contour: np.ndarray, scale: float, config: PipelineConfig, dark: bool,
              shapes_allowed: Tuple[str, ...] = FIELD_SHAPES) -> Optional[Field]:
    """The outline ``contour`` (reduced image) at full resolution if it is a field in a red (or, with ``dark``,
    a dark) ring and of a field's shape (one of ``shapes_allowed``)."""
    # the outline at full resolution (pixel centres), its box and filled mask
    contour = np.round((contour.astype(np.float64) + 0.5) / scale - 0.5).astype(np.int32)
    bbox = cv2.boundingRect(contour)
    field = np.zeros((bbox[3], bbox[2]), np.uint8)
    cv2.drawContours(field, [contour], -1, 255, thickness=cv2.FILLED, offset=(-bbox[0], -bbox[1]))
    contrast = ring_contrast(image, bbox, field, config.bright_fields.field_ring_fraction)
    red = is_red_ring(contrast, config)
    if not (red or dark and is_dark_ring(contrast, config)):
        return None
    fit, shapes = plausible_outlines(field, config)
    if red:
        # a small round field fits an octagon as well as a circle; a stop sign has no white field, so an
        # octagon reading only hides the circle (dusk speed limits on GTSDB's tune split)
        if fit.shape not in shapes_allowed and not (fit.shape == "octagon" and "circle" in shapes_allowed
                                                    and "circle" in shapes):
            return None
    elif not (fit.shape in DARK_RING_SHAPES and fit.shape in shapes_allowed
              and fit.fit >= dark_ring_fit_floor(image, bbox, field, config)):
        return None
    return Field(tuple(int(v) for v in bbox), field, contour)
