"""The reader rejects what cannot work and warns about what the format allows but no real drive holds."""

import json

import numpy as np
import pytest
from drive_fixtures import make_drive, rewrite_line

from signmapper_core.drive.images import read_depth
from signmapper_core.drive.reader import open_drive
from signmapper_core.errors import DriveFormatError, ImageReadError

POSE = "000001,0.200,{e},{n},400.0,{h},{p},{r}"


@pytest.fixture
def drive_dir(tmp_path):
    return make_drive(tmp_path / "drive", n_pairs=4)


def set_camera(drive_dir, **values):
    path = drive_dir / "drive.json"
    data = json.loads(path.read_text())
    data["camera"].update(values)
    path.write_text(json.dumps(data))


def set_pose(drive_dir, e=2600002.0, n=1200000.0, h=90.0, p=0.0, r=0.0):
    rewrite_line(drive_dir / "poses.csv", 3, POSE.format(e=e, n=n, h=h, p=p, r=r))


def test_a_plain_drive_has_no_warnings(drive_dir):
    assert open_drive(drive_dir).warnings == []


@pytest.mark.parametrize("key, value, words", [
    ("cx", -1e9, "camera.cx': principal point -1000000000.0 lies outside the image (-0.5 to 63.5 px)"),
    ("cy", 48.0, "camera.cy': principal point 48.0 lies outside the image (-0.5 to 47.5 px)"),
])
def test_principal_point_outside_the_image_is_an_error(drive_dir, key, value, words):
    set_camera(drive_dir, **{key: value})
    with pytest.raises(DriveFormatError, match="drive.json") as info:
        open_drive(drive_dir)
    assert words in str(info.value)


@pytest.mark.parametrize("values, words", [
    ({"fx": 2.0, "fy": 2.0}, "field 'camera.fx': fx 2 px gives a horizontal field of view of 172.8°"),
    ({"fy": 120.0}, "field 'camera.fy': fx 60 and fy 120 differ by more than 25 %"),
    ({"baseline_m": 900.0}, "field 'camera.baseline_m': 900 m is outside the usual 0.05-5 m; is it in metres?"),
])
def test_implausible_camera_is_a_warning(drive_dir, values, words):
    set_camera(drive_dir, **values)
    warnings = open_drive(drive_dir).warnings
    assert len(warnings) == 1 and words in warnings[0], warnings


def test_heading_that_is_no_angle_is_an_error(drive_dir):
    set_pose(drive_dir, h=1e300)
    with pytest.raises(DriveFormatError) as info:
        open_drive(drive_dir)
    assert "poses.csv, line 3, field 'heading': heading 1e+300 is not an angle in degrees" in str(info.value)


@pytest.mark.parametrize("angles, words", [
    ({"h": 400.0}, "field 'heading': 1 of 4 rows outside -360..360° (first: line 3, 400)"),
    ({"p": 60.0}, "field 'pitch': 1 of 4 rows outside -45..45° (first: line 3, 60)"),
    ({"r": 90.0}, "field 'roll': 1 of 4 rows outside -45..45° (first: line 3, 90)"),
    ({"r": 359.0}, None),  # -1 degree written as 359
])
def test_angles_outside_their_usual_range_are_warnings(drive_dir, angles, words):
    set_pose(drive_dir, **angles)
    warnings = open_drive(drive_dir).warnings
    assert warnings == [] if words is None else (len(warnings) == 1 and words in warnings[0]), warnings


def test_longitude_latitude_in_a_projected_crs_is_a_warning(drive_dir):
    lines = (drive_dir / "poses.csv").read_text().splitlines()
    rows = [line.split(",") for line in lines[1:]]
    for row in rows:
        row[2], row[3] = "8.54", "47.37"
    (drive_dir / "poses.csv").write_text("\n".join([lines[0]] + [",".join(r) for r in rows]) + "\n")
    warnings = open_drive(drive_dir).warnings
    assert len(warnings) == 1
    assert "poses.csv: 4 of 4 positions lie outside the area of use of EPSG:2056 (CH1903+ / LV95" in warnings[0]
    assert "first: line 2, easting 8.54, northing 47.37" in warnings[0]
    assert "look like longitude/latitude" in warnings[0]


def test_positions_far_from_the_crs_area_are_a_warning(tmp_path):
    drive_dir = make_drive(tmp_path / "utm", n_pairs=2, crs="EPSG:32632")  # Swiss LV95 numbers in UTM 32N
    warnings = open_drive(drive_dir).warnings
    assert len(warnings) == 1 and "outside the area of use of EPSG:32632" in warnings[0]
    assert "is the CRS in drive.json the one the positions are in?" in warnings[0]


