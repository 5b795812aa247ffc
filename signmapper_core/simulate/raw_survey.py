"""A drive turned back into what a survey vehicle records: raw stereo images, a calibration, a trajectory.

For trying and testing the importer on imagery with signs and a ground truth.
Each normal image of a drive is resampled into a raw camera turned a little
about its own centre (toe-in, roll) with its own lens and distortion; a pure
turn about the projection centre is a homography, so the raw images are what
such a camera would have recorded. The vehicle's navigation system is an IMU
(NED yaw/pitch/roll against true north, WGS 84 with ellipsoidal heights,
EPSG:4979) with the left camera on a lever arm and boresight; its trajectory
runs at ``rate_hz`` with epochs offset from the image times, so the importer
interpolates. ``truth.csv`` is copied as it is (the drive's CRS).

    python -m signmapper_core.simulate.raw_survey DRIVE OUT
"""

from __future__ import annotations

import argparse
import csv
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..drive.reader import open_drive
from ..drive.writer import write_image
from ..geometry import camera_rotation, rot_z
from ..importdrive.attitude import convention, rot_y
from ..importdrive.crs_steps import CrsSteps
from ..importdrive.interpolate import slerp
from ..importdrive.mount import Mount

NAVIGATION_CRS = "EPSG:4979"


@dataclass(frozen=True)
class RawRig:
    """How the raw cameras differ from the normal ones, and how they sit on the IMU."""

    toe_in_deg: float = 1.0                      # each camera turned inwards
    roll_deg: tuple[float, float] = (0.3, -0.2)
    focal_scale: float = 1.12                    # raw lenses a little longer: their view lies inside the normal one
    distortion_left: tuple = (-0.12, 0.05, 0.0008, -0.0004, 0.0)
    distortion_right: tuple = (-0.10, 0.04, -0.0006, 0.0005, 0.0)
    principal_offset_px: tuple[float, float] = (3.5, -2.0)
    lever_arm_m: tuple[float, float, float] = (1.2, -0.3, -0.9)    # IMU body: x forward, y right, z down
    boresight_deg: tuple[float, float, float] = (1.0, -2.0, 0.5)
    rate_hz: float = 50.0
    epoch_offset_s: float = 0.007


@dataclass(frozen=True)
class RawSurvey:
    left: Path
    right: Path
    calibration: Path
    trajectory: Path
    image_times: Path
    truth: Path | None
    rig: RawRig


def _raw_cameras(camera, rig: RawRig):
    """(K, D, raw -> normal rotation) of the left and right raw cameras."""
    k = np.array([[camera.fx * rig.focal_scale, 0, camera.cx + rig.principal_offset_px[0]],
                  [0, camera.fy * rig.focal_scale, camera.cy + rig.principal_offset_px[1]], [0, 0, 1.0]])
    k_right = k.copy()
    k_right[0, 2] -= 2 * rig.principal_offset_px[0]
    turn_left = rot_y(np.radians(rig.toe_in_deg)) @ rot_z(np.radians(rig.roll_deg[0]))
    turn_right = rot_y(np.radians(-rig.toe_in_deg)) @ rot_z(np.radians(rig.roll_deg[1]))
    return ((k, np.array(rig.distortion_left), turn_left), (k_right, np.array(rig.distortion_right), turn_right))


def _resampling_maps(camera, k, d, raw_to_normal):
    """Maps that sample a normal image at the ray of every raw pixel."""
    import cv2

    u, v = np.meshgrid(np.arange(camera.width, dtype=np.float32), np.arange(camera.height, dtype=np.float32))
    rays = cv2.undistortPoints(np.stack([u.ravel(), v.ravel()], axis=1).reshape(-1, 1, 2), k, d).reshape(-1, 2)
    normal = np.column_stack([rays, np.ones(len(rays))]) @ raw_to_normal.T
    x = camera.cx + camera.fx * normal[:, 0] / normal[:, 2]
    y = camera.cy + camera.fy * normal[:, 1] / normal[:, 2]
    shape = (camera.height, camera.width)
    return x.reshape(shape).astype(np.float32), y.reshape(shape).astype(np.float32)


def _write_calibration(path: Path, camera, left, right) -> None:
    import cv2

    (k1, d1, turn_left), (k2, d2, turn_right) = left, right
    # X_right_normal = X_left_normal - (B, 0, 0); X_normal = turn X_raw
    rotation = turn_right.T @ turn_left
    translation = -turn_right.T @ np.array([camera.baseline_m, 0.0, 0.0])
    storage = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    for key, value in (("K1", k1), ("D1", d1.reshape(1, -1)), ("K2", k2), ("D2", d2.reshape(1, -1)),
                       ("R", rotation), ("T", translation.reshape(3, 1))):
        storage.write(key, value)
    storage.write("image_width", camera.width)
    storage.write("image_height", camera.height)
    storage.release()


