"""White and grey signs (issue 16): outline candidates before depth, their judgement with depth, and the
whole pipeline on small constructed scenes (a sign on its pole, the same face on a façade, a blank board)."""

import cv2
import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, noisy_background, sign_scene

from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.boxes import box_iou, box_ious
from signmapper_core.pipeline.config import with_settings
from signmapper_core.pipeline.detection import Detection
from signmapper_core.pipeline.white_outlines import (
    edge_support,
    face_side_range_px,
    format_outline,
    group_cells,
    panel_around,
    read_face,
    read_faces,
    ring_around,
    scan_scale,
    white_candidates,
    white_formats,
)
from signmapper_core.pipeline.white_signs import (
    coloured_rim,
    coloured_share,
    in_coloured_ring,
    pole_share,
    side_share,
    support_share,
    without_panel_discs,
)

FORWARD, RIGHT, DOWN = POSE.rotation[:, 2], POSE.rotation[:, 0], POSE.rotation[:, 1]
CONFIG = with_settings(PipelineConfig(), {"white": {"white_signs": True}})


def _world(ahead, right, up):
    return POSE.centre + ahead * FORWARD + right * RIGHT - up * DOWN


def _sides(catalogue):
    return face_side_range_px(CAMERA, white_formats(catalogue, CONFIG), CONFIG)


def _with_pole(left, depth, bbox, z, background_depth):
    """A grey pole (6 cm) from under the face to the image bottom, at the face's depth."""
    x, y, w, h = bbox
    half = max(2, int(round(0.03 * CAMERA.fx / z)))
    cx = x + w // 2
    left[y + h :, cx - half : cx + half + 1] = (150, 152, 150)
    depth[y + h :, cx - half : cx + half + 1] = z
    return left, depth


def _pole_scene(catalogue, template_id, size, ahead=8.0, background_depth=30.0):
    """A white sign on its pole before a textured background, seen through a lens (slight blur)."""
    sign = _world(ahead, 1.2, 0.3)
    left, depth, bbox = sign_scene(catalogue, template_id, size, sign, background_depth=background_depth)
    left, depth = _with_pole(left, depth, bbox, ahead, background_depth)
    return sign, cv2.GaussianBlur(left, (0, 0), 1.0), depth, bbox


def test_face_side_range_covers_every_white_format_in_the_search_space(catalogue):
    lo, hi = _sides(catalogue)
    # the smallest white side counted (0.35 m: narrower text bands are sought nearer) at 14 m, the largest up to
    # 0.9 m (0.9 m disc) at 4 m, +-15 %
    assert min(min(f) for f in white_formats(catalogue, CONFIG)) < CONFIG.white.white_min_side_m == 0.35
    assert lo == pytest.approx(0.35 * 600 / 14 * 0.85)
    assert hi == pytest.approx(0.9 * 600 / 4 * 1.15)
    assert scan_scale(lo, CONFIG) == 1.0  # a small image is scanned as it is
    # a whole reduction that keeps the smallest face at least white_scan_side_px (18) wide
    assert scan_scale(72.0, CONFIG) == pytest.approx(1 / 4)
    assert scan_scale(71.0, CONFIG) == pytest.approx(1 / 3)
    # Full HD (fx 1750), 4-14 m: the smallest face, 37 px, is scanned in the image reduced by 2, not at full size
    assert scan_scale(0.35 * 1750 / 14 * 0.85, CONFIG) == pytest.approx(1 / 2)


def test_cells_overlapping_one_face_are_joined_and_far_ones_are_not():
    # the two halves of a striped field (a band between them) and a cell far away
    boxes = [(10, 10, 30, 14), (10, 28, 30, 14), (200, 10, 30, 30)]
    groups = group_cells(boxes, (20, 100), 0.35, 1.6, 0.0, 12)
    members = {tuple(sorted(m)) for _, m in groups}
    assert (0, 1) in members and (2,) in members
    box = next(b for b, m in groups if tuple(sorted(m)) == (0, 1))
    assert box == (10, 10, 30, 32)


def _gradients(grey):
    return cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3)


