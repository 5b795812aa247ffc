"""``signmapper:mapsigns`` on a small synthetic drive: toolbox call, model chain, cancel, bad pairs, CLI."""

from pathlib import Path

import numpy as np
import pytest
from model_chain import synthetic_drive_then_map_signs
from qgis.core import (
    QgsProcessingException,
    QgsProcessingFeedback,
    QgsVectorLayer,
    QgsWkbTypes,
)
from qgis_process_runner import enable_plugin, qgis_process_env, run_algorithm

from signmapper_core.drive.reader import open_drive


def read_detections(path):
    layer = QgsVectorLayer(f"{path}|layername=detections", "d", "ogr")
    assert layer.isValid()
    return layer


def positions_and_ids(layer):
    xyz, ids = [], []
    for f in layer.getFeatures():
        p = f.geometry().constGet()
        xyz.append((p.x(), p.y(), p.z()))
        ids.append(f["template_id"])
    return np.array(xyz).reshape(-1, 3), ids


def assert_finds_truth(layer, drive_dir, tolerance_m=0.3, min_signs=1):
    xyz, ids = positions_and_ids(layer)
    truth = open_drive(drive_dir).truth
    found = 0
    for sign in truth:
        dist = np.linalg.norm(xyz - sign.position, axis=1) if len(xyz) else np.array([])
        close = [ids[i] for i in np.flatnonzero(dist < tolerance_m)]
        found += sign.template_id in close
    assert found >= min_signs, f"{found} truth signs found with the right id among {len(xyz)} detections"
    return found


def test_map_signs_writes_detections_with_the_right_ids_and_positions(run, small_drive, tmp_path):
    out = tmp_path / "signs.gpkg"
    result = run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out)})
    assert result["OUTPUT"] == str(out)
    layer = read_detections(out)
    assert layer.wkbType() == QgsWkbTypes.PointZ
    assert layer.crs().authid() == "EPSG:2056"
    for name in ("template_id", "name", "colour", "shape", "width_m", "height_m", "format", "detection_indicator",
                 "classification_indicator", "status", "pair_id", "time", "u", "v", "bbox_x", "bbox_y", "bbox_w",
                 "bbox_h", "depth_m"):
        assert name in layer.fields().names()
    assert layer.featureCount() > 0
    statuses = {f["status"] for f in layer.getFeatures()}
    assert statuses <= {"accepted", "review"}
    assert_finds_truth(layer, small_drive, min_signs=2)
    assert result["SIGNS"].endswith("|layername=signs") and result["DETECTIONS"].endswith("|layername=detections")
    signs = QgsVectorLayer(f"{out}|layername=signs", "s", "ogr")
    assert signs.isValid() and signs.wkbType() == QgsWkbTypes.PointZ
    for name in ("sign_id", "n_obs", "vote_share", "sigma_m", "azimuth", "best_pair_id", "bbox_x", "status"):
        assert name in signs.fields().names()
    assert 0 < signs.featureCount() < layer.featureCount()
    # one fused sign per truth sign, close to it and with its id; every detection names its sign
    found = assert_finds_truth(signs, small_drive, tolerance_m=0.1, min_signs=2)
    assert signs.featureCount() <= found + 1
    sign_ids = {f["sign_id"] for f in signs.getFeatures()}
    assert {f["sign_id"] for f in layer.getFeatures()} == sign_ids
    assert sum(f["n_obs"] for f in signs.getFeatures()) == layer.featureCount()
    # the generator places lower edges 0.6-2.5 m above the road (SSV Art. 103) and states its camera height
    mounts = [f["mount_height_m"] for f in signs.getFeatures()]
    assert all(m is not None and 0.4 <= m <= 2.8 for m in mounts), mounts
    run_table = QgsVectorLayer(f"{out}|layername=signmapper_run", "run", "ogr")
    values = {f["key"]: f["value"] for f in run_table.getFeatures()}
    assert Path(values["drive"]) == small_drive.resolve()
    assert not list(tmp_path.glob(".*partial*"))
    assert not list(tmp_path.glob("*-wal")) and not list(tmp_path.glob("*-journal"))


