"""The inventory atlas: an A4 sheet per delivered sign with its pictogram, photo, E/N/H, SSV number and name,
status and date, and a map of where it stands.

Everything on a sheet is an expression over the atlas feature, so the layout
stays right when the layer changes (a review decision, a sign added) and can be
edited and printed again from QGIS's layout manager. Titles are the output
schema's field titles, names and coded values the catalogue's and
``value_names``' words, all in the chosen language. The photo is the sign's image crop, found from
the GeoPackage's folder; the pictogram the catalogue's drawing.
"""

from __future__ import annotations

from qgis.core import (
    QgsLayoutItemLabel,
    QgsLayoutItemMap,
    QgsLayoutItemPage,
    QgsLayoutItemPicture,
    QgsLayoutObject,
    QgsLayoutPoint,
    QgsLayoutSize,
    QgsPrintLayout,
    QgsProperty,
    QgsUnitTypes,
)
from qgis.PyQt.QtGui import QFont

from ..signmapper_core.output.schema import SIGNS, OutputContext, field
from ..signmapper_core.output.value_names import VALUE_NAMES, value_name
from ..signmapper_core.plates.catalogue import pictogram_png

MAP_SCALE = 250  # the map on each sheet: the sign's surroundings (45 × 31 m), its pole's stack readable
MARGIN_MM = 15.0
GPKG_FOLDER = "file_path(layer_property(@atlas_layerid, 'path'))"
PHOTO = f"CASE WHEN \"crop_path\" IS NULL THEN '' ELSE {GPKG_FOLDER} || '/' || \"crop_path\" END"


def _quoted(text: str) -> str:
    return "'" + str(text).replace("'", "''") + "'"


def pictogram_expression(catalogue, template_ids) -> str:
    """The path of each type's drawing, for the types the layer holds ('' for a text plate)."""
    cases = [f"WHEN \"template_id\" = {_quoted(t)} THEN {_quoted(p)}" for t in sorted(template_ids)
             if (p := pictogram_png(catalogue, t))]
    return f"CASE {' '.join(cases)} ELSE '' END" if cases else "''"


def name_expression(catalogue, template_ids, language: str) -> str:
    """Each type's name in ``language`` (the layer's own name field for a type the catalogue lacks)."""
    context = OutputContext(language=language, catalogue=catalogue)
    cases = [f"WHEN \"template_id\" = {_quoted(t)} THEN {_quoted(context.name(t, ''))}" for t in sorted(template_ids)
             if context.name(t, "")]
    return f"CASE {' '.join(cases)} ELSE \"name\" END" if cases else "\"name\""


def words(field_name: str, language: str) -> str:
    """A coded field's value as its word in ``language`` (not the layer style's language: the sheet's own)."""
    cases = [f"WHEN \"{field_name}\" = {_quoted(code)} THEN {_quoted(value_name(field_name, code, language))}"
             for code in VALUE_NAMES[field_name]]
    return f"CASE {' '.join(cases)} ELSE \"{field_name}\" END"


def facts_text(language: str) -> str:
    """The sheet's facts, one 'title: value' line each in ``language``; a line without a value (no plate, no
    text, no mounting height) is left out."""
    def line(name: str, value: str, optional: bool = False) -> str:
        text = f"{_quoted(field(SIGNS, name).alias(language) + ': ')} || {value}"
        return f"CASE WHEN \"{name}\" IS NULL THEN '' ELSE {text} END" if optional else text

    lines = [
        line("easting", "to_string(round(x($geometry), 3))"),
        line("northing", "to_string(round(y($geometry), 3))"),
        line("elevation", "to_string(round(z($geometry), 3))"),
        line("azimuth", "to_string(round(\"azimuth\"))", optional=True),
        line("mount_height_m", "to_string(round(\"mount_height_m\", 2))", optional=True),
        line("format", f"{words('format', language)} || ', ' || to_string(\"width_m\") || ' × ' || "
                       "to_string(\"height_m\") || ' m'"),
        line("plate_of", "to_string(\"plate_of\")", optional=True),
        line("text", "\"text\"", optional=True),
        line("reviewed", words("reviewed", language)),
    ]
    return f"[% array_to_string(array_filter(array({', '.join(lines)}), @element <> ''), '\\n') %]"


