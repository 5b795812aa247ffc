"""``mapsigns`` records its whole configuration and maps a drive again with the settings of an earlier output."""

import dataclasses
import json
import shutil
import sqlite3
from contextlib import closing

import pytest
from qgis.core import QgsProcessingException, QgsVectorLayer
from recorder import Recorder

from signmapper_core.fusion.signs import FusionConfig
from signmapper_core.output.run_settings import load_run_settings
from signmapper_core.output.run_table import SETTINGS_VERSION, read_run_record, settings_dict
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.config import (
    ClassificationConfig,
    ColourConfig,
    DepthConfig,
    PlanarityConfig,
    WhiteConfig,
    with_settings,
)

# not the defaults: depth range, colours, both thresholds and an excluded type
CHANGED = {"NEAR": 5.0, "FAR": 16.0, "COLOURS": [0, 1], "DETECTION_THRESHOLD": 0.6,
           "CLASSIFICATION_THRESHOLD": 0.7, "EXCLUDE": "2.30-120", "WHITE_SIGNS": False}
# a limit given fixes the range: no reach beyond it
EXPECTED = PipelineConfig(depth=DepthConfig(near_m=5.0, far_m=16.0, range_from_camera=False),
                          colour=ColourConfig(colours=("red", "blue")),
                          planarity=PlanarityConfig(detection_threshold=0.6),
                          classification=ClassificationConfig(classification_threshold=0.7, exclude=("2.30-120",)),
                          white=WhiteConfig(white_signs=False))


_MAPPED = {}  # the earlier output is mapped once for all tests (the plugin fixture is per test)


@pytest.fixture
def earlier(registered_plugin, small_drive, tmp_path_factory):
    """An output mapped with non-default settings: the record to map the drive again with."""
    import processing

    if "earlier" not in _MAPPED:
        out = tmp_path_factory.mktemp("earlier") / "earlier.gpkg"
        processing.run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), **CHANGED})
        _MAPPED["earlier"] = out
    return _MAPPED["earlier"]


def signs(path):
    layer = QgsVectorLayer(f"{path}|layername=signs", "signs", "ogr")
    assert layer.isValid()
    return sorted((f["sign_id"], f["template_id"], f["status"], f["easting"], f["northing"], f["elevation"],
                   f["n_obs"], f["classification_indicator"]) for f in layer.getFeatures())


def without_run_id(record):
    return {k: v for k, v in record.items() if k != "run_id"}


def test_the_run_table_holds_the_whole_configuration_and_reads_back(earlier):
    record = read_run_record(earlier)
    assert record["settings_version"] == SETTINGS_VERSION
    assert record["pipeline"] == settings_dict(EXPECTED)  # every field, not only the dialog's
    # the fusion carries the classifier's threshold and the run's far limit (a sign seen once near it waits)
    assert record["fusion"] == settings_dict(FusionConfig(accept_classification=0.7, far_m=16.0))
    assert record["classification_threshold"] == 0.7 and record["classifier"] in ("cnn", "ncc")
    settings = load_run_settings(earlier)
    assert settings.config == EXPECTED and settings.fusion == FusionConfig(accept_classification=0.7, far_m=16.0)
    assert settings.catalogue == record["catalogue"]


def test_a_rerun_with_the_earlier_settings_gives_the_same_record_and_signs(run_mapsigns, earlier, small_drive,
                                                                          tmp_path):
    again = tmp_path / "again.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(again), "SETTINGS_FROM": str(earlier)})
    assert without_run_id(read_run_record(again)) == without_run_id(read_run_record(earlier))
    assert signs(again) == signs(earlier) and len(signs(earlier)) >= 2
    # the default run differs, so the settings did come from the record
    default = tmp_path / "default.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(default)})
    assert read_run_record(default)["pipeline"] != read_run_record(earlier)["pipeline"]


def test_a_parameter_set_in_the_dialog_wins_over_the_record(run_mapsigns, earlier, small_drive, tmp_path):
    out = tmp_path / "far12.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(out), "SETTINGS_FROM": str(earlier), "FAR": 12.0,
                  "NEAR": 4.0})  # NEAR at its default: the record's 5 m stays
    pipeline = read_run_record(out)["pipeline"]
    depth, planarity = pipeline["depth"], pipeline["planarity"]
    assert (depth["near_m"], depth["far_m"], planarity["detection_threshold"]) == (5.0, 12.0, 0.6)
    assert pipeline["colour"]["colours"] == ["red", "blue"]


def _edited(earlier, tmp_path, sql, *args):
    copy = tmp_path / "edited.gpkg"
    shutil.copy(earlier, copy)
    with closing(sqlite3.connect(copy)) as db:
        db.execute(sql, args)
        db.commit()
    return copy


def test_unknown_settings_are_warned_about_and_ignored(run_mapsigns, earlier, small_drive, tmp_path):
    pipeline = read_run_record(earlier)["pipeline"]
    pipeline["depth"]["a_later_setting"] = 3
    edited = _edited(earlier, tmp_path, "UPDATE signmapper_run SET value = ? WHERE key = 'pipeline'",
                     json.dumps(pipeline))
    feedback = Recorder()
    out = tmp_path / "later.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(out), "SETTINGS_FROM": str(edited)}, feedback)
    assert any(f"{edited}, pipeline settings, section depth: ignored settings this version does not know: "
               "a_later_setting" in w for w in feedback.warnings), feedback.warnings
    assert read_run_record(out)["pipeline"] == settings_dict(EXPECTED)


