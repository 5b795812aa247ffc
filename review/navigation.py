"""Moving through a layer in driving order: previous, next, next needing review, and the map zoom."""

from __future__ import annotations

from qgis.core import QgsCoordinateTransform, QgsProject, QgsRectangle

from ..signmapper_core.output_schema import REVIEW
from .items import driving_order

ZOOM_HALF_SIZE_M = 20.0


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

    def zoom_to_feature(self) -> None:
        """Centre the map on the shown feature, ±20 m, and flash it."""
        layer, fid = self.session.layer, self.session.fid
        if layer is None or fid is None:
            return
        feature = layer.getFeature(fid)
        if not feature.hasGeometry():
            return
        point = feature.geometry().asPoint()
        d = ZOOM_HALF_SIZE_M
        extent = QgsRectangle(point.x() - d, point.y() - d, point.x() + d, point.y() + d)
        canvas = self.iface.mapCanvas()
        target = canvas.mapSettings().destinationCrs()
        if target.isValid() and target != layer.crs():
            extent = QgsCoordinateTransform(layer.crs(), target, QgsProject.instance()).transformBoundingBox(extent)
        canvas.setExtent(extent)
        canvas.refresh()
        canvas.flashFeatureIds(layer, [fid])
