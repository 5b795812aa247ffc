"""A run's whole configuration as JSON and back; reading a run table and refusing what cannot give settings."""

import json
import sqlite3
from contextlib import closing

import pytest

from signmapper_core.fusion import FusionConfig
from signmapper_core.output_schema import RUN_TABLE, encode_run_value
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.run_settings import (
    SETTINGS_VERSION,
    RunRecordError,
    load_run_settings,
    read_run_record,
    run_settings,
    settings_dict,
    settings_of,
)
from signmapper_core.sign_colours import SIGN_COLOURS

# every kind of field changed: numbers, None, tuples, dicts of tuples, booleans
CHANGED = PipelineConfig(
    near_m=5.5, far_m=18.0, colours=("blue",), exclude=("4.17",), classification_threshold=0.71,
    classifier="ncc", hsv_ranges={"red": ((0, 8, 95, 255, 50, 255),), "blue": ((101, 129, 110, 255, 40, 255),)},
    min_part_px={"yellow": 80, "blue": 70}, weak_shapes={"yellow": ("diamond", "square")}, scales=(0.9, 1.0),
    white_balance=True, max_depth_deviation=None, tie_margin=0.05, hough_tint_min_share=0.3,
)


def test_the_whole_pipeline_config_survives_json():
    data = json.loads(json.dumps(settings_dict(CHANGED)))
    assert settings_of(PipelineConfig, data, "test") == CHANGED
    assert set(data) == {f for f in PipelineConfig.__dataclass_fields__}  # every field, not a chosen few


def test_fusion_config_survives_json():
    fusion = FusionConfig(gate_m=0.8, max_gap_pairs=6, accept_classification=0.75)
    assert settings_of(FusionConfig, json.loads(json.dumps(settings_dict(fusion))), "test") == fusion


def test_unknown_keys_are_warned_about_and_ignored_missing_ones_keep_their_defaults():
    warnings = []
    data = {"near_m": 6.0, "later_setting": 1, "other": [2]}
    config = settings_of(PipelineConfig, data, "file.gpkg", warnings.append)
    assert config == PipelineConfig(near_m=6.0)
    assert warnings == ["file.gpkg: ignored settings this version does not know: later_setting, other"]


def test_values_the_config_refuses_name_the_record():
    with pytest.raises(RunRecordError, match=r"^file.gpkg, pipeline: need 0 < near_m < far_m, got 9.0, 3.0$"):
        settings_of(PipelineConfig, {"near_m": 9.0, "far_m": 3.0}, "file.gpkg, pipeline")
    with pytest.raises(RunRecordError, match="expected a JSON object of settings, found list"):
        settings_of(PipelineConfig, [1, 2], "file.gpkg")


def test_the_colour_choices_are_the_colour_table():
    assert PipelineConfig().colours == SIGN_COLOURS == tuple(PipelineConfig().hsv_ranges)


def _run_table(path, record: dict):
    with closing(sqlite3.connect(path)) as db:
        db.execute(f"CREATE TABLE {RUN_TABLE} (fid INTEGER PRIMARY KEY, key TEXT, value TEXT)")
        db.executemany(f"INSERT INTO {RUN_TABLE} (key, value) VALUES (?, ?)",
                       [(k, encode_run_value(v)) for k, v in record.items()])
        db.commit()
    return path


def _record(config=CHANGED, **changes):
    record = {"software": "Sign Mapper 0.1.0", "catalogue": "/catalogues/ch", "near_m": config.near_m,
              "settings_version": SETTINGS_VERSION, "pipeline": settings_dict(config),
              "fusion": settings_dict(FusionConfig(gate_m=0.7))}
    record.update(changes)
    return {k: v for k, v in record.items() if v is not None}


def test_settings_read_back_from_a_run_table(tmp_path):
    path = _run_table(tmp_path / "out.gpkg", _record())
    assert read_run_record(path)["pipeline"] == settings_dict(CHANGED)
    settings = load_run_settings(path)
    assert (settings.config, settings.fusion, settings.catalogue) == (CHANGED, FusionConfig(gate_m=0.7),
                                                                      "/catalogues/ch")


def test_a_file_without_run_table_or_no_geopackage_is_refused(tmp_path):
    with pytest.raises(RunRecordError, match="missing.gpkg: no such file"):
        read_run_record(tmp_path / "missing.gpkg")
    text = tmp_path / "text.gpkg"
    text.write_text("hello")
    with pytest.raises(RunRecordError, match="text.gpkg: not a GeoPackage"):
        read_run_record(text)
    other = tmp_path / "other.gpkg"
    with closing(sqlite3.connect(other)) as db:
        db.execute("CREATE TABLE roads (fid INTEGER PRIMARY KEY)")
    with pytest.raises(RunRecordError, match="other.gpkg: no table 'signmapper_run': not an output of Sign Mapper"):
        read_run_record(other)


def test_a_record_of_another_settings_version_or_an_older_program_is_refused():
    with pytest.raises(RunRecordError, match=r"^out.gpkg: settings version 2 \(written by Sign Mapper 0.1.0\); this "
                                             r"version of Sign Mapper reads version 1 only$"):
        run_settings(_record(settings_version=2), "out.gpkg")
    older = {k: v for k, v in _record().items() if k not in ("settings_version", "pipeline", "fusion")}
    with pytest.raises(RunRecordError, match="out.gpkg: written by Sign Mapper 0.1.0, which recorded only some"):
        run_settings(older, "out.gpkg")


def test_a_record_without_fusion_settings_gets_the_default_fusion():
    assert run_settings(_record(fusion=None), "out.gpkg").fusion == FusionConfig()
