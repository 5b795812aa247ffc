"""A run's whole configuration as JSON and back; reading a run table and refusing what cannot give settings."""

import dataclasses
import json
import sqlite3
from contextlib import closing
from pathlib import Path

import pytest

from signmapper_core.fusion.signs import FusionConfig
from signmapper_core.output.run_settings import load_run_settings, pipeline_config_of, run_settings, settings_of
from signmapper_core.output.run_table import (
    RUN_TABLE,
    SETTINGS_VERSION,
    RunRecordError,
    encode_run_value,
    read_run_record,
    settings_dict,
)
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.config import (
    SECTION_OF,
    SECTIONS,
    ClassificationConfig,
    ColourConfig,
    DepthConfig,
    HoughConfig,
    PlanarityConfig,
    PlateConfig,
    SceneConfig,
    WhiteConfig,
)
from signmapper_core.sign_colours import SIGN_COLOURS

# the run table (key -> value as stored) of settings version 1 (pipeline settings flat), as mapsigns wrote it
# before the sections: rows settings_version, pipeline, fusion, near_m, far_m of
# tests/qgis/golden/mapsigns-seed11.json at main 8b16f86 (mapsigns with its defaults)
RECORD_V1 = Path(__file__).parent.parent / "data" / "run_record_v1.json"
# rows software, settings_version, pipeline, fusion, near_m, far_m of settings version 2 as mapsigns wrote them at
# main a6850fd (tests/qgis/golden/mapsigns-seed11.json then), before the plate, white-sign, depth, scene and
# plate-text module constants became settings
RECORD_V2_A6850FD = Path(__file__).parent.parent / "data" / "run_record_v2_a6850fd.json"

# defaults changed since those records were written: the records' own values stand for them
# no blue circles yet; zone panels' surround at 0.5
# the records hold the colours segmented then (red, blue and yellow; green, brown and orange came with the whole
# catalogue), the white step's and the plates' settings of their day where they have those sections
THREE_COLOURS = ("red", "blue", "yellow")
# records of before the reach kept their range: exactly near..far (no range_from_camera in them)
DEFAULTS_THEN = PipelineConfig(depth=DepthConfig(range_from_camera=False),
                               scene=SceneConfig(weak_shapes={"yellow": ("diamond",)}),
                               classification=ClassificationConfig(min_surround_score=0.5),
                               colour=ColourConfig(colours=THREE_COLOURS, hsv_ranges={
                                   c: ColourConfig().hsv_ranges[c] for c in THREE_COLOURS}))
V2_DEFAULTS_THEN = dataclasses.replace(DEFAULTS_THEN, white=WhiteConfig(white_signs=False, white_scan_side_px=24.0),
                           plates=PlateConfig(plate_pictogram_min_score=0.6))

# every kind of field changed: numbers, None, tuples, dicts of tuples, booleans
CHANGED = PipelineConfig(
    depth=DepthConfig(near_m=5.5, far_m=18.0, sgbm_warm_up_px=32),
    colour=ColourConfig(colours=("blue",), hsv_ranges={"red": ((0, 8, 95, 255, 50, 255),),
                                                       "blue": ((101, 129, 110, 255, 40, 255),)},
                        min_part_px={"yellow": 80, "blue": 70}),
    classification=ClassificationConfig(exclude=("4.17",), classification_threshold=0.71, classifier="ncc",
                                        scales=(0.9, 1.0), tie_margin=0.05),
    scene=SceneConfig(weak_shapes={"yellow": ("diamond", "square")}, white_balance=True, scene_sample_step=2),
    planarity=PlanarityConfig(max_depth_deviation=None),
    hough=HoughConfig(hough_tint_min_share=0.3),
    plates=PlateConfig(plate_compare_insets=(0.0, 0.1), plate_min_size_px=(8, 5), plate_notched_min_fill=0.5,
                       plate_compare_height_px=48, plate_pictogram_min_seen=0.5),
    white=WhiteConfig(white_radial_cos=0.75, white_edge_band_px=1.0, white_pole_blur_rows=5),
)


def test_the_whole_pipeline_config_survives_json_grouped_by_section():
    data = json.loads(json.dumps(settings_dict(CHANGED)))
    assert pipeline_config_of(data, "test") == CHANGED
    assert set(data) == set(SECTIONS) == {"colour", "scene", "bright_fields", "rims", "shape", "size", "depth",
                                          "planarity", "classification", "hough", "white", "plates"}
    assert data["depth"]["near_m"] == 5.5 and data["classification"]["exclude"] == ["4.17"]
    assert data["plates"]["plate_compare_insets"] == [0.0, 0.1] and data["white"]["white_radial_cos"] == 0.75
    assert {name for section in data.values() for name in section} == set(SECTION_OF)  # every setting


