"""Manifests of real sign photographs (crops and whole scenes) with their SSV ids, read and checked.

Our templates and synthetic drives are drawn by the same code, so recognition
figures measured on them say little. A real-photograph set (e.g. GTSRB/GTSDB,
mapped to SSV ids) is described by CSV manifests next to the images:

``crops.csv`` / ``scenes.csv``: one row per sign, columns
``image,x0,y0,x1,y1,ssv_id,group,split,source``; ``image`` is a relative path
from the manifest's folder, the box is the sign face in pixels (x1, y1
exclusive), ``group`` says whether the photographed pictogram is the Swiss one
(``same``) or a different drawing of the same meaning (``differs``), ``split``
is ``tune`` or ``report`` (figures are reported on ``report`` only).

``scenes_images.csv``: every scene photograph, also those without a sign (for
false-positive counts), columns ``image,width,height,split,source,signs``.

Either kind may add a column ``scene``: the place a photograph shows (photographs
of one place, where one physical sign may be seen twice, share it; empty when
unknown, as for GTSRB crops, which have no track ids). The halves are meant to
share no physical sign, so every row of one scene must be in the same split.

Every row is checked on reading; an error names the file, the line and the
field, so a broken manifest never turns into a silent miscount.
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Iterable, List, Optional, Sequence, Tuple

import cv2
import numpy as np

from ..errors import InputFileError

MANIFEST_COLUMNS = ("image", "x0", "y0", "x1", "y1", "ssv_id", "group", "split", "source")
IMAGE_LIST_COLUMNS = ("image", "width", "height", "split", "source", "signs")
SCENE_COLUMN = "scene"  # optional in both kinds of manifest
GROUPS = ("same", "differs")
SPLITS = ("tune", "report")
_ID_PATTERN = re.compile(r"^[0-9A-Za-z]+(\.[0-9A-Za-z]+)*(-[0-9A-Za-z.]+)?$")


class ManifestError(InputFileError):
    """A manifest or one of its images is unusable; the message names file, line and field."""


def read_bgr(path) -> np.ndarray:
    """The image at ``path`` as 8-bit BGR; ManifestError when it is missing or cannot be decoded."""
    path = Path(path)
    if not path.is_file():
        raise ManifestError(path, "image file does not exist")
    image = cv2.imread(str(path), cv2.IMREAD_COLOR)
    if image is None:
        raise ManifestError(path, "image cannot be decoded")
    return image


@dataclass(frozen=True)
class RealSign:
    """One photographed sign: where its face is in which image, and which SSV sign it is."""

    image: Path  # absolute path of the photograph
    bbox: Tuple[int, int, int, int]  # face box x, y, w, h in pixels
    ssv_id: str
    group: str  # "same": the Swiss pictogram; "differs": same meaning, other drawing
    split: str  # "tune" or "report"
    source: str  # data set the photograph comes from, e.g. "gtsrb-test"
    manifest: str = ""  # manifest file and line, for messages
    line: int = 0
    scene: str = ""  # the place photographed ("" = unknown); one scene is in one split

    @property
    def size_px(self) -> int:
        """Longer side of the face box: the sign's size in the photograph."""
        return max(self.bbox[2], self.bbox[3])

    def load_image(self) -> np.ndarray:
        """The photograph as BGR; ManifestError when it cannot be read or the box leaves it."""
        image = read_bgr(self.image)
        x, y, w, h = self.bbox
        height, width = image.shape[:2]
        if x + w > width or y + h > height:
            raise ManifestError(self.manifest, f"box x0={x} y0={y} x1={x + w} y1={y + h} leaves the "
                                f"{width}x{height} image {self.image}", self.line)
        return image


@dataclass(frozen=True)
class SceneImage:
    """One whole photograph of the scene set, with or without signs."""

    image: Path
    width: int
    height: int
    split: str
    source: str
    signs: int  # signs of the manifest in this photograph (0: only false positives possible)
    scene: str = ""  # the place photographed ("" = unknown); one scene is in one split


