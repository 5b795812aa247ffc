"""End to end through the command line: ``qgis_process.bin`` loads the plugin from a fresh profile."""

import subprocess

import pytest
from drive_fixtures import make_drive
from kitti_folder import make_kitti_drive
from qgis.core import QgsVectorLayer
from qgis_process_runner import QGIS_PROCESS, enable_plugin, qgis_process_env, run_algorithm

from signmapper_core.drive.reader import open_drive


@pytest.fixture(scope="module")
def cli_env(plugin_dir, tmp_path_factory):
    env = qgis_process_env(plugin_dir, tmp_path_factory.mktemp("profile"))
    enable_plugin(env)
    return env


def test_list_shows_the_provider(cli_env):
    result = subprocess.run([QGIS_PROCESS, "list"], env=cli_env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0
    assert "Sign Mapper" in result.stdout
    assert "signmapper:drivetrajectory" in result.stdout


def test_run_drive_trajectory(cli_env, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=4)
    out = tmp_path / "out.gpkg"
    code, data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive, OUTPUT=out)
    assert code == 0, log
    assert data["results"]["OUTPUT"].startswith(str(out))
    layer = QgsVectorLayer(str(out), "t", "ogr")
    assert layer.featureCount() == 4
    assert layer.crs().authid() == "EPSG:2056"


def test_invalid_drive_fails_with_the_message(cli_env, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    (drive / "left" / "000001.png").unlink()
    code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive, OUTPUT=tmp_path / "o.gpkg")
    assert code != 0
    assert "no left image left/000001" in log


def test_options_by_name_kitti_preset(cli_env, tmp_path):
    """QGIS 3.22's enum parameters take numbers only; the plugin's take their options' names too."""
    folder = make_kitti_drive(tmp_path / "kitti")
    code, data, log = run_algorithm(cli_env, "signmapper:importdrive", PRESET="kitti", KITTI_CAMERAS="Colour",
                                    KITTI_FOLDER=folder, OUTPUT=tmp_path / "drive")
    assert code == 0, log
    assert data["results"]["PAIRS"] == 3
    assert open_drive(tmp_path / "drive").metadata["import"]["source"].startswith("KITTI raw 2011_09_26_drive_0001")
    code, _data, log = run_algorithm(cli_env, "signmapper:importdrive", PRESET="kitty", KITTI_FOLDER=folder,
                                     OUTPUT=tmp_path / "other")
    assert code != 0 and not (tmp_path / "other").exists()
    assert ("PRESET (What to import): 'kitty' is not one of its options; give one of generic, kitti, or the option's "
            "number 0 to 1") in log
