"""Direction signs that differ only by their lines of text: grouped from the catalogue, counted in the image."""

from __future__ import annotations

import numpy as np
import pytest

from signmapper_core.catalogue.text_lines import line_groups, with_lines
from signmapper_core.pipeline.config import ClassificationConfig
from signmapper_core.pipeline.text_lines import text_line_count, typed_by_lines

CONFIG = ClassificationConfig()


def test_entries_differing_by_their_lines_form_a_group_of_one_colour_and_outline(catalogue):
    groups = line_groups(catalogue)
    assert groups["0.1"][1] == 1 and groups["0.1-2"][1] == 2 and groups["0.1-3"][1] == 3
    assert groups["0.1"][0] == groups["0.1-3"][0] != groups["0.1-3.1"][0]  # pointer and rectangle apart
    assert groups["0.1-3.1"][0] != groups["0.1-3.2"][0]  # not directional and straight ahead apart
    assert "4.34.1" not in groups and "2.01" not in groups and "4.33" not in groups
    assert with_lines(groups, "0.1-3.1", 1) == "0.1-1.1" and with_lines(groups, "4.34", 3) == "4.34-3"
    assert with_lines(groups, "4.34", 4) is None and with_lines(groups, "2.01", 1) is None


def _drawing(catalogue, template_id, px):
    bgr, alpha = catalogue.render(template_id, px)
    a = alpha[..., None] / 255.0
    return (bgr * a + 128 * (1 - a)).astype(np.uint8)


@pytest.mark.parametrize("px", [160, 90])
def test_the_lines_of_every_grouped_drawing_are_counted(catalogue, px):
    groups = line_groups(catalogue)
    counted = {}
    for template_id in groups:
        face = _drawing(catalogue, template_id, px)
        counted[template_id] = text_line_count(face, (0, 0, face.shape[1], face.shape[0]), CONFIG)
    assert counted == {t: n for t, (_, n) in groups.items()}


def test_a_face_too_low_to_count_keeps_the_networks_reading(catalogue):
    face = _drawing(catalogue, "0.1-3.1", 40)  # 40 x 13 px
    assert text_line_count(face, (0, 0, 40, 13), CONFIG) is None
    assert typed_by_lines("0.1-2.1", face, (0, 0, 40, 13), catalogue, CONFIG) == "0.1-2.1"


def test_a_reading_in_a_group_takes_the_member_with_the_counted_lines(catalogue):
    face = _drawing(catalogue, "4.34-3", 160)
    box = (0, 0, face.shape[1], face.shape[0])
    assert typed_by_lines("4.34", face, box, catalogue, CONFIG) == "4.34-3"
    assert typed_by_lines("4.34-2", face, box, catalogue, CONFIG) == "4.34-3"
    assert typed_by_lines("2.01", face, box, catalogue, CONFIG) == "2.01"  # in no group: as read
    blank = np.full_like(face, (30, 60, 120))  # no text at all: nothing counted, the reading stays
    assert typed_by_lines("4.34", blank, box, catalogue, CONFIG) == "4.34"


def test_accents_above_a_line_are_no_line_of_their_own():
    """'Zürich' over 'Basel' on a board 21 px high: the umlauts are a band two rows high, one row above their
    line; counted as a line they typed a two-line motorway pointer as its three-line sibling."""
    face = np.full((21, 80, 3), (60, 120, 0), np.uint8)  # a green field
    face[4:6, 21:23] = face[4:6, 29:31] = 255  # the dots
    face[7:12, 16:64:3] = 255  # the first line's strokes
    face[14:19, 16:58:3] = 255  # the second's
    assert text_line_count(face, (0, 0, 80, 21), CONFIG) == 2

