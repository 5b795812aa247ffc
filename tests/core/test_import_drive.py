"""Whole imports: a rendered survey (raw convergent pairs, WGS 84 trajectory) and a tiny KITTI drive, checked
against poses computed independently in the tests; failures and cancels leave nothing behind."""

import csv
import dataclasses
import json

import cv2
import numpy as np
import pytest
from import_scenarios import BORESIGHT, LEVER_ARM, ORIGIN, make_survey
from kitti_folder import (
    FRAME_S,
    OXTS,
    R_IMU_TO_VELO,
    R_RECT_00,
    R_VELO_TO_CAM,
    T2,
    T_IMU_TO_VELO,
    T_VELO_TO_CAM,
    make_kitti_drive,
)
from pyproj import Transformer

from signmapper_core.drive.reader import open_drive
from signmapper_core.errors import ImportInputError
from signmapper_core.geometry import pixel_to_world
from signmapper_core.importdrive import (
    GenericInputs,
    ImportOptions,
    Orientation,
    generic_source,
    import_drive,
    kitti_source,
    match_features,
    utm_crs,
)
from signmapper_core.importdrive.consistency import static_point_spread
from signmapper_core.progress import Cancelled


@pytest.fixture(scope="module")
def survey(tmp_path_factory):
    return make_survey(tmp_path_factory.mktemp("survey"), pairs=3)


def trajectory_inputs(survey, **changes):
    values = dict(left=survey.left, right=survey.right, calibration=survey.calibration, poses=survey.trajectory,
                  trajectory=True, image_times=survey.image_times, orientation=Orientation("ned_ypr", "deg", "auto"),
                  input_crs="EPSG:4979", lever_arm_m=LEVER_ARM, boresight_deg=BORESIGHT)
    values.update(changes)
    return GenericInputs(**values)


@pytest.fixture(scope="module")
def imported(survey, tmp_path_factory):
    out = tmp_path_factory.mktemp("imported") / "drive"
    warnings = []
    summary = import_drive(out, generic_source(trajectory_inputs(survey)),
                           ImportOptions(output_crs="EPSG:2056", check_image=out.parent / "check.png"),
                           warn=warnings.append)
    return summary, open_drive(out), warnings


def rectifying_rotation(survey):
    """OpenCV's rectification of the survey's calibration, computed here from the file."""
    storage = cv2.FileStorage(str(survey.calibration), cv2.FILE_STORAGE_READ)
    m = {k: storage.getNode(k).mat() for k in ("K1", "D1", "K2", "D2", "R", "T")}
    size = (int(storage.getNode("image_width").real()), int(storage.getNode("image_height").real()))
    r1, *_ = cv2.stereoRectify(m["K1"], m["D1"], m["K2"], m["D2"], size, m["R"], m["T"],
                               flags=cv2.CALIB_ZERO_DISPARITY, alpha=0)
    return r1


def rotation_difference_deg(a, b):
    return np.degrees(np.linalg.norm(cv2.Rodrigues(a.T @ b)[0]))


def test_trajectory_import_gives_the_true_camera_poses(survey, imported):
    summary, drive, _ = imported
    r1 = rectifying_rotation(survey)
    assert [p.id for p in drive.pairs] == ["img_000", "img_001", "img_002"]
    assert [p.time for p in drive.pairs] == pytest.approx([1000.125, 1000.375, 1000.625])
    for record, centre, raw_rotation in zip(drive.pairs, survey.camera_centres, survey.camera_rotations):
        assert record.pose.centre == pytest.approx(centre, abs=2e-3)
        assert rotation_difference_deg(record.pose.rotation, raw_rotation @ r1.T) < 0.005
    assert summary.resampled and drive.camera.baseline_m == pytest.approx(0.5, abs=0.002)


def test_imported_pairs_map_the_walls_where_they_are(survey, imported):
    """Features of every imported pair, placed by the drive's camera, pose and their disparity, lie on the walls."""
    _, drive, _ = imported
    for record in drive.pairs:
        matches = match_features(drive.load_left(record), drive.load_right(record))
        depth = drive.camera.depth_from_disparity(matches.left[:, 0] - matches.right[:, 0])
        world = pixel_to_world(drive.camera, record.pose, matches.left[:, 0], matches.left[:, 1], depth) - ORIGIN
        distance = np.min([np.abs(world @ np.asarray(p.normal) - p.offset) for p in survey.scene.planes], axis=0)
        assert matches.matches > 500
        assert np.median(distance) < 0.02, f"{record.id}: median {np.median(distance):.3f} m off the walls"


