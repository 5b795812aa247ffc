"""Tables 1 and 2 on hand-made references with known offsets."""

import numpy as np
import pytest

from signmapper_core.evaluation.accuracy import (
    combine_reports,
    decompose,
    evaluate,
    match_to_reference,
    track_directions,
)

TRAJ = np.array([[0.0, 0.0], [10.0, 0.0], [20.0, 0.0], [30.0, 0.0]])  # driving east
REF = np.array([[5.0, 4.0, 2.0], [12.0, -4.0, 2.5], [25.0, 4.0, 1.8]])
IDS = ["2.01", "3.03", "2.30-50"]


def test_every_sign_moved_5cm_across_track():
    moved = REF + [0.0, -0.05, 0.0]  # south = right of an eastward drive
    report = evaluate(moved, IDS, REF, IDS, TRAJ, radius_m=1.0)
    across = report.table2["across"]
    assert across.mean == pytest.approx(0.05) and across.std == pytest.approx(0.0, abs=1e-12)
    assert across.max_abs == pytest.approx(0.05)
    assert report.table2["along"].max_abs == pytest.approx(0.0, abs=1e-12)
    assert report.table2["3d"].rms == pytest.approx(0.05)
    t1 = report.table1
    assert (t1.reference_signs, t1.detected_signs, t1.correctly_classified_signs) == (3, 3, 3)
    assert t1.detection_rate == 1.0 and t1.false_positive_detections == 0


def test_missing_sign_drops_detection_rate_by_exactly_one():
    report = evaluate(REF[[0, 2]], [IDS[0], IDS[2]], REF, IDS, TRAJ)
    assert report.table1.detected_signs == 2
    assert report.table1.detection_rate == pytest.approx(2 / 3)


def test_false_positive_and_misclassification():
    mapped = np.vstack([REF, [[15.0, 10.0, 2.0]]])
    report = evaluate(mapped, ["2.01", "3.04", "2.30-50", "2.01"], REF, IDS, TRAJ)
    assert report.table1.false_positive_detections == 1
    assert report.table1.correctly_classified_signs == 2
    assert report.table1.classification_rate == pytest.approx(2 / 3)
    assert report.confusions == [("3.03", "3.04")]
    assert list(report.match) == [0, 1, 2, -1]


def test_several_detections_per_sign_vote_and_count_duplicates():
    mapped = np.vstack([REF[0], REF[0] + 0.02, REF[0] - 0.02, REF[1]])
    report = evaluate(mapped, ["2.01", "2.01", "2.02", "3.03"], REF, IDS, TRAJ)
    assert report.table1.detected_signs == 2
    assert report.table1.correctly_classified_signs == 2  # majority 2.01
    assert report.table1.duplicates == 1


def test_along_track_follows_the_trajectory_direction():
    traj = np.array([[0.0, 0.0], [0.0, 10.0], [0.0, 20.0]])  # driving north
    along = track_directions(np.array([[3.0, 5.0]]), traj)
    np.testing.assert_allclose(along, [[0.0, 1.0]])
    comps = decompose(np.array([[0.1, 0.2, -0.3]]), along)
    np.testing.assert_allclose(comps[0, :3], [0.1, 0.2, -0.3])  # east is right of a northward drive


def test_match_radius():
    assert list(match_to_reference(np.array([[5.0, 4.6, 2.0]]), REF, radius_m=0.5)) == [-1]
    assert list(match_to_reference(np.array([[5.0, 4.4, 2.0]]), REF, radius_m=0.5)) == [0]


def test_combined_reports_add_counts_and_pool_differences():
    a = evaluate(REF + [0.0, -0.05, 0.0], IDS, REF, IDS, TRAJ)
    b = evaluate(REF[:1] + [0.0, 0.0, 0.1], IDS[:1], REF, IDS, TRAJ)
    both = combine_reports([a, b])
    assert both.table1.reference_signs == 6 and both.table1.detected_signs == 4
    assert both.table2["3d"].n == 4
    assert both.table2["3d"].max_abs == pytest.approx(0.1)


def test_reference_sign_faces_trajectory():
    from signmapper_core.evaluation.visibility import faces_trajectory

    traj = np.array([[float(x), 0.0] for x in range(0, 60, 2)])  # driving east along y = 0
    sign = (30.0, 4.0)  # left of the road
    assert faces_trajectory(sign, 250.0, traj)  # looking WSW, towards the approaching car
    assert not faces_trajectory(sign, 70.0, traj)  # its back-to-back twin looks ENE, away from the road
    assert not faces_trajectory((30.0, 40.0), 180.0, traj)  # too far from the drive
