"""``signmapper:evaluate`` on hand-made references with known offsets, and the full modeler chain."""

from pathlib import Path

import pytest
from qgis.core import (
    QgsFeature,
    QgsGeometry,
    QgsLineString,
    QgsPoint,
    QgsProcessingModelAlgorithm,
    QgsProcessingModelChildAlgorithm,
    QgsProcessingModelChildParameterSource,
    QgsProcessingModelOutput,
    QgsVectorLayer,
)

from signmapper_core.drive.reader import open_drive

REF = [("s1", "2.01", 2600010.0, 1200004.0, 402.0), ("s2", "3.03", 2600020.0, 1199996.0, 402.5),
       ("s3", "2.30-50", 2600030.0, 1200004.0, 401.8), ("s4", "1.22", 2600040.0, 1199996.0, 402.2)]


def point_layer(rows, name, status=None):
    layer = QgsVectorLayer("PointZ?crs=EPSG:2056&field=template_id:string&field=status:string", name, "memory")
    features = []
    for i, (_sid, tid, e, n, h) in enumerate(rows):
        f = QgsFeature(layer.fields())
        f.setGeometry(QgsGeometry(QgsPoint(e, n, h)))
        f.setAttributes([tid, (status or {}).get(i, "accepted")])
        features.append(f)
    layer.dataProvider().addFeatures(features)
    return layer


def eastward_trajectory():
    layer = QgsVectorLayer("LineString?crs=EPSG:2056", "traj", "memory")
    f = QgsFeature()
    f.setGeometry(QgsGeometry(QgsLineString([QgsPoint(2599990.0, 1200000.0), QgsPoint(2600060.0, 1200000.0)])))
    layer.dataProvider().addFeatures([f])
    return layer


def evaluate(run, tmp_path, mapped, **extra):
    params = {"SIGNS": mapped, "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD": "template_id",
              "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "report.html"),
              "STATISTICS": "memory:", "MATCHES": "memory:"}
    params.update(extra)
    return run("signmapper:evaluate", params)


def stats_of(result):
    return {f["figure"]: f["value"] for f in result["STATISTICS"].getFeatures()}


def test_every_sign_moved_5cm_across_track(run, tmp_path):
    moved = [(s, t, e, n - 0.05, h) for s, t, e, n, h in REF]  # south = right of an eastward drive
    result = evaluate(run, tmp_path, point_layer(moved, "mapped"))
    stats = stats_of(result)
    assert stats["across_mean"] == pytest.approx(0.05, abs=1e-6)
    assert stats["across_std"] == pytest.approx(0.0, abs=1e-6)
    assert stats["along_max"] == pytest.approx(0.0, abs=1e-6)
    assert stats["3d_rms"] == pytest.approx(0.05, abs=1e-6)
    assert result["DETECTION_RATE"] == 1.0 and result["CLASSIFICATION_RATE"] == 1.0
    assert result["FALSE_POSITIVES"] == 0 and result["DUPLICATES"] == 0
    html = Path(result["REPORT"]).read_text()
    assert "Table 1" in html and "Table 2" in html and "<svg" in html
    lines = list(result["MATCHES"].getFeatures())
    assert len(lines) == 4 and all(f["correct"] for f in lines)
    assert lines[0].geometry().length() == pytest.approx(0.05, abs=1e-6)


def test_one_missing_sign_drops_the_detection_rate_by_exactly_one(run, tmp_path):
    result = evaluate(run, tmp_path, point_layer(REF[:3], "mapped"))
    assert result["DETECTION_RATE"] == pytest.approx(3 / 4)
    assert stats_of(result)["detected_signs"] == 3


