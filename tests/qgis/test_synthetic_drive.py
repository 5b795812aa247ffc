"""``signmapper:syntheticdrive`` through processing.run: files, truth layer, bad folder, cancel."""

import pytest
from qgis.core import QgsProcessingException, QgsProcessingFeedback, QgsWkbTypes

from signmapper_core.drive import open_drive

SMALL = {"PAIRS": 4, "SEED": 5, "WIDTH": 480, "HEIGHT": 270, "FX": 437.5}


@pytest.fixture
def run(registered_plugin):
    import processing

    return processing.run


def test_writes_a_valid_drive_and_its_truth_layer(run, tmp_path):
    out = tmp_path / "drive"
    result = run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out), "TRUTH": "memory:"})
    drive = open_drive(result["OUTPUT"])
    assert len(drive.pairs) == 4 and drive.camera.width == 480 and drive.camera.fx == pytest.approx(437.5)
    assert drive.metadata["vehicle"]["camera_height_m"] == pytest.approx(2.4)
    truth = result["TRUTH"]
    assert truth.wkbType() == QgsWkbTypes.PointZ and truth.crs().authid() == "EPSG:2056"
    assert truth.featureCount() == len(drive.truth)
    first = next(truth.getFeatures())
    sign = next(s for s in drive.truth if s.sign_id == first["sign_id"])
    point = first.geometry().constGet()
    assert (point.x(), point.y(), point.z()) == pytest.approx((sign.easting, sign.northing, sign.height), abs=1e-3)


def test_non_empty_output_folder_is_a_clear_error(run, tmp_path):
    out = tmp_path / "busy"
    out.mkdir()
    (out / "something.txt").write_text("keep me")
    with pytest.raises(QgsProcessingException, match="Synthetic drive"):
        run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out)})
    assert (out / "something.txt").read_text() == "keep me"


def test_cancel_leaves_no_drive(run, tmp_path):
    out = tmp_path / "cancelled"
    feedback = QgsProcessingFeedback()
    feedback.progressChanged.connect(lambda p: feedback.cancel() if p > 30 else None)
    with pytest.raises(QgsProcessingException, match="Cancelled"):
        run("signmapper:syntheticdrive", {**SMALL, "PAIRS": 10, "OUTPUT": str(out)}, feedback=feedback)
    assert not out.exists() or not any(out.iterdir())
    assert not [p for p in tmp_path.iterdir() if p.name != "cancelled"]