def test_setting_names_are_unique_across_the_sections():
    names = [f.name for cls in SECTIONS.values() for f in dataclasses.fields(cls)]
    assert len(names) == len(set(names)) == len(SECTION_OF) > 100


def test_fusion_config_survives_json():
    fusion = FusionConfig(gate_m=0.8, max_gap_pairs=6, accept_classification=0.75, plate_readings=2,
                          plate_well_formed_weight=1.5)
    assert settings_of(FusionConfig, json.loads(json.dumps(settings_dict(fusion))), "test") == fusion


def test_unknown_sections_and_keys_are_warned_about_and_ignored_missing_ones_keep_their_defaults():
    warnings = []
    data = {"depth": {"near_m": 6.0, "later_setting": 1}, "stitching": {"other": [2]}}
    config = pipeline_config_of(data, "file.gpkg", warnings.append)
    assert config == PipelineConfig(depth=DepthConfig(near_m=6.0, range_from_camera=False))  # its range as recorded
    assert warnings == ["file.gpkg: ignored sections this version does not know: stitching",
                        "file.gpkg, section depth: ignored settings this version does not know: later_setting"]


def test_values_the_config_refuses_name_the_record():
    with pytest.raises(RunRecordError, match=r"^file.gpkg, section depth: need 0 < near_m < far_m, got 9.0, 3.0$"):
        pipeline_config_of({"depth": {"near_m": 9.0, "far_m": 3.0}}, "file.gpkg")
    with pytest.raises(RunRecordError, match="expected a JSON object of settings, found list"):
        pipeline_config_of([1, 2], "file.gpkg")
    with pytest.raises(RunRecordError, match="file.gpkg, section colour: expected a JSON object of settings, found "
                                             "list"):
        pipeline_config_of({"colour": ["red"]}, "file.gpkg")


def _flat(config: PipelineConfig) -> dict:
    """The pipeline settings as the version 1 writer recorded them: one object, every setting by its name."""
    return {name: value for section in settings_dict(config).values() for name, value in section.items()}


def _run_table_of(record: Path, path: Path) -> Path:
    """A GeoPackage-like file holding only a run table with the rows of a recorded run (key -> value JSON)."""
    rows = json.loads(record.read_text())
    with closing(sqlite3.connect(path)) as db:
        db.execute(f"CREATE TABLE {RUN_TABLE} (fid INTEGER PRIMARY KEY, key TEXT, value TEXT)")
        db.executemany(f"INSERT INTO {RUN_TABLE} (key, value) VALUES (?, ?)", rows.items())
        db.commit()
    return path


def test_a_version_1_run_table_of_the_earlier_writer_reads_into_its_sections(tmp_path):
    path = _run_table_of(RECORD_V1, tmp_path / "old.gpkg")
    record = read_run_record(path)
    assert record["settings_version"] == 1 and "near_m" in record["pipeline"]  # flat, as written then
    assert set(record["pipeline"]) < set(SECTION_OF)  # settings named since then keep their defaults
    warnings = []
    settings = load_run_settings(path, warnings.append)
    assert warnings == []  # every setting it holds has a section
    assert settings.config == DEFAULTS_THEN  # mapped with the defaults of its day
    assert settings.fusion == FusionConfig(accept_classification=0.8512)


def test_a_version_2_record_written_before_settings_were_added_reads_them_as_their_defaults(tmp_path):
    path = _run_table_of(RECORD_V2_A6850FD, tmp_path / "before.gpkg")
    record = read_run_record(path)
    assert record["settings_version"] == 2
    assert "plate_compare_insets" not in record["pipeline"]["plates"]  # written before these were settings
    assert "white_radial_cos" not in record["pipeline"]["white"] and "plate_readings" not in record["fusion"]
    warnings = []
    settings = load_run_settings(path, warnings.append)
    assert warnings == []
    assert settings.config == V2_DEFAULTS_THEN  # the constants had the values their settings defaulted to then
    assert settings.config.plates.plate_compare_insets == (0.0, 0.06, 0.12)
    assert settings.fusion == FusionConfig(accept_classification=0.8512)


