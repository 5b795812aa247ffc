"""Supplementary plates: found under (or over) a detected sign, fused across pairs, linked, their text read."""

from __future__ import annotations

from dataclasses import replace

import cv2
import numpy as np
import pytest
from pipeline_scenes import noisy_background, paste

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import TruthSign, open_drive
from signmapper_core.drive.writer import write_drive_json, write_pair, write_poses_csv, write_truth_csv
from signmapper_core.evaluation.accuracy import evaluate
from signmapper_core.evaluation.plates import evaluate_plates
from signmapper_core.evaluation.visibility import mappable_signs
from signmapper_core.fusion.signs import FusionConfig
from signmapper_core.geometry import Camera, Pose, world_to_pixel
from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.config import PlateConfig
from signmapper_core.pipeline.depth_sources import depth_source_for
from signmapper_core.pipeline.pair_context import PairContext
from signmapper_core.pipeline.plate_classify import classify_plate, pictogram_scores
from signmapper_core.pipeline.plates import BELOW
from signmapper_core.plates.catalogue import load_plate_templates
from signmapper_core.plates.formats import PLATE_ID
from signmapper_core.plates.fusion import read_plate_texts
from signmapper_core.plates.ocr import INSTALL_HINT, OcrUnavailable, read_texts
from signmapper_core.plates.text import normalise_text
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate.plate_faces import PAPER, draw_plate
from signmapper_core.simulate.plate_layout import pictogram_face

CAMERA = Camera(width=960, height=600, fx=1750.0, fy=1750.0, cx=479.5, cy=299.5, baseline_m=0.9)
HEADING = 90.0  # driving east: forward = +E, right = -N, up = +H
START = np.array([2600000.0, 1200000.0, 400.0])


def pose_at(ahead_m: float) -> Pose:
    return Pose(*(START + [ahead_m, 0.0, 0.0]), HEADING, 0.0, 0.0)


def sign_world(ahead, right, up):
    return START + np.array([ahead, -right, up])


@pytest.fixture(scope="module")
def catalogue():
    return load_catalogue()


def _quad(world_centre, width_m, height_m, pose):
    """Pixel box (x, y, w, h) of a face of that size centred at ``world_centre``, facing the camera."""
    u, v, z = world_to_pixel(CAMERA, pose, world_centre)
    w, h = int(round(width_m * CAMERA.fx / z)), int(round(height_m * CAMERA.fy / z))
    return int(round(u - (w - 1) / 2)), int(round(v - (h - 1) / 2)), w, h, float(z)


def scene(catalogue, pose, plate_lines=("200 m",), plate_size=(0.60, 0.20), gap_m=0.04, above=False,
          plate_depth_offset=0.0, seed=0, sign_id="2.30-50", sign_centre=None, plate_face=None):
    """(left, depth, plate box) of a 0.60 m sign with a plate right below (or above) it, depth given."""
    centre = sign_world(7.0, 1.3, 0.5) if sign_centre is None else sign_centre
    left = noisy_background(CAMERA.height, CAMERA.width, seed=seed)
    depth = np.full((CAMERA.height, CAMERA.width), 25.0, np.float32)  # a wall far behind
    x, y, w, h, z = _quad(centre, 0.60, 0.60, pose)
    bgr, alpha = catalogue.render(sign_id, (w, h))
    paste(left, bgr, alpha, x, y)
    depth[y:y + h, x:x + w][alpha > 127] = z
    box = None
    if plate_lines is not None:
        pw_m, ph_m = plate_size
        offset = (0.30 + gap_m + ph_m / 2) * (1 if above else -1)
        px, py, pw, ph, pz = _quad(centre + [0, 0, offset], pw_m, ph_m, pose)
        face = draw_plate(list(plate_lines), pw * 4, ph * 4) if plate_face is None else plate_face
        plate = cv2.resize(face, (pw, ph), interpolation=cv2.INTER_AREA)
        left[py:py + ph, px:px + pw] = plate
        depth[py:py + ph, px:px + pw] = pz + plate_depth_offset
        box = (px, py, pw, ph)
    return left, depth, box


def _detect(catalogue, left, depth, pose):
    return detect_pair(left, depth, None, CAMERA, pose, catalogue, PipelineConfig())


def test_a_plate_below_a_sign_is_found_and_linked_to_it(catalogue):
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose)
    found = _detect(catalogue, left, depth, pose)
    signs = [d for d in found if not d.is_plate]
    plates = [d for d in found if d.is_plate]
    assert [d.template_id for d in signs] == ["2.30-50"]
    (plate,) = plates
    assert plate.plate_of is signs[0]
    assert plate.template_id == PLATE_ID and plate.format == "normal-1"
    assert (plate.width_m, plate.height_m) == (0.60, 0.20)
    assert box_iou(plate.bbox, box) > 0.8
    expected = sign_world(7.0, 1.3, 0.5 - 0.30 - 0.04 - 0.10)
    assert np.linalg.norm(plate.position - expected) < 0.05
    assert plate.crop.shape[:2] == (plate.bbox[3], plate.bbox[2])
    assert plate.crop_seen >= 0.95  # seen whole


