"""Pictogram plate templates: the shipped renderings, building them from drawings, and broken plate folders."""

from __future__ import annotations

import json

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import plate_build, svg_render
from signmapper_core.catalogue.model import DEFAULT_CATALOGUE_DIR
from signmapper_core.catalogue.plates_ch import PICTOGRAM_PLATES
from signmapper_core.plate_catalogue import PlateCatalogueError, load_plate_templates, pictogram_formats

needs_renderer = pytest.mark.skipif(not svg_render.renderer_available(),
                                    reason="rsvg-convert (Debian package librsvg2-bin) is not installed")


def test_the_shipped_plate_templates_are_every_drawing_of_the_table():
    templates = load_plate_templates(DEFAULT_CATALOGUE_DIR)
    expected = {(p.id, variant) for p in PICTOGRAM_PLATES for variant in p.drawings}
    assert {(t.id, t.variant) for t in templates} == expected and len(templates) == 10
    for t in templates:
        assert t.grey.shape[1] == plate_build.MASTER_WIDTH_PX
        assert t.aspect == pytest.approx(t.grey.shape[1] / t.grey.shape[0], abs=1e-3)
        assert np.percentile(t.grey, 75) > 200 and (t.grey < 80).mean() > 0.03  # white plate, black print
    words = {(t.id, t.variant): t.text for t in templates}
    assert words[("5.31-2", "de")] == "ausgenommen" and words[("5.31-2", "fr")] == "exceptés"
    assert words[("5.20", "de")] == ""
    formats = pictogram_formats(templates)
    assert formats["5.31@0.60"] == (0.6, pytest.approx(0.6 / templates[3].aspect, abs=1e-3))


def test_a_catalogue_without_plates_has_no_pictogram_plates(tmp_path):
    assert load_plate_templates(tmp_path) == ()


@pytest.mark.parametrize("content, message", [
    ("{not json", "not readable as JSON"),
    (json.dumps({"format": "other/1", "plates": []}), "is not 'signmapper-plates/1'"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.31", "variant": "de", "names": {},
                                                             "aspect": 1.4, "png": "png/gone.png"}]}),
     "plate 1: image .*gone.png is missing"),
    (json.dumps({"format": "signmapper-plates/1", "plates": [{"id": "5.31"}]}), "plate 1 lacks the field"),
])
def test_a_broken_plate_folder_names_the_file_and_what_is_wrong(tmp_path, content, message):
    (tmp_path / "plates").mkdir()
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
    assert master.shape[1] == plate_build.MASTER_WIDTH_PX
    assert master.shape[1] / master.shape[0] == pytest.approx(102 / 42, rel=0.02)  # the plate and its stroke
    grey = cv2.cvtColor(master, cv2.COLOR_BGR2GRAY)
    assert grey[master.shape[0] // 2, master.shape[1] // 2] < 40 and grey[8, 20] > 230
