"""White text panels (4.29, 4.30, 4.33): fields, layout, frame, plates, reading crop and whole-pair detection."""

import cv2
import numpy as np
import pytest
from pipeline_scenes import POSE, constant_depth, noisy_background, paste

from signmapper_core.drive.reader import TruthSign, open_drive
from signmapper_core.drive.writer import write_drive_json, write_pair, write_poses_csv, write_truth_csv
from signmapper_core.evaluation.accuracy import evaluate
from signmapper_core.evaluation.panels import evaluate_panels
from signmapper_core.evaluation.visibility import mappable_signs
from signmapper_core.geometry import Camera, Pose, world_to_pixel
from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.config import with_settings
from signmapper_core.pipeline.detection import Detection
from signmapper_core.pipeline.text_panels import (
    PanelField,
    field_height_range_px,
    frame_indicator,
    line_share,
    panel_fields,
    plate_of,
    pointed_end,
    reading_crop,
    under_a_bar,
)
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate.text_panel_faces import text_panel_face

CONFIG = with_settings(PipelineConfig(), {"white": {"white_signs": True}})
# a mapping camera's resolution: a panel's frame line (2 % of its height) is a pixel wide at 7 m
CAMERA = Camera(width=1280, height=720, fx=1600.0, fy=1600.0, cx=639.5, cy=359.5, baseline_m=0.9)
FORWARD, RIGHT, DOWN = POSE.rotation[:, 2], POSE.rotation[:, 0], POSE.rotation[:, 1]


def _world(ahead, right, up):
    return POSE.centre + ahead * FORWARD + right * RIGHT - up * DOWN


def _range():
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.pipeline.text_panels import catalogued_kinds

    return field_height_range_px(CAMERA, list(catalogued_kinds(load_catalogue(), CONFIG).values()), CONFIG)


