"""Which of a face's readings stands for it (``detect.most_evident_per_face``): readings of one face are told
apart by the network's logit, not by their scores, which are probabilities among each reading's own candidates."""

import math

from signmapper_core.pipeline.classify import ClassificationResult
from signmapper_core.pipeline.config import PipelineConfig
from signmapper_core.pipeline.detect import most_evident_per_face

BOX, OTHER_BOX = (1370, 353, 97, 138), (1349, 120, 139, 276)  # IoU 0.09
SAME_IOU = PipelineConfig().classification.same_sign_max_iou


def _reading(face, template_id, score, logit):
    return ("match of " + template_id, face, ClassificationResult(template_id, score, {template_id: score}, logit))


def test_of_one_box_the_reading_the_network_sees_most_clearly_stays():
    measured = _reading(BOX, "4.22", 0.97, 2.6)  # among boards without 4.18: fewer good rivals, a higher score
    standard = _reading(BOX, "4.18", 0.92, 3.8)
    grown = _reading(OTHER_BOX, "2.59.1-P", 0.40, 0.5)
    kept = most_evident_per_face([measured, grown, standard], SAME_IOU)
    assert [r[2].template_id for r in kept] == ["2.59.1-P", "4.18"]  # in their order, one per box


def test_readings_without_a_logit_all_stay():
    # template matching gives no logit: its scores are what there is to compare
    a, b = _reading(BOX, "4.22", 0.97, math.inf), _reading(BOX, "4.18", 0.92, math.inf)
    assert most_evident_per_face([a, b], SAME_IOU) == [a, b]


def test_equal_logits_keep_the_earlier_reading():
    a, b = _reading(BOX, "4.08", 0.99, 5.0), _reading(BOX, "4.08.1", 0.99, 5.0)
    assert most_evident_per_face([a, b], SAME_IOU) == [a]


def test_boxes_a_pixel_or_two_apart_are_one_face():
    # a cycle pointer placed by each entry's colour extent: the mountain-bike reading among two pointers
    # (seed 604, pair 18) and the skating pointer's, its box's one candidate, 3 px narrower
    skating = _reading((380, 555, 89, 17), "4.50.4", 1.0, 3.92)
    mountain_bike = _reading((377, 555, 92, 18), "4.50.3", 0.775, 5.23)
    tourist = _reading((374, 555, 95, 17), "0.1", 0.996, -0.43)
    kept = most_evident_per_face([tourist, mountain_bike, skating], SAME_IOU)
    assert [r[2].template_id for r in kept] == ["4.50.3"]


def test_boxes_overlapping_less_than_one_sign_stay_apart():
    sign, beside = (100, 100, 40, 40), (125, 100, 40, 40)  # IoU 0.23: two signs side by side
    a, b = _reading(sign, "2.02", 0.99, 6.0), _reading(beside, "2.01", 0.98, 4.0)
    assert most_evident_per_face([a, b], SAME_IOU) == [a, b]


def test_readings_of_other_shapes_are_left_to_the_outline():
    # a stop sign read with its white rim (its octagon) and, as a disc of the red alone, as no entry: the
    # outline's best fit decides between them later, the logit only among signs of one shape
    disc, with_rim = (100, 100, 40, 40), (96, 96, 48, 48)
    no_entry, stop = _reading(disc, "2.02", 0.99, 6.0), _reading(with_rim, "3.01", 0.98, 4.0)
    shapes = {"2.02": "circle", "3.01": "octagon"}.get
    assert most_evident_per_face([stop, no_entry], SAME_IOU, shapes) == [stop, no_entry]
    assert most_evident_per_face([stop, no_entry], SAME_IOU) == [no_entry]


def test_placements_of_one_drawing_keep_the_face_its_colour_implies():
    # a priority road 3.03 at 70 px (tests/core/test_split_diamond.py): its face as the yellow's extent implies,
    # and its rim's inner edge 5 px inside, read at a higher logit; the logit does not choose between placements
    face = _reading((251, 121, 68, 68), "3.03", 0.994, 6.27)
    inner_rim = _reading((255, 125, 60, 60), "3.03", 0.998, 6.91)
    drawn = {id(face): ("3.03", (0.0, 0.0, 1.0, 1.0)), id(inner_rim): ("3.03", (0.0, 0.0, 1.0, 1.0))}.get
    assert most_evident_per_face([face, inner_rim], SAME_IOU, None, lambda r: drawn(id(r))) == [face]
    assert most_evident_per_face([face, inner_rim], SAME_IOU) == [inner_rim]  # by the logit alone
    # a rim read clearly better than the colour's placement stands for the drawing
    loose = _reading((251, 121, 68, 68), "3.03", 0.90, 6.27)
    drawn = {id(loose): ("3.03", (0.0, 0.0, 1.0, 1.0)), id(inner_rim): ("3.03", (0.0, 0.0, 1.0, 1.0))}.get
    assert most_evident_per_face([loose, inner_rim], SAME_IOU, None, lambda r: drawn(id(r))) == [inner_rim]
