"""Scene layout rules: where signs stand, how they face, which distractors exist."""

from __future__ import annotations

import numpy as np

from signmapper_core.simulate import SimulationConfig
from signmapper_core.simulate.generator import _vehicle_positions, make_scene, make_street
from signmapper_core.simulate.layout import CARRIAGEWAY, PARKING_LEFT


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
    cfg = SimulationConfig(pairs=150, seed=9)
    street = make_street(cfg)
    scene = make_scene(cfg, street)
    s_cam = _vehicle_positions(cfg)
    truth = scene.truth
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
