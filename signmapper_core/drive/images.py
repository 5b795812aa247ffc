"""Reading and writing the raster files of a drive: images and float32 depth maps.

Headers are read without decoding pixels (Pillow for images, a few bytes for
``.npy``/``.pfm``) so a whole drive can be validated up front quickly; pixels are
decoded only when a pair is processed. Images in the core are OpenCV BGR uint8.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ImageReadError

IMAGE_SUFFIXES = (".jpg", ".png", ".tif")
DEPTH_SUFFIXES = (".tif", ".npy", ".pfm")
# What each suffix must hold (Pillow's format names; MPO is a JPEG with extra pictures)
IMAGE_FORMATS = {".jpg": ("JPEG", "MPO"), ".png": ("PNG",), ".tif": ("TIFF",)}
SUFFIX_OF_FORMAT = {"JPEG": ".jpg", "MPO": ".jpg", "PNG": ".png", "TIFF": ".tif"}
GREY_MODES = ("1", "L", "LA", "I", "I;16", "F")
NPY_MAGIC = b"\x93NUMPY"
TIFF_SAMPLE_TYPES = {1: "uint", 2: "int", 3: "float"}  # TIFF tag 339 SampleFormat


def _cv2():
    import cv2  # imported lazily so a missing OpenCV fails with the plugin's own message

    return cv2


@dataclass(frozen=True)
class ImageHeader:
    """What the header of an image says, read without decoding pixels."""

    width: int
    height: int
    mode: str  # Pillow's mode: "RGB", "L" (greyscale), ...
    format: str  # Pillow's format: "JPEG", "PNG", "TIFF"

    @property
    def size(self) -> tuple[int, int]:
        return self.width, self.height

    @property
    def greyscale(self) -> bool:
        return self.mode in GREY_MODES


@dataclass(frozen=True)
class DepthHeader:
    """Size and sample type of a depth map, read without decoding it."""

    width: int
    height: int
    dtype: str  # numpy's name: "float32", "uint16", ...

    @property
    def size(self) -> tuple[int, int]:
        return self.width, self.height


def image_header(path: Path, check_suffix: bool = True) -> ImageHeader:
    """Size, mode and format of an image from its header; with ``check_suffix`` the content must match it."""
    from PIL import Image

    path = Path(path)
    try:
        with Image.open(path) as img:
            header = ImageHeader(int(img.size[0]), int(img.size[1]), img.mode, img.format or "")
    except Exception as exc:  # Pillow raises many types for broken headers
        _check_not_empty(path)
        raise ImageReadError(path, f"not a readable image ({exc.__class__.__name__}: {exc})") from exc
    allowed = IMAGE_FORMATS.get(path.suffix.lower()) if check_suffix else None
    if allowed and header.format not in allowed:
        right = SUFFIX_OF_FORMAT.get(header.format)
        hint = f"; rename it to {path.stem}{right}" if right else ""
        raise ImageReadError(path, f"is a {header.format} image, not what its suffix {path.suffix} says{hint}")
    return header


def depth_header(path: Path) -> DepthHeader:
    """Size and sample type of a depth map (.npy, .pfm, .tif) from its header."""
    path = Path(path)
    suffix = path.suffix.lower()
    try:
        if suffix == ".npy":
            arr = _open_npy(path, mmap_mode="r")
            if arr.ndim != 2:
                raise ImageReadError(path, f"depth array must be 2-D (height, width), found shape {arr.shape}")
            return DepthHeader(int(arr.shape[1]), int(arr.shape[0]), arr.dtype.name)
        if suffix == ".pfm":
            width, height, channels, _scale = _pfm_header(path)
            if channels != 1:
                raise ImageReadError(path, "PFM depth map must have one channel ('Pf'), found 'PF'")
            return DepthHeader(width, height, "float32")
        if suffix == ".tif":
            return _tiff_depth_header(path)
    except ImageReadError:
        raise
    except Exception as exc:  # Pillow/numpy raise many types for broken headers
        _check_not_empty(path)
        raise ImageReadError(path, f"not a readable depth map ({exc.__class__.__name__}: {exc})") from exc
    raise ImageReadError(path, f"unsupported depth file type '{suffix}'")


def _tiff_depth_header(path: Path) -> DepthHeader:
    """Size and sample type from a TIFF's first directory (Pillow cannot open float64 TIFFs, so no Image.open)."""
    from PIL import TiffImagePlugin

    with open(path, "rb") as fh:
        prefix = fh.read(8)
        ifd = TiffImagePlugin.ImageFileDirectory_v2(prefix)  # raises SyntaxError for a non-TIFF prefix
        fh.seek(ifd.next)
        ifd.load(fh)
    width, height = ifd.get(256), ifd.get(257)
    if not width or not height:
        raise ImageReadError(path, "TIFF without image width and length")
    bands = int(ifd.get(277, 1))
    bits = ifd.get(258, (1,))
    bits = int(bits[0] if isinstance(bits, tuple) else bits)
    sample = ifd.get(339, (1,))
    sample = int(sample[0] if isinstance(sample, tuple) else sample)
    if bands != 1:
        raise ImageReadError(path, f"depth map must have one band, found {bands}")
    return DepthHeader(int(width), int(height), f"{TIFF_SAMPLE_TYPES.get(sample, 'uint')}{bits}")


def image_size(path: Path) -> tuple[int, int]:
    """(width, height) of any image (whatever its suffix says) or .npy/.pfm depth file from its header."""
    path = Path(path)
    if path.suffix.lower() in (".npy", ".pfm"):
        return depth_header(path).size
    return image_header(path, check_suffix=False).size


def _check_not_empty(path: Path) -> None:
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise ImageReadError(path, f"cannot be read ({exc.strerror or exc})") from exc
    if size == 0:
        raise ImageReadError(path, "empty file (0 bytes)")


def _open_npy(path: Path, mmap_mode=None) -> np.ndarray:
    """A .npy array; anything that is not a NumPy file is named as such (numpy alone would blame pickling)."""
    try:
        return np.load(path, mmap_mode=mmap_mode, allow_pickle=False)
    except ValueError:
        _check_not_empty(path)
        with open(path, "rb") as fh:
            if fh.read(len(NPY_MAGIC)) != NPY_MAGIC:
                raise ImageReadError(path, "not a NumPy .npy file (no NumPy header)") from None
        raise


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
    if data.size == 0:
        raise ImageReadError(path, "empty file (0 bytes)")
    if Path(path).suffix.lower() in (".jpg", ".jpeg"):
        if data[:3].tobytes() != b"\xff\xd8\xff":
            raise ImageReadError(path, "not a JPEG file although named .jpg")
        if not _has_jpeg_end(data):
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
            depth = _open_npy(path)
        except ImageReadError:
            raise
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
        raise ImageReadError(path, depth_type_error(depth.dtype.name))
    _check_size(path, depth.shape, expected_size)
    depth = depth.astype(np.float32, copy=True)
    depth[~np.isfinite(depth) | (depth <= 0)] = np.nan
    return depth


def depth_type_error(dtype: str) -> str:
    """The message for a depth map that is not float32 metres."""
    hint = " (millimetres as integers?)" if dtype.startswith(("uint", "int")) else ""
    return f"depth map must be float32 metres (drive-format), found {dtype}{hint}"


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
