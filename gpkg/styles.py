"""Styles of Sign Mapper's layers: the same look whether a layer comes from a file, the dialog or a model.

Signs show their catalogue pictogram (SVG embedded as base64, so the style
does not depend on where the plugin is installed), a small arrow turned to the
face azimuth and the template id as label; signs on one pole are stacked by
height. The review state is drawn by status rules that follow decisions live:
an accepted sign has a thin green ring, a sign to review an orange halo and a
"?" label, a rejected sign is faded and crossed out, a manual one carries a
blue mark; the legend lists these classes by status, then the pictograms by
sign family. SVG pictograms are optional in a catalogue: an entry without one
(or whose file is missing) gets a plain marker of its shape and colour instead.
Detections show a dot coloured by status. Field titles and coded values are in
the output language (``output.schema`` aliases, ``value_names``).

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

from ..signmapper_core.catalogue.families import by_family, family_name
from ..signmapper_core.catalogue.model import UNKNOWN_ID
from ..signmapper_core.catalogue.names import sign_name, unknown_name
from ..signmapper_core.output import schema
from ..signmapper_core.output.partial_output import write_failure
from ..signmapper_core.output.schema import DETECTIONS, SIGNS
from ..signmapper_core.output.value_names import LOCALISED_FIELDS, value_map, value_name
from ..signmapper_core.plates.formats import PLATE_ID, PLATE_NAMES
from ..signmapper_core.sign_colours import DISPLAY_COLOURS
from ..signmapper_core.statuses import ACCEPTED, REJECTED, REVIEW, STATUS_COLOURS
from . import feature_actions

PICTOGRAM_MM = 7.0
REJECTED_OPACITY = 35  # percent: a rejected sign stays visible, faded under its cross
# Signs on one pole share a point: their pictograms are stacked on the map, the highest on top, one step apart,
# each with its own label. A pole is the signs within POLE_RADIUS_M (planimetric, the layer's units), found live
# (a sign added or moved in the review takes its place at the next repaint).
POLE_RADIUS_M = 0.3
STACK_STEP_MM = PICTOGRAM_MM + 1.5
STACK_MAX_SCALE = 5000  # farther out a pole is no longer told from its neighbours, and finding poles costs time
_HEIGHT = 'coalesce(z($geometry), "elevation", 0)'
_POLE = (f"overlay_nearest(@layer, array({_HEIGHT}, $id), limit:=32, max_distance:={POLE_RADIUS_M}, cache:=true)")
# mm below the pole's point (negative: above): rank from the top, the stack centred on the point
STACK_Y_MM = (f"CASE WHEN @map_scale > {STACK_MAX_SCALE} THEN 0 ELSE "
              f"with_variable('pole', {_POLE}, (array_length(array_filter(@pole, array_get(@element, 0) > {_HEIGHT} "
              f"OR (array_get(@element, 0) = {_HEIGHT} AND array_get(@element, 1) < $id))) "
              f"- array_length(@pole) / 2.0) * {STACK_STEP_MM}) END")
SIGNS_LABEL = (f"\"template_id\" || CASE WHEN \"status\" = '{REVIEW}' THEN ' ?' "
               f"WHEN \"status\" = '{REJECTED}' THEN ' ✗' ELSE '' END")
# catalogue shape -> the plain marker drawn where a template has no SVG pictogram
PLAIN_SHAPES = {"circle": "Circle", "triangle": "EquilateralTriangle", "triangle-down": "EquilateralTriangle",
                "octagon": "Octagon", "diamond": "Diamond", "square": "Square", "rectangle": "Square"}


def _stacked(layer, dx_mm: float = 0.0, dy_mm: float = 0.0):
    """``layer`` offset by (dx, dy) mm and by its sign's place in the stack of its pole."""
    layer.setOffset(QPointF(dx_mm, dy_mm))
    layer.setDataDefinedProperty(QgsSymbolLayer.PropertyOffset, QgsProperty.fromExpression(
        f"concat({dx_mm}, ',', {dy_mm} + {STACK_Y_MM})"))
    return layer


def _svg_layer(svg_bytes: bytes, size_mm: float) -> QgsSvgMarkerSymbolLayer:
    layer = QgsSvgMarkerSymbolLayer("base64:" + base64.b64encode(svg_bytes).decode("ascii"))
    layer.setSize(size_mm)
    return _stacked(layer)


