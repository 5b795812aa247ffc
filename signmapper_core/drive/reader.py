"""Reader of the drive folder, version 1 (``shared/drive-format.md``).

:func:`open_drive` validates the whole folder up front (metadata, every CSV row,
every image header) and fails with a :class:`DriveFormatError` naming the file,
line and field. Pixels are only decoded when a pair is asked for, one pair at a
time, so memory does not grow with the length of the drive.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator

import numpy as np

from ..errors import DriveFormatError, ImageReadError
from ..geometry import Camera, Pose
from ..progress import CancelCheck, ProgressCallback, check_cancelled, report
from .images import (
    DEPTH_SUFFIXES,
    IMAGE_SUFFIXES,
    depth_header,
    depth_type_error,
    image_header,
    read_depth,
    read_image,
)
from .plausibility import camera_warnings, depth_warnings, greyscale_warning, pose_warnings

FORMAT_ID = "stereo-drive/1"
POSE_COLUMNS = ("id", "time", "easting", "northing", "height", "heading", "pitch", "roll")
TRUTH_COLUMNS = ("sign_id", "template_id", "easting", "northing", "height", "width_m", "height_m", "facing")
TRUTH_OPTIONAL = ("plate_of", "text")  # a supplementary plate's sign, and the text on a plate or panel
# a column of our own (the format lets readers ignore columns they do not know): which artwork a synthetic
# face was printed from, so evaluations can tell the official drawings from other designs of a sign
TRUTH_ARTWORK = "face_artwork"
# ... and which of the catalogue entry's drawings a face printed from the official artwork shows (the master's
# file stem, or a variant's: another language, the other pointing direction), on drives that print variants
TRUTH_DRAWING = "face_drawing"
CAMERA_KEYS = ("width", "height", "fx", "fy", "cx", "cy", "baseline_m")
MAX_ANGLE_DEG = 1e9  # beyond this a double no longer resolves a microdegree: the value is not an angle


@dataclass(frozen=True)
class PairRecord:
    """One stereo pair: its pose and the paths of its files (not their pixels)."""

    index: int
    id: str
    time: float
    pose: Pose
    left_path: Path
    right_path: Path | None
    depth_path: Path | None
    ahead_m: float | None = None  # set by the mapping: drive/path_ahead.py (None: not known, the path goes on)


@dataclass(frozen=True)
class TruthSign:
    """One row of ``truth.csv``: a physical sign's face centre, standard size and facing."""

    sign_id: str
    template_id: str
    easting: float
    northing: float
    height: float
    width_m: float
    height_m: float
    facing: float
    plate_of: str = ""  # a supplementary plate: the sign_id of its sign; "" for a sign
    text: str = ""  # the text printed on a plate or panel, lines joined by " / "
    artwork: str = ""  # synthetic drives: "master" (the catalogue's drawing) or "procedural"; "" where unknown
    drawing: str = ""  # synthetic drives: the file stem of the official drawing printed ("2.30.1~2"); "" where none

    @property
    def position(self) -> np.ndarray:
        return np.array([self.easting, self.northing, self.height])

    @property
    def is_plate(self) -> bool:
        return bool(self.plate_of)


@dataclass
class Drive:
    """A validated drive folder."""

    root: Path
    crs: str
    camera: Camera
    pairs: list[PairRecord]
    truth: list[TruthSign] | None = None
    metadata: dict = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)  # implausible but readable input (``plausibility``)
    truth_error: DriveFormatError | None = None  # why a broken truth.csv was ignored

    def __len__(self) -> int:
        return len(self.pairs)

    @property
    def image_size(self) -> tuple[int, int]:
        return self.camera.width, self.camera.height

    def pair(self, pair_id: str) -> PairRecord:
        for record in self.pairs:
            if record.id == pair_id:
                return record
        raise KeyError(f"{self.root}: no pair with id '{pair_id}' in poses.csv")

    def load_left(self, record: PairRecord) -> np.ndarray:
        """Left normal image as BGR uint8."""
        return read_image(record.left_path, self.image_size)

    def load_right(self, record: PairRecord) -> np.ndarray | None:
        """Right normal image as BGR uint8, or None where the drive has none."""
        return None if record.right_path is None else read_image(record.right_path, self.image_size)

    def load_depth(self, record: PairRecord) -> np.ndarray | None:
        """Given depth map (float32 metres, NaN = no depth), or None where none is given."""
        return None if record.depth_path is None else read_depth(record.depth_path, self.image_size)


