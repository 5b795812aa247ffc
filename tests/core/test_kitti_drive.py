"""The real KITTI drive 2011_09_26_drive_0001 (Karlsruhe, 108 pairs) mapped end to end against labels by hand.

KITTI is CC BY-NC-SA: its images are never in this repository. ``make kitti-drive KITTI_REPO=<git copy>`` puts the
drive in a cache outside it ($SIGNMAPPER_KITTI_CACHE, else ~/.cache/sign_mapper/kitti); without it every test here
is skipped, saying so (``pytest -rs``). The labels (tests/data/kitti/2011_09_26_drive_0001_labels.csv, how they were
made and what the drive shows: tests/data/kitti/README.md) are boxes in the left images; a fused sign is
*at* a labelled sign when its position projects into that sign's box, grown by ``NEAR_SHARE`` of the box's size,
in some labelled frame, and it is given the label it projects nearest to (signs to signs, plates to plates).

The drive is imported with the KITTI preset and mapped the way ``python -m signmapper_core.map`` maps it, once with
the defaults (which reach the no-stopping sign, 2.49, at least 20 m away, at the frame's edge) and once with the
depth range fixed to 3-30 m.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from scripts.kitti_drive import cache_folder, drive_folder
from signmapper_core.drive.reader import open_drive
from signmapper_core.evaluation.accuracy import decompose, track_directions
from signmapper_core.fusion.mounting import camera_height_above_road, road_height_near
from signmapper_core.geometry import world_to_pixel
from signmapper_core.importdrive.importer import ImportOptions, import_drive
from signmapper_core.importdrive.kitti import kitti_source, utm_crs
from signmapper_core.plates.fusion import is_plate_feature
from signmapper_core.run.mapping import map_drive
from signmapper_core.run.setup import FAR, NEAR, assemble_run
from signmapper_core.statuses import ACCEPTED

LABELS = Path(__file__).resolve().parents[1] / "data" / "kitti" / "2011_09_26_drive_0001_labels.csv"
KITTI = drive_folder(cache_folder())
NOT_A_SIGN = "not_a_sign"
PLATE = "plate"
NO_STOPPING = "no_stopping"  # the sign key of the 2.49 (German 283)
NEAR_SHARE = 0.5  # a box grown by half its width and height on each side
INSIDE_TOLERANCE_PX = 2.0  # the 2.49's projection in its own boxes: labels drawn by eye, to a pixel or two
ROAD_CLEARANCE_M = (1.5, 3.0)  # the 2.49's centre above the road (labels triangulated with the poses: 1.95 m)
# the 2.49's offset to the left of the trajectory: 16.4 m triangulated from the labelled boxes with the OXTS poses,
# 18.1 and 18.6 m as mapped at NEAR=3 FAR=30 (2026-12-06; stereo puts it ~10 % farther along its line of sight)
LEFT_OFFSET_M = (15.0, 20.0)
DEPTH_RANGES = {"defaults": {}, "near 3 far 30": {NEAR: 3.0, FAR: 30.0}}

pytestmark = pytest.mark.slow


@dataclass(frozen=True)
class Label:
    frame: int
    box: tuple  # x0, y0, x1, y1: pixel columns x0..x1-1 and rows y0..y1-1 of the left image
    ssv_id: str
    key: str  # one per physical sign

    def grown(self, share: float, pixels: float = 0.0) -> tuple:
        """The box's extent in pixel coordinates (centres at integers), grown by ``share`` of its size + ``pixels``."""
        x0, y0, x1, y1 = self.box
        dx, dy = share * (x1 - x0) + pixels, share * (y1 - y0) + pixels
        return x0 - 0.5 - dx, y0 - 0.5 - dy, x1 - 0.5 + dx, y1 - 0.5 + dy

    def centre(self) -> np.ndarray:
        x0, y0, x1, y1 = self.box
        return np.array([(x0 + x1) / 2 - 0.5, (y0 + y1) / 2 - 0.5])


def read_labels(path: Path = LABELS) -> list[Label]:
    with path.open(newline="", encoding="utf-8") as f:
        return [Label(int(r["frame"]), tuple(int(r[k]) for k in ("x0", "y0", "x1", "y1")), r["ssv_id"], r["sign_key"])
                for r in csv.DictReader(f)]


def inside(uv, extent) -> bool:
    return extent[0] <= uv[0] <= extent[2] and extent[1] <= uv[1] <= extent[3]


def projection(drive, sign, frame: int):
    """(u, v) of the sign's position in the left image of pair ``frame``, None behind the camera."""
    u, v, z = world_to_pixel(drive.camera, drive.pairs[frame].pose, sign.position)
    return (float(u), float(v)) if z > 0 else None


def label_of(drive, labels, sign):
    """The key of the label the sign projects nearest to, within its grown box (see module); None if none."""
    best = None
    for label in labels:
        if (label.ssv_id == PLATE) != is_plate_feature(sign):
            continue
        uv = projection(drive, sign, label.frame)
        if uv is None or not inside(uv, label.grown(NEAR_SHARE)):
            continue
        size = np.hypot(label.box[2] - label.box[0], label.box[3] - label.box[1])
        distance = np.linalg.norm(np.array(uv) - label.centre()) / size
        if best is None or distance < best[0]:
            best = (distance, label.key)
    return None if best is None else best[1]


@dataclass
class Mapped:
    drive: object
    result: object
    labels: list
    keys: dict  # sign_id -> label key or None

    def at(self, key: str) -> list:
        return [s for s in self.result.signs if self.keys[s.sign_id] == key]

    def describe(self, signs) -> str:
        return "; ".join(f"#{s.sign_id} {s.template_id} {s.status} at {np.round(s.position, 2).tolist()} seen in "
                         f"pairs {[o.pair_index for o in self.result.detections_of(s)]}" for s in signs)


