"""Angle conventions of navigation and photogrammetry exports, as rotations body -> east/north/up.

Every convention turns three angles (degrees) into the rotation ``R`` that takes
vectors from the *body* frame of the thing whose orientation was recorded (an
IMU, a camera) to a local east/north/up frame, and back. Which north that frame
has (true north of the local level, or the grid north of a projected CRS) is
the caller's business (``crs_steps``). Body frames:

``ned_ypr``     navigation, aerospace: body x forward, y right, z down; yaw = heading clockwise
                from north, pitch positive nose up, roll positive right side down;
                ``R_ned = Rz(yaw) Ry(pitch) Rx(roll)`` (NED local frame).
``enu_ypr``     navigation, ROS REP-103 / KITTI OXTS: body x forward, y left, z up; yaw counter-clockwise
                from east, pitch positive nose down, roll positive left side up;
                ``R_enu = Rz(yaw) Ry(pitch) Rx(roll)``.
``opk``         photogrammetric omega/phi/kappa: camera x right, y up, looking along -z;
                ``R = Rx(omega) Ry(phi) Rz(kappa)`` (omega = 90 looks north, level).
``camera_hpr``  the drive format's own: camera x right, y down, z forward (optical axis); heading clockwise
                from north, pitch of the axis above the horizon, roll clockwise seen from behind
                (``geometry.camera_rotation``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..geometry import angles_from_rotation as camera_angles
from ..geometry import camera_rotation, rot_x, rot_z

# NED <-> ENU: swap x and y, negate z (its own inverse).
NED_TO_ENU = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
# The photogrammetric camera (x right, y up, z back) against the drive's camera (x right, y down, z forward).
OPK_TO_CAMERA = np.diag([1.0, -1.0, -1.0])


def rot_y(angle_rad: float) -> np.ndarray:
    """Right-handed rotation about y by ``angle_rad``."""
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _zyx(a: float, b: float, c: float) -> np.ndarray:
    """``Rz(a) Ry(b) Rx(c)``, angles in degrees."""
    a, b, c = np.radians([a, b, c])
    return rot_z(a) @ rot_y(b) @ rot_x(c)


def _zyx_angles(r: np.ndarray) -> tuple[float, float, float]:
    """Inverse of :func:`_zyx`: (a, b, c) in degrees, b in [-90, 90]."""
    b = np.degrees(np.arcsin(np.clip(-r[2, 0], -1.0, 1.0)))
    a = np.degrees(np.arctan2(r[1, 0], r[0, 0]))
    c = np.degrees(np.arctan2(r[2, 1], r[2, 2]))
    return float(a), float(b), float(c)


def _xyz(a: float, b: float, c: float) -> np.ndarray:
    """``Rx(a) Ry(b) Rz(c)``, angles in degrees."""
    a, b, c = np.radians([a, b, c])
    return rot_x(a) @ rot_y(b) @ rot_z(c)


def _xyz_angles(r: np.ndarray) -> tuple[float, float, float]:
    """Inverse of :func:`_xyz`: (a, b, c) in degrees, b in [-90, 90]."""
    b = np.degrees(np.arcsin(np.clip(r[0, 2], -1.0, 1.0)))
    a = np.degrees(np.arctan2(-r[1, 2], r[2, 2]))
    c = np.degrees(np.arctan2(-r[0, 1], r[0, 0]))
    return float(a), float(b), float(c)


@dataclass(frozen=True)
class Convention:
    """One way of writing an orientation down."""

    name: str
    title: str                 # for dialogs and help
    angle_names: tuple[str, str, str]
    body_axes: str             # what x, y, z of the body are (lever arms are given in these axes)
    camera_like: bool          # the body is a camera (per-image exterior orientation), not a vehicle
    to_enu: Callable[[float, float, float], np.ndarray]
    from_enu: Callable[[np.ndarray], tuple[float, float, float]]
    # the body's forward, right and up directions in its own axes (boresight angles are relative to them)
    forward: tuple[float, float, float]
    right: tuple[float, float, float]
    up: tuple[float, float, float]

    def rotation(self, angles_deg) -> np.ndarray:
        """Body -> east/north/up rotation for one row of three angles in degrees."""
        a, b, c = (float(v) for v in angles_deg)
        return self.to_enu(a, b, c)

    def angles(self, rotation: np.ndarray) -> tuple[float, float, float]:
        """The three angles (degrees) of a body -> east/north/up rotation: the inverse of :meth:`rotation`."""
        return self.from_enu(np.asarray(rotation, dtype=float))


def _ned_to_enu(yaw, pitch, roll):
    return NED_TO_ENU @ _zyx(yaw, pitch, roll)


def _ned_from_enu(r):
    yaw, pitch, roll = _zyx_angles(NED_TO_ENU @ r)
    return yaw % 360.0, pitch, roll


def _opk_to_enu(omega, phi, kappa):
    return _xyz(omega, phi, kappa)


def _camera_hpr_to_enu(heading, pitch, roll):
    return camera_rotation(heading, pitch, roll)


CONVENTIONS: dict[str, Convention] = {
    c.name: c
    for c in (
        Convention("ned_ypr", "Navigation yaw/pitch/roll, NED (heading clockwise from north; x fwd, y right, z down)",
                   ("yaw", "pitch", "roll"), "x forward, y right, z down", False, _ned_to_enu, _ned_from_enu,
                   (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, -1.0)),
        Convention("enu_ypr", "Navigation yaw/pitch/roll, ENU (yaw counter-clockwise from east; x fwd, y left, "
                   "z up; KITTI OXTS, ROS)", ("yaw", "pitch", "roll"), "x forward, y left, z up", False,
                   _zyx, _zyx_angles, (1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
        Convention("opk", "Photogrammetric omega/phi/kappa (camera x right, y up, looking along -z)",
                   ("omega", "phi", "kappa"), "x right, y up, z backwards (camera)", True, _opk_to_enu,
                   _xyz_angles, (0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
        Convention("camera_hpr", "Camera heading/pitch/roll of the drive format (x right, y down, z forward)",
                   ("heading", "pitch", "roll"), "x right, y down, z forward (camera)", True, _camera_hpr_to_enu,
                   camera_angles, (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, -1.0, 0.0)),
    )
}


def convention(name: str) -> Convention:
    """The convention called ``name``; ValueError listing the known ones otherwise."""
    try:
        return CONVENTIONS[name]
    except KeyError:
        raise ValueError(f"unknown angle convention {name!r}; known: {', '.join(CONVENTIONS)}") from None


def forward_heading(rotation: np.ndarray, conv: Convention) -> float:
    """Azimuth (degrees clockwise from the frame's north) of the body's forward direction."""
    forward = np.asarray(rotation) @ np.asarray(conv.forward)
    return float(np.degrees(np.arctan2(forward[0], forward[1])) % 360.0)