def test_a_two_line_plate_above_a_sign_is_found(catalogue):
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_lines=("Mo–Fr", "7–19 h"), plate_size=(0.60, 0.30), above=True)
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.format == "normal-2" and box_iou(plate.bbox, box) > 0.8
    assert plate.position[2] > plate.plate_of.position[2] + 0.4


@pytest.mark.parametrize("what, kwargs", [
    ("a white panel 1 m behind the sign's plane", dict(plate_depth_offset=1.0)),
    ("a white strip of no plate size", dict(plate_size=(1.20, 0.20))),
    ("a blank white rectangle", dict(plate_lines=("",))),
    ("a plate 0.4 m below the sign", dict(gap_m=0.40)),
    ("no plate", dict(plate_lines=None)),
])
def test_what_is_not_a_plate_of_the_sign(catalogue, what, kwargs):
    pose = pose_at(0.0)
    left, depth, _ = scene(catalogue, pose, **kwargs)
    if kwargs.get("plate_lines", 1) == ("",):  # no frame either: only white
        left, depth, box = scene(catalogue, pose, plate_lines=None)
        box = _quad(sign_world(7.0, 1.3, 0.5 - 0.66), 0.60, 0.20, pose)[:4]
        x, y, w, h = box
        left[y:y + h, x:x + w] = 240
    found = _detect(catalogue, left, depth, pose)
    assert [d.template_id for d in found if not d.is_plate] == ["2.30-50"], what
    assert [d for d in found if d.is_plate] == [], what


def test_the_sign_below_on_the_same_pole_is_no_plate_of_the_upper_one(catalogue):
    """Stacked signs: the white disc of the lower sign inside its red ring is no plate of the upper sign, even
    with its ring taken for something in front."""
    pose = pose_at(0.0)
    left, depth, _ = scene(catalogue, pose, plate_lines=None, sign_id="2.43")
    x, y, w, h, z = _quad(sign_world(7.0, 1.3, 0.5 - 0.66), 0.60, 0.60, pose)
    bgr, alpha = catalogue.render("2.30-80", (w, h))
    paste(left, bgr, alpha, x, y)
    depth[y:y + h, x:x + w][alpha > 127] = z
    found = _detect(catalogue, left, depth, pose)
    assert len([d for d in found if not d.is_plate]) == 2
    assert [d for d in found if d.is_plate] == []


def test_a_plate_before_a_pale_wall_without_depth_is_found_at_a_higher_brightness_floor(catalogue):
    """A light grey wall right around the plate, its depth unknown (no stereo match on a plain wall): at Otsu's
    floor plate and wall are one region cut by the window; one floor up the plate stands alone."""
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose)
    x, y, w, h = box
    wall = (slice(y - 6, y + 3 * h), slice(x - w // 2, x + w + w // 2))
    pale = np.full(left[wall].shape, 196, np.uint8) + np.random.default_rng(1).integers(0, 6, left[wall].shape,
                                                                                       dtype=np.uint8)
    plate = left[y:y + h, x:x + w].copy()
    left[wall] = pale
    left[y:y + h, x:x + w] = plate
    depth[wall] = np.nan
    depth[y:y + h, x:x + w] = np.nan
    found = detect_pair(left, depth, None, CAMERA, pose, catalogue, PipelineConfig())
    (plate_det,) = [d for d in found if d.is_plate]
    assert box_iou(plate_det.bbox, box) > 0.8 and plate_det.format == "normal-1"
    otsu_floor = PipelineConfig(plates=PlateConfig(plate_value_steps=(0,), plate_edge_cut=False))
    only_otsu = detect_pair(left, depth, None, CAMERA, pose, catalogue, otsu_floor)
    assert [d for d in only_otsu if d.is_plate] == []


@pytest.mark.parametrize("template_id, variant", [("5.31-2", "de"), ("5.20", "de"), ("5.31", "de")])
def test_a_pictogram_plate_is_classified_by_its_drawing_and_takes_its_size(catalogue, template_id, variant):
    templates = load_plate_templates(catalogue.folder)
    template = next(t for t in templates if (t.id, t.variant) == (template_id, variant))
    width = 0.60
    face = pictogram_face(template, 480, int(round(480 / template.aspect)), np.random.default_rng(7))
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_size=template.size_m(width), plate_face=face)
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.template_id == template_id and plate.name == template.name("de")
    assert (plate.width_m, plate.height_m) == template.size_m(width) and box_iou(plate.bbox, box) > 0.8
    assert plate.printed_text == template.text and plate.classification_indicator > 0.6


def test_a_layout_plate_is_typed_by_its_drawing_and_its_crop_holds_only_its_text_field(catalogue):
    templates = load_plate_templates(catalogue.folder)
    template = next(t for t in templates if (t.id, t.variant) == ("5.03", "de"))
    face = pictogram_face(template, 480, int(round(480 / template.aspect)), np.random.default_rng(2), "2,5 km")
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_size=template.size_m(0.60), plate_face=face)
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.template_id == "5.03" and plate.printed_text is None  # its text is read, not printed words
    assert (plate.width_m, plate.height_m) == template.size_m(0.60) and box_iou(plate.bbox, box) > 0.8
    x, y, w, h = plate.bbox  # the crop is its text field: between the arrows, the digits
    x0, y0, x1, y1 = template.field
    assert plate.crop.shape[:2] == (round(y1 * h) - round(y0 * h), round(x1 * w) - round(x0 * w))
    grey = cv2.cvtColor(plate.crop, cv2.COLOR_BGR2GRAY)
    assert (grey < 0.6 * np.median(grey)).mean() > 0.1
    assert normalise_text(read_texts([plate.crop])[0].lines) == "2,5 km"