def test_an_output_of_settings_version_1_maps_again_with_its_settings(run_mapsigns, earlier, small_drive, tmp_path):
    """An output written before the sections (settings version 1: the pipeline settings in one flat object)."""
    sections = read_run_record(earlier)["pipeline"]
    flat = {name: value for section in sections.values() for name, value in section.items()}
    old = _edited(earlier, tmp_path, "UPDATE signmapper_run SET value = CASE key WHEN 'settings_version' THEN '1' "
                  "ELSE ? END WHERE key IN ('settings_version', 'pipeline')", json.dumps(flat))
    assert read_run_record(old)["settings_version"] == 1 and read_run_record(old)["pipeline"] == flat
    feedback = Recorder()
    out = tmp_path / "again.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(out), "SETTINGS_FROM": str(old)}, feedback)
    assert read_run_record(out)["pipeline"] == settings_dict(EXPECTED)
    assert not [w for w in feedback.warnings if "settings" in w], feedback.warnings


@pytest.mark.parametrize("sql, args, message", [
    ("DROP TABLE signmapper_run", (), "no table 'signmapper_run': not an output of Sign Mapper's"),
    ("UPDATE signmapper_run SET value = ? WHERE key = 'settings_version'", ("99",),
     "settings version 99 (written by Sign Mapper"),
    ("DELETE FROM signmapper_run WHERE key IN ('settings_version', 'pipeline', 'fusion')", (),
     "recorded only some of its settings"),
    ("UPDATE signmapper_run SET value = ? WHERE key = 'pipeline'", ('{"depth": {"near_m": 9, "far_m": 3}}',),
     "pipeline settings, section depth: need 0 < near_m < far_m"),
    # issue 46, case 8: a wrong type is said before the first pair, not as per-pair IndexErrors blamed on images
    ("UPDATE signmapper_run SET value = ? WHERE key = 'pipeline'", ('{"colour": {"hsv_ranges": {"red": "x"}}}',),
     "pipeline settings, section colour: setting hsv_ranges['red'] must be a list of lists of 6 whole numbers, "
     "found \"x\""),
])
def test_records_that_cannot_give_the_settings_are_refused_naming_the_file(
        run_mapsigns, earlier, small_drive, tmp_path, sql, args, message):
    edited = _edited(earlier, tmp_path, sql, *args)
    with pytest.raises(QgsProcessingException) as raised:
        run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg"), "SETTINGS_FROM": str(edited)})
    assert f"Settings from an earlier output: {edited}" in str(raised.value) and message in str(raised.value)
    assert not (tmp_path / "x.gpkg").exists()


def test_a_run_table_row_contradicting_the_pipeline_settings_is_warned_about_and_the_pipeline_wins(
        run_mapsigns, earlier, small_drive, tmp_path):
    """Issue 46, case 13: the rows near_m, far_m, … repeat the pipeline settings for readers; edited apart, the
    run says which it uses."""
    edited = _edited(earlier, tmp_path, "UPDATE signmapper_run SET value = '9.5' WHERE key = 'near_m'")
    feedback = Recorder()
    out = tmp_path / "again.gpkg"
    run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(out), "SETTINGS_FROM": str(edited)}, feedback)
    assert f"{edited}: its run table says near_m 9.5, its pipeline settings depth.near_m 5.0; the pipeline " \
           "settings are used (they are what that run was mapped with)" in feedback.warnings, feedback.warnings
    assert read_run_record(out)["pipeline"] == settings_dict(EXPECTED) and read_run_record(out)["near_m"] == 5.0


def test_a_file_that_is_no_geopackage_is_refused(run_mapsigns, small_drive, tmp_path):
    text = tmp_path / "notes.gpkg"
    text.write_text("not a database")
    with pytest.raises(QgsProcessingException, match="Settings from an earlier output: .*notes.gpkg: not a GeoPackage"):
        run_mapsigns({"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg"), "SETTINGS_FROM": str(text)})


@pytest.fixture
def run_mapsigns(registered_plugin):
    import processing

    def run(parameters, feedback=None):
        return processing.run("signmapper:mapsigns", parameters, feedback=feedback)

    return run


def test_the_review_adds_signs_with_the_runs_whole_recorded_configuration(earlier):
    from sign_mapper.review.session import ReviewSession

    session = ReviewSession(lambda *args, **kwargs: None)
    record = read_run_record(earlier)
    record["pipeline"]["hough"]["hough_enabled"] = False  # a setting no dialog parameter sets
    session.run = record
    # (compared as recorded: the plugin's package is another copy of the core's classes)
    assert settings_dict(session.pipeline_config()) == settings_dict(
        with_settings(EXPECTED, {"hough": {"hough_enabled": False}}))
    # a run recorded before settings were saved whole: its dialog settings, the effective threshold, the classifier
    session.run = {k: v for k, v in record.items() if k not in ("settings_version", "pipeline", "fusion")}
    older = settings_dict(session.pipeline_config())
    classification = ClassificationConfig(classification_threshold=0.7, exclude=("2.30-120",),
                                          classifier=record["classifier"])
    # (the white step was no dialog setting then: such a record maps without it)
    assert older == settings_dict(dataclasses.replace(EXPECTED, classification=classification, white=WhiteConfig()))
