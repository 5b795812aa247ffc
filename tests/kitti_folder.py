"""A tiny KITTI raw drive written from scratch (calibration values of our own, in KITTI's formats).

Three frames of ``image_02``/``image_03`` (rectified 1242x375 PNGs: a texture and the same texture ten
pixels to the left, so rows line up), their OXTS packets and timestamps, and the three calibration files
in the date folder. KITTI's own data is never used in tests (non-commercial licence).
"""

from __future__ import annotations

from datetime import datetime, timedelta
from pathlib import Path

import cv2
import numpy as np
from stereo_scenes import texture

K = np.array([[721.5, 0.0, 609.6], [0.0, 721.5, 172.9], [0.0, 0.0, 1.0]])
T2 = np.array([0.0599, -0.0004, 0.0027])        # rectified camera 2 relative to rectified camera 0
T3 = np.array([-0.4731, 0.0024, 0.0034])
VELO_TO_CAM_AXES = np.array([[0, -1, 0], [0, 0, -1], [1, 0, 0.0]])   # velodyne x fwd, y left, z up -> camera
START = datetime(2011, 9, 26, 13, 2, 25, 964389)
FRAME_S = 0.1036
SIZE = (1242, 375)


def axis_rotation(axis, degrees):
    vector = np.asarray(axis, float) / np.linalg.norm(axis) * np.radians(degrees)
    return cv2.Rodrigues(vector)[0]


R_RECT_00 = axis_rotation((0.3, -0.5, 0.8), 0.6)
R_IMU_TO_VELO = axis_rotation((0.2, 0.1, 1.0), 0.5)
T_IMU_TO_VELO = np.array([-0.8086, 0.3195, -0.7997])
R_VELO_TO_CAM = VELO_TO_CAM_AXES @ axis_rotation((1.0, -0.4, 0.3), 0.8)
T_VELO_TO_CAM = np.array([-0.0041, -0.0763, -0.2718])
OXTS = [  # lat, lon, alt, roll, pitch, yaw (radians)
    (49.015003823, 8.434297100, 116.4303, 0.035752, 0.009030, -2.608707),
    (49.015002101, 8.434284317, 116.4389, 0.036110, 0.009420, -2.609801),
    (49.015000377, 8.434271533, 116.4468, 0.035904, 0.008750, -2.611022),
]


def numbers(values) -> str:
    return " ".join(f"{v:.12e}" for v in np.asarray(values, float).ravel())


def make_kitti_drive(root: Path) -> Path:
    """Write ``root/2011_09_26/2011_09_26_drive_0001_sync`` and its calibration; return the drive folder."""
    date = root / "2011_09_26"
    drive = date / "2011_09_26_drive_0001_sync"
    p2 = np.column_stack([K, K @ T2])
    p3 = np.column_stack([K, K @ T3])
    raw_k = np.array([[956.9, 0, 694.0], [0, 952.2, 238.6], [0, 0, 1]])
    date.mkdir(parents=True)
    (date / "calib_cam_to_cam.txt").write_text("\n".join([
        "calib_time: 01-Jan-2026 12:00:00", "corner_dist: 9.950000e-02",
        "S_00: 1.392000e+03 5.120000e+02", f"R_rect_00: {numbers(R_RECT_00)}",
        f"P_rect_00: {numbers(np.column_stack([K, np.zeros(3)]))}",
        "S_02: 1.392000e+03 5.120000e+02", f"K_02: {numbers(raw_k)}",
        f"D_02: {numbers([-0.37, 0.2, 4e-4, 1.6e-3, -0.07])}",
        f"R_02: {numbers(np.eye(3))}", f"T_02: {numbers([0.0599, -0.0014, 0.0046])}",
        f"S_rect_02: {numbers(SIZE)}", f"R_rect_02: {numbers(np.eye(3))}", f"P_rect_02: {numbers(p2)}",
        "S_03: 1.392000e+03 5.120000e+02", f"K_03: {numbers(raw_k)}",
        f"D_03: {numbers([-0.36, 0.19, -5e-4, 3e-4, -0.06])}",
        f"R_03: {numbers(axis_rotation((0, 1, 0), 0.3))}", f"T_03: {numbers([-0.4756, 0.0053, -0.0054])}",
        f"S_rect_03: {numbers(SIZE)}", f"R_rect_03: {numbers(np.eye(3))}", f"P_rect_03: {numbers(p3)}", ""]))
    (date / "calib_imu_to_velo.txt").write_text(
        f"calib_time: 25-May-2012 16:47:16\nR: {numbers(R_IMU_TO_VELO)}\nT: {numbers(T_IMU_TO_VELO)}\n")
    (date / "calib_velo_to_cam.txt").write_text(
        f"calib_time: 15-Mar-2012 11:37:16\nR: {numbers(R_VELO_TO_CAM)}\nT: {numbers(T_VELO_TO_CAM)}\n"
        "delta_f: 0 0\ndelta_c: 0 0\n")
    image = texture(7, 1400)[: SIZE[1], : SIZE[0]]
    stamps = []
    for side in ("image_02", "image_03", "oxts"):
        (drive / side / "data").mkdir(parents=True)
    for frame, packet in enumerate(OXTS):
        name = f"{frame:010d}"
        left = np.roll(image, -25 * frame, axis=1)
        cv2.imwrite(str(drive / "image_02" / "data" / f"{name}.png"), left)
        cv2.imwrite(str(drive / "image_03" / "data" / f"{name}.png"), np.roll(left, -10, axis=1))
        values = list(packet) + [0.1 * k for k in range(24)]
        (drive / "oxts" / "data" / f"{name}.txt").write_text(" ".join(f"{v:.12g}" for v in values) + "\n")
        stamp = START + timedelta(seconds=FRAME_S * frame)
        stamps.append(stamp.strftime("%Y-%m-%d %H:%M:%S.%f") + "445")
    for side in ("image_02", "image_03", "oxts"):
        (drive / side / "timestamps.txt").write_text("\n".join(stamps) + "\n")
    return drive
