"""Recognising Sign Mapper layers and reading what their GeoPackage records about the run."""

from __future__ import annotations

from typing import Optional, Tuple

from qgis.core import QgsExpression, QgsFeatureRequest, QgsProject, QgsProviderRegistry, QgsVectorLayer

from ..gpkg.output import layer_uri
from ..signmapper_core.changes import schema as changes_schema
from ..signmapper_core.output.run_table import RUN_TABLE
from ..signmapper_core.output.schema import DETECTIONS, LAYERS, SIGNS, required_names


def gpkg_source(layer) -> Tuple[str, str]:
    """(GeoPackage path, layer name) of an OGR layer, ('', '') for anything else."""
    if not isinstance(layer, QgsVectorLayer) or layer.providerType() != "ogr":
        return "", ""
    parts = QgsProviderRegistry.instance().decodeUri("ogr", layer.source())
    path = parts.get("path") or ""
    return (path, parts.get("layerName") or "") if path.lower().endswith(".gpkg") else ("", "")


def has_run_table(path: str) -> bool:
    return QgsVectorLayer(layer_uri(path, RUN_TABLE), RUN_TABLE, "ogr").isValid()


def layer_kind(layer) -> Optional[str]:
    """'signs', 'detections' or 'changes' for a Sign Mapper layer, else None.

    A layer is ours when it has the fields the review needs (``output.schema``,
    ``required``). Its kind is its name in a GeoPackage with our run table, or
    failing that what its fields say (a layer copied elsewhere or renamed keeps them).
    """
    if not isinstance(layer, QgsVectorLayer) or not layer.isValid():
        return None
    names = set(layer.fields().names())
    if changes_schema.required_names() <= names:
        return changes_schema.CHANGES
    kinds = [kind for kind in LAYERS if required_names(kind) <= names]
    if not kinds:
        return None
    path, name = gpkg_source(layer)
    if name in kinds and has_run_table(path):
        return name
    return SIGNS if SIGNS in kinds else DETECTIONS


def gpkg_layer(path: str, name: str) -> Optional[QgsVectorLayer]:
    """Layer ``name`` of the GeoPackage ``path``: the project's if loaded (so edits in its buffer show), else a
    private one; None where there is no such layer (or no path). The review and the drive viewer both reach a
    run's other layer this way."""
    if not path:
        return None
    for candidate in QgsProject.instance().mapLayers().values():
        if gpkg_source(candidate) == (path, name):
            return candidate
    private = QgsVectorLayer(layer_uri(path, name), name, "ogr")
    return private if private.isValid() else None


def detections_layer_for(layer) -> Optional[QgsVectorLayer]:
    """The ``detections`` layer of the GeoPackage holding ``layer``: the project's if loaded, else a private one."""
    return gpkg_layer(gpkg_source(layer)[0], DETECTIONS)


def features_where(layer, field: str, value):
    """Features with ``field`` equal to ``value``, through the edit buffer."""
    request = QgsFeatureRequest().setFilterExpression(QgsExpression.createFieldEqualityExpression(field, value))
    return list(layer.getFeatures(request))
