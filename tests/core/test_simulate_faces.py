"""Sign faces of synthetic drives: artwork mix, physical variations, determinism, never a template copy."""

from __future__ import annotations

from dataclasses import replace

import cv2
import numpy as np
import pytest

from signmapper_core.drive.reader import read_truth
from signmapper_core.simulate import (
    DRAWABLE_SIGNS,
    LEGACY_FACES,
    SimulationConfig,
    face_dirt,
    face_marks,
    face_print,
    face_sheeting,
    face_wear,
    generate_drive,
)
from signmapper_core.simulate.face_artwork import master_face, procedural_face
from signmapper_core.simulate.face_dents import dent_warp
from signmapper_core.simulate.face_layers import RED, circular_mean_hue, ink_layers, to_hsv
from signmapper_core.simulate.faces import (
    PROCEDURAL_ONLY,
    FaceOptions,
    SignFace,
    draw_sign_face,
    weather_face,
)

SIZE = 256
# a red circle, a red triangle, a blue square, the yellow diamond
SIGNS = ("2.30-50", "1.14", "4.08", "3.03")
NCC_FLOOR = 0.8
ALL_OFF = dict(face_print=False, face_sheeting=False, face_wear=False, face_dirt=False, face_marks=False,
               face_dents=False)


def face_size(catalogue, template_id: str, longer: int = SIZE) -> tuple[int, int]:
    aspect = catalogue[template_id].aspect
    return (longer, round(longer / aspect)) if aspect >= 1 else (round(longer * aspect), longer)


def inner_mask(alpha: np.ndarray, margin: int = 6) -> np.ndarray:
    return cv2.erode((alpha > 250).astype(np.uint8), np.ones((2 * margin + 1,) * 2, np.uint8)) > 0


def masked_ncc(a: np.ndarray, b: np.ndarray, mask: np.ndarray) -> float:
    """Normalised cross-correlation of two BGR faces inside ``mask``, over all three channels.

    Colour channels, not grey: a plain yellow field with a white border (3.03) has
    little grey structure, but yellow and white differ strongly in blue.
    """
    ga = np.asarray(a, float)[mask]
    gb = np.asarray(b, float)[mask]
    ga, gb = ga - ga.mean(axis=0), gb - gb.mean(axis=0)
    return float((ga * gb).sum() / np.sqrt((ga * ga).sum() * (gb * gb).sum()))


_RENDERED: dict = {}


def best_template(catalogue, face: np.ndarray, alpha: np.ndarray, template_id: str) -> str:
    """Among the catalogue entries of the sign's colour and shape, the one whose master correlates best (96 px)."""
    entry = catalogue[template_id]
    scale = 96 / max(face.shape[:2])
    size = (round(face.shape[1] * scale), round(face.shape[0] * scale))
    face = cv2.resize(np.clip(face, 0, 255).astype(np.uint8), size, interpolation=cv2.INTER_AREA)
    mask = inner_mask(cv2.resize(alpha, size, interpolation=cv2.INTER_AREA), 3)
    scores = {}
    for other in catalogue.filter(colours=[entry.colour], shapes=[entry.shape]):
        if abs(other.aspect - entry.aspect) > 0.02:
            continue
        key = (other.id, face.shape[1], face.shape[0])
        if key not in _RENDERED:
            _RENDERED[key] = catalogue.render(other.id, key[1:])[0]
        scores[other.id] = masked_ncc(face, _RENDERED[key], mask)
    return max(scores, key=scores.get)


