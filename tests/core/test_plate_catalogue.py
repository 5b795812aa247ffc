"""Plate templates: the shipped renderings of every plate of Signalo's table, building them from drawings, and
broken plate folders."""

from __future__ import annotations

import csv
import json

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import plate_build, svg_render
from signmapper_core.catalogue.model import DEFAULT_CATALOGUE_DIR
from signmapper_core.catalogue.official_signs import TABLE, official_signs
from signmapper_core.catalogue.plates_ch import plate_drawings, signalo_id
from signmapper_core.plates.catalogue import (
    LAYOUT,
    PICTOGRAM,
    TEXT,
    PlateCatalogueError,
    drawn_plates,
    load_plate_templates,
    pictogram_formats,
)

needs_renderer = pytest.mark.skipif(not svg_render.renderer_available(),
                                    reason="rsvg-convert (Debian package librsvg2-bin) is not installed")


def test_the_shipped_plate_templates_are_every_drawing_of_the_table():
    templates = load_plate_templates(DEFAULT_CATALOGUE_DIR)
    assert {(t.id, t.variant) for t in templates} == {(p.id, p.variant) for p in plate_drawings()}
    plate_ids = {i for i in official_signs() if i.startswith("5.")}
    assert {signalo_id(t.id) for t in templates} == plate_ids and len(plate_ids) == 57
    assert len(templates) == 64  # language versions and the two directions of 5.02 and 5.07
    for t in templates:
        assert max(t.grey.shape) == plate_build.MASTER_PX
        assert t.aspect == pytest.approx(t.grey.shape[1] / t.grey.shape[0], abs=1e-2)
        assert (t.grey < 128).mean() > 0.05, t.id  # print (black, or green, blue, red)
    # white paper, but for the black plate of 5.18 (a yellow bicycle turning right)
    assert {t.id for t in templates if np.percentile(t.grey, 75) < 200} == {"5.18"}
    by = {(t.id, t.variant): t for t in templates}
    assert by[("5.31-2", "de")].text == "ausgenommen" and by[("5.31-2", "fr")].text == "exceptés"
    assert by[("5.20", "de")].text == "" and by[("5.57", "de")].text == "SOS"
    kinds = {t.id: t.kind for t in templates}
    assert [i for i, k in sorted(kinds.items()) if k == TEXT] == ["5.00-1", "5.00-2", "5.00-3", "5.00-exception",
                                                                  "5.01"]
    assert [i for i, k in sorted(kinds.items()) if k == LAYOUT] == ["5.02-l", "5.02-r", "5.03", "5.15", "5.17",
                                                                    "5.31-3"]
    assert kinds["5.07-r"] == kinds["5.20"] == kinds["5.58"] == PICTOGRAM
    coloured = {t.id for t in templates if t.coloured}
    assert {"5.10", "5.11", "5.17", "5.18", "5.54", "5.56", "5.58"} <= coloured and not coloured & {"5.20", "5.03"}
    assert {t.id for t in drawn_plates(templates)} == set(kinds) - {i for i, k in kinds.items() if k == TEXT}
    formats = pictogram_formats(templates)
    assert formats["5.31@0.60"] == (0.6, pytest.approx(0.6 / by[("5.31", "de")].aspect, abs=1e-3))
    assert formats["5.05@0.60"] == (pytest.approx(0.6 * by[("5.05", "de")].aspect, abs=1e-3), 0.6)  # upright
    assert not any(name.startswith("5.01@") for name in formats)  # text plates have the text formats


def test_a_plates_language_versions_are_the_german_and_french_drawings_of_signalos_table():
    with TABLE.open(encoding="utf-8", newline="") as f:
        rows = {r["id"]: r for r in csv.DictReader(f) if r["id"].startswith("5.")}
    for plate in plate_drawings():
        row = rows[plate.signalo_id]
        if plate.direction:
            assert plate.drawing == row["img_de" if plate.direction == "l" else "img_de_right"]
        else:
            assert plate.drawing == row[f"img_{plate.variant}"]
            assert row["img_it"] in (row["img_de"], row["img_fr"])  # no Italian drawing of its own
        assert plate.names["fr"] == row["value_fr"].strip() or plate.direction