def test_layers_open_with_the_embedded_pictogram_style(run, small_drive, tmp_path):
    out = tmp_path / "styled.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out)})
    signs = QgsVectorLayer(f"{out}|layername=signs", "s", "ogr")
    renderer = signs.renderer()
    assert renderer.type() == "RuleRenderer"
    rules = {r.filterExpression(): r for r in renderer.rootRule().descendants()}
    assert all(f""""template_id" = '{f["template_id"]}'""" in rules for f in signs.getFeatures())
    status, families = renderer.rootRule().children()[0], renderer.rootRule().children()[1:]
    assert [r.filterExpression() for r in status.children()] == [f'"status" = \'{s}\'' for s in
                                                                 ("accepted", "review", "rejected", "manual")]
    svg = families[0].children()[0].symbol().symbolLayer(0)
    assert svg.layerType() == "SvgMarker" and svg.path().startswith("base64:")
    assert signs.labelsEnabled()
    detections = QgsVectorLayer(f"{out}|layername=detections", "d", "ogr")
    assert detections.renderer().classAttribute() == "status"


def test_sgbm_depth_without_depth_maps(run, small_drive, tmp_path):
    """The same drive without depth/: depth comes from the stereo pair."""
    import shutil

    no_depth = tmp_path / "nodepth"
    shutil.copytree(small_drive, no_depth, ignore=shutil.ignore_patterns("depth"))
    out = tmp_path / "sgbm.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(no_depth), "OUTPUT": str(out)})
    assert_finds_truth(read_detections(out), no_depth, tolerance_m=0.4, min_signs=2)


def test_excluded_type_is_never_assigned(run, small_drive, tmp_path):
    truth_ids = sorted({s.template_id for s in open_drive(small_drive).truth})
    out = tmp_path / "excl.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "EXCLUDE": ", ".join(truth_ids[:2])})
    ids = {f["template_id"] for f in read_detections(out).getFeatures()}
    assert not ids & set(truth_ids[:2])


def test_unknown_excluded_id_is_a_clear_error(run, small_drive, tmp_path):
    with pytest.raises(QgsProcessingException, match="9.99 not in the catalogue"):
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg"), "EXCLUDE": "9.99"})


@pytest.mark.parametrize("change, message", [
    ({"NEAR": 14.0, "FAR": 4.0}, "Near limit of the depth range [m] (14 m) must be less than Far limit of the depth "
                                 "range [m] (4 m)"),
    ({"COLOURS": []}, "COLOURS"),  # QGIS itself refuses an empty required choice
    ({"OUTPUT": None}, "must be a GeoPackage file ending in .gpkg"),
    ({"CATALOGUE": None}, "Template catalogue"),
    ({"DRIVE": None}, "no drive.json, not a stereo-drive/1 folder"),
])
def test_wrong_inputs_are_refused_before_the_run(registered_plugin, small_drive, tmp_path, change, message):
    from qgis.core import QgsApplication, QgsProcessingContext

    alg = QgsApplication.processingRegistry().createAlgorithmById("signmapper:mapsigns")
    paths = {"OUTPUT": tmp_path / "signs.shp", "CATALOGUE": tmp_path, "DRIVE": tmp_path}  # folders without files
    parameters = {"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg")}
    parameters.update({k: str(paths[k]) if k in paths else v for k, v in change.items()})
    ok, text = alg.checkParameterValues(parameters, QgsProcessingContext())
    assert not ok and message in text
    assert alg.checkParameterValues({"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg")},
                                    QgsProcessingContext()) == (True, "")


def test_tuning_parameters_are_advanced(registered_plugin):
    from qgis.core import QgsApplication, QgsProcessingParameterDefinition

    alg = QgsApplication.processingRegistry().algorithmById("signmapper:mapsigns")
    advanced = {p.name() for p in alg.parameterDefinitions()
                if p.flags() & QgsProcessingParameterDefinition.FlagAdvanced}
    assert advanced == {"EXCLUDE", "DETECTION_THRESHOLD", "CLASSIFIER", "CLASSIFICATION_THRESHOLD", "CATALOGUE",
                        "LANGUAGE", "MAX_SKIPPED", "WORKERS", "SCHEDULER"}


def test_corrupt_pair_is_logged_and_skipped(run, small_drive, tmp_path):
    import shutil

    drive = tmp_path / "corrupt"
    shutil.copytree(small_drive, drive)
    broken = sorted((drive / "left").iterdir())[3]
    broken.write_bytes(broken.read_bytes()[:2000])  # header readable, pixels truncated
    messages = []

    class Recorder(QgsProcessingFeedback):
        def pushWarning(self, warning):  # noqa: N802 - a skipped pair is a warning: the run goes on
            messages.append(warning)

    out = tmp_path / "c.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out)}, feedback=Recorder())
    assert read_detections(out).featureCount() > 0
    assert any(broken.stem in m and broken.name in m for m in messages), messages


