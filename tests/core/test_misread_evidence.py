"""Per-observation evidence of misread fused signs, on constructed observations."""

import numpy as np
from test_fusion import CAMERA

from signmapper_core.drive.reader import PairRecord
from signmapper_core.evaluation.accuracy import evaluate
from signmapper_core.evaluation.misread_evidence import (
    NOT_A_CANDIDATE,
    false_positive_lines,
    misread_lines,
    position_lines,
)
from signmapper_core.fusion.signs import Observation, fuse_observations
from signmapper_core.geometry import Pose
from signmapper_core.pipeline.detection import Detection

WEST = np.array([-1.0, 0.0, 0.0])


def observe(pos, pair_index, template_id, scores, shape="circle"):
    camera = np.array([2.0 * pair_index, 0.0, 2.4])
    depth = float(np.linalg.norm(np.asarray(pos[:2]) - camera[:2]))
    detection = Detection(template_id, "", "red", shape, 0.6, 0.6, "normal", 0.95, scores[template_id], "accepted",
                          500.0, 400.0, (10, 10, 40 + pair_index, 42), depth, np.asarray(pos, float), scores=scores,
                          normal_world=WEST)
    record = PairRecord(pair_index, f"p{pair_index:03d}", 0.2 * pair_index, Pose(*camera, 90.0, 0.0, 0.0),
                        None, None, None)
    return Observation(detection, record)


def test_misread_sign_lists_each_observation_with_the_true_ids_score_and_a_right_sign_is_not_listed():
    misread, right = [20.0, 3.0, 2.5], [40.0, 3.0, 2.5]
    obs = [observe(misread, 3, "2.07", {"2.07": 0.73, "2.11": 0.02, "2.20-10": 0.10}),
           observe(misread, 4, "3.01", {"3.01": 0.95}, shape="octagon"),
           observe(misread, 5, "2.07", {"2.07": 0.57, "2.11": 0.01})]
    obs += [observe(right, k, "2.01", {"2.01": 0.97, "2.02": 0.01}) for k in (13, 14)]
    signs = fuse_observations(obs, CAMERA)
    reference_ids = ["2.11", "2.01"]
    report = evaluate([s.position for s in signs], [s.template_id for s in signs], [misread, right], reference_ids,
                      np.array([[0.0, 0.0], [60.0, 0.0]]), 0.75)
    lines = misread_lines(signs, reference_ids, report.match, top=2)
    assert len(lines) == 4  # one heading, three observations: the right sign has none
    assert lines[0].startswith("  sign 1: true 2.11, mapped 2.07") and "3 observations" in lines[0]
    assert "pair p003: read 2.07 (0.73" in lines[1] and "true id 2.11: 0.02" in lines[1]
    assert "best: 2.07 0.73, 2.20-10 0.10" in lines[1]
    assert "read 3.01" in lines[2] and f"true id 2.11: {NOT_A_CANDIDATE}" in lines[2] and "octagon" in lines[2]
    assert "45x42 px at (10, 10), 10.4 m" in lines[3]  # box 40 + pair index wide; 10 m ahead, 3 m aside
    assert false_positive_lines(signs, report.match) == []  # both fused signs lie on a reference sign


def test_false_positive_lists_its_observations_without_a_true_id_and_matched_signs_are_not_listed():
    nowhere, right = [70.0, -3.0, 2.5], [40.0, 3.0, 2.5]
    obs = [observe(nowhere, k, "2.30-50", {"2.30-50": 0.93, "2.30-60": 0.05}) for k in (30, 31)]
    obs += [observe(right, k, "2.01", {"2.01": 0.97}) for k in (13, 14)]
    signs = fuse_observations(obs, CAMERA)
    report = evaluate([s.position for s in signs], [s.template_id for s in signs], [right], ["2.01"],
                      np.array([[0.0, 0.0], [80.0, 0.0]]), 0.75)
    lines = false_positive_lines(signs, report.match, top=1)
    assert len(lines) == 3  # one heading, two observations
    assert "no reference sign within reach, mapped 2.30-50 (accepted" in lines[0] and "2 observations" in lines[0]
    assert lines[1].startswith("    pair p030: read 2.30-50 (0.93") and "70x42 px at (10, 10)" in lines[1]
    assert "true id" not in lines[1] and lines[1].endswith("best: 2.30-50 0.93")
    assert "pair p031" in lines[2]
    assert misread_lines(signs, ["2.01"], report.match) == []


class Truth:
    def __init__(self, template_id, position):
        self.template_id, self.position = template_id, position


def test_position_lines_list_the_signs_off_by_more_than_the_limit_largest_first_with_their_views():
    near, far_off, exact = [20.0, 3.0, 2.5], [40.0, 3.0, 2.5], [60.0, 3.0, 2.5]
    obs = [observe([20.0, 3.1, 2.5], k, "2.01", {"2.01": 0.97}) for k in (3, 4)]
    obs += [observe([40.0, 3.0, 2.9], k, "2.01", {"2.01": 0.97}) for k in (13, 14, 15)]
    obs += [observe(exact, k, "2.01", {"2.01": 0.97}) for k in (23, 24)]
    signs = fuse_observations(obs, CAMERA)
    reference = [Truth("2.01", near), Truth("2.02", far_off), Truth("2.01", exact)]
    report = evaluate([s.position for s in signs], [s.template_id for s in signs], [t.position for t in reference],
                      [t.template_id for t in reference], np.array([[0.0, 0.0], [80.0, 0.0]]), 0.75)
    lines = position_lines(signs, reference, report.match, report.differences, 0.05)
    assert len(lines) == 1 + 3 + 1 + 2  # the exact sign is not listed; each listed sign has its views
    assert lines[0].startswith("  sign 2: true 2.02, mapped 2.01") and "3D 0.40 m" in lines[0]
    assert "height +0.40" in lines[0] and "across +0.00" in lines[0]
    assert "true id 2.02: not a candidate" in lines[1]
    assert lines[4].startswith("  sign 1: true 2.01") and "3D 0.10 m" in lines[4]
    assert "across -0.10" in lines[4]  # 0.1 m further left of the driving direction (north is left going east)
    assert len(position_lines(signs, reference, report.match, report.differences, 0.0)) == 1 + 3 + 1 + 2 + 1 + 2
