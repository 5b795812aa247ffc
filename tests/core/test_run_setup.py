"""One way to set up a run: recorded settings, the front end's choices over them, and the checks before any work;
and the settings a run table says a run was mapped with, whole or from the rows of an older writer."""

import dataclasses
import sqlite3
from contextlib import closing

import pytest

from signmapper_core.catalogue.model import DEFAULT_CATALOGUE_DIR
from signmapper_core.evaluation.reference_rows import ids_from_numbers, numeric_ids_note
from signmapper_core.fusion.signs import FusionConfig
from signmapper_core.output.run_settings import recorded_config
from signmapper_core.output.run_table import RUN_TABLE, SETTINGS_VERSION, encode_run_value, settings_dict
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.config import DepthConfig, PlanarityConfig, with_settings
from signmapper_core.run.setup import RunSetupError, assemble_run, is_default

RECORDED = PipelineConfig(depth=DepthConfig(near_m=5.0, far_m=20.0), planarity=PlanarityConfig(detection_threshold=0.7))


def _output(path, config=RECORDED, catalogue=str(DEFAULT_CATALOGUE_DIR), **rows):
    record = {"software": "Sign Mapper test", "catalogue": catalogue, "settings_version": SETTINGS_VERSION,
              "pipeline": settings_dict(config), "fusion": settings_dict(FusionConfig(gate_m=0.7)), **rows}
    with closing(sqlite3.connect(path)) as db:
        db.execute(f"CREATE TABLE {RUN_TABLE} (fid INTEGER PRIMARY KEY, key TEXT, value TEXT)")
        db.executemany(f"INSERT INTO {RUN_TABLE} (key, value) VALUES (?, ?)",
                       [(k, encode_run_value(v)) for k, v in record.items()])
        db.commit()
    return path


def test_without_a_record_the_choices_go_over_the_defaults():
    run = assemble_run({("depth", "far_m"): 25.0, ("white", "white_signs"): False})
    fixed = {"far_m": 25.0, "range_from_camera": False, "reach_m": None}  # a limit given fixes the range
    assert run.config == with_settings(PipelineConfig(), {"depth": fixed, "white": {"white_signs": False}})
    assert run.fusion == FusionConfig() and run.catalogue.folder == DEFAULT_CATALOGUE_DIR


def test_a_record_gives_the_settings_and_a_dialogs_default_yields_to_it(tmp_path):
    path = _output(tmp_path / "earlier.gpkg")
    dialog = {("depth", "near_m"): PipelineConfig().depth.near_m, ("depth", "far_m"): 30.0}
    yielded = assemble_run(dialog, path, defaults_yield=True)
    assert (yielded.config.depth.near_m, yielded.config.depth.far_m) == (5.0, 30.0)  # the changed one wins
    assert yielded.config.planarity.detection_threshold == 0.7 and yielded.fusion == FusionConfig(gate_m=0.7)
    given = assemble_run(dialog, path)  # a command line's value is given on purpose: it wins even at its default
    assert given.config.depth.near_m == PipelineConfig().depth.near_m


def test_each_refusal_names_the_input_in_the_front_ends_words(tmp_path):
    labels = {"near_m": "Near limit [m]", "far_m": "Far limit [m]", "settings_from": "Earlier output"}
    with pytest.raises(RunSetupError, match=r"^Near limit \[m\] \(14 m\) must be less than Far limit \[m\] \(4 m\)"):
        assemble_run({("depth", "near_m"): 14.0, ("depth", "far_m"): 4.0}, labels=labels)
    with pytest.raises(RunSetupError, match=r"^Sign types to exclude: 9\.99 not in the catalogue$"):
        assemble_run({("classification", "exclude"): ("1.01", "9.99")})
    with pytest.raises(RunSetupError, match=r"^Choose at least one sign colour"):
        assemble_run({("colour", "colours"): ()})
    with pytest.raises(RunSetupError, match=r"^Earlier output: .*missing\.gpkg: no such file"):
        assemble_run({}, tmp_path / "missing.gpkg", labels=labels)
    moved = _output(tmp_path / "moved.gpkg", catalogue=str(tmp_path / "gone"))
    with pytest.raises(RunSetupError, match=r"its catalogue folder .*gone does not exist here; set 'Template "
                                            r"catalogue'"):
        assemble_run({}, moved, labels=labels)
    with pytest.raises(RunSetupError, match=r"^Template catalogue: .*catalogue\.json.*not found"):
        assemble_run({}, catalogue_folder=tmp_path)
    with pytest.raises(RunSetupError, match=r"^Classifier: .*no learned classifier"):
        assemble_run({("classification", "classifier"): "cnn"}, catalogue_folder=_catalogue_without_model(tmp_path))


def _catalogue_without_model(tmp_path):
    folder = tmp_path / "no-model"
    folder.mkdir()
    (folder / "catalogue.json").write_text((DEFAULT_CATALOGUE_DIR / "catalogue.json").read_text())
    for item in DEFAULT_CATALOGUE_DIR.iterdir():
        if item.name not in ("catalogue.json", "classifier"):
            (folder / item.name).symlink_to(item)
    return folder


def test_colours_count_as_default_in_any_order():
    colours = PipelineConfig().colour.colours
    assert is_default(("colour", "colours"), tuple(reversed(colours)))
    assert not is_default(("colour", "colours"), colours[:1])


def test_the_recorded_config_is_the_whole_record_or_the_rows_an_older_writer_left():
    whole = {"settings_version": SETTINGS_VERSION, "pipeline": settings_dict(RECORDED), "near_m": 5.0}
    assert recorded_config(whole) == RECORDED
    rows = {"near_m": 6.0, "far_m": 18, "colours": ["red", "blue"], "exclude": ["1.01"], "classifier": "ncc",
            "detection_threshold": "high"}  # a value of the wrong kind is left at its default
    config = recorded_config(rows)
    assert (config.depth.near_m, config.depth.far_m) == (6.0, 18.0)
    assert config.colour.colours == ("red", "blue") and config.classification.exclude == ("1.01",)
    assert config.classification.classifier == "ncc"
    assert config.planarity == PipelineConfig().planarity
    assert recorded_config({"near_m": 20.0, "far_m": 4.0}) == PipelineConfig()  # refused as a whole: defaults
    assert recorded_config({}) == dataclasses.replace(PipelineConfig())


def test_numbers_in_a_reference_id_field_are_read_back_as_the_one_id_they_stand_for():
    known = {"1.30", "2.30-50", "4.08", "4.08.1", "3.2", "3.20"}
    ids, unresolved, example = ids_from_numbers(["1.3", 4.08, None, "3.2", "7.7"], known)
    assert ids == ["1.30", "4.08", None, "3.2", "7.7"]  # 3.2 stands for 3.2 and 3.20: it stays as written
    assert unresolved == ["3.2", "7.7"] and example == "1.3 as 1.30"
    note = numeric_ids_note("ssv", "Real", unresolved, example)
    assert "field 'ssv' is numeric (Real)" in note and "(e.g. 1.3 as 1.30)" in note and "2 stand for no" in note
