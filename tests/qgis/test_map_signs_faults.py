"""``signmapper:mapsigns`` with bad input, as a user meets it: nothing lost, nothing silent (issue 11).

Each test calls the algorithm as a user does (``processing.run`` or ``qgis_process.bin``) and checks the
message the user sees and that no earlier output or other data is lost.
"""

import hashlib
import json
import os
import shutil
import sqlite3
from pathlib import Path

import numpy as np
import pytest
from drive_fixtures import make_drive
from qgis.core import (
    QgsFeature,
    QgsGeometry,
    QgsPointXY,
    QgsProcessingException,
    QgsVectorFileWriter,
    QgsVectorLayer,
)
from qgis_process_runner import enable_plugin, qgis_process_env, run_algorithm
from recorder import Recorder

CATALOGUE = Path(__file__).resolve().parents[2] / "templates" / "ch"


@pytest.fixture(scope="module")
def cli_env(plugin_dir, tmp_path_factory):
    env = qgis_process_env(plugin_dir, tmp_path_factory.mktemp("profile"))
    enable_plugin(env)
    return env


def message(info) -> str:
    """What the user reads of a refused run: processing.run puts "Unable to execute algorithm" first."""
    return str(info.value).splitlines()[-1]


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def signs_of(path: Path) -> int:
    return QgsVectorLayer(f"{path}|layername=signs", "s", "ogr").featureCount()


@pytest.fixture
def good_output(run, small_drive, tmp_path) -> Path:
    """A GeoPackage mapped from the seed-11 drive: the user's earlier, good result."""
    out = tmp_path / "signs.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out)})
    assert signs_of(out) >= 2
    return out


def truncate_left_images(drive: Path, count: int | None = None) -> list[Path]:
    """Cut left images to 20000 bytes (header readable, pixels gone), as ``truncate -s 20000`` does."""
    images = sorted((drive / "left").iterdir())[:count]
    for path in images:
        os.truncate(path, 20000) if path.stat().st_size > 20000 else path.write_bytes(path.read_bytes()[:60])
    return images


# 1. data loss: a run where no pair (or too many) can be read

def test_run_where_no_pair_can_be_read_fails_and_keeps_the_old_output(cli_env, small_drive, good_output, tmp_path):
    drive = tmp_path / "truncated"
    shutil.copytree(small_drive, drive)
    truncate_left_images(drive)
    before = digest(good_output)
    code, _data, log = run_algorithm(cli_env, "signmapper:mapsigns", DRIVE=drive, OUTPUT=good_output)
    assert code != 0, log
    # by default it stops once more than half the pairs are skipped
    assert "Mapping failed: 7 of 12 pairs skipped, more than the 50 % allowed (first: pair 000000: " in log
    assert "truncated JPEG" in log and f"Nothing written; {good_output} is as it was." in log
    assert digest(good_output) == before and signs_of(good_output) >= 2
    # with every pair allowed to fail, a run where none can be read still fails
    code, _data, log = run_algorithm(cli_env, "signmapper:mapsigns", DRIVE=drive, OUTPUT=good_output,
                                     MAX_SKIPPED=100)
    assert code != 0, log
    assert "Mapping failed: no pair could be mapped: 12 of 12 pairs skipped (first: pair 000000: " in log
    # no share of skipped pairs helps when none maps: the message does not suggest raising it
    assert f"Nothing written; {good_output} is as it was. Repair or remove the unreadable files.\n" in log
    assert "raise 'Largest share" not in log
    assert digest(good_output) == before
    assert not list(tmp_path.glob(".*partial*"))


def test_more_unreadable_pairs_than_allowed_fail_the_run(run, small_drive, good_output, tmp_path):
    drive = tmp_path / "half"
    shutil.copytree(small_drive, drive)
    truncate_left_images(drive, 7)
    before = digest(good_output)
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(good_output)}, feedback=feedback)
    text = str(info.value)
    assert text.startswith("Mapping failed: 7 of 12 pairs skipped, more than the 50 % allowed (first: pair 000000")
    assert "raise 'Largest share of unreadable pairs [%]'" in text
    assert digest(good_output) == before
    assert sum("Skipped pair" in line for line in feedback.lines) == 7  # it stopped as soon as it was certain
    # with the share raised the same drive maps, and says what it skipped
    feedback = Recorder()
    out = tmp_path / "rest.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out), "MAX_SKIPPED": 100}, feedback=feedback)
    assert "7 of 12 pairs skipped: 7 unreadable; see the messages above" in feedback.text()
    assert QgsVectorLayer(f"{out}|layername=detections", "d", "ogr").isValid()


