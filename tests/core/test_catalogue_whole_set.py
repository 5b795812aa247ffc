"""The bundled catalogue holds the whole official set: every Signalo id covered, colours and outlines as drawn."""

from __future__ import annotations

import re

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import DEFAULT_CATALOGUE_DIR, load_catalogue
from signmapper_core.catalogue.model import MEASURED, STANDARD, fits_measured, round_size
from signmapper_core.catalogue.names import NAMES_EN, sign_name
from signmapper_core.catalogue.official_entries import OFFICIAL_ENTRIES
from signmapper_core.catalogue.official_signs import official_signs
from signmapper_core.catalogue.text_panels import COVERED_BY_PANEL
from signmapper_core.signalo.types import from_signalo, to_signalo


@pytest.fixture(scope="module")
def cat():
    return load_catalogue()


def covering_entries(signalo_id: str, ids) -> list:
    """Our entries that stand for one Signalo id: itself, its per-value entries, or its generic text panel."""
    if signalo_id in ids:
        return [signalo_id]
    if signalo_id in COVERED_BY_PANEL:
        return [COVERED_BY_PANEL[signalo_id]]
    return [t for t in ids if t.rpartition("-")[0] == signalo_id]


def test_every_official_sign_but_the_plates_is_covered(cat):
    ids = set(cat.ids())
    signs = [s for s in official_signs() if not s.startswith("5.")]
    uncovered = [s for s in signs if not covering_entries(s, ids)]
    assert uncovered == []
    assert len(signs) == 308 and len(cat) == 313
    # and every entry maps back to Signalo: the export has an official id for each of them
    official = set(official_signs())
    assert [t for t in ids if to_signalo(t, official) is None] == []


def test_the_ids_are_signalos_own(cat):
    assert {"4.77/01", "2.59.1-30", "2.59.1-NP", "0.1-1.1", "2.63-1-a", "3.22"} <= set(cat.ids())
    assert cat["4.77/01"].png == "png/4.77_01.png"
    assert from_signalo("2.59.1-30", None, set(cat.ids())) == "2.59.1-30"
    assert to_signalo("2.59.1-30", set(official_signs())) == ("2.59.1-30", None)


def test_names_are_signalos_in_three_languages(cat):
    assert cat["4.31-1"].names == {
        "de": "Wegweiser zu Autobahnen oder Autostrassen (1 Linie)",
        "fr": "Indicateur de direction pour autoroutes et semi-autoroutes (1 ligne)",
        "it": "Indicatore di direzione per le autostrade e semiautostrade (1 ligne)"}
    assert cat["2.59.4"].names["de"] == "Ende der Fussgängerzone"  # Signalo's line-break hyphen joined
    assert cat["2.63"].names["de"].startswith("Rad- und Fussweg")  # a real hyphen kept
    assert cat["2.30-50"].names["de"] == "Höchstgeschwindigkeit 50"  # per-value entries keep their own
    assert [e.id for e in cat if e.id not in NAMES_EN] == []  # and every entry has an English name
    assert sign_name(cat["3.22"], "en") == "Single St Andrew's cross"


@pytest.mark.parametrize("colour, least", [("red", 80), ("blue", 80), ("yellow", 4), ("white", 50), ("green", 12),
                                           ("brown", 9), ("orange", 11)])
def test_every_colour_family_is_there(cat, colour, least):
    assert len(cat.filter(colours=[colour], text_panels=True)) >= least


HUE_BANDS = {"red": ((0, 10), (165, 180)), "brown": ((0, 10), (165, 180)), "orange": ((10, 18),),
             "yellow": ((18, 35),), "green": ((35, 90),), "blue": ((90, 135),)}


def _hue_share(bgr: np.ndarray, alpha: np.ndarray, colour: str) -> float:
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)[alpha > 128]
    saturated = (hsv[:, 1] > 90) & (hsv[:, 2] > 50)
    hue = hsv[:, 0]
    band = np.zeros(len(hsv), bool)
    for lo, hi in HUE_BANDS[colour]:
        band |= (hue >= lo) & (hue < hi)
    return float((band & saturated).mean())


@pytest.mark.parametrize("tid", sorted(OFFICIAL_ENTRIES))
def test_the_declared_colour_and_outline_are_the_drawings(cat, tid):
    entry = cat[tid]
    bgr, alpha = cat.master(tid)
    if entry.colour == "white":  # no hue covers a third of the face
        assert max(_hue_share(bgr, alpha, c) for c in HUE_BANDS) < 0.3
    else:
        share = _hue_share(bgr, alpha, entry.colour)
        assert share >= 0.3 or (entry.colour == "red" and share >= 0.2), share
    fill = float((alpha > 128).mean())
    expected = {"circle": (0.74, 0.83), "triangle": (0.5, 0.7), "diamond": (0.45, 0.56), "square": (0.97, 1.0),
                "rectangle": (0.97, 1.0), "pointer": (0.45, 0.95), "cross": (0.45, 0.6)}[entry.shape]
    assert expected[0] <= fill <= expected[1], fill
    if entry.shape == "square":
        assert 0.93 <= entry.aspect <= 1.07


def test_brown_is_darker_than_red(cat):
    def value(tid):
        bgr, alpha = cat.master(tid)
        hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)[alpha > 128]
        return float(np.median(hsv[hsv[:, 1] > 90][:, 2]))
    assert value("0.1") < 150 < value("2.01")


def test_signs_without_a_standard_size_are_sized_as_measured(cat):
    board = cat["4.64"]
    assert board.sizing == MEASURED and not board.size_certain and list(board.formats) == ["nominal"]
    assert cat["2.15.1"].sizing == STANDARD and cat["2.15.1"].formats["normal"] == (0.6, 0.6)
    w, h = board.formats["nominal"]
    match = round_size([board], 2.0 * w, 1.5 * h)  # a longer destination: wider and taller than the drawing's
    assert match is not None and match.format == MEASURED and match.template_ids == ("4.64",)
    assert (match.width_m, match.height_m) == (2.0 * w, 1.5 * h)
    assert not fits_measured(board, 0.1, 0.1) and round_size([board], w, 5 * h) is None  # a bar, not a board
    # a standard format wins where one fits
    assert round_size([cat["2.15.1"], cat["4.64"]], 0.6, 0.6).format == "normal"


def test_language_versions_and_directions_are_one_entry_with_variants(cat):
    assert len(cat["2.30.1"].variants) == 3  # GENERELL, GÉNÉRAL, GENERALE, GENERAL
    pointer = cat["4.32-1"]
    assert len(pointer.variants) == 1
    _, lalpha = cat.master("4.32-1")
    (_, ralpha), = cat.variant_masters("4.32-1")
    w = lalpha.shape[1]
    # the left pointer's tip is on the left, the right one's on the right
    assert lalpha[:, : w // 20].mean() < lalpha[:, -w // 20:].mean()
    assert ralpha[:, -w // 20:].mean() < ralpha[:, : w // 20].mean()
    assert len(cat["1.17"].variants) == 2  # the beacons with two and one stripes


def test_every_image_file_is_named_after_its_entry(cat):
    names = {p.name for p in (DEFAULT_CATALOGUE_DIR / "png").glob("*.png")}
    expected = set()
    for e in cat:
        expected.add(e.png.split("/")[1])
        expected.update(v.split("/")[1] for v in e.variants)
    assert names == expected
    assert all(re.fullmatch(r"[0-9A-Za-z._~-]+\.png", n) for n in names)