def test_edge_support_counts_circle_points_on_radial_gradients():
    grey = np.full((100, 100), 60, np.uint8)
    cv2.circle(grey, (50, 50), 30, 220, -1)  # a bright disc
    assert edge_support(_gradients(grey), 50, 50, 30, CONFIG) == pytest.approx(1.0)
    assert edge_support(_gradients(grey), 50, 50, 15, CONFIG) == 0.0  # inside: no gradient
    grey[:50] = 60  # the upper half of the outline gone
    assert 0.4 <= edge_support(_gradients(grey), 50, 50, 30, CONFIG) <= 0.6
    # texture has strong gradients everywhere, but not along the radii of a circle
    noise = np.random.default_rng(1).integers(0, 2, (100, 100), np.uint8) * 200
    assert edge_support(_gradients(noise), 50, 50, 30, CONFIG) < 0.7
    # ...which count where any gradient direction would: it is the radial direction that tells them apart
    any_direction = with_settings(CONFIG, {"white": {"white_radial_cos": 0.0}})
    assert edge_support(_gradients(noise), 50, 50, 30, any_direction) == 1.0


@pytest.mark.parametrize("template_id,size,ahead,shape", [
    ("2.55", "normal", 8.0, "circle"), ("2.53-60", "small", 5.0, "circle"), ("2.58", "normal", 8.0, "circle"),
    ("2.59.2-30", "normal", 5.0, "rectangle"), ("2.59.6", "normal", 5.0, "rectangle")])
def test_white_faces_are_outline_candidates_with_their_box(catalogue, template_id, size, ahead, shape):
    _, left, _, bbox = _pole_scene(catalogue, template_id, size, ahead)
    cands = white_candidates(left, _sides(catalogue), CONFIG)
    x, y, w, h = bbox
    near = [c for c in cands if abs(c.segment.bbox[0] + c.segment.bbox[2] / 2 - (x + w / 2)) < 0.1 * w
            and abs(c.segment.bbox[1] + c.segment.bbox[3] / 2 - (y + h / 2)) < 0.1 * h]
    assert near and near[0].shape == shape  # largest first: a zone panel's ring may follow as a disc reading
    assert all(c.shape != shape for c in near[1:])
    bw, bh = near[0].segment.bbox[2:]
    assert abs(bw - w) <= 0.1 * w and abs(bh - h) <= 0.1 * h
    assert near[0].segment.source == "white" and near[0].segment.colour == "white"


