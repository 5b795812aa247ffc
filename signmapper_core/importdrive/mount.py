"""Where the left camera sits on the body whose pose was recorded: lever arm and boresight.

The lever arm is the left camera's projection centre in the body's own axes
(metres, the axes of the angle convention, ``Convention.body_axes``). The
boresight is the camera's heading, pitch and roll *relative to the body*, read
as the drive format reads a camera's angles with the body's forward direction
as north and its up as up: (0, 0, 0) looks straight ahead, heading 90 looks to
the right, pitch -5 looks 5 degrees down. A calibration that gives the full
camera-to-body rotation (KITTI) makes a :class:`Mount` directly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geometry import camera_rotation
from .attitude import Convention


@dataclass(frozen=True)
class Mount:
    """Rigid transform from the (raw, physical) left camera to the body.

    ``rotation`` maps drive-camera coordinates (x right, y down, z forward) to body
    coordinates; ``lever_arm_m`` is the camera centre in body coordinates.
    """

    rotation: np.ndarray
    lever_arm_m: np.ndarray

    @classmethod
    def from_boresight(cls, conv: Convention, lever_arm_m=(0.0, 0.0, 0.0),
                       boresight_deg=(0.0, 0.0, 0.0)) -> Mount:
        """Mount from a lever arm (body axes, m) and boresight heading/pitch/roll (degrees, see module)."""
        right_forward_up = np.column_stack([conv.right, conv.forward, conv.up])
        rotation = right_forward_up @ camera_rotation(*(float(a) for a in boresight_deg))
        return cls(rotation, np.asarray(lever_arm_m, dtype=float).reshape(3))

    def camera_pose(self, body_centre: np.ndarray, body_to_world: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(camera centre, camera -> world rotation) of a body at ``body_centre`` oriented ``body_to_world``.

        Works on one pose ((3,), (3, 3)) or many ((n, 3), (n, 3, 3)).
        """
        body_to_world = np.asarray(body_to_world, dtype=float)
        centre = np.asarray(body_centre, dtype=float) + body_to_world @ self.lever_arm_m
        return centre, body_to_world @ self.rotation
