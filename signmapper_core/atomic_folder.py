"""A drive folder appears whole or not at all: written in a hidden sibling, renamed when complete.

Writers of drives (the synthetic generator, the importer) build the folder in
``.<name>.partial-<pid>`` next to the target and rename it at the end, so a
failed or cancelled run leaves nothing that looks like a drive. The folder of
a run that was killed (its process is gone) is removed by the next run for the
same target.
"""

from __future__ import annotations

import os
import shutil
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator


def check_target(out_dir: Path) -> None:
    """A drive is written only into a new or empty folder: FileExistsError naming it otherwise."""
    out_dir = Path(out_dir)
    if out_dir.exists() and (not out_dir.is_dir() or any(out_dir.iterdir())):
        raise FileExistsError(f"{out_dir}: exists and is not an empty folder")


def partial_folder(out_dir: Path) -> Path:
    """The hidden sibling this process writes ``out_dir`` into."""
    out_dir = Path(out_dir)
    return out_dir.parent / f".{out_dir.name}.partial-{os.getpid()}"


def _process_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    return True


def remove_stale_partials(out_dir: Path) -> list[Path]:
    """Delete the partial folders of earlier runs for ``out_dir`` whose process no longer exists (killed)."""
    out_dir = Path(out_dir)
    removed = []
    for folder in out_dir.parent.glob(f".{out_dir.name}.partial-*"):
        pid = folder.name.rsplit("-", 1)[-1]
        if folder.is_dir() and pid.isdigit() and (int(pid) == os.getpid() or not _process_alive(int(pid))):
            shutil.rmtree(folder, ignore_errors=True)
            removed.append(folder)
    return removed


@contextmanager
def writing_folder(out_dir) -> Iterator[Path]:
    """Yield a fresh partial folder; on normal exit it becomes ``out_dir``, on any exception it is deleted.

    ``out_dir`` must not exist or be empty (checked first, FileExistsError).
    """
    out_dir = Path(out_dir)
    check_target(out_dir)
    remove_stale_partials(out_dir)
    tmp = partial_folder(out_dir)
    tmp.mkdir(parents=True)
    try:
        yield tmp
        if out_dir.exists():
            out_dir.rmdir()
        tmp.rename(out_dir)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
