"""Is a drive plausible? Values the format allows but that are most likely a mistake, as warnings.

The drive reader (``drive.py``) rejects what cannot work. The checks here name
what can be read but would put signs in the wrong place or find none: a camera
with an odd field of view or baseline, angles outside their usual ranges,
positions outside the area of use of the CRS (longitude/latitude in a projected
CRS), depth not in metres, greyscale images, pairs without usable depth or
colour. Each returns messages naming the file; the caller decides where they go
(``Drive.warnings``, the mapping's log).
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

import numpy as np

FIELD_OF_VIEW_DEG = (10.0, 150.0)  # horizontal, of the normal images
BASELINE_M = (0.05, 5.0)  # stereo rigs on vehicles are 0.1-1.5 m wide
MAX_PITCH_DEG = 45.0  # a mapping camera looks roughly along the road
MAX_ROLL_DEG = 45.0
DEPTH_M = (0.5, 500.0)  # what a street camera's depth map holds
MIN_DEPTH_SHARE = 0.5  # "most pixels" with a valid depth must lie in DEPTH_M
MIN_COLOUR_SPREAD = 12  # max - min channel value: below this everywhere, an image has no colour
AREA_MARGIN = 0.1  # of the extent of a CRS's area of use: drives just across a border are fine


def camera_warnings(path, camera) -> list[str]:
    """Field of view, pixel aspect and baseline of a camera that the format allows but no vehicle has."""
    warnings = []
    fov = math.degrees(2 * math.atan2(camera.width / 2, camera.fx))
    if not FIELD_OF_VIEW_DEG[0] <= fov <= FIELD_OF_VIEW_DEG[1]:
        warnings.append(f"{path}, field 'camera.fx': fx {camera.fx:g} px gives a horizontal field of view of "
                        f"{fov:.1f}° for {camera.width} px, outside the usual {FIELD_OF_VIEW_DEG[0]:g}-"
                        f"{FIELD_OF_VIEW_DEG[1]:g}°; is fx in pixels?")
    if not 0.8 <= camera.fx / camera.fy <= 1.25:
        warnings.append(f"{path}, field 'camera.fy': fx {camera.fx:g} and fy {camera.fy:g} differ by more than "
                        "25 %; normal images have square pixels")
    if not BASELINE_M[0] <= camera.baseline_m <= BASELINE_M[1]:
        warnings.append(f"{path}, field 'camera.baseline_m': {camera.baseline_m:g} m is outside the usual "
                        f"{BASELINE_M[0]:g}-{BASELINE_M[1]:g} m; is it in metres?")
    return warnings


def angle_warnings(path, lines, name: str, values, low: float, high: float, unit_note: str) -> list[str]:
    """One message for all rows whose ``name`` lies outside [low, high]."""
    values = np.asarray(values, float)
    bad = np.flatnonzero((values < low) | (values > high))
    if not len(bad):
        return []
    first = bad[0]
    return [f"{path}, field '{name}': {len(bad)} of {len(values)} rows outside {low:g}..{high:g}° "
            f"(first: line {lines[first]}, {values[first]:g}); {unit_note}"]


def pose_warnings(path, crs_text: str, rows) -> list[str]:
    """Angles outside their usual ranges and positions outside the CRS's area of use.

    ``rows`` are (line, id, time, Pose) as the reader parsed them; all checks are vectorised.
    """
    lines = [r[0] for r in rows]
    poses = [r[3] for r in rows]
    heading = [p.heading for p in poses]
    pitch = [p.pitch for p in poses]
    roll = (np.array([p.roll for p in poses]) + 180.0) % 360.0 - 180.0
    warnings = angle_warnings(path, lines, "heading", heading, -360.0, 360.0, "headings are degrees from grid north")
    warnings += angle_warnings(path, lines, "pitch", pitch, -MAX_PITCH_DEG, MAX_PITCH_DEG,
                               "a mapping camera looks roughly along the road; are pitch and heading swapped?")
    warnings += angle_warnings(path, lines, "roll", roll, -MAX_ROLL_DEG, MAX_ROLL_DEG,
                               "is the camera mounted upright, are pitch and roll swapped?")
    east = np.array([p.easting for p in poses])
    north = np.array([p.northing for p in poses])
    warnings += area_warnings(path, crs_text, lines, east, north)
    return warnings


@lru_cache(maxsize=16)
def area_of_use(crs_text: str):
    """(name, (xmin, ymin, xmax, ymax) in the CRS with a margin) of the CRS's area of use, or None if unknown."""
    from pyproj import CRS, Transformer

    crs = CRS.from_user_input(crs_text)
    horizontal = crs.sub_crs_list[0] if crs.is_compound else crs
    area = horizontal.area_of_use or crs.area_of_use
    if area is None or area.west > area.east:  # unknown, or across the antimeridian
        return None
    to_crs = Transformer.from_crs("EPSG:4326", horizontal, always_xy=True)
    bounds = to_crs.transform_bounds(area.west, area.south, area.east, area.north, densify_pts=21)
    if not all(math.isfinite(b) for b in bounds):
        return None
    xmin, ymin, xmax, ymax = bounds
    margin = AREA_MARGIN * max(xmax - xmin, ymax - ymin)
    name = f"{crs_text} ({horizontal.name}: {area.name.rstrip('.')})"
    return name, (xmin - margin, ymin - margin, xmax + margin, ymax + margin)


