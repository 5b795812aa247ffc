"""KITTI raw drive 2011_09_26_drive_0001 from a local git copy into a cache outside the repository.

    .venv/bin/python -m scripts.kitti_drive --repo GIT_DIR [--cache DIR]
    make kitti-drive KITTI_REPO=GIT_DIR

KITTI is CC BY-NC-SA 3.0: its images never enter this repository. A public repository holds the drive as plain
files (``SOURCE_REPOSITORY`` at ``SOURCE_COMMIT``); this tool takes the left and right colour images, the OXTS
packets and the date's calibration out of a local copy of it (a bare git dir, or a clone) and lays them out as
KITTI ships them: ``<cache>/2011_09_26/2011_09_26_drive_0001_sync/{image_02,image_03,oxts}`` and
``<cache>/2011_09_26/calib_*.txt``. The files are written into a temporary folder in the cache and renamed into
place, the drive folder last, so a drive folder that is there is whole; a second run says so and writes nothing.
tests/core/test_kitti_drive.py maps the drive from the cache (tests/data/kitti/README.md).
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

SOURCE_REPOSITORY = "github.com/stilandstul98-tech/open_cv"
SOURCE_COMMIT = "5558ad1f90a9c60d2a119b2c9083dcabe40dd2d5"
DATE = "2011_09_26"
DRIVE = f"{DATE}_drive_0001_sync"
# what is taken, as (folder in the source repository, folder under the cache's date folder)
SOURCE_FOLDERS = tuple((f"{DRIVE}/{DATE}/{DRIVE}/{name}", f"{DRIVE}/{name}")
                       for name in ("image_02", "image_03", "oxts"))
CALIBRATION_FOLDER = f"{DATE}_calib/{DATE}"
CALIBRATION_FILES = ("calib_cam_to_cam.txt", "calib_imu_to_velo.txt", "calib_velo_to_cam.txt")
CACHE_VARIABLE = "SIGNMAPPER_KITTI_CACHE"
DEFAULT_CACHE = Path("~/.cache/sign_mapper/kitti")


class SourceError(ValueError):
    """The given path is no git dir holding the commit and folders of the drive; the message says which."""


def cache_folder(given=None) -> Path:
    """The cache: ``given``, else $SIGNMAPPER_KITTI_CACHE, else ~/.cache/sign_mapper/kitti."""
    return Path(given or os.environ.get(CACHE_VARIABLE) or DEFAULT_CACHE).expanduser()


def drive_folder(cache: Path) -> Path:
    """The KITTI drive folder (``..._sync``) in ``cache``."""
    return cache / DATE / DRIVE


def is_complete(cache: Path) -> bool:
    """The drive folder and the calibration are in ``cache`` (the drive folder is renamed in last)."""
    return drive_folder(cache).is_dir() and all((cache / DATE / name).is_file() for name in CALIBRATION_FILES)


def git_dir(repo: Path) -> Path:
    """``repo`` itself when it is a git dir, its ``.git`` when it is a clone."""
    for candidate in (repo / ".git", repo):
        if (candidate / "objects").is_dir() and (candidate / "HEAD").is_file():
            return candidate
    raise SourceError(f"{repo}: not a git directory (no objects/ and HEAD in it or in its .git)")


def _git_command(gitdir: Path, *args: str) -> list:
    return ["git", f"--git-dir={gitdir}", *args]


def _git(gitdir: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(_git_command(gitdir, *args), capture_output=True, check=False)


def check_source(gitdir: Path) -> None:
    """Raise :class:`SourceError` unless ``gitdir`` holds ``SOURCE_COMMIT`` with every folder and file taken."""
    if _git(gitdir, "cat-file", "-e", f"{SOURCE_COMMIT}^{{commit}}").returncode != 0:
        raise SourceError(f"{gitdir}: does not hold commit {SOURCE_COMMIT} of {SOURCE_REPOSITORY}")
    wanted = [folder for folder, _ in SOURCE_FOLDERS] + [f"{CALIBRATION_FOLDER}/{n}" for n in CALIBRATION_FILES]
    missing = [path for path in wanted if not _git(gitdir, "ls-tree", SOURCE_COMMIT, "--", path).stdout.strip()]
    if missing:
        raise SourceError(f"{gitdir}: commit {SOURCE_COMMIT[:12]} has no {', '.join(missing)}")


def extract(gitdir: Path, into: Path) -> None:
    """The taken folders and files of ``SOURCE_COMMIT`` under ``into`` as KITTI lays them out (``into/2011_09_26``)."""
    paths = [folder for folder, _ in SOURCE_FOLDERS] + [CALIBRATION_FOLDER]
    renames = [(f"{CALIBRATION_FOLDER}/", "")] + [(f"{src}/", f"{dst}/") for src, dst in SOURCE_FOLDERS]
    command = _git_command(gitdir, "archive", "--format=tar", SOURCE_COMMIT, "--", *paths)
    unreadable = None
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as git:
        try:
            with tarfile.open(fileobj=git.stdout, mode="r|") as tar:  # streamed: ~190 MB
                for member in tar:
                    if member.isfile():
                        prefix, target = next((p, t) for p, t in renames if member.name.startswith(p))
                        path = into / DATE / (target + member.name[len(prefix):])
                        path.parent.mkdir(parents=True, exist_ok=True)
                        path.write_bytes(tar.extractfile(member).read())
        except tarfile.TarError as exc:  # git stopped (its message says why), or its output is broken
            unreadable = exc
        failure = git.stderr.read().decode(errors="replace").strip()
    if git.returncode != 0 or unreadable is not None:
        raise SourceError(f"{gitdir}: git archive of commit {SOURCE_COMMIT[:12]} failed: {failure or unreadable}")


def fetch_drive(repo: Path, cache: Path, say=print) -> Path:
    """The drive folder in ``cache``, extracted from the git copy ``repo`` unless it is there already."""
    if is_complete(cache):
        say(f"already there: {drive_folder(cache)}")
        return drive_folder(cache)
    gitdir = git_dir(repo)
    check_source(gitdir)
    cache.mkdir(parents=True, exist_ok=True)
    partial = Path(tempfile.mkdtemp(prefix=".partial-", dir=cache))
    try:
        extract(gitdir, partial)
        (cache / DATE).mkdir(exist_ok=True)
        for name in CALIBRATION_FILES:  # a date folder of an earlier KITTI download may hold them already
            if not (cache / DATE / name).exists():
                (partial / DATE / name).rename(cache / DATE / name)
        if not drive_folder(cache).exists():
            drive_folder(partial).rename(drive_folder(cache))
    finally:
        shutil.rmtree(partial, ignore_errors=True)
    say(f"written: {drive_folder(cache)} and the calibration in {cache / DATE}")
    return drive_folder(cache)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m scripts.kitti_drive",
        description="Take KITTI raw drive 2011_09_26_drive_0001 (image_02, image_03, oxts, calibration) out of a "
                    f"local git copy of {SOURCE_REPOSITORY} (commit {SOURCE_COMMIT[:12]}) into a cache outside "
                    "the repository, laid out as KITTI ships it.")
    parser.add_argument("--repo", type=Path, required=True,
                        help="the local copy: a bare git dir (e.g. a mirror's repo folder) or a clone")
    parser.add_argument("--cache", type=Path, default=None,
                        help=f"cache folder (default: ${CACHE_VARIABLE}, else {DEFAULT_CACHE})")
    args = parser.parse_args(argv)
    try:
        fetch_drive(args.repo, cache_folder(args.cache))
    except (SourceError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