def test_depth_of_the_wrong_type_fails_before_mapping_and_keeps_the_old_output(run, good_output, tmp_path):
    import cv2

    drive = make_drive(tmp_path / "u16", n_pairs=3, depth_suffix=".tif")
    for path in (drive / "depth").iterdir():
        cv2.imwrite(str(path), np.full((48, 64), 8000, np.uint16))  # millimetres as 16-bit integers
    before = digest(good_output)
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(good_output)}, feedback=feedback)
    assert str(info.value) == (f"Invalid drive: {drive / 'depth' / '000000.tif'}: depth map must be float32 metres "
                               "(drive-format), found uint16 (millimetres as integers?)")
    assert not [s for s in feedback.steps if s > 5]  # refused while validating, before any pair
    assert digest(good_output) == before


# 2. data loss: the user's own layers in the output GeoPackage

def user_geopackage(path: Path) -> Path:
    """A GeoPackage holding the user's layer 'roads' with one feature."""
    layer = QgsVectorLayer("Point?crs=EPSG:2056&field=name:string", "roads", "memory")
    feature = QgsFeature(layer.fields())
    feature.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(2600000, 1200000)))
    feature.setAttributes(["Bahnhofstrasse"])
    layer.dataProvider().addFeatures([feature])
    options = QgsVectorFileWriter.SaveVectorOptions()
    options.driverName, options.layerName = "GPKG", "roads"
    error = QgsVectorFileWriter.writeAsVectorFormatV3(layer, str(path), layer.transformContext(), options)
    assert error[0] == QgsVectorFileWriter.NoError, error
    return path


def test_other_layers_of_an_existing_geopackage_are_kept(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    project = user_geopackage(tmp_path / "project.gpkg")
    for _ in range(2):  # writing twice replaces our layers and their styles, nothing else
        feedback = Recorder()
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(project)}, feedback=feedback)
        assert f"Kept the other layers of {project}: roads" in feedback.text()
    roads = QgsVectorLayer(f"{project}|layername=roads", "roads", "ogr")
    assert roads.isValid() and [f["name"] for f in roads.getFeatures()] == ["Bahnhofstrasse"]
    with sqlite3.connect(project) as db:
        tables = sorted(name for (name,) in db.execute("SELECT table_name FROM gpkg_contents"))
        styles = sorted(name for (name,) in db.execute("SELECT f_table_name FROM layer_styles"))
    assert tables == ["detections", "layer_styles", "roads", "signmapper_run", "signs"]
    assert styles == ["detections", "signs"]


def test_a_file_that_is_no_geopackage_is_refused(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    notes = tmp_path / "notes.gpkg"
    notes.write_text("my field notes, saved under the wrong name")
    with pytest.raises(QgsProcessingException, match="notes.gpkg exists and is not a GeoPackage; it is left as it is"):
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(notes)})
    assert notes.read_text() == "my field notes, saved under the wrong name"


# 4, 5. the catalogue: optional pictograms, corrupt images found when it loads

def catalogue_copy(tmp_path: Path, svg: bool) -> Path:
    folder = tmp_path / "catalogue"
    shutil.copytree(CATALOGUE, folder, ignore=None if svg else shutil.ignore_patterns("svg"))
    return folder


def pictogram_faces(signs) -> dict:
    """Template id -> (type, colour) of the face layer of its symbol (layer 0; the status group's rules draw
    the status marks, not faces)."""
    faces = {}
    for group in signs.renderer().rootRule().children()[1:]:
        for rule in group.children():
            face = rule.symbol().symbolLayer(0)
            faces[rule.label().split(" ", 1)[0]] = (face.layerType(), face.color().name())
    return faces


def test_catalogue_without_svg_pictograms_styles_plain_markers(run, small_drive, tmp_path):
    folder = catalogue_copy(tmp_path, svg=False)
    feedback = Recorder()
    out = tmp_path / "plain.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "CATALOGUE": str(folder)},
        feedback=feedback)
    entries = json.loads((folder / "catalogue.json").read_text())["entries"]
    n, first = len(entries), entries[0]["id"]  # the first entry is the example named
    assert (f"{n} of {n} templates have no SVG pictogram (e.g. {first}): their signs are drawn with a plain marker "
            "of their shape and colour") in feedback.text()
    signs = QgsVectorLayer(f"{out}|layername=signs", "s", "ogr")
    assert signs.featureCount() >= 2
    faces = pictogram_faces(signs)
    assert faces["1.01"] == ("SimpleMarker", "#d52b1e")
    assert {kind for kind, _colour in faces.values()} == {"SimpleMarker"}


def test_one_missing_svg_gets_a_plain_marker(run, small_drive, tmp_path):
    folder = catalogue_copy(tmp_path, svg=True)
    (folder / "svg" / "2.01.svg").unlink()
    feedback = Recorder()
    out = tmp_path / "one.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "CATALOGUE": str(folder)},
        feedback=feedback)
    assert "1 of " in feedback.text() and "(e.g. 2.01)" in feedback.text()
    faces = pictogram_faces(QgsVectorLayer(f"{out}|layername=signs", "s", "ogr"))
    assert faces["2.01"][0] == "SimpleMarker" and faces["2.02"][0] == "SvgMarker"


