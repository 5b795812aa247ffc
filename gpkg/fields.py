"""QGIS fields and features of the output layers, derived from ``signmapper_core.output.schema``."""

from __future__ import annotations

from qgis.core import NULL, QgsFeature, QgsField, QgsFields, QgsGeometry, QgsPoint
from qgis.PyQt.QtCore import QVariant

from ..signmapper_core.output import schema

QT_TYPES = {schema.TEXT: QVariant.String, schema.INTEGER: QVariant.Int, schema.REAL: QVariant.Double}


def layer_fields(layer: str) -> QgsFields:
    """The QgsFields of output layer ``layer`` ("signs" or "detections"), in the schema's order."""
    fields = QgsFields()
    for field in schema.fields(layer):
        fields.append(QgsField(field.name, QT_TYPES[field.kind], len=field.length))
    return fields


def layer_feature(fields: QgsFields, layer: str, item, context=None) -> QgsFeature:
    """A PointZ feature of ``layer`` for a fused sign (signs) or an observation (detections).

    ``context`` (``output.schema.OutputContext``): language, drive clock, crops.

    Attributes are set by name, so a layer with fewer or reordered fields (one a
    person copied or edited) gets what it has room for.
    """
    feature = QgsFeature(fields)
    for name, value in schema.values(layer, item, context).items():
        index = fields.indexOf(name)
        if index >= 0:
            feature.setAttribute(index, NULL if value is None else value)
    east, north, up = (float(c) for c in item.position)
    feature.setGeometry(QgsGeometry(QgsPoint(east, north, up)))
    return feature


def declared_fields(layer: str) -> tuple:
    """The declared fields of one of our layers: a mapping run's (``output.schema``) or ``changes``."""
    from ..signmapper_core.changes import schema as changes_schema  # delays numpy until used

    return changes_schema.FIELDS if layer == changes_schema.CHANGES else schema.fields(layer)


def feature_values(feature, layer: str) -> dict:
    """Field name -> plain Python value (None for NULL) of a feature of ``layer``; None for fields it lacks."""
    names = feature.fields()
    out = {}
    for field in declared_fields(layer):
        value = feature.attribute(field.name) if names.indexOf(field.name) >= 0 else None
        out[field.name] = None if value is None or value == NULL else field.typed(value, rounded=False)
    return out
