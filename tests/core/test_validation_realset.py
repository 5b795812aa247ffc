"""Real-photograph manifests: reading, row checks with file/line/field errors, images and boxes."""

from __future__ import annotations

from pathlib import Path

import cv2
import numpy as np
import pytest

from signmapper_core.validation import (
    MANIFEST_COLUMNS,
    ManifestError,
    RealSign,
    load_manifest,
    load_scene_list,
)

HEADER = ",".join(MANIFEST_COLUMNS)


def _write_image(path: Path, width: int = 40, height: int = 30) -> np.ndarray:
    path.parent.mkdir(parents=True, exist_ok=True)
    image = np.zeros((height, width, 3), np.uint8)
    image[5:20, 10:30] = (0, 0, 255)  # a red block: BGR order must survive the round trip
    assert cv2.imwrite(str(path), image)
    return image


def _manifest(folder: Path, *rows: str, name: str = "crops.csv") -> Path:
    path = folder / name
    path.write_text("\n".join((HEADER,) + rows) + "\n", encoding="utf-8")
    return path


@pytest.fixture
def folder(tmp_path):
    _write_image(tmp_path / "gtsrb" / "a.png")
    _write_image(tmp_path / "gtsrb" / "b.png", 64, 48)
    return tmp_path


def test_reads_rows_as_signs_with_xywh_boxes(folder):
    path = _manifest(folder, "gtsrb/a.png,10,5,30,20,2.30-50,same,tune,gtsrb-test",
                     "gtsrb/b.png,1,2,41,32,1.22,differs,report,gtsrb-test")
    signs = load_manifest(path)
    assert [s.ssv_id for s in signs] == ["2.30-50", "1.22"]
    assert signs[0].bbox == (10, 5, 20, 15)
    assert signs[1].bbox == (1, 2, 40, 30)
    assert signs[1].size_px == 40
    assert (signs[0].group, signs[0].split, signs[1].group, signs[1].split) == ("same", "tune", "differs", "report")
    assert signs[0].image == folder / "gtsrb" / "a.png"
    assert signs[1].line == 3


def test_load_image_returns_bgr_pixels_inside_the_box(folder):
    sign = load_manifest(_manifest(folder, "gtsrb/a.png,10,5,30,20,2.30-50,same,tune,gtsrb-test"))[0]
    image = sign.load_image()
    x, y, w, h = sign.bbox
    assert image.shape == (30, 40, 3)
    assert (image[y : y + h, x : x + w] == (0, 0, 255)).all()


def test_root_overrides_the_manifest_folder(folder, tmp_path_factory):
    elsewhere = tmp_path_factory.mktemp("manifests")
    path = _manifest(elsewhere, "gtsrb/a.png,0,0,5,5,3.01,same,tune,x")
    with pytest.raises(ManifestError, match="does not exist"):
        load_manifest(path)
    assert load_manifest(path, root=folder)[0].image == folder / "gtsrb" / "a.png"


@pytest.mark.parametrize(
    "row, field, message",
    [
        ("gtsrb/a.png,10,5,30,20,2.30-50,same,train,g", "split", "'train' is not one of tune, report"),
        ("gtsrb/a.png,10,5,30,20,2.30-50,similar,tune,g", "group", "'similar' is not one of same, differs"),
        ("gtsrb/a.png,10,five,30,20,2.30-50,same,tune,g", "y0", "not an integer: 'five'"),
        ("gtsrb/a.png,-1,5,30,20,2.30-50,same,tune,g", "x0", "must be >= 0, got -1"),
        ("gtsrb/a.png,30,5,30,20,2.30-50,same,tune,g", "x1", "x1=30 must be greater than x0=30"),
        ("gtsrb/a.png,10,25,30,20,2.30-50,same,tune,g", "y1", "y1=20 must be greater than y0=25"),
        ("gtsrb/a.png,10,5,30,20,,same,tune,g", "ssv_id", "not a catalogue id: ''"),
        ("gtsrb/a.png,10,5,30,20,2.30-50,same,tune,", "source", "empty"),
        ("gtsrb/missing.png,10,5,30,20,2.30-50,same,tune,g", "image", "does not exist"),
        ("/abs/a.png,10,5,30,20,2.30-50,same,tune,g", "image", "need a relative path"),
        ("../a.png,10,5,30,20,2.30-50,same,tune,g", "image", "need a relative path"),
    ],
)
def test_bad_rows_name_file_line_and_field(folder, row, field, message):
    path = _manifest(folder, "gtsrb/b.png,1,2,41,32,1.22,differs,report,g", row)
    with pytest.raises(ManifestError) as err:
        load_manifest(path)
    assert err.value.line == 3
    assert err.value.field == field
    assert str(err.value).startswith(f"{path}, line 3, field '{field}': ")
    assert message in str(err.value)


def test_unknown_id_is_rejected_against_the_catalogue(folder):
    path = _manifest(folder, "gtsrb/a.png,10,5,30,20,9.99,same,tune,g")
    assert load_manifest(path)[0].ssv_id == "9.99"
    with pytest.raises(ManifestError, match=r"line 2, field 'ssv_id': '9.99' is not in the catalogue"):
        load_manifest(path, known_ids={"2.30-50", "3.01"})


