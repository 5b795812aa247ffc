"""Synthetic drives of before the whole catalogue with white and grey signs (issue 16, item 4): their share of the
poles, their truth rows, the white distractors, and drives without them left exactly as they were. (The whole
catalogue places white signs in its own share: test_simulate_sign_mix.py.)"""

from __future__ import annotations

import numpy as np
from test_simulate_scene import street_coords

from signmapper_core.catalogue import load_catalogue
from signmapper_core.catalogue.text_panels import is_text_panel
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig
from signmapper_core.simulate.face_artwork import has_procedural
from signmapper_core.simulate.faces import white_sign_kinds
from signmapper_core.simulate.generator import make_scene
from signmapper_core.simulate.layout import CARRIAGEWAY


def texture_kinds(scene) -> set[str]:
    return {s.texture.key.split(":")[0] for b in scene._bins.values() for s in b if s.texture is not None}


def test_white_kinds_are_the_white_catalogue_entries_the_procedural_drawer_knows():
    kinds = white_sign_kinds()
    catalogue = load_catalogue()
    assert [k.template_id for k in kinds] == sorted(e.id for e in catalogue.filter(colours=["white"])
                                                    if not is_text_panel(e.id) and has_procedural(e.id))
    assert {"2.53.1", "2.55", "2.56", "2.58", "2.59.2-30"} <= {k.template_id for k in kinds}
    assert all(k.colour == "white" for k in kinds)


def test_white_share_puts_white_signs_on_the_poles_with_their_truth_rows():
    colour = {e.id: e.colour for e in load_catalogue().entries.values()}
    every = make_scene(SimulationConfig(pairs=150, seed=9, white_sign_share=1.0, **DRAWABLE_SIGNS))
    # text panels (sized by their wording) have their own tests: test_simulate_text_panels.py
    signs = [t for t in every.truth if not t.is_plate and not is_text_panel(t.template_id)]
    assert signs and all(colour[t.template_id] == "white" for t in signs)
    for t in signs:  # sizes are the catalogue's formats; white signs never hang overhead
        assert (t.width_m, t.height_m) in {tuple(f) for f in load_catalogue()[t.template_id].formats.values()}
        _, lateral, _ = street_coords(every.street, t.position)
        assert not CARRIAGEWAY[0] < lateral < CARRIAGEWAY[1]
    half = make_scene(SimulationConfig(pairs=150, seed=9, white_sign_share=0.5, **DRAWABLE_SIGNS))
    half_signs = [t for t in half.truth if not t.is_plate and not is_text_panel(t.template_id)]
    white = sum(colour[t.template_id] == "white" for t in half_signs)
    assert 0 < white < len(half_signs)


def test_white_distractors_join_only_drives_with_white_signs():
    white_distractors = {"board", "white shop", "white disc"}
    with_white = texture_kinds(make_scene(SimulationConfig(pairs=150, seed=9, white_sign_share=0.5, **DRAWABLE_SIGNS)))
    assert white_distractors & with_white
    assert not white_distractors & texture_kinds(make_scene(SimulationConfig(pairs=150, seed=9, **DRAWABLE_SIGNS)))
    assert white_distractors & texture_kinds(make_scene(SimulationConfig(pairs=150, seed=9)))  # the whole catalogue


def test_drives_without_white_signs_are_unchanged():
    plain = make_scene(SimulationConfig(pairs=80, seed=4, **DRAWABLE_SIGNS))
    zero = make_scene(SimulationConfig(pairs=80, seed=4, white_sign_share=0.0, **DRAWABLE_SIGNS))
    assert [(t.template_id, t.position.tolist()) for t in plain.truth] == \
        [(t.template_id, t.position.tolist()) for t in zero.truth]
    assert all(load_catalogue()[t.template_id].colour != "white" for t in plain.truth if not t.is_plate)
    assert np.isfinite([t.facing for t in plain.truth]).all()
