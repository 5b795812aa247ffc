"""Regression figures on real photographs (the committed subset of GTSDB signs; never trained on).

The subset is found at $SIGNMAPPER_REAL_SUBSET or ../shared/real-signs next to the
repository (scripts/realset/make_subset.py builds it; its README names sources and
licences). Thresholds sit a little below what was measured on it; the full figures
are in README.md ("Recognition on real photographs").
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.pipeline.classifiers import make_classifier
from signmapper_core.validation import load_manifest

REPO = Path(__file__).resolve().parents[2]


def subset_folder():
    env = os.environ.get("SIGNMAPPER_REAL_SUBSET")
    for folder in [Path(env)] if env else [REPO.parent / "shared" / "real-signs"]:
        if (folder / "crops.csv").is_file():
            return folder
    return None


SUBSET = subset_folder()
pytestmark = pytest.mark.skipif(SUBSET is None, reason="no real-photograph subset: set SIGNMAPPER_REAL_SUBSET or "
                                                      "place it at ../shared/real-signs (scripts/realset/make_subset.py)")


@pytest.fixture(scope="module")
def classified():
    """(sign, predicted id, indicator, accept threshold) of every subset crop, perfect box, candidates = the
    entries of the true colour and shape, with the default (learned) classifier."""
    catalogue = load_catalogue()
    network = make_classifier("cnn", catalogue)
    out = []
    for sign in load_manifest(SUBSET / "crops.csv", known_ids={e.id for e in catalogue}):
        entry = catalogue[sign.ssv_id]
        ids = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape])]
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