def _azimuth_arrow() -> QgsSimpleMarkerSymbolLayer:
    """An arrow head beside the pictogram, pointing where the sign face looks.

    QGIS turns a marker's offset with its angle, and the arrow head points east
    at angle 0, so angle = azimuth - 90 with the offset to the east puts the
    arrow on the side the face looks to, pointing away from the sign.
    """
    arrow = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.ArrowHeadFilled, 2.6)
    arrow.setColor(QColor("#222222"))
    arrow.setStrokeColor(QColor("white"))
    side = PICTOGRAM_MM / 2 + 1.6
    arrow.setOffset(QPointF(side, 0.0))
    arrow.setDataDefinedProperty(QgsSymbolLayer.PropertyAngle, QgsProperty.fromExpression('"azimuth" - 90'))
    # the stack's offset is straight down the map, so it is turned back by the angle QGIS turns offsets by
    turn = 'radians("azimuth" - 90)'
    arrow.setDataDefinedProperty(QgsSymbolLayer.PropertyOffset, QgsProperty.fromExpression(
        f"with_variable('down', {STACK_Y_MM}, concat({side} + @down * sin({turn}), ',', @down * cos({turn})))"))
    arrow.setDataDefinedProperty(
        QgsSymbolLayer.PropertyLayerEnabled, QgsProperty.fromExpression('"azimuth" is not null')
    )
    return arrow


# the passes a sign is drawn in: status marks under (ring, halo) or over (cross, mark) every pictogram
UNDER, PICTOGRAM, OVER = 0, 1, 2


def _status_mark(status: str) -> QgsSimpleMarkerSymbolLayer:
    """The mark of a review status around or on a sign's pictogram (what its legend class shows)."""
    colour = QColor(STATUS_COLOURS[status])
    if status == ACCEPTED:  # a thin ring in the accepted green
        mark = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Circle, PICTOGRAM_MM + 1.6)
        mark.setColor(QColor(0, 0, 0, 0))
        mark.setStrokeColor(colour)
        mark.setStrokeWidth(0.5)
        mark.setRenderingPass(UNDER)
        return _stacked(mark)
    if status == REVIEW:  # an orange halo
        mark = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Circle, PICTOGRAM_MM + 3.0)
        fill = QColor(colour)
        fill.setAlpha(150)
        mark.setColor(fill)
        mark.setStrokeColor(colour)
        mark.setStrokeWidth(0.6)
        mark.setRenderingPass(UNDER)
        return _stacked(mark)
    if status == REJECTED:  # crossed out (the pictogram fades: sign_symbol)
        mark = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Cross2, PICTOGRAM_MM + 1.0)
        mark.setStrokeColor(QColor("#212121"))
        mark.setColor(QColor("#212121"))
        mark.setStrokeWidth(0.8)
        mark.setRenderingPass(OVER)
        return _stacked(mark)
    mark = QgsSimpleMarkerSymbolLayer(QgsSimpleMarkerSymbolLayerBase.Square, 2.2)  # manual: a blue corner mark
    mark.setColor(colour)
    mark.setStrokeColor(QColor("white"))
    mark.setRenderingPass(OVER)
    return _stacked(mark, -PICTOGRAM_MM / 2, -PICTOGRAM_MM / 2)


def status_rules(language: str) -> QgsRuleBasedRenderer.Rule:
    """The legend's classes by status: one rule per status drawing its mark, grouped under the field's title."""
    group = QgsRuleBasedRenderer.Rule(None, 0, 0, "", schema.field(SIGNS, "status").alias(language))
    for status in STATUS_COLOURS:
        symbol = QgsMarkerSymbol()
        symbol.changeSymbolLayer(0, _status_mark(status))
        group.appendChild(QgsRuleBasedRenderer.Rule(symbol, 0, 0, f"\"status\" = '{status}'",
                                                    value_name("status", status, language)))
    return group


def _plain_layer(entry, size_mm: float) -> QgsSimpleMarkerSymbolLayer:
    """A marker of the entry's shape and colour, for a template without an SVG pictogram."""
    shape = getattr(QgsSimpleMarkerSymbolLayerBase, PLAIN_SHAPES.get(entry.shape, "Circle"),
                    QgsSimpleMarkerSymbolLayerBase.Circle)
    layer = QgsSimpleMarkerSymbolLayer(shape, size_mm * 0.7)
    layer.setColor(QColor(DISPLAY_COLOURS.get(entry.colour, DISPLAY_COLOURS["red"])))
    layer.setStrokeColor(QColor("#222222"))
    if entry.shape == "triangle-down":
        layer.setAngle(180.0)  # no offset to turn: the stack's stays straight down
    return _stacked(layer)


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
    """A pictogram and its face arrow, faded when rejected."""
    return sign_symbol(_svg_layer(svg_bytes, PICTOGRAM_MM))


def sign_symbol(face) -> QgsMarkerSymbol:
    """The symbol of one sign type: its ``face`` (pictogram or plain marker) and the face arrow, faded when
    rejected; the status marks are the status rules' (``status_rules``)."""
    symbol = QgsMarkerSymbol()
    face.setRenderingPass(PICTOGRAM)
    symbol.changeSymbolLayer(0, face)
    arrow = _azimuth_arrow()
    arrow.setRenderingPass(PICTOGRAM)
    symbol.appendSymbolLayer(arrow)
    symbol.setDataDefinedProperty(
        QgsSymbol.PropertyOpacity,
        QgsProperty.fromExpression(f"CASE WHEN \"status\" = '{REJECTED}' THEN {REJECTED_OPACITY} ELSE 100 END"),
    )
    return symbol