def _hsv_disc(ring_hsv, field_hsv, size=61):
    """A disc (BGR) whose outer ring and inner field have the given HSV colours, and its mask."""
    mask = np.zeros((size, size), np.uint8)
    cv2.circle(mask, (size // 2, size // 2), size // 2, 255, -1)
    hsv = np.zeros((size, size, 3), np.uint8)
    hsv[mask > 0] = ring_hsv
    cv2.circle(hsv, (size // 2, size // 2), int(size * 0.38), tuple(int(v) for v in field_hsv), -1)
    return cv2.cvtColor(hsv, cv2.COLOR_HSV2BGR), mask


def test_a_tinted_white_face_has_no_coloured_rim_but_a_faded_red_ring_has():
    # a white face in the pink light of a warm façade: ring and field equally tinted (saturation 30)
    tinted, mask = _hsv_disc((175, 30, 220), (175, 30, 225))
    assert not coloured_rim(tinted, mask, CONFIG)
    # a faded red ring (saturation 60) around a white field (12): the Hough fallback's red sign
    faded, mask = _hsv_disc((178, 60, 200), (175, 12, 230))
    assert coloured_rim(faded, mask, CONFIG)
    white, mask = _hsv_disc((0, 5, 220), (0, 5, 225))
    assert not coloured_rim(white, mask, CONFIG)


def _striped_panel_cells(w=40, h=56, pad=6):
    """Gradients of a bright panel with a dark frame before a darker background, and the mask of its field's
    cells as the stripes leave them: the two corners the diagonal stripe band crosses are cut off."""
    grey = np.full((h + 2 * pad, w + 2 * pad), 90, np.uint8)
    cv2.rectangle(grey, (pad, pad), (pad + w - 1, pad + h - 1), 225, -1)
    cv2.rectangle(grey, (pad, pad), (pad + w - 1, pad + h - 1), 30, 1)
    mask = np.zeros((h, w), np.uint8)
    triangle_top = np.array([[0, 0], [w - 14, 0], [0, h - 20]], np.int32)
    triangle_bottom = np.array([[w - 1, 14], [w - 1, h - 1], [14, h - 1]], np.int32)
    cv2.fillConvexPoly(mask, triangle_top, 255)
    cv2.fillConvexPoly(mask, triangle_bottom, 255)
    gradients = (cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3))
    return gradients, mask, (pad + 1, pad + 1, w - 2, h - 2)


def test_a_panel_cut_by_its_stripes_reads_as_a_rectangle_on_its_four_sides():
    gradients, mask, box = _striped_panel_cells()
    x, y, w, h = box
    readings = read_face(mask[1 : 1 + h, 1 : 1 + w], box, gradients, CONFIG)
    rectangles = [r for r in readings if r[0] == "rectangle"]
    assert len(rectangles) == 1
    rx, ry, rw, rh = rectangles[0][1]
    assert abs(rx - (x - 1)) <= 1 and abs(ry - (y - 1)) <= 1 and abs(rw - (w + 2)) <= 2 and abs(rh - (h + 2)) <= 2


def test_a_disc_does_not_read_as_a_rectangle():
    grey = np.full((80, 80), 90, np.uint8)
    cv2.circle(grey, (40, 40), 28, 225, -1)
    gradients = (cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3))
    mask = np.zeros((80, 80), np.uint8)
    cv2.circle(mask, (40, 40), 26, 255, -1)
    mask[36:44] = 0  # a stripe band across its field
    box = (14, 14, 53, 53)
    readings = read_face(mask[14:67, 14:67], box, gradients, CONFIG)
    assert [r[0] for r in readings] == ["circle"]


def test_unions_read_together_keep_each_its_own_readings():
    # a striped panel's cells, the same box with only a thin sliver of cells (too little of the box covered for a
    # panel), and a disc: read in one call, each union keeps the readings of its own cells
    gradients, mask, box = _striped_panel_cells()
    x, y, w, h = box
    cells = mask[1 : 1 + h, 1 : 1 + w]
    sliver = np.zeros_like(cells)
    sliver[: h // 4, : w // 4] = 255
    readings = read_faces([(cells, box), (sliver, box)], gradients, CONFIG)
    assert [[r[0] for r in found] for found in readings] == [["rectangle"], []]
    assert readings[0][0][1] == read_face(cells, box, gradients, CONFIG)[0][1]


def test_box_ious_agrees_with_the_iou_of_each_box():
    rng = np.random.default_rng(5)
    face = (10.0, 12.0, 30.0, 20.0)
    u, v = rng.uniform(-20, 50, 200), rng.uniform(-20, 50, 200)
    expected = [box_iou((a, b, 25.0, 18.0), face) for a, b in zip(u, v)]
    placed = np.column_stack([u, v, np.full(200, 25.0), np.full(200, 18.0)])
    assert box_ious(face, placed) == pytest.approx(expected)
    assert 0 < np.count_nonzero(box_ious(face, placed)) < 200  # some overlap, some do not


def test_a_disc_above_its_plate_stays_a_candidate_beside_their_joint_panel_reading(catalogue):
    # a 2.55 disc right above a white plate on the same pole: the cells of both may read as one tall panel,
    # the disc inside it must still be judged on its own
    sign, left, depth, bbox = _pole_scene(catalogue, "2.55", "normal")
    x, y, w, h = bbox
    plate = (x, y + h + 3, w, int(0.5 * h))  # as wide as the disc: disc and plate fill one panel's outline
    px, py, pw, ph = plate
    left[py : py + ph, px : px + pw] = (232, 232, 230)
    cv2.rectangle(left, (px, py), (px + pw - 1, py + ph - 1), (25, 25, 25), 2)
    depth[py : py + ph, px : px + pw] = depth[y + h // 2, x + w // 2]
    cands = white_candidates(left, _sides(catalogue), CONFIG)
    assert any(c.shape == "rectangle" and c.segment.bbox[3] > 1.3 * h for c in cands)  # the joint reading
    discs = [c for c in cands if c.shape == "circle" and abs(c.segment.bbox[0] - x) <= 0.1 * w
             and abs(c.segment.bbox[1] - y) <= 0.1 * h]
    assert len(discs) == 1
    dets = [d for d in detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG) if d.source == "white"]
    assert [d.template_id for d in dets] == ["2.55"]


def test_coloured_signs_are_no_white_signs_and_dark_windows_no_candidates(catalogue):
    _, left, depth, _ = _pole_scene(catalogue, "2.30-50", "normal")
    cv2.rectangle(left, (40, 60), (100, 150), (40, 38, 35), -1)  # a dark window pane with a light frame
    cv2.rectangle(left, (40, 60), (100, 150), (230, 230, 230), 3)
    assert not any(c.segment.bbox[0] < 110 for c in white_candidates(left, _sides(catalogue), CONFIG))
    dets = detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG)
    assert [(d.template_id, d.source) for d in dets] == [("2.30-50", "colour")]  # its white field is no sign


def test_side_share_tells_a_free_standing_face_from_one_in_a_wall():
    depth = np.full((100, 200), 30.0, np.float32)
    bbox = (80, 30, 40, 40)
    depth[30:70, 80:120] = 8.0
    assert side_share(depth, bbox, 8.0, CONFIG) == 0.0  # background far behind
    depth[:] = 8.1  # a façade right behind the face
    assert side_share(depth, bbox, 8.0, CONFIG) == 1.0
    depth[:] = np.nan  # sky or a blank wall: no depth beside it, no verdict
    assert side_share(depth, bbox, 8.0, CONFIG) is None


def test_support_below_from_depth_and_from_a_pole_in_the_image():
    bbox = (80, 20, 40, 40)
    depth = np.full((120, 200), 30.0, np.float32)
    assert support_share(depth, bbox, 8.0, CONFIG) == 0.0
    depth[60:, 98:102] = 8.0  # a pole at the face's depth
    assert support_share(depth, bbox, 8.0, CONFIG) == 1.0
    grey = noisy_background(120, 200)[:, :, 0]
    assert pole_share(grey, bbox, CONFIG) < CONFIG.white.white_min_pole_rows  # texture alone gives scattered edges
    grey[60:, 97:103] = 200
    assert pole_share(grey, bbox, CONFIG) == 1.0


def test_white_sign_on_its_pole_is_detected_and_classified(catalogue):
    sign, left, depth, _ = _pole_scene(catalogue, "2.55", "normal")
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG)
    assert det.template_id == "2.55" and det.source == "white" and det.colour == "white"
    assert det.format == "normal" and det.status == "accepted"
    assert np.linalg.norm(det.position - sign) < 0.1


def test_zone_end_panel_is_detected(catalogue):
    _, left, depth, _ = _pole_scene(catalogue, "2.59.2-30", "normal", ahead=5.0)
    dets = detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG)
    assert [(d.template_id, d.source) for d in dets] == [("2.59.2-30", "white")]


