"""Procedural faces of another pictogram are reported apart: the list, the grouping and the evaluation's lines."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from signmapper_core.catalogue import load_catalogue
from signmapper_core.simulate.artwork_sheet import artwork_sheet
from signmapper_core.simulate.face_artwork import (
    MASTER,
    OFFICIAL_PICTOGRAM,
    OTHER,
    OTHER_PICTOGRAM,
    PROCEDURAL,
    has_procedural,
    pictogram_group,
)


def test_every_listed_sign_is_in_the_catalogue_and_drawn_procedurally():
    ids = {e.id for e in load_catalogue()}
    assert set(OTHER_PICTOGRAM) <= ids
    assert all(has_procedural(tid) for tid in OTHER_PICTOGRAM)
    assert all(reason.strip() for reason in OTHER_PICTOGRAM.values())


def test_group_depends_on_artwork_and_id():
    assert pictogram_group("2.12", PROCEDURAL) == OTHER
    assert pictogram_group("2.12", MASTER) == OFFICIAL_PICTOGRAM  # the official drawing is the official pictogram
    assert pictogram_group("2.07", PROCEDURAL) == OFFICIAL_PICTOGRAM
    assert pictogram_group("2.12", "") == ""


def test_sheet_has_a_tile_per_sign_in_rows_of_six():
    sheet = artwork_sheet(["2.12", "2.07", "3.01"], 40, np.random.default_rng(0))
    tile_w, tile_h = 2 * 40 + 4, 40 + 14
    assert sheet.shape == (tile_h, 6 * tile_w, 3)
    # the master face of 2.12 (left of its tile) is drawn: not the grey background alone
    assert sheet[14:, :40].std() > 10


def test_evaluation_counts_each_group_and_the_official_pictogram_total():
    from scripts import evaluate_mapping as em

    reference = [SimpleNamespace(template_id=t, artwork=a) for t, a in
                 [("2.12", PROCEDURAL), ("2.12", MASTER), ("2.07", PROCEDURAL), ("2.07", PROCEDURAL), ("1.01", "")]]
    signs = [SimpleNamespace(template_id=t) for t in ("2.13", "2.12", "2.07", "2.09")]
    report = SimpleNamespace(match=[0, 1, 2, 4])  # the second procedural 2.07 is missed
    totals = em.by_artwork(signs, reference, report)
    assert totals == {(PROCEDURAL, OTHER): [1, 1, 0], (MASTER, OFFICIAL_PICTOGRAM): [1, 1, 1],
                      (PROCEDURAL, OFFICIAL_PICTOGRAM): [2, 1, 1]}
    lines = em.artwork_lines(totals)
    assert len(lines) == 4
    assert lines[-1].startswith(f"Fused signs whose face was printed from any artwork showing the {OFFICIAL_PICTOGRAM}"
                                ": 3; detected 2 (66.7 %), correctly classified 2 (100.0 %")
    assert any("procedural artwork (other pictogram): 1; detected 1 (100.0 %), correctly classified 0 (0.0 %"
               in line for line in lines)
