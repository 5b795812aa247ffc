"""Where a colour lies inside each template's face: which templates a colour segment may be.

Most faces carry their colour up to the edge (a red ring, a blue disc), but
some have a white rim around the coloured part (the yellow diamond of the
priority road) or carry a coloured disc on a white panel (zone signs): the
colour segment is then smaller than the face, and the face's box must be grown
before it is sized and matched. And a sign catalogued under one colour may be
outlined by another (the blue no-parking disc has a red ring). The extent is
measured once per template and colour on its rendering, with the same HSV
thresholds as the colour step, so it follows whatever the catalogue draws.
"""

from __future__ import annotations

from typing import Dict, Iterable, List, Optional, Tuple

import cv2
import numpy as np

from .boxes import box_iou
from .classify import canonical_drawings, canonical_template
from .colour import hsv_mask
from .config import TEMPLATE_GEOMETRY
from .shape import IDEAL_POLYGONS, classify_shape

FULL = (0.0, 0.0, 1.0, 1.0)
# outlines of the panels a part of another colour is found in (a zone panel's disc, a white pointer's blue symbol)
PANEL_SHAPES = ("rectangle", "square", "pointer")
_cache: Dict[tuple, tuple] = {}
Extent = Tuple[float, float, float, float]  # x0, y0, x1, y1 as fractions of the face box


def _ranges_key(hsv_ranges, colour: str) -> tuple:
    """The thresholds of ``colour`` as a hashable value: a measurement holds for those thresholds only (a run
    may change the colour table)."""
    return tuple(tuple(map(int, r)) for r in hsv_ranges.get(colour, ()))


def _measured_once(catalogue, key: tuple, measure):
    """``measure()`` of one template, kept per catalogue object and colour thresholds (``key``: the catalogue's
    id, the template, what is measured and :func:`_ranges_key`; a template's rendering does not change)."""
    hit = _cache.get(key)
    if hit is not None and hit[0] is catalogue:
        return hit[1]
    value = measure()
    _cache[key] = (catalogue, value)
    return value


def _colour_mask(catalogue, template_id: str, colour: str, hsv_ranges) -> Optional[np.ndarray]:
    """uint8 0/255 mask of the template's pixels the colour step reads as ``colour``, inside its outline;
    None for a colour without thresholds."""
    if colour not in hsv_ranges:
        return None
    return _drawing_colour_mask(*canonical_template(catalogue, template_id), hsv_ranges[colour])


def _drawing_colour_mask(bgr: np.ndarray, alpha: np.ndarray, ranges) -> np.ndarray:
    mask = hsv_mask(cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV), ranges)
    mask[alpha <= 127] = 0
    return mask


def colour_part(catalogue, template_id: str, colour: str, hsv_ranges) -> Tuple[Optional[Extent], Optional[str]]:
    """(extent, outline shape) of the template's ``colour`` pixels; (None, None) if it has none.

    The extent is the colour's bounding box as fractions of the face box; the
    shape is that of the filled outline of the colour's pixels, as the colour
    step would see it: where a bar cuts the colour into pieces that fit no
    outline alone (3.04's halves), the hull of all pieces, as the colour step
    merges them (``colour.split_face_merges``).
    """
    return _measured_once(catalogue, (id(catalogue), template_id, colour, _ranges_key(hsv_ranges, colour)),
                          lambda: _part_of(_colour_mask(catalogue, template_id, colour, hsv_ranges)))


def further_parts(catalogue, template_id: str, colour: str, hsv_ranges) -> List[Tuple[Extent, Optional[str]]]:
    """(extent, outline shape) of the ``colour`` part in each further drawing of the template (a pointer pointing
    the other way carries its symbol at the other end) placed otherwise than in its master and in each other."""
    def measure():
        master = colour_part(catalogue, template_id, colour, hsv_ranges)
        places = [master] if master[0] is not None else []
        for bgr, alpha in canonical_drawings(catalogue, template_id)[1:]:
            part = _part_of(_drawing_colour_mask(bgr, alpha, hsv_ranges[colour]))
            if part[0] is not None and not any(_same_place(part[0], seen) for seen, _ in places):
                places.append(part)
        return places[1:] if master[0] is not None else places

    if colour not in hsv_ranges:
        return []
    return _measured_once(catalogue, (id(catalogue), template_id, "further:" + colour,
                                      _ranges_key(hsv_ranges, colour)), measure)