def test_zone_end_panel_before_a_pale_wall_is_read_as_the_panel_not_as_its_disc(catalogue):
    # held-out drives: a 2.59.2 before a pale wall was found as its zone disc alone and read as a disc sign;
    # sought as the disc of a panel around it, the panel is found (without that, the disc is the sign)
    sign = _world(10.0, 1.2, 0.3)
    left, depth, bbox = sign_scene(catalogue, "2.59.2-30", "normal", sign, background_depth=30.0)
    wall = noisy_background(seed=2, level=190, sigma=6)
    x, y, w, h = bbox
    outside = np.ones(left.shape[:2], bool)
    outside[y : y + h, x : x + w] = False
    left[outside] = wall[outside]
    left = cv2.GaussianBlur(left, (0, 0), 1.0)
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG)
    assert (det.template_id, det.status, det.format) == ("2.59.2-30", "accepted", "normal")
    assert max(abs(a - b) for a, b in zip(det.bbox, bbox)) <= 2
    assert np.linalg.norm(det.position - sign) < 0.1
    disc_only = with_settings(CONFIG, {"white": {"white_panel_around": False}})
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, disc_only)
    assert det.template_id != "2.59.2-30" and det.bbox[2] < w


def test_a_face_matching_its_drawing_weakly_is_read_by_the_network_when_it_is_held(catalogue):
    # template matching below its floor (here: a floor no face reaches) leaves the face to the network where
    # it knows every white candidate and reads it clearly; without that gate, or without a pole, no sign
    _, left, depth, _ = _pole_scene(catalogue, "2.55", "normal")
    strict = with_settings(CONFIG, {"white": {"white_min_score": 0.999, "white_unsupported_min_score": 0.999}})
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, strict)
    assert (det.template_id, det.source, det.status) == ("2.55", "white", "accepted")
    no_gate = with_settings(strict, {"white": {"white_network_gate": False}})
    assert detect_pair(left, depth, None, CAMERA, POSE, catalogue, no_gate) == []