def _label(layout, text: str, x: float, y: float, w: float, h: float, size: float = 10.0, bold: bool = False):
    label = QgsLayoutItemLabel(layout)
    label.setText(text)
    font = QFont()
    font.setPointSizeF(size)
    font.setBold(bold)
    label.setFont(font)
    label.attemptMove(QgsLayoutPoint(x, y, QgsUnitTypes.LayoutMillimeters))
    label.attemptResize(QgsLayoutSize(w, h, QgsUnitTypes.LayoutMillimeters))
    layout.addLayoutItem(label)
    return label


def _picture(layout, expression: str, x: float, y: float, w: float, h: float, item_id: str):
    picture = QgsLayoutItemPicture(layout)
    picture.setId(item_id)
    picture.setMode(QgsLayoutItemPicture.FormatRaster)
    picture.setResizeMode(QgsLayoutItemPicture.Zoom)  # the whole image, its aspect kept
    picture.dataDefinedProperties().setProperty(QgsLayoutObject.PictureSource, QgsProperty.fromExpression(expression))
    picture.attemptMove(QgsLayoutPoint(x, y, QgsUnitTypes.LayoutMillimeters))
    picture.attemptResize(QgsLayoutSize(w, h, QgsUnitTypes.LayoutMillimeters))
    layout.addLayoutItem(picture)
    return picture


def atlas_layout(project, layer, catalogue, language: str, statuses, name: str) -> QgsPrintLayout:
    """An A4 portrait layout whose atlas has a sheet per sign of ``layer`` with a status in ``statuses``, in sign
    number order. Its map shows the project's layers when ``layer`` is one of them, else ``layer`` alone."""
    layout = QgsPrintLayout(project)
    layout.initializeDefaults()
    layout.setName(name)
    layout.pageCollection().page(0).setPageSize("A4", QgsLayoutItemPage.Portrait)
    width = 210.0 - 2 * MARGIN_MM
    x, alias = MARGIN_MM, (lambda n: field(SIGNS, n).alias(language))
    ids = {f["template_id"] for f in layer.getFeatures() if f["template_id"]}
    title = _label(layout, f"[% \"template_id\" %]  [% {name_expression(catalogue, ids, language)} %]", x, 12,
                   width, 12, 18, bold=True)
    title.setId("title")
    recorded = _quoted(f"  ·  {alias('timestamp')} ")
    _label(layout, f"{alias('sign_id')} [% \"sign_id\" %]  ·  [% {words('status', language)} %]"
                   f"[% CASE WHEN \"timestamp\" IS NULL THEN '' ELSE {recorded} || "
                   f"format_date(to_datetime(\"timestamp\"), 'dd.MM.yyyy HH:mm') END %]",
           x, 26, width, 8, 11).setId("status")
    _picture(layout, pictogram_expression(catalogue, ids), x, 40, 45, 45, "pictogram")
    _picture(layout, PHOTO, x + 55, 40, width - 55, 95, "photo")
    _label(layout, facts_text(language), x, 92, 52, 60, 9).setId("facts")
    item_map = QgsLayoutItemMap(layout)
    item_map.setId("map")
    layout.addLayoutItem(item_map)
    # in this order: QGIS 3.22 leaves the extent empty when the map was moved or given its CRS before
    # zoomToExtent (and setExtent would resize the item to the extent's shape)
    item_map.attemptResize(QgsLayoutSize(width, 125, QgsUnitTypes.LayoutMillimeters))
    item_map.zoomToExtent(layer.extent())
    item_map.setCrs(layer.crs())
    if project.mapLayer(layer.id()) is None:
        item_map.setLayers([layer])
        item_map.setKeepLayerSet(True)
    item_map.setFrameEnabled(True)
    item_map.setAtlasDriven(True)
    item_map.setAtlasScalingMode(QgsLayoutItemMap.Fixed)
    item_map.setScale(MAP_SCALE)
    item_map.attemptMove(QgsLayoutPoint(x, 145, QgsUnitTypes.LayoutMillimeters))
    _label(layout, f"Sign Mapper · {layer.name()} · [% @atlas_featurenumber %] / [% @atlas_totalfeatures %]",
           x, 280, width, 6, 8).setId("footer")
    atlas = layout.atlas()
    atlas.setCoverageLayer(layer)
    atlas.setEnabled(True)
    atlas.setFilterFeatures(True)
    atlas.setFilterExpression(f"\"status\" IN ({', '.join(_quoted(s) for s in statuses)})")
    atlas.setSortFeatures(True)
    atlas.setSortExpression("\"sign_id\"")
    atlas.setPageNameExpression("'sign_' || lpad(to_string(\"sign_id\"), 5, '0')")
    return layout
