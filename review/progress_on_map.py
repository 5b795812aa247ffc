"""The review's progress drawn on the map canvas: "signs: 3 to review · 12 of 20 reviewed" in a corner box."""

from __future__ import annotations

from qgis.gui import QgsMapCanvasItem
from qgis.PyQt.QtCore import QRectF, Qt
from qgis.PyQt.QtGui import QBrush, QColor, QFont, QFontMetricsF, QPen

from ..signmapper_core.statuses import REVIEW, STATUS_COLOURS

MARGIN_PX = 10


class ReviewProgressItem(QgsMapCanvasItem):
    """A fixed box in the canvas's top left corner (it does not move with the map)."""

    def __init__(self, canvas):
        super().__init__(canvas)
        self.text = ""
        self.to_review = 0
        self.font = QFont()
        self.font.setBold(True)
        self.setZValue(1000)
        self.hide()

    def set_progress(self, layer_name: str, to_review: int, reviewed: int, total: int) -> None:
        self.text = f"Sign Mapper · {layer_name}: {to_review} to review · {reviewed} of {total} reviewed"
        self.to_review = to_review
        self.prepareGeometryChange()
        self.show()
        self.update()

    def clear(self) -> None:
        self.text = ""
        self.hide()

    def _rect(self) -> QRectF:
        metrics = QFontMetricsF(self.font)
        return QRectF(0, 0, metrics.horizontalAdvance(self.text) + 16, metrics.height() + 8)

    def boundingRect(self):  # noqa: N802 - Qt override
        return self._rect()

    def updatePosition(self):  # noqa: N802 - QgsMapCanvasItem: keep the box in the corner, not on the map
        self.setPos(MARGIN_PX, MARGIN_PX)

    def paint(self, painter, option=None, widget=None):
        if not self.text:
            return
        self.setPos(MARGIN_PX, MARGIN_PX)
        rect = self._rect()
        colour = QColor(STATUS_COLOURS[REVIEW]) if self.to_review else QColor("#2e7d32")
        painter.setPen(QPen(colour, 2))
        painter.setBrush(QBrush(QColor(255, 255, 255, 225)))
        painter.drawRoundedRect(rect, 4, 4)
        painter.setFont(self.font)
        painter.setPen(QColor("#212121"))
        painter.drawText(rect, Qt.AlignCenter, self.text)
