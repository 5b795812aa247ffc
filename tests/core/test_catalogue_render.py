"""Rendering of templates and procedural faces: sizes, outline masks, colour classes, style variation."""

from __future__ import annotations

import math

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import FaceStyle, load_catalogue, render_face
from signmapper_core.catalogue.drawing import to_svg
from signmapper_core.catalogue.faces import face_drawing
from signmapper_core.catalogue.signs_ch import SIGNS

# fraction of the bounding box covered by the outline, and tolerance (corners are rounded)
SHAPE_FILL = {
    "circle": (math.pi / 4, 0.02),
    "triangle": (0.5, 0.06),
    "triangle-down": (0.5, 0.06),
    "octagon": (2 / (1 + math.sqrt(2)), 0.02),
    "diamond": (0.5, 0.05),
    "square": (1.0, 0.02),
    "rectangle": (1.0, 0.02),
}


@pytest.fixture(scope="module")
def cat():
    return load_catalogue()


def colour_class(bgr: np.ndarray, alpha: np.ndarray) -> str:
    """Dominant chromatic class inside the outline, as a colour segmenter sees it; "white" below 5 %."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    inside = alpha > 200
    h, s, v = hsv[..., 0][inside], hsv[..., 1][inside], hsv[..., 2][inside]
    chroma = (s > 90) & (v > 70)
    counts = {
        "red": int(np.sum(chroma & ((h <= 10) | (h >= 165)))),
        "yellow": int(np.sum(chroma & (h >= 18) & (h <= 35))),
        "blue": int(np.sum(chroma & (h >= 95) & (h <= 130))),
    }
    best = max(counts, key=counts.get)
    return best if counts[best] > 0.05 * inside.sum() else "white"


def test_every_entry_renders_at_24_64_256(cat):
    for e in cat:
        for n in (24, 64, 256):
            bgr, alpha = cat.render(e.id, n)
            assert bgr.dtype == np.uint8 and alpha.dtype == np.uint8
            assert bgr.shape[:2] == alpha.shape and bgr.shape[2] == 3
            assert max(alpha.shape) == n
            # within a pixel of the shorter side: a 5:1 pointer is 5 px high at 24 px
            rel = max(0.06, 1.0 / min(alpha.shape))
            assert alpha.shape[1] / alpha.shape[0] == pytest.approx(e.aspect, rel=rel)
            assert alpha.max() == 255
            if e.shape not in ("square", "rectangle"):
                assert alpha.min() == 0


def drawn(cat):
    """The entries the project draws itself too (the others' masters: test_catalogue_whole_set)."""
    return [e for e in cat if e.id in SIGNS]


def test_alpha_mask_matches_the_declared_shape(cat):
    for e in drawn(cat):
        _, alpha = cat.render(e.id, 256)
        expected, tol = SHAPE_FILL[e.shape]
        if e.id == "4.33":  # a direction panel: a rectangle with one end pointed, in its rectangle's box
            expected, tol = 0.88, 0.05
        assert alpha.mean() / 255 == pytest.approx(expected, abs=tol), e.id


def test_triangles_point_the_declared_way(cat):
    _, up = cat.render("1.22", 128)
    _, down = cat.render("3.02", 128)
    assert up[:10].mean() < up[-10:].mean()
    assert down[:10].mean() > down[-10:].mean()


def test_dominant_colour_matches_the_colour_class(cat):
    wrong = {}
    for e in drawn(cat):
        got = colour_class(*cat.render(e.id, 64))
        if got != e.colour:
            wrong[e.id] = (e.colour, got)
    assert not wrong


def test_render_face_reference_equals_default_style():
    a = render_face("2.30-50", 80)
    b = render_face("2.30-50", 80, FaceStyle())
    assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])


def test_catalogue_render_of_an_own_drawing_is_close_to_the_reference_face(cat):
    # entries without official artwork keep the procedural drawing (official ones and the own values set into
    # the official rim: test_catalogue_official); the outline is the procedural one's for all of them
    for tid in ("2.30-70", "2.53-50", "2.17-10", "2.47-70"):
        t_bgr, t_alpha = cat.render(tid, 64)
        f_bgr, f_alpha = render_face(tid, 64)
        assert np.abs(t_alpha.astype(int) - f_alpha).mean() < 2
    t_bgr, _ = cat.render("2.53-50", 64)
    assert np.abs(t_bgr.astype(int) - render_face("2.53-50", 64)[0]).mean() < 6


@pytest.mark.parametrize("tid", ["2.30-50", "2.01", "1.22", "3.01", "3.02", "3.03", "2.33", "4.08", "1.32",
                                 "2.59.1-30"])
def test_render_face_with_a_varied_style_differs_but_keeps_the_colour_class(cat, tid):
    ref_bgr, ref_alpha = render_face(tid, 96)
    for seed in range(3):
        style = FaceStyle.random(np.random.default_rng(seed))
        bgr, alpha = render_face(tid, 96, style)
        assert bgr.shape == ref_bgr.shape
        inside = (alpha > 200) & (ref_alpha > 200)
        diff = np.abs(bgr.astype(int) - ref_bgr.astype(int)).max(axis=2)[inside]
        assert (diff > 12).mean() > 0.02, (tid, seed)
        assert colour_class(bgr, alpha) == cat[tid].colour, (tid, seed, style)
    a = render_face(tid, 96, FaceStyle.random(np.random.default_rng(5)))
    b = render_face(tid, 96, FaceStyle.random(np.random.default_rng(5)))
    assert np.array_equal(a[0], b[0])


def test_render_face_sizes_and_unknown_ids():
    bgr, alpha = render_face("1.01", (50, 40))
    assert bgr.shape == (40, 50, 3) and alpha.shape == (40, 50)
    bgr, alpha = render_face("1.01", 30)
    assert alpha.shape == (26, 30)
    with pytest.raises(KeyError):
        render_face("9.99", 30)
    with pytest.raises(ValueError):
        render_face("1.01", 0)


def test_svg_is_written_from_the_same_drawing():
    svg = to_svg(face_drawing("2.30-50"), 64, "2.30-50")
    assert svg.startswith("<?xml") and "<svg" in svg and svg.rstrip().endswith("</svg>")
    assert ">50</text>" in svg and "#c81420" in svg.lower()


def test_random_styles_keep_every_entry_in_its_colour_class_and_shape(cat):
    """The generator draws random styles: no style may turn a sign into another colour class."""
    for e in drawn(cat):
        for seed in (11, 12):
            bgr, alpha = render_face(e.id, 48, FaceStyle.random(np.random.default_rng(seed)))
            assert colour_class(bgr, alpha) == e.colour, (e.id, seed)
            expected, tol = SHAPE_FILL[e.shape]
            assert alpha.mean() / 255 == pytest.approx(expected, abs=tol + 0.03), (e.id, seed)
