"""The declared output schema: layers and their fields, values read from signs and detections, the run table."""

import numpy as np
import pytest
from test_fusion import CAMERA

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import PairRecord
from signmapper_core.fusion.signs import Observation, fuse_observations
from signmapper_core.geometry import Pose
from signmapper_core.output import run_table, schema
from signmapper_core.pipeline.detection import Detection
from signmapper_core.run.mapping import manual_sign
from signmapper_core.statuses import ACCEPTED, MANUAL, REJECTED, REVIEW, STATUS_COLOURS, STATUSES


def observation(pair_index, position, status="accepted", u=512.345678, depth=9.87654):
    detection = Detection("2.30-50", "Höchstgeschwindigkeit 50", "red", "circle", 0.6, 0.6, "normal", 0.912345,
                          0.876543, status, u, 300.5, (480, 270, 64, 62), depth, np.asarray(position, float))
    pose = Pose(2600000.0 + 2.0 * pair_index, 1200000.0, 402.0, 90.0, 0.0, 0.0)
    return Observation(detection, PairRecord(pair_index, f"{pair_index:06d}", 0.2 * pair_index, pose, None, None,
                                             None), id=pair_index + 1)


@pytest.fixture
def fused():
    truth = np.array([2600020.0, 1200003.0, 404.5])
    observations = [observation(k, truth + [0.01 * k, 0.0, 0.0], depth=20.0 - 2.0 * k) for k in range(3, 7)]
    return fuse_observations(observations, CAMERA)[0], observations


def test_each_layer_has_its_fields_once_in_the_declared_order():
    signs = [f.name for f in schema.fields(schema.SIGNS)]
    detections = [f.name for f in schema.fields(schema.DETECTIONS)]
    assert signs[0] == "sign_id" and detections[-1] == "sign_id"  # the sign's number; the detection's link
    assert len(set(signs)) == len(signs) and len(set(detections)) == len(detections)
    assert {"n_obs", "vote_share", "sigma_m", "azimuth", "mount_height_m", "best_pair_id"} <= set(signs) - set(
        detections)
    assert set(detections) - set(signs) == {"pair_id"}
    assert all(f.help and f.kind in (schema.TEXT, schema.INTEGER, schema.REAL) for f in schema.FIELDS)
    with pytest.raises(ValueError, match="no output layer 'tracks'"):
        schema.fields("tracks")


def test_a_detection_row_is_read_from_its_observation_typed_and_rounded(fused):
    sign, observations = fused
    row = schema.values(schema.DETECTIONS, observations[0])
    assert row["template_id"] == "2.30-50" and row["pair_id"] == "000003" and row["time"] == pytest.approx(0.6)
    assert row["detection_indicator"] == 0.9123 and row["u"] == 512.35 and row["depth_m"] == 14.0
    assert (row["bbox_x"], row["bbox_y"], row["bbox_w"], row["bbox_h"]) == (480, 270, 64, 62)
    assert row["status"] == "accepted" and row["reviewed"] == 0 and row["sign_id"] == sign.sign_id


def test_a_sign_row_takes_its_pixels_from_the_best_observation(fused):
    sign, _ = fused
    row = schema.values(schema.SIGNS, sign)
    assert row["sign_id"] == 1 and row["n_obs"] == 4 and row["vote_share"] == 1.0
    assert row["best_pair_id"] == sign.best.pair_id and row["depth_m"] == round(sign.best.depth_m, 3)
    assert row["azimuth"] == round(sign.azimuth, 1) and row["mount_height_m"] is None
    assert row["colour"] == "red" and row["source"] == "colour"


def test_a_manual_sign_is_reviewed_and_faces_the_camera():
    obs = observation(4, [2600020.0, 1200003.0, 404.5], status="manual")
    row = schema.values(schema.SIGNS, manual_sign(obs, 7))
    assert (row["sign_id"], row["status"], row["reviewed"], row["n_obs"], row["sigma_m"]) == (7, "manual", 1, 1, None)
    assert row["azimuth"] == pytest.approx(np.degrees(np.arctan2(-12.0, -3.0)) % 360, abs=0.05)
    assert schema.values(schema.DETECTIONS, obs)["reviewed"] == 1


def test_reclassifying_writes_what_the_template_gives():
    entry = load_catalogue()["2.01"]
    fmt = next(iter(entry.formats))
    values = schema.template_values(schema.SIGNS, entry, fmt)
    assert values == {"template_id": "2.01", "name": entry.name("de"), "colour": entry.colour,
                      "shape": entry.shape, "width_m": entry.formats[fmt][0], "height_m": entry.formats[fmt][1],
                      "format": fmt}


def test_our_layers_are_known_by_what_the_review_needs():
    assert {"template_id", "status", "reviewed", "pair_id", "u", "v", "bbox_h"} == schema.required_names(
        schema.DETECTIONS) - {"bbox_x", "bbox_y", "bbox_w"}
    assert {"sign_id", "n_obs", "best_pair_id"} <= schema.required_names(schema.SIGNS)
    assert "pair_id" not in schema.required_names(schema.SIGNS)