def test_the_drive_records_its_import_and_the_rows_check(imported):
    summary, drive, warnings = imported
    record = drive.metadata["import"]
    assert record["angle_convention"] == "ned_ypr" and record["poses_kind"] == "trajectory"
    assert record["rectified_by_import"] is True and record["lever_arm_m"] == pytest.approx(list(LEVER_ARM))
    assert record["epipolar_check"]["matches"] > 500
    assert record["epipolar_check"]["mean_abs_vertical_disparity_px"] < 0.1
    assert summary.check.mean_abs_dy < 0.1
    check = cv2.imread(str(drive.root.parent / "check.png"))
    assert check.shape == (360, 960, 3)
    assert any("heights are copied" in w for w in warnings)   # LV95 without heights: WGS 84 heights kept, said so


def test_static_points_map_to_one_place_from_every_pair_and_a_pose_error_shows(imported):
    _, drive, _ = imported
    right = static_point_spread(drive, 0, 3)
    assert len(right.positions) > 100 and right.pairs == ["img_000", "img_001", "img_002"]
    assert np.median(right.spread_3d) < 0.02
    turned = dataclasses.replace(drive.pairs[1], pose=dataclasses.replace(drive.pairs[1].pose,
                                                                          heading=drive.pairs[1].pose.heading + 0.3))
    wrong = dataclasses.replace(drive, pairs=[drive.pairs[0], turned, drive.pairs[2]])
    assert np.median(static_point_spread(wrong, 0, 3).spread_3d) > 2 * np.median(right.spread_3d)


def opk_of(rotation):
    """omega, phi, kappa (degrees) of a drive-camera -> world rotation: R_opk = R diag(1, -1, -1) = Rx Ry Rz."""
    r = rotation @ np.diag([1.0, -1.0, -1.0])
    return (np.degrees(np.arctan2(-r[1, 2], r[2, 2])), np.degrees(np.arcsin(r[0, 2])),
            np.degrees(np.arctan2(-r[0, 1], r[0, 0])))


def test_photogrammetric_exterior_orientation_in_lv95_gives_the_same_drive(survey, imported, tmp_path):
    """The raw left cameras' true omega/phi/kappa per image (grid north, LV95) instead of the trajectory."""
    _, trajectory_drive, _ = imported
    eo = tmp_path / "eo.csv"
    with open(eo, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["image", "easting", "northing", "height", "omega", "phi", "kappa"])
        for i, (centre, rotation) in enumerate(zip(survey.camera_centres, survey.camera_rotations)):
            writer.writerow([f"img_{i:03d}.png", *(f"{v:.5f}" for v in centre), *(f"{a:.7f}" for a in
                                                                                 opk_of(rotation))])
    inputs = trajectory_inputs(survey, poses=eo, trajectory=False, orientation=Orientation("opk", "deg", "auto"),
                               input_crs="EPSG:2056", lever_arm_m=(0, 0, 0), boresight_deg=(0, 0, 0))
    import_drive(tmp_path / "drive", generic_source(inputs), ImportOptions(output_crs="EPSG:2056"))
    drive = open_drive(tmp_path / "drive")
    for a, b in zip(drive.pairs, trajectory_drive.pairs):
        assert a.id == b.id and a.time == pytest.approx(b.time)
        assert a.pose.centre == pytest.approx(b.pose.centre, abs=2e-3)
        assert rotation_difference_deg(a.pose.rotation, b.pose.rotation) < 0.005


def leaves_nothing(folder):
    return not any(p.name.startswith(".drive") or p.name == "drive" for p in folder.iterdir())


