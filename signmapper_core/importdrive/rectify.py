"""Epipolar rectification: raw, slightly convergent stereo pairs into the normal case (OpenCV).

``cv2.stereoRectify`` turns both cameras about their centres so that their
image rows line up and their principal points agree (``CALIB_ZERO_DISPARITY``);
``alpha=0`` zooms so that every output pixel sees the scene (no black borders
for the colour step or the matcher). The undistort+rectify maps are computed
once per calibration (``cv2.initUndistortRectifyMap``, fixed-point maps) and
every pair goes through ``cv2.remap``. A calibration of normal images
(``StereoCalibration.rectified``) passes images through untouched.
"""

from __future__ import annotations

import numpy as np

from ..errors import ImportInputError
from ..geometry import Camera
from .calibration import StereoCalibration


class Rectifier:
    """Maps of one stereo calibration at one image size, and the camera of the normal images they give."""

    def __init__(self, calibration: StereoCalibration, size: tuple[int, int]):
        import cv2

        self.calibration = calibration
        self.size = (int(size[0]), int(size[1]))
        width, height = self.size
        if calibration.rectified:
            k = calibration.k1
            self.camera = Camera(width, height, float(k[0, 0]), float(k[1, 1]), float(k[0, 2]), float(k[1, 2]),
                                 abs(float(calibration.translation[0])))
            self.rotation = np.eye(3)  # raw left camera -> rectified left camera
            self.maps = None
            return
        r1, r2, p1, p2, _q, _roi1, _roi2 = cv2.stereoRectify(
            calibration.k1, calibration.d1, calibration.k2, calibration.d2, self.size, calibration.rotation,
            calibration.translation.reshape(3, 1), flags=cv2.CALIB_ZERO_DISPARITY, alpha=0)
        if abs(p2[1, 3]) > abs(p2[0, 3]):
            raise ImportInputError(calibration.source, "the cameras are above each other (vertical stereo); the "
                                   "drive format needs them side by side", field="T")
        baseline = -p2[0, 3] / p2[0, 0]
        if baseline <= 0:
            raise ImportInputError(calibration.source, "after rectification the right camera lies left of the left "
                                   "one; swap the left and right images", field="T")
        self.camera = Camera(width, height, float(p1[0, 0]), float(p1[1, 1]), float(p1[0, 2]), float(p1[1, 2]),
                             float(baseline))
        self.rotation = np.asarray(r1, dtype=float)
        self.maps = (cv2.initUndistortRectifyMap(calibration.k1, calibration.d1, r1, p1, self.size, cv2.CV_16SC2),
                     cv2.initUndistortRectifyMap(calibration.k2, calibration.d2, r2, p2, self.size, cv2.CV_16SC2))

    @property
    def resamples(self) -> bool:
        """Whether images are remapped (raw pairs) or passed through (normal images)."""
        return self.maps is not None

    def rectify(self, left: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The normal images of one raw pair (BGR or grey, the calibration's size)."""
        import cv2

        if self.maps is None:
            return left, right
        (lx, ly), (rx, ry) = self.maps
        return (cv2.remap(left, lx, ly, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT),
                cv2.remap(right, rx, ry, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT))

    def rectified_rotation(self, raw_to_world: np.ndarray) -> np.ndarray:
        """Camera -> world rotation(s) of the rectified left camera from the raw left camera's."""
        return np.asarray(raw_to_world, dtype=float) @ self.rotation.T