def test_a_plate_printed_in_colour_is_told_although_its_colour_counts_as_hidden_in_front(catalogue):
    """The plate step takes coloured pixels for something in front of a white plate (a branch): they are left
    out of the comparison, which still tells 5.10 by its black print; 5.56 (a blue star of life in a blue frame)
    has nearly none, and is told by the crop as seen."""
    templates = load_plate_templates(catalogue.folder)
    assert {t.id for t in templates if t.coloured} >= {"5.10", "5.56"} and not template_of(templates, "5.20").coloured
    for plate_id in ("5.10", "5.56"):
        template = template_of(templates, plate_id)
        h = 60
        w = int(round(h * template.aspect))
        face = pictogram_face(template, w, h, np.random.default_rng(3))
        coloured = (cv2.cvtColor(face, cv2.COLOR_BGR2HSV)[:, :, 1] > PlateConfig().plate_max_saturation)
        assert 0.1 < coloured.mean() < 0.5
        found, score = classify_plate(face, templates, PipelineConfig(), coloured.astype(np.uint8))
        assert found.id == plate_id and score > 0.8
    only_hidden = replace(template, coloured=False)  # 5.56 without its coloured print: a white square
    assert max(pictogram_scores(face, [only_hidden], PipelineConfig(), coloured.astype(np.uint8))) < 0.5


def test_a_pole_in_front_of_a_plate_is_left_out_of_the_comparison(catalogue):
    """A pale post crossing the plate from top to bottom whose depth is unknown: the plate step kept it as the
    plate's paper; the comparison tries it as hidden."""
    templates = load_plate_templates(catalogue.folder)
    template = template_of(templates, "5.31-2")
    h = 60
    w = int(round(h * template.aspect))
    face = pictogram_face(template, w, h, np.random.default_rng(4))
    face[:, int(0.375 * w):int(0.625 * w)] = 120  # a grey pole over "ausgenommen" and the bicycle
    found, score = classify_plate(face, templates, PipelineConfig())
    assert found.id == "5.31-2" and score > PipelineConfig().plates.plate_pictogram_min_score
    no_poles = PipelineConfig(plates=PlateConfig(plate_occluder_contrast=0.0))
    assert classify_plate(face, templates, no_poles)[0] is None  # as the plate step saw it: a text plate
    upright = template_of(templates, "5.05")  # its arrow runs top to bottom: still told
    arrow = pictogram_face(upright, 24, int(round(24 / upright.aspect)), np.random.default_rng(5))
    assert classify_plate(arrow, templates, PipelineConfig())[0].id == "5.05"


def template_of(templates, plate_id, variant="de"):
    return next(t for t in templates if (t.id, t.variant) == (plate_id, variant))


