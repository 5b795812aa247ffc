"""Build a drive folder from a survey's images, calibration and poses: the import every front end runs.

A :class:`DriveSource` says what the survey holds (image pairs, candidate
calibrations, the pose table and how to read it, the camera's mount); the
generic reader (``generic.py``) and the KITTI preset (``kitti.py``) make one.
:func:`import_drive` then checks everything it can before touching a pixel
(image sizes against the calibration, poses against the image times, angle
units, CRSs), rectifies the first pair and measures its rows
(``epipolar``), converts the rest on ``workers`` threads (OpenCV releases the
GIL), and writes the drive atomically (``atomic_folder``): a failure or a
cancel leaves nothing behind. The result is opened with the drive reader
before it takes its name, so what is written is what the reader accepts.
"""

from __future__ import annotations

import shutil
import time
from collections import deque
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Optional, Union

import numpy as np

from ..drive.atomic_folder import writing_folder
from ..drive.images import IMAGE_SUFFIXES, image_header, read_image
from ..drive.reader import open_drive
from ..drive.writer import write_drive_json, write_image, write_poses_csv
from ..errors import ImportInputError
from ..geometry import Camera, Pose
from ..progress import CancelCheck, ProgressCallback, WarnCallback, check_cancelled, report, send_warning
from .calibration import StereoCalibration, choose_calibration
from .camera_poses import Orientation, body_poses, drive_poses
from .crs_steps import CrsSteps
from .epipolar import EpipolarCheck, draw_check, match_features
from .image_pairs import ImagePair, pair_size
from .interpolate import MAX_GAP_S, check_increasing, interpolate
from .mount import Mount
from .pose_table import PoseTable
from .rectify import Rectifier

IMAGE_FORMATS = ("auto", "jpg", "png")
SOFTWARE = "Sign Mapper importdrive"


@dataclass
class DriveSource:
    """What a survey holds, read but not yet converted."""

    label: str                                    # what was imported, in words
    pairs: list[ImagePair]
    calibrations: list[StereoCalibration]         # candidates; the one for the images' size is used
    poses: PoseTable
    per_image: bool                               # one row per image (by id) or a trajectory (by time)
    orientation: Orientation
    input_crs: str
    mount: Union[Mount, Callable[[StereoCalibration], Mount]]
    image_times: Optional[dict[str, float]] = None  # id -> seconds (trajectories; optional per image)
    image_times_source: Optional[Path] = None
    metadata: dict = field(default_factory=dict)    # extra drive.json keys (start_time, vehicle, ...)


@dataclass(frozen=True)
class ImportOptions:
    output_crs: str = "EPSG:2056"
    image_format: str = "auto"         # auto: keep rectified inputs as they are, else JPEG; jpg; png
    jpeg_quality: int = 95
    max_vertical_disparity_px: float = 0.5
    check_image: Optional[Path] = None  # PNG of the first pair with epipolar lines
    workers: int = 2
    max_gap_s: float = MAX_GAP_S


@dataclass
class ImportSummary:
    out_dir: Path
    pairs: int
    camera: Camera
    resampled: bool                   # raw pairs were undistorted and rectified
    check: EpipolarCheck
    warnings: list[str]
    seconds: float
    crs: str


@dataclass
class ImportPlan:
    """Everything an import decides before it touches a pixel."""

    size: tuple[int, int]
    calibration: StereoCalibration
    rectifier: Rectifier
    mount: Mount
    pairs: list[ImagePair]             # in time order
    times: list[float]
    poses: list[Pose]                  # of the left normal images
    suffixes: list[Optional[str]]      # per pair: None = copy the files, else the suffix to write


def plan_import(source: DriveSource, options: ImportOptions, note: Callable[[str], None] = lambda _m: None,
                all_headers: bool = True) -> ImportPlan:
    """Check the inputs against each other and compute the poses (see module); no pixel is read.

    ``all_headers``: check every image's size (else the first image's only, for a quick check in a dialog).
    """
    if options.image_format not in IMAGE_FORMATS:
        raise ValueError(f"image format must be one of {IMAGE_FORMATS}, not {options.image_format!r}")
    first = source.pairs[0].left
    size = pair_size(source.pairs) if all_headers else image_header(first, check_suffix=False).size
    calibration = choose_calibration(source.calibrations, size, first)
    if calibration.size is None:
        note(f"{calibration.source}: the calibration does not state its image size; taken as the images' "
             f"{size[0]}x{size[1]}")
    rectifier = Rectifier(calibration, size)
    mount = source.mount(calibration) if callable(source.mount) else source.mount
    steps = CrsSteps(source.input_crs, options.output_crs)
    for message in steps.warnings:
        note(message)
    ordered, times, poses = _camera_poses(source, steps, mount, rectifier, options, note)
    return ImportPlan(size, calibration, rectifier, mount, ordered, times, poses,
                      _output_suffixes(ordered, rectifier, options.image_format))


