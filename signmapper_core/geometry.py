"""Pose rotation and pixel/world transforms exactly as ``drive-format.md`` defines them.

Camera frame: x right, y down, z forward. World: easting, northing, height.
``R = Rz(-heading) @ R0 @ Rx(pitch) @ Rz(roll)`` and ``Xw = C + R @ Xc``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

# Camera looking north, level: x -> east, y -> down, z -> north.
R0 = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])


def rot_z(angle_rad: float) -> np.ndarray:
    """Right-handed rotation about z by ``angle_rad``."""
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_x(angle_rad: float) -> np.ndarray:
    """Right-handed rotation about x by ``angle_rad``."""
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def camera_rotation(heading_deg: float, pitch_deg: float, roll_deg: float) -> np.ndarray:
    """Rotation matrix camera -> world for the spec's heading/pitch/roll in degrees."""
    h, p, r = np.radians([heading_deg, pitch_deg, roll_deg])
    return rot_z(-h) @ R0 @ rot_x(p) @ rot_z(r)


def angles_from_rotation(rotation: np.ndarray) -> tuple[float, float, float]:
    """Inverse of :func:`camera_rotation`: (heading, pitch, roll) in degrees.

    Heading in [0, 360), pitch in [-90, 90], roll in (-180, 180].
    """
    z_axis = rotation[:, 2]  # optical axis in world
    heading = np.degrees(np.arctan2(z_axis[0], z_axis[1])) % 360.0
    pitch = np.degrees(np.arcsin(np.clip(z_axis[2], -1.0, 1.0)))
    # Remove heading and pitch; what is left is Rz(roll).
    rest = (rot_z(-np.radians(heading)) @ R0 @ rot_x(np.radians(pitch))).T @ rotation
    roll = np.degrees(np.arctan2(rest[1, 0], rest[0, 0]))
    return float(heading), float(pitch), float(roll)


@dataclass(frozen=True)
class Camera:
    """Pinhole model shared by the left and right normal images."""

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    baseline_m: float

    def disparity_from_depth(self, depth_m):
        """Disparity in pixels of a point at depth ``Z``: ``d = fx * B / Z``."""
        return self.fx * self.baseline_m / np.asarray(depth_m, dtype=float)

    def depth_from_disparity(self, disparity_px):
        """Depth ``Z = fx * B / d``; non-positive disparities give NaN."""
        d = np.asarray(disparity_px, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(d > 0, self.fx * self.baseline_m / d, np.nan)

    def pixel_to_camera(self, u, v, depth_m) -> np.ndarray:
        """Camera coordinates (..., 3) of pixels with depth ``Z`` along the optical axis."""
        u, v, z = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (u, v, depth_m)))
        return np.stack([(u - self.cx) * z / self.fx, (v - self.cy) * z / self.fy, z], axis=-1)

    def camera_to_pixel(self, xc: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Pixel (u, v) and depth Z of camera points (..., 3)."""
        xc = np.asarray(xc, dtype=float)
        z = xc[..., 2]
        with np.errstate(divide="ignore", invalid="ignore"):
            u = self.cx + self.fx * xc[..., 0] / z
            v = self.cy + self.fy * xc[..., 1] / z
        return u, v, z


@dataclass(frozen=True)
class Pose:
    """Exterior orientation of a stereo pair's left camera."""

    easting: float
    northing: float
    height: float
    heading: float
    pitch: float
    roll: float

    @property
    def centre(self) -> np.ndarray:
        return np.array([self.easting, self.northing, self.height])

    @property
    def rotation(self) -> np.ndarray:
        return camera_rotation(self.heading, self.pitch, self.roll)

    def camera_to_world(self, xc: np.ndarray) -> np.ndarray:
        """World coordinates of camera points (..., 3)."""
        return self.centre + np.asarray(xc, dtype=float) @ self.rotation.T

    def world_to_camera(self, xw: np.ndarray) -> np.ndarray:
        """Camera coordinates of world points (..., 3)."""
        return (np.asarray(xw, dtype=float) - self.centre) @ self.rotation


def pixel_to_world(camera: Camera, pose: Pose, u, v, depth_m) -> np.ndarray:
    """World coordinates (..., 3) of pixels (u, v) with depth Z."""
    return pose.camera_to_world(camera.pixel_to_camera(u, v, depth_m))


def world_to_pixel(camera: Camera, pose: Pose, xw) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pixel (u, v) and depth Z of world points; Z <= 0 means behind the camera."""
    return camera.camera_to_pixel(pose.world_to_camera(xw))