def _quoted(text: str) -> str:
    return "'" + text.replace("'", "''") + "'"


def signs_renderer(catalogue, language: str = "en") -> QgsRuleBasedRenderer:
    """Rule-based: the status marks (the legend's classes by status), one group per sign family with one
    pictogram rule per catalogue entry, the plates; an 'other' rule last."""
    root = QgsRuleBasedRenderer.Rule(None)
    root.appendChild(status_rules(language))
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
        f'"plate_of" IS NOT NULL OR "template_id" = {_quoted(PLATE_ID)}',  # typed (5.01, 5.31-2, ...) or not
        PLATE_NAMES.get(language, PLATE_NAMES["en"]))
    root.appendChild(plates)
    unknown = QgsMarkerSymbol.createSimple({"name": "circle", "color": "#ffffff", "outline_color": "#f57c00",
                                            "outline_width": "0.6", "size": str(PICTOGRAM_MM * 0.8)})
    root.appendChild(QgsRuleBasedRenderer.Rule(sign_symbol(unknown.symbolLayer(0).clone()), 0, 0,
                                               f'"template_id" = {_quoted(UNKNOWN_ID)}', unknown_name(language)))
    fallback = QgsMarkerSymbol.createSimple({"name": "circle", "color": "#d52b1e", "size": "3"})
    other = QgsRuleBasedRenderer.Rule(fallback, 0, 0, "", "other")
    other.setIsElse(True)
    root.appendChild(other)
    return QgsRuleBasedRenderer(root)


def detections_renderer(language: str = "en") -> QgsCategorizedSymbolRenderer:
    """A dot per detection in its status colour, the legend's classes named in ``language``."""
    renderer = QgsCategorizedSymbolRenderer("status")
    for status, colour in STATUS_COLOURS.items():
        symbol = QgsMarkerSymbol.createSimple({"name": "circle", "color": colour, "size": "1.6",
                                               "outline_color": "white"})
        renderer.addCategory(QgsRendererCategory(status, symbol, value_name("status", status, language)))
    return renderer


def id_labels(expression: str) -> QgsVectorLayerSimpleLabeling:
    """Each sign's label to the left of its own pictogram (in its pole's stack), every one shown."""
    settings = QgsPalLayerSettings()
    settings.fieldName = expression
    settings.isExpression = True
    settings.placement = QgsPalLayerSettings.OverPoint
    settings.quadOffset = QgsPalLayerSettings.QuadrantLeft
    settings.xOffset = -(PICTOGRAM_MM / 2 + 0.8)
    settings.displayAll = True  # a pole's labels sit close together: none may be dropped as a collision
    settings.scaleVisibility = True  # farther out than the stacks, thousands of ids would only cost time
    settings.minimumScale = STACK_MAX_SCALE
    settings.dataDefinedProperties().setProperty(QgsPalLayerSettings.OffsetXY, QgsProperty.fromExpression(
        f"concat({settings.xOffset}, ',', {STACK_Y_MM})"))
    text = QgsTextFormat()
    text.setSize(8)
    buffer = text.buffer()
    buffer.setEnabled(True)
    buffer.setSize(0.8)
    text.setBuffer(buffer)
    settings.setFormat(text)
    return QgsVectorLayerSimpleLabeling(settings)


def set_aliases(layer: QgsVectorLayer, kind: str, language: str) -> None:
    """Field aliases and coded values (status, shape, ...) in ``language``."""
    fields = layer.fields()
    for field in schema.fields(kind):
        index = fields.indexOf(field.name)
        if index >= 0:
            layer.setFieldAlias(index, field.alias(language))
    for name in LOCALISED_FIELDS:
        index = fields.indexOf(name)
        if index >= 0:  # the file keeps the code; tables, forms, identify and represent_value() show the word
            words = [{word: code} for word, code in value_map(name, language).items()]
            layer.setEditorWidgetSetup(index, QgsEditorWidgetSetup("ValueMap", {"map": words}))


def apply_style(layer: QgsVectorLayer, kind: str, catalogue, language: str = "en") -> None:
    """Give ``layer`` (of kind signs or detections) Sign Mapper's look."""
    if kind == SIGNS:
        layer.setRenderer(signs_renderer(catalogue, language))
        layer.setLabeling(id_labels(SIGNS_LABEL))
        layer.setLabelsEnabled(True)
    elif kind == DETECTIONS:
        layer.setRenderer(detections_renderer(language))
    else:
        raise ValueError(f"no style for layer kind '{kind}'")
    set_aliases(layer, kind, language)
    feature_actions.apply(layer, kind)  # the photo in form and map tip; open in the viewer
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
