"""Other designs of a sign for training (training/face_variants.py) and the class shares of the labels.

Training itself needs PyTorch and is not run here; these parts need only OpenCV,
numpy and Pillow, and a wrong variant would teach the network a wrong class.
"""

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.plates.printed_numbers import speed_limit_number
from training.dataset import CLASS_SHARE, class_shares, labels_for
from training.face_variants import (
    MIRROR_SAFE,
    design_field,
    inner_field,
    mirrored,
    pictogram_scaled,
    pictogram_variant,
    speed_limit_face,
)

SIDE = 96


@pytest.fixture(scope="module")
def catalogue():
    return load_catalogue()


def small_master(catalogue, tid):
    bgr, alpha = catalogue.master(tid)
    return (cv2.resize(bgr, (SIDE, SIDE), interpolation=cv2.INTER_AREA),
            cv2.resize(alpha, (SIDE, SIDE), interpolation=cv2.INTER_AREA))


def test_no_mirror_safe_sign_has_a_mirror_twin_in_the_catalogue(catalogue):
    """Flipping a sign that another sign mirrors (curves, narrowing, descent/climb) would teach the wrong class.

    A twin: the flipped face matches another face better than itself, and closely.
    """
    faces = {e.id: small_master(catalogue, e.id)[0].astype(np.float32) for e in catalogue
             if e.shape in ("triangle", "circle")}

    def ncc(x, y):
        return float(cv2.matchTemplate(x, y, cv2.TM_CCOEFF_NORMED)[0, 0])

    twins = set()
    for a, fa in faces.items():
        flipped = np.ascontiguousarray(fa[:, ::-1])
        itself = ncc(flipped, fa)
        twins.update(b for b, fb in faces.items() if b != a and ncc(flipped, fb) > max(0.92, itself))
    assert {"1.01", "1.02", "1.03", "1.04", "1.08", "1.09", "1.10", "1.11", "2.42", "2.43", "3.07",
            "3.08"} <= twins  # the check finds the known pairs
    assert not twins & MIRROR_SAFE
    assert MIRROR_SAFE <= {e.id for e in catalogue}


def test_mirrored_flips_face_and_outline_together(catalogue):
    face, alpha = small_master(catalogue, "1.23")
    f2, a2 = mirrored(face, alpha)
    assert np.array_equal(f2[:, 0], face[:, -1]) and np.array_equal(a2[:, 5], alpha[:, -6])


