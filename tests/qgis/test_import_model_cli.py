"""The shipped model ``models/import_and_map_signs.model3`` run by ``qgis_process.bin``: a raw survey (raw
convergent images, OpenCV calibration, 50 Hz WGS 84 trajectory of the IMU with lever arm and boresight) in,
the drive, its trajectory and the mapped signs out; signs where the truth puts them."""

from pathlib import Path

import numpy as np
import pytest
from drive_fixtures import SMALL_SYNTHETIC
from qgis.core import QgsApplication, QgsProcessingModelAlgorithm, QgsVectorLayer
from qgis_process_runner import enable_plugin, qgis_process_env, run_algorithm

from signmapper_core.drive.reader import open_drive

REPO = Path(__file__).resolve().parents[2]
MODEL = REPO / "models" / "import_and_map_signs.model3"


@pytest.fixture(scope="module")
def raw_survey(tmp_path_factory):
    from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive
    from signmapper_core.simulate.raw_survey import write_raw_survey

    base = tmp_path_factory.mktemp("model_survey")
    generate_drive(base / "drive", SimulationConfig(pairs=8, seed=11, **SMALL_SYNTHETIC, **DRAWABLE_SIGNS))
    return open_drive(base / "drive"), write_raw_survey(base / "drive", base / "survey")


def survey_parameters(survey) -> dict:
    rig = survey.rig
    return {"LEFT": survey.left, "RIGHT": survey.right, "CALIBRATION": survey.calibration,
            "POSES": survey.trajectory, "POSES_KIND": 1, "IMAGE_TIMES": survey.image_times, "ANGLES": 0,
            "ANGLE_UNIT": 0, "INPUT_CRS": "EPSG:4979", "OUTPUT_CRS": "EPSG:2056",
            "LEVER_X": rig.lever_arm_m[0], "LEVER_Y": rig.lever_arm_m[1], "LEVER_Z": rig.lever_arm_m[2],
            "BORESIGHT_HEADING": rig.boresight_deg[0], "BORESIGHT_PITCH": rig.boresight_deg[1],
            "BORESIGHT_ROLL": rig.boresight_deg[2]}


def test_the_model_chains_the_import_into_the_preview_and_the_mapping(registered_plugin):
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    registry = QgsApplication.processingRegistry()
    assert set(model.childAlgorithms()) == {"import", "trajectory", "map"}
    for child_id, child in model.childAlgorithms().items():
        ok, issues = model.validateChildAlgorithm(child_id)
        assert ok, (child_id, issues)
        assert registry.algorithmById(child.algorithmId()) is not None
    for child_id in ("trajectory", "map"):
        (drive_source,) = model.childAlgorithm(child_id).parameterSources()["DRIVE"]
        assert (drive_source.outputChildId(), drive_source.outputName()) == ("import", "OUTPUT")
    importer = registry.algorithmById("signmapper:importdrive")
    for definition in model.parameterDefinitions():
        if not definition.isDestination():
            assert importer.parameterDefinition(definition.name()) is not None, definition.name()


def test_qgis_process_runs_the_model_from_raw_survey_to_mapped_signs(plugin_dir, raw_survey, tmp_path):
    original, survey = raw_survey
    env = qgis_process_env(plugin_dir, tmp_path / "profile")
    enable_plugin(env)
    out = {"import:Drive folder": tmp_path / "drive", "import:Epipolar check image": tmp_path / "check.png",
           "trajectory:Trajectory": tmp_path / "trajectory.gpkg", "map:Signs GeoPackage": tmp_path / "signs.gpkg"}
    code, data, log = run_algorithm(env, str(MODEL), **survey_parameters(survey), **out)
    assert code == 0, log

    drive = open_drive(tmp_path / "drive")
    assert [p.id for p in drive.pairs] == [p.id for p in original.pairs]
    assert drive.crs == "EPSG:2056"
    assert drive.metadata["import"]["epipolar_check"]["mean_abs_vertical_disparity_px"] < 0.5
    assert (tmp_path / "check.png").stat().st_size > 0
    for imported, truth in zip(drive.pairs, original.pairs):
        assert np.linalg.norm(imported.pose.centre - truth.pose.centre) < 0.005

    trajectory = QgsVectorLayer(str(tmp_path / "trajectory.gpkg"), "t", "ogr")
    assert trajectory.featureCount() == len(original.pairs)
    first = next(trajectory.getFeatures()).geometry().constGet()
    assert np.allclose((first.x(), first.y(), first.z()), original.pairs[0].pose.centre, atol=0.005)

    signs = list(QgsVectorLayer(f"{tmp_path / 'signs.gpkg'}|layername=signs", "s", "ogr").getFeatures())
    assert sorted(s["template_id"] for s in signs) == sorted(t.template_id for t in original.truth)   # 2 signs
    for sign in signs:
        point = sign.geometry().constGet()
        position = np.array([point.x(), point.y(), point.z()])
        nearest = min(original.truth, key=lambda t: np.linalg.norm(position - t.position))
        assert sign["template_id"] == nearest.template_id
        assert np.linalg.norm(position - nearest.position) < 0.1