def _panel_scene(kind, lines, ahead=7.0, background_depth=30.0, point="right", pole=True, seed=0, pose=POSE,
                 centre=None):
    """A text panel drawn by the simulator's drawer on a pole, before a textured background, through a lens:
    ``ahead`` of ``POSE`` or at ``centre`` (world) seen from ``pose``."""
    centre = _world(ahead, 1.5, 0.6) if centre is None else centre
    u, v, z = world_to_pixel(CAMERA, pose, centre)
    bgr, alpha = text_panel_face(kind, lines, CAMERA.fx / float(z), point=point)
    h, w = alpha.shape
    x, y = int(round(float(u) - w / 2)), int(round(float(v) - h / 2))
    left = noisy_background(CAMERA.height, CAMERA.width, seed=seed)
    depth = constant_depth(background_depth, CAMERA.height, CAMERA.width)
    if pole:
        half = max(2, int(round(0.03 * CAMERA.fx / z)))
        left[y + h :, x + w // 2 - half : x + w // 2 + half + 1] = (150, 152, 150)
        depth[y + h :, x + w // 2 - half : x + w // 2 + half + 1] = z
    paste(left, bgr, alpha, x, y)
    depth[y : y + h, x : x + w][alpha > 127] = z
    return centre, cv2.GaussianBlur(left, (0, 0), 0.8), depth, (x, y, w, h)


@pytest.mark.parametrize("kind, lines, layout", [
    ("4.29", ["Wädenswil"], "place-name"),
    ("4.30", ["Mönchaltorf", "Rüti 14 km"], "place-end"),
    ("4.33", ["Bellinzona", "Airolo"], "direction"),
])
def test_a_framed_lettered_field_is_found_with_its_layout(kind, lines, layout):
    _, left, _, box = _panel_scene(kind, lines)
    fields = panel_fields(left, _range(), CONFIG)
    assert [f.layout for f in fields] == [layout]
    (field,) = fields
    x, y, w, h = field.box
    assert box[0] <= x and x + w <= box[0] + box[2] and box[1] <= y and y + h <= box[1] + box[3]
    assert w >= 0.8 * box[2] and h >= 0.8 * box[3]
    assert field.frame_share > 0.9 and field.line_share > 0.6 and frame_indicator(field, CONFIG) > 0.9
    if layout == "place-end":
        top, bottom = field.bar_rows
        assert 0.3 * h < top < bottom < 0.7 * h


def test_a_direction_panel_points_the_way_it_is_drawn():
    _, left, _, _ = _panel_scene("4.33", ["Sion"], point="left")
    (field,) = panel_fields(left, _range(), CONFIG)
    assert field.layout == "direction" and pointed_end(field.mask, CONFIG) == "left"


def test_a_white_board_without_frame_is_no_panel_field():
    # the same lettering on a white board before a dark background: dark beside it, but no thin line with a
    # white margin outside it
    left = noisy_background(CAMERA.height, CAMERA.width, seed=3, level=70, sigma=6)
    cv2.rectangle(left, (250, 150), (450, 220), (232, 234, 233), -1)
    cv2.putText(left, "Zimmer", (270, 200), cv2.FONT_HERSHEY_SIMPLEX, 1.0, (30, 30, 30), 2)
    assert panel_fields(cv2.GaussianBlur(left, (0, 0), 0.8), _range(), CONFIG) == []


def test_line_share_sees_a_frame_line_and_not_a_dark_surrounding():
    grey = np.full((60, 120), 70, np.uint8)
    grey[10:50, 10:110] = 230  # a white panel...
    grey[13:14, 13:107] = 30  # ...its frame's top and bottom lines, 3 px in...
    grey[46:47, 13:107] = 30
    mask = np.ones((32, 94), np.uint8)
    framed = line_share(grey, (13, 14, 94, 32), mask, CONFIG)
    board = line_share(grey, (10, 10, 100, 40), np.ones((40, 100), np.uint8), CONFIG)  # the board's edge
    assert framed > 0.9 and board == 0.0


def test_pointed_end_tells_a_pointer_from_a_rounded_rectangle():
    pointer = np.zeros((40, 200), np.uint8)
    cv2.fillPoly(pointer, [np.array([[0, 0], [175, 0], [199, 20], [175, 39], [0, 39]])], 1)
    rounded = np.zeros((40, 200), np.uint8)
    cv2.rectangle(rounded, (6, 0), (193, 39), 1, -1)
    cv2.rectangle(rounded, (0, 6), (199, 33), 1, -1)
    assert pointed_end(pointer, CONFIG) == "right"
    assert pointed_end(pointer[:, ::-1].copy(), CONFIG) == "left"
    assert pointed_end(rounded, CONFIG) is None


def test_a_field_right_under_a_sign_is_its_plate():
    sign = Detection("2.01", "", "red", "circle", 0.6, 0.6, "normal", 1.0, 1.0, "accepted", 0, 0, (100, 100, 60, 60),
                     8.0, np.zeros(3))
    assert plate_of((105, 165, 50, 20), [sign], CONFIG)  # 5 px below, under it
    assert not plate_of((105, 200, 50, 20), [sign], CONFIG)  # 40 px below: another panel on the pole
    assert not plate_of((300, 165, 50, 20), [sign], CONFIG)  # beside it


def test_a_place_end_reading_crop_sets_its_small_top_line_over_the_lower_one():
    field = np.full((50, 100, 3), 200, np.uint8)
    field[20:26] = 20  # the bar
    mask = np.ones((50, 100), np.uint8)
    crop = reading_crop(np.pad(field, ((10, 10), (10, 10), (0, 0))),
                        PanelField((10, 10, 100, 50), mask, "place-end", 1.0, 1.0, (20, 26)))
    assert crop.shape[0] > 24 + 20 and crop.min() > 100  # both parts, the bar gone


def test_a_text_panel_on_its_pole_is_detected_measured_and_located():
    centre, left, depth, box = _panel_scene("4.29", ["Wädenswil"], ahead=8.0)
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, _catalogue(), CONFIG)
    assert (det.template_id, det.source, det.status, det.format) == ("4.29", "text-panel", "accepted", "measured")
    assert np.linalg.norm(det.position - centre) < 0.1
    assert det.height_m == pytest.approx(0.42, abs=0.06) and det.crop is not None
    assert det.width_m == pytest.approx(box[2] * 8.0 / CAMERA.fx, abs=0.08)


def test_a_text_panel_in_a_facade_or_with_the_step_off_is_not_detected():
    _, left, depth, _ = _panel_scene("4.30", ["Uster", "Egg 4 km"], ahead=8.0, background_depth=8.1, pole=False)
    assert detect_pair(left, depth, None, CAMERA, POSE, _catalogue(), CONFIG) == []  # a shop sign in a wall
    _, left, depth, _ = _panel_scene("4.30", ["Uster", "Egg 4 km"], ahead=8.0)
    off = with_settings(CONFIG, {"white": {"text_panels": False}})
    assert detect_pair(left, depth, None, CAMERA, POSE, _catalogue(), off) == []


def _catalogue():
    from signmapper_core.catalogue import load_catalogue

    return load_catalogue()


def test_a_lower_field_under_a_bar_is_read_as_a_place_end_with_its_upper_field():
    grey = np.full((120, 200), 90, np.uint8)
    grey[10:110, 20:180] = 230  # the panel
    grey[13:15, 23:177] = 30  # its frame line at the top...
    grey[40:50, 23:177] = 25  # ...the 4.30's bar...
    lower = PanelField((25, 50, 150, 55), np.ones((55, 150), np.uint8), "place-name", 1.0, 1.0)
    found = under_a_bar(lower, grey, CONFIG)
    assert found is not None and found.layout == "place-end"
    x, y, w, h = found.box
    assert (x, w) == (25, 150) and 14 <= y <= 16 and y + h == 105
    assert found.bar_rows == (40 - y, 50 - y)
    grey[40:50, 23:177] = 230  # no bar: a 4.29's field stays one
    assert under_a_bar(lower, grey, CONFIG) is None


def test_a_text_panel_seen_in_three_pairs_is_one_feature_with_its_text(tmp_path):
    # driving east towards a 4.30 at 9-10 m; its text read after fusion, the evaluation's rows agreeing
    root = tmp_path / "drive"
    centre = _world(10.0, 1.5, 0.6)
    write_drive_json(root, "EPSG:2056", CAMERA, software="tests")
    poses = [(f"{i:06d}", 0.2 * i, Pose(POSE.easting + 0.5 * i, POSE.northing, POSE.height, POSE.heading, 0.0, 0.0))
             for i in range(3)]
    write_poses_csv(root, poses)
    for i, (pair_id, _t, pose) in enumerate(poses):
        _, left, depth, box = _panel_scene("4.30", ["Uster", "Egg 4 km"], pose=pose, centre=centre, seed=i)
        write_pair(root, pair_id, left, None, depth, image_suffix=".png", depth_suffix=".npy")
    width_m = box[2] * (10.0 - 1.0) / CAMERA.fx
    write_truth_csv(root, [TruthSign("s1", "4.30", *centre, width_m, 0.6, (POSE.heading + 180.0) % 360.0,
                                     text="Uster / Egg 4 km")])
    drive = open_drive(root)
    catalogue = _catalogue()
    result = map_drive(drive, catalogue, CONFIG, workers=1)
    (panel,) = result.signs
    assert (panel.template_id, panel.n_obs, panel.status) == ("4.30", 3, "accepted")
    assert panel.text == "Uster / Egg 4 km" and panel.text_confidence > 0.5
    assert np.linalg.norm(panel.position - centre) < 0.1
    reference = mappable_signs(drive, result.config.depth)
    report = evaluate([panel.position], [panel.template_id], [r.position for r in reference],
                      [r.template_id for r in reference], [[0, 0], [1, 1]], 0.75)
    evidence = []
    figures = evaluate_panels(drive, result.signs, reference, report.match, result.config.depth, evidence=evidence)
    assert (figures.reference, figures.detected, figures.kinds_right, figures.texts_right) == (1, 1, 1, 1)
    assert evidence == []


@pytest.mark.parametrize("template_id, size", [("4.49", (222, 40)), ("4.45", (156, 41))])
def test_a_white_pointer_with_a_pictogram_is_read_as_its_own_sign_not_the_generic_panel(template_id, size):
    """Found by its layout as a direction panel, a catalogued pointer (a company's 4.49, the lorries' 4.45) is what
    the network reads among the white pointers; they were mapped and accepted as 4.33 (crops of tune drive 600)."""
    from pathlib import Path

    from signmapper_core.pipeline.pair_context import PairContext
    from signmapper_core.pipeline.text_panels import specific_pointer

    crop = cv2.imread(str(Path(__file__).parents[1] / "data" / "white-pointers" / f"{template_id}.png"))
    pair = PairContext.whole(crop, CAMERA, POSE, _catalogue(), PipelineConfig(), None)
    assert specific_pointer(pair, (40, 40) + size, "4.33") == template_id
    centre, left, depth, box = _panel_scene("4.33", ["Bellinzona", "Airolo"], ahead=8.0)
    generic = PairContext.whole(left, CAMERA, POSE, _catalogue(), PipelineConfig(), None)
    assert specific_pointer(generic, box, "4.33") == "4.33"  # a destination panel stays the generic one


def test_a_pointer_whose_dark_edge_is_its_outline_is_still_a_direction_field():
    """The lorries' pointer 4.45 before foliage (tune drive 606): its black edge has no white margin outside, so it
    shows no frame line, but it is pointed: found as a direction field, its frame seen all round, read as 4.45."""
    from pathlib import Path

    from signmapper_core.pipeline.pair_context import PairContext
    from signmapper_core.pipeline.text_panels import specific_pointer

    crop = cv2.imread(str(Path(__file__).parents[1] / "data" / "white-pointers" / "4.45-before-foliage.png"))
    (field,) = panel_fields(crop, _range(), CONFIG)
    assert field.layout == "direction" and field.line_share < CONFIG.white.panel_min_line
    x, y, w, h = field.box
    assert abs(x - 40) <= 3 and abs(y - 40) <= 3 and abs(w - 219) <= 6 and abs(h - 57) <= 4
    assert frame_indicator(field, CONFIG) == field.frame_share > 0.9  # no board: its point tells it from one
    pair = PairContext.whole(crop, CAMERA, POSE, _catalogue(), PipelineConfig(), None)
    assert specific_pointer(pair, field.box, "4.33") == "4.45"
