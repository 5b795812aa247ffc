"""QGIS fields and features of the output layers, derived from ``signmapper_core.output.schema``."""

from __future__ import annotations

from typing import Iterable, Mapping, Optional, Sequence

from qgis.core import NULL, QgsFeature, QgsField, QgsFields, QgsGeometry, QgsLineString, QgsPoint
from qgis.PyQt.QtCore import QVariant

from ..signmapper_core.output import schema

QT_TYPES = {schema.TEXT: QVariant.String, schema.INTEGER: QVariant.Int, schema.REAL: QVariant.Double}


def qgs_fields(columns: Iterable[tuple]) -> QgsFields:
    """QgsFields of ``(name, QVariant type)`` or ``(name, QVariant type, length)`` columns, in their order: each
    layer or table a tool writes declares its columns so, and this builds them."""
    fields = QgsFields()
    for name, kind, *length in columns:
        fields.append(QgsField(name, kind, len=length[0] if length else 0))
    return fields


def declared_qgs_fields(declared) -> QgsFields:
    """The QgsFields of declared fields (``output.schema.Field``: a mapping run's layers, ``changes``)."""
    return qgs_fields((field.name, QT_TYPES[field.kind], field.length) for field in declared)


def layer_fields(layer: str) -> QgsFields:
    """The QgsFields of output layer ``layer`` ("signs" or "detections"), in the schema's order."""
    return declared_qgs_fields(schema.fields(layer))


def point_z(east: float, north: float, up: float) -> QgsGeometry:
    return QgsGeometry(QgsPoint(east, north, up))


def line_z(points: Iterable[Sequence[float]]) -> QgsGeometry:
    """A LineStringZ through ``points`` (east, north, up), numbers of any kind (numpy's too) taken as floats."""
    return QgsGeometry(QgsLineString([QgsPoint(*(float(c) for c in point)) for point in points]))


def new_feature(fields: QgsFields, attributes: Sequence, geometry: Optional[QgsGeometry] = None) -> QgsFeature:
    """A feature of ``fields`` with ``attributes`` in the fields' order (and ``geometry``, if any)."""
    feature = QgsFeature(fields)
    feature.setAttributes(list(attributes))
    if geometry is not None:
        feature.setGeometry(geometry)
    return feature


def named_feature(fields: QgsFields, values: Mapping, geometry: QgsGeometry) -> QgsFeature:
    """A feature of ``fields`` with ``values`` set by field name (None as NULL) and ``geometry``.

    Set by name, so a layer with fewer or reordered fields (one a person copied or
    edited) gets what it has room for.
    """
    feature = QgsFeature(fields)
    for name, value in values.items():
        index = fields.indexOf(name)
        if index >= 0:
            feature.setAttribute(index, NULL if value is None else value)
    feature.setGeometry(geometry)
    return feature


def layer_feature(fields: QgsFields, layer: str, item, context=None) -> QgsFeature:
    """A PointZ feature of ``layer`` for a fused sign (signs) or an observation (detections), its attributes set
    by name (:func:`named_feature`).

    ``context`` (``output.schema.OutputContext``): language, drive clock, crops.
    """
    east, north, up = (float(c) for c in item.position)
    return named_feature(fields, schema.values(layer, item, context), point_z(east, north, up))


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
