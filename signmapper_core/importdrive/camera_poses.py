"""From recorded body poses to the drive's left-camera poses: the chain of every import.

1. angles in degrees (``angle_units``), positions into the output CRS (``crs_steps``); the angles checked
   against the direction of travel (``angle_units``, ``convention_check``);
2. body -> local east/north/up (``attitude``), then -> output grid (meridian convergence);
3. interpolation to the image times for trajectories (``interpolate``);
4. lever arm and boresight to the raw left camera (``mount``);
5. the rectifying rotation to the left normal image (``rectify``), and heading/pitch/roll
   as drive-format.md defines them (``geometry.angles_from_rotation``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np

from ..geometry import Pose, angles_from_rotation
from .angle_units import check_radians_as_degrees, to_degrees
from .attitude import Convention, convention, forward_heading
from .convention_check import check_convention
from .crs_steps import CrsSteps
from .mount import Mount
from .pose_table import PoseTable
from .travel import travel_legs

NORTHS = ("auto", "true", "grid")


@dataclass(frozen=True)
class Orientation:
    """How a pose table's angles are to be read."""

    convention: str = "ned_ypr"
    unit: str = "deg"            # "deg" or "rad"
    north: str = "auto"          # "true", "grid" (of a projected input CRS), "auto"


def resolve_north(orientation: Orientation, conv: Convention, steps: CrsSteps) -> str:
    """``auto``: navigation angles are against true north; a camera's exterior orientation against the grid of a
    projected input CRS (true north for a geographic one)."""
    if orientation.north not in NORTHS:
        raise ValueError(f"north must be one of {NORTHS}, not {orientation.north!r}")
    if orientation.north != "auto":
        return orientation.north
    return "grid" if conv.camera_like and not steps.input_geographic else "true"


def body_poses(table: PoseTable, orientation: Orientation, steps: CrsSteps,
               note: Callable[[str], None] = lambda _m: None,
               order: Optional[np.ndarray] = None) -> tuple[np.ndarray, np.ndarray]:
    """Body positions (n, 3) in the output CRS and body -> output-grid rotations (n, 3, 3).

    The angles are checked against the direction of travel (unit, convention) with the rows in ``order``, the
    driving order (default: as given); ``note`` gets what could not be checked.
    """
    conv = convention(orientation.convention)
    angles = to_degrees(table.angles, orientation.unit, table)
    centres = steps.positions(table.xyz)
    to_grid: dict[str, np.ndarray] = {}

    def rotations(c: Convention, rows_deg: np.ndarray) -> np.ndarray:
        north = resolve_north(orientation, c, steps)
        if north not in to_grid:
            to_grid[north] = steps.grid_rotations(table.xyz, north)
        return np.stack([g @ c.rotation(a) for g, a in zip(to_grid[north], rows_deg)])

    read = rotations(conv, angles)

    def headings(c: Convention, rows_deg: np.ndarray) -> np.ndarray:
        turned = read if c is conv and rows_deg is angles else rotations(c, rows_deg)
        return np.array([forward_heading(r, c) for r in turned])

    legs = travel_legs(centres, order)
    if orientation.unit == "deg":
        check_radians_as_degrees(angles, legs, table, lambda rows: headings(conv, rows))
    check_convention(conv, legs, table, lambda c: headings(c, angles), note)
    return centres, read


def drive_poses(centres: np.ndarray, rotations: np.ndarray, mount: Mount, rectify_rotation: np.ndarray) -> list[Pose]:
    """Poses of the left normal image for body poses; ``rectify_rotation`` maps raw to rectified left camera."""
    camera_centres, raw_to_world = mount.camera_pose(centres, rotations)
    poses = []
    for centre, rotation in zip(camera_centres, raw_to_world @ np.asarray(rectify_rotation).T):
        poses.append(Pose(*(float(v) for v in centre), *angles_from_rotation(rotation)))
    return poses
