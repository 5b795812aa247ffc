"""The direction of travel from a vehicle's positions: what recorded headings are checked against.

A vehicle's forward axis (a forward camera's optical axis) follows its track, so
headings that miss the direction of travel were read the wrong way (unit,
convention). The track is cut into *legs*: each starts where the last one
ended and ends at the first later epoch at least ``MIN_STEP_M`` away in a
straight line. A vehicle standing still starts no leg, and the centimetre
jitter of a standing receiver never makes one; a high-rate trajectory still
gives one leg per half metre. On a curve a leg's chord runs along the tangent
halfway, so it is compared with the mean of the headings at its two ends.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

MIN_STEP_M = 0.5   # straight-line length of a leg: enough movement for a course over ground
MIN_LEGS = 3       # fewer legs than this and the direction of travel says nothing


@dataclass(frozen=True)
class Legs:
    """Stretches of the track: the rows where each starts and ends, and its azimuth (degrees, grid)."""

    starts: np.ndarray
    ends: np.ndarray
    course_deg: np.ndarray

    def __len__(self) -> int:
        return len(self.starts)


def _leg_end(en: np.ndarray, start: int) -> int:
    """The first row after ``start`` at least ``MIN_STEP_M`` from it, or ``len(en)``; searched in growing windows
    so that a long stop costs one pass, not one per epoch."""
    window = 16
    first = start + 1
    while first < len(en):
        stop = min(len(en), first + window)
        far = np.flatnonzero(np.hypot(*(en[first:stop] - en[start]).T) >= MIN_STEP_M)
        if far.size:
            return first + int(far[0])
        first, window = stop, 2 * window
    return len(en)


def travel_legs(en: np.ndarray, order: Optional[np.ndarray] = None) -> Legs:
    """The legs (see module) of positions ``en`` (rows of easting, northing[, height]) taken in ``order`` (driving
    order; default: as given); ``starts``/``ends`` index the rows of ``en``."""
    en = np.asarray(en, float)[:, :2]
    order = np.arange(len(en)) if order is None else np.asarray(order, dtype=int)
    driven = en[order]
    starts, ends = [], []
    start = 0
    while start < len(driven) - 1:
        end = _leg_end(driven, start)
        if end == len(driven):
            break
        starts.append(start)
        ends.append(end)
        start = end
    starts, ends = np.array(starts, dtype=int), np.array(ends, dtype=int)
    steps = driven[ends] - driven[starts] if len(starts) else np.zeros((0, 2))
    course = np.degrees(np.arctan2(steps[:, 0], steps[:, 1])) % 360.0
    return Legs(order[starts], order[ends], course)


def angle_difference(a, b) -> np.ndarray:
    """``a - b`` in degrees, wrapped to [-180, 180)."""
    return (np.asarray(a, float) - np.asarray(b, float) + 180.0) % 360.0 - 180.0


def heading_miss(legs: Legs, headings: np.ndarray) -> float:
    """Median absolute difference (degrees) between each leg's course and the mean forward heading at its ends;
    ``headings`` are per row of the positions the legs were cut from."""
    headings = np.asarray(headings, float)
    start, end = headings[legs.starts], headings[legs.ends]
    mean = start + angle_difference(end, start) / 2.0
    return float(np.median(np.abs(angle_difference(mean, legs.course_deg))))