def test_false_positive_duplicate_misclassified_and_rejected(run, tmp_path):
    rows = list(REF) + [("x", "2.01", 2600050.0, 1200010.0, 402.0),  # nothing there
                        ("d", "2.01", 2600010.1, 1200004.0, 402.0),  # second feature for s1
                        ("r", "2.01", 2600055.0, 1200010.0, 402.0)]  # rejected in review: ignored
    rows[1] = ("s2", "3.04", *REF[1][2:])
    result = evaluate(run, tmp_path, point_layer(rows, "mapped", status={6: "rejected"}))
    assert result["FALSE_POSITIVES"] == 1
    assert result["DUPLICATES"] == 1
    assert result["CLASSIFICATION_RATE"] == pytest.approx(3 / 4)
    assert "3.03 → 3.04" in Path(result["REPORT"]).read_text()


def test_reference_signs_facing_away_from_the_drive_are_left_out(run, tmp_path):
    reference = QgsVectorLayer("PointZ?crs=EPSG:2056&field=template_id:string&field=facing:double", "ref", "memory")
    features = []
    for tid, north, facing in (("2.01", 1200004.0, 250.0), ("2.02", 1200004.0, 70.0)):  # back to back on one pole
        f = QgsFeature(reference.fields())
        f.setGeometry(QgsGeometry(QgsPoint(2600030.0, north, 402.0)))
        f.setAttributes([tid, facing])
        features.append(f)
    reference.dataProvider().addFeatures(features)
    mapped = point_layer([("a", "2.01", 2600030.0, 1200004.0, 402.0)], "mapped")
    common = {"SIGNS": mapped, "REFERENCE": reference, "REFERENCE_ID_FIELD": "template_id", "RADIUS": 0.5,
              "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"), "STATISTICS": "memory:",
              "MATCHES": "memory:"}
    assert run("signmapper:evaluate", common)["DETECTION_RATE"] == pytest.approx(0.5)
    result = run("signmapper:evaluate", {**common, "REFERENCE_FACING_FIELD": "facing"})
    assert result["DETECTION_RATE"] == 1.0
    assert stats_of(result)["reference_signs"] == 1


