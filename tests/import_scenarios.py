"""A survey written the way a vehicle writes it, with the truth kept: raw images, calibration, trajectory.

The vehicle drives through a scene of two textured walls in LV95 (EPSG:2056).
Its IMU trajectory is exported as WGS 84 longitude/latitude with ellipsoidal
heights (EPSG:4979) and navigation yaw/pitch/roll against true north (NED,
x forward, y right, z down), at 20 Hz; the raw left and right cameras (toed in,
different lenses and distortions) sit on the vehicle with a lever arm and a
boresight. Every step from the recorded numbers to the true camera poses is
computed here with its own formulas (grid convergence by finite differences,
rotations written out), independently of ``signmapper_core.importdrive``.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import cv2
import numpy as np
from pyproj import Transformer
from stereo_scenes import Plane, RawCamera, Scene, convergent_rig, relative_pose

ORIGIN = np.array([2600000.0, 1200000.0, 500.0])   # LV95 E, N and a height (m)
GRID_HEADING = 60.0                                # vehicle course, degrees from grid north
SPEED = 8.0                                        # m/s
LEVER_ARM = (1.2, -0.3, -0.9)                      # left camera in the body (x fwd, y right, z down), m
BORESIGHT = (2.0, -3.0, 0.5)                       # camera heading/pitch/roll relative to the body, degrees


def rx(d):
    a = np.radians(d)
    return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])


def ry(d):
    a = np.radians(d)
    return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])


def rz(d):
    a = np.radians(d)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


NED_TO_ENU = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1.0]])
# drive camera (x right, y down, z forward) looking along the body's x axis, level: camera x = body y,
# camera y = body z, camera z = body x (body x fwd, y right, z down)
CAMERA_IN_BODY = np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0.0]])


def boresight_rotation(heading, pitch, roll):
    """Camera -> body of a camera turned by heading (to the right), pitch (up) and roll (clockwise from behind)."""
    # in the body (x fwd, y right, z down): heading turns about +z (down) towards +y, pitch about -y
    return rz(heading) @ ry(pitch) @ CAMERA_IN_BODY @ rz(roll)


def grid_convergence(lon, lat):
    """Grid azimuth of true north in LV95 at a point (finite differences, degrees)."""
    t = Transformer.from_crs("EPSG:4326", "EPSG:2056", always_xy=True)
    e0, n0 = t.transform(lon, lat)
    e1, n1 = t.transform(lon, lat + 1e-6)
    return np.degrees(np.arctan2(e1 - e0, n1 - n0))


@dataclass
class Survey:
    folder: Path
    left: Path
    right: Path
    calibration: Path
    trajectory: Path
    image_times: Path
    scene: Scene
    camera_centres: list          # true raw left camera centres, LV95 (E, N, H)
    camera_rotations: list        # true raw left camera -> (E, N, Up) rotations
    k1: np.ndarray = None


def body_attitude(t):
    """Small, smooth roll and pitch (degrees) and a slight yaw rate of the vehicle at time t."""
    return 1.5 * np.sin(0.9 * t), -0.8 + 0.6 * np.cos(1.3 * t), 0.4 * t


def make_survey(folder: Path, pairs: int = 3, size=(480, 360), image_suffix=".png") -> Survey:
    folder.mkdir(parents=True, exist_ok=True)
    to_wgs = Transformer.from_crs("EPSG:2056", "EPSG:4979", always_xy=True)
    direction = np.array([np.sin(np.radians(GRID_HEADING)), np.cos(np.radians(GRID_HEADING)), 0.0])
    # walls in the local frame (E, N, Up relative to ORIGIN): one across the road 14 m ahead, one along its right
    ahead = direction * 14.0
    right = np.array([direction[1], -direction[0], 0.0])
    scene = Scene([
        Plane(tuple(direction), float(direction @ ahead), tuple(right), (0.0, 0.0, 1.0), seed=3),
        Plane(tuple(-right), float(-right @ (right * 4.5)), tuple(direction), (0.0, 0.0, 1.0), seed=4),
    ])
    rig_left, rig_right = convergent_rig(size=size, baseline=0.5, toe_in_deg=1.0)
    r_lr, t_lr = relative_pose(rig_left, rig_right)          # right camera in the left camera's frame
    # trajectory at 20 Hz from -0.5 s to (pairs + 0.5) * 0.25 s
    epochs = np.arange(-0.5, pairs * 0.25 + 0.5, 0.05)
    rows = []
    for t in epochs:
        pos = ORIGIN + direction * SPEED * t + np.array([0, 0, 0.02 * np.sin(t)])
        lon, lat, h = to_wgs.transform(pos[0], pos[1], pos[2])
        roll, pitch, yaw_offset = body_attitude(t)
        true_yaw = GRID_HEADING + yaw_offset - grid_convergence(lon, lat)  # grid azimuth = true + convergence
        rows.append((t, lon, lat, h, true_yaw, pitch, roll))
    trajectory = folder / "trajectory.csv"
    with open(trajectory, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["time", "longitude", "latitude", "height", "yaw", "pitch", "roll"])
        for t, lon, lat, h, yaw, pitch, roll in rows:
            writer.writerow([f"{t + 1000:.3f}", f"{lon:.10f}", f"{lat:.10f}", f"{h:.4f}", f"{yaw:.6f}",
                             f"{pitch:.6f}", f"{roll:.6f}"])
    # images at 0.25 s steps (0.125 s after an epoch: interpolation matters)
    left_dir, right_dir = folder / "left", folder / "right"
    left_dir.mkdir(exist_ok=True)
    right_dir.mkdir(exist_ok=True)
    times_file = folder / "image_times.csv"
    centres, rotations = [], []
    with open(times_file, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["id", "time"])
        for i in range(pairs):
            t = 0.125 + 0.25 * i
            pos = ORIGIN + direction * SPEED * t + np.array([0, 0, 0.02 * np.sin(t)])
            roll, pitch, yaw_offset = body_attitude(t)
            body_to_grid = NED_TO_ENU @ rz(GRID_HEADING + yaw_offset) @ ry(pitch) @ rx(roll)
            camera_to_grid = body_to_grid @ boresight_rotation(*BORESIGHT)
            centre = pos + body_to_grid @ np.array(LEVER_ARM)
            centres.append(centre)
            rotations.append(camera_to_grid)
            left = RawCamera(rig_left.k, rig_left.d, centre - ORIGIN, camera_to_grid, size)
            right_rotation = camera_to_grid @ r_lr.T
            right_centre = centre - ORIGIN - right_rotation @ t_lr
            right = RawCamera(rig_right.k, rig_right.d, right_centre, right_rotation, size)
            cv2.imwrite(str(left_dir / f"img_{i:03d}{image_suffix}"), scene.render(left))
            cv2.imwrite(str(right_dir / f"img_{i:03d}{image_suffix}"), scene.render(right))
            writer.writerow([f"img_{i:03d}", f"{t + 1000:.4f}"])
    calibration = folder / "stereo.yml"
    storage = cv2.FileStorage(str(calibration), cv2.FILE_STORAGE_WRITE)
    for key, value in (("K1", rig_left.k), ("D1", rig_left.d.reshape(1, -1)), ("K2", rig_right.k),
                       ("D2", rig_right.d.reshape(1, -1)), ("R", r_lr), ("T", t_lr.reshape(3, 1))):
        storage.write(key, value)
    storage.write("image_width", size[0])
    storage.write("image_height", size[1])
    storage.release()
    return Survey(folder, left_dir, right_dir, calibration, trajectory, times_file, scene, centres, rotations,
                  rig_left.k)
