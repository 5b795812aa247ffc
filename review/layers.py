"""Recognising Sign Mapper layers and reading what their GeoPackage records about the run."""

from __future__ import annotations

import json
from typing import Optional, Tuple

from qgis.core import QgsExpression, QgsFeatureRequest, QgsProject, QgsProviderRegistry, QgsVectorLayer

RUN_TABLE = "signmapper_run"  # written by algorithms/gpkg_output.py
KINDS = ("signs", "detections")
_COMMON = {"template_id", "status", "reviewed", "u", "v", "bbox_x", "bbox_y", "bbox_w", "bbox_h"}
_SIGN_ONLY = {"sign_id", "n_obs", "best_pair_id"}


def gpkg_source(layer) -> Tuple[str, str]:
    """(GeoPackage path, layer name) of an OGR layer, ('', '') for anything else."""
    if not isinstance(layer, QgsVectorLayer) or layer.providerType() != "ogr":
        return "", ""
    parts = QgsProviderRegistry.instance().decodeUri("ogr", layer.source())
    path = parts.get("path") or ""
    return (path, parts.get("layerName") or "") if path.lower().endswith(".gpkg") else ("", "")


def has_run_table(path: str) -> bool:
    table = QgsVectorLayer(f"{path}|layername={RUN_TABLE}", RUN_TABLE, "ogr")
    return table.isValid()


def layer_kind(layer) -> Optional[str]:
    """'signs' or 'detections' for a Sign Mapper layer, else None.

    Recognised by its GeoPackage's run table and layer name, or failing that by its fields
    (a layer copied elsewhere or renamed keeps them).
    """
    if not isinstance(layer, QgsVectorLayer) or not layer.isValid():
        return None
    names = set(layer.fields().names())
    if not _COMMON <= names or not ({"pair_id", "best_pair_id"} & names):
        return None
    path, name = gpkg_source(layer)
    if name in KINDS and has_run_table(path):
        return name
    return "signs" if _SIGN_ONLY <= names else "detections"


def read_run_table(path: str) -> dict:
    """The key/value rows of ``signmapper_run``; JSON values decoded, strings kept as written."""
    if not path:
        return {}
    table = QgsVectorLayer(f"{path}|layername={RUN_TABLE}", RUN_TABLE, "ogr")
    if not table.isValid():
        return {}
    values = {}
    for feature in table.getFeatures():
        key, text = feature["key"], feature["value"]
        if not isinstance(key, str) or not isinstance(text, str):
            continue
        try:
            values[key] = json.loads(text) if key != "drive" else text
        except ValueError:
            values[key] = text
    return values


def detections_layer_for(layer) -> Optional[QgsVectorLayer]:
    """The ``detections`` layer of the GeoPackage holding ``layer``: the project's if loaded, else a private one."""
    path, _ = gpkg_source(layer)
    if not path:
        return None
    for candidate in QgsProject.instance().mapLayers().values():
        if gpkg_source(candidate) == (path, "detections"):
            return candidate
    private = QgsVectorLayer(f"{path}|layername=detections", "detections", "ogr")
    return private if private.isValid() else None


def features_where(layer, field: str, value, attributes=None):
    """Features with ``field`` equal to ``value`` (no geometry unless asked), through the edit buffer."""
    request = QgsFeatureRequest().setFilterExpression(QgsExpression.createFieldEqualityExpression(field, value))
    if attributes is not None:
        request.setSubsetOfAttributes(attributes, layer.fields())
    return list(layer.getFeatures(request))
