"""White text panels in synthetic drives (4.29 place name, 4.30 place end, 4.33 direction): their faces as
set from their wording, their poles and truth rows, and drives without white signs left without them."""

from __future__ import annotations

import numpy as np
import pytest
from test_simulate_scene import street_coords

from signmapper_core.catalogue.text_panels import TEXT_PANELS, is_text_panel
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig
from signmapper_core.simulate import faces as faces_module
from signmapper_core.simulate.faces import FaceOptions, SignKind, white_sign_kinds
from signmapper_core.simulate.generator import make_scene, make_street
from signmapper_core.simulate.panels import PanelLook
from signmapper_core.simulate.place_names import PLACES, panel_lines
from signmapper_core.simulate.scene_pieces import Pieces, TextureKeys
from signmapper_core.simulate.text_panel_faces import plan_panel, text_panel_face
from signmapper_core.simulate.text_panel_poles import LOWER_EDGE_M, text_panel_pole

PX_PER_M = 400.0


@pytest.mark.parametrize("kind_id, lines", [("4.29", ["Maur"]), ("4.29", ["Mönchaltorf", "(ZH)"]),
                                            ("4.30", ["Mönchaltorf", "Rüti 14 km"]),
                                            ("4.33", ["Zürich", "Basel", "Opfikon"])])
def test_the_face_has_the_size_of_its_plan_within_the_kinds_range(kind_id, lines):
    plan = plan_panel(kind_id, lines)
    bgr, alpha = text_panel_face(kind_id, lines, PX_PER_M)
    w, h = plan.size_px(PX_PER_M)
    assert bgr.shape == (h, w, 3) and alpha.shape == (h, w)
    assert bgr.dtype == np.uint8 and alpha.dtype == np.uint8
    assert abs(w - plan.width_m * PX_PER_M) <= 1 and abs(h - plan.height_m * PX_PER_M) <= 1
    kind = TEXT_PANELS[kind_id]
    assert kind.fits(plan.width_m, plan.height_m, 0.0)
    assert plan.lines == tuple(lines)
    ink = (bgr[alpha > 250].mean(axis=1) < 80).mean()
    assert 0.03 < ink < 0.5  # black letters and frame on white


def test_the_width_follows_the_longest_line_within_the_kinds_range():
    short, long = plan_panel("4.29", ["Zug"]), plan_panel("4.29", ["Münchenstein"])
    assert short.width_m < long.width_m
    assert short.width_m == pytest.approx(0.56, abs=0.03)  # the norm's drawing: 0.57 m for "Name"
    assert plan_panel("4.33", ["Zug"]).width_m == pytest.approx(TEXT_PANELS["4.33"].smallest[0])  # clamped up
    huge = plan_panel("4.29", ["Yverdon-les-Bains-sur-le-Lac"])
    assert huge.width_m == pytest.approx(TEXT_PANELS["4.29"].largest[0])
    assert huge.rows[0].size_m < long.rows[0].size_m  # the letters set smaller to fit


