"""The drive reader accepts exactly drive-format.md and names file, line and field when it does not."""

import json
import shutil

import numpy as np
import pytest
from drive_fixtures import SMALL_CAMERA, make_drive, rewrite_line

from signmapper_core.drive.images import read_depth, write_depth
from signmapper_core.drive.reader import open_drive, read_truth
from signmapper_core.errors import DriveFormatError, ImageReadError


@pytest.fixture
def drive_dir(tmp_path):
    return make_drive(tmp_path / "drive", n_pairs=4)


def error_of(path) -> DriveFormatError:
    with pytest.raises(DriveFormatError) as info:
        open_drive(path)
    return info.value


def test_valid_drive_opens_with_everything(drive_dir):
    drive = open_drive(drive_dir)
    assert drive.crs == "EPSG:2056"
    assert drive.camera == SMALL_CAMERA
    assert [p.id for p in drive.pairs] == ["000000", "000001", "000002", "000003"]
    assert drive.pairs[1].pose.easting == pytest.approx(2600002.0)
    assert drive.pairs[1].left_path.name == "000001.png"
    assert drive.truth[0].template_id == "2.30-50"
    assert drive.metadata["software"] == "tests"  # unknown keys are kept, not rejected
    left = drive.load_left(drive.pairs[0])
    assert left.shape == (48, 64, 3) and left.dtype == np.uint8
    depth = drive.load_depth(drive.pairs[0])
    assert depth.dtype == np.float32 and np.all(depth == 8.0)


def test_progress_is_reported_per_pair(drive_dir):
    calls = []
    open_drive(drive_dir, progress=lambda fraction, message: calls.append((fraction, message)))
    assert [f for f, _ in calls] == [0.25, 0.5, 0.75, 1.0]
    assert calls[1][1] == "checked pair 000001 (2 of 4)"


def test_cancel_stops_opening_with_cancelled(drive_dir):
    from signmapper_core.progress import Cancelled

    seen = []
    with pytest.raises(Cancelled, match="opening drive"):
        open_drive(drive_dir, progress=lambda f, m: seen.append(f), is_cancelled=lambda: len(seen) >= 2)
    assert seen == [0.25, 0.5]


def test_missing_folder_and_files(tmp_path, drive_dir):
    assert "does not exist" in str(error_of(tmp_path / "nowhere"))
    (drive_dir / "poses.csv").unlink()
    err = error_of(drive_dir)
    assert err.path.endswith("poses.csv") and "missing" in str(err)
    (drive_dir / "drive.json").unlink()
    assert error_of(drive_dir).path.endswith("drive.json")


def test_missing_left_folder(drive_dir):
    shutil.rmtree(drive_dir / "left")
    err = error_of(drive_dir)
    assert err.path.endswith("left") and "folder is missing" in str(err)


def test_invalid_json(drive_dir):
    (drive_dir / "drive.json").write_text('{"format": "stereo-drive/1",\n "crs": }')
    err = error_of(drive_dir)
    assert err.line == 2 and "not valid JSON" in str(err)


@pytest.mark.parametrize(
    "change, field, words",
    [
        (lambda d: d.pop("crs"), "crs", "missing"),
        (lambda d: d.update(format="stereo-drive/2"), "format", "unsupported"),
        (lambda d: d["camera"].pop("fx"), "camera.fx", "missing"),
        (lambda d: d["camera"].update(fy="1750"), "camera.fy", "finite number"),
        (lambda d: d["camera"].update(width=-5), "camera.width", "positive whole"),
        (lambda d: d["camera"].update(baseline_m=0), "camera.baseline_m", "positive"),
        (lambda d: d.update(crs="EPSG:999999"), "crs", "unknown CRS"),
        (lambda d: d.update(crs="EPSG:4326"), "crs", "not projected"),
        (lambda d: d.update(crs="EPSG:2227"), "crs", "not metres"),  # California zone 3, US survey feet
    ],
)
def test_drive_json_fields(drive_dir, change, field, words):
    path = drive_dir / "drive.json"
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))
    err = error_of(drive_dir)
    assert err.field == field and words in str(err), str(err)
    assert "drive.json" in str(err)


def test_compound_crs_with_projected_horizontal_is_accepted(drive_dir):
    path = drive_dir / "drive.json"
    data = json.loads(path.read_text())
    data["crs"] = "EPSG:2056+5728"
    path.write_text(json.dumps(data))
    assert open_drive(drive_dir).crs == "EPSG:2056+5728"