def test_a_calibration_for_another_image_size_is_refused_before_any_work(survey, tmp_path):
    storage = cv2.FileStorage(str(survey.calibration), cv2.FILE_STORAGE_READ)
    values = {k: storage.getNode(k).mat() for k in ("K1", "D1", "K2", "D2", "R", "T")}
    other = tmp_path / "other.yml"
    out = cv2.FileStorage(str(other), cv2.FILE_STORAGE_WRITE)
    for key, value in values.items():
        out.write(key, value)
    out.write("image_size", np.array([[640, 480]]))
    out.release()
    with pytest.raises(ImportInputError, match=r"other\.yml: the calibration is for images of 640x480 .* is 480x360"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey, calibration=other)))
    assert leaves_nothing(tmp_path)


def test_images_the_trajectory_does_not_cover_are_named(survey, tmp_path):
    times = tmp_path / "times.csv"
    times.write_text("id,time\nimg_000,1000.125\nimg_001,1000.375\nimg_002,1003.0\n")
    with pytest.raises(ImportInputError, match=r"do not cover image 'img_002' at time 1003\.000 s"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey, image_times=times)))
    assert leaves_nothing(tmp_path)


def test_radians_given_as_degrees_are_refused(survey, tmp_path):
    radians = tmp_path / "trajectory_rad.csv"
    rows = list(csv.reader(open(survey.trajectory)))
    with open(radians, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(rows[0])
        for row in rows[1:]:
            writer.writerow(row[:4] + [f"{np.radians(float(v)):.9f}" for v in row[4:]])
    with pytest.raises(ImportInputError, match="radians given as degrees"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey, poses=radians)))
    summary = import_drive(tmp_path / "ok", generic_source(trajectory_inputs(
        survey, poses=radians, orientation=Orientation("ned_ypr", "rad", "auto"))))
    assert summary.pairs == 3



def test_navigation_angles_in_the_wrong_frame_are_refused_naming_the_right_one(survey, tmp_path):
    """NED yaw/pitch/roll (heading 60 degrees) read as ENU: the vehicle would face 30 degrees, off its track."""
    with pytest.raises(ImportInputError, match=r"trajectory\.csv, line \d+, field 'yaw': the forward direction of the "
                                               r"enu_ypr angles differs from the direction of travel by 30 degrees "
                                               r".*set the angle convention to ned_ypr$"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(
            survey, orientation=Orientation("enu_ypr", "deg", "auto"))))
    assert leaves_nothing(tmp_path)

def test_an_output_crs_in_feet_is_refused(survey, tmp_path):
    with pytest.raises(ImportInputError, match="not metres"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey)),
                     ImportOptions(output_crs="EPSG:2229"))
    assert leaves_nothing(tmp_path)


def test_a_calibration_that_does_not_fit_fails_the_rows_check(survey, tmp_path):
    storage = cv2.FileStorage(str(survey.calibration), cv2.FILE_STORAGE_READ)
    values = {k: storage.getNode(k).mat() for k in ("K1", "D1", "K2", "D2", "R", "T")}
    values["R"] = cv2.Rodrigues(np.array([np.radians(0.4), 0.0, 0.0]))[0] @ values["R"]   # rig moved 0.4 deg
    wrong = tmp_path / "moved.yml"
    out = cv2.FileStorage(str(wrong), cv2.FILE_STORAGE_WRITE)
    for key, value in values.items():
        out.write(key, value)
    out.release()
    with pytest.raises(ImportInputError, match=r"moved\.yml: the rows of the first pair \(img_000\) do not line up"):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey, calibration=wrong)))
    assert leaves_nothing(tmp_path)


def test_cancel_leaves_nothing(survey, tmp_path):
    calls = []

    def cancel_after_first_pair():
        calls.append(1)
        return len(calls) > 2

    with pytest.raises(Cancelled):
        import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey)),
                     is_cancelled=cancel_after_first_pair)
    assert leaves_nothing(tmp_path)


def test_a_non_empty_output_folder_is_kept(survey, tmp_path):
    out = tmp_path / "drive"
    out.mkdir()
    (out / "keep.txt").write_text("mine")
    with pytest.raises(FileExistsError):
        import_drive(out, generic_source(trajectory_inputs(survey)))
    assert (out / "keep.txt").read_text() == "mine"


# -- KITTI --------------------------------------------------------------------------------------------------------

