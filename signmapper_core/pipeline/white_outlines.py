"""White and grey sign candidates by outline, before depth: the fields that strong edges enclose, achromatic
and bright, gathered into a disc or an upright rectangle.

End-of-restriction discs and end-of-zone panels carry no hue the colour step could segment, so they are
looked for over the whole image (not only the rows a colour candidate already holds), cheaply: the grey
image, reduced so the smallest face sought keeps ``white_scan_side_px``, gives Canny edges; the cells they
enclose (connected non-edge pixels) are measured all at once, and the achromatic, bright ones of a face's
size are kept. A pole or a wall touching a face is another cell, so it never spoils the outline. The
cells of one face (a field cut by stripes, a ring around a field) overlap in their boxes and are joined;
their union, holes filled and stripes bridged, is read as a disc (the smallest circle around it, its
perimeter on strong edges) or a rectangle (:func:`.shape.classify_shape`). Depth decides later
(``white_signs``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import cv2
import numpy as np

from ..geometry import Camera
from .boxes import box_iou, box_ious
from .colour import Segment
from .config import PipelineConfig
from .scene_colour import median_u8
from .shape import classify_shape, fill_ratio, shapes_tried

Box = Tuple[int, int, int, int]  # x, y, w, h


@dataclass(frozen=True)
class WhiteCandidate:
    """An outline that may be a white or grey sign: its segment (full-image pixels) and its outline shape."""

    segment: Segment
    shape: str  # "circle" or "rectangle"


def white_formats(catalogue, config: PipelineConfig) -> List[Tuple[float, float]]:
    """(width_m, height_m) of every format of the catalogue's white entries up to ``white_max_side_m``."""
    return [f for e in catalogue.filter(colours=["white"], exclude=tuple(config.classification.exclude))
            for f in e.formats.values() if max(f) <= config.white.white_max_side_m]


def face_side_range_px(camera: Camera, formats: Sequence[Tuple[float, float]], config: PipelineConfig
                       ) -> Tuple[float, float]:
    """(smallest shorter side, largest longer side) in pixels of the formats anywhere in near..far,
    widened by the size tolerance; no shorter side counts as less than ``white_min_side_m``."""
    if not formats:
        return 0.0, 0.0
    f = min(camera.fx, camera.fy)
    tol = config.size.size_tolerance
    shortest = max(min(min(w, h) for w, h in formats), config.white.white_min_side_m)
    lo = shortest * f / config.depth.far_m * (1.0 - tol)
    hi = max(max(w, h) for w, h in formats) * f / config.depth.near_m * (1.0 + tol)
    return lo, hi


