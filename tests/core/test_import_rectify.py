"""Epipolar rectification of a rendered convergent pair, the rows check, and the calibration files."""

import json
from pathlib import Path

import cv2
import numpy as np
import pytest
from stereo_scenes import convergent_rig, relative_pose, wall_scene

from signmapper_core.errors import ImportInputError
from signmapper_core.importdrive.calibration import (
    StereoCalibration,
    check_calibration,
    choose_calibration,
    read_calibrations,
)
from signmapper_core.importdrive.epipolar import draw_check, match_features
from signmapper_core.importdrive.rectify import Rectifier


@pytest.fixture(scope="module")
def rig():
    """A toed-in rig (1.5 degrees each way, different lenses and distortions) and its raw pair of two walls."""
    left, right = convergent_rig(size=(640, 480), baseline=0.5, toe_in_deg=1.5)
    scene = wall_scene()
    r, t = relative_pose(left, right)
    calibration = check_calibration(StereoCalibration("test rig", Path("rig.yml"), left.size, left.k, left.d, right.k,
                                                      right.d, r, t, False))
    return left, right, scene, calibration, scene.render(left), scene.render(right)


def test_raw_rows_do_not_line_up_and_rectified_rows_do(rig):
    _, _, _, calibration, raw_left, raw_right = rig
    raw = match_features(raw_left, raw_right)
    assert raw.enough and raw.mean_abs_dy > 2.0     # toe-in and distortion: rows several pixels apart
    rectifier = Rectifier(calibration, calibration.size)
    normal = match_features(*rectifier.rectify(raw_left, raw_right))
    assert normal.matches > 500
    assert normal.mean_abs_dy < 0.1 and abs(normal.mean_dy) < 0.05


def test_rectified_pair_gives_the_known_disparity_of_every_point(rig):
    """Each matched point's true position comes from the scene: its disparity in the normal images must agree."""
    left, _, scene, calibration, raw_left, raw_right = rig
    rectifier = Rectifier(calibration, calibration.size)
    cam = rectifier.camera
    assert cam.baseline_m == pytest.approx(0.5, abs=0.002)   # the rig's camera distance (with its 1 cm offsets)
    matches = match_features(*rectifier.rectify(raw_left, raw_right))
    xl, yl = matches.left.T
    rays = np.column_stack([(xl - cam.cx) / cam.fx, (yl - cam.cy) / cam.fy, np.ones_like(xl)])
    world = rays @ rectifier.rotation @ left.rotation.T          # rectified -> raw left -> world
    points, plane = scene.hits(left.centre, world)
    in_rect = (points - left.centre) @ left.rotation @ rectifier.rotation.T
    true_disparity = cam.fx * cam.baseline_m / in_rect[:, 2]
    true_xr = xl - true_disparity
    error = np.abs(matches.right[:, 0] - true_xr)
    assert set(np.unique(plane)) == {0, 1}                        # points on both walls, 5.5 to 12 m away
    assert true_disparity.min() < 25 < 40 < true_disparity.max()
    assert np.median(error) < 0.1
    assert np.mean(error < 0.3) > 0.97, f"{np.mean(error < 0.3):.3f} of {len(error)} points within 0.3 px"


def test_rows_shifted_by_two_pixels_are_measured(rig):
    _, _, _, calibration, raw_left, raw_right = rig
    left, right = Rectifier(calibration, calibration.size).rectify(raw_left, raw_right)
    shifted = cv2.warpAffine(right, np.float32([[1, 0, 0], [0, 1, 2.0]]), (right.shape[1], right.shape[0]))
    check = match_features(left, shifted)
    assert check.mean_abs_dy == pytest.approx(2.0, abs=0.1) and check.mean_dy == pytest.approx(2.0, abs=0.1)
    picture = draw_check(left, shifted, check)
    assert picture.shape == (left.shape[0], 2 * left.shape[1], 3)


def test_normal_images_pass_through_untouched(tmp_path):
    calibration = read_calibrations(_write(tmp_path / "cam.json",
                                           {"fx": 700, "fy": 700, "cx": 320, "cy": 240, "baseline_m": 0.54,
                                            "width": 640, "height": 480}))[0]
    rectifier = Rectifier(calibration, (640, 480))
    image = np.zeros((480, 640, 3), np.uint8)
    left, right = rectifier.rectify(image, image)
    assert left is image and right is image and not rectifier.resamples
    assert (rectifier.camera.fx, rectifier.camera.cx, rectifier.camera.baseline_m) == (700, 320, 0.54)


def test_swapped_cameras_are_refused(rig):
    left, right, _, calibration, _, _ = rig
    r, t = relative_pose(right, left)
    with pytest.raises(ImportInputError, match="swap"):
        check_calibration(StereoCalibration("swapped", Path("rig.yml"), left.size, right.k, right.d, left.k, left.d,
                                            r, t, False))


# -- calibration files --------------------------------------------------------------------------------------------

def _write(path: Path, data) -> Path:
    path.write_text(json.dumps(data) if isinstance(data, dict) else data)
    return path


def _opencv_yaml(path: Path, calibration: StereoCalibration, scale: float = 1.0) -> Path:
    storage = cv2.FileStorage(str(path), cv2.FILE_STORAGE_WRITE)
    for key, value in (("K1", calibration.k1), ("D1", calibration.d1), ("M2", calibration.k2),
                       ("D2", calibration.d2), ("R", calibration.rotation), ("T", calibration.translation * scale)):
        storage.write(key, value)
    storage.write("image_size", np.array([calibration.size]))
    storage.release()
    return path