def test_white_step_can_be_switched_off(catalogue):
    _, left, depth, _ = _pole_scene(catalogue, "2.55", "normal")
    off = with_settings(CONFIG, {"white": {"white_signs": False}})
    assert detect_pair(left, depth, None, CAMERA, POSE, catalogue, off) == []


def test_the_same_face_in_a_facade_is_not_a_sign(catalogue):
    # a white disc painted on a wall right behind it (an emblem, a house number): it does not stand free
    sign = _world(8.0, 1.2, 0.3)
    left, depth, bbox = sign_scene(catalogue, "2.55", "normal", sign, background_depth=8.1)
    left, depth = _with_pole(left, depth, bbox, 8.0, 8.1)
    assert detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG) == []


def test_a_blank_white_board_on_a_pole_is_not_a_sign(catalogue):
    # a free-standing white board of a zone panel's size with dark lettering: no white template resembles it
    sign = _world(7.0, 1.2, 0.3)
    left, depth, bbox = sign_scene(catalogue, "2.59.2-30", "normal", sign, background_depth=30.0)
    x, y, w, h = bbox
    left[y : y + h, x : x + w] = (236, 236, 234)
    cv2.rectangle(left, (x, y), (x + w - 1, y + h - 1), (20, 20, 20), 2)
    for k in range(3):
        cv2.putText(left, "Zimmer", (x + 6, y + 22 + 22 * k), cv2.FONT_HERSHEY_SIMPLEX, 0.4, (30, 30, 30), 1)
    left, depth = _with_pole(left, depth, bbox, 7.0, 30.0)
    assert white_candidates(left, _sides(catalogue), CONFIG) != []  # its outline is a candidate...
    assert detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG) == []  # ...but no sign


def test_a_disc_whose_field_is_cut_into_small_cells_is_found_by_its_round_outline():
    # a white disc whose field dark lines cut into cells far below a part of a face (digits and stripes of a
    # small far disc do that): no union of cells reads as a face, the Hough transform finds its outline
    background = noisy_background(200, 200, seed=3, level=120, sigma=10)
    left = background.copy()
    cv2.circle(left, (100, 100), 32, (228, 228, 228), -1)
    for k in range(70, 131, 6):
        cv2.line(left, (k, 60), (k, 140), (60, 60, 60), 2)
        cv2.line(left, (60, k), (140, k), (60, 60, 60), 2)
    field = np.zeros((200, 200), np.uint8)
    cv2.circle(field, (100, 100), 30, 255, -1)
    left[field == 0] = background[field == 0]
    cv2.circle(left, (100, 100), 32, (40, 40, 40), 2)
    left = cv2.GaussianBlur(left, (0, 0), 0.8)
    no_hough = with_settings(CONFIG, {"white": {"white_hough": False}})
    assert white_candidates(left, (24.0, 120.0), no_hough) == []
    cands = white_candidates(left, (24.0, 120.0), CONFIG)
    assert [c.shape for c in cands] == ["circle"]
    x, y, w, h = cands[0].segment.bbox
    assert abs(x + w / 2 - 100) <= 2 and abs(y + h / 2 - 100) <= 2 and 64 <= w <= 72 and w == h


