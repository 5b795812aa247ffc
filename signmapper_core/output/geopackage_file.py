"""A GeoPackage output that keeps what is not the writer's (no QGIS: every writer of GeoPackages shares it).

Built as a :class:`~signmapper_core.output.partial_output.PartialOutput`: a failed or
cancelled run leaves an earlier file untouched. An existing GeoPackage is
copied into the partial file first and only the writer's ``owned`` layers are
replaced: the user's layers, styles and tables stay. A file of that name that
is no GeoPackage is refused. Layers written into a file the user named (the
feature-sink outputs) are marked as ours in ``gpkg_contents.description``, so a
later run replaces its own layer, never a user's layer of the same name.
"""

from __future__ import annotations

import sqlite3
from contextlib import closing
from pathlib import Path

from ..errors import OutputFileError
from .partial_output import PartialOutput, write_failure
from .run_table import RUN_TABLE
from .schema import DETECTIONS, SIGNS

OUR_TABLES = (SIGNS, DETECTIONS, RUN_TABLE)
STYLE_TABLE = "layer_styles"  # QGIS's styles of every layer in the file: kept, minus the replaced layers' ones
SQLITE_HEADER = b"SQLite format 3\x00"
OUR_MARK = "Sign Mapper"  # gpkg_contents.description of a layer written into a file the user named


def _read_only(path: Path):
    return closing(sqlite3.connect(f"{path.resolve().as_uri()}?mode=ro", uri=True))


def geopackage_tables(path) -> list[str] | None:
    """Tables (layers) of an existing GeoPackage; None where there is no file or an empty one.

    Raises OutputFileError when the file exists but is no GeoPackage: it is not ours to replace.
    """
    contents = geopackage_contents(path)
    return None if contents is None else list(contents)


def geopackage_contents(path) -> dict[str, str] | None:
    """Table -> description of an existing GeoPackage's layers; None where there is no file or an empty one.

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
        with _read_only(path) as db:
            return {name: description or "" for name, description in
                    db.execute("SELECT table_name, description FROM gpkg_contents")}
    except sqlite3.Error as exc:
        raise OutputFileError(f"{refused} ({exc})") from exc


def is_ours(description: str) -> bool:
    return description.startswith(OUR_MARK)


class PartialGeoPackage(PartialOutput):
    """A GeoPackage built layer by layer in a partial file, committed at the end.

    ``owned`` are the layers the writer (re)writes; ``kept`` lists the other layers of an existing target,
    carried over unchanged. :attr:`path` makes the partial file (a copy of the target when there is
    something to keep) the first time it is asked for.
    """

    def __init__(self, target, owned=OUR_TABLES):
        target = Path(target)
        if target.suffix.lower() != ".gpkg":
            raise OutputFileError(f"{target}: the output must be a GeoPackage file ending in .gpkg")
        tables = geopackage_tables(target) or []
        super().__init__(target)
        self.owned = tuple(owned)
        self.kept = [t for t in tables if t not in self.owned + (STYLE_TABLE,)]
        self._made = False

    @property
    def starts_empty(self) -> bool:
        """Whether the first layer creates the file (nothing of an earlier file is kept)."""
        return not self.kept

    @property
    def path(self) -> Path:
        path = super().path
        if not self._made:
            self._made = True
            if self.kept:
                self._copy_target(path)
        return path

    def _copy_target(self, copy_path: Path) -> None:
        """The target's contents into the partial file (SQLite's backup: consistent even with a WAL), without
        the layers about to be replaced and their styles.

        The styles go too: saving a style over an existing one of the same name hangs QGIS 3.22 when run
        headless (it opens a window no one can answer).
        """
        try:
            with _read_only(self.target) as source, closing(sqlite3.connect(copy_path)) as copy:
                source.backup(copy)
                if copy.execute("SELECT 1 FROM sqlite_master WHERE name = ?", (STYLE_TABLE,)).fetchone():
                    marks = ", ".join("?" * len(self.owned))
                    copy.execute(f"DELETE FROM {STYLE_TABLE} WHERE f_table_name IN ({marks})", self.owned)
                    copy.commit()
            self._delete_layers(copy_path, [t for t in geopackage_tables(copy_path) or [] if t in self.owned])
        except (sqlite3.Error, OSError, RuntimeError) as exc:
            raise write_failure(self.target, "a copy of its layers to keep", exc) from exc

    @staticmethod
    def _delete_layers(path: Path, names: list[str]) -> None:
        """Remove layers with GDAL, which also drops their spatial index, metadata and registrations."""
        if not names:
            return
        from osgeo import gdal

        dataset = gdal.OpenEx(str(path), gdal.OF_VECTOR | gdal.OF_UPDATE)
        if dataset is None:
            raise RuntimeError(gdal.GetLastErrorMsg() or "GDAL cannot open it")
        for name in names:
            for index in range(dataset.GetLayerCount()):
                if dataset.GetLayer(index).GetName() == name:
                    if dataset.DeleteLayer(index) != 0:
                        raise RuntimeError(f"GDAL cannot remove the layer '{name}': {gdal.GetLastErrorMsg()}")
                    break
        dataset = None

    def mark_ours(self, layers, what: str) -> None:
        """Record in ``gpkg_contents`` that ``layers`` of the partial file are Sign Mapper's (``what`` wrote them)."""
        try:
            with closing(sqlite3.connect(self.path)) as db:
                db.executemany("UPDATE gpkg_contents SET description = ? WHERE table_name = ?",
                               [(f"{OUR_MARK}: {what}", name) for name in layers])
                db.commit()
        except sqlite3.Error as exc:
            raise write_failure(self.target, f"the description of the layer {', '.join(layers)}", exc) from exc
