"""Every output is written whole or not at all: built in a hidden partial folder, moved in when complete.

One mechanism for all writers (the QGIS algorithms' outputs, the drive
writers, the crops, the QGIS-free GeoPackage writer): :class:`PartialOutput`
takes the target's lock (:mod:`target_lock`), builds the new output in
``.<name>.signmapper-partial`` beside it and moves it over the target only in
:meth:`~PartialOutput.commit`. A failed or cancelled run discards the partial
folder; an earlier output stays as it was. A run that was killed leaves its
partial folder and lock file behind: the next run writing into the same folder
removes them (:func:`remove_stale_partials`), since their lock can be taken.
"""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

from ..errors import OutputBusyError, OutputFileError, OutputWriteError
from .target_lock import LOCK_SUFFIX, TargetLock

PARTIAL_SUFFIX = ".signmapper-partial"
# what writers leave beside a target: ours now, and the partial files and folders of earlier versions
# (".<stem>.partial.gpkg" with SQLite's side files, ".<name>.partial-<pid>", ".<stem>_crops.partial")
LEFT_BEHIND = re.compile(r"^\.(?P<name>.+?)(?:" + re.escape(PARTIAL_SUFFIX) + "|" + re.escape(LOCK_SUFFIX)
                         + r"|\.partial(?:-\d+)?(?P<ext>\.gpkg)?(?:-journal|-wal|-shm)?)$")
FULL_DISK_BYTES = 4 * 1024 * 1024  # less free space than this after a failed write: the disk is full


def partial_folder(target) -> Path:
    target = Path(target)
    return target.parent / f".{target.name}{PARTIAL_SUFFIX}"


def remove_stale_partials(folder) -> list[Path]:
    """Remove what runs that are gone left in ``folder`` (partial outputs, lock files); returns what was removed.

    A target whose lock can be taken has no live writer; live runs' files are left alone.
    """
    folder = Path(folder)
    try:
        entries = list(folder.iterdir())
    except OSError:
        return []
    by_target: dict[str, list[Path]] = {}
    for entry in entries:
        match = LEFT_BEHIND.match(entry.name)
        if match:
            by_target.setdefault(match["name"] + (match["ext"] or ""), []).append(entry)
    removed = []
    for name, leftovers in by_target.items():
        lock = TargetLock(folder / name)
        try:
            lock.acquire()
        except (OutputBusyError, OSError):
            continue
        try:
            for entry in leftovers:
                if entry != lock.path:
                    _remove(entry)
                    removed.append(entry)
        finally:
            lock.release()
    return removed


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        path.unlink(missing_ok=True)


def write_failure(target, what: str, detail) -> OutputWriteError:
    """The error of a write that failed part way: names the target and what was written, and says so when
    the disk is full (the file system's own words rarely do: "Error looking for style")."""
    target = Path(target)
    text = f"{target}: could not write {what}: {detail}"
    try:
        free = shutil.disk_usage(_existing(target.parent)).free
    except OSError:
        free = None
    if free is not None and free < FULL_DISK_BYTES or "disk is full" in str(detail) or "No space" in str(detail):
        left = f", {free // 1024} kB free" if free is not None else ""
        text += f" (the disk holding {target.parent} is full{left}: free some space, or write to another disk)"
    return OutputWriteError(text)


def _existing(folder: Path) -> Path:
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    return folder


class PartialOutput:
    """``target`` (a file; a folder with ``folder=True``) written in a hidden partial folder under its lock.

    Construction takes the lock (:class:`OutputBusyError` when another run holds it) and clears what killed
    runs left in the target's folder. Write to :attr:`path`, then :meth:`commit` or :meth:`discard`; either
    releases the lock. A folder target replaces only a missing or empty folder, unless ``replace_folder``
    (its contents are the writer's own, e.g. the crops of the last run).
    """

    def __init__(self, target, folder: bool = False, replace_folder: bool = False):
        self.target = Path(target)
        self.is_folder = folder
        self.replace_folder = replace_folder
        self.partial = partial_folder(self.target)
        self.lock = TargetLock(self.target).acquire()
        try:
            remove_stale_partials(self.target.parent)
            _remove(self.partial)  # ours by the lock: what a killed run of the same target left
        except BaseException:
            self.lock.release()
            raise

    @property
    def existed(self) -> bool:
        """Whether there is an earlier output (it stays as it is until the commit)."""
        return self.target.exists()

    @property
    def path(self) -> Path:
        """Where the new output is written: the partial folder for a folder target, the target's name in it
        for a file (its side files, e.g. a shapefile's, go beside it)."""
        if not self.partial.is_dir():
            try:
                self.partial.mkdir(parents=True)
            except OSError as exc:
                raise write_failure(self.target, "the partial output", exc.strerror or exc) from exc
        return self.partial if self.is_folder else self.partial / self.target.name

    def commit(self) -> str:
        """Move the new output over the target; returns the target's path."""
        if not self.is_folder and not self.partial.exists():  # nothing was written: the target stays
            self.lock.release()
            return str(self.target)
        try:
            if self.is_folder:
                self._commit_folder()
            else:
                for entry in sorted(self.path.parent.iterdir(), key=lambda p: p.name == self.target.name):
                    os.replace(entry, self.target.parent / entry.name)  # the main file last
                self.partial.rmdir()
        except BaseException as exc:
            self.discard()
            if isinstance(exc, OSError):
                raise write_failure(self.target, "the finished output over the earlier one", exc.strerror or exc) \
                    from exc
            raise
        self.lock.release()
        return str(self.target)

    def _commit_folder(self) -> None:
        self.partial.mkdir(parents=True, exist_ok=True)  # nothing written is still an (empty) folder
        if self.target.is_dir() and any(self.target.iterdir()):
            if not self.replace_folder:
                raise OutputFileError(f"{self.target}: exists and is not an empty folder")
            shutil.rmtree(self.target)
        elif self.target.is_dir():
            self.target.rmdir()
        os.rename(self.partial, self.target)

    def discard(self) -> None:
        """Drop the partial output (the target stays as it was) and release the lock."""
        try:
            _remove(self.partial)
        finally:
            self.lock.release()