def open_drive(path, check_images: bool = True, progress: ProgressCallback | None = None,
               is_cancelled: CancelCheck | None = None, require_truth: bool = False) -> Drive:
    """Validate and open a drive folder.

    ``check_images`` reads the header of every image and depth map to check it
    decodes, has the camera's size and (depth) is float32, and decodes the first
    depth map to see it holds metres; leave it on unless the caller checks.
    ``progress`` and ``is_cancelled`` follow :mod:`signmapper_core.progress`
    (reported per pair; :class:`~signmapper_core.progress.Cancelled` when cancelled).
    Implausible but readable values are listed in ``Drive.warnings``. A broken
    ``truth.csv`` is only needed by evaluation: it raises with ``require_truth``,
    otherwise it is a warning and ``Drive.truth`` is None.
    """
    root = Path(path)
    if not root.is_dir():
        raise DriveFormatError(root, "drive folder does not exist or is not a folder")
    metadata = _read_drive_json(root / "drive.json")
    crs = _validate_crs(root / "drive.json", metadata["crs"])
    camera = _read_camera(root / "drive.json", metadata["camera"])
    rows = _read_poses(root / "poses.csv")
    warnings = camera_warnings(root / "drive.json", camera) + pose_warnings(root / "poses.csv", crs, rows)
    pairs = _attach_files(root, rows, camera, check_images, progress, is_cancelled, warnings)
    if check_images:
        warnings += _first_depth_warnings(pairs, camera)
    drive = Drive(root=root, crs=crs, camera=camera, pairs=pairs, metadata=metadata, warnings=warnings)
    truth_path = root / "truth.csv"
    if truth_path.exists():
        try:
            drive.truth = read_truth(truth_path)
        except DriveFormatError as exc:
            if require_truth:
                raise
            drive.truth_error = exc
            warnings.append(f"{exc}; the ground truth is ignored (only evaluation needs it)")
    return drive


def _first_depth_warnings(pairs: list[PairRecord], camera: Camera) -> list[str]:
    """Decode the first given depth map: depth in millimetres or without any valid value shows there."""
    first = next((r.depth_path for r in pairs if r.depth_path is not None), None)
    return [] if first is None else depth_warnings(first, read_depth(first, (camera.width, camera.height)))


def _read_drive_json(path: Path) -> dict:
    if not path.is_file():
        raise DriveFormatError(path, "required file is missing")
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        line = getattr(exc, "lineno", None)
        raise DriveFormatError(path, f"not valid JSON ({exc})", line=line) from exc
    if not isinstance(data, dict):
        raise DriveFormatError(path, "must hold a JSON object")
    for key in ("format", "crs", "camera"):
        if key not in data:
            raise DriveFormatError(path, "required key is missing", field=key)
    if data["format"] != FORMAT_ID:
        raise DriveFormatError(path, f"unsupported format {data['format']!r}, expected {FORMAT_ID!r}", field="format")
    if not isinstance(data["camera"], dict):
        raise DriveFormatError(path, "must be an object", field="camera")
    return data


def _validate_crs(path: Path, crs_text) -> str:
    """Accept any projected CRS with metre units that PROJ knows; return it as given."""
    from pyproj import CRS
    from pyproj.exceptions import CRSError

    if not isinstance(crs_text, str) or not crs_text.strip():
        raise DriveFormatError(path, "must be a CRS string such as 'EPSG:2056'", field="crs")
    try:
        crs = CRS.from_user_input(crs_text)
    except CRSError as exc:
        raise DriveFormatError(path, f"unknown CRS {crs_text!r}", field="crs") from exc
    horizontal = crs.sub_crs_list[0] if crs.is_compound else crs
    if not horizontal.is_projected:
        raise DriveFormatError(path, f"CRS {crs_text!r} is not projected; positions must be in metres", field="crs")
    units = {axis.unit_name.lower() for axis in horizontal.axis_info}
    if units - {"metre", "meter"}:
        raise DriveFormatError(path, f"CRS {crs_text!r} has units {sorted(units)}, not metres", field="crs")
    return crs_text.strip()


