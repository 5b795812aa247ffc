"""The drive's absolute start (drive.json start_time) and the image crop written per sign."""

import json
from datetime import datetime, timedelta, timezone

import cv2
import numpy as np
import pytest
from drive_fixtures import make_drive

from signmapper_core.drive.clock import drive_start
from signmapper_core.drive.reader import open_drive
from signmapper_core.errors import DriveFormatError
from signmapper_core.output.sign_crops import crop_box, write_sign_crops
from signmapper_core.progress import Cancelled


def with_start(root, value):
    meta = json.loads((root / "drive.json").read_text())
    meta["start_time"] = value
    (root / "drive.json").write_text(json.dumps(meta))
    return open_drive(root)


def test_start_time_is_read_and_a_bad_one_names_the_file_and_key(tmp_path):
    root = make_drive(tmp_path / "d")
    assert drive_start(open_drive(root)) is None
    assert drive_start(with_start(root, "2026-05-04T09:12:03.2Z")) == datetime(2026, 5, 4, 9, 12, 3, 200000,
                                                                               tzinfo=timezone.utc)
    assert drive_start(with_start(root, "2026-05-04T09:12:03+02:00")).utcoffset() == timedelta(hours=2)
    with pytest.raises(DriveFormatError, match=r"drive.json, field 'start_time': 'yesterday' is not an ISO 8601"):
        drive_start(with_start(root, "yesterday"))
    with pytest.raises(DriveFormatError, match="start_time"):
        drive_start(with_start(root, 1714813923))


class _Best:
    def __init__(self, pair_id, bbox):
        self.pair_id, self.bbox = pair_id, bbox


class _Sign:
    def __init__(self, sign_id, pair_id, bbox):
        self.sign_id, self.best = sign_id, _Best(pair_id, bbox)


def test_a_crop_per_sign_is_the_region_around_its_box_in_the_best_pair(tmp_path):
    root = make_drive(tmp_path / "d", n_pairs=2)
    yy, xx = np.mgrid[0:48, 0:64]
    smooth = np.dstack([xx * 4, yy * 5, 255 - xx * 2]).astype(np.uint8)  # JPEG keeps a smooth image
    cv2.imwrite(str(root / "left" / "000001.png"), smooth)
    drive = open_drive(root)
    signs = [_Sign(1, "000001", (20, 10, 8, 8)), _Sign(2, "000000", (0, 0, 4, 4)), _Sign(3, "nope", (0, 0, 4, 4))]
    warnings = []
    written = write_sign_crops(drive, signs, tmp_path / "crops", warn=warnings.append)
    assert written == {1: "sign_00001.jpg", 2: "sign_00002.jpg"}
    assert len(warnings) == 1 and "nope" in warnings[0]
    x, y, w, h = crop_box((20, 10, 8, 8), drive.image_size)
    crop = cv2.imread(str(tmp_path / "crops" / "sign_00001.jpg"))
    assert crop.shape[:2] == (h, w)
    left = drive.load_left(drive.pair("000001"))[y:y + h, x:x + w]
    assert np.abs(crop.astype(int) - left.astype(int)).mean() < 3
    assert crop_box((0, 0, 4, 4), (64, 48), min_px=120) == (0, 0, 64, 48)  # clipped to the image


def test_writing_crops_stops_with_cancelled_like_every_long_operation(tmp_path):
    drive = open_drive(make_drive(tmp_path / "d", n_pairs=2))
    signs = [_Sign(1, "000001", (20, 10, 8, 8)), _Sign(2, "000000", (0, 0, 4, 4))]
    asked = []

    def is_cancelled():  # cancelled after the first pair's crops
        asked.append(1)
        return len(asked) > 1

    with pytest.raises(Cancelled, match="writing sign crops cancelled"):
        write_sign_crops(drive, signs, tmp_path / "crops", is_cancelled)
    assert sorted(p.name for p in (tmp_path / "crops").iterdir()) == ["sign_00001.jpg"]
