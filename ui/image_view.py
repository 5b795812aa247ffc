"""A zoomable view of one left normal image with the sign's bbox and centroid, or many labelled boxes, on it.

The whole image is in the scene so a missed sign anywhere in the pair can be
clicked; the view opens zoomed to the crop around the sign. Once the user
zooms or pans, the view stays where they put it (resizing the dock or the next
frame of the same size keep it; double click returns to the crop). Clicks are
reported in image pixel coordinates (u right, v down), the pipeline's convention.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

from qgis.PyQt.QtCore import QPointF, QRectF, QSize, Qt, pyqtSignal
from qgis.PyQt.QtGui import QBrush, QColor, QFont, QImage, QPainter, QPen, QPixmap
from qgis.PyQt.QtWidgets import QGraphicsItem, QGraphicsScene, QGraphicsView


@dataclass(frozen=True)
class OverlayBox:
    """A labelled box drawn over the image; clicking it emits ``boxClicked(key)``."""

    key: str  # e.g. "signs:12": what a click selects
    rect: Tuple[float, float, float, float]  # x, y, w, h in image pixels
    colour: str
    label: str = ""
    dashed: bool = False  # projected from the map rather than detected in this image

BBOX_COLOUR = QColor(0, 230, 255)
CENTROID_COLOUR = QColor(255, 40, 200)
WHEEL_STEP = 1.25
MAX_ZOOM = 16.0  # screen pixels per image pixel


class ImageView(QGraphicsView):
    """Shows an image, a bbox and a centroid; wheel zooms around the cursor; a click emits image (u, v)."""

    imageClicked = pyqtSignal(float, float)  # noqa: N815 - Qt naming
    boxClicked = pyqtSignal(str)  # noqa: N815 - OverlayBox.key

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
        self._boxes: List[Tuple[OverlayBox, object]] = []  # (box, its graphics items)
        self._user_view = False  # the user zoomed or panned: keep their view
        self._picking = False

    def sizeHint(self):  # noqa: N802 - Qt override
        """As small as allowed: a dock's other widgets come first, the image takes whatever height is left
        (a scroll area sizes its content by the preferred heights, which would push the buttons out of view)."""
        return QSize(400, self.minimumHeight())

    # content -------------------------------------------------------------------------------------------
    def clear_image(self) -> None:
        self.scene().clear()
        self._pixmap_item = None
        self._overlay = []
        self._boxes = []
        self._crop = None
        self._user_view = False

    def set_image(self, image: QImage, crop: Optional[Tuple[int, int, int, int]] = None,
                  bbox: Optional[Tuple[float, float, float, float]] = None,
                  centroid: Optional[Tuple[float, float]] = None, keep_view: bool = False) -> None:
        """Show ``image``; zoom to ``crop`` (x, y, w, h) if given; draw ``bbox`` and ``centroid`` if given.

        ``keep_view``: an image of the same size replaces the shown one where the
        user left the view (stepping through a drive).
        """
        same_size = self._pixmap_item is not None and self.sceneRect() == QRectF(0, 0, image.width(), image.height())
        if keep_view and same_size:
            self._pixmap_item.setPixmap(QPixmap.fromImage(image))
            self.set_marks(bbox, centroid)
            if not self._user_view:
                self.reset_zoom()
            return
        self.clear_image()
        self._pixmap_item = self.scene().addPixmap(QPixmap.fromImage(image))
        self._pixmap_item.setTransformationMode(Qt.SmoothTransformation)
        self.scene().setSceneRect(QRectF(0, 0, image.width(), image.height()))
        self.set_marks(bbox, centroid)
        self._crop = QRectF(*crop) if crop else QRectF(0, 0, image.width(), image.height())
        self.reset_zoom()

    def set_boxes(self, boxes: Sequence[OverlayBox]) -> None:
        """Replace the labelled boxes (a pair's signs and detections)."""
        for _box, items in self._boxes:
            for item in items:
                self.scene().removeItem(item)
        self._boxes = []
        font = QFont()
        font.setBold(True)
        font.setPointSizeF(max(6.0, font.pointSizeF() * 0.8))
        for box in boxes:
            pen = QPen(QColor(box.colour), 2, Qt.DashLine if box.dashed else Qt.SolidLine)
            pen.setCosmetic(True)
            rect = self.scene().addRect(QRectF(*box.rect), pen)
            items = [rect]
            if box.label:
                text = self.scene().addSimpleText(box.label, font)
                text.setBrush(QBrush(QColor(box.colour)))
                text.setPen(QPen(QColor(0, 0, 0, 160), 0.5))
                text.setFlag(QGraphicsItem.ItemIgnoresTransformations, True)
                text.setPos(box.rect[0], box.rect[1] + box.rect[3] + 1)
                items.append(text)
            self._boxes.append((box, items))

    def boxes(self) -> List[OverlayBox]:
        return [box for box, _ in self._boxes]

    def box_at(self, u: float, v: float) -> Optional[OverlayBox]:
        """The smallest box containing image point (u, v): the most specific when boxes nest."""
        hits = [b for b in self.boxes() if b.rect[0] <= u + 0.5 <= b.rect[0] + b.rect[2]
                and b.rect[1] <= v + 0.5 <= b.rect[1] + b.rect[3]]
        return min(hits, key=lambda b: b.rect[2] * b.rect[3]) if hits else None

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
        self._picking = picking
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
        self._user_view = False
        if self._crop is not None:
            self.fitInView(self._crop, Qt.KeepAspectRatio)

    def zoom_by(self, factor: float) -> None:
        scale = self.transform().m11()
        factor = min(factor, MAX_ZOOM / max(scale, 1e-9))
        self.scale(factor, factor)
        self._user_view = True

    def user_moved_view(self) -> bool:
        return self._user_view

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
        if not self._user_view:  # a dock that grows or shrinks keeps the user's zoom
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
        if moved:
            self._user_view = True  # panned
        if event.button() == Qt.LeftButton and not moved and self.has_image():
            u, v = self.view_to_image(event.pos())
            if 0 <= u < self.sceneRect().width() and 0 <= v < self.sceneRect().height():
                box = None if self._picking else self.box_at(u, v)
                if box is not None:
                    self.boxClicked.emit(box.key)
                else:
                    self.imageClicked.emit(u, v)
        self._press_pos = None

    def view_to_image(self, pos) -> Tuple[float, float]:
        """Image pixel coordinates of a viewport position (pixel centres at integers)."""
        p: QPointF = self.mapToScene(pos)
        return p.x() - 0.5, p.y() - 0.5

    def image_to_view(self, u: float, v: float):
        return self.mapFromScene(QPointF(u + 0.5, v + 0.5))