def test_a_face_read_too_large_is_read_again_as_the_format_whose_outline_lies_on_edges():
    # a 45 px disc before a pale board up and left of it: read with the board, its box is 56 px, between the
    # 30, 45 and 67.5 px formats at its depth; the 45 px circle lies on the disc's outline
    grey = cv2.cvtColor(noisy_background(160, 160, seed=4, level=110, sigma=8), cv2.COLOR_BGR2GRAY)
    cv2.rectangle(grey, (40, 40), (95, 85), 205, -1)
    cv2.circle(grey, (90, 90), 22, 235, -1)
    cv2.circle(grey, (90, 90), 22, 60, 1)
    grey = cv2.GaussianBlur(grey, (0, 0), 0.8)
    sizes = [("circle", 30.0, 30.0), ("circle", 45.0, 45.0), ("circle", 67.5, 67.5), ("rectangle", 37.5, 52.5)]
    shape, (x, y, w, h), support = format_outline(grey, (58, 58, 56, 56), sizes, 1.0, CONFIG)
    assert shape == "circle" and (w, h) == (45, 45) and abs(x - 68) <= 1 and abs(y - 68) <= 1
    assert support >= CONFIG.white.white_min_edge_support
    # a rectangle cut short (its lower third) reads as the panel format it is part of
    grey = np.full((200, 160), 100, np.uint8)
    cv2.rectangle(grey, (50, 40), (99, 109), 230, -1)  # a 50 x 70 px panel
    grey = cv2.GaussianBlur(grey, (0, 0), 0.8)
    shape, box, _ = format_outline(grey, (50, 40, 50, 48), [("rectangle", 50.0, 70.0)], 1.0, CONFIG)
    assert shape == "rectangle" and abs(box[0] - 50) <= 1 and abs(box[1] - 40) <= 1 and box[2:] == (50, 70)
    # no outline of a format near: none
    flat = np.full((160, 160), 120, np.uint8)
    assert format_outline(flat, (58, 58, 56, 56), sizes, 1.0, CONFIG) is None


def test_a_disc_in_a_panel_before_a_pale_wall_finds_the_panels_outline_around_it():
    # 2.59.2 before a pale wall: a 50 x 70 px panel with a thin dark border holds its zone's 30 px disc,
    # and only the disc was a candidate; of the panel formats the one whose sides lie on edges is read (within
    # the outline's one-pixel tolerance either side of the border line)
    wall = cv2.cvtColor(noisy_background(200, 160, seed=6, level=205, sigma=6), cv2.COLOR_BGR2GRAY)
    grey = wall.copy()
    cv2.rectangle(grey, (50, 40), (99, 109), 235, -1)
    cv2.rectangle(grey, (50, 40), (99, 109), 60, 1)
    cv2.circle(grey, (75, 62), 15, 120, -1)
    cv2.circle(grey, (75, 62), 11, 240, -1)
    grey = cv2.GaussianBlur(grey, (0, 0), 0.8)
    disc, sizes = (60, 47, 31, 31), [(50.0, 70.0), (75.0, 105.0), (20.0, 28.0)]
    shape, (x, y, w, h), support = panel_around(grey, disc, sizes, 1.0, CONFIG)
    assert shape == "rectangle" and abs(x - 50) <= 2 and abs(y - 40) <= 2 and (w, h) == (50, 70)
    assert support >= CONFIG.white.white_min_panel_support
    # the same disc alone before the wall, or above a plate narrower than any panel: no panel around it
    alone = wall.copy()
    cv2.circle(alone, (75, 62), 15, 120, -1)
    cv2.circle(alone, (75, 62), 11, 240, -1)
    assert panel_around(cv2.GaussianBlur(alone, (0, 0), 0.8), disc, sizes, 1.0, CONFIG) is None
    plated = alone.copy()
    cv2.rectangle(plated, (58, 80), (92, 96), 235, -1)
    cv2.rectangle(plated, (58, 80), (92, 96), 60, 1)
    assert panel_around(cv2.GaussianBlur(plated, (0, 0), 0.8), disc, sizes, 1.0, CONFIG) is None
    # no panel format larger than the disc: none sought
    assert panel_around(grey, disc, [(20.0, 28.0)], 1.0, CONFIG) is None