def import_drive(out_dir, source: DriveSource, options: Optional[ImportOptions] = None,
                 progress: Optional[ProgressCallback] = None, is_cancelled: Optional[CancelCheck] = None,
                 warn: Optional[WarnCallback] = None) -> ImportSummary:
    """Write ``source`` as a drive folder ``out_dir`` (new or empty); see module."""
    started = time.perf_counter()
    options = options or ImportOptions()
    warnings: list[str] = []

    def note(message: str) -> None:
        warnings.append(message)
        send_warning(warn, message)

    report(progress, 0.0, "reading image headers, calibration and poses")
    plan = plan_import(source, options, note)
    check_cancelled(is_cancelled, "drive import")
    with writing_folder(out_dir) as tmp:
        check, first_pair = _convert_pairs(tmp, plan, options, progress, is_cancelled)
        if not check.enough:
            note(f"only {check.matches} features matched in the first pair ({plan.pairs[0].id}): the rows could "
                 "not be checked; look at the pairs before mapping")
        metadata = {**source.metadata, "software": SOFTWARE,
                    "import": _import_record(source, plan, options, check)}
        write_drive_json(tmp, options.output_crs, plan.rectifier.camera, **metadata)
        write_poses_csv(tmp, [(pair.id, t, pose) for pair, t, pose in zip(plan.pairs, plan.times, plan.poses)])
        report(progress, 0.97, "validating the written drive")
        written = open_drive(tmp, is_cancelled=is_cancelled)
        for message in written.warnings:
            note(message.replace(str(tmp), str(out_dir)))
        if options.check_image is not None:
            _write_check_image(options.check_image, check, first_pair)
    report(progress, 1.0, f"{len(plan.pairs)} pairs written")
    return ImportSummary(Path(out_dir), len(plan.pairs), plan.rectifier.camera, plan.rectifier.resamples, check,
                         warnings, time.perf_counter() - started, options.output_crs)


# -- poses --------------------------------------------------------------------------------------------------------

def _rows_for_pairs(source: DriveSource) -> list[int]:
    """Row of the per-image table for every pair (by id, file name or stem); a pair without one is an error."""
    table = source.poses
    row_of = {name: i for i, name in enumerate(table.ids)}
    rows = []
    for pair in source.pairs:
        row = next((row_of[n] for n in (pair.id, pair.left.name, pair.left.stem) if n in row_of), None)
        if row is None:
            raise ImportInputError(table.path, f"the poses do not cover image {pair.id!r} ({pair.left.name}): no row "
                                   "has its id", field="id")
        rows.append(row)
    return rows


def _camera_poses(source: DriveSource, steps: CrsSteps, mount: Mount, rectifier: Rectifier, options: ImportOptions,
                  note) -> tuple[list[ImagePair], list[float], list[Pose]]:
    """Pairs in time order, their times and the left normal image's poses."""
    table = source.poses
    if source.per_image:
        rows = _rows_for_pairs(source)
        unused = len(table) - len(set(rows))
        if unused:
            note(f"{table.path}: {unused} row(s) name no image pair and are not used")
        if table.times is not None:
            times = table.times[rows]
        elif source.image_times is not None:
            times = np.array([_image_time(source, pair) for pair in source.pairs])
        else:
            note(f"{table.path}: no time column; the pairs keep the table's order and get its row numbers as times")
            times = np.array(rows, dtype=float)
        centres, rotations = body_poses(table.subset(rows), source.orientation, steps, note,
                                        np.argsort(times, kind="stable"))
    else:
        if table.times is None:
            raise ImportInputError(table.path, "a trajectory needs a time column", line=1, field="time")
        check_increasing(table.times, table.path, table.lines)
        times = np.array([_image_time(source, pair) for pair in source.pairs])
        needed = _bracketing_rows(table.times, times)
        sub = table.subset(needed)
        epoch_centres, epoch_rotations = body_poses(sub, source.orientation, steps, note)
        where = f"image times from {source.image_times_source}" if source.image_times_source else "image times"
        centres, rotations = interpolate(sub.times, epoch_centres, epoch_rotations, times,
                                         [p.id for p in source.pairs], table.path, where, options.max_gap_s)
    if source.image_times is not None:
        _note_unused_image_times(source, note)
    order = np.argsort(times, kind="stable")
    times = times[order]
    same = np.flatnonzero(np.diff(times) <= 0)
    if same.size:
        a, b = source.pairs[order[same[0]]], source.pairs[order[same[0] + 1]]
        raise ImportInputError(source.image_times_source or table.path, f"images {a.id!r} and {b.id!r} have the same "
                               f"time {times[same[0]]:.6f} s; every pair needs its own time", field="time")
    poses = drive_poses(centres[order], rotations[order], mount, rectifier.rotation)
    return [source.pairs[i] for i in order], [float(t) for t in times], poses


def _note_unused_image_times(source: DriveSource, note) -> None:
    """Tell ``note`` of image times that name no image: a row for a file that does not exist (renamed, left
    out) would otherwise be ignored without a word."""
    names = {name for pair in source.pairs for name in (pair.id, pair.left.name, pair.left.stem)}
    unused = [key for key in source.image_times if key not in names]
    if unused:
        where = source.image_times_source or "the image times"
        note(f"{where}: {len(unused)} row(s) name no image found among the images and are not used (first: id "
             f"{unused[0]!r})")


