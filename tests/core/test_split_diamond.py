"""End of the priority road (3.04): its black bar along the diagonal cuts the yellow into two halves.

Neither half fits an outline, so before the halves were merged along the
diagonal the sign never became a candidate at all (found on held-out drive 1023;
these constructed scenes are the test). Official artwork of the shipped catalogue.
"""

import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, constant_depth, noisy_background, paste

from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.colour import find_colour_segments, split_face_merges
from signmapper_core.pipeline.face_extent import colour_part

CONFIG = PipelineConfig()
SIDE_M = 0.707  # normal format of 3.03 and 3.04


def _scene(catalogue, template_id, n):
    image = noisy_background(level=95, sigma=10)
    bgr, alpha = catalogue.render(template_id, n)
    paste(image, bgr, alpha, 250, 120)
    return image


def test_the_yellow_of_3_04_reads_as_a_diamond_like_that_of_3_03(catalogue):
    extent_303, shape_303 = colour_part(catalogue, "3.03", "yellow", CONFIG.colour.hsv_ranges)
    extent_304, shape_304 = colour_part(catalogue, "3.04", "yellow", CONFIG.colour.hsv_ranges)
    assert shape_303 == shape_304 == "diamond"
    assert np.allclose(extent_303, extent_304, atol=0.03)


def test_halves_cut_along_the_diagonal_are_merged_into_the_diamond(catalogue):
    n = 120
    segments = find_colour_segments(_scene(catalogue, "3.04", n), None, CONFIG, None)
    halves = [s for s in segments if s.colour == "yellow"]
    assert len(halves) == 2
    ((merged, _, _),) = split_face_merges(segments, CONFIG)
    ys, xs = np.nonzero(catalogue.render("3.04", n)[0][..., 2] > 200)  # the yellow's extent in the face
    assert merged.bbox[2] >= 0.9 * (max(halves[0].bbox[0] + halves[0].bbox[2], halves[1].bbox[0] + halves[1].bbox[2])
                                    - min(halves[0].bbox[0], halves[1].bbox[0]))


@pytest.mark.parametrize("template_id", ["3.04", "3.03"])
@pytest.mark.parametrize("n", [40, 70, 100])  # 10.6, 6.1 and 4.2 m: inside the 4-14 m search space
def test_priority_road_signs_are_detected_and_told_apart(catalogue, template_id, n):
    image = _scene(catalogue, template_id, n)
    depth = constant_depth(SIDE_M * CAMERA.fx / n)
    detections = detect_pair(image, depth, None, CAMERA, POSE, catalogue, CONFIG)
    (det,) = [d for d in detections if box_iou(d.bbox, (250, 120, n, n)) > 0.8]
    assert det.template_id == template_id and det.format == "normal"
    assert det.status == "accepted"
