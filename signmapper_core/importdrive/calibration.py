"""Stereo calibrations as surveyors have them, read into one model.

Three kinds of file are understood, told apart by their content:

- OpenCV's YAML (``cv2.FileStorage``, ``%YAML:1.0``) or JSON with ``K1, D1, K2, D2, R, T`` as
  ``cv2.stereoCalibrate`` gives them (``M1``/``M2`` also accepted), and the image size as
  ``image_width``/``image_height``, ``width``/``height`` or ``image_size``/``size`` ``[w, h]``;
  ``X_right = R X_left + T``, T in metres;
- KITTI's ``calib_cam_to_cam.txt``: both the raw cameras (``K_0i, D_0i, R_0i, T_0i, S_0i``) and the
  rectified ones (``P_rect_0i, S_rect_0i``); which applies is decided by the images' size;
- a plain pinhole for pairs that are rectified already: ``fx, fy, cx, cy, baseline_m`` and optionally
  ``width, height`` (the ``camera`` block of drive.json, also nested under ``camera``), JSON or YAML.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ImportInputError
from .kitti_files import read_key_values

MIN_BASELINE_M, MAX_BASELINE_M = 0.02, 10.0
SIZE_KEYS = (("image_width", "image_height"), ("width", "height"))
SIZE_PAIR_KEYS = ("image_size", "imageSize", "size")


@dataclass(frozen=True)
class StereoCalibration:
    """Intrinsics of both cameras and the pose of the right camera in the left one's frame.

    ``rotation``/``translation``: ``X_right = R X_left + T`` (metres), the convention of
    ``cv2.stereoCalibrate``. ``rectified``: the images are normal images already (no distortion,
    same camera matrix, right camera on the left one's x axis); then no resampling is done.
    """

    name: str
    source: Path
    size: tuple[int, int] | None          # (width, height) of the images the calibration is for
    k1: np.ndarray
    d1: np.ndarray
    k2: np.ndarray
    d2: np.ndarray
    rotation: np.ndarray
    translation: np.ndarray
    rectified: bool

    @property
    def baseline_m(self) -> float:
        return float(np.linalg.norm(self.translation))


def pinhole(source, fx, fy, cx, cy, baseline_m, size=None, name="pinhole") -> StereoCalibration:
    """A rectified pair's calibration: one pinhole, the right camera ``baseline_m`` along +x."""
    k = np.array([[fx, 0.0, cx], [0.0, fy, cy], [0.0, 0.0, 1.0]], dtype=float)
    return StereoCalibration(name, Path(source), size, k, np.zeros(5), k.copy(), np.zeros(5), np.eye(3),
                             np.array([-float(baseline_m), 0.0, 0.0]), True)


def read_calibrations(path) -> list[StereoCalibration]:
    """Every calibration a file holds (KITTI: rectified and raw); ImportInputError naming the file otherwise."""
    path = Path(path)
    if not path.is_file():
        raise ImportInputError(path, "calibration file does not exist")
    if path.suffix.lower() == ".txt":
        return _kitti(path)
    values = _read_json(path) if path.suffix.lower() == ".json" else _read_filestorage(path)
    if "camera" in values and isinstance(values["camera"], dict):
        values = values["camera"]
    if "fx" in values:
        return [_pinhole_values(path, values)]
    return [_opencv_values(path, values)]


def choose_calibration(candidates: list[StereoCalibration], image_size: tuple[int, int],
                       image_path: Path) -> StereoCalibration:
    """The calibration made for images of ``image_size``; a clear error when none is."""
    for calibration in candidates:
        if calibration.size is None or tuple(calibration.size) == tuple(image_size):
            return calibration
    stated = ", ".join(f"{c.size[0]}x{c.size[1]} ({c.name})" for c in candidates)
    raise ImportInputError(
        candidates[0].source, f"the calibration is for images of {stated}, but {image_path} is "
        f"{image_size[0]}x{image_size[1]}; give the calibration of these cameras at this resolution")


def check_calibration(calibration: StereoCalibration) -> StereoCalibration:
    """Values no stereo rig has: non-positive focal lengths, a baseline not in metres, a right camera left."""
    path = calibration.source
    for label, k in (("K1", calibration.k1), ("K2", calibration.k2)):
        if k.shape != (3, 3) or not np.all(np.isfinite(k)) or k[0, 0] <= 0 or k[1, 1] <= 0:
            raise ImportInputError(path, f"camera matrix must be 3x3 with positive focal lengths, found {k.tolist()}",
                                   field=label)
    rotation = calibration.rotation
    if rotation.shape != (3, 3) or not np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-4):
        raise ImportInputError(path, "must be a 3x3 rotation matrix", field="R")
    baseline = calibration.baseline_m
    if not MIN_BASELINE_M <= baseline <= MAX_BASELINE_M:
        hint = " (millimetres? T must be in metres)" if baseline > MAX_BASELINE_M else ""
        raise ImportInputError(path, f"baseline {baseline:g} is not between {MIN_BASELINE_M} and "
                               f"{MAX_BASELINE_M} m{hint}", field="T")
    t = calibration.translation
    if abs(t[0]) < 0.7 * baseline:
        raise ImportInputError(path, f"the right camera is not beside the left one (T = {t.tolist()}); the drive "
                               "format needs a horizontal baseline", field="T")
    if t[0] > 0:
        raise ImportInputError(path, f"T = {t.tolist()} puts the 'right' camera to the left of the 'left' one; "
                               "swap the left and right images (or cameras)", field="T")
    return calibration


