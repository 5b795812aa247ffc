"""Left images of a drive decoded in worker threads, ahead of where the user is stepping.

A frame is decoded to a QImage in the pixel format a pixmap uses natively
(32-bit BGRA), so showing it on the GUI thread costs one copy. A small cache
keeps the frames around the current one; stepping asks for the next few
frames before they are needed, so a Full-HD drive steps at display speed.
"""

from __future__ import annotations

from collections import OrderedDict
from typing import Callable, Dict, List

import cv2
import numpy as np
from qgis.PyQt.QtGui import QImage

CACHE_FRAMES = 12
PREFETCH = 4


def bgr_to_rgb32(bgr: np.ndarray) -> QImage:
    """A QImage (Format_RGB32, owning its pixels) of a BGR uint8 image."""
    bgra = cv2.cvtColor(bgr, cv2.COLOR_BGR2BGRA)
    height, width = bgra.shape[:2]
    return QImage(bgra.data, width, height, 4 * width, QImage.Format_RGB32).copy()


class FrameCache:
    """index -> QImage of the drive's left images, decoded by ``runner`` (review.background.BackgroundRunner)."""

    def __init__(self, runner, drive, on_error: Callable[[int, str], None], size: int = CACHE_FRAMES):
        self.runner, self.drive, self.on_error, self.size = runner, drive, on_error, size
        self._images: OrderedDict[int, QImage] = OrderedDict()
        self._pending: Dict[int, int] = {}  # index -> job token
        self._waiting: Dict[int, List[Callable[[QImage], None]]] = {}

    def ready(self, index: int) -> bool:
        return index in self._images

    def get(self, index: int, on_ready: Callable[[QImage], None]) -> None:
        """Call ``on_ready(image)`` now if decoded, else once decoded (the latest caller per frame only)."""
        if index in self._images:
            self._images.move_to_end(index)
            on_ready(self._images[index])
            return
        self._waiting[index] = [on_ready]
        self._load(index)

    def prefetch(self, indices) -> None:
        for index in indices:
            if 0 <= index < len(self.drive.pairs) and index not in self._images:
                self._load(index)

    def forget_waiting(self) -> None:
        """Drop the callbacks of frames not shown yet (the user moved on); their decoding still fills the cache."""
        self._waiting.clear()

    def clear(self) -> None:
        for token in self._pending.values():
            self.runner.forget(token)
        self._pending.clear()
        self._waiting.clear()
        self._images.clear()

    def _load(self, index: int) -> None:
        if index in self._pending:
            return
        record, drive = self.drive.pairs[index], self.drive

        def done(image):
            self._pending.pop(index, None)
            self._images[index] = image
            while len(self._images) > self.size:
                self._images.popitem(last=False)
            for callback in self._waiting.pop(index, []):
                callback(image)

        def failed(message):
            self._pending.pop(index, None)
            self._waiting.pop(index, None)
            self.on_error(index, message.splitlines()[0])

        self._pending[index] = self.runner.submit(lambda: bgr_to_rgb32(drive.load_left(record)), done, failed)
