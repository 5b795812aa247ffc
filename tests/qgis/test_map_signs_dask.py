"""``signmapper:mapsigns`` with a *Dask scheduler address* (a LocalCluster of two worker processes on 127.0.0.1):
the same output as on this computer, cancel cancels the cluster's tasks, a bad address is said before the run;
and ``python -m signmapper_core.map`` writes the layers, fields, run table and crops mapsigns writes."""

import subprocess
import sys
import time

import distributed  # requirements-dask.txt, part of requirements-dev.txt
import pytest
from golden import differences, dump_gpkg
from gpkg_dump import REPO_ROOT
from gpkg_dump import dump_gpkg as dump_tables
from qgis.core import QgsProcessingException, QgsProcessingFeedback

GERMAN = 2  # LANGUAGE_CHOICES index of "de": the same names whatever the QGIS locale


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=":0") as local:
        yield local


def test_mapsigns_on_the_cluster_writes_the_same_geopackage_as_on_this_computer(run, small_drive, cluster,
                                                                               tmp_path):
    # the same file name in two folders: crops are written by default, their paths name the GeoPackage
    here, there = tmp_path / "here" / "signs.gpkg", tmp_path / "there" / "signs.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(here), "WORKERS": 1, "LANGUAGE": GERMAN})
    result = run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(there), "LANGUAGE": GERMAN,
                                         "SCHEDULER": cluster.scheduler_address})
    assert result["OUTPUT"] == str(there)
    expected = dump_gpkg(here, small_drive)
    assert len(expected["tables"]["signs"]["features"]) >= 2
    assert differences(expected, dump_gpkg(there, small_drive)) == []


def test_the_command_writes_the_layers_fields_run_table_and_crops_mapsigns_writes(run, small_drive, tmp_path):
    # the same file name in two folders: the crop_path fields name the crops folder after the GeoPackage
    from_qgis, from_command = tmp_path / "qgis" / "signs.gpkg", tmp_path / "command" / "signs.gpkg"
    from_qgis.parent.mkdir()
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(from_qgis), "WORKERS": 1,
                                "LANGUAGE": GERMAN, "CROPS": True})
    done = subprocess.run([sys.executable, "-m", "signmapper_core.map", str(small_drive), "--out", str(from_command),
                           "--workers", "1", "--language", "de", "--crops"], capture_output=True, text=True,
                          cwd=str(REPO_ROOT), timeout=300)
    assert done.returncode == 0, done.stderr
    crops = [{path.name: path.read_bytes() for path in (out.parent / "signs_crops").iterdir()}
             for out in (from_qgis, from_command)]
    assert len(crops[0]) >= 2 and crops[1] == crops[0]
    assert "crops in" in done.stdout and not list(from_command.parent.glob(".*partial*"))
    expected, written = dump_tables(from_qgis, small_drive), dump_tables(from_command, small_drive)
    # what only QGIS adds: the default styles it embeds (table layer_styles, registered in gpkg_contents)
    assert "layer_styles" in expected["sqlite_tables"] and "layer_styles" not in written["sqlite_tables"]
    expected["sqlite_tables"].remove("layer_styles")
    expected["tables"].pop("layer_styles")
    assert expected.pop("layer_styles") and not written.pop("layer_styles")
    assert expected["tables"]["signmapper_run"]["rows"]["drive"] == "<drive>"
    assert differences(expected, written) == []


def test_cancel_from_qgis_cancels_the_cluster_s_tasks(run, small_drive, cluster, tmp_path):
    out = tmp_path / "cancelled.gpkg"
    feedback = QgsProcessingFeedback()
    feedback.progressChanged.connect(lambda p: feedback.cancel() if p > 20 else None)
    with pytest.raises(QgsProcessingException, match="Cancelled; no output written"):
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out),
                                    "SCHEDULER": cluster.scheduler_address}, feedback=feedback)
    assert not out.exists()
    deadline = time.monotonic() + 10
    while cluster.scheduler.tasks and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not cluster.scheduler.tasks


def test_a_malformed_scheduler_address_is_refused_before_the_run(registered_plugin, small_drive, tmp_path):
    from qgis.core import QgsApplication, QgsProcessingContext

    algorithm = QgsApplication.processingRegistry().algorithmById("signmapper:mapsigns")
    ok, message = algorithm.checkParameterValues(
        {"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg"), "SCHEDULER": "my-scheduler"},
        QgsProcessingContext())
    assert not ok
    assert message.startswith("Dask scheduler address: Dask scheduler address 'my-scheduler': expected "
                              "tcp://HOST:PORT")
