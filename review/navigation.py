"""Moving through a layer in driving order: previous, next, next needing review, and the map zoom."""

from __future__ import annotations

from qgis.core import QgsCoordinateTransform, QgsProject, QgsRectangle

from ..signmapper_core.statuses import REVIEW
from .items import driving_order

ZOOM_HALF_SIZE_M = 20.0
FOLLOW_MARGIN = 0.15  # Follow pans when the feature comes this close (share of the extent) to the map's edge
FOLLOW_WIDEST_M = 300.0  # and zooms in to ±ZOOM_HALF_SIZE_M when the map shows more than this across


class Navigator:
    def __init__(self, session, dock, iface, show_feature):
        self.session, self.dock, self.iface = session, dock, iface
        self.show_feature = show_feature  # controller: show_feature(fid)

    def _order(self):
        session = self.session
        return driving_order(session.layer, session.kind) if session.layer is not None else []

    def select(self, fid: int) -> None:
        """Select ``fid`` in the layer and show it (selecting an already selected feature emits nothing)."""
        self.session.layer.selectByIds([fid])
        if self.session.fid != fid:
            self.show_feature(fid)

    def step(self, step: int) -> None:
        order = [fid for fid, _ in self._order()]
        if not order:
            return
        fid = self.session.fid
        if fid in order:
            target = order[(order.index(fid) + step) % len(order)]
        else:
            target = order[0] if step > 0 else order[-1]
        self.select(target)

    def next(self) -> None:
        self.step(1)

    def previous(self) -> None:
        self.step(-1)

    def next_review(self) -> bool:
        """Select the next feature (in driving order, wrapping) with status 'review'; False if there is none."""
        session = self.session
        if session.layer is None:
            return False
        order = self._order()
        start = next((i for i, (fid, _) in enumerate(order) if fid == session.fid), -1)
        for k in range(1, len(order) + 1):
            fid, status = order[(start + k) % len(order)]
            if status == REVIEW and fid != session.fid:
                self.select(fid)
                return True
        self.dock.show_message(f"{session.layer.name()}: no other feature needs review")
        return False

    def _shown_point(self):
        """(layer, fid, point in the map's CRS) of the shown feature; None without one or without a geometry."""
        layer, fid = self.session.layer, self.session.fid
        if layer is None or fid is None:
            return None
        feature = layer.getFeature(fid)
        if not feature.hasGeometry():
            return None
        point = feature.geometry().asPoint()
        return layer, fid, self._to_canvas(layer).transform(point)

    def _to_canvas(self, layer) -> QgsCoordinateTransform:
        target = self.iface.mapCanvas().mapSettings().destinationCrs()
        return QgsCoordinateTransform(layer.crs(), target if target.isValid() else layer.crs(),
                                      QgsProject.instance())

    def zoom_to_feature(self) -> None:
        """Centre the map on the shown feature, ±20 m, and flash it."""
        shown = self._shown_point()
        if shown is None:
            return
        layer, fid, _ = shown
        point = layer.getFeature(fid).geometry().asPoint()
        d = ZOOM_HALF_SIZE_M
        extent = QgsRectangle(point.x() - d, point.y() - d, point.x() + d, point.y() + d)
        canvas = self.iface.mapCanvas()
        canvas.setExtent(self._to_canvas(layer).transformBoundingBox(extent))
        canvas.refresh()
        canvas.flashFeatureIds(layer, [fid])

    def follow(self) -> None:
        """Keep the shown feature in view: pan when it is near or beyond the map's edge, zoom in to ±20 m when the
        map shows a wide area (a sign there is a dot among dozens); a map already close by is left alone."""
        shown = self._shown_point()
        if shown is None:
            return
        layer, fid, point = shown
        canvas = self.iface.mapCanvas()
        extent = canvas.extent()
        across_m = self._to_canvas(layer).transformBoundingBox(extent, QgsCoordinateTransform.ReverseTransform)
        if extent.isEmpty() or max(across_m.width(), across_m.height()) > FOLLOW_WIDEST_M:
            self.zoom_to_feature()
            return
        if not extent.buffered(-FOLLOW_MARGIN * min(extent.width(), extent.height())).contains(point):
            canvas.setCenter(point)
            canvas.refresh()
        canvas.flashFeatureIds(layer, [fid])