def scan_scale(smallest_side_px: float, config: PipelineConfig) -> float:
    """Scale of the scanned image: a whole reduction (which OpenCV averages several times faster than any other)
    by which the smallest face sought keeps at least ``white_scan_side_px`` (never enlarged)."""
    if smallest_side_px <= 0:
        return 1.0
    return 1.0 / max(1, int(smallest_side_px // config.white.white_scan_side_px))


def edge_map(grey: np.ndarray, config: PipelineConfig) -> np.ndarray:
    """Strong edges (Canny), one pixel wider so a thin outline line closes."""
    edges = cv2.Canny(cv2.GaussianBlur(grey, (3, 3), 0), config.white.white_canny_low, config.white.white_canny_high)
    return cv2.dilate(edges, np.ones((3, 3), np.uint8))


def bright_achromatic(labels: np.ndarray, hsv: np.ndarray, label: int, stat: np.ndarray, floor: float, config
                      ) -> bool:
    """Whether cell ``label`` (its ``stat`` row of connectedComponentsWithStats) has a mean value of at least
    ``floor`` and ``white_min_achromatic`` of its pixels achromatic."""
    x, y, w, h, area = (int(v) for v in stat[:5])
    cell = labels[y : y + h, x : x + w] == label
    pixels = hsv[y : y + h, x : x + w][cell]
    area = max(area, 1)
    return (float(pixels[:, 2].sum(dtype=np.float64)) / area >= floor
            and np.count_nonzero(pixels[:, 1] <= config.white.white_max_saturation) / area
            >= config.white.white_min_achromatic)


@dataclass(frozen=True)
class WhiteScan:
    """One reduced look at an image that the white step's searches share (white faces by their cells and
    outline, text panels' fields by their cells): the image at ``scale``, its grey levels, HSV and gradients,
    and the cells that strong edges enclose (labels and connectedComponentsWithStats rows)."""

    scale: float
    grey: np.ndarray
    hsv: np.ndarray
    gradients: Tuple[np.ndarray, np.ndarray]
    labels: np.ndarray
    stats: np.ndarray
    median_value: float  # the scene's median brightness (HSV value)


def scan_image(bgr: np.ndarray, smallest_side_px: float, config: PipelineConfig) -> WhiteScan:
    """The :class:`WhiteScan` of ``bgr``, reduced so that the smallest face sought keeps ``white_scan_side_px``
    (:func:`scan_scale`)."""
    scale = scan_scale(smallest_side_px, config)
    small = cv2.resize(bgr, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA) if scale < 1 else bgr
    grey = cv2.cvtColor(small, cv2.COLOR_BGR2GRAY)
    hsv = cv2.cvtColor(small, cv2.COLOR_BGR2HSV)
    gradients = (cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3))
    _, labels, stats, _ = cv2.connectedComponentsWithStatsWithAlgorithm((edge_map(grey, config) == 0).astype(np.uint8),
                                                                      4, cv2.CV_32S, cv2.CCL_SPAGHETTI)
    return WhiteScan(scale, grey, hsv, gradients, labels, stats, median_u8(hsv[:, :, 2]))


def white_cells(scan: WhiteScan, side_range: Tuple[float, float], config: PipelineConfig
                ) -> Tuple[np.ndarray, List[Box]]:
    """(ids of the cells that may be a white face or a part of one, their boxes): cells of ``scan`` (enclosed by
    strong edges), achromatic (``white_min_achromatic`` of their pixels), bright (mean value at least
    ``white_min_brightness`` x the scene's median), compact, from a part of the smallest face to the largest
    (``side_range``, pixels of the scan)."""
    stats = scan.stats
    w, h, area = stats[:, cv2.CC_STAT_WIDTH], stats[:, cv2.CC_STAT_HEIGHT], stats[:, cv2.CC_STAT_AREA]
    lo, hi = side_range
    keep = ((np.maximum(w, h) >= config.white.white_part_share * lo) & (np.maximum(w, h) <= hi)
            & (np.maximum(area, 1) >= config.white.white_min_cell_fill * w * h))
    keep[0] = False  # the edges
    # brightness and colour only for the cells of a face's size, each within its own box
    floor = config.white.white_min_brightness * scan.median_value
    ids = np.array([i for i in np.flatnonzero(keep)
                    if bright_achromatic(scan.labels, scan.hsv, i, stats[i], floor, config)], np.intp)
    return ids, [tuple(int(v) for v in stats[i, :4]) for i in ids]


def _union(a: Box, b: Box) -> Box:
    x0, y0 = min(a[0], b[0]), min(a[1], b[1])
    return x0, y0, max(a[0] + a[2], b[0] + b[2]) - x0, max(a[1] + a[3], b[1] + b[3]) - y0


def group_cells(boxes: Sequence[Box], side_range: Tuple[float, float], reach: float, max_aspect: float,
                gap: float, max_steps: int) -> List[Tuple[Box, Tuple[int, ...]]]:
    """(union box, indices) of the cells that may be read together as one face, largest cell first.

    From each cell, the cells are joined one at a time, the nearest first, while one lies within
    ``reach`` of its own size or ``gap`` pixels of the union (the parts of a field cut by a stripe band, by
    digits or by a ring, a ring around its field); every union on the way that has a face's size
    (``side_range``) and aspect is a reading, the stripes between two stacked panels tell them apart as
    two readings before their union grows too long. At most ``max_steps`` joins from a cell.
    """
    if not boxes:
        return []
    b = np.asarray(boxes, np.float64)
    x0, y0, x1, y1 = b[:, 0], b[:, 1], b[:, 0] + b[:, 2], b[:, 1] + b[:, 3]
    lo, hi = side_range
    allowed = np.maximum(gap, reach * np.maximum(b[:, 2], b[:, 3]))
    # every start cell (largest first) grows its own union, all of them one join at a time side by side
    starts = np.argsort(-(b[:, 2] * b[:, 3]), kind="stable")
    n, rows = len(starts), np.arange(len(starts))
    ux0, uy0, ux1, uy1 = x0[starts], y0[starts], x1[starts], y1[starts]
    taken = np.zeros((n, len(b)), bool)
    taken[rows, starts] = True
    members = [[int(i)] for i in starts]
    readings: List[List[Tuple[Box, Tuple[int, ...]]]] = [[] for _ in range(n)]
    active = np.ones(n, bool)
    for _ in range(max_steps + 1):
        w, h = ux1 - ux0, uy1 - uy0
        face = active & (lo <= np.minimum(w, h)) & (np.maximum(w, h) <= hi) & \
            (np.maximum(w, h) <= max_aspect * np.minimum(w, h))
        for k in np.flatnonzero(face):
            readings[k].append(((int(ux0[k]), int(uy0[k]), int(w[k]), int(h[k])), tuple(sorted(members[k]))))
        # distance of every cell's box to each union box; a cell joins within its reach or the gap
        dist = np.maximum(np.maximum(0.0, np.maximum(x0 - ux1[:, None], ux0[:, None] - x1)),
                          np.maximum(0.0, np.maximum(y0 - uy1[:, None], uy0[:, None] - y1)))
        nx0, ny0 = np.minimum(ux0[:, None], x0), np.minimum(uy0[:, None], y0)
        nx1, ny1 = np.maximum(ux1[:, None], x1), np.maximum(uy1[:, None], y1)
        dist[taken | (dist > allowed) | (np.maximum(nx1 - nx0, ny1 - ny0) > hi)] = np.inf
        j = np.argmin(dist, axis=1)
        active &= np.isfinite(dist[rows, j])
        if not active.any():
            break
        for k in np.flatnonzero(active):
            members[k].append(int(j[k]))
        taken[rows[active], j[active]] = True
        ux0, uy0 = np.where(active, nx0[rows, j], ux0), np.where(active, ny0[rows, j], uy0)
        ux1, uy1 = np.where(active, nx1[rows, j], ux1), np.where(active, ny1[rows, j], uy1)
    groups, seen = [], set()
    for box, key in (r for start in readings for r in start):
        if key not in seen:
            seen.add(key)
            groups.append((box, key))
    return groups


def filled(mask: np.ndarray) -> np.ndarray:
    """``mask`` with its holes (pictogram, digits) filled."""
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    out = np.zeros_like(mask)
    cv2.drawContours(out, contours, -1, 255, -1)
    return out


def edge_support(gradients: Tuple[np.ndarray, np.ndarray], cu, cv, r, config: PipelineConfig):
    """Share of ``white_support_samples`` points on the circle (cu, cv, r), each looked for a pixel inward or
    outward, where the grey image has a strong gradient (``white_min_gradient``) pointing along the radius
    (``white_radial_cos``): an outline, where texture (leaves, noise) has strong gradients in every direction.
    ``cu``, ``cv``, ``r`` may be arrays of circles (then an array)."""
    white = config.white
    min_gradient, samples = white.white_min_gradient, white.white_support_samples
    gx, gy = gradients
    cu, cv, r = (np.asarray(a, np.float64)[..., None] for a in (cu, cv, r))
    angles = np.linspace(0.0, 2 * np.pi, samples, endpoint=False)
    c, s = np.cos(angles), np.sin(angles)
    hit = np.zeros(np.broadcast_shapes(cu.shape, r.shape, c.shape), bool)
    for dr in (-1.0, 0.0, 1.0):
        us = np.round(cu + (r + dr) * c).astype(int)
        vs = np.round(cv + (r + dr) * s).astype(int)
        inside = (us >= 0) & (vs >= 0) & (us < gx.shape[1]) & (vs < gx.shape[0])
        us, vs = np.where(inside, us, 0), np.where(inside, vs, 0)
        a, b = np.where(inside, gx[vs, us], 0.0), np.where(inside, gy[vs, us], 0.0)
        norm = np.hypot(a, b)
        hit |= (norm >= min_gradient) & (np.abs(a * c + b * s) >= white.white_radial_cos * norm)
    share = np.count_nonzero(hit, axis=-1) / float(samples)
    return float(share) if share.ndim == 0 else share


def refine_circle(gradients: Tuple[np.ndarray, np.ndarray], cu: float, cv: float, r: float, config: PipelineConfig
                  ) -> Tuple[float, float, float, float]:
    """(cu, cv, r, edge support) of the circle near (cu, cv, r) whose perimeter lies best on radial
    gradients: the cells around which it was drawn stop short of a weak stretch of the outline (a grey ring
    before a grey wall), so the radius is sought up to ``white_circle_search`` of it outward, the centre as
    far around."""
    k, steps = config.white.white_circle_search * r, config.white.white_circle_search_steps
    du, dv, dr = np.meshgrid(np.linspace(-k, k, steps), np.linspace(-k, k, steps),
                             np.linspace(-0.5 * k, 1.5 * k, steps), indexing="ij")
    support = edge_support(gradients, cu + du.ravel(), cv + dv.ravel(), r + dr.ravel(), config)
    best = int(np.argmax(support))
    return cu + du.ravel()[best], cv + dv.ravel()[best], r + dr.ravel()[best], float(support[best])


def box_edge_supports(gradients: Tuple[np.ndarray, np.ndarray], boxes: Sequence[Box], config: PipelineConfig
                      ) -> np.ndarray:
    """Share of points on the sides of each of ``boxes`` (each looked for a pixel inward or outward) where the grey
    image has a strong gradient across the side: the outline of a panel (the settings of :func:`edge_support`),
    all boxes at once."""
    white = config.white
    min_gradient, samples = white.white_min_gradient, white.white_support_samples
    gx, gy = gradients
    height, width = gx.shape
    x, y, w, h = (np.asarray(v)[:, None, None] for v in zip(*boxes))  # (boxes, 1, 1)
    n = max(2, samples // 4)
    t = (np.arange(n) + 0.5) / n
    along_u, along_v = np.round(x + t * w).astype(int), np.round(y + t * h).astype(int)  # (boxes, 1, n)
    d = np.array([-1, 0, 1])[:, None]
    shape = (len(boxes), 3, n)
    # rows of points (3 offsets x n) on the top, bottom (gradient across: gy) and left, right sides (gx)
    us = np.concatenate([np.broadcast_to(along_u, shape), np.broadcast_to(along_u, shape),
                         np.broadcast_to(x + d, shape), np.broadcast_to(x + w - 1 + d, shape)], axis=2)
    vs = np.concatenate([np.broadcast_to(y + d, shape), np.broadcast_to(y + h - 1 + d, shape),
                         np.broadcast_to(along_v, shape), np.broadcast_to(along_v, shape)], axis=2)
    inside = (us >= 0) & (vs >= 0) & (us < width) & (vs < height)
    us, vs = np.where(inside, us, 0), np.where(inside, vs, 0)
    horizontal = np.arange(4 * n) < 2 * n
    across = np.where(horizontal, gy[vs, us], gx[vs, us]) * inside
    along = np.where(horizontal, gx[vs, us], gy[vs, us]) * inside
    hit = (np.abs(across) >= min_gradient) & (np.abs(across) >= white.white_radial_cos * np.hypot(across, along))
    return np.count_nonzero(hit.any(axis=1), axis=1) / float(4 * n)


def refine_box(gradients: Tuple[np.ndarray, np.ndarray], box: Box, max_grow: float) -> Box:
    """``box`` with each side moved outward (up to ``max_grow`` of its size) to the line of the strongest
    gradient across it: a panel's outline, where its field's cells stop short of a ring, a stripe or
    lettering running into the frame."""
    gx, gy = gradients
    height, width = gx.shape
    x, y, w, h = box
    kx, ky = max(1, int(round(max_grow * w))), max(1, int(round(max_grow * h)))
    r0, r1, c0, c1 = max(0, y), min(height, y + h), max(0, x), min(width, x + w)
    if r1 <= r0 or c1 <= c0:
        return box
    # mean gradient across each column line over the box's rows (and each row line over its columns), only
    # within the reach of its sides: the profiles start at u0 and v0
    u0, v0 = max(0, x - kx), max(0, y - ky)
    column = np.abs(gx[r0:r1, u0 : min(width, x + w + kx)]).mean(axis=0)
    row = np.abs(gy[v0 : min(height, y + h + ky), c0:c1]).mean(axis=1)

    def outward(profile, first, start, step, reach, size):
        offsets = [o for o in range(reach + 1) if 0 <= start + step * o < size]
        return offsets[int(np.argmax([profile[start + step * o - first] for o in offsets]))] if offsets else 0

    dl, dr = outward(column, u0, x, -1, kx, width), outward(column, u0, x + w - 1, 1, kx, width)
    dt, db = outward(row, v0, y, -1, ky, height), outward(row, v0, y + h - 1, 1, ky, height)
    return x - dl, y - dt, w + dl + dr, h + dt + db


def outlines_in_reach(gradients: Tuple[np.ndarray, np.ndarray], boxes: Sequence[Box], config: PipelineConfig
                      ) -> np.ndarray:
    """Whether strong edges run near the outline of each of ``boxes`` at all (its inscribed circle
    ``white_edge_band_px`` outside, or its sides a pixel outside): the cheap test that spares most unions of
    cells reading their outline. The circles of all boxes are measured at once."""
    if not boxes:
        return np.zeros(0, bool)
    floor = config.white.white_min_edge_support - config.white.white_refine_margin
    b = np.asarray(boxes, np.float64)
    circle = np.atleast_1d(edge_support(gradients, b[:, 0] + b[:, 2] / 2.0, b[:, 1] + b[:, 3] / 2.0,
                                        np.maximum(b[:, 2], b[:, 3]) / 2.0 + config.white.white_edge_band_px, config))
    reached = circle >= floor
    rest = np.flatnonzero(~reached)
    if len(rest):
        reached[rest] = box_edge_supports(gradients, [(boxes[i][0] - 1, boxes[i][1] - 1, boxes[i][2] + 2,
                                                       boxes[i][3] + 2) for i in rest], config) >= floor
    return reached


def read_face(mask: np.ndarray, box: Box, gradients: Tuple[np.ndarray, np.ndarray], config: PipelineConfig
              ) -> List[Tuple[str, Box, np.ndarray]]:
    """The readings (shape, box, outline mask in that box) of the face that the joined cells ``mask`` (in
    ``box``) fill: :func:`read_faces` of that one union."""
    return read_faces([(mask, box)], gradients, config)[0]


def read_faces(unions: Sequence[Tuple[np.ndarray, Box]], gradients: Tuple[np.ndarray, np.ndarray],
               config: PipelineConfig) -> List[List[Tuple[str, Box, np.ndarray]]]:
    """The readings (shape, box, outline mask in that box) of each face that joined cells fill (``unions``:
    their mask and its box): a rectangle whose sides lie on strong edges, and, unless the cells' hull fits a
    rectangle, the smallest circle around them when its perimeter lies on strong edges (a field cut by a stripe
    band still spans the disc's diameter). A zone panel cut by its stripes may read as both: depth and the
    templates decide.

    Many unions of a pair share their box (small cells inside it join without widening it): a panel's outline
    depends on the box alone and is read once per box, and the outlines of all unions are measured in one call
    each (:func:`box_edge_supports`, :func:`edge_support`)."""
    white = config.white
    hulls = [_hull(mask, config) for mask, _ in unions]
    panel = [hull is not None and _may_be_panel(box, hull.cover, white) for (_, box), hull in zip(unions, hulls)]
    panels = {box for (_, box), is_panel in zip(unions, panel) if is_panel}
    panel_faces = {box: refine_box(gradients, box, white.white_panel_grow) for box in sorted(panels)}
    panel_support = dict(zip(panel_faces, box_edge_supports(gradients, list(panel_faces.values()), config)
                             if panel_faces else ()))
    # the smallest circle around each union's hull that does not fit a rectangle, widened by the edge band
    circles = {}
    for k, ((_, (x, y, _, _)), hull) in enumerate(zip(unions, hulls)):
        if hull is None or hull.fitted:
            continue
        (cu, cv), r = cv2.minEnclosingCircle(hull.points)
        if r >= 2 and hull.cover >= white.white_min_disc_cover * np.pi * r * r:
            circles[k] = (x + cu, y + cv, r + white.white_edge_band_px)  # the cells end where the band begins
    if circles:
        cu, cv, r = (np.array(v, np.float64) for v in zip(*circles.values()))
        near = np.atleast_1d(edge_support(gradients, cu, cv, r, config))
        floor = white.white_min_edge_support - white.white_refine_margin
        circles = {k: c for (k, c), s in zip(circles.items(), near) if s >= floor}
    refined = {c: refine_circle(gradients, *c, config) for c in set(circles.values())}
    readings = []
    for k, ((_, box), hull) in enumerate(zip(unions, hulls)):
        found = []
        if panel[k]:
            face = panel_faces[box]
            if panel_support[box] >= (white.white_min_edge_support if hull.fitted else white.white_min_panel_support):
                found.append(("rectangle", face, np.full((face[3], face[2]), 255, np.uint8)))
        if k in circles:
            cu, cv, r, support = refined[circles[k]]
            if support >= white.white_min_edge_support:
                side = int(round(2 * r)) + 1
                disc = np.zeros((side, side), np.uint8)
                cv2.circle(disc, (side // 2, side // 2), side // 2, 255, -1)
                found.append(("circle", (int(round(cu - side / 2)), int(round(cv - side / 2)), side, side), disc))
        readings.append(found)
    return readings


@dataclass(frozen=True)
class _Hull:
    points: np.ndarray  # the convex hull of the joined cells (pixels of their box)
    cover: int  # pixels of the cells
    fitted: bool  # whether the filled hull reads as a rectangle (:func:`.shape.classify_shape`)


def _hull(mask: np.ndarray, config: PipelineConfig) -> Optional[_Hull]:
    """The hull of joined cells ``mask``: it bridges stripe bands, digits and frame lines of a convex face. Its
    outline is fitted only when its fill leaves a rectangle among the shapes tried."""
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    if not contours:
        return None
    hull = cv2.convexHull(np.vstack(contours))
    closed = np.zeros_like(mask)
    cv2.fillConvexPoly(closed, hull, 255)
    fill_window = config.shape.shape_fill_window
    fitted = ("rectangle" in shapes_tried(fill_ratio(closed), fill_window)
              and classify_shape(closed, config.white.white_min_shape_fit, fill_window).shape
              in ("rectangle", "square"))
    return _Hull(hull, int(np.count_nonzero(mask)), fitted)


def _may_be_panel(box: Box, cover: int, white) -> bool:
    """A panel whose field the stripes cut into pieces that leave its corners out still has four straight sides on
    strong edges, where a disc's box touches its outline at four points only: unions of a panel's aspect whose
    cells cover enough of their box have their box's sides measured."""
    x, y, w, h = box
    return max(w, h) <= white.white_max_aspect * min(w, h) and cover >= white.white_min_panel_cover * w * h


def hough_discs(scan: WhiteScan, side_range: Tuple[float, float], config: PipelineConfig
                ) -> List[Tuple[str, Box, np.ndarray]]:
    """Disc readings (shape, box, outline mask in that box) of the round outlines that the Hough transform
    finds in the scanned grey image: a disc whose field digits and stripes cut into cells smaller than
    a part of a face, or whose pale ring runs into a pale wall, still has a round outline. Each circle is
    moved to its best outline (:func:`refine_circle`) and kept when that lies on strong radial gradients and
    the disc inside is achromatic and bright like a white face's cells (``white_cells``)."""
    grey, hsv, gradients = scan.grey, scan.hsv, scan.gradients
    white = config.white
    lo, hi = side_range
    r_min, r_max = max(2, int(white.white_hough_min_radius * lo / 2)), int(np.ceil(hi / 2))
    if r_max <= r_min:
        return []
    circles = hough_circles(grey, r_min, r_max, config)
    floor = white.white_min_brightness * scan.median_value
    height, width = grey.shape[:2]
    readings = []
    for cu, cv, r in circles:
        cu, cv, r, support = refine_circle(gradients, float(cu), float(cv), float(r), config)
        if support < white.white_min_edge_support:
            continue
        side = int(round(2 * r)) + 1
        x, y = int(round(cu - side / 2)), int(round(cv - side / 2))
        if x < 0 or y < 0 or x + side > width or y + side > height:
            continue
        disc = np.zeros((side, side), np.uint8)
        cv2.circle(disc, (side // 2, side // 2), side // 2, 255, -1)
        inside = hsv[y : y + side, x : x + side][disc > 0]
        if (np.mean(inside[:, 1] <= white.white_max_saturation) < white.white_min_achromatic
                or float(np.mean(inside[:, 2])) < floor):
            continue
        readings.append(("circle", (x, y, side, side), disc))
    return readings


def hough_circles(grey: np.ndarray, r_min: int, r_max: int, config: PipelineConfig) -> List[Tuple[float, float, float]]:
    """(u, v, r) of the round outlines of radius ``r_min``..``r_max`` in ``grey`` (Hough transform). Radii above
    ``white_hough_coarse_radius`` are sought in ``grey`` reduced by 2, where they still span that radius: the
    transform's cost grows with the radii it sweeps over, and a large disc loses nothing at half the scale
    (:func:`refine_circle` then places it on the full scan's gradients)."""
    white = config.white
    split = max(r_min, int(white.white_hough_coarse_radius))
    passes = [(grey, 1.0, r_min, min(r_max, split))]
    if r_max > split:
        half = cv2.resize(grey, None, fx=0.5, fy=0.5, interpolation=cv2.INTER_AREA)
        passes.append((half, 2.0, split // 2, int(np.ceil(r_max / 2.0))))
    found = []
    for image, factor, lo, hi in passes:
        if hi <= lo:
            continue
        circles = cv2.HoughCircles(image, cv2.HOUGH_GRADIENT_ALT, white.white_hough_dp, white.white_hough_min_dist * lo,
                                   param1=white.white_hough_edge, param2=white.white_hough_roundness,
                                   minRadius=lo, maxRadius=hi)
        if circles is not None:
            shift = (factor - 1.0) / 2.0  # a reduced pixel's centre lies between the pixels it averages
            found += [(float(u) * factor + shift, float(v) * factor + shift, float(r) * factor)
                      for u, v, r in circles[0]]
    return found


def format_outline(grey: np.ndarray, bbox: Box, sizes_px: Sequence[Tuple[str, float, float]], scale: float,
                   config: PipelineConfig) -> Optional[Tuple[str, Box, float]]:
    """(shape, box, edge support) of the outline of a standard size best lying on strong edges near ``bbox``
    (full-image pixels of ``grey``), or None when none reaches ``white_min_edge_support``.

    ``sizes_px``: (shape, width, height) of the white formats at the face's depth. A face whose measured size
    fell between two formats had its outline read too large (a pale disc before a white board behind it, read
    with it) or too small (a panel's field cut short by its stripes): the outline of each format is sought
    where it overlaps ``bbox`` by at least ``white_format_min_iou``, in the image scanned at ``scale`` like
    the candidates, and the edges decide between the formats.
    """
    min_iou = config.white.white_format_min_iou
    return _best_outline(grey, bbox, sizes_px, scale, config, config.white.white_min_edge_support,
                         lambda u, v, fw, fh, face: box_ious(face, np.column_stack(
                             [u, v, np.full_like(u, fw), np.full_like(u, fh)])) >= min_iou)


def panel_around(grey: np.ndarray, bbox: Box, sizes_px: Sequence[Tuple[float, float]], scale: float,
                 config: PipelineConfig) -> Optional[Tuple[str, Box, float]]:
    """("rectangle", box, edge support) of the panel outline of a standard size around the disc ``bbox`` whose
    four sides lie best on strong edges (at least ``white_min_panel_support`` of them), or None.

    An end-of-zone panel carries its zone's disc; where the panel's field is pale before a pale wall, or
    its lettering and stripe cut it into cells too small to read, only the disc is found, and it resembles
    a disc sign (2.53.1, 2.30-30). ``sizes_px``: (width, height) of the white panel formats at the disc's
    depth; only those larger than the disc both ways are tried, wherever they hold the whole disc. A disc
    over a plate or before a wall has no straight outline on all four sides at a panel's size.
    """
    x, y, w, h = bbox
    sizes = [("rectangle", fw, fh) for fw, fh in sizes_px if fw > w and fh > h]
    if not sizes:
        return None
    return _best_outline(grey, bbox, sizes, scale, config, config.white.white_min_panel_support,
                         lambda u, v, fw, fh, face: ((u <= face[0] + 1) & (v <= face[1] + 1)
                                                     & (u + fw >= face[0] + face[2] - 1)
                                                     & (v + fh >= face[1] + face[3] - 1)))


_OUTLINES_AT_ONCE = 4096  # placements whose edge support is measured in one call: bounds its arrays' memory


def _best_outline(grey: np.ndarray, bbox: Box, sizes_px: Sequence[Tuple[str, float, float]], scale: float,
                  config: PipelineConfig, min_support: float, placed_well
                  ) -> Optional[Tuple[str, Box, float]]:
    """(shape, box, edge support) of the outline among ``sizes_px`` (shape, width, height in full-image pixels)
    lying best on strong edges, placed on a one-pixel grid of the image scanned at ``scale`` wherever
    ``placed_well(u, v, width, height, face)`` holds (corners as arrays, both at that scale; ``face`` is
    ``bbox``), or None when the best has less support than ``min_support``. Of equal supports the first
    (in the order of ``sizes_px``, then of the corner's column and row) wins."""
    x, y, w, h = bbox
    height, width = grey.shape[:2]
    big = max([w, h] + [max(sw, sh) for _, sw, sh in sizes_px])
    x0, y0 = max(0, int(x - big)), max(0, int(y - big))
    x1, y1 = min(width, int(x + w + big)), min(height, int(y + h + big))
    if x1 - x0 < 8 or y1 - y0 < 8:
        return None
    crop = grey[y0:y1, x0:x1]
    small = cv2.resize(crop, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA) if scale < 1 else crop
    gradients = (cv2.Sobel(small, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(small, cv2.CV_32F, 0, 1, ksize=3))
    face = ((x - x0) * scale, (y - y0) * scale, w * scale, h * scale)
    sx, sy, sw0, sh0 = face
    best = None
    for shape, fw, fh in sizes_px:
        fw, fh = fw * scale, fh * scale
        # positions of the format's box overlapping the candidate's: its corner on a one-pixel grid
        us = np.arange(np.floor(min(sx, sx + sw0 - fw)), np.ceil(max(sx, sx + sw0 - fw)) + 1.0)
        vs = np.arange(np.floor(min(sy, sy + sh0 - fh)), np.ceil(max(sy, sy + sh0 - fh)) + 1.0)
        u, v = (a.ravel() for a in np.meshgrid(us, vs, indexing="ij"))
        well = placed_well(u, v, fw, fh, face)
        u, v = u[well], v[well]
        for start in range(0, len(u), _OUTLINES_AT_ONCE):
            cu, cv = u[start : start + _OUTLINES_AT_ONCE], v[start : start + _OUTLINES_AT_ONCE]
            if shape == "circle":
                support = np.atleast_1d(edge_support(gradients, cu + fw / 2.0, cv + fh / 2.0, fw / 2.0, config))
            else:
                side_w, side_h = int(round(fw)), int(round(fh))
                support = box_edge_supports(gradients, [(int(a), int(b), side_w, side_h) for a, b in zip(cu, cv)],
                                            config)
            k = int(np.argmax(support))
            if best is None or support[k] > best[0]:
                best = (float(support[k]), shape, (float(cu[k]), float(cv[k]), fw, fh))
    if best is None or best[0] < min_support:
        return None
    support, shape, (u, v, fw, fh) = best
    return shape, (int(round(x0 + u / scale)), int(round(y0 + v / scale)), int(round(fw / scale)),
                   int(round(fh / scale))), float(support)


def ring_around(bgr: np.ndarray, bbox: Box, scale: float, config: PipelineConfig) -> Optional[Box]:
    """Box of the outer outline of an achromatic ring around the disc ``bbox`` (full-image pixels of ``bgr``),
    or None: a grey-ringed disc (2.53.1's GENERELL ring) whose ring runs into a pale wall reads as its inner
    field alone. The outline is sought concentric, ``white_ring_ratios`` x the disc's radius, in the image
    scanned at ``scale``; the ring's own outline is weaker than a face's, so ``white_ring_min_support`` of
    its points on radial gradients suffice, and the ring between must be achromatic."""
    white = config.white
    lo_ratio, hi_ratio = white.white_ring_ratios
    x, y, w, h = bbox
    height, width = bgr.shape[:2]
    reach = int(np.ceil(hi_ratio * max(w, h) / 2.0)) + 2
    cx, cy = x + w / 2.0, y + h / 2.0
    x0, y0 = max(0, int(cx - reach)), max(0, int(cy - reach))
    x1, y1 = min(width, int(cx + reach) + 1), min(height, int(cy + reach) + 1)
    crop = bgr[y0:y1, x0:x1]
    if crop.shape[0] < 8 or crop.shape[1] < 8:
        return None
    small = cv2.resize(crop, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA) if scale < 1 else crop
    grey = cv2.cvtColor(small, cv2.COLOR_BGR2GRAY)
    gradients = (cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3))
    cu, cv, r = (cx - x0) * scale, (cy - y0) * scale, max(w, h) / 2.0 * scale
    du, dv, ratio = np.meshgrid([-1.0, 0.0, 1.0], [-1.0, 0.0, 1.0],
                                np.linspace(lo_ratio, hi_ratio, white.white_ring_steps), indexing="ij")
    support = edge_support(gradients, cu + du.ravel(), cv + dv.ravel(), r * ratio.ravel(), config)
    best = int(np.argmax(support))
    if support[best] < white.white_ring_min_support:
        return None
    ou, ov, outer = cu + du.ravel()[best], cv + dv.ravel()[best], r * ratio.ravel()[best]
    ring = np.zeros(grey.shape, np.uint8)
    cv2.circle(ring, (int(round(ou)), int(round(ov))), int(round(outer - 1)), 255, -1)
    cv2.circle(ring, (int(round(ou)), int(round(ov))), int(round(r + 1)), 0, -1)
    saturation = cv2.cvtColor(small, cv2.COLOR_BGR2HSV)[:, :, 1][ring > 0]
    if saturation.size == 0 or np.mean(saturation <= white.white_max_saturation) < white.white_min_achromatic:
        return None
    side = int(round(2 * outer / scale))
    return int(round(x0 + ou / scale - side / 2.0)), int(round(y0 + ov / scale - side / 2.0)), side, side


def _centre_inside(a: Box, b: Box) -> bool:
    cu, cv = a[0] + a[2] / 2.0, a[1] + a[3] / 2.0
    return b[0] <= cu < b[0] + b[2] and b[1] <= cv < b[1] + b[3]


def white_candidates(bgr: np.ndarray, side_range_px: Tuple[float, float], config: PipelineConfig,
                     scan: Optional[WhiteScan] = None) -> List[WhiteCandidate]:
    """Candidates of white and grey signs in ``bgr`` (a whole image or a window; pixels of that image).

    ``side_range_px``: the smallest and the largest face side sought (:func:`face_side_range_px`); ``scan``:
    the image's :func:`scan_image` for its smallest side, when already made.
    The faces read from the cells, largest first; one whose centre lies inside a larger one is a part of it
    (the ring on a zone panel). At most ``white_max_candidates``.
    """
    lo, hi = side_range_px
    height, width = bgr.shape[:2]
    if lo <= 0 or hi <= 0:
        return []
    scan = scan if scan is not None else scan_image(bgr, lo, config)
    scale, gradients = scan.scale, scan.gradients
    ids, boxes = white_cells(scan, (lo * scale, hi * scale), config)
    faces = hough_discs(scan, (lo * scale, hi * scale), config) if config.white.white_hough else []
    groups = group_cells(boxes, (lo * scale, hi * scale), config.white.white_join_reach,
                         config.white.white_max_aspect, config.white.white_join_gap * lo * scale,
                         config.white.white_join_steps)
    in_reach = outlines_in_reach(gradients, [box for box, _ in groups], config)
    labels = int(scan.labels.max()) + 1 if groups else 0
    unions = []
    for (box, members), reached in zip(groups, in_reach):
        if not reached:
            continue
        x, y, w, h = box
        member = np.zeros(labels, np.uint8)  # a table of the group's labels: a lookup instead of np.isin
        member[ids[list(members)]] = 255
        unions.append((member[scan.labels[y : y + h, x : x + w]], box))
    faces += [face for readings in read_faces(unions, gradients, config) for face in readings
              if lo * scale <= min(face[1][2:]) and max(face[1][2:]) <= hi * scale]
    faces.sort(key=lambda f: f[1][2] * f[1][3], reverse=True)
    kept: List[WhiteCandidate] = []
    margin = config.colour.border_margin_px
    for shape, (fx, fy, fw, fh), outline in faces:
        bx, by = int(round(fx / scale)), int(round(fy / scale))
        bw, bh = max(1, int(round(fw / scale))), max(1, int(round(fh / scale)))
        full_box = (bx, by, bw, bh)
        if bx < 0 or by < 0 or bx + bw > width or by + bh > height:
            continue
        # a face inside a larger one of the same shape is a part of it (the ring on a zone panel); of the other
        # shape it may be the face itself (a disc above its plate, read together as a panel): depth and the
        # templates decide, and the best of overlapping detections is kept (detect.suppress_overlaps)
        if any(box_iou(full_box, c.segment.bbox) > config.white.white_same_iou
               or (c.shape == shape and _centre_inside(full_box, c.segment.bbox)) for c in kept):
            continue
        outline = cv2.resize(outline, (bw, bh), interpolation=cv2.INTER_NEAREST)
        contours, _ = cv2.findContours(outline, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        if not contours:
            continue
        touches = bx <= margin or by <= margin or bx + bw >= width - margin or by + bh >= height - margin
        seg = Segment("white", full_box, outline, max(contours, key=cv2.contourArea) + np.array([bx, by]),
                      int(np.count_nonzero(outline)), touches, source="white")
        kept.append(WhiteCandidate(seg, shape))
        if len(kept) >= config.white.white_max_candidates:
            break
    return kept


def context_boxes(candidates: Sequence[WhiteCandidate], config: PipelineConfig) -> List[Box]:
    """Boxes around the candidates that depth is needed in: the face, its sides (is it standing free?) and
    the strip below it (its pole), as multiples of the face's size."""
    boxes = []
    for cand in candidates:
        x, y, w, h = cand.segment.bbox
        side = int(round((config.white.white_side_gap + config.white.white_side_band) * w))
        below = int(round((config.white.white_support_gap + config.white.white_support_length) * h))
        boxes.append((max(0, x - side), y, w + 2 * side, h + below))
    return boxes
