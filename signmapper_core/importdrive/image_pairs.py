"""Which left image goes with which right image: two folders with the same names, or one folder and a pattern.

Without a pattern every image of a folder is taken and its id is its file
name without suffix. A pattern holds one ``*`` that stands for the id:
``*_L.jpg`` and ``*_R.jpg`` pair ``0001_L.jpg`` with ``0001_R.jpg`` as id
``0001``. An image without its partner is an error naming it: silently
dropping it would lose data.
"""

from __future__ import annotations

import fnmatch
import re
from dataclasses import dataclass
from pathlib import Path

from ..drive.images import image_header
from ..errors import ImportInputError

INPUT_SUFFIXES = (".jpg", ".jpeg", ".png", ".tif", ".tiff", ".bmp")


@dataclass(frozen=True)
class ImagePair:
    id: str
    left: Path
    right: Path


def natural_key(text: str):
    """Sort key that puts img_2 before img_10."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def images_by_id(folder: Path, pattern: str = "") -> dict[str, Path]:
    """id -> file of the images in ``folder`` (see module for ``pattern``)."""
    folder = Path(folder)
    if not folder.is_dir():
        raise ImportInputError(folder, "image folder does not exist")
    if pattern and pattern.count("*") != 1:
        raise ImportInputError(folder, f"pattern {pattern!r} must hold exactly one '*' standing for the image id")
    regex = re.compile(fnmatch.translate(pattern).replace(".*", "(.+)", 1), re.IGNORECASE) if pattern else None
    found: dict[str, Path] = {}
    for path in folder.iterdir():
        if not path.is_file() or path.name.startswith("."):
            continue
        if regex is not None:
            match = regex.fullmatch(path.name)
            if not match:
                continue
            image_id = match.group(1)
        elif path.suffix.lower() in INPUT_SUFFIXES:
            image_id = path.stem
        else:
            continue
        if "/" in image_id or "\\" in image_id:
            continue
        if image_id in found:
            raise ImportInputError(folder, f"two images have the id {image_id!r}: {found[image_id].name} and "
                                   f"{path.name}; give a pattern that tells them apart")
        found[image_id] = path
    if not found:
        what = f"matching {pattern!r}" if pattern else f"({', '.join(INPUT_SUFFIXES)})"
        raise ImportInputError(folder, f"holds no images {what}")
    return found


def list_pairs(left_folder, right_folder=None, left_pattern: str = "", right_pattern: str = "") -> list[ImagePair]:
    """Stereo pairs sorted by id (naturally); right folder defaults to the left one when patterns tell them apart."""
    left_folder = Path(left_folder)
    if right_folder is None or str(right_folder) == "":
        if not (left_pattern and right_pattern):
            raise ImportInputError(left_folder, "no right image folder given; for left and right images in one "
                                   "folder give a pattern for each, e.g. *_L.jpg and *_R.jpg")
        right_folder = left_folder
    right_folder = Path(right_folder)
    if left_folder.resolve() == right_folder.resolve() and left_pattern == right_pattern:
        raise ImportInputError(left_folder, "left and right images are read from the same folder with the same "
                               "pattern; give each its own folder or pattern")
    left, right = images_by_id(left_folder, left_pattern), images_by_id(right_folder, right_pattern)
    only_left = sorted(set(left) - set(right), key=natural_key)
    only_right = sorted(set(right) - set(left), key=natural_key)
    if only_left or only_right:
        side, folder, ids = ("left", right_folder, only_left) if only_left else ("right", left_folder, only_right)
        source = left if only_left else right
        raise ImportInputError(source[ids[0]], f"has no partner in {folder} ({len(ids)} {side} image(s) without "
                               f"one, e.g. {', '.join(ids[:3])}); every pair needs both images")
    return [ImagePair(i, left[i], right[i]) for i in sorted(left, key=natural_key)]


def pair_size(pairs: list[ImagePair]) -> tuple[int, int]:
    """The common (width, height) of all images, from their headers; the first that differs is an error."""
    size = image_header(pairs[0].left, check_suffix=False).size
    for pair in pairs:
        for path in (pair.left, pair.right):
            found = image_header(path, check_suffix=False).size
            if found != size:
                raise ImportInputError(path, f"is {found[0]}x{found[1]}, the other images are {size[0]}x{size[1]}")
    return size
