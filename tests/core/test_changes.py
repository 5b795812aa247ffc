"""Change detection without images: a straight drive, an inventory and mapped signs placed by hand."""

from pathlib import Path

import numpy as np
import pytest
from drive_fixtures import START, straight_poses

from signmapper_core.changes.compare import (
    CHANGED,
    CONFIRMED,
    MISSING,
    MOVED,
    NEW,
    NOT_COVERED,
    ChangeConfig,
    InventorySign,
    MappedSign,
    compare,
)
from signmapper_core.changes.report import report_html
from signmapper_core.changes.schema import values
from signmapper_core.drive.reader import PairRecord
from signmapper_core.geometry import Camera

CAMERA = Camera(width=1920, height=1080, fx=1750.0, fy=1750.0, cx=959.5, cy=539.5, baseline_m=0.9)
RECORDS = [PairRecord(i, pid, t, pose, Path(f"left/{pid}.jpg"), None, None)
           for i, (pid, t, pose) in enumerate(straight_poses(60))]  # heading east, 2 m steps, 118 m
E0, N0, H0 = START
WEST = 270.0  # faces the vehicle driving east


def at(ahead_m, right_m=4.0, dz=0.0):
    """A point ``ahead_m`` east of the start, ``right_m`` to the right (south) of the track."""
    return np.array([E0 + ahead_m, N0 - right_m, H0 + dz])


def inv(key, type_id, position, facing=WEST):
    return InventorySign(key, type_id, np.asarray(position, float), facing, 0.6, 0.6, label=type_id)


def mapped(sign_id, type_id, position):
    return MappedSign(sign_id, type_id, np.asarray(position, float), "accepted", WEST, f"{sign_id:06d}", 900.0,
                      500.0, (870, 470, 60, 60))


@pytest.fixture(scope="module")
def report():
    inventory = [
        inv("A", "2.30-50", at(20)),
        inv("B", "3.05", at(30)),
        inv("C", "2.01", at(40)),
        inv("D", "2.02", at(50)),  # gone
        inv("E", "2.02", at(300)),  # beyond the drive
        inv("F", "2.02", at(60), facing=90.0),  # faces away from the vehicle
        inv("G", "5.01", at(70)),  # a plate: not in the catalogue
        inv("I", "2.30-50", at(80, dz=0.35)),  # stacked pair: upper
        inv("J", "2.01", at(80, dz=-0.35)),  # lower, its type changed in reality
    ]
    found = [
        mapped(1, "2.30-50", at(20.05, 4.03)),
        mapped(2, "3.05", at(31.0)),
        mapped(3, "2.04", at(40.1)),
        mapped(4, "2.02", at(90)),  # not in the inventory
        mapped(5, "2.30-50", at(80, dz=0.33)),
        mapped(6, "3.05", at(80.02, dz=-0.36)),
    ]
    mappable = {"2.30-50", "3.05", "2.01", "2.02", "2.04"}
    return compare(inventory, found, CAMERA, RECORDS, ChangeConfig(), mappable_types=mappable)


def verdicts(report):
    return {(c.inventory.key if c.inventory else f"mapped {c.mapped.sign_id}"): c.verdict for c in report.changes}


def test_every_verdict_as_expected(report):
    assert verdicts(report) == {"A": CONFIRMED, "B": MOVED, "C": CHANGED, "D": MISSING, "E": NOT_COVERED,
                                "F": NOT_COVERED, "G": NOT_COVERED, "I": CONFIRMED, "J": CHANGED,
                                "mapped 4": NEW}
    assert report.counts() == {CONFIRMED: 2, MOVED: 1, CHANGED: 2, MISSING: 1, NOT_COVERED: 3, NEW: 1}


def test_matches_carry_the_mapped_sign_and_distance(report):
    by_key = {c.inventory.key: c for c in report.changes if c.inventory}
    assert by_key["A"].mapped.sign_id == 1 and by_key["A"].distance_m == pytest.approx(np.hypot(0.05, 0.03))
    assert by_key["B"].mapped.sign_id == 2 and by_key["B"].distance_m == pytest.approx(1.0)
    assert by_key["C"].mapped.template_id == "2.04"
    assert by_key["J"].mapped.sign_id == 6 and by_key["J"].height_difference_m == pytest.approx(-0.01)
    assert by_key["I"].mapped.sign_id == 5  # the stacked 3.05 below is not taken for the upper sign


def test_missing_sign_names_the_pairs_that_should_show_it(report):
    missing = report.of(MISSING)[0]
    # 50 m ahead, 4 m right: in view from where it is 4-14 m ahead with its whole face in the image
    ids = missing.visible_pair_ids
    assert ids and ids == sorted(ids)
    ahead = [50.0 - 2.0 * int(pid) for pid in ids]
    assert min(ahead) >= 4.0 - 1e-9 and max(ahead) <= 14.0 + 1e-9
    best = missing.best_view
    assert best.depth_m == pytest.approx(min(ahead)) and 0 <= best.bbox[0] and best.bbox[0] + best.bbox[2] <= 1919
    row = values(missing)
    assert row["verdict"] == MISSING and row["pair_id"] == best.pair_id and row["status"] == "review"
    assert row["n_pairs"] == len(ids) and row["visible_pairs"] == " ".join(ids)


def test_not_covered_has_no_pairs_and_says_why(report):
    by_key = {c.inventory.key: c for c in report.changes if c.inventory}
    assert by_key["E"].views == [] and "never in view" in by_key["E"].reason
    assert by_key["F"].views == []
    assert "cannot be mapped" in by_key["G"].reason


def test_sign_without_height_is_placed_at_camera_height_and_compared_planimetrically():
    sign = InventorySign("X", "2.02", np.array([E0 + 50, N0 - 4, np.nan]), None)
    report = compare([sign], [mapped(1, "2.02", at(50.2, dz=0.8))], CAMERA, RECORDS)
    change = report.changes[0]
    assert change.verdict == CONFIRMED and change.height_difference_m is None and change.views


def test_html_report_counts_and_plots(report):
    page = report_html(report, [(r.pose.easting, r.pose.northing) for r in RECORDS], "t")
    assert "<svg" in page and page.count("<circle") >= 9 and "missing" in page
    assert "2 confirmed, 1 moved, 2 changed, 1 missing, 3 not covered; 1 new" in page


def test_wrong_tolerances_are_refused():
    with pytest.raises(ValueError, match="tolerance"):
        compare([], [], CAMERA, RECORDS, ChangeConfig(tolerance_m=6.0, move_radius_m=5.0))
