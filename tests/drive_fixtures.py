"""Small, fast drive folders for tests, written with the core's own drive writer."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from signmapper_core.drive.reader import TruthSign
from signmapper_core.drive.writer import write_drive_json, write_pair, write_poses_csv, write_truth_csv
from signmapper_core.geometry import Camera, Pose

SMALL_CAMERA = Camera(width=64, height=48, fx=60.0, fy=60.0, cx=31.5, cy=23.5, baseline_m=0.9)
START = (2600000.0, 1200000.0, 400.0)
# Synthetic drives for mapping tests: half-HD with half the focal length keeps the angular resolution of the
# real camera's 4-14 m range at a quarter of the pixels, so the tests stay quick.
SMALL_SYNTHETIC = dict(width=960, height=540, fx=875.0)


def straight_poses(n: int, heading: float = 90.0, step_m: float = 2.0, start=START) -> list[tuple[str, float, Pose]]:
    """``n`` poses driving along ``heading`` every ``step_m`` metres, 0.2 s apart."""
    east, north, up = start
    dx, dy = np.sin(np.radians(heading)) * step_m, np.cos(np.radians(heading)) * step_m
    return [(f"{i:06d}", 0.2 * i, Pose(east + i * dx, north + i * dy, up, heading, 0.0, 0.0)) for i in range(n)]


def make_drive(root: Path, n_pairs: int = 3, camera: Camera = SMALL_CAMERA, crs: str = "EPSG:2056",
               with_right: bool = True, depth_suffix: str | None = ".npy", image_suffix: str = ".png",
               truth: bool = True) -> Path:
    """Write a valid drive with flat grey images and constant depth (8 m)."""
    root = Path(root)
    write_drive_json(root, crs, camera, software="tests")
    poses = straight_poses(n_pairs)
    write_poses_csv(root, poses)
    rng = np.random.default_rng(0)
    for pair_id, _t, _p in poses:
        left = rng.integers(0, 255, (camera.height, camera.width, 3), dtype=np.uint8)
        right = left.copy() if with_right else None
        depth = np.full((camera.height, camera.width), 8.0, np.float32) if depth_suffix else None
        write_pair(root, pair_id, left, right, depth, image_suffix=image_suffix, depth_suffix=depth_suffix or ".npy")
    if truth:
        sign = TruthSign("s001", "2.30-50", START[0] + 5, START[1] + 3, START[2] + 1.5, 0.6, 0.6, 270.0)
        write_truth_csv(root, [sign])
    return root


def rewrite_line(path: Path, line_no: int, text: str) -> None:
    """Replace 1-based line ``line_no`` of a text file."""
    lines = Path(path).read_text().splitlines()
    lines[line_no - 1] = text
    Path(path).write_text("\n".join(lines) + "\n")