def _same_place(a: Extent, b: Extent) -> bool:
    return all(abs(p - q) <= TEMPLATE_GEOMETRY.template_same_place for p, q in zip(a, b))


def _template_shape(mask: np.ndarray) -> Optional[str]:
    """The outline shape of a part of a drawn template (:data:`.config.TEMPLATE_GEOMETRY`)."""
    return classify_shape(mask, TEMPLATE_GEOMETRY.template_min_fit, TEMPLATE_GEOMETRY.template_fill_window).shape


def _part_of(mask: Optional[np.ndarray]) -> Tuple[Optional[Extent], Optional[str]]:
    extent, shape = None, None
    if mask is None:
        return extent, shape
    ys, xs = np.nonzero(mask)
    if ys.size > TEMPLATE_GEOMETRY.template_min_part_share * mask.size:
        h, w = mask.shape
        extent = (xs.min() / w, ys.min() / h, (xs.max() + 1) / w, (ys.max() + 1) / h)
        if all(abs(a - b) < TEMPLATE_GEOMETRY.template_full_snap for a, b in zip(extent, FULL)):
            extent = FULL  # colour reaches the edge: no correction, avoid rounding noise
        filled = np.zeros_like(mask)
        contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        cv2.drawContours(filled, contours, -1, 255, thickness=cv2.FILLED)
        part = filled[ys.min() : ys.max() + 1, xs.min() : xs.max() + 1]
        shape = _template_shape(part)
        if shape is None and len(contours) > 1:
            hull = cv2.convexHull(np.vstack([c.reshape(-1, 2) for c in contours]))
            merged = np.zeros_like(mask)
            cv2.drawContours(merged, [hull], -1, 255, thickness=cv2.FILLED)
            shape = _template_shape(merged[ys.min() : ys.max() + 1, xs.min() : xs.max() + 1])
    return extent, shape


def hole_part(catalogue, template_id: str, colour: str, hsv_ranges) -> Tuple[Optional[Extent], Optional[str]]:
    """(extent, shape) of the largest field the template's ``colour`` encloses (the white field inside a
    red ring or border, the bar of no entry); (None, None) if it encloses none of at least
    ``TEMPLATE_GEOMETRY.template_min_field_share`` of the face."""
    return _measured_once(catalogue, (id(catalogue), template_id, "hole:" + colour,
                                      _ranges_key(hsv_ranges, colour)),
                          lambda: _hole_of(_colour_mask(catalogue, template_id, colour, hsv_ranges)))


def _hole_of(mask: Optional[np.ndarray]) -> Tuple[Optional[Extent], Optional[str]]:
    extent, shape = None, None
    if mask is None:
        return extent, shape
    contours, hierarchy = cv2.findContours(mask, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_NONE)
    holes = [c for c, h in zip(contours, hierarchy[0] if hierarchy is not None else []) if h[3] >= 0]
    h, w = mask.shape
    if holes:
        hole = max(holes, key=cv2.contourArea)
        if cv2.contourArea(hole) >= TEMPLATE_GEOMETRY.template_min_field_share * h * w:
            x, y, hw, hh = cv2.boundingRect(hole)
            extent = (x / w, y / h, (x + hw) / w, (y + hh) / h)
            filled = np.zeros((hh, hw), np.uint8)
            cv2.drawContours(filled, [hole], -1, 255, thickness=cv2.FILLED, offset=(-x, -y))
            shape = _template_shape(filled)
    return extent, shape


