"""View-model of the review dock: everything it shows of one feature, already read and decoded.

The controller fills it from the layer, the drive and the catalogue; the dock
only displays it. Images arrive later than the attributes (they are decoded off
the GUI thread), so they are optional.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import List, Optional, Tuple

from qgis.PyQt.QtGui import QImage


@dataclass
class ObservationView:
    """One detection of a fused sign as the strip shows it: a thumbnail of its box and a label."""

    pair_id: str
    label: str
    thumbnail: Optional[QImage] = None
    template_id: str = ""
    bbox: Tuple[int, int, int, int] = (0, 0, 0, 0)  # in the left image of pair_id


@dataclass
class ReviewItem:
    """One feature of a ``signs`` or ``detections`` layer as the dock shows it."""

    layer_kind: str  # "signs" or "detections"
    fid: int
    title: str
    template_id: str = ""
    name: str = ""
    colour: str = ""
    shape: str = ""
    format: str = ""
    size_m: Tuple[float, float] = (0.0, 0.0)
    status: str = ""
    reviewed: bool = False
    detection_indicator: Optional[float] = None
    classification_indicator: Optional[float] = None
    pair_id: str = ""
    time: Optional[float] = None
    depth_m: Optional[float] = None
    extra: List[Tuple[str, str]] = field(default_factory=list)  # e.g. n_obs, vote share for fused signs
    pictogram_path: str = ""
    bbox: Optional[Tuple[int, int, int, int]] = None
    centroid: Optional[Tuple[float, float]] = None
    crop: Optional[Tuple[int, int, int, int]] = None  # x, y, w, h of the region around the sign
    image: Optional[QImage] = None  # the whole left image of pair_id
    observations: Optional[List[ObservationView]] = None  # None for a detection; list (maybe empty) for a sign
    position: Optional[Tuple[float, float, float]] = None
    plate_of: Optional[int] = None  # a supplementary plate: the sign_id of its sign
    text: Optional[str] = None  # a plate's text as read (or as a person set it)
    text_confidence: Optional[float] = None
    alternatives: List[Tuple[str, float]] = field(default_factory=list)  # the classifier's next choices, best first
    review_reason: str = ""  # why the mapping left it for review

    @property
    def is_plate(self) -> bool:
        return self.plate_of is not None

    def crop_image(self) -> Optional[QImage]:
        """The crop around the sign as a separate image (what the view opens zoomed to)."""
        if self.image is None or self.crop is None:
            return None
        return self.image.copy(*self.crop)
