"""Reading and writing the raster files of a drive: images and float32 depth maps.

Headers are read without decoding pixels (Pillow for images, a few bytes for
``.npy``/``.pfm``) so a whole drive can be validated up front quickly; pixels are
decoded only when a pair is processed. Images in the core are OpenCV BGR uint8.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .errors import ImageReadError

IMAGE_SUFFIXES = (".jpg", ".png", ".tif")
DEPTH_SUFFIXES = (".tif", ".npy", ".pfm")


def _cv2():
    import cv2  # imported lazily so a missing OpenCV fails with the plugin's own message

    return cv2


def image_size(path: Path) -> tuple[int, int]:
    """(width, height) of an image or depth file from its header."""
    path = Path(path)
    suffix = path.suffix.lower()
    try:
        if suffix == ".npy":
            arr = np.load(path, mmap_mode="r", allow_pickle=False)
            if arr.ndim != 2:
                raise ImageReadError(path, f"depth array must be 2-D (height, width), found shape {arr.shape}")
            return int(arr.shape[1]), int(arr.shape[0])
        if suffix == ".pfm":
            width, height, channels, _scale = _pfm_header(path)
            if channels != 1:
                raise ImageReadError(path, "PFM depth map must have one channel ('Pf'), found 'PF'")
            return width, height
        from PIL import Image

        with Image.open(path) as img:
            return int(img.size[0]), int(img.size[1])
    except ImageReadError:
        raise
    except Exception as exc:  # Pillow/numpy raise many types for broken headers
        raise ImageReadError(path, f"not a readable image ({exc.__class__.__name__}: {exc})") from exc


def _pfm_header(path: Path) -> tuple[int, int, int, float]:
    with open(path, "rb") as fh:
        tokens: list[bytes] = []
        while len(tokens) < 4:
            line = fh.readline(256)
            if not line:
                raise ImageReadError(path, "truncated PFM header")
            tokens.extend(line.split())
    kind = tokens[0]
    if kind not in (b"Pf", b"PF"):
        raise ImageReadError(path, f"not a PFM file (magic {kind!r})")
    try:
        width, height, scale = int(tokens[1]), int(tokens[2]), float(tokens[3])
    except ValueError as exc:
        raise ImageReadError(path, "malformed PFM header") from exc
    return width, height, 1 if kind == b"Pf" else 3, scale


def read_image(path: Path, expected_size: tuple[int, int] | None = None) -> np.ndarray:
    """Decode an 8-bit colour image as BGR uint8 (H, W, 3).

    libjpeg fills a truncated JPEG with grey and only warns; such a file is
    rejected here (no end-of-image marker) rather than mapped as a grey picture.
    """
    cv2 = _cv2()
    try:
        data = np.fromfile(path, dtype=np.uint8)
    except OSError as exc:
        raise ImageReadError(path, f"cannot be read ({exc.strerror or exc})") from exc
    if Path(path).suffix.lower() in (".jpg", ".jpeg") and not _has_jpeg_end(data):
        raise ImageReadError(path, "truncated JPEG (no end-of-image marker)")
    img = cv2.imdecode(data, cv2.IMREAD_COLOR) if data.size else None
    if img is None:
        raise ImageReadError(path, "cannot be decoded as an image (corrupt or unsupported)")
    _check_size(path, img.shape, expected_size)
    return img


def _has_jpeg_end(data: np.ndarray) -> bool:
    tail = data[-64:].tobytes().rstrip(b"\x00\r\n ")
    return tail.endswith(b"\xff\xd9")


def read_depth(path: Path, expected_size: tuple[int, int] | None = None) -> np.ndarray:
    """Decode a depth map as float32 (H, W) metres; 0, negative, inf and NaN become NaN."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".npy":
        try:
            depth = np.load(path, allow_pickle=False)
        except Exception as exc:
            raise ImageReadError(path, f"cannot be read as a numpy array ({exc})") from exc
    elif suffix in (".tif", ".pfm"):
        cv2 = _cv2()
        depth = cv2.imread(str(path), cv2.IMREAD_UNCHANGED)
        if depth is None:
            raise ImageReadError(path, "cannot be decoded as a float32 depth map")
    else:
        raise ImageReadError(path, f"unsupported depth file type '{suffix}'")
    if depth.ndim != 2:
        raise ImageReadError(path, f"depth map must have one band, found shape {depth.shape}")
    if depth.dtype != np.float32:
        raise ImageReadError(path, f"depth map must be float32, found {depth.dtype}")
    _check_size(path, depth.shape, expected_size)
    depth = depth.astype(np.float32, copy=True)
    depth[~np.isfinite(depth) | (depth <= 0)] = np.nan
    return depth


def write_depth(path: Path, depth: np.ndarray) -> Path:
    """Write a float32 depth map in the format given by the suffix (.tif, .npy, .pfm)."""
    path = Path(path)
    depth = np.asarray(depth, dtype=np.float32)
    suffix = path.suffix.lower()
    if suffix == ".npy":
        np.save(path, depth)
    elif suffix in (".tif", ".pfm"):
        if not _cv2().imwrite(str(path), depth):
            raise OSError(f"{path}: OpenCV could not write the depth map")
    else:
        raise ValueError(f"{path}: unsupported depth suffix '{suffix}'")
    return path


def _check_size(path, shape, expected_size):
    if expected_size is None:
        return
    width, height = expected_size
    if shape[0] != height or shape[1] != width:
        raise ImageReadError(path, f"size {shape[1]}x{shape[0]} differs from the camera's {width}x{height}")