def test_depth_in_millimetres_is_a_warning(drive_dir):
    np.save(drive_dir / "depth" / "000000.npy", np.full((48, 64), 8000.0, np.float32))
    warnings = open_drive(drive_dir).warnings
    assert len(warnings) == 1 and "000000.npy: only 0 % of the valid depths lie within 0.5-500 m" in warnings[0]
    assert "median 8000 (millimetres?)" in warnings[0]


def test_depth_map_without_any_depth_is_a_warning(drive_dir):
    np.save(drive_dir / "depth" / "000000.npy", np.full((48, 64), np.nan, np.float32))
    warnings = open_drive(drive_dir).warnings
    assert warnings == [f"{drive_dir / 'depth' / '000000.npy'}: no pixel has a depth (all 0, negative, inf or NaN)"]


def test_greyscale_images_are_a_warning(drive_dir):
    import cv2

    for i in (1, 3):
        cv2.imwrite(str(drive_dir / "left" / f"00000{i}.png"), np.full((48, 64), 90, np.uint8))
    warnings = open_drive(drive_dir).warnings
    assert len(warnings) == 1
    assert "left/: 2 of 4 images are greyscale (first: 000001.png); signs are found by their colour" in warnings[0]


@pytest.mark.parametrize("dtype, suffix", [(np.uint16, ".tif"), (np.float64, ".tif"), (np.float64, ".npy"),
                                           (np.uint16, ".npy")])
def test_depth_of_the_wrong_type_is_an_error_before_any_pair_is_mapped(tmp_path, dtype, suffix):
    import cv2

    drive_dir = make_drive(tmp_path / "d", n_pairs=3, depth_suffix=suffix)
    path = drive_dir / "depth" / f"000002{suffix}"  # the last pair: found up front, not after mapping two
    depth = np.full((48, 64), 8000 if dtype == np.uint16 else 8.0, dtype)
    np.save(path, depth) if suffix == ".npy" else cv2.imwrite(str(path), depth)
    with pytest.raises(ImageReadError) as info:
        open_drive(drive_dir)
    name = np.dtype(dtype).name
    assert info.value.path == str(path)
    assert f"depth map must be float32 metres (drive-format), found {name}" in str(info.value)


def test_zero_byte_and_foreign_npy_name_what_they_are(drive_dir):
    path = drive_dir / "depth" / "000001.npy"
    path.write_bytes(b"")
    with pytest.raises(ImageReadError, match="000001.npy: empty file \\(0 bytes\\)"):
        open_drive(drive_dir)
    with pytest.raises(ImageReadError, match="empty file"):
        read_depth(path)
    path.write_bytes(b"8.0 8.0 8.0\n")
    with pytest.raises(ImageReadError, match="000001.npy: not a NumPy .npy file"):
        open_drive(drive_dir)
    with pytest.raises(ImageReadError, match="not a NumPy .npy file"):
        read_depth(path)


def test_png_named_jpg_is_named_as_such(tmp_path):
    drive_dir = make_drive(tmp_path / "d", n_pairs=2, image_suffix=".jpg")
    png = (drive_dir / "left" / "000001.jpg")
    import cv2

    png.write_bytes(cv2.imencode(".png", np.zeros((48, 64, 3), np.uint8))[1].tobytes())
    with pytest.raises(ImageReadError) as info:
        open_drive(drive_dir)
    assert str(info.value) == f"{png}: is a PNG image, not what its suffix .jpg says; rename it to 000001.png"
    drive = open_drive(drive_dir, check_images=False)  # the review opens without headers: loading names it too
    with pytest.raises(ImageReadError, match="not a JPEG file although named .jpg"):
        drive.load_left(drive.pairs[1])


def test_a_pair_has_colour_where_only_the_finer_sample_shows_it():
    from signmapper_core.drive.plausibility import has_colour

    grey = np.full((1080, 1920, 3), 128, np.uint8)
    assert not has_colour(grey)
    coloured = grey.copy()
    coloured[4, 8] = (128, 128, 200)  # in the every-4th-pixel sample, not in the every-16th one
    assert has_colour(coloured)
    coloured[4, 8] = 128
    coloured[5, 9] = (128, 128, 200)  # in neither sample
    assert not has_colour(coloured)
