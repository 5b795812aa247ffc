"""The generic import: image folders, a calibration file and a pose CSV, as any survey vehicle can export them."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from ..errors import ImportInputError
from .attitude import convention
from .calibration import read_calibrations
from .camera_poses import Orientation
from .crs_steps import horizontal, parse_crs
from .image_pairs import list_pairs
from .importer import DriveSource
from .mount import Mount
from .pose_table import read_image_times, read_pose_table


@dataclass(frozen=True)
class GenericInputs:
    """Everything a user names for a generic import."""

    left: Path
    calibration: Path
    poses: Path
    right: Optional[Path] = None
    left_pattern: str = ""
    right_pattern: str = ""
    trajectory: bool = False              # poses are a time-stamped trajectory (else one row per image)
    image_times: Optional[Path] = None    # id,time CSV (trajectories; optional for per-image tables)
    orientation: Orientation = Orientation()
    input_crs: str = "EPSG:4979"
    lever_arm_m: tuple[float, float, float] = (0.0, 0.0, 0.0)
    boresight_deg: tuple[float, float, float] = (0.0, 0.0, 0.0)


def generic_source(inputs: GenericInputs) -> DriveSource:
    """Read the images' names, the calibration and the pose table (no pixels yet)."""
    conv = convention(inputs.orientation.convention)
    pairs = list_pairs(inputs.left, inputs.right, inputs.left_pattern, inputs.right_pattern)
    calibrations = read_calibrations(inputs.calibration)
    geographic = horizontal(parse_crs(inputs.input_crs, "input")).is_geographic
    table = read_pose_table(inputs.poses, conv.angle_names, need_ids=not inputs.trajectory,
                            need_times=inputs.trajectory, geographic=geographic)
    times = None
    if inputs.image_times is not None:
        times = {k: t for k, (t, _line) in read_image_times(inputs.image_times).items()}
    elif inputs.trajectory:
        raise ImportInputError(inputs.poses, "a trajectory is interpolated to the image times: give the image times "
                               "(a CSV with id,time)")
    return DriveSource(
        label=f"images {inputs.left}" + (f" and {inputs.right}" if inputs.right else ""),
        pairs=pairs, calibrations=calibrations, poses=table, per_image=not inputs.trajectory,
        orientation=inputs.orientation, input_crs=inputs.input_crs,
        mount=Mount.from_boresight(conv, inputs.lever_arm_m, inputs.boresight_deg),
        image_times=times, image_times_source=inputs.image_times)