def test_a_grey_ring_around_a_disc_is_its_outer_outline():
    # 2.53.1: a grey ring (radius 36) around a white field (24) before a pale wall; the field alone was the
    # candidate, the ring's outer outline is weaker than a face's but still read
    wall = noisy_background(160, 160, seed=5, level=172, sigma=6)
    bgr = wall.copy()
    cv2.circle(bgr, (80, 80), 36, (135, 135, 135), -1)
    cv2.circle(bgr, (80, 80), 24, (235, 235, 235), -1)
    cv2.circle(bgr, (80, 80), 24, (50, 50, 50), 1)
    bgr = cv2.GaussianBlur(bgr, (0, 0), 0.8)
    x, y, w, h = ring_around(bgr, (56, 56, 49, 49), 1.0, CONFIG)
    assert abs(x + w / 2 - 80.5) <= 2 and abs(y + h / 2 - 80.5) <= 2 and 69 <= w <= 75 and w == h
    # a white disc alone before the wall, and a disc in a red ring, have no achromatic ring around them
    plain = wall.copy()
    cv2.circle(plain, (80, 80), 24, (235, 235, 235), -1)
    cv2.circle(plain, (80, 80), 24, (50, 50, 50), 1)
    assert ring_around(cv2.GaussianBlur(plain, (0, 0), 0.8), (56, 56, 49, 49), 1.0, CONFIG) is None
    red = wall.copy()
    cv2.circle(red, (80, 80), 36, (40, 40, 200), -1)
    cv2.circle(red, (80, 80), 24, (235, 235, 235), -1)
    assert ring_around(cv2.GaussianBlur(red, (0, 0), 0.8), (56, 56, 49, 49), 1.0, CONFIG) is None


def test_a_white_field_in_a_red_ring_is_told_from_a_white_disc_before_red_or_blue_ground():
    # a speed limit's white field (radius 30) in its red ring (to 38) before a grey wall; the image's right edge
    # cuts the ring: the field is a coloured sign's
    wall = noisy_background(160, 150, seed=7, level=150, sigma=6)
    sign = wall.copy()
    cv2.circle(sign, (110, 80), 38, (40, 40, 210), -1)
    cv2.circle(sign, (110, 80), 30, (235, 235, 235), -1)
    field = (80, 50, 61, 61)
    assert in_coloured_ring(cv2.GaussianBlur(sign, (0, 0), 0.8), field, CONFIG)
    assert in_coloured_ring(cv2.GaussianBlur(sign[:, :140], (0, 0), 0.8), field, CONFIG)  # ring cut by the edge
    # a white disc before a red brick wall or a deep blue sky: the colour goes on beyond any ring
    for ground in ((40, 40, 200), (200, 90, 30)):
        plain = np.full((160, 150, 3), ground, np.uint8)
        cv2.circle(plain, (110, 80), 30, (235, 235, 235), -1)
        assert not in_coloured_ring(cv2.GaussianBlur(plain, (0, 0), 0.8), field, CONFIG)
    # 2.53.1's grey ring, and a white disc before the grey wall: no coloured ring
    grey_ring = wall.copy()
    cv2.circle(grey_ring, (110, 80), 38, (135, 135, 135), -1)
    cv2.circle(grey_ring, (110, 80), 30, (235, 235, 235), -1)
    assert not in_coloured_ring(cv2.GaussianBlur(grey_ring, (0, 0), 0.8), field, CONFIG)
    alone = wall.copy()
    cv2.circle(alone, (110, 80), 30, (235, 235, 235), -1)
    assert not in_coloured_ring(cv2.GaussianBlur(alone, (0, 0), 0.8), field, CONFIG)


