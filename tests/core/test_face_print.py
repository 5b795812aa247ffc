"""Print on a face: what tells a sign nobody catalogued from a plain coloured patch."""

import cv2
import numpy as np
import pytest

from signmapper_core.pipeline.face_print import print_share


def test_a_plain_patch_has_no_print_and_a_symbol_has():
    face = np.full((100, 100, 3), (170, 80, 20), np.uint8)  # plain blue
    assert print_share(face, (0, 0, 100, 100), 0.1, 50, 150) == 0.0
    cv2.arrowedLine(face, (20, 50), (80, 50), (255, 255, 255), 8, tipLength=0.4)
    assert print_share(face, (0, 0, 100, 100), 0.1, 50, 150) > 0.03


def test_the_outline_itself_lies_in_the_cut_off_margin():
    face = np.zeros((100, 100, 3), np.uint8)
    face[10:90, 10:90] = (170, 80, 20)  # a plain patch on black: only its outline is an edge
    assert print_share(face, (5, 5, 90, 90), 0.1, 50, 150) == 0.0  # the box a little larger than the patch
    assert print_share(face, (5, 5, 90, 90), 0.0, 50, 150) > 0.0


@pytest.mark.parametrize("bbox", [(0, 0, 2, 2), (95, 95, 10, 10)])
def test_a_part_too_small_or_off_the_image_has_none(bbox):
    assert print_share(np.full((100, 100, 3), 128, np.uint8), bbox, 0.2, 50, 150) == 0.0
