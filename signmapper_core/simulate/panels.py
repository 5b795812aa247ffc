"""A sign panel as the scene lays it out, and what every panel of a scene shares: the pieces that poles, plates
and panels all place."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..drive.reader import TruthSign
from .faces import FaceOptions
from .surfaces import Surface


@dataclass
class PlacedSign:
    """A sign panel as laid out: truth row when its face looks towards the vehicle."""

    truth: TruthSign | None
    colour: str
    centre: np.ndarray
    surfaces: list[Surface] = field(default_factory=list)
    host: PlacedSign | None = None  # a supplementary plate: the sign it hangs under


@dataclass(frozen=True)
class PanelLook:
    """What every panel of a scene shares: the focal length its face texture is sized for, the face
    options, and the realism switches that touch signs."""

    fx: float
    face_options: FaceOptions
    weathering: bool
    shadows: bool
    occlusion: bool  # a branch or pole may stand in front of a sign
    plate_share: float = 0.0  # share of poles whose lowest sign carries a supplementary plate (plate_layout)


def face_shape(size_px: int, w_m: float, h_m: float) -> tuple[int, int]:
    """(height, width) in pixels of a face texture whose longer side is ``size_px``."""
    if w_m >= h_m:
        return max(1, int(round(size_px * h_m / w_m))), size_px
    return size_px, max(1, int(round(size_px * w_m / h_m)))