def test_short_row_missing_column_duplicate_and_empty_manifest(folder):
    with pytest.raises(ManifestError, match=r"line 2: expected 9 fields"):
        load_manifest(_manifest(folder, "gtsrb/a.png,10,5,30,20,2.30-50,same,tune"))
    path = folder / "nogroup.csv"
    path.write_text("image,x0,y0,x1,y1,ssv_id,split,source\n", encoding="utf-8")
    with pytest.raises(ManifestError, match=r"line 1: header lacks column\(s\) group"):
        load_manifest(path)
    row = "gtsrb/a.png,10,5,30,20,2.30-50,same,tune,g"
    with pytest.raises(ManifestError, match=r"line 3: the same image and box as line 2"):
        load_manifest(_manifest(folder, row, row))
    with pytest.raises(ManifestError, match="no signs listed"):
        load_manifest(_manifest(folder))
    (folder / "empty.csv").write_text("", encoding="utf-8")
    with pytest.raises(ManifestError, match="empty file"):
        load_manifest(folder / "empty.csv")
    with pytest.raises(ManifestError, match="manifest file does not exist"):
        load_manifest(folder / "nothing.csv")


def test_extra_columns_are_ignored(folder):
    path = folder / "extra.csv"
    path.write_text(HEADER + ",note\ngtsrb/a.png,10,5,30,20,3.02,same,report,g,faded\n", encoding="utf-8")
    assert load_manifest(path)[0].ssv_id == "3.02"


def test_load_image_names_a_box_outside_and_an_undecodable_file(folder):
    path = _manifest(folder, "gtsrb/a.png,10,5,41,20,3.01,same,tune,g")
    sign = load_manifest(path)[0]
    with pytest.raises(ManifestError, match=r"line 2: box x0=10 y0=5 x1=41 y1=20 leaves the 40x30 image"):
        sign.load_image()
    (folder / "gtsrb" / "broken.png").write_bytes(b"not a png")
    broken = RealSign(folder / "gtsrb" / "broken.png", (0, 0, 4, 4), "3.01", "same", "tune", "g")
    with pytest.raises(ManifestError, match="broken.png: image cannot be decoded"):
        broken.load_image()


def test_scene_list_reads_every_image_and_checks_rows(folder):
    path = folder / "scenes_images.csv"
    path.write_text("image,width,height,split,source,signs\n"
                    "gtsrb/a.png,40,30,tune,gtsdb,2\n"
                    "gtsrb/b.png,64,48,report,gtsdb,0\n", encoding="utf-8")
    scenes = load_scene_list(path)
    assert [(s.image.name, s.width, s.height, s.split, s.signs) for s in scenes] == [
        ("a.png", 40, 30, "tune", 2), ("b.png", 64, 48, "report", 0)]
    path.write_text("image,width,height,split,source,signs\n"
                    "gtsrb/a.png,40,30,tune,gtsdb,2\n"
                    "gtsrb/a.png,40,30,tune,gtsdb,2\n", encoding="utf-8")
    with pytest.raises(ManifestError, match=r"line 3, field 'image': image listed twice \(first on line 2\)"):
        load_scene_list(path)
    path.write_text("image,width,height,split,source,signs\ngtsrb/a.png,0,30,tune,gtsdb,2\n", encoding="utf-8")
    with pytest.raises(ManifestError, match=r"line 2, field 'width': must be >= 1, got 0"):
        load_scene_list(path)


def test_the_scene_column_is_optional_and_a_scene_is_in_one_split(folder):
    path = _manifest(folder, "gtsrb/a.png,10,5,30,20,3.01,same,tune,g")
    assert load_manifest(path)[0].scene == ""  # manifests written before the column read as before
    path.write_text(HEADER + ",scene\n"
                    "gtsrb/a.png,10,5,30,20,3.01,same,tune,g,00112\n"
                    "gtsrb/b.png,10,5,30,20,3.01,same,tune,g,00112\n"
                    "gtsrb/b.png,0,0,9,9,3.01,same,report,g,\n", encoding="utf-8")
    assert [s.scene for s in load_manifest(path)] == ["00112", "00112", ""]
    path.write_text(HEADER + ",scene\n"
                    "gtsrb/a.png,10,5,30,20,3.01,same,tune,g,00112\n"
                    "gtsrb/b.png,10,5,30,20,3.01,same,report,g,00112\n", encoding="utf-8")
    with pytest.raises(ManifestError, match=r"line 3, field 'scene': scene '00112' is report here but tune on "
                                            r"line 2: a scene belongs to one split"):
        load_manifest(path)
    listing = folder / "scenes_images.csv"
    listing.write_text("image,width,height,split,source,signs,scene\n"
                       "gtsrb/a.png,40,30,tune,gtsdb,2,00110\n"
                       "gtsrb/b.png,64,48,report,gtsdb,0,00110\n", encoding="utf-8")
    with pytest.raises(ManifestError, match=r"line 3, field 'scene': scene '00110' is report here but tune"):
        load_scene_list(listing)
