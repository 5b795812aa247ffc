"""Scene layout rules: where signs stand, how they face, which distractors exist."""

from __future__ import annotations

import numpy as np
import pytest

from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig
from signmapper_core.simulate.distractors import facade_distractor
from signmapper_core.simulate.faces import FaceOptions, sign_kinds
from signmapper_core.simulate.generator import _vehicle_positions, make_scene, make_street
from signmapper_core.simulate.layout import CARRIAGEWAY, PARKING_LEFT
from signmapper_core.simulate.panels import PanelLook
from signmapper_core.simulate.scene_pieces import Pieces, TextureKeys
from signmapper_core.simulate.sign_poles import sign_pole
from signmapper_core.simulate.street_body import buildings


def texture_kinds(scene) -> set[str]:
    return {s.texture.key.split(":")[0] for b in scene._bins.values() for s in b if s.texture is not None}


def street_coords(street, point):
    """(s, lateral, height above road) of a world point, by searching along the centreline."""
    ss = np.arange(0.0, street.length, 0.02)
    centre = street.point(ss)
    fwd = street.forward(ss)
    along = np.einsum("ij,ij->i", (point - centre)[:, :2], fwd[:, :2])
    near = np.linalg.norm((point - centre)[:, :2], axis=1) < 30
    k = int(np.argmin(np.where(near, np.abs(along), np.inf)))
    lat = float(np.dot(point - centre[k], street.right(ss[k])))
    return float(ss[k]), lat, float(point[2] - centre[k][2])


def test_signs_stand_along_the_driven_path_and_face_the_traffic():
    """The standing poles of the drives of before (the whole catalogue's posts and boards: test_simulate_sign_mix)."""
    cfg = SimulationConfig(pairs=150, seed=9, **DRAWABLE_SIGNS)
    street = make_street(cfg)
    scene = make_scene(cfg, street)
    s_cam = _vehicle_positions(cfg)
    truth = [t for t in scene.truth if not t.is_plate]  # plates hang below signs: test_simulate_plates.py
    driven = s_cam[-1] - s_cam[0]
    assert 0.5 * cfg.sign_density * driven / 100 <= len(truth) <= 3 * cfg.sign_density * driven / 100
    for sign in truth:
        s, lat, h = street_coords(street, sign.position)
        assert s_cam[0] + 7 <= s <= s_cam[-1] + 13
        heading = np.degrees(street.heading(s))
        # facing the approaching vehicle, a few degrees off
        assert abs((sign.facing - (heading + 180) + 180) % 360 - 180) < 15
        lower = h - sign.height_m / 2
        overhead = CARRIAGEWAY[0] < lat < CARRIAGEWAY[1]
        if overhead:
            assert lower > 4.0
        else:
            assert 0.6 + 0.12 - 0.01 <= lower <= 2.5 + 0.7 + 1.0 + 0.12   # stacked panels sit higher
            edge = CARRIAGEWAY[1] if lat > 0 else PARKING_LEFT[0]
            gap = abs(lat - edge) - sign.width_m / 2
            assert 0.29 <= gap <= 2.01
    # some poles carry two panels about 0.7 m apart
    pos = np.array([t.position for t in truth])
    stacked = [(i, j) for i in range(len(pos)) for j in range(i + 1, len(pos))
               if np.linalg.norm(pos[i, :2] - pos[j, :2]) < 0.05]
    assert stacked
    assert all(0.65 <= abs(pos[i, 2] - pos[j, 2]) <= 1.0 for i, j in stacked)
    # panels facing away from the vehicle (grey backs) exist but are not in the truth
    assert len(scene.signs) > len(truth)


def test_distractors_and_densities():
    cfg = SimulationConfig(pairs=150, seed=9)
    kinds = texture_kinds(make_scene(cfg))
    assert {"car", "cone", "face", "back", "facade", "road"} <= kinds
    assert kinds & {"shop", "patch", "logo"}
    bare = make_scene(SimulationConfig(pairs=150, seed=9, sign_density=0, distractor_density=0))
    assert bare.truth == []
    assert not texture_kinds(bare) & {"car", "cone", "shop", "patch", "logo", "face"}


def _pole(form, seed=3):
    street = make_street(SimulationConfig(pairs=10, seed=seed))
    pieces = Pieces(street, TextureKeys(seed))
    look = PanelLook(1750.0, FaceOptions(), weathering=False, shadows=False, occlusion=False)
    placed = sign_pole(pieces, look, 30.0, sign_kinds(), np.random.default_rng(seed), 1, form)
    return street, pieces, placed


def test_each_pole_form_places_its_panels_from_explicit_inputs():
    _street, pieces, (single,) = _pole("single")
    assert single.truth is not None and len(pieces.surfaces) == 2 + 2  # face, back, two crossed pole quads
    _street, _pieces, (low, high) = _pole("stacked")
    assert 0.65 <= high.centre[2] - low.centre[2] <= 1.0 and low.truth and high.truth
    street, _pieces, (front, back) = _pole("back-to-back")
    assert front.truth is not None and back.truth is None
    _street, _pieces, (away,) = _pole("away")
    assert away.truth is None
    street, _pieces, (overhead,) = _pole("overhead")
    assert CARRIAGEWAY[0] < street_coords(street, overhead.centre)[1] < CARRIAGEWAY[1]
    with pytest.raises(ValueError, match="unknown pole form 'sideways'"):
        _pole("sideways")


def test_the_pole_stands_behind_every_tilted_panel_and_plate():
    """A panel or plate tilted back must not swallow its pole: the pole stays clear of its lower edge."""
    for seed in range(12):
        street = make_street(SimulationConfig(pairs=10, seed=seed))
        pieces = Pieces(street, TextureKeys(seed))
        look = PanelLook(1750.0, FaceOptions(), weathering=False, shadows=False, occlusion=False, plate_share=1.0)
        placed = sign_pole(pieces, look, 30.0, sign_kinds(), np.random.default_rng(seed), 1, "stacked")
        assert any(p.host is not None for p in placed)  # a plate hangs under the lower sign
        pole = pieces.surfaces[-2:]  # the two crossed quads, added last
        axis = np.mean([q.origin for q in pole], axis=0)[:2]
        radius = np.linalg.norm(pole[0].axis_u) * (pole[0].polygon[1, 0] - pole[0].polygon[0, 0]) / 2
        facing = np.radians(placed[0].truth.facing)
        n_h = np.array([np.sin(facing), np.cos(facing)])
        for item in placed:
            face = item.surfaces[0]
            for u, v in face.polygon:
                corner = face.origin + u * face.axis_u + v * face.axis_v
                assert np.dot(corner[:2] - axis, n_h) > radius, f"seed {seed}: the pole pierces {item.truth}"


def test_shop_signs_hang_only_on_the_facades_they_are_given():
    street = make_street(SimulationConfig(pairs=30, seed=4))
    pieces = Pieces(street, TextureKeys(4))
    facades = buildings(pieces, street.length)
    assert facades and all(f.s1 > f.s0 and f.side in (1, -1) for f in facades)
    before = len(pieces.surfaces)
    facade_distractor(pieces, facades[3].s0 + 2.0, "red", "shop", np.random.default_rng(0), [])
    assert len(pieces.surfaces) == before  # no façade given: nothing hung
    facade_distractor(pieces, facades[3].s0 + 2.0, "red", "shop", np.random.default_rng(0), facades[3:4])
    assert len(pieces.surfaces) == before + 1
