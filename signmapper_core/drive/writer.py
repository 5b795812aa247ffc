"""Writer of drive folders (``drive-format.md`` v1), for generators, fixtures and converters.

The writer produces exactly the layout the reader accepts, so round trips are
the tests' guarantee that both sides agree on the format.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Iterable

import numpy as np

from ..geometry import Camera, Pose
from .images import write_depth
from .reader import FORMAT_ID, POSE_COLUMNS, TRUTH_ARTWORK, TRUTH_COLUMNS, TRUTH_DRAWING, TRUTH_OPTIONAL, TruthSign


def write_drive_json(root: Path, crs: str, camera: Camera, **extra) -> Path:
    """Write ``drive.json``; ``extra`` keys (vehicle, software, notes) are kept."""
    cam = {k: getattr(camera, k) for k in ("width", "height", "fx", "fy", "cx", "cy", "baseline_m")}
    data = {"format": FORMAT_ID, "crs": crs, "camera": cam, **extra}
    path = Path(root) / "drive.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    return path


def write_poses_csv(root: Path, rows: Iterable[tuple[str, float, Pose]]) -> Path:
    """Write ``poses.csv`` from (id, time, pose) rows in driving order (mm / 1e-6 deg precision)."""
    path = Path(root) / "poses.csv"
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(POSE_COLUMNS)
        for pair_id, time, p in rows:
            writer.writerow(
                [pair_id, f"{time:.3f}", f"{p.easting:.4f}", f"{p.northing:.4f}", f"{p.height:.4f}",
                 f"{p.heading:.6f}", f"{p.pitch:.6f}", f"{p.roll:.6f}"]
            )
    return path


def write_truth_csv(root: Path, signs: Iterable[TruthSign]) -> Path:
    """Write ``truth.csv``."""
    path = Path(root) / "truth.csv"
    signs = list(signs)
    optional = any(s.plate_of or s.text for s in signs)  # the columns only where a plate or text needs them
    artwork = any(s.artwork for s in signs)
    drawing = any(s.drawing for s in signs)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(TRUTH_COLUMNS + (TRUTH_OPTIONAL if optional else ()) + ((TRUTH_ARTWORK,) if artwork else ())
                        + ((TRUTH_DRAWING,) if drawing else ()))
        for s in signs:
            writer.writerow(
                [s.sign_id, s.template_id, f"{s.easting:.4f}", f"{s.northing:.4f}", f"{s.height:.4f}",
                 f"{s.width_m:.3f}", f"{s.height_m:.3f}", f"{s.facing:.2f}"]
                + ([s.plate_of, s.text] if optional else []) + ([s.artwork] if artwork else [])
                + ([s.drawing] if drawing else [])
            )
    return path


def write_image(path: Path, bgr: np.ndarray, jpeg_quality: int = 90) -> Path:
    """Write a BGR uint8 image; the suffix picks the format (.jpg, .png, .tif)."""
    import cv2

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    params = [cv2.IMWRITE_JPEG_QUALITY, int(jpeg_quality)] if path.suffix.lower() == ".jpg" else []
    if not cv2.imwrite(str(path), bgr, params):
        raise OSError(f"{path}: OpenCV could not write the image")
    return path


def write_pair(root: Path, pair_id: str, left: np.ndarray, right: np.ndarray | None = None,
               depth: np.ndarray | None = None, image_suffix: str = ".jpg", depth_suffix: str = ".npy",
               jpeg_quality: int = 90) -> None:
    """Write the files of one pair into ``left/``, ``right/`` and ``depth/``."""
    root = Path(root)
    write_image(root / "left" / f"{pair_id}{image_suffix}", left, jpeg_quality)
    if right is not None:
        write_image(root / "right" / f"{pair_id}{image_suffix}", right, jpeg_quality)
    if depth is not None:
        (root / "depth").mkdir(parents=True, exist_ok=True)
        write_depth(root / "depth" / f"{pair_id}{depth_suffix}", depth)
