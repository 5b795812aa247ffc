"""Image helpers of the review: the crop around a sign and numpy BGR to QImage.

Runs in worker threads too: QImage (unlike QPixmap) may be built off the GUI thread.
"""

from __future__ import annotations

from typing import Tuple

import numpy as np
from qgis.PyQt.QtCore import Qt
from qgis.PyQt.QtGui import QImage

from ..signmapper_core.output.sign_crops import crop_box as crop_rect  # noqa: F401 - the review's name for it

Rect = Tuple[int, int, int, int]  # x, y, w, h


def bgr_to_qimage(bgr: np.ndarray) -> QImage:
    """A QImage owning a copy of a BGR uint8 image."""
    rgb = np.ascontiguousarray(bgr[:, :, ::-1])
    height, width = rgb.shape[:2]
    return QImage(rgb.data, width, height, 3 * width, QImage.Format_RGB888).copy()


def thumbnail(bgr: np.ndarray, bbox: Rect, size_px: int = 72) -> QImage:
    """The sign with a little context, scaled to ``size_px`` for the observation strip."""
    x, y, w, h = crop_rect(bbox, (bgr.shape[1], bgr.shape[0]), context=1.4, min_px=16)
    image = bgr_to_qimage(bgr[y:y + h, x:x + w])
    return image.scaled(size_px, size_px, Qt.KeepAspectRatio, Qt.SmoothTransformation)