@pytest.mark.parametrize("damage", ["truncate", "flip"])
def test_corrupt_catalogue_image_is_refused_before_the_run(run, small_drive, tmp_path, damage):
    folder = catalogue_copy(tmp_path, svg=True)
    png = folder / "png" / "3.07.png"  # the sign of the drive whose templates are compared mid-run
    data = bytearray(png.read_bytes())
    if damage == "truncate":
        data = data[: len(data) // 2]
    else:
        data[len(data) // 2] ^= 0xFF
    png.write_bytes(bytes(data))
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "x.gpkg"),
                                    "CATALOGUE": str(folder)}, feedback=feedback)
    assert message(info).startswith(f"Template catalogue: {png}: entry '3.07': the template image is corrupt or "
                                    "unreadable")
    assert not feedback.steps  # refused when the parameters were checked, before the drive was opened
    assert not (tmp_path / "x.gpkg").exists()


# 6. output paths checked before the run

def read_only_folder(tmp_path: Path) -> Path:
    """A folder no file can be created in (root ignores permissions: /sys refuses even root)."""
    if os.geteuid() == 0:
        if not os.path.isdir("/sys"):
            pytest.skip("running as root without /sys: no read-only folder to try")
        return Path("/sys")
    folder = tmp_path / "read-only"
    folder.mkdir()
    folder.chmod(0o555)
    return folder


def test_output_that_is_a_folder_or_unwritable_is_refused_before_the_run(run, small_drive, tmp_path):
    folder = tmp_path / "results.gpkg"
    folder.mkdir()
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(folder)}, feedback=feedback)
    assert message(info) == f"Output GeoPackage: {folder} is an existing folder; give a file name"
    assert not feedback.steps
    locked = read_only_folder(tmp_path)
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(locked / "signs.gpkg")},
            feedback=feedback)
    assert message(info).startswith(f"Output GeoPackage: {locked / 'signs.gpkg'}: cannot write into the folder "
                                      f"{locked} (")
    assert not feedback.steps


def test_output_that_is_no_geopackage_is_refused_naming_the_parameter(run, small_drive, tmp_path):
    drive = tmp_path / "drive"
    shutil.copytree(small_drive, drive)
    poses = drive / "poses.csv"
    before = digest(poses)
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(poses)}, feedback=feedback)
    assert message(info) == f"Output GeoPackage: {poses}: the output must be a GeoPackage file ending in .gpkg"
    assert not feedback.steps
    assert digest(poses) == before


# 9. a cancel is a cancel, wherever it happens

def test_cancel_while_writing_writes_nothing(run, small_drive, good_output):
    before = digest(good_output)
    feedback = Recorder()
    feedback.progressChanged.connect(lambda p: feedback.cancel() if p >= 97 else None)
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(good_output)}, feedback=feedback)
    assert str(info.value) == f"Cancelled; no output written; {good_output} is as it was."
    assert max(feedback.steps) >= 97  # the mapping was done: the cancel came while fusing or writing
    assert digest(good_output) == before
    assert not list(good_output.parent.glob(".*partial*"))


# 11. implausible input: errors where it cannot work, warnings where it is only unlikely

def test_principal_point_outside_the_image_is_refused(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    meta = json.loads((drive / "drive.json").read_text())
    meta["camera"]["cx"] = -1e9
    (drive / "drive.json").write_text(json.dumps(meta))
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "x.gpkg")})
    assert str(info.value) == (f"Invalid drive: {drive / 'drive.json'}, field 'camera.cx': principal point "
                               "-1000000000.0 lies outside the image (-0.5 to 63.5 px)")


def test_heading_that_is_no_angle_is_refused(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    lines = (drive / "poses.csv").read_text().splitlines()
    row = lines[2].split(",")
    row[5] = "1e300"
    lines[2] = ",".join(row)
    (drive / "poses.csv").write_text("\n".join(lines) + "\n")
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "x.gpkg")})
    assert str(info.value) == (f"Invalid drive: {drive / 'poses.csv'}, line 3, field 'heading': heading 1e+300 is "
                               "not an angle in degrees")


