"""What a click on one of our features gives, part of the layer style: the sign's photo (the image crop written
beside the GeoPackage) in its form and map tip, and layer actions to open the drive viewer at it or its photo.

Crops are stored relative to the GeoPackage: every path here is resolved from the
layer's own file (``GPKG_FOLDER``), so a GeoPackage moved with its crops folder
still finds them. The actions appear in the identify panel, the attribute table
and the Actions map tool; the viewer action calls the plugin's ``open_viewer_at``.
"""

from __future__ import annotations

from qgis.core import QgsAction, QgsEditorWidgetSetup, QgsVectorLayer

from ..signmapper_core.output.schema import SIGNS

GPKG_FOLDER = "file_path(layer_property(@layer, 'path'))"
CROP_FILE = f"CASE WHEN \"crop_path\" IS NULL THEN '' ELSE {GPKG_FOLDER} || '/' || \"crop_path\" END"
PHOTO_WIDTH_PX = 240
VIEWER_ACTION = "Open in the drive viewer"
PHOTO_ACTION = "Show the image crop"
SCOPES = {"Feature", "Canvas"}  # identify panel and attribute table; the Actions map tool

VIEWER_CODE = """from qgis.utils import plugins
sign_mapper = next((p for p in plugins.values() if hasattr(p, "open_viewer_at")), None)
if sign_mapper is not None:
    sign_mapper.open_viewer_at("[% @layer_id %]", [% $id %])
"""
PHOTO_CODE = f"""from qgis.PyQt.QtCore import QUrl
from qgis.PyQt.QtGui import QDesktopServices
photo = r"[% {CROP_FILE} %]"
if photo:
    QDesktopServices.openUrl(QUrl.fromLocalFile(photo))
"""
MAP_TIP = (f"<b>[% \"template_id\" %]</b> [% \"name\" %]<br>[% represent_value(\"status\") %]"
           f"[% CASE WHEN \"crop_path\" IS NULL THEN '' ELSE '<br><img width=\"{PHOTO_WIDTH_PX}\" src=\"' || "
           f"'file:///' || regexp_replace({CROP_FILE}, '^/', '') || '\">' END %]")


def apply(layer: QgsVectorLayer, kind: str) -> None:
    """The photo widget and map tip (signs) and the layer actions (both kinds) of ``layer``."""
    fields = layer.fields()
    index = fields.indexOf("crop_path")
    if index >= 0:  # the form shows the image itself, found from the GeoPackage's folder
        layer.setEditorWidgetSetup(index, QgsEditorWidgetSetup("ExternalResource", {
            "DocumentViewer": 1, "DocumentViewerHeight": 0, "DocumentViewerWidth": 0, "RelativeStorage": 2,
            "FileWidget": True, "UseLink": True, "FullUrl": False,
            "PropertyCollection": {"name": None, "type": "collection", "properties": {
                "propertyRootPath": {"active": True, "expression": GPKG_FOLDER, "type": 3}}}}))
    if kind == SIGNS:
        layer.setMapTipTemplate(MAP_TIP)
    manager = layer.actions()
    for action in manager.actions():
        if action.name() in (VIEWER_ACTION, PHOTO_ACTION):
            manager.removeAction(action.id())
    manager.addAction(QgsAction(QgsAction.GenericPython, VIEWER_ACTION, VIEWER_CODE, "", False, "Drive viewer",
                                SCOPES))
    if index >= 0:
        manager.addAction(QgsAction(QgsAction.GenericPython, PHOTO_ACTION, PHOTO_CODE, "", False, "Photo", SCOPES))
