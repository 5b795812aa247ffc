"""Signalo's table of official signs, the catalogue's list of ids: read whole, names and drawings per id."""

from __future__ import annotations

import csv

from signmapper_core.catalogue.official_signs import TABLE, official_signs


def test_every_active_row_is_read_with_its_names_and_drawings():
    with TABLE.open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    signs = official_signs()
    assert len(signs) == sum(r["active"] == "True" for r in rows) == 365
    assert signs["1.01"].names == {"de": "Rechtskurve", "fr": "Virage à droite", "it": "Curva a destra"}
    assert signs["1.01"].drawings == ("101.svg",)


def test_language_and_direction_drawings_of_one_id_stay_one_sign():
    signs = official_signs()
    assert signs["2.30.1"].drawings == ("230-1-a.svg", "230-1-b.svg", "230-1-c.svg", "230-1-d.svg")
    pointer = signs["4.31-1"]
    assert pointer.directional and (pointer.left_drawing, pointer.right_drawing) == ("431-1-l.svg", "431-1-r.svg")
    assert signs["2.30"].inscriptions == 1 and signs["4.77/01"].drawings == ("477-1.svg",)
