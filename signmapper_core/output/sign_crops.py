"""An image crop per mapped sign, written beside the GeoPackage so a sign can be checked without the drive."""

from __future__ import annotations

from pathlib import Path
from typing import Dict, Optional, Tuple

import cv2

from ..progress import CancelCheck, WarnCallback, check_cancelled, send_warning
from .partial_output import PartialOutput

Rect = Tuple[int, int, int, int]  # x, y, w, h
JPEG_QUALITY = 90


def crop_box(bbox: Rect, image_size: Tuple[int, int], context: float = 3.0, min_px: int = 120) -> Rect:
    """A square-ish region ``context`` times the sign's size around it (at least ``min_px``), inside the image."""
    x, y, w, h = bbox
    width, height = image_size
    side = int(max(min_px, context * max(w, h)))
    side_w, side_h = min(side, width), min(side, height)
    cx, cy = x + w / 2.0, y + h / 2.0
    x0 = int(round(min(max(cx - side_w / 2.0, 0), width - side_w)))
    y0 = int(round(min(max(cy - side_h / 2.0, 0), height - side_h)))
    return x0, y0, side_w, side_h


def crop_name(sign_id: int) -> str:
    return f"sign_{sign_id:05d}.jpg"


def write_sign_crops(drive, signs, folder: Path, is_cancelled: Optional[CancelCheck] = None,
                     warn: Optional[WarnCallback] = None) -> Dict[int, str]:
    """One JPEG per sign from its best observation's left image; sign_id -> file name in ``folder``.

    Signs seen best in the same pair share one decode. A pair that cannot be
    read any more costs only its signs' crops (reported through ``warn``).
    Raises ``Cancelled`` between pairs when ``is_cancelled()`` turns true (the
    caller discards the folder).
    """
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    by_pair: Dict[str, list] = {}
    for sign in signs:
        by_pair.setdefault(sign.best.pair_id, []).append(sign)
    written = {}
    for pair_id, pair_signs in by_pair.items():
        check_cancelled(is_cancelled, "writing sign crops")
        try:
            left = drive.load_left(drive.pair(pair_id))
        except Exception as exc:  # noqa: BLE001 - a crop is a convenience: report and go on
            send_warning(warn, f"No crops for the signs of pair {pair_id}: {exc}")
            continue
        for sign in pair_signs:
            x, y, w, h = crop_box(sign.best.bbox, (left.shape[1], left.shape[0]))
            name = crop_name(sign.sign_id)
            if cv2.imwrite(str(folder / name), left[y:y + h, x:x + w], [cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY]):
                written[sign.sign_id] = name
            else:
                send_warning(warn, f"Could not write {folder / name}")
    return written


class CropFolder:
    """The crops folder beside a GeoPackage (``<name>_crops``), written as a partial output
    (:class:`~signmapper_core.output.partial_output.PartialOutput`): a failed or cancelled run leaves the crops of an
    earlier run as they were."""

    def __init__(self, target: Path):
        target = Path(target)
        self.folder = target.with_name(f"{target.stem}_crops")
        self.output = PartialOutput(self.folder, folder=True, replace_folder=True)  # holds only our crops

    def write(self, drive, signs, is_cancelled: Optional[CancelCheck] = None,
              warn: Optional[WarnCallback] = None) -> Dict[int, str]:
        """The crops of ``signs`` (:func:`write_sign_crops`) into the partial folder; sign_id -> path
        relative to the GeoPackage (the ``crop_path`` field)."""
        names = write_sign_crops(drive, signs, self.output.path, is_cancelled, warn)
        return {sign_id: f"{self.folder.name}/{name}" for sign_id, name in names.items()}

    def commit(self) -> None:
        self.output.commit()

    def discard(self) -> None:
        self.output.discard()
