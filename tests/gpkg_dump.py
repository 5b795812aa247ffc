"""A GeoPackage of a mapping run as plain data, and the differences of two such dumps (no QGIS).

The dump holds what a user of the file sees: every table's columns (name,
SQL type, order), every feature (fid, PointZ, attributes), the run table, the
layer abstracts and the layer_styles rows. Paths that depend on where the test
runs are replaced by placeholders. ``tests/qgis/golden.py`` adds what the
embedded default styles show in QGIS.
"""

from __future__ import annotations

import math
import sqlite3
import uuid
from pathlib import Path

from osgeo import ogr

from signmapper_core.output.classifier_alternatives import parse_alternatives

REPO_ROOT = Path(__file__).resolve().parents[1]

# Largest difference accepted per float attribute: one unit of the last written decimal (they are rounded
# on writing, so a last-digit flip is possible across platforms); geometry to 0.1 mm.
FLOAT_TOLERANCE = {
    "detection_indicator": 1.1e-4, "classification_indicator": 1.1e-4, "vote_share": 1.1e-3, "sigma_m": 1.1e-4,
    "sigma_along_m": 1.1e-4, "sigma_across_m": 1.1e-4, "azimuth": 0.11, "mount_height_m": 0.011, "u": 0.011,
    "v": 0.011, "depth_m": 1.1e-3, "geometry": 1e-4,
    "easting": 1.1e-3, "northing": 1.1e-3, "elevation": 1.1e-3,
}
DEFAULT_TOLERANCE = 1e-9
# Text attributes holding "<id> <score>, ..." (written with two decimals): ids exact, scores to one unit.
SCORE_LIST_TOLERANCE = {"alternatives": 0.011}


def _columns(db: sqlite3.Connection, table: str) -> list:
    return [[name, kind] for _cid, name, kind, *_rest in db.execute(f'PRAGMA table_info("{table}")')]


def _placeholders(text, drive_dir: Path):
    if not isinstance(text, str):
        return text
    for path, name in ((drive_dir.resolve(), "<drive>"), (drive_dir, "<drive>"), (REPO_ROOT, "<plugin>")):
        text = text.replace(str(path), name)
    return text


def _is_uuid(text) -> bool:
    try:
        uuid.UUID(str(text))
    except ValueError:
        return False
    return True


def _features(path: Path, table: str) -> list:
    source = ogr.Open(str(path))
    layer = source.GetLayerByName(table)
    names = [layer.GetLayerDefn().GetFieldDefn(i).GetName() for i in range(layer.GetLayerDefn().GetFieldCount())]
    rows = []
    for feature in layer:
        geometry = feature.GetGeometryRef()
        point = list(geometry.GetPoint()) if geometry is not None else None
        rows.append({"fid": feature.GetFID(), "geometry": point,
                     "attributes": {n: feature.GetField(n) for n in names}})
    return rows


