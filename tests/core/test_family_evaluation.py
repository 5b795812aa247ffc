"""Per-family figures of fused signs (procedural faces apart) and the outcomes of chosen ids, on hand-made cases."""

from __future__ import annotations

from collections import Counter
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import TruthSign
from signmapper_core.evaluation.accuracy import evaluate
from signmapper_core.evaluation.families import (
    GROUPS,
    PROCEDURAL_GROUP,
    catalogue_colour,
    group_figures,
    group_lines,
    sign_group,
)
from signmapper_core.evaluation.id_outcomes import (
    ACCEPTED_OTHER,
    MISSED,
    REVIEW_OTHER,
    RIGHT,
    UNKNOWN,
    UNKNOWN_ID,
    id_outcomes,
    outcome_lines,
)

REPO = Path(__file__).resolve().parents[2]
E0, N0, H0 = 2600000.0, 1200000.0, 400.0


def ref(sign_id, template_id, east, artwork="master"):
    return TruthSign(sign_id, template_id, E0 + east, N0 + 5.0, H0 + 2.0, 0.6, 0.6, 270.0, artwork=artwork)


def fused(template_id, east, status="accepted", dz=0.0):
    position = np.array([E0 + east, N0 + 5.0, H0 + 2.0 + dz])
    return SimpleNamespace(template_id=template_id, status=status, position=position)


@pytest.fixture(scope="module")
def colour_of():
    return catalogue_colour(load_catalogue())


def evaluated(signs, reference):
    trajectory = np.array([[E0 - 10.0, N0], [E0 + 200.0, N0]])
    return evaluate([s.position for s in signs], [s.template_id for s in signs], [r.position for r in reference],
                    [r.template_id for r in reference], trajectory, 0.75)


def test_each_family_and_the_procedural_designs_have_their_own_row(colour_of):
    reference = [
        ref("s1", "2.30-50", 0),                      # red, accepted right, 3 cm high
        ref("s2", "2.49", 10),                        # red, accepted as another id
        ref("s3", "4.08", 20),                        # blue, in review with its id
        ref("s4", "0.1", 30),                         # brown, missed
        ref("s5", "4.31-1", 40),                      # green, accepted right
        ref("s6", "2.12", 50, artwork="procedural"),  # a procedural design: its own row, not red
        ref("s7", "4.29", 60, artwork="procedural"),  # a text panel set from its wording: white, not procedural
        ref("s8", "4.34", 70),                        # orange, two fused signs: one accepted right, one review wrong
    ]
    signs = [fused("2.30-50", 0, dz=0.03), fused("2.50", 10), fused("4.08", 20, status="review"),
             fused("4.31-1", 40, dz=-0.04), fused("2.13", 50), fused("4.29", 60, status="review"),
             fused("4.34", 70), fused("4.34-2", 70.1, status="review"),
             fused("3.03", 90)]  # accepted, matching no sign: counted by its id's colour
    report = evaluated(signs, reference)
    rows = group_figures(signs, reference, report.match, colour_of)
    assert list(rows) == list(GROUPS)
    red, blue, brown, green = rows["red"], rows["blue"], rows["brown"], rows["green"]
    assert (red.in_view, red.detected, red.right, red.accepted, red.accepted_wrong) == (2, 2, 1, 2, 1)
    assert (blue.in_view, blue.detected, blue.right, blue.accepted) == (1, 1, 1, 0)
    assert (brown.in_view, brown.detected, brown.accepted) == (1, 0, 0)
    assert (green.right, green.accepted, green.accepted_wrong) == (1, 1, 0)
    assert green.rms_3d_m == pytest.approx(0.04)
    assert red.rms_3d_m == pytest.approx(np.sqrt(0.03 ** 2 / 2))
    procedural = rows[PROCEDURAL_GROUP]
    assert (procedural.in_view, procedural.detected, procedural.right, procedural.accepted_wrong) == (1, 1, 0, 1)
    assert rows["white"].in_view == 1 and rows["white"].right == 1
    orange = rows["orange"]
    # the accepted one carries the id: accepted, not wrong; the right id is the first of equals, whatever the status
    assert (orange.in_view, orange.matched, orange.accepted, orange.accepted_wrong, orange.right) == (1, 2, 1, 0, 1)
    assert rows["yellow"].accepted_no_sign == 1 and rows["yellow"].in_view == 0
    # the rows add up over drives, and print with the families together last
    twice = {g: rows[g] + rows[g] for g in rows}
    assert twice["red"].in_view == 4 and twice["red"].rms_3d_m == pytest.approx(red.rms_3d_m)
    lines = group_lines(rows, "title")
    assert lines[0] == "title" and len(lines) == 2 + len(GROUPS) + 1
    assert lines[-1].startswith("all families") and " 7 " in lines[-1]  # eight in view, the procedural one apart
    assert any(line.startswith("white and grey") for line in lines)


def test_a_sign_s_row_is_its_family_unless_printed_from_a_procedural_design(colour_of):
    assert sign_group(ref("a", "0.1", 0), colour_of) == "brown"
    assert sign_group(ref("a", "2.12", 0, artwork="procedural"), colour_of) == PROCEDURAL_GROUP
    assert sign_group(ref("a", "4.33", 0, artwork="procedural"), colour_of) == "white"
    assert sign_group(SimpleNamespace(template_id="4.64"), colour_of) == "green"  # a real drive: no artwork
    assert sign_group(ref("a", "5.99", 0), colour_of) == ""


def test_left_out_ids_are_told_unknown_accepted_as_another_or_missed():
    reference = [ref("s1", "4.64", 0), ref("s2", "4.64", 10), ref("s3", "4.64", 20), ref("s4", "0.3", 30),
                 ref("s5", "0.3", 40), ref("s6", "2.30-50", 50)]
    signs = [fused(UNKNOWN_ID, 0, status="review"), fused("4.65", 10), fused("0.3", 40, status="review"),
             fused("0.2", 30, status="review"), fused(UNKNOWN_ID, 20.05, status="review"),
             fused("4.66", 20, status="accepted"), fused("2.30-50", 50)]
    report = evaluated(signs, reference)
    table = id_outcomes(signs, reference, report.match, ["4.64", "0.3", "4.99"])
    # an accepted wrong id outweighs an unknown on the same sign: that is the error to count
    assert table == {"4.64": Counter({UNKNOWN: 1, ACCEPTED_OTHER: 2}), "0.3": Counter({REVIEW_OTHER: 1, RIGHT: 1})}
    missed = id_outcomes([], reference, np.zeros(0, int), ["2.30-50"])
    assert missed == {"2.30-50": Counter({MISSED: 1})}
    lines = outcome_lines(table, "left out")
    assert lines[0] == "left out" and lines[-1].startswith("all") and "1 of 5 (20.0 %)" in lines[-1]
    assert [line.split()[0] for line in lines[2:]] == ["0.3", "4.64", "all"]


def test_evaluate_mapping_reads_ids_from_a_list_or_a_file(tmp_path):
    from scripts import evaluate_mapping as module

    assert module.read_ids("4.64, 0.3,") == ["4.64", "0.3"]
    (tmp_path / "ids.txt").write_text("# left out, seed 7\n4.64\n\n0.3  # tourist\n", encoding="utf-8")
    assert module.read_ids(f"@{tmp_path / 'ids.txt'}") == ["4.64", "0.3"]
    assert module.read_ids("") == []