@pytest.mark.parametrize(
    "line_no, text, field, words",
    [
        (1, "id,time,easting,northing,height,heading,pitch", "roll", "lacks required column"),
        (3, "000001,0.200,2600002.0,abc,400.0,90.0,0.0,0.0", "northing", "'abc' is not a number"),
        (3, "000001,0.200,2600002.0,1200000.0,nan,90.0,0.0,0.0", "height", "not a finite number"),
        (4, "000002,0.100,2600004.0,1200000.0,400.0,90.0,0.0,0.0", "time", "not after"),
        (4, "000002,0.200,2600004.0,1200000.0,400.0,90.0,0.0,0.0", "time", "not after"),
        (3, "000000,0.200,2600002.0,1200000.0,400.0,90.0,0.0,0.0", "id", "repeats line 2"),
        (3, "a/b,0.200,2600002.0,1200000.0,400.0,90.0,0.0,0.0", "id", "path separator"),
        (3, "000001,0.200,2600002.0,1200000.0,400.0,90.0,95.0,0.0", "pitch", "outside"),
        (3, "000001,0.200,,1200000.0,400.0,90.0,0.0,0.0", "easting", "empty"),
        (3, "000001,0.200,2600002.0,1200000.0,400.0,90.0", None, "has 6 fields"),
        (5, "nopic,0.800,2600006.0,1200000.0,400.0,90.0,0.0,0.0", "id", "no left image"),
    ],
)
def test_poses_csv_rows(drive_dir, line_no, text, field, words):
    rewrite_line(drive_dir / "poses.csv", line_no, text)
    err = error_of(drive_dir)
    assert err.path.endswith("poses.csv")
    assert err.line == line_no and err.field == field and words in str(err), str(err)
    assert f"line {line_no}" in str(err)


def test_poses_csv_without_rows(drive_dir):
    (drive_dir / "poses.csv").write_text("id,time,easting,northing,height,heading,pitch,roll\n")
    assert "no pair rows" in str(error_of(drive_dir))


def test_pair_without_depth_or_right_image(tmp_path):
    root = make_drive(tmp_path / "d", n_pairs=2, with_right=False)
    (root / "depth" / "000001.npy").unlink()
    err = error_of(root)
    assert err.line == 3 and "neither depth/000001.* nor right/000001.*" in str(err)


def test_right_images_alone_are_enough(tmp_path):
    root = make_drive(tmp_path / "d", n_pairs=2, depth_suffix=None)
    drive = open_drive(root)
    assert drive.pairs[0].depth_path is None and drive.load_depth(drive.pairs[0]) is None
    assert drive.load_right(drive.pairs[0]).shape == (48, 64, 3)


def test_ambiguous_images_for_one_id(drive_dir):
    shutil.copy(drive_dir / "left" / "000001.png", drive_dir / "left" / "000001.jpg")
    err = error_of(drive_dir)
    assert "ambiguous" in str(err) and "000001.jpg" in str(err)


def test_image_of_wrong_size(drive_dir):
    import cv2

    cv2.imwrite(str(drive_dir / "left" / "000002.png"), np.zeros((40, 64, 3), np.uint8))
    err = error_of(drive_dir)
    assert err.path.endswith("000002.png") and "64x40 differs from the camera's 64x48" in str(err)


def test_depth_of_wrong_size(drive_dir):
    np.save(drive_dir / "depth" / "000003.npy", np.ones((48, 60), np.float32))
    err = error_of(drive_dir)
    assert err.path.endswith("000003.npy") and "60x48" in str(err)


def test_corrupt_image_header(drive_dir):
    (drive_dir / "left" / "000001.png").write_bytes(b"not a png at all")
    err = error_of(drive_dir)
    assert isinstance(err, ImageReadError) and "not a readable image" in str(err)


def test_corrupt_image_body_is_reported_when_loaded(drive_dir):
    path = drive_dir / "left" / "000001.png"
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 3])  # header intact, pixels truncated
    drive = open_drive(drive_dir)
    with pytest.raises(ImageReadError, match="000001.png"):
        drive.load_left(drive.pairs[1])


@pytest.mark.parametrize("suffix", [".npy", ".tif", ".pfm"])
def test_depth_formats_round_trip_and_invalid_values_become_nan(tmp_path, suffix):
    depth = np.full((48, 64), 7.5, np.float32)
    depth[0, 0], depth[0, 1], depth[0, 2], depth[0, 3] = 0.0, -1.0, np.inf, np.nan
    depth[5, 7] = 12.25
    path = write_depth(tmp_path / f"d{suffix}", depth)
    back = read_depth(path, (64, 48))
    assert back.dtype == np.float32 and back.shape == (48, 64)
    assert np.isnan(back[0, :4]).all()
    assert back[5, 7] == 12.25 and back[10, 10] == 7.5


@pytest.mark.parametrize("suffix", [".tif", ".pfm"])
def test_drive_with_tif_and_pfm_depth(tmp_path, suffix):
    root = make_drive(tmp_path / "d", n_pairs=2, depth_suffix=suffix, with_right=False)
    drive = open_drive(root)
    assert drive.pairs[1].depth_path.suffix == suffix
    assert float(np.nanmean(drive.load_depth(drive.pairs[1]))) == pytest.approx(8.0)


