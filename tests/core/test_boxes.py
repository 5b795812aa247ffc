"""Pixel boxes: overlap measures the pipeline's steps decide on."""

import pytest

from signmapper_core.pipeline.boxes import box_iou, share_inside, smaller_box_cover


def test_a_box_inside_another_is_wholly_covered_however_small():
    assert smaller_box_cover((0, 0, 100, 100), (10, 10, 20, 20)) == 1.0
    assert box_iou((0, 0, 100, 100), (10, 10, 20, 20)) == pytest.approx(0.04)


def test_a_plate_and_a_reading_reaching_past_it_share_the_plates_rows():
    plate, reading = (730, 15, 150, 75), (733, 20, 144, 105)  # a white-step reading grown into the sign below
    assert smaller_box_cover(plate, reading) == pytest.approx(144 * 70 / (150 * 75))


def test_boxes_apart_share_nothing():
    assert smaller_box_cover((0, 0, 10, 10), (10, 0, 10, 10)) == 0.0
    assert smaller_box_cover((0, 0, 0, 0), (0, 0, 10, 10)) == 0.0


def test_the_share_of_one_box_inside_another_is_read_from_the_first():
    assert share_inside((10, 10, 20, 20), (0, 0, 100, 100)) == 1.0
    assert share_inside((0, 0, 100, 100), (10, 10, 20, 20)) == pytest.approx(0.04)
    assert share_inside((0, 0, 0, 0), (0, 0, 10, 10)) == 0.0
