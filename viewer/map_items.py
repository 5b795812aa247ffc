"""The vehicle on the map canvas (camera position and view cone) and the map tool that opens a pair by a click."""

from __future__ import annotations

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsGeometry,
    QgsPointXY,
    QgsProject,
    QgsWkbTypes,
)
from qgis.gui import QgsMapToolEmitPoint, QgsRubberBand, QgsVertexMarker
from qgis.PyQt.QtCore import pyqtSignal
from qgis.PyQt.QtGui import QColor

from ..signmapper_core.drive.viewing import view_cone

CONE_COLOUR = QColor(21, 101, 192, 70)
VEHICLE_COLOUR = QColor(21, 101, 192)
FOLLOW_MARGIN = 0.15  # recentre when the vehicle comes this close (share of the extent) to the canvas edge


class VehicleOnMap:
    """A marker at the camera and its view cone up to the far limit, kept in the canvas CRS."""

    def __init__(self, canvas):
        self.canvas = canvas
        self.cone = QgsRubberBand(canvas, QgsWkbTypes.PolygonGeometry)
        self.cone.setColor(CONE_COLOUR)
        self.cone.setStrokeColor(VEHICLE_COLOUR)
        self.cone.setWidth(1)
        self.marker = QgsVertexMarker(canvas)
        self.marker.setIconType(QgsVertexMarker.ICON_CIRCLE)
        self.marker.setColor(VEHICLE_COLOUR)
        self.marker.setFillColor(QColor("white"))
        self.marker.setIconSize(12)
        self.marker.setPenWidth(3)
        self.crs = None
        self.position = None  # QgsPointXY in canvas CRS, for tests

    def _to_canvas(self):
        target = self.canvas.mapSettings().destinationCrs()
        if self.crs is None or not target.isValid() or target == self.crs:
            return None
        return QgsCoordinateTransform(self.crs, target, QgsProject.instance())

    def show(self, camera, pose, far_m: float, crs: str, follow: bool) -> None:
        self.crs = QgsCoordinateReferenceSystem(crs)
        transform = self._to_canvas()
        points = [QgsPointXY(e, n) for e, n in view_cone(camera, pose, far_m)]
        if transform is not None:
            points = [transform.transform(p) for p in points]
        self.cone.setToGeometry(QgsGeometry.fromPolygonXY([points + points[:1]]), None)
        self.position = points[0]
        self.marker.setCenter(points[0])
        self.marker.show()
        self.cone.show()
        if follow:
            self.keep_in_view(points[0])

    def keep_in_view(self, point) -> None:
        extent = self.canvas.extent()
        inner = extent.buffered(-FOLLOW_MARGIN * min(extent.width(), extent.height()))
        if not inner.contains(point):
            self.canvas.setCenter(point)
            self.canvas.refresh()

    def hide(self) -> None:
        self.cone.reset(QgsWkbTypes.PolygonGeometry)
        self.marker.hide()
        self.position = None

    def remove(self) -> None:
        scene = self.canvas.scene()
        for item in (self.cone, self.marker):
            scene.removeItem(item)


class PairPickTool(QgsMapToolEmitPoint):
    """Click the map: the viewer opens the pair at that trajectory point, or the pair that sees the place best."""

    picked = pyqtSignal(float, float, float)  # x, y in canvas CRS, map units per pixel

    def __init__(self, canvas):
        super().__init__(canvas)
        self.canvasClicked.connect(self._clicked)

    def _clicked(self, point, _button):
        self.picked.emit(point.x(), point.y(), self.canvas().mapUnitsPerPixel())