def _read_camera(path: Path, cam: dict) -> Camera:
    values = {}
    for key in CAMERA_KEYS:
        if key not in cam:
            raise DriveFormatError(path, "required key is missing", field=f"camera.{key}")
        value = cam[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise DriveFormatError(path, f"must be a finite number, found {value!r}", field=f"camera.{key}")
        values[key] = value
    for key in ("width", "height"):
        if values[key] != int(values[key]) or values[key] <= 0:
            raise DriveFormatError(
                path, f"must be a positive whole number, found {values[key]!r}", field=f"camera.{key}"
            )
        values[key] = int(values[key])
    for key in ("fx", "fy", "baseline_m"):
        if values[key] <= 0:
            raise DriveFormatError(path, f"must be positive, found {values[key]!r}", field=f"camera.{key}")
    for key, size in (("cx", values["width"]), ("cy", values["height"])):
        if not -0.5 <= values[key] <= size - 0.5:
            raise DriveFormatError(
                path, f"principal point {values[key]!r} lies outside the image (-0.5 to {size - 0.5:g} px)",
                field=f"camera.{key}",
            )
    return Camera(**values)


def _parse_float(path, line, name, text) -> float:
    try:
        value = float(text)
    except (TypeError, ValueError):
        raise DriveFormatError(path, f"{text!r} is not a number", line=line, field=name) from None
    if not math.isfinite(value):
        raise DriveFormatError(path, f"{text!r} is not a finite number", line=line, field=name)
    return value


def _read_csv_rows(path: Path, columns: tuple[str, ...], optional: tuple[str, ...] = ()) -> Iterator[tuple[int, dict]]:
    """Yield (line number, row) with every required column present and non-empty; ``optional`` columns are ""
    where the header lacks them or the cell is empty."""
    if not path.is_file():
        raise DriveFormatError(path, "required file is missing")
    with open(path, newline="", encoding="utf-8-sig") as fh:
        reader = csv.reader(fh)
        try:
            header = next(reader)
        except StopIteration:
            raise DriveFormatError(path, "file is empty, expected a header line", line=1) from None
        except (csv.Error, UnicodeDecodeError) as exc:
            raise DriveFormatError(path, f"unreadable CSV ({exc})", line=1) from exc
        header = [h.strip() for h in header]
        for col in columns:
            if col not in header:
                raise DriveFormatError(path, f"header lacks required column; found {header}", line=1, field=col)
        index = {col: header.index(col) for col in columns}
        extra = {col: header.index(col) for col in optional if col in header}
        while True:
            try:
                raw = next(reader)
            except StopIteration:
                return
            except (csv.Error, UnicodeDecodeError) as exc:
                raise DriveFormatError(path, f"unreadable CSV ({exc})", line=reader.line_num) from exc
            line = reader.line_num
            if not raw or all(not cell.strip() for cell in raw):
                continue
            if len(raw) != len(header):
                raise DriveFormatError(path, f"has {len(raw)} fields, header has {len(header)}", line=line)
            row = {}
            for col, i in index.items():
                cell = raw[i].strip()
                if cell == "":
                    raise DriveFormatError(path, "value is empty", line=line, field=col)
                row[col] = cell
            row.update({col: extra.get(col) is not None and raw[extra[col]].strip() or "" for col in optional})
            yield line, row


def _read_poses(path: Path) -> list[tuple[int, str, float, Pose]]:
    rows = []
    seen: dict[str, int] = {}
    last_time = -math.inf
    for line, row in _read_csv_rows(path, POSE_COLUMNS):
        pair_id = row["id"]
        if "/" in pair_id or "\\" in pair_id or pair_id in (".", ".."):
            raise DriveFormatError(path, f"id {pair_id!r} must not contain a path separator", line=line, field="id")
        if pair_id in seen:
            raise DriveFormatError(path, f"id {pair_id!r} repeats line {seen[pair_id]}", line=line, field="id")
        seen[pair_id] = line
        nums = {k: _parse_float(path, line, k, row[k]) for k in POSE_COLUMNS[1:]}
        if nums["time"] <= last_time:
            raise DriveFormatError(
                path, f"time {row['time']} is not after the previous row's {last_time:g}", line=line, field="time"
            )
        last_time = nums["time"]
        if not -90.0 <= nums["pitch"] <= 90.0:
            raise DriveFormatError(path, f"pitch {nums['pitch']} outside [-90, 90] degrees", line=line, field="pitch")
        for name in ("heading", "roll"):
            if abs(nums[name]) > MAX_ANGLE_DEG:
                raise DriveFormatError(path, f"{name} {nums[name]:g} is not an angle in degrees", line=line,
                                       field=name)
        pose = Pose(nums["easting"], nums["northing"], nums["height"], nums["heading"], nums["pitch"], nums["roll"])
        rows.append((line, pair_id, nums["time"], pose))
    if not rows:
        raise DriveFormatError(path, "has a header but no pair rows", line=2)
    return rows


def _find_file(folder: Path, stem: str, suffixes: tuple[str, ...], poses_path: Path, line: int) -> Path | None:
    """The single file ``<stem><suffix>`` in ``folder``; more than one is ambiguous."""
    found = [folder / f"{stem}{s}" for s in suffixes if (folder / f"{stem}{s}").is_file()]
    if len(found) > 1:
        names = ", ".join(p.name for p in found)
        raise DriveFormatError(
            poses_path, f"ambiguous files for id {stem!r} in {folder.name}/: {names}", line=line, field="id"
        )
    return found[0] if found else None


def _attach_files(root: Path, rows, camera: Camera, check_images: bool, progress=None,
                  is_cancelled=None, warnings: list | None = None) -> list[PairRecord]:
    poses_path = root / "poses.csv"
    left_dir, right_dir, depth_dir = root / "left", root / "right", root / "depth"
    if not left_dir.is_dir():
        raise DriveFormatError(left_dir, "required folder is missing")
    expected = (camera.width, camera.height)
    pairs, grey = [], []
    for index, (line, pair_id, time, pose) in enumerate(rows):
        check_cancelled(is_cancelled, f"opening drive {root}")
        left = _find_file(left_dir, pair_id, IMAGE_SUFFIXES, poses_path, line)
        if left is None:
            raise DriveFormatError(
                poses_path, f"no left image left/{pair_id}.jpg|.png|.tif for id {pair_id!r}", line=line, field="id"
            )
        right = _find_file(right_dir, pair_id, IMAGE_SUFFIXES, poses_path, line) if right_dir.is_dir() else None
        depth = _find_file(depth_dir, pair_id, DEPTH_SUFFIXES, poses_path, line) if depth_dir.is_dir() else None
        if right is None and depth is None:
            raise DriveFormatError(
                poses_path,
                f"pair {pair_id!r} has neither depth/{pair_id}.* nor right/{pair_id}.* to compute depth from",
                line=line,
                field="id",
            )
        if check_images:
            if _check_headers(left, right, depth, expected):
                grey.append(left)
        pairs.append(PairRecord(index, pair_id, time, pose, left, right, depth))
        report(progress, (index + 1) / len(rows), f"checked pair {pair_id} ({index + 1} of {len(rows)})")
    if warnings is not None:
        warnings += greyscale_warning(left_dir, grey, len(pairs)) + _unlisted_images(left_dir, pairs)
    return pairs


def _unlisted_images(left_dir: Path, pairs: list[PairRecord]) -> list[str]:
    """The warning for left images that no row of poses.csv names: they are not mapped, and the user should
    know (a row lost when the poses were exported)."""
    listed = {record.left_path.name for record in pairs}
    unlisted = sorted(p.name for p in left_dir.iterdir() if p.suffix.lower() in IMAGE_SUFFIXES
                      and p.name not in listed and not p.name.startswith("."))
    if not unlisted:
        return []
    return [f"{left_dir}/: {len(unlisted)} image{'s have' if len(unlisted) > 1 else ' has'} no row in poses.csv and "
            f"{'are' if len(unlisted) > 1 else 'is'} not mapped (first: {unlisted[0]})"]


def _check_headers(left: Path, right: Path | None, depth: Path | None, expected: tuple[int, int]) -> bool:
    """Sizes of a pair's files, their content against their suffix, the depth's sample type.

    Returns whether the left image is greyscale.
    """
    headers = [image_header(left)] + ([image_header(right)] if right is not None else [])
    if depth is not None:
        found = depth_header(depth)
        if found.dtype != "float32":
            raise ImageReadError(depth, depth_type_error(found.dtype))
        headers.append(found)
    for path, header in zip([p for p in (left, right, depth) if p is not None], headers):
        if header.size != expected:
            raise DriveFormatError(
                path, f"size {header.size[0]}x{header.size[1]} differs from the camera's {expected[0]}x{expected[1]}"
            )
    return headers[0].greyscale


def read_truth(path) -> list[TruthSign]:
    """Read and validate ``truth.csv``."""
    path = Path(path)
    signs = []
    seen: dict[str, int] = {}
    plates = []
    for line, row in _read_csv_rows(path, TRUTH_COLUMNS, TRUTH_OPTIONAL + (TRUTH_ARTWORK, TRUTH_DRAWING)):
        if row["sign_id"] in seen:
            raise DriveFormatError(
                path, f"sign_id {row['sign_id']!r} repeats line {seen[row['sign_id']]}", line=line, field="sign_id"
            )
        seen[row["sign_id"]] = line
        nums = {k: _parse_float(path, line, k, row[k]) for k in TRUTH_COLUMNS[2:]}
        for k in ("width_m", "height_m"):
            if nums[k] <= 0:
                raise DriveFormatError(path, f"must be positive, found {row[k]}", line=line, field=k)
        signs.append(TruthSign(row["sign_id"], row["template_id"], **nums, plate_of=row["plate_of"], text=row["text"],
                               artwork=row[TRUTH_ARTWORK], drawing=row[TRUTH_DRAWING]))
        if row["plate_of"]:
            plates.append((line, row["plate_of"]))
    for line, sign_id in plates:
        if sign_id not in seen:
            raise DriveFormatError(path, f"plate_of names sign_id {sign_id!r}, which no row has", line=line,
                                   field="plate_of")
    return signs