def test_a_speed_limit_cut_by_the_image_edge_is_not_read_as_a_white_sign(catalogue):
    # the colour step drops a red ring that touches the image's edge; its white field, whole inside the image,
    # is a white candidate and resembles the end of the same limit (tune drive 1708: read as 2.53-60 at 1.00)
    _, _, (x, _, w, _) = sign_scene(catalogue, "2.30-60", "normal", _world(7.0, 1.2, 0.3), background_depth=30.0)
    # moved right until the image ends a tenth of the face before the ring's right edge
    sign = _world(7.0, 1.2 + (CAMERA.width - (x + w - w // 10)) * 7.0 / CAMERA.fx, 0.3)
    left, depth, bbox = sign_scene(catalogue, "2.30-60", "normal", sign, background_depth=30.0)
    assert bbox[0] + bbox[2] > CAMERA.width > bbox[0] + bbox[2] * 0.8
    left, depth = _with_pole(left, depth, bbox, 7.0, 30.0)
    left = cv2.GaussianBlur(left, (0, 0), 1.0)
    assert [d for d in detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG) if d.source == "white"] == []
    unguarded = with_settings(CONFIG, {"white": {"white_min_ring_share": 1.01}})
    found = [d for d in detect_pair(left, depth, None, CAMERA, POSE, catalogue, unguarded) if d.source == "white"]
    assert found and found[0].template_id.startswith("2.53")


def _white_detection(template_id, shape, bbox):
    return Detection(template_id=template_id, name=template_id, colour="white", shape=shape, width_m=0.6,
                     height_m=0.6, format="normal", detection_indicator=0.9, classification_indicator=0.8,
                     status="accepted", u=0.0, v=0.0, bbox=bbox, depth_m=8.0, position=np.zeros(3), source="white")


def test_a_disc_inside_a_white_panel_is_the_panels_zone_disc():
    panel = _white_detection("2.59.2-30", "rectangle", (100, 100, 50, 70))
    inner = _white_detection("2.53.1", "circle", (108, 125, 34, 34))  # the zone's ring on the panel
    alone = _white_detection("2.55", "circle", (300, 100, 50, 50))
    assert without_panel_discs([panel, inner, alone], [], CONFIG) == [panel, alone]
    # a panel outline that no template resembled (not detected) still holds its disc
    assert without_panel_discs([inner, alone], [(100, 100, 50, 70)], CONFIG) == [alone]
    # a disc merely overlapping a panel's edge is not inside it
    beside = _white_detection("2.55", "circle", (130, 100, 50, 50))
    assert without_panel_discs([panel, beside], [], CONFIG) == [panel, beside]


def test_a_red_ringed_zone_panel_is_coloured_but_a_white_panel_in_warm_light_is_not():
    panel = np.full((70, 50, 3), 235, np.uint8)
    cv2.putText(panel, "30", (10, 45), cv2.FONT_HERSHEY_SIMPLEX, 0.8, (20, 20, 20), 2)
    warm = cv2.cvtColor(panel, cv2.COLOR_BGR2HSV)
    warm[:, :, 0], warm[:, :, 1] = 10, np.minimum(warm[:, :, 1] + 40, 255)  # the pink light of a warm façade
    warm = cv2.cvtColor(warm, cv2.COLOR_HSV2BGR)
    ringed = panel.copy()
    cv2.circle(ringed, (25, 35), 19, (40, 40, 200), 10)  # 2.59.5's red ring (0.40 of its panel on a tune drive)
    box = (0, 0, 50, 70)
    limit = CONFIG.white.white_max_coloured_share
    assert coloured_share(panel, box, CONFIG) == 0.0 and coloured_share(warm, box, CONFIG) < limit
    assert coloured_share(ringed, box, CONFIG) > limit


class _NetworkReading:
    """A stand-in for a network trained on the white family: knows every id, reads each face as ``answer``
    (when that is a candidate) with ``score``."""

    name, accept_threshold, min_score, marginal_min_score = "stand-in", 0.85, 0.25, 0.5

    def __init__(self, answer: str, score: float):
        self.answer, self.score = answer, score

    def knows(self, template_ids):
        return True

    def classify(self, image, bbox, candidate_ids):
        from signmapper_core.pipeline.classify import ClassificationResult

        if self.answer not in candidate_ids:
            return ClassificationResult(None, 0.0)
        return ClassificationResult(self.answer, self.score, {self.answer: self.score})


@pytest.mark.parametrize("answer, score, want_id, want_indicator, want_status", [
    ("2.56", 0.95, "2.56", 0.95, "accepted"),  # the network's id and its calibrated indicator
    ("2.56", 0.60, "2.56", 0.60, "review"),  # below the network's acceptance threshold
    ("4.17", 0.95, "2.55", None, "review"),  # no white candidate read: the template matching's id, for review
])
def test_a_white_face_is_read_by_a_network_that_knows_the_white_family(catalogue, monkeypatch, answer, score,
                                                                       want_id, want_indicator, want_status):
    import signmapper_core.pipeline.pair_context as pair_context

    sign, left, depth, _ = _pole_scene(catalogue, "2.55", "normal")
    by_template = with_settings(CONFIG, {"classification": {"classifier": "ncc"}})
    (matched,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, by_template)  # template matching alone
    monkeypatch.setattr(pair_context, "classifier_for", lambda catalogue, config: _NetworkReading(answer, score))
    (det,) = [d for d in detect_pair(left, depth, None, CAMERA, POSE, catalogue, CONFIG) if d.source == "white"]
    assert (det.template_id, det.status) == (want_id, want_status)
    assert det.classification_indicator == pytest.approx(want_indicator or matched.classification_indicator)
    assert np.linalg.norm(det.position - sign) < 0.1 and det.bbox == matched.bbox
