"""Face boxes measured in the image on constructed scenes: a field's ring by its outer edge, small rimmed parts.

Rings, borders and rims differ between sign designs (Germany's prohibition signs carry a
white border around the red ring, its priority road a yellow diamond on half the face), so
the face box taken from the Swiss template's extent can miss the face; these tests build
such faces and check that the colour step also offers the box measured in the image.
"""

import cv2
import numpy as np
import pytest
from pipeline_scenes import noisy_background, paste
from test_bright_fields import _at_dusk
from test_pipeline_real_conditions import _priority_sign

from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.candidates import face_candidates
from signmapper_core.pipeline.config import ColourConfig, RimConfig
from signmapper_core.pipeline.face_extent import face_bbox, hole_candidates, ring_edge_bbox

CATALOGUE = "reference drawing"  # scenes and templates of our reference drawing (tests/conftest.py)


def _bordered_disc_at_dusk(catalogue, template_id, n, border, x=300, y=150):
    """A round face of ``n`` px inside a white border to ``border`` x n (the German design), at dusk.

    Returns the image and the face box including the border.
    """
    size = int(round(n * border))
    size += (size - n) % 2
    face = np.full((size, size, 3), 235, np.uint8)
    alpha = np.zeros((size, size), np.uint8)
    cv2.circle(alpha, (size // 2, size // 2), size // 2, 255, -1)
    bgr, a = catalogue.render(template_id, n)
    paste(face, bgr, a, (size - n) // 2, (size - n) // 2)
    image = noisy_background(level=22, sigma=4)
    image = np.clip(image.astype(np.int16) + (6, 1, 0), 0, 255).astype(np.uint8)  # dark blue-grey trees
    paste(image, _at_dusk(face), alpha, x, y)
    return cv2.GaussianBlur(image, (3, 3), 0), (x, y, size, size)


@pytest.mark.parametrize("template_id, n", [("2.30-50", 50), ("2.01", 44)])
def test_field_inside_a_bordered_ring_gets_the_face_box_of_the_ring_outer_edge(catalogue, template_id, n):
    image, face = _bordered_disc_at_dusk(catalogue, template_id, n, 1.3)
    (candidate,) = face_candidates(image, catalogue, hough=False)
    field = candidate.segment
    assert field.source == "hole" and candidate.shape == "circle"
    # the Swiss ring around the field misses the border: no reading from the template's extent matches
    extents = [ext for entry, ext in hole_candidates(catalogue, "red", ("circle",), PipelineConfig().colour.hsv_ranges,
                                                     ("red", "blue", "white")) if entry.id == template_id]
    assert extents and max(box_iou(face_bbox(field.bbox, ext), face) for ext in extents) < 0.65
    ring = ring_edge_bbox(image, field.bbox, "circle", PipelineConfig())
    assert box_iou(ring, face) > 0.85
    assert any(box_iou(r.bbox, face) > 0.85 and template_id in r.template_ids for r in candidate.readings)


def test_ring_edge_of_a_swiss_face_is_its_own_edge(catalogue):
    # no border beyond the ring: the outer edge found is the face's, not something beyond it
    n = 50
    bgr, alpha = catalogue.render("2.30-50", n)
    image = noisy_background(level=22, sigma=4)
    paste(image, _at_dusk(bgr), alpha, 300, 150)
    image = cv2.GaussianBlur(image, (3, 3), 0)
    (candidate,) = face_candidates(image, catalogue, hough=False)
    assert candidate.segment.source == "hole"
    ring = ring_edge_bbox(image, candidate.segment.bbox, "circle", PipelineConfig())
    assert ring is None or box_iou(ring, (300, 150, n, n)) > 0.8
    assert all(box_iou(r.bbox, (300, 150, n, n)) > 0.7 for r in candidate.readings if "2.30-50" in r.template_ids)


def test_ring_edge_is_not_invented_on_plain_background():
    image = noisy_background(level=110, sigma=6)
    cv2.circle(image, (200, 150), 20, (235, 235, 235), -1)  # a bright disc, no ring around it
    assert ring_edge_bbox(image, (180, 130, 41, 41), "circle", PipelineConfig()) is None


def test_thirty_pixel_priority_road_is_a_face_candidate_by_its_small_yellow_part(catalogue):
    # the yellow diamond of a 30 px face is 15 px wide, ~110 px: below the usual smallest segment
    image = noisy_background(level=100, sigma=8)
    _priority_sign(image, 200, 100, 30, 0.5)
    face = (200, 100, 31, 31)

    def best(config):
        return max((box_iou(r.bbox, face) for c in face_candidates(image, catalogue, config, hough=False)
                    if c.segment.colour == "yellow" and c.segment.source == "colour"
                    for r in c.readings if "3.03" in r.template_ids), default=0.0)

    assert best(PipelineConfig(colour=ColourConfig(min_part_px={}))) == 0.0
    assert best(PipelineConfig()) > 0.6


def test_blurred_small_part_still_reaches_the_face_outer_edge(catalogue):
    # the colour segment of a blurred 15 px diamond misses its soft edge: the outer-edge search allows for it
    image = noisy_background(level=100, sigma=8)
    _priority_sign(image, 200, 100, 30, 0.5)
    image = cv2.GaussianBlur(image, (3, 3), 0)
    face = (200, 100, 31, 31)

    def best(config):
        return max((box_iou(r.bbox, face) for c in face_candidates(image, catalogue, config, hough=False)
                    if c.segment.colour == "yellow" for r in c.readings if "3.03" in r.template_ids), default=0.0)

    assert best(PipelineConfig(rims=RimConfig(rim_blur_px=0.0))) < 0.6
    assert best(PipelineConfig()) > 0.85