def hole_candidates(catalogue, colour: str, shapes: Iterable[str], hsv_ranges, allowed_colours: Iterable[str],
                    exclude: Iterable[str] = ()) -> List[Tuple[object, Extent]]:
    """(entry, field extent) of the templates whose ``colour`` encloses a field of one of ``shapes``."""
    shapes, allowed, excluded = set(shapes), set(allowed_colours), set(exclude)
    out = []
    for entry in catalogue.filter(exclude=excluded):  # the generic text panels left out too
        if entry.colour not in allowed:
            continue
        extent, shape = hole_part(catalogue, entry.id, colour, hsv_ranges)
        if extent is not None and shape in shapes:
            out.append((entry, extent))
    return out


def bright_part(catalogue, template_id: str) -> Tuple[Optional[Extent], Optional[str]]:
    """(extent, shape) of the template's bright part (white and light colours inside its dark edge line, if
    any): what a white frame found by brightness outlines (:mod:`.framed_diamonds`)."""
    def measure():
        bgr, alpha = canonical_template(catalogue, template_id)
        grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)
        mask = ((grey >= TEMPLATE_GEOMETRY.template_bright_grey) & (alpha > 127)).astype(np.uint8) * 255
        return _part_of(mask)

    return _measured_once(catalogue, (id(catalogue), template_id, "bright"), measure)


def frame_candidates(catalogue, colour: str, shapes: Iterable[str],
                     exclude: Iterable[str] = ()) -> List[Tuple[object, Extent]]:
    """(entry, bright extent) of the templates of ``colour`` and one of ``shapes`` whose bright part has that
    shape too: what a white-framed ``colour`` face found by brightness may be."""
    shapes, excluded = set(shapes), set(exclude)
    out = []
    for entry in catalogue.filter(exclude=excluded):  # the generic text panels left out too
        if entry.colour != colour or entry.shape not in shapes:
            continue
        extent, shape = bright_part(catalogue, entry.id)
        if extent is not None and shape in shapes:
            out.append((entry, extent))
    return out


def colour_extent(catalogue, template_id: str, colour: str, hsv_ranges) -> Optional[Extent]:
    """Bounding box of the template's ``colour`` pixels as fractions of its face box; None if it has none."""
    return colour_part(catalogue, template_id, colour, hsv_ranges)[0]


def face_bbox(segment_bbox, extent: Extent) -> Tuple[int, int, int, int]:
    """The face's pixel box given the colour segment's box and the template's colour extent."""
    if extent == FULL:
        return tuple(int(v) for v in segment_bbox)
    x, y, w, h = segment_bbox
    fx0, fy0, fx1, fy1 = extent
    fw, fh = w / (fx1 - fx0), h / (fy1 - fy0)
    return (int(round(x - fx0 * fw)), int(round(y - fy0 * fh)), int(round(fw)), int(round(fh)))


def _area(extent: Extent) -> float:
    return (extent[2] - extent[0]) * (extent[3] - extent[1])


def candidate_entries(catalogue, colour: str, shapes: Iterable[str], hsv_ranges, allowed_colours: Iterable[str],
                      exclude: Iterable[str] = ()) -> List[Tuple[object, Extent]]:
    """(entry, colour extent) of the templates a ``colour`` segment of one of ``shapes`` may show.

    - entries of that colour and shape (extent as measured, FULL if not measurable);
    - entries of another allowed colour and that shape outlined by this colour;
    - panels (rectangles, squares, pointers) carrying an inset part of this colour and shape (zone signs, a white
      pointer's blue parking symbol).

    Kept per catalogue like the templates' parts it is read from: a pair asks for the same few
    (colour, shapes) readings again and again.
    """
    shapes, allowed, excluded = frozenset(shapes), frozenset(allowed_colours), frozenset(exclude)
    key = ("candidates", id(catalogue), colour, shapes, _ranges_key(hsv_ranges, colour), allowed, excluded)
    return list(_measured_once(catalogue, key, lambda: _candidate_entries(catalogue, colour, shapes, hsv_ranges,
                                                                          allowed, excluded)))


