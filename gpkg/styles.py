"""Default styles embedded in Sign Mapper's GeoPackages, so a layer opens showing pictograms.

Signs show their catalogue pictogram (SVG embedded as base64, so the style
does not depend on where the plugin is installed), a small arrow turned to the
face azimuth, and the template id as label ("?" for signs awaiting review).
Detections show a small dot coloured by status.
"""

from __future__ import annotations

import base64

from qgis.core import (
    QgsCategorizedSymbolRenderer,
    QgsMarkerSymbol,
    QgsPalLayerSettings,
    QgsProperty,
    QgsRendererCategory,
    QgsSimpleMarkerSymbolLayer,
    QgsSimpleMarkerSymbolLayerBase,
    QgsSvgMarkerSymbolLayer,
    QgsSymbolLayer,
    QgsTextFormat,
    QgsVectorLayer,
    QgsVectorLayerSimpleLabeling,
)
from qgis.PyQt.QtCore import QPointF
from qgis.PyQt.QtGui import QColor

from ..signmapper_core.output_schema import DETECTIONS, REVIEW, SIGNS, STATUS_COLOURS

PICTOGRAM_MM = 7.0


def _svg_layer(svg_bytes: bytes, size_mm: float) -> QgsSvgMarkerSymbolLayer:
    layer = QgsSvgMarkerSymbolLayer("base64:" + base64.b64encode(svg_bytes).decode("ascii"))
    layer.setSize(size_mm)
    return layer


def _azimuth_arrow() -> QgsSimpleMarkerSymbolLayer:
    """An arrow head beside the pictogram, pointing where the sign face looks.

    QGIS turns a marker's offset with its angle, and the arrow head points east
    at angle 0, so angle = azimuth - 90 with the offset to the east puts the
    arrow on the side the face looks to, pointing away from the sign.
    """
    arrow = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.ArrowHeadFilled, 2.6)
    arrow.setColor(QColor("#222222"))
    arrow.setStrokeColor(QColor("white"))
    arrow.setOffset(QPointF(PICTOGRAM_MM / 2 + 1.6, 0.0))
    arrow.setDataDefinedProperty(QgsSymbolLayer.PropertyAngle, QgsProperty.fromExpression('"azimuth" - 90'))
    arrow.setDataDefinedProperty(
        QgsSymbolLayer.PropertyLayerEnabled, QgsProperty.fromExpression('"azimuth" is not null')
    )
    return arrow


def signs_renderer(catalogue) -> QgsCategorizedSymbolRenderer:
    renderer = QgsCategorizedSymbolRenderer("template_id")
    for entry in catalogue:
        svg = catalogue.pictogram_path(entry.id, "svg")
        symbol = QgsMarkerSymbol()
        symbol.changeSymbolLayer(0, _svg_layer(svg.read_bytes(), PICTOGRAM_MM))
        symbol.appendSymbolLayer(_azimuth_arrow())
        renderer.addCategory(QgsRendererCategory(entry.id, symbol, entry.id))
    fallback = QgsMarkerSymbol.createSimple({"name": "circle", "color": "#d52b1e", "size": "3"})
    renderer.addCategory(QgsRendererCategory("", fallback, "other"))
    return renderer


def detections_renderer() -> QgsCategorizedSymbolRenderer:
    renderer = QgsCategorizedSymbolRenderer("status")
    for status, colour in STATUS_COLOURS.items():
        symbol = QgsMarkerSymbol.createSimple({"name": "circle", "color": colour, "size": "1.6",
                                               "outline_color": "white"})
        renderer.addCategory(QgsRendererCategory(status, symbol, status))
    return renderer


def id_labels(expression: str) -> QgsVectorLayerSimpleLabeling:
    settings = QgsPalLayerSettings()
    settings.fieldName = expression
    settings.isExpression = True
    settings.placement = QgsPalLayerSettings.OverPoint
    settings.yOffset = PICTOGRAM_MM / 2 + 2.5
    text = QgsTextFormat()
    text.setSize(8)
    buffer = text.buffer()
    buffer.setEnabled(True)
    buffer.setSize(0.8)
    text.setBuffer(buffer)
    settings.setFormat(text)
    return QgsVectorLayerSimpleLabeling(settings)


def embed_default_styles(gpkg_path: str, catalogue) -> None:
    """Save the default styles into the GeoPackage's layer_styles table, used when the layers are opened."""
    signs = QgsVectorLayer(f"{gpkg_path}|layername={SIGNS}", SIGNS, "ogr")
    signs.setRenderer(signs_renderer(catalogue))
    signs.setLabeling(id_labels(f"\"template_id\" || if(\"status\" = '{REVIEW}', ' ?', '')"))
    signs.setLabelsEnabled(True)
    _save(signs, "Sign Mapper: pictograms, face direction and ids")
    detections = QgsVectorLayer(f"{gpkg_path}|layername={DETECTIONS}", DETECTIONS, "ogr")
    detections.setRenderer(detections_renderer())
    _save(detections, "Sign Mapper: detections by status")


def _save(layer: QgsVectorLayer, description: str) -> None:
    if not layer.isValid():
        raise RuntimeError(f"cannot open {layer.source()} to store its style")
    error = layer.saveStyleToDatabase("default", description, True, "")
    if error:
        raise RuntimeError(f"{layer.source()}: style not saved: {error}")
