"""``signmapper:evaluate`` with outputs naming inputs, numeric ids and nothing to compare (issue 11)."""

import hashlib

import pytest
from qgis.core import QgsProcessingException, QgsVectorLayer
from qgis_process_runner import enable_plugin, qgis_process_env, run_algorithm
from recorder import Recorder
from test_evaluate import REF, eastward_trajectory, point_layer


def digest(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture
def mapped_gpkg(run, small_drive, tmp_path):
    """(signs GeoPackage written by mapsigns, truth layer of the drive as a GeoPackage)."""
    signs = tmp_path / "signs.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(signs)})
    truth = tmp_path / "truth.gpkg"
    run("native:createpointslayerfromtable", {"INPUT": str(small_drive / "truth.csv"), "XFIELD": "easting",
                                              "YFIELD": "northing", "ZFIELD": "height", "TARGET_CRS": "EPSG:2056",
                                              "OUTPUT": str(truth)})
    return signs, truth


# 3. an output that names an input is refused before any work

@pytest.mark.parametrize("output, label", [("REPORT", "HTML report"), ("MATCHES", "Matches"),
                                           ("STATISTICS", "Statistics")])
def test_outputs_that_name_an_input_are_refused(run, mapped_gpkg, tmp_path, output, label):
    signs, truth = mapped_gpkg
    before = digest(signs)
    params = {"SIGNS": f"{signs}|layername=signs", "REFERENCE": str(truth), "REFERENCE_ID_FIELD": "template_id",
              "RADIUS": 0.75, "REPORT": str(tmp_path / "report.html"), "STATISTICS": "memory:",
              "MATCHES": "memory:", output: str(signs)}
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:evaluate", params)
    assert str(info.value).splitlines()[-1] == (f"{label}: {signs} is also the input 'Mapped signs'; writing it "
                                                "would destroy that input, choose another file")
    assert digest(signs) == before
    assert QgsVectorLayer(f"{signs}|layername=signs", "s", "ogr").featureCount() >= 2
    assert not (tmp_path / "report.html").exists()


def test_report_over_the_signs_is_refused_on_the_command_line(plugin_dir, mapped_gpkg, tmp_path):
    signs, truth = mapped_gpkg
    before = digest(signs)
    env = qgis_process_env(plugin_dir, tmp_path / "profile")
    enable_plugin(env)
    code, _data, log = run_algorithm(env, "signmapper:evaluate", SIGNS=f"{signs}|layername=signs", REFERENCE=truth,
                                     REFERENCE_ID_FIELD="template_id", RADIUS=0.75, REPORT=signs,
                                     STATISTICS=tmp_path / "stats.gpkg", MATCHES=tmp_path / "matches.gpkg")
    assert code != 0
    assert f"HTML report: {signs} is also the input 'Mapped signs'" in log
    assert digest(signs) == before


def test_reference_of_the_same_file_as_an_output_is_refused(run, tmp_path):
    reference = tmp_path / "reference.gpkg"
    run("native:savefeatures", {"INPUT": point_layer(REF, "ref"), "OUTPUT": str(reference)})
    before = digest(reference)
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:evaluate", {"SIGNS": point_layer(REF, "mapped"), "REFERENCE": str(reference),
                                    "REFERENCE_ID_FIELD": "template_id", "RADIUS": 1.0,
                                    "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
                                    "STATISTICS": str(reference), "MATCHES": "memory:"})
    assert "Statistics: " in str(info.value) and "is also the input 'Reference signs'" in str(info.value)
    assert digest(reference) == before


# 10. catalogue ids are text, also when QGIS typed the reference field as a number

def test_numeric_reference_ids_are_read_back_as_catalogue_ids(run, tmp_path):
    rows = [("s1", "1.30", 2600010.0, 1200004.0, 402.0), ("s2", "2.01", 2600020.0, 1199996.0, 402.5)]
    csv = tmp_path / "truth.csv"
    csv.write_text("sign_id,template_id,easting,northing,height\n"
                   + "".join(f"{s},{t},{e},{n},{h}\n" for s, t, e, n, h in rows))
    # the delimited-text defaults detect field types: every id here looks like a number
    reference = QgsVectorLayer(f"file://{csv}?delimiter=,&xField=easting&yField=northing&zField=height"
                               "&crs=EPSG:2056", "truth", "delimitedtext")
    assert reference.isValid() and reference.fields().field("template_id").isNumeric()
    feedback = Recorder()
    result = run("signmapper:evaluate", {
        "SIGNS": point_layer(rows, "mapped"), "REFERENCE": reference, "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": "memory:", "MATCHES": "memory:"}, feedback=feedback)
    assert result["DETECTION_RATE"] == 1.0 and result["CLASSIFICATION_RATE"] == 1.0
    assert ("Reference field 'template_id' is numeric (double), but sign types are catalogue ids compared as text "
            "('1.30' is not '1.3')") in feedback.text()
    assert "(e.g. 1.3 as 1.30)" in feedback.text()
    assert {f["reference_id"] for f in result["MATCHES"].getFeatures()} == {"1.30", "2.01"}


def test_help_says_ids_are_compared_as_text(registered_plugin):
    from qgis.core import QgsApplication

    help_text = QgsApplication.processingRegistry().algorithmById("signmapper:evaluate").shortHelpString()
    assert "catalogue ids compared as text: '1.30' is not '1.3'" in help_text


# 12. nothing to compare is said in words, never "nan %"

def test_no_mapped_signs_says_so(run, tmp_path):
    feedback = Recorder()
    result = run("signmapper:evaluate", {
        "SIGNS": point_layer([], "mapped"), "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": "memory:", "MATCHES": "memory:"}, feedback=feedback)
    log = feedback.text()
    assert "No mapped signs: every reference sign counts as missed." in log
    assert "detected signs                  0 of 4 (0.0 %)" in log
    assert "correctly classified signs      0 (no sign detected)" in log
    assert "mapped features                 0 (no mapped signs)" in log
    assert "no mapped sign matches a reference sign: no coordinate differences" in log
    html = (tmp_path / "r.html").read_text()
    assert "nan" not in log.lower() and "nan" not in html.lower()
    assert "0 (no mapped signs)" in html
    assert result["DETECTION_RATE"] == 0.0


def test_no_match_says_0_of_n(run, tmp_path):
    far = [(s, t, e + 50.0, n, h) for s, t, e, n, h in REF]
    feedback = Recorder()
    run("signmapper:evaluate", {
        "SIGNS": point_layer(far, "mapped"), "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": "memory:", "MATCHES": "memory:"}, feedback=feedback)
    log = feedback.text()
    assert "detected signs                  0 of 4 (0.0 %)" in log
    assert "false positive features         4" in log
    assert "nan" not in log.lower() and "nan" not in (tmp_path / "r.html").read_text().lower()


# 9. a cancel is a cancel

def test_cancel_writes_nothing(run, tmp_path):
    class CancelAtTables(Recorder):
        def pushInfo(self, info):  # noqa: N802
            super().pushInfo(info)
            if info.startswith("Table 1"):
                self.cancel()

    report, statistics = tmp_path / "r.html", tmp_path / "stats.gpkg"
    with pytest.raises(QgsProcessingException, match="Cancelled; nothing written"):
        run("signmapper:evaluate", {
            "SIGNS": point_layer(REF, "mapped"), "REFERENCE": point_layer(REF, "ref"),
            "REFERENCE_ID_FIELD": "template_id", "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(),
            "REPORT": str(report), "STATISTICS": str(statistics), "MATCHES": "memory:"}, feedback=CancelAtTables())
    assert not report.exists() and not statistics.exists()