def _candidate_entries(catalogue, colour: str, shapes, hsv_ranges, allowed, excluded) -> List[Tuple[object, Extent]]:
    out = []
    for entry in catalogue.filter(exclude=excluded):  # the generic text panels left out too
        if entry.colour not in allowed:
            continue
        extent, part_shape = colour_part(catalogue, entry.id, colour, hsv_ranges)
        if entry.colour == colour and entry.shape in shapes and (extent in (None, FULL) or part_shape in shapes):
            out.append((entry, extent or FULL))
        elif extent is None:
            continue
        elif extent == FULL and entry.shape in shapes:
            out.append((entry, extent))
        elif entry.shape in PANEL_SHAPES and part_shape in shapes and _panel_part(extent):
            out.append((entry, extent))
            # the same panel drawn otherwise (pointing the other way): its part elsewhere, its face grown elsewhere
            out += [(entry, other) for other, other_shape in further_parts(catalogue, entry.id, colour, hsv_ranges)
                    if other_shape in shapes and _panel_part(other)]
        elif entry.shape in shapes and part_shape in shapes and reads_as(catalogue, entry, colour, hsv_ranges):
            out.append((entry, extent))  # its own colour reads as this one: the network tells them apart
    return out


def reads_as(catalogue, entry, colour: str, hsv_ranges) -> bool:
    """Whether the segmentation may take ``entry``'s own colour for ``colour``: the template's pixels in
    ``colour``'s thresholds cover the same part of its face as its own colour's (tourist brown is dark red)."""
    if entry.colour == colour:
        return True
    extent = colour_part(catalogue, entry.id, colour, hsv_ranges)[0]
    own = colour_part(catalogue, entry.id, entry.colour, hsv_ranges)[0]
    tolerance = TEMPLATE_GEOMETRY.template_same_part_tolerance
    return extent is not None and own is not None and max(abs(a - b) for a, b in zip(extent, own)) <= tolerance


def carried_discs(catalogue, hsv_ranges) -> Dict[str, str]:
    """{panel id: disc id} of the rectangular panels that carry a disc of one colour inside (the zone panels:
    2.59.1's "30" ring, 2.59.3's pedestrian disc), each with the round sign of that colour its disc looks most
    like (normalized cross-correlation at 48 px): a view that misses the panel reads that disc (``fusion``).
    Measured once per catalogue and thresholds: every run of a session asks again."""
    key = (id(catalogue), "carried discs") + tuple((colour, _ranges_key(hsv_ranges, colour))
                                                   for colour in sorted(hsv_ranges))
    return dict(_measured_once(catalogue, key, lambda: _carried_discs(catalogue, hsv_ranges)))


def _carried_discs(catalogue, hsv_ranges) -> Dict[str, str]:
    out = {}
    for entry in catalogue:
        if entry.shape not in ("rectangle", "square"):
            continue
        for colour in hsv_ranges:
            extent, part_shape = colour_part(catalogue, entry.id, colour, hsv_ranges)
            if extent is not None and part_shape == "circle" and _panel_part(extent):
                disc = _most_like(catalogue, _part_image(catalogue, entry.id, extent),
                                  [e.id for e in catalogue.filter(colours=[colour], shapes=["circle"])])
                if disc is not None:
                    out[entry.id] = disc
    return out


def _part_image(catalogue, template_id: str, extent: Extent, side: int = 48) -> np.ndarray:
    """The template's drawing inside ``extent``, ``side`` px square, float32 BGR."""
    bgr, alpha = canonical_template(catalogue, template_id)
    h, w = alpha.shape
    x0, y0, x1, y1 = extent
    part = bgr[int(y0 * h) : max(int(y1 * h), int(y0 * h) + 1), int(x0 * w) : max(int(x1 * w), int(x0 * w) + 1)]
    return cv2.resize(part, (side, side), interpolation=cv2.INTER_AREA).astype(np.float32)


def _most_like(catalogue, image: np.ndarray, template_ids: List[str]) -> Optional[str]:
    """The template among ``template_ids`` whose drawing correlates best with ``image`` (same size)."""
    side = image.shape[0]
    scores = {t: float(cv2.matchTemplate(image, _part_image(catalogue, t, FULL, side), cv2.TM_CCOEFF_NORMED)[0, 0])
              for t in template_ids}
    return max(scores, key=scores.get) if scores else None


