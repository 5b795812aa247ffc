"""Regression figures on two small held-out synthetic drives (mapping end to end, depth by stereo matching).

Their faces are not copies of the templates: 70 % the official drawings printed worn, faded, dirty or with
stickers, 30 % our procedural designs (``SimulationConfig`` defaults), on the signs of before the whole catalogue
(``DRAWABLE_SIGNS``: the drives these figures were measured on). Seeds 9001 and 9002 were generated for this
test and taken as they came. Thresholds sit a little below what was measured on them (2026-12-06, the whole
catalogue and its network: 23 signs in view within 4-14 m, 23 detected, 20 right, 17 accepted with none wrong, no
false positive; 3D RMS 3.8 cm; four more are in view only in the reach at the frame's edges, tested apart.
2026-12-04 before it: 22 detected, 19 right, 20 accepted with 1 wrong). Since the single-view rule
for off-format and unknown readings (FusionConfig.doubtful_min_views) was made looking at their three extra
features, these drives are regression drives, no longer held out: the figures of record are those of fresh drives
measured once (README, "Measuring accuracy and speed").
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.evaluation.accuracy import evaluate
from signmapper_core.evaluation.visibility import mappable_signs
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive

SEEDS = (9001, 9002)
PAIRS = 50


@pytest.fixture(scope="module")
def figures(tmp_path_factory):
    """Per drive: (reference signs, evaluation report, fused signs without plates, whether each reference sign is
    in view within near..far rather than only in the reach at the frame's edges)."""
    catalogue = load_catalogue(None)
    out = []
    for seed in SEEDS:
        folder = tmp_path_factory.mktemp(f"held_out_{seed}")
        generate_drive(folder, SimulationConfig(pairs=PAIRS, seed=seed, write_depth=False, **DRAWABLE_SIGNS))
        drive = open_drive(folder, require_truth=True)
        result = map_drive(drive, catalogue, PipelineConfig(), workers=1)
        signs = [s for s in result.signs if s.plate_of is None]
        depth = result.config.depth
        reference = mappable_signs(drive, depth)
        within = {id(s) for s in mappable_signs(drive, replace(depth, reach_m=None))}
        trajectory = np.array([[r.pose.easting, r.pose.northing] for r in drive.pairs])
        report = evaluate([s.position for s in signs], [s.template_id for s in signs],
                          [r.position for r in reference], [r.template_id for r in reference], trajectory, 0.75)
        out.append((reference, report, signs, [id(r) in within for r in reference]))
    return out


def outcomes(figures, within_range: bool) -> dict:
    """Counts over the reference signs in view within near..far (or only in the reach): in view, detected,
    right id, duplicates, accepted, accepted with a wrong id, 3D errors of the first feature of each."""
    counts = dict(in_view=0, detected=0, right=0, duplicates=0, accepted=0, wrong=0, errors=[])
    for reference, report, signs, within in figures:
        for k, ref in enumerate(reference):
            if within[k] != within_range:
                continue
            found = [s for s, m in zip(signs, report.match) if m == k]
            counts["in_view"] += 1
            counts["detected"] += bool(found)
            counts["duplicates"] += len(found) > 1
            for sign in found[:1]:
                counts["right"] += sign.template_id == ref.template_id
                counts["accepted"] += sign.status == "accepted"
                counts["wrong"] += sign.status == "accepted" and sign.template_id != ref.template_id
                counts["errors"].append(float(np.linalg.norm(sign.position - ref.position)))
    return counts


@pytest.mark.slow
def test_held_out_drives_detect_and_classify_their_signs(figures):
    near = outcomes(figures, True)
    assert near["in_view"] == 23, "the generator draws other drives now: measure them again and set the thresholds anew"
    assert near["detected"] >= 22 and near["right"] >= 19 and near["duplicates"] == 0
    false_positives = sum(r.table1.false_positive_detections for _, r, _, _ in figures)
    assert false_positives <= 1


@pytest.mark.slow
def test_held_out_drives_accept_few_wrong_ids(figures):
    accepted = wrong = 0
    for reference, report, signs, _ in figures:
        for sign, match in zip(signs, report.match):
            if sign.status == "accepted":
                accepted += 1
                wrong += match < 0 or sign.template_id != reference[match].template_id
    assert accepted >= 16 and wrong <= 1


@pytest.mark.slow
def test_held_out_drives_place_their_signs_within_a_few_centimetres(figures):
    errors = np.array(outcomes(figures, True)["errors"])
    assert len(errors) >= 21
    assert float(np.sqrt(np.mean(errors ** 2))) <= 0.04


@pytest.mark.slow
def test_signs_that_leave_the_view_before_the_far_limit_are_mapped_from_the_reach(figures):
    """Issue 45 item 1: four signs of these drives are in view only beyond 14 m, near the frame's edges (measured
    2026-12-06: all four detected and read right, two accepted, 3D RMS 10 cm, one of them as two features with
    the fixed fusion gate)."""
    reach = outcomes(figures, False)
    assert reach["in_view"] == 4
    assert reach["detected"] >= 3 and reach["right"] >= 3 and reach["wrong"] == 0
    assert float(np.sqrt(np.mean(np.square(reach["errors"])))) <= 0.2
