"""A drive folder appears whole or not at all: written by :class:`~signmapper_core.output.partial_output.PartialOutput`.

Writers of drives (the synthetic generator, the importer) build the folder in
its hidden partial folder next to the target, under the target's lock, and
move it in at the end, so a failed or cancelled run leaves nothing that looks
like a drive, and a second run writing the same drive at the same time is
refused. What a killed run left is removed by the next run writing into the
same folder.
"""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from ..output.partial_output import PartialOutput


def check_target(out_dir: Path) -> None:
    """A drive is written only into a new or empty folder: FileExistsError naming it otherwise."""
    out_dir = Path(out_dir)
    if out_dir.exists() and (not out_dir.is_dir() or any(out_dir.iterdir())):
        raise FileExistsError(f"{out_dir}: exists and is not an empty folder")


@contextmanager
def writing_folder(out_dir) -> Iterator[Path]:
    """Yield a fresh partial folder; on normal exit it becomes ``out_dir``, on any exception it is deleted.

    ``out_dir`` must not exist or be empty (checked first, FileExistsError); ``OutputBusyError`` when another
    run writes it.
    """
    out_dir = Path(out_dir)
    check_target(out_dir)
    output = PartialOutput(out_dir, folder=True)
    try:
        yield output.path
    except BaseException:
        output.discard()
        raise
    output.commit()