def _panel_part(extent: Extent) -> bool:
    smallest, largest = TEMPLATE_GEOMETRY.template_panel_part_area
    return smallest < _area(extent) < largest


def measured_rim_bbox(image: np.ndarray, segment_bbox, segment_mask: np.ndarray, extent: Extent,
                      config) -> Optional[Tuple[int, int, int, int]]:
    """The face box of a rimmed face measured in the image: the white rim around the coloured part.

    The rim's width differs between sign designs (Germany's priority road carries its
    yellow on half the face, the Swiss template on 78 %), so the template's extent can
    misplace the face. Around the segment, bright low-saturation pixels joined to it
    are the rim; the filled outline of segment plus rim must have the segment's
    shape. None when no such rim is found (then the template's extent stands).
    """
    min_fit, fill_window = config.shape.min_shape_fit, config.shape.compare_fill_window
    x, y, w, h = segment_bbox
    fx0, fy0, fx1, fy1 = extent
    grow = max(fx0, fy0, 1 - fx1, 1 - fy1) / max(0.05, min(fx1 - fx0, fy1 - fy0))  # rim / coloured part
    margin = config.rims.rim_window_margin
    gx, gy = int(np.ceil(w * (2.0 * grow + margin))), int(np.ceil(h * (2.0 * grow + margin)))
    height, width = image.shape[:2]
    x0, y0, x1, y1 = max(0, x - gx), max(0, y - gy), min(width, x + w + gx), min(height, y + h + gy)
    hsv = cv2.cvtColor(image[y0:y1, x0:x1], cv2.COLOR_BGR2HSV)
    inner = hsv[y - y0 : y - y0 + h, x - x0 : x - x0 + w, 2][segment_mask > 0]
    if inner.size == 0:
        return None
    rims = config.rims
    bright = (hsv[..., 1] < rims.rim_max_saturation) & (hsv[..., 2] >= max(rims.rim_min_value,
                                                                          np.median(inner) * rims.rim_value_ratio))
    mask = bright.astype(np.uint8) * 255
    mask[y - y0 : y - y0 + h, x - x0 : x - x0 + w][segment_mask > 0] = 255
    mask = cv2.morphologyEx(mask, cv2.MORPH_CLOSE, np.ones((3, 3), np.uint8))
    n, labels = cv2.connectedComponents(mask)
    cy, cx = y - y0 + h // 2, x - x0 + w // 2
    label = labels[cy, cx]
    if n < 2 or label == 0:
        return None
    contours, _ = cv2.findContours((labels == label).astype(np.uint8), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    contour = max(contours, key=cv2.contourArea)
    bx, by, bw, bh = cv2.boundingRect(contour)
    if bx == 0 or by == 0 or bx + bw >= x1 - x0 or by + bh >= y1 - y0:
        return None  # the bright area runs out of the window: sky or a wall, not a rim
    lo, hi = rims.rim_measured_scales
    if not (lo * w <= bw <= hi * w and lo * h <= bh <= hi * h):
        return None
    filled = np.zeros((bh, bw), np.uint8)
    cv2.drawContours(filled, [cv2.convexHull(contour)], -1, 255, thickness=cv2.FILLED, offset=(-bx, -by))
    seg_shape = classify_shape(segment_mask, min_fit, fill_window)
    face_shape = classify_shape(filled, min_fit, fill_window)
    if seg_shape.shape is None or face_shape.shape != seg_shape.shape:
        return None
    return (x0 + bx, y0 + by, bw, bh)


def outline_samples(shape: str, count: int) -> Tuple[np.ndarray, np.ndarray]:
    """(points, outward normals), each (N, 2), evenly along the ideal outline of ``shape`` in the unit box."""

    if shape not in IDEAL_POLYGONS:  # a circle (or an unknown shape: its inscribed ellipse)
        t = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
        normals = np.stack([np.cos(t), np.sin(t)], axis=1)
        return 0.5 + 0.5 * normals, normals
    corners = np.asarray(IDEAL_POLYGONS[shape], float)
    centre = corners.mean(axis=0)
    sides = np.roll(corners, -1, axis=0) - corners
    lengths = np.linalg.norm(sides, axis=1)
    points, normals = [], []
    for a, side, length in zip(corners, sides, lengths):
        n = max(2, int(round(count * length / lengths.sum())))
        points.append(a + ((np.arange(n) + 0.5) / n)[:, None] * side)
        normal = np.array([side[1], -side[0]]) / length
        normals.append(np.repeat((normal if np.dot(a - centre, normal) > 0 else -normal)[None], n, axis=0))
    return np.vstack(points), np.vstack(normals)


def scale_pivot(shape: str, w: float, h: float) -> Tuple[float, float]:
    """Where in its box (shares of width and height) an outline of ``shape`` stays when a band of even width is
    laid around it: the centre of its inscribed circle. The box centre for every shape but the triangles, whose
    incentre lies about a sixth of their height off it, towards the base."""
    if shape not in ("triangle", "triangle-down"):
        return 0.5, 0.5
    leg = float(np.hypot(w / 2.0, h))
    v = 2.0 * leg / (w + 2.0 * leg)  # apex at 0, base at 1
    return 0.5, (v if shape == "triangle" else 1.0 - v)


def scaled_box(box, shape: str, scale: float) -> Tuple[float, float, float, float]:
    """``box`` (x, y, w, h) of an outline of ``shape`` grown by ``scale`` about its :func:`scale_pivot`."""
    x, y, w, h = box
    u, v = scale_pivot(shape, w, h)
    return x + u * w * (1.0 - scale), y + v * h * (1.0 - scale), scale * w, scale * h


def outline_edge_profile(image: np.ndarray, segment_bbox, shape: str, scales: np.ndarray,
                         min_inside: float, samples: int) -> np.ndarray:
    """Median edge strength across the ideal ``shape`` outline (``samples`` points) of the segment's box scaled
    by each of ``scales`` about its :func:`scale_pivot` (0 where less than ``min_inside`` of the outline lies in
    the image)."""
    x, y, w, h = segment_bbox
    u, v = scale_pivot(shape, w, h)
    cx, cy = x + u * w, y + v * h  # the pivot
    reach = float(scales.max()) * max(w, h) * max(u, 1.0 - u, v, 1.0 - v) + 3
    height, width = image.shape[:2]
    x0, y0 = int(max(0, cx - reach)), int(max(0, cy - reach))
    x1, y1 = int(min(width, cx + reach + 1)), int(min(height, cy + reach + 1))
    grey = cv2.GaussianBlur(cv2.cvtColor(image[y0:y1, x0:x1], cv2.COLOR_BGR2GRAY), (3, 3), 0)
    gx, gy = cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3)
    points, normals = outline_samples(shape, samples)
    # all scales at once (one row per scale): a median per scale was most of the time of this step
    fw, fh = (scales * w)[:, None], (scales * h)[:, None]
    px = np.round(cx - u * fw + points[None, :, 0] * fw - 0.5 - x0).astype(int)
    py = np.round(cy - v * fh + points[None, :, 1] * fh - 0.5 - y0).astype(int)
    inside = (px >= 0) & (py >= 0) & (px < gx.shape[1]) & (py < gx.shape[0])
    n = normals[None] / np.stack([fw, fh], axis=2)  # the normal of the outline stretched to the box
    n /= np.linalg.norm(n, axis=2, keepdims=True)
    strength = np.abs(gx[np.where(inside, py, 0), np.where(inside, px, 0)] * n[..., 0]
                      + gy[np.where(inside, py, 0), np.where(inside, px, 0)] * n[..., 1])
    out = np.zeros(len(scales))
    whole = inside.all(axis=1)
    if whole.any():
        out[whole] = np.median(strength[whole], axis=1)
    for k in np.flatnonzero(~whole & (inside.mean(axis=1) >= min_inside)):
        out[k] = float(np.median(strength[k][inside[k]]))
    return out


