"""A synthetic drive recorded the way a vehicle records it (raw convergent images, OpenCV calibration, a 50 Hz
WGS 84 trajectory of the IMU with lever arm and boresight), imported again: same poses, same signs mapped."""

import cv2
import numpy as np
import pytest
from drive_fixtures import SMALL_SYNTHETIC

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.importdrive import (
    GenericInputs,
    ImportOptions,
    Orientation,
    generic_source,
    import_drive,
    match_features,
)
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive
from signmapper_core.simulate.raw_survey import write_raw_survey

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def drives(tmp_path_factory):
    base = tmp_path_factory.mktemp("raw_survey")
    generate_drive(base / "drive", SimulationConfig(pairs=8, seed=11, **SMALL_SYNTHETIC, **DRAWABLE_SIGNS))
    survey = write_raw_survey(base / "drive", base / "survey")
    original = open_drive(base / "drive")
    source = generic_source(GenericInputs(
        left=survey.left, right=survey.right, calibration=survey.calibration, poses=survey.trajectory,
        trajectory=True, image_times=survey.image_times, orientation=Orientation("ned_ypr", "deg"),
        input_crs="EPSG:4979", lever_arm_m=survey.rig.lever_arm_m, boresight_deg=survey.rig.boresight_deg))
    summary = import_drive(base / "imported", source, ImportOptions(output_crs=original.crs))
    return original, open_drive(base / "imported"), survey, summary


def test_the_survey_is_raw_and_the_import_lines_its_rows_up(drives):
    original, imported, survey, summary = drives
    first = original.pairs[0].id
    raw = match_features(cv2.imread(str(survey.left / f"{first}.jpg")), cv2.imread(str(survey.right / f"{first}.jpg")))
    assert raw.mean_abs_dy > 1.0
    assert summary.resampled and summary.check.enough and summary.check.mean_abs_dy < 0.5
    assert imported.camera.baseline_m == pytest.approx(original.camera.baseline_m, abs=1e-6)


def test_imported_poses_are_the_drives_poses(drives):
    original, imported, _, _ = drives
    assert [p.id for p in imported.pairs] == [p.id for p in original.pairs]
    for a, b in zip(original.pairs, imported.pairs):
        assert a.time == pytest.approx(b.time, abs=1e-3)
        assert np.linalg.norm(a.pose.centre - b.pose.centre) < 0.005
        turn = np.degrees(np.linalg.norm(cv2.Rodrigues(a.pose.rotation.T @ b.pose.rotation)[0]))
        assert turn < 0.03


def test_the_imported_drive_maps_the_same_signs_where_they_are(drives):
    original, imported, _, _ = drives
    catalogue = load_catalogue()
    before = map_drive(original, catalogue, PipelineConfig())
    after = map_drive(imported, catalogue, PipelineConfig())
    assert after.signs and sorted(s.template_id for s in after.signs) == sorted(s.template_id for s in before.signs)
    for sign in after.signs:
        nearest = min(original.truth, key=lambda t: np.linalg.norm(sign.position - t.position))
        assert nearest.template_id == sign.template_id
        assert np.linalg.norm(sign.position - nearest.position) < 0.1