def test_depth_must_be_float32(tmp_path):
    np.save(tmp_path / "d.npy", np.ones((48, 64), np.float64))
    with pytest.raises(ImageReadError, match="float32"):
        read_depth(tmp_path / "d.npy")


@pytest.mark.parametrize(
    "line_no, text, field, words",
    [
        (1, "sign_id,template_id,easting,northing,height,width_m,height_m", "facing", "lacks required column"),
        (2, "s001,2.01,2600005,1200003,x,0.6,0.6,270", "height", "not a number"),
        (2, "s001,2.01,2600005,1200003,401,0,0.6,270", "width_m", "positive"),
    ],
)
def test_truth_csv_rows(drive_dir, line_no, text, field, words):
    rewrite_line(drive_dir / "truth.csv", line_no, text)
    with pytest.raises(DriveFormatError) as info:
        open_drive(drive_dir, require_truth=True)
    err = info.value
    assert err.path.endswith("truth.csv") and err.line == line_no and err.field == field and words in str(err)
    # mapping does not need the truth: by default the drive opens without it and says why
    drive = open_drive(drive_dir)
    assert drive.truth is None and drive.truth_error is not None
    assert drive.warnings == [f"{err}; the ground truth is ignored (only evaluation needs it)"]


def test_truth_duplicate_sign_id(drive_dir):
    path = drive_dir / "truth.csv"
    path.write_text(path.read_text() + "s001,2.01,2600001,1200001,401,0.6,0.6,90\n")
    with pytest.raises(DriveFormatError, match="repeats line 2"):
        read_truth(path)


def test_pairs_are_loaded_one_at_a_time(tmp_path):
    root = make_drive(tmp_path / "d", n_pairs=3)
    drive = open_drive(root)
    # Opening decodes no pixels: breaking a later image body only fails when that pair is loaded.
    path = drive.pairs[2].left_path
    path.write_bytes(path.read_bytes()[:200])
    assert drive.load_left(drive.pairs[0]).shape == (48, 64, 3)
    with pytest.raises(ImageReadError):
        drive.load_left(drive.pairs[2])


def test_truncated_jpeg_is_an_error_not_a_grey_picture(tmp_path):
    root = make_drive(tmp_path / "d", n_pairs=2, image_suffix=".jpg")
    drive = open_drive(root)
    path = drive.pairs[1].left_path
    path.write_bytes(path.read_bytes()[:-200])
    assert drive.load_left(drive.pairs[0]).shape == (48, 64, 3)
    with pytest.raises(ImageReadError, match="truncated JPEG"):
        drive.load_left(drive.pairs[1])


def test_input_errors_name_the_place_the_same_way_and_stay_apart():
    from signmapper_core.catalogue.model import CatalogueError
    from signmapper_core.errors import ImportInputError, InputFileError
    from signmapper_core.validation.realset import ManifestError

    for cls in (DriveFormatError, ImportInputError, ManifestError):
        error = cls("poses.csv", "heading is not a number", line=3, field="heading")
        assert str(error) == "poses.csv, line 3, field 'heading': heading is not a number"
        assert isinstance(error, InputFileError) and isinstance(error, ValueError)
        assert (error.path, error.line, error.field, error.reason) == ("poses.csv", 3, "heading",
                                                                      "heading is not a number")
    assert str(CatalogueError("catalogue.json", "entry 1.01: no formats")) == "catalogue.json: entry 1.01: no formats"
    # an import's input is not the drive folder: catching one does not catch the other
    assert not isinstance(ImportInputError("a", "b"), DriveFormatError)
    assert not isinstance(ManifestError("a", "b"), DriveFormatError)


def test_images_without_a_row_in_poses_csv_are_said(drive_dir):
    """Issue 46, case 11: a pair whose images exist but whose poses.csv row is missing is not dropped silently."""
    lines = (drive_dir / "poses.csv").read_text().splitlines()
    (drive_dir / "poses.csv").write_text("\n".join(lines[:3] + lines[4:]) + "\n")  # the row of 000002
    drive = open_drive(drive_dir)
    assert [p.id for p in drive.pairs] == ["000000", "000001", "000003"]
    assert drive.warnings == [f"{drive_dir / 'left'}/: 1 image has no row in poses.csv and is not mapped "
                              "(first: 000002.png)"]
    (drive_dir / "poses.csv").write_text("\n".join(lines[:2]) + "\n")
    assert open_drive(drive_dir).warnings == [f"{drive_dir / 'left'}/: 3 images have no row in poses.csv and are "
                                              "not mapped (first: 000001.png)"]
