"""A zoomable view of one left normal image with the sign's bbox and centroid drawn on it.

The whole image is in the scene so a missed sign anywhere in the pair can be
clicked; the view opens zoomed to the crop around the sign. Clicks are reported
in image pixel coordinates (u right, v down), the pipeline's convention.
"""

from __future__ import annotations

from typing import Optional, Tuple

from qgis.PyQt.QtCore import QPointF, QRectF, Qt, pyqtSignal
from qgis.PyQt.QtGui import QBrush, QColor, QImage, QPainter, QPen, QPixmap
from qgis.PyQt.QtWidgets import QGraphicsScene, QGraphicsView

BBOX_COLOUR = QColor(0, 230, 255)
CENTROID_COLOUR = QColor(255, 40, 200)
WHEEL_STEP = 1.25
MAX_ZOOM = 16.0  # screen pixels per image pixel


class ImageView(QGraphicsView):
    """Shows an image, a bbox and a centroid; wheel zooms around the cursor; a click emits image (u, v)."""

    imageClicked = pyqtSignal(float, float)  # noqa: N815 - Qt naming

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setScene(QGraphicsScene(self))
        self.setRenderHints(QPainter.Antialiasing | QPainter.SmoothPixmapTransform)
        self.setTransformationAnchor(QGraphicsView.AnchorUnderMouse)
        self.setDragMode(QGraphicsView.ScrollHandDrag)
        self.setBackgroundBrush(QBrush(QColor(40, 40, 40)))
        self.setMinimumHeight(260)
        self._pixmap_item = None
        self._overlay = []
        self._crop: Optional[QRectF] = None
        self._press_pos = None

    # content -------------------------------------------------------------------------------------------
    def clear_image(self) -> None:
        self.scene().clear()
        self._pixmap_item = None
        self._overlay = []
        self._crop = None

    def set_image(self, image: QImage, crop: Optional[Tuple[int, int, int, int]] = None,
                  bbox: Optional[Tuple[float, float, float, float]] = None,
                  centroid: Optional[Tuple[float, float]] = None) -> None:
        """Show ``image``; zoom to ``crop`` (x, y, w, h) if given; draw ``bbox`` and ``centroid`` if given."""
        self.clear_image()
        self._pixmap_item = self.scene().addPixmap(QPixmap.fromImage(image))
        self.scene().setSceneRect(QRectF(0, 0, image.width(), image.height()))
        self.set_marks(bbox, centroid)
        self._crop = QRectF(*crop) if crop else QRectF(0, 0, image.width(), image.height())
        self.reset_zoom()

    def set_marks(self, bbox, centroid) -> None:
        for item in self._overlay:
            self.scene().removeItem(item)
        self._overlay = []
        pen = QPen(BBOX_COLOUR, 2)
        pen.setCosmetic(True)  # stays 2 screen pixels wide at any zoom
        if bbox is not None:
            self._overlay.append(self.scene().addRect(QRectF(*bbox), pen))
        if centroid is not None:
            u, v = centroid
            cross = QPen(CENTROID_COLOUR, 2)
            cross.setCosmetic(True)
            # pixel centres are at integer (u, v); the scene's pixel u spans [u, u + 1)
            cx, cy = u + 0.5, v + 0.5
            r = max(3.0, 0.2 * min(bbox[2], bbox[3])) if bbox is not None else 6.0
            self._overlay.append(self.scene().addLine(cx - r, cy, cx + r, cy, cross))
            self._overlay.append(self.scene().addLine(cx, cy - r, cx, cy + r, cross))

    def set_picking(self, picking: bool) -> None:
        """While picking a point the cursor is a cross and dragging does not pan."""
        self.setDragMode(QGraphicsView.NoDrag if picking else QGraphicsView.ScrollHandDrag)
        self.viewport().setCursor(Qt.CrossCursor if picking else Qt.OpenHandCursor)

    def has_image(self) -> bool:
        return self._pixmap_item is not None

    def image(self) -> Optional[QImage]:
        return None if self._pixmap_item is None else self._pixmap_item.pixmap().toImage()

    def bbox_rect(self) -> Optional[QRectF]:
        rects = [i.rect() for i in self._overlay if hasattr(i, "rect")]
        return rects[0] if rects else None

    # zoom ----------------------------------------------------------------------------------------------
    def reset_zoom(self) -> None:
        """Fit the crop around the sign (or the whole image) into the view."""
        if self._crop is not None:
            self.fitInView(self._crop, Qt.KeepAspectRatio)

    def zoom_by(self, factor: float) -> None:
        scale = self.transform().m11()
        factor = min(factor, MAX_ZOOM / max(scale, 1e-9))
        self.scale(factor, factor)

    def visible_image_rect(self) -> QRectF:
        """The part of the image shown, in image pixels."""
        return self.mapToScene(self.viewport().rect()).boundingRect().intersected(self.sceneRect())

    def wheelEvent(self, event):  # noqa: N802 - Qt override
        if not self.has_image():
            return
        steps = event.angleDelta().y() / 120.0
        if steps:
            self.zoom_by(WHEEL_STEP ** steps)
        event.accept()

    def resizeEvent(self, event):  # noqa: N802
        super().resizeEvent(event)
        self.reset_zoom()

    def mouseDoubleClickEvent(self, event):  # noqa: N802
        self.reset_zoom()

    # clicks --------------------------------------------------------------------------------------------
    def mousePressEvent(self, event):  # noqa: N802
        self._press_pos = event.pos()
        super().mousePressEvent(event)

    def mouseReleaseEvent(self, event):  # noqa: N802
        super().mouseReleaseEvent(event)
        moved = self._press_pos is not None and (event.pos() - self._press_pos).manhattanLength() > 3
        if event.button() == Qt.LeftButton and not moved and self.has_image():
            u, v = self.view_to_image(event.pos())
            if 0 <= u < self.sceneRect().width() and 0 <= v < self.sceneRect().height():
                self.imageClicked.emit(u, v)
        self._press_pos = None

    def view_to_image(self, pos) -> Tuple[float, float]:
        """Image pixel coordinates of a viewport position (pixel centres at integers)."""
        p: QPointF = self.mapToScene(pos)
        return p.x() - 0.5, p.y() - 0.5

    def image_to_view(self, u: float, v: float):
        return self.mapFromScene(QPointF(u + 0.5, v + 0.5))
