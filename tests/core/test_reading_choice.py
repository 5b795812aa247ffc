"""Which of a face's readings stands for it (``detect.most_evident_per_face``): readings of one box are told
apart by the network's logit, not by their scores, which are probabilities among each reading's own candidates."""

import math

from signmapper_core.pipeline.classify import ClassificationResult
from signmapper_core.pipeline.detect import most_evident_per_face

BOX, OTHER_BOX = (1370, 353, 97, 138), (1349, 284, 139, 276)


def _reading(face, template_id, score, logit):
    return ("match of " + template_id, face, ClassificationResult(template_id, score, {template_id: score}, logit))


def test_of_one_box_the_reading_the_network_sees_most_clearly_stays():
    measured = _reading(BOX, "4.22", 0.97, 2.6)  # among boards without 4.18: fewer good rivals, a higher score
    standard = _reading(BOX, "4.18", 0.92, 3.8)
    grown = _reading(OTHER_BOX, "2.59.1-P", 0.40, 0.5)
    kept = most_evident_per_face([measured, grown, standard])
    assert [r[2].template_id for r in kept] == ["2.59.1-P", "4.18"]  # in their order, one per box


def test_readings_without_a_logit_all_stay():
    # template matching gives no logit: its scores are what there is to compare
    a, b = _reading(BOX, "4.22", 0.97, math.inf), _reading(BOX, "4.18", 0.92, math.inf)
    assert most_evident_per_face([a, b]) == [a, b]


def test_equal_logits_keep_the_earlier_reading():
    a, b = _reading(BOX, "4.08", 0.99, 5.0), _reading(BOX, "4.08.1", 0.99, 5.0)
    assert most_evident_per_face([a, b]) == [a]