def test_a_layout_plates_text_field_holds_its_text_and_none_of_its_drawing():
    templates = {(t.id, t.variant): t for t in load_plate_templates(DEFAULT_CATALOGUE_DIR)}
    plate = templates[("5.03", "de")]  # two arrows around "2,5 km"
    x0, y0, x1, y1 = plate_build.field_pixels(plate.grey.shape, plate.field)
    ink = plate.grey < plate_build.INK_GREY
    outside = ink.copy()
    outside[y0:y1, x0:x1] = False
    assert ink[y0:y1, x0:x1].mean() > 0.15  # the digits
    # the arrows at both ends, outside the field
    assert outside[:, :x0].mean() > 0.1 and outside[:, x1:].mean() > 0.1
    master = cv2.cvtColor(plate.grey, cv2.COLOR_GRAY2BGR)
    plate_build.check_field(master, plate.field, "5.03")
    with pytest.raises(ValueError, match="cuts 1 strokes"):  # into the right arrow
        plate_build.check_field(master, (0.18, 0.08, 0.90, 0.92), "5.03")
    with pytest.raises(ValueError, match="holds no print"):
        plate_build.check_field(master, (0.16, 0.01, 0.84, 0.05), "5.03")


def test_a_catalogue_without_plates_has_no_pictogram_plates(tmp_path):
    assert load_plate_templates(tmp_path) == ()


@pytest.mark.parametrize("content, message", [
    ("{not json", "not readable as JSON"),
    (json.dumps({"format": "other/1", "plates": []}), "is not 'signmapper-plates/1'"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.31", "variant": "de", "names": {},
                                                             "aspect": 1.4, "png": "png/gone.png"}]}),
     "plate 1: image .*gone.png is missing"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.31"}]}), "plate 1 lacks the field"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.03", "variant": "de", "names": {},
                                                             "aspect": 2.9, "png": "png/5.03.png", "kind": "layout"}]}),
     "plate 1: a layout plate, and only one, has a text field"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.03", "variant": "de", "names": {},
                                                             "aspect": 2.9, "png": "png/5.03.png", "kind": "round"}]}),
     "plate 1: kind 'round' is none of"),
])
def test_a_broken_plate_folder_names_the_file_and_what_is_wrong(tmp_path, content, message):
    (tmp_path / "plates" / "png").mkdir(parents=True)
    cv2.imwrite(str(tmp_path / "plates" / "png" / "5.03.png"), np.full((20, 58), 255, np.uint8))
    (tmp_path / "plates" / "plates.json").write_text(content, encoding="utf-8")
    with pytest.raises(PlateCatalogueError, match=message) as info:
        load_plate_templates(tmp_path)
    assert str(tmp_path / "plates" / "plates.json") in str(info.value)


@needs_renderer
def test_a_drawing_is_cut_to_its_outline_and_set_on_white(tmp_path):
    svg = tmp_path / "5xx.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="120" height="60">'
                   '<rect x="10" y="10" width="100" height="40" fill="#fff" stroke="#000" stroke-width="2"/>'
                   '<rect x="40" y="20" width="40" height="20" fill="#000"/></svg>', encoding="utf-8")
    master = plate_build.plate_master(svg)
    assert master.shape[1] == plate_build.MASTER_PX
    assert master.shape[1] / master.shape[0] == pytest.approx(102 / 42, rel=0.02)  # the plate and its stroke
    grey = cv2.cvtColor(master, cv2.COLOR_BGR2GRAY)
    assert grey[master.shape[0] // 2, master.shape[1] // 2] < 40 and grey[8, 20] > 230
