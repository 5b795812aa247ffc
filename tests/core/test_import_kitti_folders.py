"""A folder that is not a KITTI raw drive folder says which drive folders it holds (issue 45, items 4.2 and 4.3).

Empty folder trees as KITTI's downloads unpack (download folder / date folder / drive folder with image_02,
image_03, oxts): no file of KITTI's is needed to tell the folders apart.
"""

import pytest

from signmapper_core.errors import ImportInputError
from signmapper_core.importdrive import kitti_source
from signmapper_core.importdrive.__main__ import main
from signmapper_core.importdrive.kitti import drive_folders_in, is_kitti_drive

NOT_A_DRIVE = "is not a KITTI raw drive folder (no image_02/, image_03/, oxts/)"


def drive(root, date, number, kind="sync"):
    folder = root / date / f"{date}_drive_{number:04d}_{kind}"
    for part in ("image_02/data", "image_03/data", "oxts/data"):
        (folder / part).mkdir(parents=True)
    return folder


def refusal(folder) -> str:
    with pytest.raises(ImportInputError) as caught:
        kitti_source(folder)
    return str(caught.value)


def test_the_date_and_the_download_folder_name_the_drive_folders_in_them(tmp_path):
    download = tmp_path / "kitti"
    drive(download, "2011_09_26", 5)
    drive(download, "2011_09_26", 1)
    drive(download, "2011_09_29", 71, "extract")
    assert refusal(download) == (
        f"{download}: {NOT_A_DRIVE}; it holds 3 drive folders: 2011_09_26/2011_09_26_drive_0001_sync, "
        "2011_09_26/2011_09_26_drive_0005_sync, 2011_09_29/2011_09_29_drive_0071_extract; give one of them as the "
        "KITTI drive folder")
    date = download / "2011_09_29"
    assert refusal(date) == (f"{date}: {NOT_A_DRIVE}; it holds the drive folder 2011_09_29_drive_0071_extract; give "
                             "it as the KITTI drive folder")


def test_many_drive_folders_are_counted_and_a_folder_inside_a_drive_names_the_drive(tmp_path):
    for number in range(1, 8):
        drive(tmp_path, "2011_09_26", number)
    message = refusal(tmp_path / "2011_09_26")
    assert "it holds 7 drive folders: 2011_09_26_drive_0001_sync, " in message
    assert "2011_09_26_drive_0005_sync and 2 more; give one of them" in message
    images = tmp_path / "2011_09_26" / "2011_09_26_drive_0003_sync" / "image_02"
    assert refusal(images) == (f"{images}: {NOT_A_DRIVE}; it lies in the drive folder {images.parent}: give that one")


def test_a_folder_without_drive_folders_says_so(tmp_path):
    drive(tmp_path / "a" / "b", "2011_09_26", 1)       # four levels down: beyond the search
    assert drive_folders_in(tmp_path) == []
    assert refusal(tmp_path) == (
        f"{tmp_path}: {NOT_A_DRIVE}, and no drive folder (<date>_drive_<nnnn>_sync or _extract) is in it or 2 levels "
        "below; give a drive folder such as 2011_09_26/2011_09_26_drive_0001_sync")
    assert len(drive_folders_in(tmp_path / "a")) == 1


def test_a_drive_folder_with_a_camera_missing_still_names_the_missing_images(tmp_path):
    folder = drive(tmp_path, "2011_09_26", 1)
    (folder / "image_02" / "data").rmdir()
    assert is_kitti_drive(folder)
    assert refusal(folder) == f"{folder / 'image_02' / 'data'}: image folder does not exist"


def test_the_command_line_sends_a_kitti_folder_given_as_left_images_to_kitti(tmp_path):
    folder = drive(tmp_path, "2011_09_26", 1)
    with pytest.raises(SystemExit) as caught:
        main([str(tmp_path / "out"), "--left", str(folder)])
    assert str(caught.value) == (f"error: {folder} is a KITTI raw drive folder, which the generic import does not "
                                 f"read: give it as --kitti {folder}")
