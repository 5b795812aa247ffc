"""QGIS fields and features of the output layers follow the declared schema."""

import numpy as np
from qgis.core import NULL, QgsField, QgsFields
from qgis.PyQt.QtCore import QVariant

from signmapper_core.drive.reader import PairRecord
from signmapper_core.fusion.signs import Observation
from signmapper_core.geometry import Pose
from signmapper_core.output import schema
from signmapper_core.pipeline.detection import Detection


def an_observation():
    detection = Detection("1.01", "Rechtskurve", "red", "triangle", 0.9, 0.779, "normal", 0.95, 0.81234, "review",
                          640.123, 210.987, (600, 170, 80, 70), 11.23456, np.array([2600010.0, 1200004.0, 403.1]))
    return Observation(detection, PairRecord(2, "000002", 0.4, Pose(2600000.0, 1200000.0, 402.0, 90.0, 0.0, 0.0),
                                             None, None, None), id=3)


def test_layer_fields_have_the_schema_names_and_types(sign_mapper):
    from sign_mapper.gpkg.fields import layer_fields

    for layer in schema.LAYERS:
        fields = layer_fields(layer)
        assert fields.names() == [f.name for f in schema.fields(layer)]
        kinds = {f.name: f.kind for f in schema.fields(layer)}
        expected = {schema.TEXT: QVariant.String, schema.INTEGER: QVariant.Int, schema.REAL: QVariant.Double}
        assert all(field.type() == expected[kinds[field.name()]] for field in fields)


def test_a_feature_fills_the_fields_a_layer_has_and_reads_back(sign_mapper):
    from sign_mapper.gpkg.fields import feature_values, layer_feature

    fields = QgsFields()  # a layer a person trimmed: three of the fields, in another order
    for name, kind in (("depth_m", QVariant.Double), ("template_id", QVariant.String), ("sign_id", QVariant.Int)):
        fields.append(QgsField(name, kind))
    feature = layer_feature(fields, schema.DETECTIONS, an_observation())
    assert feature.attributes() == [11.235, "1.01", NULL]
    point = feature.geometry().constGet()
    assert (point.x(), point.y(), point.z()) == (2600010.0, 1200004.0, 403.1)
    values = feature_values(feature, schema.DETECTIONS)
    assert values["depth_m"] == 11.235 and values["template_id"] == "1.01"
    assert values["sign_id"] is None and values["pair_id"] is None  # NULL, and a field the layer lacks
    assert set(values) == {f.name for f in schema.fields(schema.DETECTIONS)}
