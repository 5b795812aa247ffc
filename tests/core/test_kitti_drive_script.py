"""``scripts.kitti_drive`` on a small git repository of our own laid out as the one holding the KITTI drive.

The commit is ours (its files a few bytes each), put in place of ``SOURCE_COMMIT``: what is taken, where it goes, a
second run, and the errors for a path that is no git dir, a missing commit and a commit without the drive.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from scripts import kitti_drive

SYNC = "2011_09_26_drive_0001_sync/2011_09_26/2011_09_26_drive_0001_sync"
FILES = {  # path in the source repository -> path under the cache, None: not taken
    f"{SYNC}/image_02/data/0000000000.png": "2011_09_26/2011_09_26_drive_0001_sync/image_02/data/0000000000.png",
    f"{SYNC}/image_02/timestamps.txt": "2011_09_26/2011_09_26_drive_0001_sync/image_02/timestamps.txt",
    f"{SYNC}/image_03/data/0000000000.png": "2011_09_26/2011_09_26_drive_0001_sync/image_03/data/0000000000.png",
    f"{SYNC}/oxts/data/0000000000.txt": "2011_09_26/2011_09_26_drive_0001_sync/oxts/data/0000000000.txt",
    f"{SYNC}/oxts/dataformat.txt": "2011_09_26/2011_09_26_drive_0001_sync/oxts/dataformat.txt",
    "2011_09_26_calib/2011_09_26/calib_cam_to_cam.txt": "2011_09_26/calib_cam_to_cam.txt",
    "2011_09_26_calib/2011_09_26/calib_imu_to_velo.txt": "2011_09_26/calib_imu_to_velo.txt",
    "2011_09_26_calib/2011_09_26/calib_velo_to_cam.txt": "2011_09_26/calib_velo_to_cam.txt",
    f"{SYNC}/image_00/data/0000000000.png": None,
    f"{SYNC}/velodyne_points/data/0000000000.bin": None,
    "README.MD": None,
}


def _git(folder: Path, *args: str) -> str:
    return subprocess.run(["git", "-C", str(folder), "-c", "user.name=t", "-c", "user.email=t@t", *args],
                          check=True, capture_output=True, text=True).stdout.strip()


def _repository(folder: Path, files) -> str:
    """A git repository in ``folder`` with ``files`` (each holding its own path) committed; the commit's hash."""
    _git(folder.parent, "init", "-q", folder.name)
    for name in files:
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(name, encoding="utf-8")
    _git(folder, "add", "-A")
    _git(folder, "commit", "-q", "-m", "drive")
    return _git(folder, "rev-parse", "HEAD")


@pytest.fixture
def source(tmp_path, monkeypatch):
    """A clone-like repository holding the drive's layout, its commit standing for ``SOURCE_COMMIT``."""
    commit = _repository(tmp_path / "open_cv", FILES)
    monkeypatch.setattr(kitti_drive, "SOURCE_COMMIT", commit)
    return tmp_path / "open_cv"


def test_takes_the_drive_and_calibration_as_kitti_lays_them_out(source, tmp_path):
    cache = tmp_path / "cache"
    said = []
    drive = kitti_drive.fetch_drive(source, cache, say=said.append)
    assert drive == cache / "2011_09_26" / "2011_09_26_drive_0001_sync" and kitti_drive.is_complete(cache)
    written = sorted(p.relative_to(cache).as_posix() for p in cache.rglob("*") if p.is_file())
    assert written == sorted(target for target in FILES.values() if target)
    for name, target in FILES.items():
        if target:
            assert (cache / target).read_text(encoding="utf-8") == name
    assert said == [f"written: {drive} and the calibration in {cache / '2011_09_26'}"]


def test_a_second_run_says_it_is_there_and_writes_nothing(source, tmp_path):
    cache = tmp_path / "cache"
    kitti_drive.fetch_drive(source, cache, say=lambda message: None)
    image = cache / FILES[f"{SYNC}/image_02/data/0000000000.png"]
    image.write_text("kept", encoding="utf-8")
    said = []
    kitti_drive.fetch_drive(source, cache, say=said.append)
    assert said == [f"already there: {kitti_drive.drive_folder(cache)}"]
    assert image.read_text(encoding="utf-8") == "kept"


def test_a_bare_git_dir_serves_as_well(source, tmp_path):
    bare = tmp_path / "mirror.git"
    subprocess.run(["git", "clone", "-q", "--bare", str(source), str(bare)], check=True)
    kitti_drive.fetch_drive(bare, tmp_path / "cache", say=lambda message: None)
    assert kitti_drive.is_complete(tmp_path / "cache")


def test_a_failed_extraction_leaves_nothing_behind(source, tmp_path, monkeypatch):
    def half_written(gitdir, into):
        (into / "2011_09_26" / "2011_09_26_drive_0001_sync").mkdir(parents=True)
        raise OSError("disk full")

    monkeypatch.setattr(kitti_drive, "extract", half_written)
    cache = tmp_path / "cache"
    with pytest.raises(OSError, match="disk full"):
        kitti_drive.fetch_drive(source, cache, say=lambda message: None)
    assert list(cache.iterdir()) == []


@pytest.mark.parametrize("case", ("no git dir", "no such commit", "commit without the drive"))
def test_wrong_sources_are_named_and_nothing_is_written(case, tmp_path, monkeypatch, capsys):
    repo = tmp_path / "repo"
    if case == "no git dir":
        repo.mkdir()
        expected = f"{repo}: not a git directory"
    elif case == "no such commit":
        _repository(repo, ["README.MD"])
        expected = f"does not hold commit {kitti_drive.SOURCE_COMMIT} of {kitti_drive.SOURCE_REPOSITORY}"
    else:
        monkeypatch.setattr(kitti_drive, "SOURCE_COMMIT", _repository(repo, [f"{SYNC}/image_02/data/0.png"]))
        expected = f"has no {SYNC}/image_03, {SYNC}/oxts, 2011_09_26_calib/2011_09_26/calib_cam_to_cam.txt"
    cache = tmp_path / "cache"
    assert kitti_drive.main(["--repo", str(repo), "--cache", str(cache)]) == 2
    assert expected in capsys.readouterr().err
    assert not cache.exists() or list(cache.iterdir()) == []


def test_the_cache_is_the_given_folder_else_the_environment_s_else_the_default(monkeypatch, tmp_path):
    monkeypatch.delenv(kitti_drive.CACHE_VARIABLE, raising=False)
    assert kitti_drive.cache_folder() == Path.home() / ".cache" / "sign_mapper" / "kitti"
    monkeypatch.setenv(kitti_drive.CACHE_VARIABLE, str(tmp_path / "env"))
    assert kitti_drive.cache_folder() == tmp_path / "env"
    assert kitti_drive.cache_folder(tmp_path / "given") == tmp_path / "given"