def test_every_status_has_one_colour():
    assert set(STATUS_COLOURS) == set(STATUSES) == {ACCEPTED, REVIEW, REJECTED, MANUAL}
    assert all(c.startswith("#") and len(c) == 7 for c in STATUS_COLOURS.values())


def test_run_values_round_trip_as_text_or_json():
    assert run_table.decode_run_value("drive", run_table.encode_run_value("/data/2024")) == "/data/2024"
    assert run_table.decode_run_value("drive", "123") == "123"  # a path stays text even when it looks like JSON
    assert run_table.decode_run_value("near_m", run_table.encode_run_value(4.0)) == 4.0
    assert run_table.decode_run_value("colours", run_table.encode_run_value(["red", "blue"])) == ["red", "blue"]
    assert run_table.decode_run_value("from_a_later_version", "not json") == "not json"
    assert [k.key for k in run_table.RUN_KEYS][:2] == ["software", "drive"]


def test_survey_fields_come_first_with_coordinates_and_aliases_in_four_languages():
    for layer in schema.LAYERS:
        survey = [f.survey for f in schema.fields(layer)]
        assert survey == sorted(survey, reverse=True), layer  # no survey field after an internal one
        assert all(set(f.aliases) == set(schema.LANGUAGES) for f in schema.fields(layer))
    names = [f.name for f in schema.fields(schema.SIGNS)]
    assert names.index("elevation") < names.index("u") and names.index("timestamp") < names.index("bbox_x")
    assert schema.field(schema.SIGNS, "template_id").alias("it") == "Tipo di segnale (OSS)"
    assert schema.field(schema.SIGNS, "sigma_m").alias("xx") == "Position σ [m]"  # unknown: English
    assert [schema.language_of(x) for x in ("fr_CH", "de", "it-IT", "C", "", "rm_CH")] == ["fr", "de", "it", "en",
                                                                                         "en", "en"]


def test_coordinates_names_and_iso_timestamps_follow_the_output_context(fused):
    from datetime import datetime, timedelta, timezone

    sign, observations = fused
    plain = schema.values(schema.SIGNS, sign)
    assert (plain["easting"], plain["northing"], plain["elevation"]) == tuple(round(float(c), 3) for c in
                                                                             sign.position)
    assert plain["timestamp"] is None and plain["crop_path"] is None and plain["name"] == sign.name
    start = datetime(2026, 5, 4, 9, 12, 3, 200000, tzinfo=timezone(timedelta(hours=2)))
    context = schema.OutputContext(language="fr", catalogue=load_catalogue(), start=start, first_time=0.2,
                                   crops={sign.sign_id: "run_crops/sign_00001.jpg"})
    row = schema.values(schema.SIGNS, sign, context)
    assert row["name"] == load_catalogue()["2.30-50"].name("fr")
    expected = (start + timedelta(seconds=sign.best.time - 0.2)).isoformat(timespec="milliseconds")
    assert row["timestamp"] == expected and expected.endswith("+02:00")
    assert row["crop_path"] == "run_crops/sign_00001.jpg"
    assert schema.values(schema.DETECTIONS, observations[0], context)["timestamp"] == (
        start + timedelta(seconds=0.4)).isoformat(timespec="milliseconds")
    assert schema.template_values(schema.SIGNS, load_catalogue()["2.01"], "normal", "it")["name"] == \
        load_catalogue()["2.01"].name("it")


def test_run_table_records_how_the_rows_were_written():
    from types import SimpleNamespace

    context = schema.OutputContext(language="it", crops={1: "a.jpg", 2: "b.jpg"})
    record = {k.key: k.read(context) for k in run_table.OUTPUT_RUN_KEYS}
    assert record == {"language": "it", "start_time": "", "crops": 2}
    assert run_table.decode_run_value("language", "it") == "it"
    assert SimpleNamespace  # the mapping part is covered by the golden GeoPackage


def test_every_swiss_sign_has_an_english_name_and_english_output_uses_it():
    from signmapper_core.catalogue.names import NAMES_EN, sign_name

    catalogue = load_catalogue()
    assert set(NAMES_EN) == set(catalogue.ids())
    entry = catalogue["2.02"]
    assert [sign_name(entry, lang) for lang in ("en", "de", "fr")] == ["No entry", "Einfahrt verboten",
                                                                      "Accès interdit"]
    assert schema.template_values(schema.SIGNS, entry, "normal", "en")["name"] == "No entry"
    context = schema.OutputContext(language="en", catalogue=catalogue)
    assert context.name("2.30-50", "Höchstgeschwindigkeit 50") == "Speed limit 50"
    assert context.name("9.99", "unknown") == "unknown"


def test_plates_are_named_in_the_output_language():
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.output.schema import OutputContext

    catalogue = load_catalogue()
    assert OutputContext("fr", catalogue).name("5.31-2", "Ausgenommen Fahrräder") == "Exceptés cycles"
    assert OutputContext("it", catalogue).name("plate", "Zusatztafel") == "Tavola complementare"
    assert OutputContext("de", catalogue).name("5.99", "as detected") == "as detected"  # no such plate
