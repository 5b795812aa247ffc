"""``signmapper:syntheticdrive`` through processing.run: files, truth layer, bad folder, cancel."""

import pytest
from qgis.core import QgsProcessingException, QgsProcessingFeedback, QgsWkbTypes

from signmapper_core.drive.reader import open_drive

SMALL = {"PAIRS": 4, "SEED": 5, "WIDTH": 480, "HEIGHT": 270, "FX": 437.5}


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


def test_killed_run_leaves_no_partial_folder_behind(run, tmp_path):
    import os
    import signal
    import subprocess
    import sys
    import time
    from pathlib import Path

    out = tmp_path / "drive"
    repo = Path(__file__).resolve().parents[2]
    process = subprocess.Popen([sys.executable, "-m", "signmapper_core.simulate", str(out), "--pairs", "200",
                                "--width", "480", "--height", "270", "--fx", "437.5", "--quiet"], cwd=repo)
    partial = tmp_path / ".drive.signmapper-partial"
    deadline = time.monotonic() + 120
    while not (partial / "left").is_dir() and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.1)
    os.kill(process.pid, signal.SIGKILL)  # as the operating system kills a run (out of memory, logout)
    process.wait()
    assert partial.is_dir() and (tmp_path / ".drive.signmapper-lock").is_file() and not out.exists()
    result = run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out)})
    assert open_drive(result["OUTPUT"]).pairs
    assert [p.name for p in tmp_path.iterdir()] == ["drive"]


def test_failing_truth_output_leaves_no_drive(run, tmp_path):
    out = tmp_path / "drive"
    truth = tmp_path / "missing-folder" / "deeper" / "truth.gpkg"
    truth.parent.parent.write_text("a file where the truth's folder should be")
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out), "TRUTH": str(truth)})
    assert "Ground truth signs: " in str(info.value) and "is a file, not a folder" in str(info.value)
    assert not out.exists()
    # the identical run with a truth file that can be written is not refused
    result = run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out), "TRUTH": str(tmp_path / "truth.gpkg")})
    assert open_drive(result["OUTPUT"]).truth


def test_truth_failing_while_written_leaves_no_drive(run, tmp_path, monkeypatch):
    from sign_mapper.algorithms import synthetic_drive

    def broken(self, signs):
        raise QgsProcessingException(f"{self.dest}: cannot write the ground truth signs")

    monkeypatch.setattr(synthetic_drive.TruthLayer, "write", broken)
    out, truth = tmp_path / "drive", tmp_path / "truth.gpkg"
    with pytest.raises(QgsProcessingException, match="cannot write the ground truth signs"):
        run("signmapper:syntheticdrive", {**SMALL, "OUTPUT": str(out), "TRUTH": str(truth)})
    assert not out.exists() and not truth.exists()
    assert not list(tmp_path.iterdir())