# -- OpenCV YAML / JSON -------------------------------------------------------------------------------------------

def _read_json(path: Path) -> dict:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ImportInputError(path, f"not valid JSON ({exc})", line=getattr(exc, "lineno", None)) from None
    if not isinstance(data, dict):
        raise ImportInputError(path, "must hold a JSON object")
    return data


def _node_value(node):
    if node.isMap():
        mat = node.mat()
        return None if mat is None else np.asarray(mat, dtype=float)
    if node.isSeq():
        return [_node_value(node.at(i)) for i in range(node.size())]
    if node.isString():
        return node.string()
    if node.isInt() or node.isReal():
        return node.real()
    return None


def _read_filestorage(path: Path) -> dict:
    """Top-level keys of an OpenCV YAML/XML/JSON file (what cv2.FileStorage writes)."""
    import cv2

    head = path.read_bytes()[:64]
    if path.suffix.lower() in (".yml", ".yaml") and not head.lstrip().startswith(b"%YAML"):
        raise ImportInputError(path, "not an OpenCV YAML file: it must start with '%YAML:1.0' as cv2.FileStorage "
                               "writes it (or give the calibration as JSON)", line=1)
    try:
        storage = cv2.FileStorage(str(path), cv2.FILE_STORAGE_READ)
    except (cv2.error, SystemError) as exc:
        raise ImportInputError(path, f"OpenCV cannot read it ({str(exc).strip().splitlines()[-1]})") from None
    if not storage.isOpened():
        raise ImportInputError(path, "OpenCV cannot read it as YAML, XML or JSON")
    try:
        root = storage.root()
        return {key: _node_value(root.getNode(key)) for key in root.keys()}
    finally:
        storage.release()


def _matrix(path: Path, values: dict, names: tuple[str, ...], shape) -> np.ndarray:
    name = next((n for n in names if n in values), None)
    if name is None:
        raise ImportInputError(path, f"required key is missing (looked for {' or '.join(names)})", field=names[0])
    raw = values[name]
    if isinstance(raw, dict) and "data" in raw:  # OpenCV JSON matrix
        raw = raw["data"]
    try:
        array = np.asarray(raw, dtype=float)
    except (TypeError, ValueError):
        raise ImportInputError(path, f"must be numbers, found {raw!r}", field=name) from None
    if shape == "vector":
        array = array.reshape(-1)
        if array.size not in (4, 5, 8, 12, 14):
            raise ImportInputError(path, f"distortion must have 4, 5, 8, 12 or 14 coefficients, found {array.size}",
                                   field=name)
        return array
    if array.size != int(np.prod(shape)):
        raise ImportInputError(path, f"must have {int(np.prod(shape))} values ({shape[0]}x{shape[-1]}), "
                               f"found {array.size}", field=name)
    if not np.all(np.isfinite(array)):
        raise ImportInputError(path, "holds a value that is not a finite number", field=name)
    return array.reshape(shape)


def _size(path: Path, values: dict) -> tuple[int, int] | None:
    for wk, hk in SIZE_KEYS:
        if wk in values and hk in values:
            return _whole_size(path, [values[wk], values[hk]], f"{wk}/{hk}")
    for key in SIZE_PAIR_KEYS:
        if key in values:
            return _whole_size(path, values[key], key)
    return None