def area_warnings(path, crs_text: str, lines, east, north) -> list[str]:
    """Positions outside the CRS's area of use, with a hint when they look like longitude/latitude."""
    known = area_of_use(crs_text)
    if known is None:
        return []
    name, (xmin, ymin, xmax, ymax) = known
    east, north = np.asarray(east, float), np.asarray(north, float)
    outside = np.flatnonzero((east < xmin) | (east > xmax) | (north < ymin) | (north > ymax))
    if not len(outside):
        return []
    first = outside[0]
    degrees = np.all((np.abs(east[outside]) <= 180) & (np.abs(north[outside]) <= 90))
    hint = ("they look like longitude/latitude in degrees, but positions must be easting and northing in "
            "metres of the drive's CRS" if degrees else "is the CRS in drive.json the one the positions are in?")
    return [f"{path}: {len(outside)} of {len(east)} positions lie outside the area of use of {name} "
            f"(first: line {lines[first]}, easting {east[first]:.6g}, northing {north[first]:.6g}); {hint}"]


def depth_warnings(path, depth: np.ndarray) -> list[str]:
    """A depth map (NaN = no depth) whose values are not the metres of a street scene."""
    valid = depth[np.isfinite(depth)]
    if valid.size == 0:
        return [f"{path}: no pixel has a depth (all 0, negative, inf or NaN)"]
    inside = np.count_nonzero((valid >= DEPTH_M[0]) & (valid <= DEPTH_M[1])) / valid.size
    if inside >= MIN_DEPTH_SHARE:
        return []
    median = float(np.median(valid))
    unit = " (millimetres?)" if median > 1000 * DEPTH_M[0] else " (kilometres?)" if median < DEPTH_M[0] else ""
    return [f"{path}: only {100 * inside:.0f} % of the valid depths lie within {DEPTH_M[0]:g}-{DEPTH_M[1]:g} m, "
            f"median {median:.4g}{unit}; depth maps hold metres"]


def greyscale_warning(folder: Path, grey: list, total: int) -> list[str]:
    """Greyscale images in ``folder``: signs are found by colour, so none will be found in them."""
    if not grey:
        return []
    return [f"{folder}/: {len(grey)} of {total} images are greyscale (first: {Path(grey[0]).name}); "
            "signs are found by their colour, so none can be found there"]


def has_colour(bgr: np.ndarray) -> bool:
    """Whether any pixel of a BGR image has a colour (channels differing), sampled every 4th pixel.

    Every 16th pixel (part of that sample) is looked at first: a colour photograph
    answers there, at 1/16 of the cost; only a grey one needs the whole sample.
    """
    return any(_colour_spread(bgr[::step, ::step]) >= MIN_COLOUR_SPREAD for step in (16, 4))


def _colour_spread(sample: np.ndarray) -> int:
    sample = sample.astype(np.int16)
    return int((sample.max(axis=2) - sample.min(axis=2)).max(initial=0))


def pair_warnings(record, left: np.ndarray, depth: np.ndarray | None) -> list[str]:
    """What makes one decoded pair useless although it reads: a depth map without depth, no colour."""
    warnings = []
    if depth is not None and not np.isfinite(depth).any():
        warnings.append(f"Pair {record.id}: {record.depth_path} has no usable depth (all 0, negative, inf or NaN); "
                        "no sign can be found in it")
    if not has_colour(left):
        warnings.append(f"Pair {record.id}: {record.left_path} has no colour at all (a greyscale picture?); signs "
                        "are found by their colour")
    return warnings
