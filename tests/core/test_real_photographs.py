"""Regression figures on real photographs (the committed subset of GTSDB signs; never trained on).

The subset is committed under tests/data/real-signs (GTSDB scenes, free for any use; its
README names source, commit and licence; scripts/realset/make_subset.py builds it);
$SIGNMAPPER_REAL_SUBSET points the tests at another one. Thresholds sit a little below what
was measured on it; the full figures are in README.md ("Recognition on real photographs").
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.pipeline.candidates import colour_step
from signmapper_core.pipeline.classifiers import make_classifier
from signmapper_core.validation import load_manifest, load_scene_list, read_bgr

REPO = Path(__file__).resolve().parents[2]


def subset_folder():
    env = os.environ.get("SIGNMAPPER_REAL_SUBSET")
    return Path(env) if env else REPO / "tests" / "data" / "real-signs"


SUBSET = subset_folder()

# measured 2026-12-06 on the subset's 600 crops with the committed model (the whole catalogue's, 313 entries, among
# every entry of the true colour and shape): 92.4 % of the 445 same-pictogram signs >= 30 px right, 89.0 % of the
# 136 smaller ones; 73.5 % accepted, 1.4 % of those wrong (2026-12-01, the 112-id model: 94.6 %, 90.4 %, 80.3 %,
# 1.2 %; the model before it: 85.6 %, 81.6 %, 50.3 %, 2.6 %)
MIN_CORRECT_30PX = 0.91
MIN_CORRECT_SMALL = 0.87
MIN_ACCEPTED_SHARE = 0.71
MAX_WRONG_ACCEPTED = 0.025
# the colour step on the subset's 60 whole scenes (no depth): the face of 59 of the 65 same-pictogram signs
# >= 30 px found with the true id among its candidates (90.8 %, measured 2026-12-02 after bitten fields were read
# by their hull; 58 before)
MIN_FACE_FOUND_30PX = 0.88


@pytest.fixture(scope="module")
def classified():
    """(sign, predicted id, indicator, accept threshold) of every subset crop, perfect box, candidates = the
    entries of the true colour and shape, with the default (learned) classifier."""
    catalogue = load_catalogue()
    network = make_classifier("cnn", catalogue)
    out = []
    for sign in load_manifest(SUBSET / "crops.csv", known_ids={e.id for e in catalogue}):
        entry = catalogue[sign.ssv_id]
        # the ids the network knows (the white signs added after it was trained are the NCC's, white_signs.py)
        ids = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape]) if network.knows([e.id])]
        result = network.classify(sign.load_image(), sign.bbox, ids)
        out.append((sign, result.template_id, result.score))
    return out, network.accept_threshold


def _select(records, group="same", min_px=0, max_px=10**6):
    return [r for r in records if r[0].group == group and min_px <= r[0].size_px < max_px]


def test_signs_of_30_px_and_more_get_the_right_id(classified):
    records, _ = classified
    sel = _select(records, min_px=30)
    assert len(sel) >= 200
    assert np.mean([r[1] == r[0].ssv_id for r in sel]) >= MIN_CORRECT_30PX


def test_smaller_signs_get_the_right_id_mostly(classified):
    records, _ = classified
    sel = _select(records, max_px=30)
    assert np.mean([r[1] == r[0].ssv_id for r in sel]) >= MIN_CORRECT_SMALL


def test_accepted_signs_are_right(classified):
    records, threshold = classified
    accepted = [r for r in records if r[2] >= threshold]
    assert len(accepted) >= MIN_ACCEPTED_SHARE * len(records)
    assert np.mean([r[1] != r[0].ssv_id for r in accepted]) <= MAX_WRONG_ACCEPTED


def test_colour_step_finds_the_faces_of_whole_photographs():
    """Colour and shape on whole GTSDB scenes, no depth: a face is found when a reading's box overlaps the
    sign's by IoU >= 0.5 and the true id is among its candidates (``python -m scripts.evaluate_real_photos detect``)."""
    catalogue = load_catalogue()
    config = PipelineConfig()
    signs = [s for s in load_manifest(SUBSET / "scenes.csv", known_ids={e.id for e in catalogue})
             if s.group == "same" and s.size_px >= 30]
    wanted = {s.image for s in signs}
    found = 0
    for scene in load_scene_list(SUBSET / "scenes_images.csv"):
        if scene.image not in wanted:
            continue
        _, candidates = colour_step(read_bgr(scene.image), catalogue, config)
        found += sum(any(box_iou(r.bbox, s.bbox) >= 0.5 and s.ssv_id in r.template_ids
                         for c in candidates for r in c.readings) for s in signs if s.image == scene.image)
    assert len(signs) >= 50
    assert found / len(signs) >= MIN_FACE_FOUND_30PX
