"""Styles of Sign Mapper's layers: the same look whether a layer comes from a file, the dialog or a model.

Signs show their catalogue pictogram (SVG embedded as base64, so the style
does not depend on where the plugin is installed), a small arrow turned to the
face azimuth and the template id as label; the legend groups the pictograms by
sign family. The review state is part of every symbol and follows decisions
live (data-defined on ``status``): a sign to review has an orange halo and a
"?" label, a rejected sign is faded and crossed out, a manual one carries a
blue mark. SVG pictograms are optional in a catalogue: an entry without one (or
whose file is missing) gets a plain marker of its shape and colour instead.
Detections show a dot coloured by status. Field aliases are in the output
language (``output_schema.ALIASES``).

The styles are embedded in the GeoPackage as its default (opening the file
shows them) and applied by a Processing layer post-processor to the layers a
run loads (:class:`OutputStyler`), since Processing loads results without
their default style.
"""

from __future__ import annotations

import base64
from types import SimpleNamespace

from qgis.core import (
    QgsCategorizedSymbolRenderer,
    QgsEditorWidgetSetup,
    QgsMarkerSymbol,
    QgsPalLayerSettings,
    QgsProcessingLayerPostProcessorInterface,
    QgsProperty,
    QgsRendererCategory,
    QgsRuleBasedRenderer,
    QgsSimpleMarkerSymbolLayer,
    QgsSimpleMarkerSymbolLayerBase,
    QgsSvgMarkerSymbolLayer,
    QgsSymbol,
    QgsSymbolLayer,
    QgsTextFormat,
    QgsVectorLayer,
    QgsVectorLayerSimpleLabeling,
)
from qgis.PyQt.QtCore import QPointF
from qgis.PyQt.QtGui import QColor

from ..signmapper_core import output_schema as schema
from ..signmapper_core.catalogue.families import by_family, family_name
from ..signmapper_core.catalogue.names import sign_name
from ..signmapper_core.output_schema import DETECTIONS, MANUAL, REJECTED, REVIEW, SIGNS, STATUS_COLOURS
from ..signmapper_core.partial_output import write_failure
from ..signmapper_core.plate_formats import PLATE_ID, PLATE_NAMES
from ..signmapper_core.sign_colours import DISPLAY_COLOURS

PICTOGRAM_MM = 7.0
REJECTED_OPACITY = 35  # percent: a rejected sign stays visible, faded under its cross
SIGNS_LABEL = (f"\"template_id\" || CASE WHEN \"status\" = '{REVIEW}' THEN ' ?' "
               f"WHEN \"status\" = '{REJECTED}' THEN ' ✗' ELSE '' END")
# catalogue shape -> the plain marker drawn where a template has no SVG pictogram
PLAIN_SHAPES = {"circle": "Circle", "triangle": "EquilateralTriangle", "triangle-down": "EquilateralTriangle",
                "octagon": "Octagon", "diamond": "Diamond", "square": "Square", "rectangle": "Square"}


def _when(status: str) -> QgsProperty:
    return QgsProperty.fromExpression(f"\"status\" = '{status}'")


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


def _review_halo() -> QgsSimpleMarkerSymbolLayer:
    halo = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Circle, PICTOGRAM_MM + 3.0)
    colour = QColor(STATUS_COLOURS[REVIEW])
    colour.setAlpha(150)
    halo.setColor(colour)
    halo.setStrokeColor(QColor(STATUS_COLOURS[REVIEW]))
    halo.setStrokeWidth(0.6)
    halo.setDataDefinedProperty(QgsSymbolLayer.PropertyLayerEnabled, _when(REVIEW))
    return halo


def _rejected_cross() -> QgsSimpleMarkerSymbolLayer:
    cross = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Cross2, PICTOGRAM_MM + 1.0)
    cross.setStrokeColor(QColor("#212121"))
    cross.setColor(QColor("#212121"))
    cross.setStrokeWidth(0.8)
    cross.setDataDefinedProperty(QgsSymbolLayer.PropertyLayerEnabled, _when(REJECTED))
    return cross


