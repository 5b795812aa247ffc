"""Regression figures on two small held-out synthetic drives (mapping end to end, depth by stereo matching).

Their faces are not copies of the templates: 70 % the official drawings printed worn, faded, dirty or with
stickers, 30 % our procedural designs (``SimulationConfig`` defaults), on the signs of before the whole catalogue
(``DRAWABLE_SIGNS``: the drives these figures were measured on). Seeds 9001 and 9002 were generated for this
test and taken as they came. Thresholds sit a little below what was measured on them (2026-12-06, the whole
catalogue and its network: 23 signs in view, 23 detected, 20 right, 17 accepted with none wrong, no false positive;
3D RMS 3.8 cm. 2026-12-04 before it: 22 detected, 19 right, 20 accepted with 1 wrong). Since the single-view rule
for off-format and unknown readings (FusionConfig.doubtful_min_views) was made looking at their three extra
features, these drives are regression drives, no longer held out: the figures of record are those of fresh drives
measured once (README, "Measuring accuracy and speed").
"""

from __future__ import annotations

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
    """Per drive: (reference signs, evaluation report, fused signs without plates)."""
    catalogue = load_catalogue(None)
    out = []
    for seed in SEEDS:
        folder = tmp_path_factory.mktemp(f"held_out_{seed}")
        generate_drive(folder, SimulationConfig(pairs=PAIRS, seed=seed, write_depth=False, **DRAWABLE_SIGNS))
        drive = open_drive(folder, require_truth=True)
        result = map_drive(drive, catalogue, PipelineConfig(), workers=1)
        signs = [s for s in result.signs if s.plate_of is None]
        reference = mappable_signs(drive, result.config.depth)
        trajectory = np.array([[r.pose.easting, r.pose.northing] for r in drive.pairs])
        report = evaluate([s.position for s in signs], [s.template_id for s in signs],
                          [r.position for r in reference], [r.template_id for r in reference], trajectory, 0.75)
        out.append((reference, report, signs))
    return out


@pytest.mark.slow
def test_held_out_drives_detect_and_classify_their_signs(figures):
    in_view = sum(r.table1.reference_signs for _, r, _ in figures)
    detected = sum(r.table1.detected_signs for _, r, _ in figures)
    right = sum(r.table1.correctly_classified_signs for _, r, _ in figures)
    false_positives = sum(r.table1.false_positive_detections for _, r, _ in figures)
    assert in_view == 23, "the generator draws other drives now: measure them again and set the thresholds anew"
    assert detected >= 22 and right >= 19 and false_positives <= 1
    assert all(r.table1.duplicates == 0 for _, r, _ in figures)  # one feature per sign


@pytest.mark.slow
def test_held_out_drives_accept_few_wrong_ids(figures):
    accepted = wrong = 0
    for reference, report, signs in figures:
        for sign, match in zip(signs, report.match):
            if sign.status == "accepted":
                accepted += 1
                wrong += match < 0 or sign.template_id != reference[match].template_id
    assert accepted >= 16 and wrong <= 1


@pytest.mark.slow
def test_held_out_drives_place_their_signs_within_a_few_centimetres(figures):
    errors = np.concatenate([r.differences[:, 4] for _, r, _ in figures])
    assert len(errors) >= 21
    assert float(np.sqrt(np.mean(errors ** 2))) <= 0.04