@pytest.mark.parametrize("point", ["left", "right"])
def test_the_direction_panel_is_pointed_on_the_requested_side(point):
    _, alpha = text_panel_face("4.33", ["Bellinzona", "Airolo"], PX_PER_M, point)
    h, w = alpha.shape
    tip, blunt = (0, w - 1) if point == "left" else (w - 1, 0)
    assert alpha[0, tip] == 0 and alpha[h - 1, tip] == 0  # the pointed end's corners are empty
    assert (alpha[h // 2, 2:w - 2] > 250).all()  # the middle row reaches the tip
    assert alpha[h // 4, blunt + (3 if blunt == 0 else -3)] > 250  # the blunt end is square
    inner = slice(int(0.1 * w), int(0.9 * w))
    assert (alpha[h // 4, inner] > 250).mean() < (alpha[h // 2, inner] > 250).mean() + 1e-9


def test_the_place_end_panel_has_a_dark_bar_across():
    bgr, alpha = text_panel_face("4.30", ["Mönchaltorf", "Rüti 14 km"], PX_PER_M)
    h, w = alpha.shape
    dark = bgr.mean(axis=2) < 80
    inner = slice(int(0.06 * w), int(0.94 * w))
    full_rows = [y for y in range(h) if dark[y, inner].all()]
    assert full_rows and all(0.3 * h < y < 0.5 * h for y in full_rows if 0.1 * h < y < 0.9 * h)
    assert sum(0.1 * h < y < 0.9 * h for y in full_rows) >= 0.08 * h  # thick: about 11 % of the height


def test_the_wording_uses_real_place_names_and_distances():
    rng = np.random.default_rng(3)
    names = {name for name, _ in PLACES}
    assert len(names) >= 60 and {"Mönchaltorf", "Châtel-St-Denis", "Biasca"} <= names
    for _ in range(30):
        place, *below = panel_lines("4.30", rng)
        assert place in names and 1 <= len(below) <= 2
        for line in below:
            name, km, unit = line.rsplit(" ", 2)
            assert name in names and 1 <= int(km) <= 25 and unit == "km"
        assert 1 <= len(panel_lines("4.33", rng)) <= 3
        assert len(panel_lines("4.29", rng)) in (1, 2)


def test_white_sign_kinds_leave_the_text_panels_out(monkeypatch):
    assert not any(is_text_panel(k.template_id) for k in white_sign_kinds())
    # once the catalogue carries them (colour white), they are still left out
    fake = [SignKind(i, "white", "rectangle", (("normal", 0.9, 0.45),)) for i in ("2.53.1", "4.29", "4.30", "4.33")]
    monkeypatch.setattr(faces_module, "sign_kinds", lambda colours=("white",): fake)
    assert [k.template_id for k in white_sign_kinds()] == ["2.53.1"]


def test_a_white_drive_has_text_panels_with_their_text_in_the_truth():
    scene = make_scene(SimulationConfig(pairs=150, seed=9, white_sign_share=0.5, **DRAWABLE_SIGNS))
    panels = [t for t in scene.truth if is_text_panel(t.template_id)]
    assert panels and {t.template_id for t in panels} <= {"4.29", "4.30", "4.33"}
    for t in panels:
        assert t.text and not t.plate_of and t.artwork == "procedural"
        assert TEXT_PANELS[t.template_id].fits(t.width_m, t.height_m, 0.0)
        assert 1 <= len(t.text.split(" / ")) <= 3


def test_drives_of_before_without_white_signs_have_no_text_panels():
    for cfg in (SimulationConfig(pairs=150, seed=9, **DRAWABLE_SIGNS),
                SimulationConfig(pairs=150, seed=9, white_sign_share=0.0, **DRAWABLE_SIGNS)):
        assert not any(is_text_panel(t.template_id) for t in make_scene(cfg).truth)


def test_a_text_panel_pole_faces_the_traffic_at_the_height_of_a_sign():
    street = make_street(SimulationConfig(pairs=10, seed=3))
    look = PanelLook(1750.0, FaceOptions(), True, True, False)
    seen = set()
    for seed in range(12):
        pieces = Pieces(street, TextureKeys(seed))
        placed = text_panel_pole(pieces, look, 20.0, np.random.default_rng(seed), 1)
        truth = [p.truth for p in placed]
        seen |= {t.template_id for t in truth}
        assert 1 <= len(truth) <= 2 and all(t.text for t in truth)
        heading = np.degrees(street.heading(20.0))
        lowest = min(street_coords(street, t.position)[2] - t.height_m / 2 for t in truth)
        assert LOWER_EDGE_M[0] - 0.01 <= lowest <= LOWER_EDGE_M[1] + 0.01
        for t in truth:
            assert abs((t.facing - (heading + 180) + 180) % 360 - 180) < 15
        if len(truth) == 2:  # stacked direction panels: one above the other, a small gap between them
            low, high = sorted(truth, key=lambda t: t.height)
            assert low.template_id == high.template_id == "4.33"
            gap = (high.height - high.height_m / 2) - (low.height + low.height_m / 2)
            assert 0.02 < gap < 0.15
        # the face ages like a sign face but keeps its outline
        face = placed[0].surfaces[0].texture.make()
        assert face.alpha is not None and face.bgr.shape[:2] == face.alpha.shape
    assert len(seen) >= 2