def test_inner_field_of_the_empty_ring_is_the_white_disc(catalogue):
    ring, alpha = small_master(catalogue, "2.01")
    field = inner_field(ring, alpha)
    assert field[SIDE // 2, SIDE // 2] and not field[0, 0] and not field[SIDE // 2, 2]
    share = field.mean()
    assert 0.25 < share < 0.55, share  # a disc of 0.6-0.8 of the diameter
    assert (ring[field].astype(int).sum(axis=1) > 600).mean() > 0.95  # white inside
    assert inner_field(*small_master(catalogue, "2.32")) is None  # a blue face has no red rim


def test_speed_limit_face_draws_the_number_inside_the_field_only(catalogue):
    ring, alpha = small_master(catalogue, "2.01")
    field = inner_field(ring, alpha)
    for seed in range(12):  # every font, sizes and widths
        face = speed_limit_face(ring, alpha, "120", np.random.default_rng(seed))
        changed = np.abs(face.astype(int) - ring.astype(int)).sum(axis=2) > 30
        assert changed.sum() > 0.04 * SIDE * SIDE, seed  # a legible number
        assert not (changed & ~field).any(), seed
        ink = face[changed].astype(int).sum(axis=1)
        assert np.median(ink) < 300  # dark digits
    assert speed_limit_number("2.30-80") == "80" and speed_limit_number("2.30.1") is None
    assert speed_limit_number("2.31-60") is None


def test_pictogram_scaled_keeps_the_rim(catalogue):
    face, alpha = small_master(catalogue, "2.08")
    field = inner_field(face, alpha)
    rng = np.random.default_rng(2)
    out = pictogram_scaled(face, alpha, rng)
    assert np.array_equal(out[~field], face[~field])
    assert np.abs(out[field].astype(int) - face[field].astype(int)).sum() > 0  # the bus changed size
    blue, blue_alpha = small_master(catalogue, "2.32")
    assert np.array_equal(pictogram_scaled(blue, blue_alpha, rng), blue)


@pytest.mark.parametrize("template_id", ["1.31", "2.15", "4.20", "2.53-60"])
def test_pictogram_variant_redraws_only_inside_the_field(catalogue, template_id):
    """Generic design variation: the pictogram moves, bends, is restroked; rim, border and outline stay."""
    face, alpha = small_master(catalogue, template_id)
    field, colour = design_field(face, alpha)
    assert 0.1 * alpha.size < field.sum() < (alpha > 127).sum()
    assert np.abs(np.median(face[field].astype(np.float32), axis=0) - colour).sum() < 30  # the field's paint
    changed = 0
    for seed in range(6):
        out = pictogram_variant(face, alpha, np.random.default_rng(seed))
        assert out.shape == face.shape and out.dtype == face.dtype
        assert np.array_equal(out[~field], face[~field])
        changed += np.abs(out[field].astype(int) - face[field].astype(int)).sum() > 0
    assert changed == 6


def test_field_of_a_blue_panel_leaves_its_white_edge_out(catalogue):
    face, alpha = small_master(catalogue, "4.20")
    field, colour = design_field(face, alpha)
    assert colour[0] > colour[2] + 60  # blue paint
    ys, xs = np.nonzero(alpha > 127)
    assert not field[ys.min():ys.min() + 2].any() and not field[:, xs.min():xs.min() + 2].any()


def test_labels_follow_class_shares():
    ids = ["2.30-50", "2.30.1", "1.23"]
    labels = labels_for(3, 100, 50, seed=4, shares=class_shares(ids))
    counts = {i: int((labels == k).sum()) for k, i in enumerate(ids)}
    assert counts == {"2.30-50": 100, "2.30.1": round(100 * CLASS_SHARE["2.30.1"]), "1.23": 100}
    assert int((labels == -1).sum()) == 50
    assert np.array_equal(labels, labels_for(3, 100, 50, seed=4, shares=class_shares(ids)))


def test_rims_grow_only_with_design_variants(catalogue):
    """Without ``--design-variants`` rims only thin, as the shipped model was trained; with it some grow."""
    from training.face_wear import colour_masks, rim_width

    face, alpha = small_master(catalogue, "2.30-50")
    face = face.astype(np.float32)
    red = colour_masks(face, alpha)[0].sum()
    thin_only = [colour_masks(rim_width(face, alpha, np.random.default_rng(s), wider=False), alpha)[0].sum()
                 for s in range(20)]
    both = [colour_masks(rim_width(face, alpha, np.random.default_rng(s), wider=True), alpha)[0].sum()
            for s in range(20)]
    assert max(thin_only) <= red
    assert max(both) > red * 1.05 and min(both) < red


def test_design_variants_switch_the_pictogram_redrawing(catalogue, monkeypatch):
    """The default faces are the shipped model's: pictograms scaled (30 %), never redrawn."""
    from training import compose

    calls = {"scaled": 0, "variant": 0}

    def counted(name):
        def redraw(face, alpha, rng):
            calls[name] += 1
            return face
        return redraw

    monkeypatch.setattr(compose, "pictogram_scaled", counted("scaled"))
    monkeypatch.setattr(compose, "pictogram_variant", counted("variant"))
    maker = compose.SampleMaker.__new__(compose.SampleMaker)
    maker.masters = {"1.31": [small_master(catalogue, "1.31")]}  # its drawings: one here
    for flag in (False, True):
        maker.design_variants = flag
        for s in range(200):
            maker._design("1.31", np.random.default_rng(s))
    assert 30 < calls["scaled"] < 90 and 70 < calls["variant"] < 130


def _ink_components(face, field, colour):
    from training.face_variants import _ink

    ink = _ink(face.astype(np.float32), field, colour)
    return ink, cv2.connectedComponents(ink.astype(np.uint8))[0] - 1


@pytest.mark.parametrize("template_id", ["1.09", "2.37"])
def test_line_drawn_thins_every_stroke_and_keeps_it(template_id):
    """A thin-pen design: less paint, the same separate strokes, nothing outside the field touched."""
    from training.compose import WORK_PX
    from training.face_variants import _line_drawn

    bgr, alpha = load_catalogue().master(template_id)
    face = cv2.resize(bgr, (WORK_PX, WORK_PX), interpolation=cv2.INTER_AREA).astype(np.float32)
    alpha = cv2.resize(alpha, (WORK_PX, WORK_PX), interpolation=cv2.INTER_AREA)
    field, colour = design_field(face, alpha)
    ink, strokes = _ink_components(face, field, colour)
    for seed in range(4):
        out = _line_drawn(face, field, colour, np.random.default_rng(seed))
        assert np.array_equal(out[~field], face[~field])
        new_ink, new_strokes = _ink_components(out, field, colour)
        assert 0.2 * ink.sum() < new_ink.sum() < 0.8 * ink.sum()
        assert new_strokes == strokes
        assert not (new_ink & ~cv2.dilate(ink.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)).any()


def test_line_drawn_leaves_many_coloured_pictograms_alone(catalogue):
    face, alpha = small_master(catalogue, "1.31")  # traffic lights: red, yellow and green in black
    field, colour = design_field(face, alpha)
    img = face.astype(np.float32)
    from training.face_variants import _line_drawn

    assert np.array_equal(_line_drawn(img, field, colour, np.random.default_rng(0)), img)