def test_truth_csv_as_reference_and_trajectory_from_the_recorded_drive(run, tmp_path):
    from drive_fixtures import make_drive

    drive = make_drive(tmp_path / "drive", n_pairs=5)
    uri = (f"file://{drive / 'truth.csv'}?delimiter=,&xField=easting&yField=northing&zField=height"
           "&crs=EPSG:2056")
    truth = QgsVectorLayer(uri, "truth", "delimitedtext")
    assert truth.isValid() and truth.featureCount() == 1
    gpkg = tmp_path / "signs.gpkg"
    mapped = point_layer([("s", "2.30-50", 2600005.0, 1200003.0, 401.6)], "signs")
    from sign_mapper.gpkg.output import GeoPackageLayers
    from sign_mapper.signmapper_core.output.geopackage_file import PartialGeoPackage

    out = PartialGeoPackage(gpkg)
    layers = GeoPackageLayers(out)
    writer = layers.open_layer("signs", mapped.fields(), mapped.wkbType(), mapped.crs())
    for f in mapped.getFeatures():
        writer.addFeature(f)
    writer.close()
    layers.write_run_table({"drive": str(drive)})
    out.commit()
    result = run("signmapper:evaluate", {
        "SIGNS": f"{gpkg}|layername=signs", "REFERENCE": truth, "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 0.5, "REPORT": str(tmp_path / "r.html"), "STATISTICS": "memory:", "MATCHES": "memory:"})
    stats = stats_of(result)
    assert result["DETECTION_RATE"] == 1.0
    assert stats["height_mean"] == pytest.approx(0.1, abs=1e-6)
    assert stats["along_max"] == pytest.approx(0.0, abs=1e-6)


def test_modeler_chain_synthetic_drive_map_signs_evaluate(run, tmp_path):
    model = QgsProcessingModelAlgorithm("chain", "tests")
    static = QgsProcessingModelChildParameterSource.fromStaticValue
    sim = QgsProcessingModelChildAlgorithm("signmapper:syntheticdrive")
    sim.setChildId("sim")
    for name, value in {"PAIRS": 8, "SEED": 21, "WRITE_DEPTH": True, "WIDTH": 960, "HEIGHT": 540, "FX": 875.0,
                        "OUTPUT": str(tmp_path / "drive"), "TRUTH": "memory:"}.items():
        sim.addParameterSources(name, [static(value)])
    mapper = QgsProcessingModelChildAlgorithm("signmapper:mapsigns")
    mapper.setChildId("map")
    mapper.addParameterSources("DRIVE", [QgsProcessingModelChildParameterSource.fromChildOutput("sim", "OUTPUT")])
    mapper.addParameterSources("OUTPUT", [static(str(tmp_path / "signs.gpkg"))])
    ev = QgsProcessingModelChildAlgorithm("signmapper:evaluate")
    ev.setChildId("eval")
    ev.addParameterSources("SIGNS", [QgsProcessingModelChildParameterSource.fromChildOutput("map", "SIGNS")])
    ev.addParameterSources("REFERENCE", [QgsProcessingModelChildParameterSource.fromChildOutput("sim", "TRUTH")])
    ev.addParameterSources("REFERENCE_ID_FIELD", [static("template_id")])
    ev.addParameterSources("RADIUS", [static(0.5)])
    ev.addParameterSources("STATISTICS", [static("memory:")])
    ev.addParameterSources("MATCHES", [static("memory:")])
    report = QgsProcessingModelOutput("report", "Report")
    report.setChildId("eval")
    report.setChildOutputName("REPORT")
    ev.setModelOutputs({"report": report})
    for child in (sim, mapper, ev):
        model.addChildAlgorithm(child)
    model.updateDestinationParameters()
    result = run(model, {"eval:report": str(tmp_path / "report.html")})
    html = Path(result["eval:report"]).read_text()
    assert "Table 1" in html and "Detected signs" in html
    reference_row = html.split("Reference signs</td><td>")[1].split("<")[0]
    assert int(reference_row) == len(open_drive(tmp_path / "drive").truth)
    # for people: the drive by its folder, the figures first, each sign with its status, the settings last, folded
    drive = (tmp_path / "drive").resolve()
    assert "<h1>Sign Mapper: evaluation of drive drive</h1>" in html
    assert f"<td>drive</td><td>drive ({drive})</td>" in html
    order = [html.index(marker) for marker in ("Table 1", "Table 2", "<svg", "<h2>Mapped signs</h2>",
                                               "<h2>Missed reference signs", "<details>", "mapping: pipeline")]
    assert order == sorted(order)
    assert "<th>sign</th><th>status</th><th>mapped</th>" in html
    assert "<tr><td>sign 1</td><td>accepted</td>" in html or "<tr><td>sign 1</td><td>review</td>" in html
    assert html.index("</details>") > html.index("mapping: fusion")  # the dumps are inside the fold


def test_facing_as_text_radius_default_and_a_report_with_signs_missed_and_parameters(run, tmp_path):
    """The demo's truth layer (native:createpointslayerfromtable) stores facing as text."""
    reference = QgsVectorLayer("PointZ?crs=EPSG:2056&field=template_id:string&field=facing:string", "truth",
                               "memory")
    features = []
    for (_sid, tid, e, n, h), facing in zip(REF, ["270.0", "270", "270", " 270,0 "]):
        f = QgsFeature(reference.fields())
        f.setGeometry(QgsGeometry(QgsPoint(e, n, h)))
        f.setAttributes([tid, facing])
        features.append(f)
    reference.dataProvider().addFeatures(features)
    mapped = [(s, t, e + 0.6, n, h) for s, t, e, n, h in REF[:3]]  # 0.6 m off: within 0.75 m, not within 0.5
    mapped[1] = (mapped[1][0], "3.02", *mapped[1][2:])  # one misread
    from qgis.core import QgsApplication

    alg = QgsApplication.processingRegistry().algorithmById("signmapper:evaluate")
    assert alg.parameterDefinition("RADIUS").defaultValue() == 0.75
    params = {"SIGNS": point_layer(mapped, "mapped"), "REFERENCE": reference, "REFERENCE_ID_FIELD": "template_id",
              "REFERENCE_FACING_FIELD": "facing", "TRAJECTORY": eastward_trajectory(),
              "REPORT": str(tmp_path / "report.html"), "STATISTICS": "memory:", "MATCHES": "memory:"}
    result = run("signmapper:evaluate", params)  # RADIUS left at its default
    assert result["FALSE_POSITIVES"] == 0
    html = Path(result["REPORT"]).read_text()
    assert "<h2>Mapped signs</h2>" in html and html.count(">misclassified<") == 1 and html.count(">correct<") == 2
    # s4 is not mapped: the one missed sign
    assert "<h2>Missed reference signs (1)</h2>" in html and ">1.22<" in html
    assert "date of this evaluation" in html and "matching radius [m]</td><td>0.75" in html
    assert "facing field</td><td>facing" in html


def test_a_facing_that_is_no_number_names_the_feature(run, tmp_path):
    reference = QgsVectorLayer("PointZ?crs=EPSG:2056&field=template_id:string&field=facing:string", "truth",
                               "memory")
    f = QgsFeature(reference.fields())
    f.setGeometry(QgsGeometry(QgsPoint(2600010.0, 1200004.0, 402.0)))
    f.setAttributes(["2.01", "west"])
    reference.dataProvider().addFeatures([f])
    from qgis.core import QgsProcessingException

    with pytest.raises(QgsProcessingException, match="facing field 'facing' holds 'west', not an azimuth"):
        evaluate(run, tmp_path, point_layer(REF[:1], "mapped"), REFERENCE=reference, REFERENCE_FACING_FIELD="facing")


def test_table_2_in_the_log_labels_every_figure(run, tmp_path):
    from qgis.core import QgsProcessingFeedback

    class Recorder(QgsProcessingFeedback):
        def __init__(self):
            super().__init__()
            self.lines = []

        def pushInfo(self, info):  # noqa: N802
            self.lines.append(info)

    feedback = Recorder()
    import processing

    moved = [(s, t, e, n - 0.05, h) for s, t, e, n, h in REF]
    processing.run("signmapper:evaluate", {
        "SIGNS": point_layer(moved, "mapped"), "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD":
        "template_id", "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": "memory:", "MATCHES": "memory:"}, feedback=feedback)
    text = "\n".join(feedback.lines)
    assert "  across: n 4, mean 0.050, empirical σ 0.000, RMS 0.050, max |d| 0.050" in text


@pytest.mark.parametrize("temporary", ["TEMPORARY_OUTPUT", "memory:"])
def test_temporary_outputs_loaded_on_completion_are_only_layers_that_exist(run, tmp_path, temporary):
    """As the dialog and a model run it: temporary outputs to be loaded into the project. Every layer the run
    asks Processing to load must load (a stray 'memory:Matches' once ended a model run with a red error)."""
    from qgis.core import (
        QgsApplication,
        QgsProcessingContext,
        QgsProcessingFeedback,
        QgsProcessingOutputLayerDefinition,
        QgsProcessingUtils,
        QgsProject,
    )

    context = QgsProcessingContext()
    context.setProject(QgsProject.instance())
    params = {"SIGNS": point_layer(REF, "mapped"), "REFERENCE": point_layer(REF, "ref"),
              "REFERENCE_ID_FIELD": "template_id", "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(),
              "REPORT": str(tmp_path / "report.html"),
              "STATISTICS": QgsProcessingOutputLayerDefinition(temporary, QgsProject.instance()),
              "MATCHES": QgsProcessingOutputLayerDefinition(temporary, QgsProject.instance())}
    alg = QgsApplication.processingRegistry().createAlgorithmById("signmapper:evaluate")
    result, ok = alg.run(params, context, QgsProcessingFeedback())  # what the dialog runs; the layers stay
    assert ok
    to_load = context.layersToLoadOnCompletion()
    assert sorted(to_load) == sorted([result["STATISTICS"], result["MATCHES"]])
    for source in to_load:
        assert QgsProcessingUtils.mapLayerFromString(source, context) is not None, source
