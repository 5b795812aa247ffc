"""KITTI raw drives (``<date>_drive_<nnnn>_sync`` or ``_extract``) as a named preset: the worked example.

What KITTI's development kit says, turned into a :class:`DriveSource`:

- images: ``image_02/data`` (left colour) and ``image_03/data`` (right), or 00/01 (grey); the rectified
  ``_sync`` images (1242x375) or the raw ``_extract`` ones (1392x512) - the size picks the calibration;
- calibration: ``calib_cam_to_cam.txt`` (in the drive folder or its date folder above);
- poses: one OXTS packet per frame (``oxts/data``): latitude, longitude, altitude, then roll, pitch,
  yaw in radians of the IMU (x forward, y left, z up; yaw counter-clockwise from east), i.e. the
  ``enu_ypr`` convention against true north. The altitude is taken as EGM96 height (EPSG:4326+5773):
  the drive's OXTS altitudes are about 116 m in Karlsruhe, where the ground lies about 115 m above
  sea level and the geoid 48 m above the ellipsoid;
- camera mount: ``calib_imu_to_velo.txt`` and ``calib_velo_to_cam.txt`` chain the IMU to camera 0,
  ``R_rect_00`` and ``P_rect_0x`` to the rectified left camera (``R_0x``/``T_0x`` to the raw one);
- times: ``image_02/timestamps.txt``; drive.json gets the first as ``start_time`` and the
  camera's height above the road, 1.65 m (KITTI's sensor set-up), as ``vehicle.camera_height_m``.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np

from ..errors import ImportInputError
from .calibration import StereoCalibration, kitti_calibrations
from .camera_poses import Orientation
from .image_pairs import list_pairs
from .importer import DriveSource
from .kitti_files import read_key_values, read_oxts, read_timestamps
from .mount import Mount
from .pose_table import PoseTable

CAMERAS = {"colour": ("02", "03"), "grey": ("00", "01")}
INPUT_CRS = "EPSG:4326+5773"   # WGS 84 with EGM96 heights (see module)
CAMERA_HEIGHT_M = 1.65
DRIVE_NAME = re.compile(r"\d{4}_\d{2}_\d{2}_drive_\d{4}_(sync|extract)")
DRIVE_PARTS = ("image_00", "image_01", "image_02", "image_03", "oxts")
SEARCH_DEPTH = 3    # levels below a given folder searched for drive folders (download folder/date folder/drive)
LISTED_DRIVES = 5   # drive folders named in a message


def is_kitti_drive(folder) -> bool:
    """Whether ``folder`` looks like a KITTI raw drive folder: it holds a camera's images or the OXTS poses."""
    return any((Path(folder) / part).is_dir() for part in DRIVE_PARTS)


def drive_folders_in(folder) -> list[Path]:
    """The KITTI raw drive folders (``<date>_drive_<nnnn>_sync`` or ``_extract``) at most ``SEARCH_DEPTH`` levels
    below ``folder`` (a date, base or download folder), sorted; drive folders are not searched inside."""
    found = []
    top = len(Path(folder).parts)
    for here, folders, _files in os.walk(folder):
        depth = len(Path(here).parts) - top
        drives = [name for name in folders if DRIVE_NAME.fullmatch(name)]
        found += [Path(here) / name for name in drives]
        folders[:] = [] if depth + 1 >= SEARCH_DEPTH else sorted(set(folders) - set(drives))
    return sorted(found)


def _not_a_drive(folder: Path) -> ImportInputError:
    """The error for a folder that is no drive folder, naming the drive folders found inside (or above) it."""
    what = f"is not a KITTI raw drive folder (no {', '.join(p + '/' for p in DRIVE_PARTS[2:])})"
    if is_kitti_drive(folder.parent):
        return ImportInputError(folder, f"{what}; it lies in the drive folder {folder.parent}: give that one")
    drives = drive_folders_in(folder)
    if not drives:
        return ImportInputError(folder, f"{what}, and no drive folder (<date>_drive_<nnnn>_sync or _extract) is in "
                                f"it or {SEARCH_DEPTH - 1} levels below; give a drive folder such as "
                                "2011_09_26/2011_09_26_drive_0001_sync")
    names = [str(d.relative_to(folder)) for d in drives[:LISTED_DRIVES]]
    more = f" and {len(drives) - LISTED_DRIVES} more" if len(drives) > LISTED_DRIVES else ""
    which = "the drive folder" if len(drives) == 1 else f"{len(drives)} drive folders:"
    return ImportInputError(folder, f"{what}; it holds {which} {', '.join(names)}{more}; give "
                            f"{'it' if len(drives) == 1 else 'one of them'} as the KITTI drive folder")


def find_calibration_file(folder: Path, name: str) -> Path:
    """``name`` in the drive folder or the date folder above it."""
    for candidate in (folder / name, folder.parent / name):
        if candidate.is_file():
            return candidate
    raise ImportInputError(folder, f"no {name} in the drive folder or in {folder.parent}; KITTI keeps the "
                           "calibration files in the date folder (e.g. 2011_09_26/)")