def _body_poses(drive, turn_left: np.ndarray, rig: RawRig) -> tuple[np.ndarray, np.ndarray]:
    """IMU centres (grid) and IMU -> grid rotations at the pairs, from the drive's left normal poses."""
    mount = Mount.from_boresight(convention("ned_ypr"), rig.lever_arm_m, rig.boresight_deg)
    centres, rotations = [], []
    for record in drive.pairs:
        pose = record.pose
        raw_to_grid = camera_rotation(pose.heading, pose.pitch, pose.roll) @ turn_left
        body_to_grid = raw_to_grid @ mount.rotation.T
        rotations.append(body_to_grid)
        centres.append(pose.centre - body_to_grid @ mount.lever_arm_m)
    return np.array(centres), np.array(rotations)


def _trajectory_rows(drive, centres, rotations, rig: RawRig):
    """Epochs every 1/``rate_hz`` from just before the first pair to just after the last, offset from the image
    times; positions linear and turns along the shortest way between the pairs' body poses (beyond the first and
    last pair: positions extrapolated, turns held)."""
    times = np.array([r.time for r in drive.pairs])
    step = 1.0 / rig.rate_hz
    first = times[0] - step + rig.epoch_offset_s
    epochs = first + step * np.arange(int(np.ceil((times[-1] - first) / step)) + 1)
    rows = []
    for t in epochs:
        j = int(np.clip(np.searchsorted(times, t) - 1, 0, len(times) - 2))
        s = (t - times[j]) / (times[j + 1] - times[j])
        rotation = slerp(rotations[j], rotations[j + 1], float(np.clip(s, 0.0, 1.0)))
        rows.append((t, centres[j] + s * (centres[j + 1] - centres[j]), rotation))
    return rows


def write_raw_survey(drive_path, out_dir, rig: RawRig | None = None, jpeg_quality: int = 95) -> RawSurvey:
    """Write the raw survey of a drive (see module); ``out_dir`` must not exist or be empty."""
    import cv2


    rig = rig or RawRig()
    drive = open_drive(drive_path)
    if len(drive.pairs) < 2:
        raise ValueError(f"{drive_path}: a trajectory needs at least two pairs")
    out = Path(out_dir)
    if out.exists() and any(out.iterdir()):
        raise FileExistsError(f"{out}: exists and is not empty")
    camera = drive.camera
    left_cam, right_cam = _raw_cameras(camera, rig)
    maps = [_resampling_maps(camera, k, d, turn) for k, d, turn in (left_cam, right_cam)]
    for record in drive.pairs:
        for side, image, (mx, my) in (("left", drive.load_left(record), maps[0]),
                                      ("right", drive.load_right(record), maps[1])):
            if image is None:
                raise ValueError(f"{drive_path}: pair {record.id} has no right image")
            raw = cv2.remap(image, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
            write_image(out / side / f"{record.id}.jpg", raw, jpeg_quality)
    survey = RawSurvey(out / "left", out / "right", out / "stereo.yml", out / "trajectory.csv",
                       out / "image_times.csv", None, rig)
    _write_calibration(survey.calibration, camera, left_cam, right_cam)
    centres, rotations = _body_poses(drive, left_cam[2], rig)
    rows = _trajectory_rows(drive, centres, rotations, rig)
    grid = np.array([c for _, c, _ in rows])
    from pyproj import Transformer

    to_wgs = Transformer.from_crs(drive.crs, NAVIGATION_CRS, always_xy=True)
    lon, lat, _ = to_wgs.transform(grid[:, 0], grid[:, 1], grid[:, 2])
    # angles against true north: turn the grid frame back by the grid azimuth of true north
    north = CrsSteps(NAVIGATION_CRS, drive.crs).north_azimuths(np.column_stack([lon, lat, grid[:, 2]]), "true")
    ned = convention("ned_ypr")
    with open(survey.trajectory, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(["time", "longitude", "latitude", "height", "yaw", "pitch", "roll"])
        for (t, centre, rotation), x, y, a in zip(rows, lon, lat, north):
            yaw, pitch, roll = ned.angles(rot_z(np.radians(a)) @ rotation)
            writer.writerow([f"{t:.4f}", f"{x:.10f}", f"{y:.10f}", f"{centre[2]:.4f}", f"{yaw:.7f}",
                             f"{pitch:.7f}", f"{roll:.7f}"])
    with open(survey.image_times, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(["id", "time"])
        writer.writerows([r.id, f"{r.time:.4f}"] for r in drive.pairs)
    truth = None
    if (drive.root / "truth.csv").is_file():
        truth = shutil.copyfile(drive.root / "truth.csv", out / "truth.csv")
    return RawSurvey(survey.left, survey.right, survey.calibration, survey.trajectory, survey.image_times,
                     truth, rig)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m signmapper_core.simulate.raw_survey",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("drive", type=Path, help="a drive folder with left and right images")
    parser.add_argument("out", type=Path, help="folder for the raw survey (must not exist, or be empty)")
    args = parser.parse_args(argv)
    survey = write_raw_survey(args.drive, args.out)
    rig = survey.rig
    print(f"{args.out}: raw images in left/ and right/, {survey.calibration.name}, {survey.trajectory.name} "
          f"(EPSG:4979, ned_ypr degrees, {rig.rate_hz:g} Hz), {survey.image_times.name}; import with lever arm "
          f"{' '.join(f'{v:g}' for v in rig.lever_arm_m)} and boresight "
          f"{' '.join(f'{v:g}' for v in rig.boresight_deg)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
