"""A GeoPackage written by ``mapsigns`` as plain data, and its comparison with a golden copy.

``gpkg_dump`` holds what a user of the file sees (tables, columns, features,
run table, abstracts); this adds what the embedded default styles show in QGIS.
"""

from __future__ import annotations

import json
from pathlib import Path

from gpkg_dump import differences  # noqa: F401 - re-exported: the golden test compares with it
from gpkg_dump import dump_gpkg as dump_tables


def _styles(path: Path) -> dict:
    """What the default style of each layer shows: renderer, its groups or categories, labels, aliases."""
    from qgis.core import QgsVectorLayer

    out = {}
    for name in ("signs", "detections"):
        layer = QgsVectorLayer(f"{path}|layername={name}", name, "ogr")
        renderer = layer.renderer()
        style = {"renderer": renderer.type(), "labels": None}
        if name == "detections":
            categories = renderer.categories()  # keep the list alive: its symbols belong to it
            style["attribute"] = renderer.classAttribute()
            style["categories"] = [[c.value(), c.symbol().color().name()] for c in categories]
        else:  # one pictogram per catalogue entry: the catalogue is not this file's schema; its family groups are
            groups = renderer.rootRule().children()
            style["groups"] = [[g.label(), len(g.children()), g.isElse()] for g in groups]
        if layer.labelsEnabled():
            style["labels"] = layer.labeling().settings().fieldName
        style["aliases"] = {f.name(): f.alias() for f in layer.fields() if f.alias()}
        out[name] = style
    return out


def dump_gpkg(path: Path, drive_dir: Path) -> dict:
    """The GeoPackage ``path`` written from ``drive_dir`` as JSON-able data, with what its styles show."""
    return {**dump_tables(path, drive_dir), "styles": _styles(path)}


def write_golden(path: Path, dump: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(dump, indent=1, ensure_ascii=False, sort_keys=False) + "\n", encoding="utf-8")


def read_golden(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))