def _read_rows(path: Path, columns: Sequence[str]) -> Iterable[Tuple[int, dict]]:
    if not path.is_file():
        raise ManifestError(path, "manifest file does not exist")
    with path.open(newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames is None:
            raise ManifestError(path, "empty file, expected a header " + ",".join(columns), 1)
        missing = [c for c in columns if c not in reader.fieldnames]
        if missing:
            raise ManifestError(path, f"header lacks column(s) {', '.join(missing)}; expected "
                                + ",".join(columns), 1)
        for row in reader:
            line = reader.line_num
            if None in row or any(row.get(c) is None for c in columns):
                raise ManifestError(path, f"expected {len(reader.fieldnames)} fields", line)
            yield line, {k: (v or "").strip() for k, v in row.items()}


def _int(path, line, row, name, minimum=0) -> int:
    text = row[name]
    try:
        value = int(text)
    except ValueError:
        raise ManifestError(path, f"not an integer: {text!r}", line, name) from None
    if value < minimum:
        raise ManifestError(path, f"must be >= {minimum}, got {value}", line, name)
    return value


def _choice(path, line, row, name, allowed) -> str:
    value = row[name]
    if value not in allowed:
        raise ManifestError(path, f"{value!r} is not one of {', '.join(allowed)}", line, name)
    return value


def _image_path(path, line, row, root: Path, check_files: bool) -> Path:
    text = row["image"]
    rel = PurePosixPath(text)
    if not text or rel.is_absolute() or ".." in rel.parts or "\\" in text:
        raise ManifestError(path, f"need a relative path below the manifest's folder, got {text!r}", line, "image")
    full = root.joinpath(*rel.parts)
    if check_files and not full.is_file():
        raise ManifestError(path, f"image file {full} does not exist", line, "image")
    return full


def _source(path, line, row) -> str:
    if not row["source"]:
        raise ManifestError(path, "empty", line, "source")
    return row["source"]


def _scene(path, line, row, split: str, splits_seen: dict) -> str:
    """The row's scene ("" without the column); a scene met before in the other split is an error."""
    scene = row.get(SCENE_COLUMN) or ""
    if scene:
        first = splits_seen.setdefault(scene, (split, line))
        if first[0] != split:
            raise ManifestError(path, f"scene {scene!r} is {split} here but {first[0]} on line {first[1]}: "
                                "a scene belongs to one split", line, SCENE_COLUMN)
    return scene


def load_manifest(path, root=None, known_ids: Optional[Iterable[str]] = None,
                  check_files: bool = True) -> List[RealSign]:
    """The signs of a ``crops.csv`` / ``scenes.csv`` manifest, every row checked.

    ``root``: folder the image paths are relative to (default: the manifest's).
    ``known_ids``: if given, every ``ssv_id`` must be one of them (the catalogue's).
    ``check_files``: every image must exist (a missing one is an error, not a skip).
    """
    path = Path(path)
    root = Path(root) if root is not None else path.parent
    known = set(known_ids) if known_ids is not None else None
    signs: List[RealSign] = []
    seen, scene_splits = {}, {}
    for line, row in _read_rows(path, MANIFEST_COLUMNS):
        image = _image_path(path, line, row, root, check_files)
        x0, y0, x1, y1 = (_int(path, line, row, c) for c in ("x0", "y0", "x1", "y1"))
        if x1 <= x0:
            raise ManifestError(path, f"x1={x1} must be greater than x0={x0}", line, "x1")
        if y1 <= y0:
            raise ManifestError(path, f"y1={y1} must be greater than y0={y0}", line, "y1")
        ssv_id = row["ssv_id"]
        if not _ID_PATTERN.match(ssv_id):
            raise ManifestError(path, f"not a catalogue id: {ssv_id!r}", line, "ssv_id")
        if known is not None and ssv_id not in known:
            raise ManifestError(path, f"{ssv_id!r} is not in the catalogue", line, "ssv_id")
        group = _choice(path, line, row, "group", GROUPS)
        split = _choice(path, line, row, "split", SPLITS)
        key = (row["image"], x0, y0, x1, y1)
        if key in seen:
            raise ManifestError(path, f"the same image and box as line {seen[key]}", line)
        seen[key] = line
        signs.append(RealSign(image, (x0, y0, x1 - x0, y1 - y0), ssv_id, group, split,
                              _source(path, line, row), str(path), line,
                              _scene(path, line, row, split, scene_splits)))
    if not signs:
        raise ManifestError(path, "no signs listed")
    return signs


def load_scene_list(path, root=None, check_files: bool = True) -> List[SceneImage]:
    """Every photograph of a ``scenes_images.csv``, every row checked."""
    path = Path(path)
    root = Path(root) if root is not None else path.parent
    scenes: List[SceneImage] = []
    seen, scene_splits = {}, {}
    for line, row in _read_rows(path, IMAGE_LIST_COLUMNS):
        image = _image_path(path, line, row, root, check_files)
        if row["image"] in seen:
            raise ManifestError(path, f"image listed twice (first on line {seen[row['image']]})", line, "image")
        seen[row["image"]] = line
        width, height = _int(path, line, row, "width", 1), _int(path, line, row, "height", 1)
        split = _choice(path, line, row, "split", SPLITS)
        scenes.append(SceneImage(image, width, height, split, _source(path, line, row),
                                 _int(path, line, row, "signs"), _scene(path, line, row, split, scene_splits)))
    if not scenes:
        raise ManifestError(path, "no images listed")
    return scenes