def dump_gpkg(path: Path, drive_dir: Path) -> dict:
    """The GeoPackage ``path`` written from ``drive_dir`` as JSON-able data."""
    db = sqlite3.connect(str(path))
    try:
        contents = db.execute("SELECT table_name, data_type, identifier, description FROM gpkg_contents "
                              "ORDER BY table_name")
        tables = {name: {"data_type": kind, "identifier": ident, "description": _placeholders(text, drive_dir)}
                  for name, kind, ident, text in contents}
        geometry = dict(db.execute("SELECT table_name, geometry_type_name || ':' || z FROM gpkg_geometry_columns"))
        srs = dict(db.execute("SELECT c.table_name, s.organization || ':' || s.organization_coordsys_id "
                              "FROM gpkg_contents c JOIN gpkg_spatial_ref_sys s ON c.srs_id = s.srs_id"))
        has_metadata = db.execute("SELECT 1 FROM sqlite_master WHERE name = 'gpkg_metadata'").fetchone()
        metadata = db.execute("SELECT metadata FROM gpkg_metadata").fetchall() if has_metadata else []
        abstracts = [_placeholders(m, drive_dir) for (m,) in metadata]
        sqlite_tables = sorted(name for (name,) in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'"))
        extensions = sorted(list(r) for r in db.execute("SELECT table_name, column_name, extension_name "
                                                        "FROM gpkg_extensions"))
        has_styles = db.execute("SELECT 1 FROM sqlite_master WHERE name = 'layer_styles'").fetchone()
        styles_table = [list(r) for r in db.execute(
            "SELECT f_table_name, styleName, useAsDefault, description FROM layer_styles ORDER BY f_table_name")] \
            if has_styles else []
        for name, table in tables.items():
            table["columns"] = _columns(db, name)
            table["geometry"] = geometry.get(name)
            table["srs"] = srs.get(name)
    finally:
        db.close()
    for name, table in tables.items():
        if name == "layer_styles":
            continue  # QML with embedded pictograms: summarised by layer_styles and styles below
        rows = _features(path, name)
        if name == "signmapper_run":
            table["rows"] = {r["attributes"]["key"]: _placeholders(r["attributes"]["value"], drive_dir) for r in rows}
            software = table["rows"].get("software", "")
            table["rows"]["software"] = "Sign Mapper <version>" if software.startswith("Sign Mapper ") else software
            if "run_id" in table["rows"]:  # a new UUID every run
                table["rows"]["run_id"] = "<uuid>" if _is_uuid(table["rows"]["run_id"]) else table["rows"]["run_id"]
        else:
            table["features"] = rows
    abstracts = sorted(a[a.index("<abstract>"):a.index("</abstract>") + 11] for a in abstracts if "<abstract>" in a)
    return {"sqlite_tables": sqlite_tables, "extensions": extensions, "tables": tables, "abstracts": abstracts,
            "layer_styles": styles_table}


def differences(expected, actual, where="") -> list[str]:
    """Human-readable differences of two dumps; floats within FLOAT_TOLERANCE of their attribute."""
    if isinstance(expected, dict) and isinstance(actual, dict):
        out = [f"{where}/{k}: missing" for k in expected if k not in actual]
        out += [f"{where}/{k}: unexpected" for k in actual if k not in expected]
        for key in expected:
            if key in actual:
                out += differences(expected[key], actual[key], f"{where}/{key}")
        return out
    if isinstance(expected, list) and isinstance(actual, list):
        if len(expected) != len(actual):
            return [f"{where}: {len(expected)} items expected, {len(actual)} found"]
        out = []
        for i, (e, a) in enumerate(zip(expected, actual)):
            out += differences(e, a, f"{where}[{i}]")
        return out
    field = where.rsplit("/", 1)[-1].split("[", 1)[0]
    if field in SCORE_LIST_TOLERANCE and isinstance(expected, str) and isinstance(actual, str):
        if _same_score_list(expected, actual, SCORE_LIST_TOLERANCE[field]):
            return []
    elif isinstance(expected, float) and isinstance(actual, (int, float)) and not isinstance(actual, bool):
        tolerance = FLOAT_TOLERANCE.get(field, DEFAULT_TOLERANCE)
        if math.isclose(expected, actual, rel_tol=0.0, abs_tol=tolerance):
            return []
    elif expected == actual and type(expected) is type(actual):
        return []
    return [f"{where}: expected {expected!r}, found {actual!r}"]


def _same_score_list(expected: str, actual: str, tolerance: float) -> bool:
    e, a = parse_alternatives(expected), parse_alternatives(actual)
    if len(e) != len(expected.split(",")) or len(a) != len(actual.split(",")):
        return expected == actual  # a part that is no "<id> <score>": compared as text
    return [t for t, _ in e] == [t for t, _ in a] and all(
        math.isclose(x, y, rel_tol=0.0, abs_tol=tolerance) for (_, x), (_, y) in zip(e, a))