@pytest.fixture(scope="module")
def kitti_drive(tmp_path_factory):
    """The drive imported with the KITTI preset (``python -m signmapper_core.importdrive OUT --kitti ...``)."""
    if not KITTI.is_dir():
        pytest.skip(f"no KITTI drive in {KITTI}: make kitti-drive KITTI_REPO=<git copy> (tests/data/kitti/README.md)")
    source = kitti_source(KITTI)
    out = tmp_path_factory.mktemp("kitti") / "drive"
    import_drive(out, source, ImportOptions(output_crs=utm_crs(source)))
    return open_drive(out)


def _map(drive, choices) -> Mapped:
    run = assemble_run(choices)
    result = map_drive(drive, run.catalogue, run.config, fusion=run.fusion)
    labels = read_labels()
    return Mapped(drive, result, labels, {s.sign_id: label_of(drive, labels, s) for s in result.signs})


@pytest.fixture(scope="module")
def by_defaults(kitti_drive) -> Mapped:
    return _map(kitti_drive, DEPTH_RANGES["defaults"])


@pytest.fixture(scope="module")
def near_3_far_30(kitti_drive) -> Mapped:
    return _map(kitti_drive, DEPTH_RANGES["near 3 far 30"])


@pytest.fixture(params=tuple(DEPTH_RANGES))
def mapped(request) -> Mapped:
    return request.getfixturevalue({"defaults": "by_defaults", "near 3 far 30": "near_3_far_30"}[request.param])


def test_the_labels_are_whole():
    """Every box is inside the 1242x375 image and at least 20 px on its longer side; one id per sign key."""
    labels = read_labels()
    assert len({label.key for label in labels}) == 6
    for label in labels:
        x0, y0, x1, y1 = label.box
        assert 0 <= x0 < x1 <= 1242 and 0 <= y0 < y1 <= 375 and max(x1 - x0, y1 - y0) >= 20, label
    ids = {}
    for label in labels:
        assert ids.setdefault(label.key, label.ssv_id) == label.ssv_id, label


def test_no_accepted_sign_away_from_a_labelled_sign(mapped):
    stray = [s for s in mapped.result.signs if s.status == ACCEPTED and mapped.keys[s.sign_id] is None]
    assert stray == [], f"accepted where no sign is labelled: {mapped.describe(stray)}"


def test_the_car_wheel_is_not_accepted(mapped):
    wheel = [s for s in mapped.at("car_wheel") if s.status == ACCEPTED]
    assert wheel == [], f"the parked car's wheel (frames 68-70) accepted: {mapped.describe(wheel)}"


def test_no_accepted_sign_carries_a_wrong_id(mapped):
    ids = {label.key: label.ssv_id for label in mapped.labels}
    wrong = [s for s in mapped.result.signs if s.status == ACCEPTED and mapped.keys[s.sign_id] is not None
             and s.template_id != ids[mapped.keys[s.sign_id]] and not is_plate_feature(s)]
    assert wrong == [], f"accepted with another id than labelled: {mapped.describe(wrong)}"


def test_no_labelled_sign_is_mapped_twice(mapped):
    signs = {label.key for label in mapped.labels if label.ssv_id != NOT_A_SIGN}
    twice = {key: mapped.describe(mapped.at(key)) for key in signs if len(mapped.at(key)) > 1}
    assert twice == {}


def test_the_no_stopping_sign_is_one_accepted_2_49(mapped):
    """Issue 45: with the defaults it is seen only beyond 14 m, at the frame's left edge (the camera's reach); its
    far views stay one feature as the fusion gate follows their depth's uncertainty."""
    found = mapped.at(NO_STOPPING)
    assert [(s.template_id, s.status) for s in found] == [("2.49", ACCEPTED)], mapped.describe(found)


def test_the_2_49_is_placed_at_a_mounting_height(mapped):
    drive = mapped.drive
    centres = np.array([record.pose.centre for record in drive.pairs])
    camera_height = camera_height_above_road(drive.metadata)
    assert camera_height == pytest.approx(1.65)
    for sign in mapped.at(NO_STOPPING):
        above_road = sign.position[2] - road_height_near(sign.position, centres, camera_height)
        assert ROAD_CLEARANCE_M[0] <= above_road <= ROAD_CLEARANCE_M[1], mapped.describe([sign])


def test_the_2_49_is_placed_left_of_the_track(mapped):
    centres = np.array([record.pose.centre for record in mapped.drive.pairs])
    for sign in mapped.at(NO_STOPPING):
        nearest = centres[np.argmin(np.hypot(*(centres[:, :2] - sign.position[:2]).T))]
        along = track_directions(sign.position[:2], centres[:, :2])
        across = decompose(sign.position - nearest, along)[0, 0]  # positive to the right of the driving direction
        assert LEFT_OFFSET_M[0] <= -across <= LEFT_OFFSET_M[1], mapped.describe([sign])


def test_the_2_49_projects_into_its_boxes(mapped):
    """The 2.49, in every labelled frame it was seen in, lies in the labelled box."""
    boxes = {label.frame: label for label in mapped.labels if label.key == NO_STOPPING}
    checked = 0
    for sign in mapped.at(NO_STOPPING):
        for frame in {o.pair_index for o in mapped.result.detections_of(sign)} & set(boxes):
            uv = projection(mapped.drive, sign, frame)
            assert uv is not None and inside(uv, boxes[frame].grown(0.0, INSIDE_TOLERANCE_PX)), (frame, uv)
            checked += 1
    assert checked >= 2