def test_a_pictogram_plate_partly_hidden_by_a_branch_is_classified_by_what_is_seen(catalogue):
    templates = load_plate_templates(catalogue.folder)
    template = next(t for t in templates if (t.id, t.variant) == ("5.31-1", "de"))
    face = pictogram_face(template, 480, int(round(480 / template.aspect)), np.random.default_rng(8))
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_size=template.size_m(0.60), plate_face=face)
    x, y, w, h = box
    leaves = np.random.default_rng(4).integers(0, 40, (h + 20, w // 3))
    left[y - 10:y + h + 10, x - 5:x - 5 + w // 3] = np.stack([20 + leaves, 90 + leaves, 30 + leaves // 2], -1)
    depth[y - 10:y + h + 10, x - 5:x - 5 + w // 3] = np.nan
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.template_id == "5.31-1" and plate.printed_text == "gestattet" and box_iou(plate.bbox, box) > 0.8
    # the branch counted as dark print: no pictogram plate (unless taken for a pole in front, as it runs across)
    as_print = PipelineConfig(plates=PlateConfig(plate_occluder_contrast=0.0))
    assert max(pictogram_scores(plate.crop, templates, as_print)) < 0.6


def test_a_box_around_a_pictogram_plates_frame_needs_an_inset_and_a_plate_must_be_seen_enough(catalogue):
    """A box taken a few pixels around a pictogram plate (wall in it) matches the drawing only cut by one of
    ``plate_compare_insets``; a plate hidden beyond ``plate_pictogram_min_seen`` is not compared at all."""
    templates = load_plate_templates(catalogue.folder)
    template = next(t for t in templates if (t.id, t.variant) == ("5.31-2", "de"))
    h = 40
    w = int(round(h * template.aspect))
    face = pictogram_face(template, w, h, np.random.default_rng(7))
    around = np.full((h + 12, w + 12, 3), 235, np.uint8)
    around[6:6 + h, 6:6 + w] = face
    config = PipelineConfig()
    found, score = classify_plate(around, templates, config)
    assert (found.id, found.variant) == ("5.31-2", "de") and score > 0.8
    uncut = PipelineConfig(plates=PlateConfig(plate_compare_insets=(0.0,)))
    assert classify_plate(around, templates, uncut)[0] is None
    half_hidden = np.zeros((h, w), np.uint8)
    half_hidden[:, :w // 2] = 1
    assert max(pictogram_scores(face, templates, config, half_hidden)) > 0.5  # compared (seen half > 0.4)
    stricter = PipelineConfig(plates=PlateConfig(plate_pictogram_min_seen=0.6))
    assert pictogram_scores(face, templates, stricter, half_hidden) == [-1.0] * len(templates)


def test_a_text_plate_is_no_pictogram_plate(catalogue):
    pose = pose_at(0.0)
    left, depth, _ = scene(catalogue, pose, plate_lines=("ausgenommen", "Bus"), plate_size=(0.60, 0.30))
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.template_id == PLATE_ID and plate.printed_text is None
    scores = pictogram_scores(plate.crop, load_plate_templates(catalogue.folder), PipelineConfig())
    assert max(scores) < PipelineConfig().plates.plate_pictogram_min_score


def test_a_thin_line_into_a_plate_does_not_make_it_less_of_a_rectangle(catalogue):
    """Thin grey lines (a fence's wires, a bracket) rising across the lower part of a plate: notches in its
    white, not its outline; counted against its fill they would make it no rectangle."""
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_lines=("Mo–Fr", "7–19 h"), plate_size=(0.60, 0.30))
    x, y, w, h = box
    for k in range(1, 7):  # 4 px wide (0.016 m at 7 m), from the lower edge to a fifth below the top
        left[y + h // 5:y + h, x + k * w // 7 - 2:x + k * w // 7 + 2] = 115
    depth[y:y + h, x:x + w] = np.nan  # nothing says it is in front
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.format == "normal-2" and box_iou(plate.bbox, box) > 0.8
    unclosed = detect_pair(left, depth, None, CAMERA, pose, catalogue,
                           PipelineConfig(plates=PlateConfig(plate_notch_m=0.0)))
    assert [d for d in unclosed if d.is_plate] == []
    # the region fills too little of its box to be measured again with its notches closed: no plate either
    unmeasured = detect_pair(left, depth, None, CAMERA, pose, catalogue,
                             PipelineConfig(plates=PlateConfig(plate_notched_min_fill=0.85)))
    assert [d for d in unmeasured if d.is_plate] == []


@pytest.mark.parametrize("occluder", ["branch", "lamp post", "lamp post over its end"])
def test_a_plate_cut_apart_by_something_in_front_is_found_whole(catalogue, occluder):
    """A branch (green, depth unknown) or a lamp post (grey, nearer) across the plate cuts its white into
    pieces none of which is a plate; together, the hidden pixels counted as the plate's, they are. A lamp post
    over one end leaves one piece: completed under the post to a plate's width, it is the plate."""
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_lines=("Mo–Fr", "7–19 h"), plate_size=(0.60, 0.30))
    x, y, w, h = box
    band = (slice(y - 10, y + h + 25), slice(x + w // 3, x + w // 3 + w // 4))
    if occluder.endswith("end"):
        band = (slice(y - 10, y + h + 25), slice(x + 2 * w // 3, x + w + 12))
    if occluder == "branch":
        leaves = np.random.default_rng(3).integers(0, 40, left[band].shape[:2])
        left[band] = np.stack([20 + leaves, 90 + leaves, 30 + leaves // 2], axis=-1).astype(np.uint8)
        depth[band] = np.nan
    else:
        left[band] = 150
        depth[band] = depth[y, x] - 2.0
    found = _detect(catalogue, left, depth, pose)
    (plate,) = [d for d in found if d.is_plate]
    assert plate.format == "normal-2" and box_iou(plate.bbox, box) > 0.8
    assert 0.5 < plate.crop_seen < 0.95  # its text is read from views that saw it whole first
    whole_only = detect_pair(left, depth, None, CAMERA, pose, catalogue,
                             PipelineConfig(plates=PlateConfig(plate_min_visible=1.0)))
    # seen pieces only: none, or (its end hidden) the seen part taken for a smaller plate
    assert all(box_iou(d.bbox, box) < 0.8 for d in whole_only if d.is_plate)
    if occluder.endswith("end"):  # completing the piece needs it widened by more than plate_min_widening
        unwidened = detect_pair(left, depth, None, CAMERA, pose, catalogue,
                                PipelineConfig(plates=PlateConfig(plate_min_widening=10.0)))
        assert all(box_iou(d.bbox, box) < 0.8 for d in unwidened if d.is_plate)


def test_a_plate_before_a_facade_nearly_as_bright_as_its_paper_is_parted_from_it_along_its_outline(catalogue):
    """A façade at 220 around paper at 238, depth unknown: every brightness floor keeps both or neither, but the
    step in brightness along the plate's outline parts them."""
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose)
    x, y, w, h = box
    wall = (slice(y - 6, y + 3 * h), slice(x - w // 2, x + w + w // 2))
    plate = left[y:y + h, x:x + w].copy()
    left[wall] = 220 + np.random.default_rng(1).integers(0, 6, left[wall].shape, dtype=np.uint8)
    left[y:y + h, x:x + w] = plate
    depth[wall] = np.nan
    (found,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert box_iou(found.bbox, box) > 0.8 and found.format == "normal-1"
    floors_only = PipelineConfig(plates=PlateConfig(plate_edge_cut=False))
    assert [d for d in detect_pair(left, depth, None, CAMERA, pose, catalogue, floors_only) if d.is_plate] == []


def test_a_plate_joined_to_a_pale_pole_running_on_below_it_is_read_with_the_pole_cut_off(catalogue):
    """A plate whose frame is lost (far away, blurred) on a pole as pale as its paper, the pole's depth unknown:
    at every brightness floor plate and pole are one region that runs on out of the window below; cut at the
    pole's narrow rows, the plate stands alone."""
    pose = pose_at(0.0)
    x, y, w, h, _ = _quad(sign_world(7.0, 1.3, 0.5 - 0.30 - 0.04 - 0.10), 0.60, 0.20, pose)
    face = draw_plate(["200 m"], w * 4, h * 4, border=False)
    left, depth, box = scene(catalogue, pose, plate_face=face)
    pole_width = int(round(0.07 * CAMERA.fx / 7.0))
    pole = (slice(y + h, CAMERA.height), slice(x + w // 2 - pole_width // 2, x + w // 2 + pole_width // 2))
    left[pole] = 236
    depth[pole] = np.nan
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.format == "normal-1" and box_iou(plate.bbox, box) > 0.8
    uncut = PipelineConfig(plates=PlateConfig(plate_neck_m=0.0))
    assert [d for d in detect_pair(left, depth, None, CAMERA, pose, catalogue, uncut) if d.is_plate] == []


def test_the_top_of_a_white_panel_under_the_sign_is_no_plate_when_its_sides_are_cut_as_necks(catalogue):
    """A tall white panel under the sign (a zone panel on the same pole), running on out of the window below,
    its field dark but for a lettered band at the top and narrow white sides: cut at its sides' narrow rows, the
    band alone would read as a plate; the panel's sides going on below it at both ends say it is a panel's top."""
    from signmapper_core.pipeline.plates import goes_on_at_both_ends

    pose = pose_at(0.0)
    left, depth, _ = scene(catalogue, pose, plate_lines=None)
    x, y, w, h, _ = _quad(sign_world(7.0, 1.3, 0.5 - 0.30 - 0.04 - 0.60), 0.50, 1.20, pose)
    left[y:y + h, x:x + w] = PAPER[0]
    side = int(round(0.04 * CAMERA.fx / 7.0))
    band = int(round(0.2 * CAMERA.fy / 7.0))
    left[y + band:y + h, x + side:x + w - side] = 90  # the panel's dark field
    lettering = cv2.resize(draw_plate(["ZONE"], (w - 2 * side) * 4, band * 4, border=False), (w - 2 * side, band),
                           interpolation=cv2.INTER_AREA)
    left[y:y + band, x + side:x + w - side] = lettering
    depth[y:y + h, x:x + w] = np.nan
    assert [d for d in _detect(catalogue, left, depth, pose) if d.is_plate] == []

    mask = np.zeros((40, 60), np.uint8)
    mask[5:15, 10:50] = 1  # a band ...
    mask[15:, 10:14] = mask[15:, 46:50] = 1  # ... going on at both ends: a panel's sides
    assert goes_on_at_both_ends(mask, (10, 5, 40, 10), BELOW, 0.15)
    mask[15:, 46:50] = 0
    mask[15:, 28:32] = 1  # ... or on a pole in its middle
    mask[15:, 10:14] = 0
    assert not goes_on_at_both_ends(mask, (10, 5, 40, 10), BELOW, 0.15)


def test_a_plate_under_a_sign_box_that_overshoots_the_face_is_still_its_plate(catalogue):
    """A face box grown from its coloured part (a zone panel from its ring) may reach a little past the face,
    over the plate's top: the plate is still found below it, unless the box may not overshoot at all."""
    from signmapper_core.pipeline.plates import plates_of_sign

    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, gap_m=0.01)
    (sign,) = [d for d in _detect(catalogue, left, depth, pose) if not d.is_plate]
    x, y, w, h = sign.bbox
    overshooting = replace(sign, bbox=(x, y, w, box[1] + int(0.09 * h) - y))  # 9 % of its height over the plate
    pair = PairContext.whole(left, CAMERA, pose, catalogue, PipelineConfig(), depth_source_for(depth, None))
    plate = plates_of_sign(pair, depth, overshooting, BELOW)
    assert plate is not None and plate.format == "normal-1" and box_iou(plate.bbox, box) > 0.8
    exact_boxes = PipelineConfig(plates=PlateConfig(plate_box_overshoot=0.0))
    exact = PairContext.whole(left, CAMERA, pose, catalogue, exact_boxes, depth_source_for(depth, None))
    assert plates_of_sign(exact, depth, overshooting, BELOW) is None


def test_a_pictogram_plate_taller_than_any_text_plate_is_within_reach(catalogue):
    """5.31 under a 0.9 m sign is 0.62 m high, more than the largest text plate (0.45 m): the window below the
    sign reaches that far, or the plate is taken for something cut by it."""
    templates = load_plate_templates(catalogue.folder)
    template = next(t for t in templates if (t.id, t.variant) == ("5.31", "de"))
    face = pictogram_face(template, 480, int(round(480 / template.aspect)), np.random.default_rng(5))
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_size=template.size_m(0.90), plate_face=face)
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.template_id == "5.31" and box_iou(plate.bbox, box) > 0.8


def test_a_post_of_unknown_depth_in_front_of_sign_and_plate_hides_the_part_of_the_plate_behind_it(catalogue):
    """A grey lamp post crossing sign and plate, where stereo matched nothing (depth unknown), cuts the plate
    into two level pieces: read together, the post counted as hiding the plate, they are the plate."""
    pose = pose_at(0.0)
    left, depth, box = scene(catalogue, pose, plate_lines=("ausgenommen", "Anwohner"), plate_size=(0.60, 0.30))
    x, y, w, h = box
    post = slice(x + w // 3, x + w // 3 + w // 8)
    left[:, post] = 70  # darker than any paper
    depth[:, post] = np.nan
    (plate,) = [d for d in _detect(catalogue, left, depth, pose) if d.is_plate]
    assert plate.format == "normal-2" and box_iou(plate.bbox, box) > 0.8
    assert 0.5 < plate.crop_seen < 0.95  # its text is read from views that saw it whole first
    no_posts = PipelineConfig(plates=PlateConfig(plate_occluder_span=2.0))  # no run is that long
    (unaware,) = [d for d in detect_pair(left, depth, None, CAMERA, pose, catalogue, no_posts) if d.is_plate]
    assert unaware.crop_seen == 1.0  # the post taken for print on a plate seen whole


def test_crossing_posts_are_narrow_and_run_the_whole_window_within_the_signs_columns():
    from signmapper_core.pipeline.plate_classify import crossing_occluders

    not_white = np.zeros((100, 80), np.uint8)
    not_white[:, 30:36] = 1  # a post from top to bottom
    not_white[40:, 50:54] = 1  # the sign's own pole, from the sign's lower edge down
    not_white[:, 60:79] = 1  # a wall beside the sign: too wide
    found = crossing_occluders(not_white, (20, 80), 60, PlateConfig())
    assert np.flatnonzero(found.any(axis=0)).tolist() == list(range(30, 36))
    assert not crossing_occluders(not_white, (40, 80), 60, PlateConfig()).any()  # outside the sign's columns


def test_level_pieces_are_grouped_with_what_lies_between_them():
    from signmapper_core.pipeline.plates import side_by_side

    stats = np.array([[0, 0, 100, 100, 0],  # background label 0 (not a piece)
                      [10, 50, 20, 40, 800],  # left piece
                      [40, 48, 50, 44, 2000],  # right piece, level with it
                      [55, 60, 10, 10, 100],  # a wheel's inside, within the right piece
                      [12, 95, 60, 5, 300]])  # a strip below: not level with either
    assert side_by_side([1, 2, 3, 4], stats, 0.8) == [[1, 2, 3]]


def _write_drive(root, catalogue, lines=("200 m",), n=3):
    write_drive_json(root, "EPSG:2056", CAMERA, software="tests")
    poses = [(f"{i:06d}", 0.2 * i, pose_at(0.5 * i)) for i in range(n)]
    write_poses_csv(root, poses)
    for i, (pair_id, _t, pose) in enumerate(poses):
        left, depth, _ = scene(catalogue, pose, plate_lines=lines, seed=i,
                               sign_centre=sign_world(8.0, 1.3, 0.5))
        write_pair(root, pair_id, left, None, depth, image_suffix=".png", depth_suffix=".npy")
    centre = sign_world(8.0, 1.3, 0.5)
    facing = (HEADING + 180.0) % 360.0
    plate = centre + [0.0, 0.0, -(0.30 + 0.04 + 0.10)]
    write_truth_csv(root, [TruthSign("s1", "2.30-50", *centre, 0.6, 0.6, facing),
                           TruthSign("s2", "5.01", *plate, 0.6, 0.2, facing, plate_of="s1", text=" / ".join(lines)),
                           TruthSign("s3", "5.00-1", *(plate - [30.0, 0, 0]), 0.6, 0.2, facing, plate_of="s1",
                                     text="never in view")])
    return open_drive(root)


def test_a_plate_seen_in_three_pairs_is_one_feature_linked_to_its_sign_with_its_text(catalogue, tmp_path):
    drive = _write_drive(tmp_path / "drive", catalogue)
    messages = []
    result = map_drive(drive, catalogue, PipelineConfig(), warn=messages.append, workers=1)
    signs = [s for s in result.signs if s.plate_of is None]
    plates = [s for s in result.signs if s.plate_of is not None]
    assert [s.template_id for s in signs] == ["2.30-50"] and len(plates) == 1
    (sign,), (plate,) = signs, plates
    assert plate.plate_of == sign.sign_id and plate.sign_id == sign.sign_id + 1
    assert plate.n_obs == 3 and plate.text == "200 m" and plate.text_confidence > 0.7
    assert plate.template_id == "5.01"  # a distance plate: typed by what it says
    assert sign.text == "50" and sign.status == "accepted"  # its digits read by OCR agree with its id
    plate_detections = [o for o in result.detections if o.sign_id == plate.sign_id]
    assert len(plate_detections) == 3
    assert not [m for m in messages if "plate" in m]
    reference = mappable_signs(drive, result.config.depth)
    report = evaluate([s.position for s in signs], [s.template_id for s in signs], [r.position for r in reference],
                      [r.template_id for r in reference], [[0, 0], [1, 1]], 0.75)
    evidence = []
    figures = evaluate_plates(drive, result.signs, reference, report.match, result.config.depth, evidence=evidence)
    assert (figures.reference, figures.detected, figures.links_right, figures.false_positives) == (1, 1, 1, 0)
    assert (figures.text, figures.text_typed, figures.typed_right) == (1, 1, 1)
    assert (figures.readable, figures.texts_right) == (1, 1)  # 0.2 m at 8 m: 44 px high
    assert evidence == []  # nothing missed, linked or read wrong


def test_without_tesseract_plates_are_mapped_and_the_run_says_once_how_to_install_it(catalogue, tmp_path,
                                                                                     monkeypatch):
    drive = _write_drive(tmp_path / "drive", catalogue)
    monkeypatch.setenv("PATH", str(tmp_path))  # no tesseract to be found
    messages = []
    result = map_drive(drive, catalogue, PipelineConfig(), warn=messages.append, workers=1)
    plates = [s for s in result.signs if s.plate_of is not None]
    assert len(plates) == 1 and plates[0].text is None and plates[0].text_confidence is None
    assert plates[0].template_id == PLATE_ID  # not read: untyped
    about_plates = [m for m in messages if "plate" in m]
    assert len(about_plates) == 1 and INSTALL_HINT in about_plates[0]
    signs = [s for s in result.signs if s.plate_of is None]
    reference = mappable_signs(drive, result.config.depth)
    report = evaluate([s.position for s in signs], [s.template_id for s in signs], [r.position for r in reference],
                      [r.template_id for r in reference], [[0, 0], [1, 1]], 0.75)
    evidence = []
    evaluate_plates(drive, result.signs, reference, report.match, result.config.depth, evidence=evidence)
    assert len(evidence) == 1 and "typed wrong, text wrong; truth 5.01 '200 m'; mapped plate None" in evidence[0]


def test_plate_texts_are_voted_over_readings_in_one_ocr_call():
    from signmapper_core.fusion.signs import FusedSign
    from signmapper_core.plates.ocr import TextReading, Word

    class Obs:
        def __init__(self, height):
            self.bbox, self.template_id = (0, 0, 2 * height, height), PLATE_ID
            self.detection = type("D", (), {"crop": np.full((height, 2 * height, 3), 200, np.uint8)})()

    def plate(heights):
        return FusedSign(1, PLATE_ID, 0.6, 0.2, "normal-1", np.zeros(3), len(heights), 1.0, 0.0, None, 1.0, 1.0,
                         "accepted", None, [Obs(h) for h in heights], plate_of=1)

    calls = []

    def fake_read(crops, config):
        calls.append([c.shape[0] for c in crops])
        texts = {50: ("2OOm", 0.9), 45: ("200 m", 0.8), 40: ("ZOO m", 0.3), 30: ("", 0.0), 60: ("Mo-Fr", 0.9)}
        return [TextReading(tuple(Word(t, c, 0) for t in [texts[c_.shape[0]][0]] if t
                                  for c in [texts[c_.shape[0]][1]])) for c_ in crops]

    a, b = plate([30, 40, 45, 50]), plate([60])
    assert read_plate_texts([a, b], read=fake_read) == 2
    assert calls == [[50, 45, 40, 60]]  # the three nearest of the first, all in one call
    assert a.text == "200 m" and a.text_confidence == pytest.approx((0.9 + 0.8) / 3)  # "ZOO m" disagrees
    assert b.text == "Mo–Fr"
    assert (a.template_id, b.template_id) == ("5.01", "5.00-1")  # typed by what they say
    calls.clear()
    a.template_id = PLATE_ID
    assert read_plate_texts([a], read=fake_read, config=FusionConfig(plate_readings=1)) == 1
    assert calls == [[50]] and a.text == "200 m" and a.text_confidence == pytest.approx(0.9)  # the nearest alone

    def missing(crops, config):
        raise OcrUnavailable(f"no tesseract; {INSTALL_HINT}")

    heard = []
    assert read_plate_texts([plate([50])], heard.append, read=missing) == 0
    assert len(heard) == 1 and INSTALL_HINT in heard[0]

    # a pictogram plate is not read: its text is the words of the drawing most of its observations matched
    pictogram = plate([50, 45, 40])
    pictogram.template_id = "5.31-2"
    for obs, words in zip(pictogram.observations, ("exceptés", "ausgenommen", "ausgenommen")):
        obs.template_id, obs.detection.printed_text = "5.31-2", words
    bare = plate([50])
    bare.template_id = "5.31"
    bare.observations[0].template_id, bare.observations[0].detection.printed_text = "5.31", ""
    calls.clear()
    assert read_plate_texts([pictogram, bare], read=fake_read) == 1 and calls == []
    assert pictogram.text == "ausgenommen" and pictogram.text_confidence == pytest.approx(2 / 3)
    assert bare.text is None and bare.text_confidence is None

    # a layout plate's text field is read, from its views of its own id only (the others' crops hold all of it)
    layout = plate([50, 45, 60])
    layout.template_id = "5.03"
    for obs, own in zip(layout.observations, (True, True, False)):
        obs.template_id, obs.detection.printed_text = ("5.03", None) if own else (PLATE_ID, None)
    assert read_plate_texts([layout], read=fake_read) == 1 and calls == [[50, 45]]
    assert layout.template_id == "5.03" and layout.text == "200 m"


def test_a_reading_in_a_form_plates_print_outweighs_a_surer_misreading():
    from signmapper_core.plates.fusion import vote_text
    from signmapper_core.plates.ocr import TextReading, Word

    def reading(text, confidence):
        return TextReading(tuple(Word(w, confidence, 0) for w in text.split()))

    readings = [reading("100 nil", 0.9), reading("100 m", 0.6), reading("", 0.0)]
    text, confidence = vote_text(readings)
    assert text == "100 m" and confidence == pytest.approx(0.6 / 3)
    assert vote_text(readings, FusionConfig(plate_well_formed_weight=1.0))[0] == "100 nil"  # no bonus: surer wins
    assert vote_text([reading("100 nil", 0.9), reading("10O nil", 0.5)]) == ("100 nil", pytest.approx(0.7))


def test_a_view_that_read_only_some_lines_supports_the_reading_of_all_of_them():
    from signmapper_core.plates.fusion import vote_text
    from signmapper_core.plates.ocr import TextReading, Word

    def reading(lines, confidence):
        return TextReading(tuple(Word(w, confidence, k) for k, line in enumerate(lines) for w in line.split()))

    whole, part = reading(["ausgenommen", "Anwohner"], 0.9), reading(["Anwohner"], 0.95)
    assert vote_text([part, whole]) == ("ausgenommen / Anwohner", pytest.approx(0.45))
    # a reading that is no plate's (a pole read as words) gets no support from the lines it holds
    assert vote_text([part, reading(["mu Lei", "Anwohner"], 0.9)])[0] == "Anwohner"


def test_a_plate_seen_whole_is_told_from_one_cut_by_the_image_edge_or_hidden_in_part():
    from signmapper_core.pipeline.plates import seen_share

    shape = (1080, 1920, 3)
    assert seen_share((100, 200, 80, 30), None, shape, 2) == 1.0
    assert seen_share((1860, 200, 60, 30), None, shape, 2) == 0.0  # reaches the right edge: may go on beyond it
    assert seen_share((0, 200, 60, 30), None, shape, 2) == 0.0
    hidden = np.zeros((30, 80), np.uint8)
    hidden[:, :20] = 1  # a branch over a quarter of it
    assert seen_share((100, 200, 80, 30), hidden, shape, 2) == pytest.approx(0.75)


def test_a_plates_text_is_read_from_the_views_that_saw_it_whole_before_larger_cut_ones():
    from signmapper_core.fusion.signs import FusedSign
    from signmapper_core.plates.fusion import reading_crops

    class Obs:
        def __init__(self, height, seen):
            self.bbox, self.template_id = (0, 0, 2 * height, height), PLATE_ID
            self.detection = type("D", (), {"crop": np.full((height, 2 * height, 3), 200, np.uint8),
                                            "crop_seen": seen})()

    observations = [Obs(30, 1.0), Obs(40, 0.97), Obs(55, 0.6), Obs(60, 0.0), Obs(45, 1.0)]
    plate = FusedSign(1, PLATE_ID, 0.6, 0.2, "normal-1", np.zeros(3), 5, 1.0, 0.0, None, 1.0, 1.0, "accepted",
                      None, observations, plate_of=1)
    assert [c.shape[0] for c in reading_crops(plate, 3, 0.95)] == [45, 40, 30]  # whole ones, the largest first
    assert [c.shape[0] for c in reading_crops(plate, 4, 0.95)] == [45, 40, 30, 60]  # then the largest cut one
    assert [c.shape[0] for c in reading_crops(plate, 3, 0.0)] == [60, 55, 45]  # every view counts as whole
