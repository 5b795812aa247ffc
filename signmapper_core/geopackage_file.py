"""A GeoPackage written without ever leaving a half-written file (no QGIS: both writers share it).

Layers go into a hidden ``.<name>.partial.gpkg`` beside the target; only a
completed run moves it over the target (an atomic rename on one file system).
A failed or cancelled run deletes the partial file and leaves any earlier
output untouched. An existing GeoPackage holding layers we did not write (the
user's own) is copied into the partial file first, so only our layers are
replaced; a file of that name that is no GeoPackage is refused.
"""

from __future__ import annotations

import os
import sqlite3
from contextlib import closing
from pathlib import Path

from .output_schema import DETECTIONS, RUN_TABLE, SIGNS

OUR_TABLES = (SIGNS, DETECTIONS, RUN_TABLE)
STYLE_TABLE = "layer_styles"  # QGIS's styles of every layer in the file: kept, minus our layers' old ones
SQLITE_HEADER = b"SQLite format 3\x00"


class OutputFileError(ValueError):
    """The output file cannot be written as asked (not .gpkg, or an existing file that is no GeoPackage)."""


def geopackage_tables(path) -> list[str] | None:
    """Tables (layers) of an existing GeoPackage; None where there is no file or an empty one.

    Raises OutputFileError when the file exists but is no GeoPackage: it is not ours to replace.
    """
    path = Path(path)
    if not path.is_file() or path.stat().st_size == 0:
        return None
    refused = f"{path} exists and is not a GeoPackage; it is left as it is: choose another file name"
    with open(path, "rb") as fh:
        if fh.read(len(SQLITE_HEADER)) != SQLITE_HEADER:
            raise OutputFileError(refused)
    try:
        with closing(sqlite3.connect(f"{path.resolve().as_uri()}?mode=ro", uri=True)) as db:
            return [row[0] for row in db.execute("SELECT table_name FROM gpkg_contents")]
    except sqlite3.Error as exc:
        raise OutputFileError(f"{refused} ({exc})") from exc


class PartialGeoPackage:
    """A GeoPackage built layer by layer in a partial file, committed at the end.

    ``kept`` lists the layers of an existing target that are not ours: they are
    carried over unchanged. ``starts_empty``: the first layer creates the partial file.
    """

    def __init__(self, target, ours=OUR_TABLES):
        self.target = Path(target)
        self.ours = tuple(ours)  # the tables this writer replaces (a mapping run's, unless said otherwise)
        if self.target.suffix.lower() != ".gpkg":
            raise OutputFileError(f"{self.target}: the output must be a GeoPackage file ending in .gpkg")
        self.partial = self.target.with_name(f".{self.target.stem}.partial.gpkg")
        self.discard()
        self.kept = [t for t in geopackage_tables(self.target) or [] if t not in self.ours + (STYLE_TABLE,)]
        if self.kept:
            self._copy_target()

    @property
    def starts_empty(self) -> bool:
        return not self.kept

    def _copy_target(self) -> None:
        """The target's contents into the partial file (SQLite's backup: consistent even with a WAL).

        Our layers' old default styles are dropped from the copy: saving a style over an existing one of
        the same name hangs QGIS 3.22 when run headless (it opens a window no one can answer).
        """
        uri = f"{self.target.resolve().as_uri()}?mode=ro"
        with closing(sqlite3.connect(uri, uri=True)) as source, closing(sqlite3.connect(self.partial)) as copy:
            source.backup(copy)
            if copy.execute("SELECT 1 FROM sqlite_master WHERE name = ?", (STYLE_TABLE,)).fetchone():
                marks = ", ".join("?" * len(self.ours))
                copy.execute(f"DELETE FROM {STYLE_TABLE} WHERE f_table_name IN ({marks})", self.ours)
                copy.commit()

    def commit(self) -> str:
        os.replace(self.partial, self.target)
        return str(self.target)

    def discard(self) -> None:
        for suffix in ("", "-journal", "-wal", "-shm"):
            path = Path(str(self.partial) + suffix)
            if path.exists():
                path.unlink()