def _whole_size(path: Path, raw, field: str) -> tuple[int, int]:
    try:
        w, h = (float(v) for v in np.asarray(raw, dtype=float).reshape(-1))
    except (TypeError, ValueError):
        raise ImportInputError(path, f"image size must be two numbers [width, height], found {raw!r}",
                               field=field) from None
    if w != int(w) or h != int(h) or w <= 0 or h <= 0:
        raise ImportInputError(path, f"image size must be two positive whole numbers, found {raw!r}", field=field)
    return int(w), int(h)


def _opencv_values(path: Path, values: dict) -> StereoCalibration:
    calibration = StereoCalibration(
        "OpenCV stereo calibration", path, _size(path, values),
        _matrix(path, values, ("K1", "M1", "cameraMatrix1"), (3, 3)),
        _matrix(path, values, ("D1", "distCoeffs1"), "vector"),
        _matrix(path, values, ("K2", "M2", "cameraMatrix2"), (3, 3)),
        _matrix(path, values, ("D2", "distCoeffs2"), "vector"),
        _matrix(path, values, ("R",), (3, 3)),
        _matrix(path, values, ("T",), (3,)),
        False)
    return check_calibration(calibration)


def _pinhole_values(path: Path, values: dict) -> StereoCalibration:
    numbers = {}
    for key in ("fx", "fy", "cx", "cy", "baseline_m"):
        if key not in values:
            raise ImportInputError(path, "required key of a pinhole calibration is missing", field=key)
        value = values[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value):
            raise ImportInputError(path, f"must be a finite number, found {value!r}", field=key)
        numbers[key] = float(value)
    if numbers["baseline_m"] <= 0:
        raise ImportInputError(path, f"must be positive, found {numbers['baseline_m']!r}", field="baseline_m")
    return check_calibration(pinhole(path, size=_size(path, values), **numbers))


# -- KITTI calib_cam_to_cam.txt -----------------------------------------------------------------------------------

def kitti_calibrations(path: Path, left: str = "02", right: str = "03") -> list[StereoCalibration]:
    """The rectified and the raw calibration of KITTI cameras ``left``/``right`` (e.g. 02/03 colour)."""
    values = read_key_values(path)
    cams = f"cameras {left}/{right}"

    def get(key, shape):
        if key not in values:
            raise ImportInputError(path, "required key is missing", field=key)
        array = values[key]
        if array.size != int(np.prod(shape)):
            raise ImportInputError(path, f"must have {int(np.prod(shape))} values, found {array.size}", field=key)
        return array.reshape(shape)

    p_left, p_right = get(f"P_rect_{left}", (3, 4)), get(f"P_rect_{right}", (3, 4))
    k = p_left[:, :3]
    offset_left, offset_right = np.linalg.solve(k, p_left[:, 3]), np.linalg.solve(k, p_right[:, 3])
    rect_size = _whole_size(path, get(f"S_rect_{left}", (2,)), f"S_rect_{left}")
    rectified = StereoCalibration(f"KITTI rectified {cams}", path, rect_size, k, np.zeros(5), k.copy(),
                                  np.zeros(5), np.eye(3), offset_right - offset_left, True)
    candidates = [check_calibration(rectified)]
    if f"K_{left}" in values and f"K_{right}" in values:
        r_left, t_left = get(f"R_{left}", (3, 3)), get(f"T_{left}", (3,))
        r_right, t_right = get(f"R_{right}", (3, 3)), get(f"T_{right}", (3,))
        relative = r_right @ r_left.T
        raw = StereoCalibration(f"KITTI raw {cams}", path, _whole_size(path, get(f"S_{left}", (2,)), f"S_{left}"),
                                get(f"K_{left}", (3, 3)), get(f"D_{left}", (5,)), get(f"K_{right}", (3, 3)),
                                get(f"D_{right}", (5,)), relative, t_right - relative @ t_left, False)
        candidates.append(check_calibration(raw))
    return candidates


def _kitti(path: Path) -> list[StereoCalibration]:
    values = read_key_values(path)
    if "P_rect_02" not in values and "P_rect_00" not in values:
        raise ImportInputError(path, "not a KITTI calib_cam_to_cam.txt (no P_rect_02); give OpenCV YAML/JSON or a "
                               "pinhole JSON")
    cams = ("02", "03") if "P_rect_02" in values else ("00", "01")
    return kitti_calibrations(path, *cams)