def apply_at_full_strength(name: str, bgr: np.ndarray, alpha: np.ndarray, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """One variation at its strongest: (bgr float, alpha)."""
    rng = np.random.default_rng(seed)
    labels = ink_layers(bgr)
    px_per_m = bgr.shape[1] / 0.6
    if name == "print":
        return face_print.print_variation(bgr.astype(np.float32), labels, rng, 1.0, px_per_m), alpha
    if name == "prism":
        return face_sheeting.prism_texture(bgr, rng, 1.0, px_per_m), alpha
    if name == "sheen":
        return face_sheeting.sheen(bgr, alpha, rng, 1.0, hot_spot=True), alpha
    if name == "wear":
        return face_wear.uv_ageing(bgr, labels, rng, 1.0), alpha
    if name == "peel":
        return face_wear.peel(bgr, alpha, rng, 1.0), alpha
    if name == "dirt":
        img = face_dirt.grime(bgr, rng, 1.0)
        return face_dirt.rain_streaks(face_dirt.spots(img, alpha, rng, 1.0), rng, 1.0), alpha
    if name == "marks":
        return face_marks.graffiti_tag(face_marks.sticker(bgr, alpha, rng), alpha, rng), alpha
    if name == "dents":
        warp = dent_warp((bgr.shape[1], bgr.shape[0]), rng, 1.0, bend=True)
        return warp.apply(bgr), warp.outline(alpha)
    raise ValueError(name)


VARIATIONS = ("print", "prism", "sheen", "wear", "peel", "dirt", "marks", "dents")


@pytest.mark.parametrize("name", VARIATIONS)
@pytest.mark.parametrize("template_id", SIGNS)
def test_each_variation_at_full_strength_changes_the_face_but_keeps_it_recognisable(catalogue, name, template_id):
    bgr, alpha = master_face(template_id, face_size(catalogue, template_id), np.random.default_rng(1))
    mask = inner_mask(alpha)
    mean_change, share_changed, nccs = [], [], []
    for seed in range(3):
        varied, varied_alpha = apply_at_full_strength(name, bgr, alpha, seed)
        diff = np.abs(varied - bgr.astype(np.float32)).max(axis=2)[mask]
        mean_change.append(float(diff.mean()))
        share_changed.append(float((diff > 30).mean()))
        nccs.append(masked_ncc(varied, bgr, mask))
        assert best_template(catalogue, varied, varied_alpha, template_id) == template_id, (name, seed)
    # global variations shift every pixel a little, local ones (peeling, stickers) a few pixels a lot
    changed = [m > 1.0 or s > 0.004 for m, s in zip(mean_change, share_changed)]
    assert all(changed), f"{name} did not change {template_id}: mean |d| {mean_change}, share > 30 {share_changed}"
    assert min(nccs) > NCC_FLOOR, f"{name} made {template_id} unrecognisable: NCC {nccs}"


@pytest.mark.parametrize("name", ("print", "wear", "dirt", "prism", "sheen"))
def test_red_ring_stays_red_under_each_colour_variation(catalogue, name):
    bgr, alpha = master_face("2.30-50", face_size(catalogue, "2.30-50"), np.random.default_rng(2))
    ring = cv2.erode((ink_layers(bgr) == RED).astype(np.uint8), np.ones((5, 5), np.uint8)) > 0
    assert ring.sum() > 0.2 * ring.size
    assert abs(circular_mean_hue(bgr, ring)) < 8.0
    for seed in range(6):
        varied, _a = apply_at_full_strength(name, bgr, alpha, seed)
        hue = circular_mean_hue(varied, ring)
        saturation = float(to_hsv(varied)[..., 1][ring].mean())
        assert -15.0 < hue < 20.0, f"{name}: red ring hue {hue:.1f} deg"  # orange-red .. pink-red, not magenta
        assert saturation > 0.4, f"{name}: red ring saturation {saturation:.2f}"


def test_wear_moves_red_towards_orange_or_pink_and_chalks_blue(catalogue):
    red, _ = master_face("2.30-50", face_size(catalogue, "2.30-50"), np.random.default_rng(0))
    ring = ink_layers(red) == RED
    shifts = {np.sign(round(circular_mean_hue(face_wear.uv_ageing(red, ink_layers(red), np.random.default_rng(s),
                                                                     1.0), ring) - circular_mean_hue(red, ring), 1))
              for s in range(12)}
    assert shifts == {-1.0, 1.0}  # some signs drift to orange (+), others to pink (-)
    blue, _ = master_face("4.08", face_size(catalogue, "4.08"), np.random.default_rng(0))
    labels = ink_layers(blue)
    field = labels == labels[10, SIZE // 2]  # the blue field near the top edge
    worn = face_wear.uv_ageing(blue, labels, np.random.default_rng(0), 1.0)
    before, after = to_hsv(blue)[field], to_hsv(worn)[field]
    assert after[:, 1].mean() < before[:, 1].mean() - 0.15  # chalky: less saturated
    assert after[:, 2].mean() > before[:, 2].mean() + 0.05  # and lighter


def test_dents_keep_the_outline_close_and_the_back_uses_the_same_outline(catalogue):
    size = face_size(catalogue, "1.14")
    _bgr, alpha = master_face("1.14", size, np.random.default_rng(0))
    warped = dent_warp(size, np.random.default_rng(3), 1.0, bend=True).outline(alpha)
    a, b = alpha > 128, warped > 128
    assert (a & b).sum() / (a | b).sum() > 0.95
    options = replace(FaceOptions(), master_share=1.0)
    dented = next(f for f in (SignFace("1.14", size, 0.9, 1, seed, options) for seed in range(100))
                  if f.dents() is not None)
    face_alpha = dented.pixels()[1]
    back_bgr, back_alpha = dented.back(np.random.default_rng(0))
    assert np.array_equal(face_alpha, back_alpha)
    assert not np.array_equal(face_alpha, master_face("1.14", size, np.random.default_rng(0))[1])


def test_same_recipe_same_pixels_and_switching_one_variation_off_keeps_the_others(catalogue):
    size = face_size(catalogue, "2.30-50")
    face = draw_sign_face("2.30-50", size, 0.6, np.random.default_rng(5), FaceOptions())
    first, again = face.pixels(), face.pixels()
    assert np.array_equal(first[0], again[0]) and np.array_equal(first[1], again[1])
    notes_all, notes_no_dirt = [], []
    face.pixels(notes_all)
    replace(face, options=replace(face.options, face_dirt=False)).pixels(notes_no_dirt)
    assert [n for n in notes_all if not n.startswith(("grime", "spots", "streaks"))] == notes_no_dirt


def test_artwork_mix_follows_the_configured_share():
    def share(options: FaceOptions, n: int = 1500) -> float:
        rng = np.random.default_rng(9)
        faces = [draw_sign_face("2.01", (32, 32), 0.6, rng, options) for _ in range(n)]
        return float(np.mean([f.artwork == "master" for f in faces]))

    assert 0.66 < share(FaceOptions(master_share=0.7)) < 0.74
    assert 0.27 < share(FaceOptions(master_share=0.3)) < 0.33
    assert share(FaceOptions(master_share=1.0)) == 1.0
    assert share(FaceOptions(face_artwork="procedural", master_share=1.0)) == 0.0


def test_a_sign_the_procedural_drawer_does_not_know_is_printed_from_its_master():
    face = SignFace("9.99-unknown", (64, 64), 0.6, 1, 2, FaceOptions(face_artwork="procedural"))
    assert face.artwork == "master"


@pytest.mark.parametrize("template_id", SIGNS)
def test_no_face_is_a_pixel_copy_of_its_master(catalogue, template_id):
    master_bgr, _a = catalogue.master(template_id)
    own_size = (master_bgr.shape[1], master_bgr.shape[0])
    bare = FaceOptions(master_share=1.0, **ALL_OFF, back_mounts=False)
    for seed in range(4):
        # even printed from the master at the master's own size with no variation at all
        face = SignFace(template_id, own_size, 0.6, seed, seed, bare)
        bgr, alpha = face.pixels()
        diff = np.abs(bgr.astype(float) - master_bgr.astype(float))[inner_mask(alpha)]
        assert diff.mean() > 1.0, f"face {seed} of {template_id} is nearly the master: mean |d| {diff.mean():.2f}"
        # and as the generator draws them, against the template at the face's size
        varied = draw_sign_face(template_id, face_size(catalogue, template_id), 0.6, np.random.default_rng(seed),
                                FaceOptions())
        vb, va = varied.pixels()
        template, _ta = catalogue.render(template_id, (vb.shape[1], vb.shape[0]))
        assert np.abs(vb.astype(float) - template.astype(float))[inner_mask(va)].mean() > 1.0


def test_legacy_faces_are_the_procedural_drawing_with_the_older_weathering_only(catalogue):
    config = SimulationConfig(**LEGACY_FACES)
    options = FaceOptions.from_config(config)
    assert options == PROCEDURAL_ONLY
    size = face_size(catalogue, "1.14", 200)
    face = draw_sign_face("1.14", size, 0.9, np.random.default_rng(4), options)
    expected_bgr, expected_alpha = procedural_face("1.14", size, np.random.default_rng(face.style_seed))
    expected_bgr = weather_face(expected_bgr, expected_alpha, np.random.default_rng(face.effect_seed), face.faded,
                                face.dirt, face.shadow)
    bgr, alpha = face.pixels()
    assert np.array_equal(bgr, expected_bgr) and np.array_equal(alpha, expected_alpha)


def test_faces_do_not_move_signs_truth_and_poses_are_those_of_legacy_faces(tmp_path):
    base = dict(pairs=3, seed=21, width=320, height=180, fx=1750.0 / 6, sign_density=25.0)
    generate_drive(tmp_path / "new", SimulationConfig(**base, **DRAWABLE_SIGNS))  # legacy faces: the signs of before
    generate_drive(tmp_path / "old", SimulationConfig(**base, **LEGACY_FACES))
    for name in ("poses.csv", "drive.json"):
        assert (tmp_path / "new" / name).read_bytes() == (tmp_path / "old" / name).read_bytes(), name
    new_truth, old_truth = read_truth(tmp_path / "new" / "truth.csv"), read_truth(tmp_path / "old" / "truth.csv")
    assert len(new_truth) > 1
    # the same signs in the same places; only the artwork their faces were printed from differs
    assert [replace(t, artwork="") for t in new_truth] == [replace(t, artwork="") for t in old_truth]
    assert {t.artwork for t in old_truth if not t.is_plate} == {"procedural"}
    assert "master" in {t.artwork for t in new_truth}
    new_left = (tmp_path / "new" / "left" / "000000.jpg").read_bytes()
    assert new_left != (tmp_path / "old" / "left" / "000000.jpg").read_bytes()


@pytest.mark.parametrize("settings, message", [({"face_artwork": "official"}, "face_artwork"),
                                               ({"master_share": 1.5}, "master_share"),
                                               ({"sign_set": "all"}, "sign_set"),
                                               ({"white_sign_share": 0.3}, "white_sign_share applies to")])
def test_bad_face_settings_are_rejected_by_name(settings, message):
    with pytest.raises(ValueError, match=message):
        SimulationConfig(**settings).validate()
    SimulationConfig(white_sign_share=0.3, **DRAWABLE_SIGNS).validate()  # the drives of before take it


def test_no_two_procedural_drawings_of_one_colour_and_shape_look_alike(catalogue):
    """A procedural face must be readable as its own sign: the moped of 2.06 was once a bicycle with a small
    box under the saddle, 0.7 grey levels from 2.05's bicycle, so drives counted a right reading as wrong."""
    from signmapper_core.simulate.face_artwork import has_procedural

    faces = {}
    for entry in catalogue:
        if has_procedural(entry.id):
            size = (96, int(round(96 / entry.aspect)))
            faces[entry.id] = (entry.colour, entry.shape, procedural_face(entry.id, size, np.random.default_rng(5))[0])
    ids = sorted(faces)
    for i, a in enumerate(ids):
        for b in ids[i + 1:]:
            (ca, sa, fa), (cb, sb, fb) = faces[a], faces[b]
            if (ca, sa) == (cb, sb) and fa.shape == fb.shape:
                assert np.abs(fa.astype(np.float32) - fb).mean() > 1.0, (a, b)
    for seed in range(4):
        bicycle = procedural_face("2.05", (96, 96), np.random.default_rng(seed))[0].astype(np.float32)
        moped = procedural_face("2.06", (96, 96), np.random.default_rng(seed))[0]
        assert np.abs(bicycle - moped).mean() > 5.0