def test_a_version_1_record_with_changed_settings_puts_each_into_its_section():
    warnings = []
    flat = dict(_flat(CHANGED), retired_setting=3)
    record = {"software": "Sign Mapper 0.1.0", "settings_version": 1, "pipeline": flat}
    assert run_settings(record, "old.gpkg", warnings.append).config == CHANGED
    assert warnings == ["old.gpkg, pipeline settings: ignored settings this version does not know: retired_setting"]
    with pytest.raises(RunRecordError, match=r"^old.gpkg, pipeline settings, section depth: need 0 < near_m"):
        run_settings(dict(record, pipeline={"near_m": 9.0, "far_m": 3.0}), "old.gpkg")


def test_the_colour_choices_are_the_colour_table():
    assert PipelineConfig().colour.colours == SIGN_COLOURS == tuple(PipelineConfig().colour.hsv_ranges)


def _run_table(path, record: dict):
    with closing(sqlite3.connect(path)) as db:
        db.execute(f"CREATE TABLE {RUN_TABLE} (fid INTEGER PRIMARY KEY, key TEXT, value TEXT)")
        db.executemany(f"INSERT INTO {RUN_TABLE} (key, value) VALUES (?, ?)",
                       [(k, encode_run_value(v)) for k, v in record.items()])
        db.commit()
    return path


def _record(config=CHANGED, **changes):
    record = {"software": "Sign Mapper 0.1.0", "catalogue": "/catalogues/ch", "near_m": config.depth.near_m,
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
    with pytest.raises(RunRecordError, match=r"^out.gpkg: settings version 3 \(written by Sign Mapper 0.1.0\); this "
                                             r"version of Sign Mapper reads versions 1 and 2 only$"):
        run_settings(_record(settings_version=3), "out.gpkg")
    older = {k: v for k, v in _record().items() if k not in ("settings_version", "pipeline", "fusion")}
    with pytest.raises(RunRecordError, match="out.gpkg: written by Sign Mapper 0.1.0, which recorded only some"):
        run_settings(older, "out.gpkg")


def test_a_record_without_fusion_settings_gets_the_default_fusion():
    assert run_settings(_record(fusion=None), "out.gpkg").fusion == FusionConfig()


# issue 46, case 8: a recorded setting of the wrong type is refused before the first pair, naming the setting

@pytest.mark.parametrize("section, name, value, message", [
    ("colour", "hsv_ranges", {"red": "x"},
     "section colour: setting hsv_ranges['red'] must be a list of lists of 6 whole numbers, found \"x\""),
    ("colour", "hsv_ranges", {"red": [[1, 2, 3]]},
     "section colour: setting hsv_ranges['red'][0] must be a list of 6 whole numbers, found [1, 2, 3]"),
    ("depth", "near_m", "5", "section depth: setting near_m must be a number, found \"5\""),
    ("classification", "exclude", "2.01", "section classification: setting exclude must be a list of texts, "
                                          "found \"2.01\""),
])
def test_a_setting_of_the_wrong_type_is_refused_naming_it(section, name, value, message):
    pipeline = settings_dict(PipelineConfig())
    pipeline[section][name] = value
    with pytest.raises(RunRecordError) as info:
        run_settings(_record(pipeline=pipeline), "out.gpkg")
    assert str(info.value) == f"out.gpkg, pipeline settings, {message}"


def test_a_wrong_type_in_the_fusion_settings_is_refused_too():
    with pytest.raises(RunRecordError, match=r"^out.gpkg, fusion settings: setting gate_m must be a number, "
                                             r"found \[1\]$"):
        run_settings(_record(fusion={"gate_m": [1]}), "out.gpkg")


# issue 46, case 13: run-table rows that contradict the pipeline settings are said; the pipeline settings win

def test_rows_that_contradict_the_pipeline_settings_are_said_and_the_pipeline_settings_win():
    warnings = []
    settings = run_settings(_record(near_m=7.0, far_m=CHANGED.depth.far_m, exclude=["1.01"]), "out.gpkg",
                            warnings.append)
    assert settings.config == CHANGED
    assert warnings == [
        "out.gpkg: its run table says near_m 7.0, its pipeline settings depth.near_m 5.5; the pipeline settings are "
        "used (they are what that run was mapped with)",
        "out.gpkg: its run table says exclude [\"1.01\"], its pipeline settings classification.exclude [\"4.17\"]; "
        "the pipeline settings are used (they are what that run was mapped with)"]
    agreeing = []
    run_settings(_record(), "out.gpkg", agreeing.append)
    assert agreeing == []
