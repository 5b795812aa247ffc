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
from .travel import MIN_LEGS, Legs, heading_miss

FULL_TURN_RAD = 2 * np.pi + 1e-6
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


def check_radians_as_degrees(angles_deg: np.ndarray, legs: Legs, table,
                             forward_headings: Callable[[np.ndarray], np.ndarray]) -> None:
    """ImportInputError when angles given as degrees behave like radians (see module).

    ``legs``: the track's legs (``travel.travel_legs``) of the table's rows; ``forward_headings(angles_deg)`` gives
    the grid azimuth of the body's forward axis per row.
    """
    angles_deg = np.asarray(angles_deg, float)
    if np.any(np.abs(angles_deg) > FULL_TURN_RAD) or len(legs) < MIN_LEGS:
        return
    as_degrees = heading_miss(legs, forward_headings(angles_deg))
    as_radians = heading_miss(legs, forward_headings(np.degrees(angles_deg)))
    if as_degrees > DEGREES_OFF_DEG and as_radians < RADIANS_ON_DEG:
        path, line = table.where(int(legs.starts[0]))
        raise ImportInputError(
            path, f"the angles look like radians given as degrees: read as degrees the forward direction misses the "
            f"direction of travel by {as_degrees:.0f} degrees (median), read as radians by {as_radians:.1f}; set the "
            "angle unit to radians", line=line, field=table.angle_names[0])