def edge_rim_bbox(image: np.ndarray, segment_bbox, shape: str, max_scale: float,
                  config) -> Optional[Tuple[int, int, int, int]]:
    """The face box of a coloured part inside a rim, from the face's outer edge; None if no clear edge.

    The part's box is scaled about its pivot (:func:`scale_pivot`) from 1 to ``max_scale`` (geometric steps of
    ``config.rims.rim_scale_step``), the ideal outline of ``shape`` laid at each scale: the part's own
    edge is the strongest within ``rim_inner_scale``, then the rim (a plain band, weak edges), then
    the face's outer edge. The outer edge is the local maximum beyond the part whose strength is at
    least ``rim_edge_contrast`` x the weakest between them (+ ``rim_edge_noise``, Sobel units: ~2 grey
    levels); where a dark border line follows within ``rim_border_scale``, its outer edge.
    Works where the white rim blends into a white wall or sky (the black border line
    still is an edge), which :func:`measured_rim_bbox` cannot measure. A small part's colour
    segment misses the blurred edge of its colour, ``rim_blur_px`` on each side: both scale limits
    grow by that share of the part.
    """
    rims = config.rims
    inner_scale, min_contrast, noise = rims.rim_inner_scale, rims.rim_edge_contrast, rims.rim_edge_noise
    border_scale, blur_px, step = rims.rim_border_scale, rims.rim_blur_px, rims.rim_scale_step
    x, y, w, h = segment_bbox
    blur = 2.0 * blur_px / max(1, min(w, h))
    max_scale, inner_scale = max_scale * (1.0 + blur), inner_scale + blur
    scales = step ** np.arange(int(np.floor(np.log(max_scale) / np.log(step))) + 1)
    profile = outline_edge_profile(image, segment_bbox, shape, scales, rims.rim_outline_min_inside,
                                   rims.rim_outline_samples)
    inner = int(np.argmax(np.where(scales <= inner_scale, profile, -1.0)))
    best, best_k = 0.0, None
    for k in range(inner + 2, len(scales) - 1):
        if profile[k] < profile[k - 1] or profile[k] < profile[k + 1]:
            continue
        contrast = profile[k] / (profile[inner:k].min() + noise)
        if contrast > best:
            best, best_k = contrast, k
    if best_k is None or best < min_contrast:
        return None
    # a dark border line has two edges: the face ends at its outer one, a strong maximum just beyond
    outer = [k for k in range(best_k + 1, len(scales) - 1) if scales[k] <= border_scale * scales[best_k]
             and profile[k] >= profile[k - 1] and profile[k] >= profile[k + 1]
             and profile[k] >= rims.rim_border_min_strength * profile[best_k]]
    fx, fy, fw, fh = scaled_box(segment_bbox, shape, scales[outer[-1] if outer else best_k])
    return int(round(fx)), int(round(fy)), int(round(fw)), int(round(fh))


