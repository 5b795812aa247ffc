"""Face direction of a sign from the plane fitted to its disparities.

A plane in disparity space, ``d = a + b*u + c*v``, is a plane in the camera
frame: multiplying ``fx*B/Z = a + b*(cx + fx*X/Z) + c*(cy + fy*Y/Z)`` by Z gives
``b*fx*X + c*fy*Y + (a + b*cx + c*cy)*Z = fx*B``. Its normal, turned towards the
camera, is the direction the sign face looks; in world coordinates its
horizontal part gives the face azimuth.
"""

from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from ..geometry import Camera, Pose


def normal_from_disparity_plane(camera: Camera, plane: Sequence[float]) -> Optional[np.ndarray]:
    """Unit normal in the camera frame, pointing from the face towards the camera; None if degenerate."""
    a, b, c = (float(x) for x in plane)
    n = np.array([b * camera.fx, c * camera.fy, a + b * camera.cx + c * camera.cy])
    norm = np.linalg.norm(n)
    if not np.isfinite(norm) or norm == 0:
        return None
    n /= norm
    return -n if n[2] > 0 else n  # the plane lies in front (+Z); its face looks back at the camera


def world_face_normal(camera: Camera, pose: Pose, plane) -> Optional[np.ndarray]:
    """The face normal in world coordinates (E, N, H components)."""
    if plane is None:
        return None
    n = normal_from_disparity_plane(camera, plane)
    return None if n is None else pose.rotation @ n
