"""Do the rows line up? Vertical disparity of matched features in a pair of normal images.

Corners of the left image (``goodFeaturesToTrack``, refined to a tenth of a
pixel by ``cornerSubPix``) are followed into the right image by pyramidal
Lucas-Kanade, kept where tracking back lands within ``FB_MAX_PX`` of the start,
and cleaned of mismatches by a RANSAC fundamental matrix. In a well rectified
pair their vertical disparity ``y_right - y_left`` is zero up to the matching
noise; the drive's stereo matcher searches along rows only, so a mean absolute
vertical disparity above half a pixel means the calibration does not fit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

FB_MAX_PX = 0.5        # forward-backward tracking error allowed for a match
RANSAC_PX = 1.0        # distance to the epipolar line for a RANSAC inlier
MIN_MATCHES = 20       # fewer matches tell nothing about the rows


@dataclass(frozen=True)
class EpipolarCheck:
    """Matched features of one pair and their vertical disparity (pixels)."""

    left: np.ndarray     # (n, 2) x, y in the left image
    right: np.ndarray    # (n, 2) x, y in the right image

    @property
    def matches(self) -> int:
        return int(len(self.left))

    @property
    def dy(self) -> np.ndarray:
        return self.right[:, 1] - self.left[:, 1]

    @property
    def mean_abs_dy(self) -> float:
        return float(np.mean(np.abs(self.dy))) if self.matches else float("nan")

    @property
    def mean_dy(self) -> float:
        return float(np.mean(self.dy)) if self.matches else float("nan")

    @property
    def enough(self) -> bool:
        return self.matches >= MIN_MATCHES

    def summary(self) -> dict:
        """The figures as drive.json keeps them."""
        return {"matches": self.matches, "mean_abs_vertical_disparity_px": round(self.mean_abs_dy, 4),
                "mean_vertical_disparity_px": round(self.mean_dy, 4)}

    def text(self) -> str:
        if not self.matches:
            return "no features could be matched between the left and right image"
        return (f"mean vertical disparity {self.mean_abs_dy:.2f} px (absolute; signed {self.mean_dy:+.2f} px) "
                f"over {self.matches} matched features")


def grey(image: np.ndarray) -> np.ndarray:
    import cv2

    return image if image.ndim == 2 else cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)


LK_CRITERIA = (3, 40, 0.001)   # cv2.TERM_CRITERIA_EPS | COUNT, 40 iterations, 0.001 px


def corners(grey_image: np.ndarray, max_features: int = 1500) -> np.ndarray:
    """Well-textured points (n, 2) of an image, refined to sub-pixel positions."""
    import cv2

    spacing = max(5, min(grey_image.shape) // 60)
    found = cv2.goodFeaturesToTrack(grey_image, maxCorners=max_features, qualityLevel=0.005, minDistance=spacing,
                                    blockSize=7)
    if found is None:
        return np.zeros((0, 2), np.float32)
    return cv2.cornerSubPix(grey_image, found.astype(np.float32), (5, 5), (-1, -1), LK_CRITERIA).reshape(-1, 2)


def track(grey_a: np.ndarray, grey_b: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Positions in ``grey_b`` of ``points`` of ``grey_a`` (pyramidal Lucas-Kanade) and which are trustworthy:
    tracked both ways, back within ``FB_MAX_PX``."""
    import cv2

    points = np.asarray(points, np.float32).reshape(-1, 1, 2)
    if not len(points):
        return np.zeros((0, 2)), np.zeros(0, bool)
    lk = {"winSize": (21, 21), "maxLevel": 5, "criteria": LK_CRITERIA}
    forward, ok_f, _ = cv2.calcOpticalFlowPyrLK(grey_a, grey_b, points, None, **lk)
    back, ok_b, _ = cv2.calcOpticalFlowPyrLK(grey_b, grey_a, forward, None, **lk)
    good = (ok_f.ravel() == 1) & (ok_b.ravel() == 1)
    good &= np.linalg.norm((back - points).reshape(-1, 2), axis=1) < FB_MAX_PX
    return forward.reshape(-1, 2).astype(float), good


def match_features(left: np.ndarray, right: np.ndarray, max_features: int = 1500) -> EpipolarCheck:
    """Matched features of a stereo pair (see module)."""
    import cv2

    grey_l, grey_r = grey(left), grey(right)
    start = corners(grey_l, max_features)
    empty = EpipolarCheck(np.zeros((0, 2)), np.zeros((0, 2)))
    if len(start) < 8:
        return empty
    found, good = track(grey_l, grey_r, start)
    pl, pr = start[good].astype(float), found[good]
    if len(pl) < 8:
        return EpipolarCheck(pl, pr)
    _, inliers = cv2.findFundamentalMat(pl, pr, cv2.FM_RANSAC, RANSAC_PX, 0.999)
    if inliers is None:
        return empty
    keep = inliers.ravel() == 1
    return EpipolarCheck(pl[keep], pr[keep])


def draw_check(left: np.ndarray, right: np.ndarray, check: EpipolarCheck, lines: int = 14) -> np.ndarray:
    """Left and right side by side with rows through some matched features: both ends must sit on the line."""
    import cv2

    def bgr(image):
        return cv2.cvtColor(image, cv2.COLOR_GRAY2BGR) if image.ndim == 2 else image.copy()

    a, b = bgr(left), bgr(right)
    width = a.shape[1]
    canvas = np.hstack([a, b])
    scale = max(1, canvas.shape[0] // 500)
    if check.matches:
        order = np.argsort(check.left[:, 1])
        chosen = order[np.linspace(0, len(order) - 1, min(lines, len(order))).astype(int)]
        for k, i in enumerate(chosen):
            colour = tuple(int(c) for c in cv2.applyColorMap(np.uint8([[k * 255 // max(1, lines - 1)]]),
                                                             cv2.COLORMAP_JET)[0, 0])
            (xl, yl), (xr, yr) = check.left[i], check.right[i]
            row = int(round(yl))
            cv2.line(canvas, (0, row), (canvas.shape[1] - 1, row), colour, scale, cv2.LINE_AA)
            cv2.circle(canvas, (int(round(xl)), int(round(yl))), 5 * scale, colour, scale, cv2.LINE_AA)
            cv2.circle(canvas, (int(round(xr)) + width, int(round(yr))), 5 * scale, colour, scale, cv2.LINE_AA)
    text = check.text()
    (text_width, text_height), _ = cv2.getTextSize(text, cv2.FONT_HERSHEY_SIMPLEX, 1.0, 1)
    font = min(0.8 * scale, 0.95 * canvas.shape[1] / text_width)
    thick = max(1, int(round(font)))
    for thickness, colour in ((3 * thick, (0, 0, 0)), (thick, (255, 255, 255))):
        cv2.putText(canvas, text, (8, int(8 + text_height * font)), cv2.FONT_HERSHEY_SIMPLEX, font, colour,
                    thickness, cv2.LINE_AA)
    return canvas