def rz(a):
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def ry(a):
    return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])


def rx(a):
    return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])


def expected_kitti_poses():
    """Rectified camera 2 per frame, as KITTI's development kit chains it, in UTM 32N with EGM96 heights."""
    a = R_RECT_00 @ R_VELO_TO_CAM @ R_IMU_TO_VELO
    b = R_RECT_00 @ (R_VELO_TO_CAM @ T_IMU_TO_VELO + T_VELO_TO_CAM) + T2
    to_utm = Transformer.from_crs("EPSG:4326", "EPSG:32632", always_xy=True)
    out = []
    for lat, lon, alt, roll, pitch, yaw in OXTS:
        e0, n0 = to_utm.transform(lon, lat)
        e1, n1 = to_utm.transform(lon, lat + 1e-6)
        north = np.arctan2(e1 - e0, n1 - n0)                   # grid azimuth of true north
        imu_to_grid = rz(-north) @ rz(yaw) @ ry(pitch) @ rx(roll)
        centre = np.array([e0, n0, alt]) + imu_to_grid @ (-a.T @ b)
        r = imu_to_grid @ a.T                                   # camera (x right, y down, z forward) -> grid
        heading = np.degrees(np.arctan2(r[0, 2], r[1, 2])) % 360
        tilt = np.arcsin(r[2, 2])
        out.append((centre, heading, np.degrees(tilt), np.degrees(np.arcsin(-r[2, 0] / np.cos(tilt)))))
    return out


def test_kitti_preset_matches_the_development_kit_chain(tmp_path):
    folder = make_kitti_drive(tmp_path / "kitti")
    source = kitti_source(folder)
    assert utm_crs(source) == "EPSG:32632+5773"
    summary = import_drive(tmp_path / "drive", source, ImportOptions(output_crs=utm_crs(source)))
    drive = open_drive(tmp_path / "drive")
    assert [p.id for p in drive.pairs] == ["0000000000", "0000000001", "0000000002"]
    assert [p.time for p in drive.pairs] == pytest.approx([0.0, FRAME_S, 2 * FRAME_S], abs=1e-3)
    assert drive.metadata["start_time"] == "2011-09-26T13:02:25.964389"
    assert drive.metadata["vehicle"]["camera_height_m"] == 1.65
    assert (drive.camera.fx, drive.camera.cx, drive.camera.cy) == (721.5, 609.6, 172.9)
    assert drive.camera.baseline_m == pytest.approx(T2[0] - (-0.4731), abs=1e-9)
    assert not summary.resampled and summary.check.mean_abs_dy < 0.05
    for record, (centre, heading, pitch, roll) in zip(drive.pairs, expected_kitti_poses()):
        assert record.pose.centre == pytest.approx(centre, abs=2e-4)
        assert (record.pose.heading, record.pose.pitch, record.pose.roll) == pytest.approx((heading, pitch, roll),
                                                                                            abs=2e-6)
    # the PNGs are kept as KITTI wrote them
    assert (drive.pairs[0].left_path.read_bytes()
            == (folder / "image_02" / "data" / "0000000000.png").read_bytes())
    assert json.loads((tmp_path / "drive" / "drive.json").read_text())["import"]["angle_unit"] == "rad"


def test_kitti_frames_without_oxts_are_named(tmp_path):
    folder = make_kitti_drive(tmp_path / "kitti")
    (folder / "oxts" / "data" / "0000000001.txt").unlink()
    with pytest.raises(ImportInputError, match=r"0000000001\.txt: the poses do not cover frame 0000000001"):
        kitti_source(folder)


def test_image_times_of_images_that_do_not_exist_are_said(survey, tmp_path):
    """Issue 46, case 12: an image_times.csv row for an image that is not there is not ignored silently."""
    times = tmp_path / "image_times.csv"
    times.write_text(survey.image_times.read_text() + "img_017,1000.8750\n")
    warnings = []
    summary = import_drive(tmp_path / "drive", generic_source(trajectory_inputs(survey, image_times=times)),
                           warn=warnings.append)
    assert summary.pairs == 3
    assert f"{times}: 1 row(s) name no image found among the images and are not used (first: id 'img_017')" \
        in warnings, warnings
