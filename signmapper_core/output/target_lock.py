"""One writer at a time per output: a lock file beside the target, held for as long as a run writes it.

The lock is the operating system's file lock (``flock``; ``msvcrt.locking`` on
Windows) on ``.<name>.signmapper-lock``. The system drops it when its process
ends, however it ends (``kill -9`` included), so a lock that can be taken says
that no live run writes the target: its partial files are stale. Two tasks of
one process (QGIS runs algorithms side by side) exclude each other too, since
each opens the file itself. The file holds the writer's process id and start
time, for the message the other run shows.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

from ..errors import OutputBusyError

LOCK_SUFFIX = ".signmapper-lock"

try:
    import fcntl
except ImportError:  # Windows
    fcntl = None
    import msvcrt


def lock_path(target) -> Path:
    target = Path(target)
    return target.parent / f".{target.name}{LOCK_SUFFIX}"


def _try_lock(fd: int) -> bool:
    try:
        if fcntl is not None:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        else:
            msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
    except OSError:  # BlockingIOError: held by another open file
        return False
    return True


def _unlock(fd: int) -> None:
    if fcntl is not None:
        fcntl.flock(fd, fcntl.LOCK_UN)
    else:
        os.lseek(fd, 0, os.SEEK_SET)
        msvcrt.locking(fd, msvcrt.LK_UNLCK, 1)


def _holder(fd: int) -> str:
    try:
        os.lseek(fd, 0, os.SEEK_SET)
        return os.read(fd, 200).decode("utf-8", "replace").strip()
    except OSError:
        return ""


class TargetLock:
    """The lock of one output target; :meth:`acquire` raises :class:`OutputBusyError` when a live run holds it."""

    def __init__(self, target):
        self.target = Path(target)
        self.path = lock_path(self.target)
        self._fd: int | None = None

    def acquire(self) -> TargetLock:
        """Take the lock without waiting; the target's folder is created when missing."""
        self.target.parent.mkdir(parents=True, exist_ok=True)
        while True:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
            if not _try_lock(fd):
                holder = _holder(fd)
                os.close(fd)
                raise OutputBusyError(f"{self.target}: another run is writing this output right now"
                                      f"{f' ({holder})' if holder else ''}; wait until it has ended, or choose "
                                      "another file")
            if self._still_named(fd):
                break
            os.close(fd)  # its last holder removed the file after we opened it: take the one there now
        try:
            os.ftruncate(fd, 0)
            os.write(fd, f"process {os.getpid()}, since {time.strftime('%Y-%m-%d %H:%M:%S')}".encode())
        except OSError:  # a full disk: the note is only for the message, the lock holds without it
            pass
        self._fd = fd
        return self

    def _still_named(self, fd: int) -> bool:
        try:
            return os.path.samestat(os.fstat(fd), os.stat(self.path))
        except OSError:
            return False

    @property
    def held(self) -> bool:
        return self._fd is not None

    def release(self) -> None:
        """Remove the lock file (while holding it: a run that opened it meanwhile sees it gone) and unlock."""
        if self._fd is None:
            return
        try:
            os.unlink(self.path)
        except OSError:  # Windows cannot remove an open file: it stays and is taken again next time
            pass
        try:
            _unlock(self._fd)
        finally:
            os.close(self._fd)
            self._fd = None

    def __enter__(self) -> TargetLock:
        return self.acquire()

    def __exit__(self, *exc) -> None:
        self.release()
