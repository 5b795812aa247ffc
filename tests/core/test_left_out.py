"""The open-set split (training/left_out.py): the ids written down before training stay the ids drawn."""

import json

from signmapper_core.catalogue import load_catalogue
from training.left_out import DEVELOPMENT_SEED, IDS_FILE, REPORT_SEED, catalogue_without, left_out_ids

# docs/measurements.md, "the open-set measurement, fixed before training" (2026-12-06)
WRITTEN_DOWN = """0.1-3.1, 1.13, 1.22, 2.05, 2.14, 2.15, 2.30.1, 2.37, 2.41.1, 2.42, 2.43, 2.44, 2.53-60, 2.56.1,
2.59.1-30, 2.60.1, 2.63-a, 3.01, 3.03, 3.21, 4.08, 4.11, 4.34-2, 4.34.1, 4.47, 4.50.1, 4.51.4, 4.71, 4.77/14, 4.77/20,
4.77/24"""


def test_the_report_seed_draws_the_ids_written_down_before_training():
    ids = left_out_ids(load_catalogue().ids(), REPORT_SEED)
    assert ids == [t.strip() for t in WRITTEN_DOWN.split(",")]


def test_the_development_split_shares_no_id_with_the_measured_one():
    catalogue_ids = load_catalogue().ids()
    measured = set(left_out_ids(catalogue_ids, REPORT_SEED))
    development = left_out_ids(catalogue_ids, DEVELOPMENT_SEED, besides=measured)
    assert len(development) == len(measured) == 31 and not measured & set(development)


def test_the_catalogue_without_the_ids_keeps_every_other_entry_and_lists_the_ids(tmp_path):
    source = load_catalogue()
    ids = left_out_ids(source.ids(), REPORT_SEED)
    assert catalogue_without(source.folder, tmp_path / "cat", ids) == ids
    kept = load_catalogue(tmp_path / "cat")
    assert len(kept) == len(source) - 31 and not set(ids) & set(kept.ids())
    assert (tmp_path / "cat" / IDS_FILE).read_text(encoding="utf-8").split("\n")[:-1] == ids
    assert json.loads((tmp_path / "cat" / "catalogue.json").read_text())["name"].endswith("without 31 signs "
                                                                                          "(open-set measurement)")
