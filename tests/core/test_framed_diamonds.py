"""Priority roads found by their white frame when their yellow is lost to the hue band (dusk, backlight)."""

from dataclasses import replace

import cv2
import numpy as np
import pytest
from pipeline_scenes import noisy_background, paste

from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.bright_fields import bright_faces
from signmapper_core.pipeline.candidates import colour_step, face_candidates
from signmapper_core.pipeline.colour import (
    find_colour_segments,
    merge_candidates,
    segments_from_mask,
    split_face_merges,
)
from signmapper_core.pipeline.config import BrightFieldConfig, with_settings
from signmapper_core.pipeline.framed_diamonds import yellow_against_frame

FACE = (300, 150, 60, 60)  # x, y, w, h of the pasted face


def _lit(bgr, gains):
    """The face under a light of these B, G, R gains (dusk: the yellow turns dark orange)."""
    return np.clip(bgr.astype(np.float32) * np.float32(gains), 0, 255).astype(np.uint8)


def _scene(catalogue, template_id="3.03", gains=(0.22, 0.1, 0.24), level=12, middle=None):
    bgr, alpha = catalogue.render(template_id, FACE[2])
    if middle is not None:  # repaint the yellow part
        yellow = (bgr[..., 0] < 100) & (bgr[..., 2] > 150)
        bgr = bgr.copy()
        bgr[yellow] = middle
    image = noisy_background(level=level, sigma=3)
    paste(image, _lit(bgr, gains), alpha, FACE[0], FACE[1])
    return cv2.GaussianBlur(image, (3, 3), 0)


def test_yellow_is_judged_against_the_frame_not_against_a_hue_band():
    white, dusk_orange = (56, 25, 61), (0, 19, 60)  # hue 9: below the yellow band
    assert yellow_against_frame(dusk_orange, white, PipelineConfig())
    assert not yellow_against_frame(white, white, PipelineConfig())  # a white middle
    assert not yellow_against_frame((10, 5, 60), white, PipelineConfig())  # a red middle loses its green too


def test_dusk_priority_road_is_found_by_its_frame_only(catalogue):
    image = _scene(catalogue)
    without = PipelineConfig(bright_fields=BrightFieldConfig(diamond_pass=False))
    assert [s for s in find_colour_segments(image, None, without, None) if s.colour == "yellow"] == []
    (seg,) = [s for s in find_colour_segments(image, None, PipelineConfig(), None) if s.colour == "yellow"]
    x, y, w, h = seg.bbox  # the white frame: inside the face's dark edge line
    assert seg.source == "frame" and x >= FACE[0] and y >= FACE[1] and x + w <= 360 and y + h <= 210
    assert box_iou(seg.bbox, FACE) > 0.6
    readings = [r for c in face_candidates(image, catalogue, hough=False) for r in c.readings]
    assert any("3.03" in r.template_ids and box_iou(r.bbox, FACE) > 0.8 for r in readings)


@pytest.mark.parametrize("middle", [(245, 245, 245), (30, 30, 200)], ids=["white", "red"])
def test_a_framed_diamond_without_a_yellow_middle_is_no_priority_road(catalogue, middle):
    image = _scene(catalogue, middle=middle)
    assert bright_faces(image, None, PipelineConfig()).diamonds == []


def test_a_framed_yellow_square_is_no_diamond(catalogue):
    image = noisy_background(level=12, sigma=3)
    cv2.rectangle(image, (300, 150), (360, 210), (56, 25, 61), -1)
    cv2.rectangle(image, (312, 162), (348, 198), (0, 19, 60), -1)
    assert bright_faces(image, None, PipelineConfig()).diamonds == []


def test_a_frame_is_no_piece_of_a_split_face(catalogue):
    # in good light the colour passes find the yellow part as well: the frame stays a face of its own beside it,
    # not merged with the yellow into one hull (which would keep the yellow's source and lose the frame's extent)
    image = _scene(catalogue, gains=(1.0, 1.0, 1.0), level=40)
    found = find_colour_segments(image, None, PipelineConfig(), None)
    (frame,) = [s for s in found if s.source == "frame"]
    segments, candidates = colour_step(image, catalogue, hough=False)
    assert [s.bbox for s in segments if s.source == "frame"] == [frame.bbox]
    assert any(s.colour == "yellow" and s.source == "colour" for s in segments)
    readings = [r for c in candidates if c.segment.source == "frame" for r in c.readings]
    assert any("3.03" in r.template_ids and box_iou(r.bbox, FACE) > 0.8 for r in readings)


def test_split_pieces_are_merged_but_a_frame_never_is():
    mask = np.zeros((200, 200), np.uint8)
    cv2.fillPoly(mask, [np.array([(100, 40), (160, 100), (100, 160), (40, 100)], np.int32)], 255)
    mask[:, 97:104] = 0  # a pole in front: two pieces of one diamond
    halves = segments_from_mask(mask, "yellow", 50, PipelineConfig().colour)
    assert len(halves) == 2
    (merged, _, _), = split_face_merges(halves, PipelineConfig())
    assert box_iou(merged.bbox, (40, 40, 121, 121)) > 0.9
    as_frame = [replace(halves[0], source="frame"), halves[1]]
    assert split_face_merges(as_frame, PipelineConfig()) == []
    assert merge_candidates(as_frame, 0.35, 2.0) == [] and len(merge_candidates(halves, 0.35, 2.0)) == 1


def test_a_priority_road_whose_middle_turned_dark_orange_is_read_from_its_red_diamond(catalogue):
    # at dusk the yellow middle reads as red (hue 9, below the yellow bands) and is too orange against its frame
    # for the frame test (green/red 0.42): its red diamond outline stands for the priority road
    image = np.clip(np.random.default_rng(4).normal(40, 4, (240, 320, 3)), 0, 255).astype(np.uint8)
    centre = np.array([160, 120])
    outer = centre + np.array([(0, -40), (40, 0), (0, 40), (-40, 0)])
    cv2.fillPoly(image, [outer.astype(np.int32)], (120, 120, 120), cv2.LINE_AA)
    cv2.fillPoly(image, [(centre + 0.62 * (outer - centre)).astype(np.int32)], (20, 50, 120), cv2.LINE_AA)
    image = cv2.GaussianBlur(image, (3, 3), 0)
    segments, candidates = colour_step(image, catalogue, hough=False)
    # the dark orange middle is also in the brown family's range; no brown entry reads a diamond
    assert [(s.colour, s.source) for s in segments if s.colour != "brown"] == [("red", "colour")]
    assert all(r.template_ids[0] not in {e.id for e in catalogue.filter(colours=["brown"])}
               for c in candidates for r in c.readings)
    assert any("3.03" in r.template_ids and box_iou(r.bbox, (120, 80, 81, 81)) > 0.9
               for c in candidates for r in c.readings)
    off = with_settings(PipelineConfig(), {"colour": {"red_diamonds_as_yellow": False}})
    # off, the red diamond is only what the red family holds of that shape (the cycle route marker 4.51.1)
    assert not any("3.03" in r.template_ids for c in colour_step(image, catalogue, off, hough=False)[1]
                   for r in c.readings)