def rim_face_bboxes(image: np.ndarray, segment_bbox, segment_mask: np.ndarray, extent: Extent, shape: str,
                    config) -> List[Tuple[int, int, int, int]]:
    """Face boxes of a coloured part inside a rim measured in the image, beyond the template's own
    (``face_bbox(segment_bbox, extent)``): the white rim (:func:`measured_rim_bbox`) and the outer edge
    (:func:`edge_rim_bbox`), each kept when it differs from the boxes before it (IoU < ``config.rims.rim_same_iou``).
    """
    boxes = [face_bbox(segment_bbox, extent)]
    for box in (measured_rim_bbox(image, segment_bbox, segment_mask, extent, config),
                edge_rim_bbox(image, segment_bbox, shape, config.rims.rim_max_scale, config)):
        if box is not None and all(box_iou(box, b) < config.rims.rim_same_iou for b in boxes):
            boxes.append(box)
    return boxes[1:]


def ring_edge_bbox(image: np.ndarray, field_bbox, shape: str, config) -> Optional[Tuple[int, int, int, int]]:
    """The face box of a field inside a ring, from the ring's outer edge (:func:`edge_rim_bbox` with the
    field as the part and the ring as the plain band); None if no clear edge. Ring widths differ between
    designs (Germany's prohibition signs: face ~1.35 x field with their white border, the Swiss 1.21)."""
    return edge_rim_bbox(image, field_bbox, shape, config.rims.ring_edge_max_scale, config)
