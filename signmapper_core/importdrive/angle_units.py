"""Angles in the unit the user said, and the two mix-ups that are easy to see.

Degrees given as radians show at once: a value beyond 2 pi. Radians given as
degrees look like small but valid angles; they show against the direction of
travel: a vehicle's forward axis (a forward camera's optical axis) follows the
track, so when the headings read as degrees miss the course over ground by
tens of degrees while the same numbers read as radians follow it, the unit is
wrong.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from ..errors import ImportInputError

FULL_TURN_RAD = 2 * np.pi + 1e-6
MIN_STEP_M = 0.5           # movement between epochs that gives a usable course over ground
DEGREES_OFF_DEG = 45.0     # read as degrees, the heading misses the course by more than this (median) ...
RADIANS_ON_DEG = 20.0      # ... and read as radians, it is within this


def to_degrees(angles: np.ndarray, unit: str, table) -> np.ndarray:
    """Angles of a pose table in degrees; radians beyond a full turn are an error naming the row."""
    if unit not in ("deg", "rad"):
        raise ValueError(f"angle unit must be 'deg' or 'rad', not {unit!r}")
    angles = np.asarray(angles, float)
    if unit == "deg":
        return angles
    beyond = np.argwhere(np.abs(angles) > FULL_TURN_RAD)
    if beyond.size:
        row, col = (int(v) for v in beyond[0])
        path, line = table.where(row)
        raise ImportInputError(path, f"{angles[row, col]:g} is more than a full turn in radians: are the angles "
                               "in degrees? set the angle unit to degrees", line=line, field=table.angle_names[col])
    return np.degrees(angles)


def course_over_ground(en: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(indices, azimuths in degrees): from each epoch to the first later one at least ``MIN_STEP_M`` away
    along the track (so high-rate trajectories give a course too)."""
    en = np.asarray(en, float)[:, :2]
    travelled = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(en, axis=0).T))])
    ahead = np.searchsorted(travelled, travelled + MIN_STEP_M)
    moving = np.flatnonzero(ahead < len(en))
    steps = en[ahead[moving]] - en[moving]
    return moving, np.degrees(np.arctan2(steps[:, 0], steps[:, 1])) % 360.0


def _median_miss(headings: np.ndarray, course: np.ndarray) -> float:
    diff = (np.asarray(headings) - course + 180.0) % 360.0 - 180.0
    return float(np.median(np.abs(diff)))


def check_radians_as_degrees(angles_deg: np.ndarray, en: np.ndarray, table,
                             forward_headings: Callable[[np.ndarray], np.ndarray]) -> None:
    """ImportInputError when angles given as degrees behave like radians (see module).

    ``forward_headings(angles_deg)`` gives the grid azimuth of the body's forward axis per row.
    """
    angles_deg = np.asarray(angles_deg, float)
    if np.any(np.abs(angles_deg) > FULL_TURN_RAD):
        return
    moving, course = course_over_ground(en)
    if moving.size < 3:
        return
    as_degrees = _median_miss(forward_headings(angles_deg)[moving], course)
    as_radians = _median_miss(forward_headings(np.degrees(angles_deg))[moving], course)
    if as_degrees > DEGREES_OFF_DEG and as_radians < RADIANS_ON_DEG:
        path, line = table.where(int(moving[0]))
        raise ImportInputError(
            path, f"the angles look like radians given as degrees: read as degrees the forward direction misses the "
            f"direction of travel by {as_degrees:.0f} degrees (median), read as radians by {as_radians:.1f}; set the "
            "angle unit to radians", line=line, field=table.angle_names[0])