def _manual_mark() -> QgsSimpleMarkerSymbolLayer:
    mark = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Square, 2.2)
    mark.setColor(QColor(STATUS_COLOURS[MANUAL]))
    mark.setStrokeColor(QColor("white"))
    mark.setOffset(QPointF(-PICTOGRAM_MM / 2, -PICTOGRAM_MM / 2))
    mark.setDataDefinedProperty(QgsSymbolLayer.PropertyLayerEnabled, _when(MANUAL))
    return mark


def _plain_layer(entry, size_mm: float) -> QgsSimpleMarkerSymbolLayer:
    """A marker of the entry's shape and colour, for a template without an SVG pictogram."""
    shape = getattr(QgsSimpleMarkerSymbolLayerBase, PLAIN_SHAPES.get(entry.shape, "Circle"),
                    QgsSimpleMarkerSymbolLayerBase.Circle)
    layer = QgsSimpleMarkerSymbolLayer(shape, size_mm * 0.7)
    layer.setColor(QColor(DISPLAY_COLOURS.get(entry.colour, DISPLAY_COLOURS["red"])))
    layer.setStrokeColor(QColor("#222222"))
    if entry.shape == "triangle-down":
        layer.setAngle(180.0)
    return layer


def pictogram_svg(catalogue, entry) -> bytes | None:
    """The entry's SVG pictogram, or None where the catalogue has none (or its file is missing)."""
    if not entry.svg:
        return None
    try:
        return catalogue.pictogram_path(entry.id, "svg").read_bytes()
    except OSError:
        return None


def templates_without_pictogram(catalogue) -> list[str]:
    """Ids of the entries drawn with a plain marker: no SVG pictogram, or its file is missing."""
    return [e.id for e in catalogue if not e.svg or not catalogue.pictogram_path(e.id, "svg").is_file()]


def pictogram_symbol(svg_bytes: bytes) -> QgsMarkerSymbol:
    """Halo (review), pictogram, face arrow, cross (rejected), mark (manual); faded when rejected."""
    return sign_symbol(_svg_layer(svg_bytes, PICTOGRAM_MM))


def sign_symbol(face) -> QgsMarkerSymbol:
    """The symbol of one sign type around its ``face`` layer (pictogram or plain marker)."""
    symbol = QgsMarkerSymbol()
    symbol.changeSymbolLayer(0, _review_halo())
    for layer in (face, _azimuth_arrow(), _rejected_cross(), _manual_mark()):
        symbol.appendSymbolLayer(layer)
    symbol.setDataDefinedProperty(
        QgsSymbol.PropertyOpacity,
        QgsProperty.fromExpression(f"CASE WHEN \"status\" = '{REJECTED}' THEN {REJECTED_OPACITY} ELSE 100 END"),
    )
    return symbol


def _quoted(text: str) -> str:
    return "'" + text.replace("'", "''") + "'"


def signs_renderer(catalogue, language: str = "en") -> QgsRuleBasedRenderer:
    """Rule-based: one group per sign family, one pictogram rule per catalogue entry; an 'other' rule last."""
    root = QgsRuleBasedRenderer.Rule(None)
    for name, entries in by_family(catalogue).items():
        if not entries:
            continue
        ids = ", ".join(_quoted(e.id) for e in entries)
        group = QgsRuleBasedRenderer.Rule(None, 0, 0, f'"template_id" IN ({ids})', family_name(name, language))
        for entry in entries:
            svg = pictogram_svg(catalogue, entry)
            face = _plain_layer(entry, PICTOGRAM_MM) if svg is None else _svg_layer(svg, PICTOGRAM_MM)
            group.appendChild(QgsRuleBasedRenderer.Rule(
                sign_symbol(face), 0, 0, f'"template_id" = {_quoted(entry.id)}',
                f"{entry.id} {sign_name(entry, language)}"))
        root.appendChild(group)
    plates = QgsRuleBasedRenderer.Rule(
        sign_symbol(_plain_layer(SimpleNamespace(shape="rectangle", colour="white"), PICTOGRAM_MM)), 0, 0,
        f'"template_id" = {_quoted(PLATE_ID)}', PLATE_NAMES.get(language, PLATE_NAMES["en"]))
    root.appendChild(plates)
    fallback = QgsMarkerSymbol.createSimple({"name": "circle", "color": "#d52b1e", "size": "3"})
    other = QgsRuleBasedRenderer.Rule(fallback, 0, 0, "", "other")
    other.setIsElse(True)
    root.appendChild(other)
    return QgsRuleBasedRenderer(root)


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