def _rigid(path: Path) -> tuple[np.ndarray, np.ndarray]:
    values = read_key_values(path)
    for key, size in (("R", 9), ("T", 3)):
        if key not in values or values[key].size != size:
            raise ImportInputError(path, f"must hold {key} with {size} numbers", field=key)
    return values["R"].reshape(3, 3), values["T"].reshape(3)


def imu_to_camera0(folder: Path) -> tuple[np.ndarray, np.ndarray]:
    """(A, b) with X_cam0 = A X_imu + b (camera 0 unrectified), from the IMU->velodyne->camera chain."""
    r_vi, t_vi = _rigid(find_calibration_file(folder, "calib_imu_to_velo.txt"))
    r_cv, t_cv = _rigid(find_calibration_file(folder, "calib_velo_to_cam.txt"))
    return r_cv @ r_vi, r_cv @ t_vi + t_cv


def camera_mount(folder: Path, calibration: StereoCalibration, left: str) -> Mount:
    """Mount of the left camera (rectified or raw, as ``calibration`` is) on the IMU."""
    a0, b0 = imu_to_camera0(folder)
    values = read_key_values(calibration.source)
    if calibration.rectified:
        p = values[f"P_rect_{left}"].reshape(3, 4)
        rect = values["R_rect_00"].reshape(3, 3)
        a, b = rect @ a0, rect @ b0 + np.linalg.solve(p[:, :3], p[:, 3])
    else:
        r, t = values[f"R_{left}"].reshape(3, 3), values[f"T_{left}"].reshape(3)
        a, b = r @ a0, r @ b0 + t
    return Mount(rotation=a.T, lever_arm_m=-a.T @ b)


def oxts_table(folder: Path, ids: list[str]) -> PoseTable:
    """The OXTS packets of the frames ``ids`` as a per-image pose table (lon, lat, alt; yaw, pitch, roll)."""
    data = folder / "oxts" / "data"
    if not data.is_dir():
        raise ImportInputError(folder, "no oxts/data folder: the drive's GNSS/INS poses are missing")
    files, rows = [], []
    for frame in ids:
        path = data / f"{frame}.txt"
        if not path.is_file():
            raise ImportInputError(path, f"the poses do not cover frame {frame}: its OXTS packet is missing")
        files.append(path)
        rows.append(read_oxts(path))
    packets = np.array(rows)
    return PoseTable(data, np.arange(1, len(ids) + 1), list(ids), None, packets[:, [1, 0, 2]], packets[:, [5, 4, 3]],
                     ("yaw", "pitch", "roll"), files)


def kitti_source(folder, cameras: str = "colour") -> DriveSource:
    """A KITTI raw drive folder as a drive source (see module)."""
    folder = Path(folder)
    if not folder.is_dir():
        raise ImportInputError(folder, "KITTI drive folder does not exist")
    if not is_kitti_drive(folder):
        raise _not_a_drive(folder)
    if cameras not in CAMERAS:
        raise ValueError(f"cameras must be one of {tuple(CAMERAS)}, not {cameras!r}")
    left, right = CAMERAS[cameras]
    pairs = list_pairs(folder / f"image_{left}" / "data", folder / f"image_{right}" / "data")
    calibration_file = find_calibration_file(folder, "calib_cam_to_cam.txt")
    calibrations = kitti_calibrations(calibration_file, left, right)
    stamps_file = folder / f"image_{left}" / "timestamps.txt"
    stamps = read_timestamps(stamps_file)
    times = {}
    for pair in pairs:
        if not pair.id.isdigit() or int(pair.id) >= len(stamps):
            raise ImportInputError(stamps_file, f"has {len(stamps)} times, none for frame {pair.id}")
        times[pair.id] = (stamps[int(pair.id)] - stamps[0]).total_seconds()
    return DriveSource(
        label=f"KITTI raw {folder.name} (cameras {left}/{right})",
        pairs=pairs, calibrations=calibrations, poses=oxts_table(folder, [p.id for p in pairs]), per_image=True,
        orientation=Orientation("enu_ypr", "rad", "true"), input_crs=INPUT_CRS,
        mount=lambda calibration: camera_mount(folder, calibration, left),
        image_times=times, image_times_source=stamps_file,
        metadata={"start_time": stamps[0].isoformat(), "vehicle": {"camera_height_m": CAMERA_HEIGHT_M}})


def utm_crs(source: DriveSource) -> str:
    """The UTM zone of the drive's first position with EGM96 heights (the default output CRS of the preset)."""
    from pyproj.aoi import AreaOfInterest
    from pyproj.database import query_utm_crs_info

    lon, lat = (float(v) for v in source.poses.xyz[0, :2])
    found = query_utm_crs_info(datum_name="WGS 84", area_of_interest=AreaOfInterest(lon, lat, lon, lat))
    if not found:
        raise ImportInputError(source.poses.where(0)[0], f"no UTM zone for longitude {lon:g}, latitude {lat:g}")
    return f"{found[0].auth_name}:{found[0].code}+5773"