def test_implausible_drive_is_mapped_with_warnings_in_the_log(run, tmp_path):
    import cv2

    drive = make_drive(tmp_path / "drive", n_pairs=3)
    poses = (drive / "poses.csv").read_text().splitlines()
    rows = [row.split(",") for row in poses[1:]]
    for row in rows:  # longitude/latitude in a projected CRS
        row[2], row[3] = "8.54", "47.37"
    (drive / "poses.csv").write_text("\n".join([poses[0]] + [",".join(r) for r in rows]) + "\n")
    np.save(drive / "depth" / "000000.npy", np.full((48, 64), 8000.0, np.float32))  # millimetres
    np.save(drive / "depth" / "000001.npy", np.full((48, 64), np.nan, np.float32))  # no depth at all
    cv2.imwrite(str(drive / "left" / "000002.png"), np.full((48, 64), 90, np.uint8))  # greyscale
    feedback = Recorder()
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "x.gpkg")}, feedback=feedback)
    log = feedback.text()
    assert any("poses.csv: 3 of 3 positions lie outside the area of use of EPSG:2056" in w for w in feedback.warnings)
    assert "look like longitude/latitude" in log
    assert "000000.npy: only 0 % of the valid depths lie within 0.5-500 m, median 8000 (millimetres?)" in log
    assert "left/: 1 of 3 images are greyscale (first: 000002.png)" in log
    assert f"Pair 000001: {drive / 'depth' / '000001.npy'} has no usable depth" in log
    assert f"Pair 000002: {drive / 'left' / '000002.png'} has no colour at all" in log


# 13. late or misleading errors

def test_near_beyond_far_names_the_dialog_labels(cli_env, small_drive, tmp_path):
    code, _data, log = run_algorithm(cli_env, "signmapper:mapsigns", DRIVE=small_drive,
                                     OUTPUT=tmp_path / "x.gpkg", NEAR=14, FAR=4)
    assert code != 0
    assert ("Near limit of the depth range [m] (14 m) must be less than Far limit of the depth range [m] (4 m)."
            in log)
    assert "near_m" not in log


@pytest.mark.parametrize("damage, words", [
    ("zero-byte npy", "000001.npy: empty file (0 bytes)"),
    ("png named jpg", "000001.jpg: is a PNG image, not what its suffix .jpg says; rename it to 000001.png"),
])
def test_misnamed_or_empty_files_are_named_for_what_they_are(run, tmp_path, damage, words):
    import cv2

    drive = make_drive(tmp_path / "drive", n_pairs=3, image_suffix=".jpg")
    if damage == "zero-byte npy":
        (drive / "depth" / "000001.npy").write_bytes(b"")
    else:
        (drive / "left" / "000001.jpg").write_bytes(cv2.imencode(".png", np.zeros((48, 64, 3), np.uint8))[1])
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "x.gpkg")})
    assert str(info.value).startswith("Invalid drive: ") and str(info.value).endswith(words)


# 14. the optional truth.csv never blocks mapping

def test_broken_truth_csv_does_not_block_mapping(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    with open(drive / "truth.csv", "a") as fh:
        fh.write("s002,2.01,2600010,1200003,north,0.6,0.6,270\n")
    feedback = Recorder()
    out = tmp_path / "x.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out)}, feedback=feedback)
    assert QgsVectorLayer(f"{out}|layername=signs", "s", "ogr").isValid()
    assert (f"{drive / 'truth.csv'}, line 3, field 'height': 'north' is not a number; the ground truth "
            "is ignored (only evaluation needs it)") in feedback.warnings


# 8. a compound CRS or a PROJ string reaches the layers

LV95_PROJ = ("+proj=somerc +lat_0=46.9524055555556 +lon_0=7.43958333333333 +k_0=1 +x_0=2600000 +y_0=1200000 "
             "+ellps=bessel +towgs84=674.374,15.056,405.346,0,0,0,0 +units=m +no_defs +type=crs")


@pytest.mark.parametrize("crs, words", [
    ("EPSG:2056+5728", "CRS EPSG:2056+5728: the layers carry its horizontal part EPSG:2056 (QGIS 3.22 has no "
                       "compound CRS); heights are those of LN02 height"),
    (LV95_PROJ, f"CRS {LV95_PROJ}: the layers carry it as EPSG:2056"),
])
def test_compound_crs_or_proj_string_reaches_the_layers(run, tmp_path, crs, words):
    drive = make_drive(tmp_path / "drive", n_pairs=2, crs=crs)
    feedback = Recorder()
    out = tmp_path / "x.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out)}, feedback=feedback)
    for layer in ("signs", "detections"):
        crs = QgsVectorLayer(f"{out}|layername={layer}", layer, "ogr").crs()
        assert crs.isValid() and crs.authid() == "EPSG:2056" and not crs.isGeographic()
    assert words in feedback.text()
    with sqlite3.connect(out) as db:
        assert db.execute("SELECT organization || ':' || organization_coordsys_id FROM gpkg_spatial_ref_sys s "
                          "JOIN gpkg_contents c ON c.srs_id = s.srs_id WHERE c.table_name = 'signs'").fetchone() \
            == ("EPSG:2056",)