def test_pair_whose_detection_raises_is_logged_with_its_traceback_and_the_run_goes_on(
        run, sign_mapper, small_drive, tmp_path, monkeypatch):
    import importlib

    pipeline = importlib.import_module(f"{sign_mapper.__name__}.signmapper_core.pipeline")
    real, failing = pipeline.detect_pair, open_drive(small_drive).pairs[4].pose

    def detect_pair(left, depth, right, camera, pose, *args, **kwargs):
        if (pose.easting, pose.northing) == (failing.easting, failing.northing):  # the plugin's Pose is another class
            raise ZeroDivisionError("bad pixels")
        return real(left, depth, right, camera, pose, *args, **kwargs)

    monkeypatch.setattr(pipeline, "detect_pair", detect_pair)
    errors, warnings = [], []

    class Recorder(QgsProcessingFeedback):
        def reportError(self, error, fatalError=False):  # noqa: N802, N803
            errors.append(error)

        def pushWarning(self, warning):  # noqa: N802
            warnings.append(warning)

    out = tmp_path / "failing.gpkg"  # in this process, where the patch is (tests/core/test_pair_pool: in workers)
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "WORKERS": 1}, feedback=Recorder())
    assert read_detections(out).featureCount() > 0
    assert errors == []  # the run went on: warnings, not errors (qgis_process prints them as WARNING)
    (error,) = [w for w in warnings if w.startswith("Skipped pair")]
    assert error.startswith("Skipped pair 000004: detection failed: ZeroDivisionError: bad pixels\nTraceback")
    assert 'raise ZeroDivisionError("bad pixels")' in error
    n = len(open_drive(small_drive).pairs)
    assert any(w.startswith(f"1 of {n} pairs skipped: 1 detection error") for w in warnings), warnings


@pytest.mark.parametrize("workers", [1, 2])
def test_cancel_writes_nothing(run, small_drive, tmp_path, workers):
    import multiprocessing

    out = tmp_path / "cancelled.gpkg"
    feedback = QgsProcessingFeedback()
    feedback.progressChanged.connect(lambda p: feedback.cancel() if p > 20 else None)
    with pytest.raises(QgsProcessingException, match="Cancelled"):
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "WORKERS": workers},
            feedback=feedback)
    assert not out.exists() and multiprocessing.active_children() == []
    assert not list(tmp_path.glob("*.gpkg")) and not list(tmp_path.glob(".*partial*"))


def test_model_chains_synthetic_drive_into_map_signs(run, tmp_path):
    model = synthetic_drive_then_map_signs(tmp_path / "d")
    out = tmp_path / "chain.gpkg"
    result = run(model, {"map:gpkg": str(out)})
    assert Path(result["map:gpkg"]) == out
    assert read_detections(out).featureCount() > 0
    assert (tmp_path / "d" / "truth.csv").exists()


def test_map_signs_through_qgis_process(plugin_dir, small_drive, tmp_path):
    env = qgis_process_env(plugin_dir, tmp_path / "profile")
    enable_plugin(env)
    out = tmp_path / "cli.gpkg"
    code, data, log = run_algorithm(env, "signmapper:mapsigns", DRIVE=small_drive, OUTPUT=out, NEAR=4, FAR=14)
    assert code == 0, log
    assert data["results"]["OUTPUT"] == str(out)
    assert_finds_truth(read_detections(out), small_drive, min_signs=2)


def test_crops_beside_the_geopackage_and_iso_timestamps(run, small_drive, tmp_path):
    import json
    import shutil

    drive = tmp_path / "dated"
    shutil.copytree(small_drive, drive)
    meta = json.loads((drive / "drive.json").read_text())
    meta["start_time"] = "2026-05-04T09:12:03+02:00"
    (drive / "drive.json").write_text(json.dumps(meta))
    out = tmp_path / "run.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out), "CROPS": True})
    signs = list(QgsVectorLayer(f"{out}|layername=signs", "s", "ogr").getFeatures())
    assert signs
    first = open_drive(drive).pairs[0].time
    for sign in signs:
        crop = out.parent / sign["crop_path"]
        assert sign["crop_path"] == f"run_crops/sign_{sign['sign_id']:05d}.jpg" and crop.is_file()
        assert sign["timestamp"].startswith("2026-05-04T09:12:") and sign["timestamp"].endswith("+02:00")
        seconds = float(sign["timestamp"][17:23]) - 3.0
        assert seconds == pytest.approx(sign["time"] - first, abs=1e-3)
    assert not list(tmp_path.glob(".*partial*"))
