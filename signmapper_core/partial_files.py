"""Files that appear whole or not at all: written in a hidden folder beside the target, moved in at the end.

For outputs that are more than one file or no GeoPackage (a shapefile's .shp, .dbf,
.shx, .prj and .cpg; a CSV; a PDF): the writer writes ``path`` inside the partial
folder; ``commit`` moves every file written there over its namesake beside the
target, ``discard`` deletes them, so a failed or cancelled run leaves an earlier
output as it was. (A GeoPackage has its own: ``geopackage_file``.)
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path


class PartialFiles:
    def __init__(self, target):
        self.target = Path(target)
        self.folder = self.target.with_name(f".{self.target.name}.partial")
        self.discard()
        self.folder.mkdir(parents=True)

    @property
    def path(self) -> Path:
        """Where to write the target (its sidecar files beside it)."""
        return self.folder / self.target.name

    def commit(self) -> str:
        for written in sorted(self.folder.iterdir()):
            os.replace(written, self.target.with_name(written.name))
        self.folder.rmdir()
        return str(self.target)

    def discard(self) -> None:
        shutil.rmtree(self.folder, ignore_errors=True)