def set_aliases(layer: QgsVectorLayer, kind: str, language: str) -> None:
    """Field aliases in ``language``; a crop path field opens as an image in the attribute form."""
    fields = layer.fields()
    for field in schema.fields(kind):
        index = fields.indexOf(field.name)
        if index >= 0:
            layer.setFieldAlias(index, field.alias(language))
    index = fields.indexOf("crop_path")
    if index >= 0:
        layer.setEditorWidgetSetup(index, QgsEditorWidgetSetup("ExternalResource", {
            "DocumentViewer": 1, "RelativeStorage": 1, "FileWidget": True, "UseLink": True}))


def apply_style(layer: QgsVectorLayer, kind: str, catalogue, language: str = "en") -> None:
    """Give ``layer`` (of kind signs or detections) Sign Mapper's look."""
    if kind == SIGNS:
        layer.setRenderer(signs_renderer(catalogue, language))
        layer.setLabeling(id_labels(SIGNS_LABEL))
        layer.setLabelsEnabled(True)
    elif kind == DETECTIONS:
        layer.setRenderer(detections_renderer())
    else:
        raise ValueError(f"no style for layer kind '{kind}'")
    set_aliases(layer, kind, language)
    layer.triggerRepaint()


def embed_default_styles(gpkg_path: str, catalogue, language: str = "en", target=None) -> list[str]:
    """Save the styles into the GeoPackage's layer_styles table, used when the layers are opened.

    Returns the ids of the templates drawn with a plain marker (``templates_without_pictogram``). A style that
    cannot be saved is an ``OutputWriteError`` naming ``target`` (the file ``gpkg_path`` becomes) and a full
    disk, which QGIS's own words ("Error looking for style") do not.
    """
    for kind, description in ((SIGNS, "Sign Mapper: pictograms by family, review state, face direction, ids"),
                              (DETECTIONS, "Sign Mapper: detections by status")):
        layer = QgsVectorLayer(f"{gpkg_path}|layername={kind}", kind, "ogr")
        error = "" if layer.isValid() else "the layer cannot be opened"
        if not error:
            apply_style(layer, kind, catalogue, language)
            error = layer.saveStyleToDatabase("default", description, True, "")
        if error:
            raise write_failure(target or gpkg_path, f"the style of the layer '{kind}'", error)
    return templates_without_pictogram(catalogue)


class OutputStyler(QgsProcessingLayerPostProcessorInterface):
    """Styles a layer Processing loads from a run (dialog, model, ``runAndLoadResults``).

    Processing calls it after adding the layer to the project; it must outlive
    the algorithm, so :meth:`create` keeps every instance in a class list.
    """

    _alive = []

    def __init__(self, kind: str, catalogue, language: str):
        super().__init__()
        self.kind, self.catalogue, self.language = kind, catalogue, language

    @classmethod
    def create(cls, kind: str, catalogue, language: str) -> OutputStyler:
        styler = cls(kind, catalogue, language)
        cls._alive.append(styler)
        del cls._alive[:-16]  # Processing uses one right after the run; keep the last few
        return styler

    def postProcessLayer(self, layer, context, feedback):  # noqa: N802 - QGIS interface
        if isinstance(layer, QgsVectorLayer) and layer.isValid():
            apply_style(layer, self.kind, self.catalogue, self.language)