def _image_time(source: DriveSource, pair: ImagePair) -> float:
    times = source.image_times or {}
    for name in (pair.id, pair.left.name, pair.left.stem):
        if name in times:
            return float(times[name])
    where = source.image_times_source or "the image times"
    raise ImportInputError(where, f"no time for image {pair.id!r} ({pair.left.name})", field="id")


def _bracketing_rows(epochs: np.ndarray, times: np.ndarray) -> np.ndarray:
    """Indices of the trajectory epochs on either side of every image time (all that interpolation reads)."""
    right = np.clip(np.searchsorted(epochs, times, side="left"), 0, len(epochs) - 1)
    left = np.clip(right - 1, 0, len(epochs) - 1)
    return np.unique(np.concatenate([left, right, [0, len(epochs) - 1]]))


# -- pixels -------------------------------------------------------------------------------------------------------

def _output_suffixes(pairs: list[ImagePair], rectifier: Rectifier, image_format: str) -> list[Optional[str]]:
    """Per pair: None = copy the files as they are (normal images in a drive format), else the suffix to write."""
    if image_format in ("jpg", "png"):
        return [f".{image_format}"] * len(pairs)
    if rectifier.resamples:
        return [".jpg"] * len(pairs)
    return [None if p.left.suffix in IMAGE_SUFFIXES and p.right.suffix in IMAGE_SUFFIXES else ".jpg" for p in pairs]


def _convert_one(tmp: Path, pair: ImagePair, suffix: Optional[str], rectifier: Rectifier, size, quality: int,
                 images=None) -> None:
    if suffix is None:
        for side, path in (("left", pair.left), ("right", pair.right)):
            image_header(path)  # the content must be what the suffix says, as the drive reader wants
            (tmp / side).mkdir(exist_ok=True)
            shutil.copyfile(path, tmp / side / f"{pair.id}{path.suffix}")
        return
    left, right = images if images is not None else rectifier.rectify(read_image(pair.left, size),
                                                                      read_image(pair.right, size))
    write_image(tmp / "left" / f"{pair.id}{suffix}", left, quality)
    write_image(tmp / "right" / f"{pair.id}{suffix}", right, quality)


def _convert_pairs(tmp: Path, plan: ImportPlan, options: ImportOptions, progress,
                   is_cancelled) -> tuple[EpipolarCheck, tuple]:
    """Rectify and write every pair; the first one is checked (rows line up) before the others are touched.

    Returns the check and the first pair's normal images.
    """
    pairs, suffixes, rectifier, size = plan.pairs, plan.suffixes, plan.rectifier, plan.size
    first = pairs[0]
    normal = rectifier.rectify(read_image(first.left, size), read_image(first.right, size))
    check = match_features(*normal)
    if check.enough and check.mean_abs_dy >= options.max_vertical_disparity_px:
        raise ImportInputError(
            plan.calibration.source, f"the rows of the first pair ({first.id}) do not line up after rectification: "
            f"{check.text()}, at most {options.max_vertical_disparity_px:g} px allowed; the calibration does not "
            "fit these images (wrong file, cameras swapped, or the rig moved since it was calibrated)")
    _convert_one(tmp, first, suffixes[0], rectifier, size, options.jpeg_quality, normal)
    total = len(pairs)

    def step(done: int) -> None:
        report(progress, 0.05 + 0.9 * done / total, f"pair {done} of {total}")

    step(1)
    workers = max(1, int(options.workers))
    pool = ThreadPoolExecutor(max_workers=workers)
    try:
        running: deque = deque()
        done = 1
        for index in range(1, total):
            check_cancelled(is_cancelled, "drive import")
            running.append(pool.submit(_convert_one, tmp, pairs[index], suffixes[index], rectifier, size,
                                       options.jpeg_quality))
            while len(running) >= 2 * workers:
                running.popleft().result()
                done += 1
                step(done)
        while running:
            running.popleft().result()
            done += 1
            step(done)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return check, normal


def _write_check_image(path: Path, check: EpipolarCheck, images: tuple) -> None:
    picture = draw_check(images[0], images[1], check)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    write_image(Path(path), picture)


def _import_record(source: DriveSource, plan: ImportPlan, options: ImportOptions, check: EpipolarCheck) -> dict:
    """How the drive was made, kept in drive.json (a writer key) so that a result can be traced."""
    o = source.orientation
    return {
        "source": source.label,
        "calibration": str(plan.calibration.source),
        "calibration_kind": plan.calibration.name,
        "rectified_by_import": plan.rectifier.resamples,
        "poses": str(source.poses.path),
        "poses_kind": "per image" if source.per_image else "trajectory",
        "angle_convention": o.convention, "angle_unit": o.unit, "north": o.north,
        "input_crs": source.input_crs,
        "lever_arm_m": [round(float(v), 6) for v in plan.mount.lever_arm_m],
        "camera_to_body": np.round(plan.mount.rotation, 9).tolist(),
        "epipolar_check": {"pair": "first", **check.summary()},
    }