def test_opencv_yaml_and_json_give_the_same_calibration(rig, tmp_path):
    *_, calibration, _, _ = rig
    from_yaml = read_calibrations(_opencv_yaml(tmp_path / "stereo.yml", calibration))[0]
    as_json = {"K1": calibration.k1.tolist(), "D1": calibration.d1.tolist(), "K2": calibration.k2.ravel().tolist(),
               "D2": calibration.d2.tolist(), "R": {"type_id": "opencv-matrix", "rows": 3, "cols": 3,
                                                    "data": calibration.rotation.ravel().tolist()},
               "T": calibration.translation.tolist(), "image_width": 640, "image_height": 480}
    from_json = read_calibrations(_write(tmp_path / "stereo.json", as_json))[0]
    for found in (from_yaml, from_json):
        assert found.size == (640, 480) and not found.rectified
        for a, b in ((found.k1, calibration.k1), (found.d2, calibration.d2), (found.rotation, calibration.rotation),
                     (found.translation, calibration.translation)):
            assert a == pytest.approx(b)


def test_calibration_errors_name_the_file_and_key(rig, tmp_path):
    *_, calibration, _, _ = rig
    with pytest.raises(ImportInputError, match=r"stereo\.json, field 'D1': required key is missing"):
        read_calibrations(_write(tmp_path / "stereo.json", {"K1": np.eye(3).tolist()}))
    with pytest.raises(ImportInputError, match="millimetres"):
        read_calibrations(_opencv_yaml(tmp_path / "mm.yml", calibration, scale=1000.0))
    with pytest.raises(ImportInputError, match="%YAML:1.0"):
        read_calibrations(_write(tmp_path / "plain.yaml", "K1: [1, 0, 0]\n"))
    with pytest.raises(ImportInputError, match="does not exist"):
        read_calibrations(tmp_path / "missing.yml")
    with pytest.raises(ImportInputError, match="baseline_m"):
        read_calibrations(_write(tmp_path / "cam.json", {"fx": 700, "fy": 700, "cx": 320, "cy": 240}))


def test_a_calibration_for_other_images_names_both_sizes(rig, tmp_path):
    *_, calibration, _, _ = rig
    found = read_calibrations(_opencv_yaml(tmp_path / "stereo.yml", calibration))
    with pytest.raises(ImportInputError, match=r"640x480 .*left/0001\.png is 1280x960"):
        choose_calibration(found, (1280, 960), Path("left/0001.png"))


KITTI_CAM_TO_CAM = """calib_time: 01-Jan-2026 12:00:00
corner_dist: 9.950000e-02
S_02: 1.392000e+03 5.120000e+02
K_02: 9.6e+02 0 6.9e+02 0 9.55e+02 2.4e+02 0 0 1
D_02: -3.7e-01 2.0e-01 4.0e-04 1.6e-03 -7.0e-02
R_02: 1 0 0 0 1 0 0 0 1
T_02: 6.0e-02 -1.0e-03 4.0e-03
S_rect_02: 1.242000e+03 3.750000e+02
R_rect_02: 1 0 0 0 1 0 0 0 1
P_rect_02: 7.2e+02 0 6.1e+02 4.32e+01 0 7.2e+02 1.73e+02 0 0 0 1 0
S_03: 1.392000e+03 5.120000e+02
K_03: 9.0e+02 0 7.0e+02 0 9.0e+02 2.4e+02 0 0 1
D_03: -3.6e-01 1.9e-01 -5.0e-04 3.0e-04 -6.0e-02
R_03: 9.9995e-01 1.0e-02 0 -1.0e-02 9.9995e-01 0 0 0 1
T_03: -4.76e-01 5.0e-03 -5.0e-03
S_rect_03: 1.242000e+03 3.750000e+02
P_rect_03: 7.2e+02 0 6.1e+02 -3.384e+02 0 7.2e+02 1.73e+02 0 0 0 1 0
"""


def test_kitti_calibration_gives_the_rectified_and_the_raw_cameras(tmp_path):
    path = _write(tmp_path / "calib_cam_to_cam.txt", KITTI_CAM_TO_CAM)
    rectified, raw = read_calibrations(path)
    assert rectified.rectified and rectified.size == (1242, 375)
    assert rectified.baseline_m == pytest.approx((43.2 + 338.4) / 720)     # P_rect: fx * t_x of each camera
    assert rectified.k1[0, 2] == pytest.approx(610)
    assert not raw.rectified and raw.size == (1392, 512)
    assert raw.translation[0] == pytest.approx(-0.476 - 0.06, abs=0.002)   # camera 3 seen from camera 2
    assert choose_calibration([rectified, raw], (1392, 512), Path("x.png")) is raw
    assert choose_calibration([rectified, raw], (1242, 375), Path("x.png")) is rectified


def test_a_text_file_that_is_no_kitti_calibration_is_refused(tmp_path):
    with pytest.raises(ImportInputError, match="not a KITTI calib_cam_to_cam.txt"):
        read_calibrations(_write(tmp_path / "calib.txt", "K: 1 2 3\n"))
