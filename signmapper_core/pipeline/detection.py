"""The result of the pipeline for one sign seen in one stereo pair."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, Optional, Tuple

import numpy as np


@dataclass
class Detection:
    """One detected sign face in one pair; indicators are 0..1.

    ``detection_indicator``: planar share of the segment (is it a sign?);
    ``classification_indicator``: best template NCC (is it this sign?).
    ``status`` is "accepted" when the classification indicator reaches the
    threshold, else "review".
    """

    template_id: Optional[str]
    name: str
    colour: str
    shape: str
    width_m: float
    height_m: float
    format: str
    detection_indicator: float
    classification_indicator: float
    status: str
    u: float
    v: float
    bbox: Tuple[int, int, int, int]
    depth_m: float
    position: np.ndarray
    # "colour" segmentation, "hole" (the field inside a ring), "frame" (a white-framed diamond, by brightness),
    # "half" (a disc read from the half that kept its colour) or "hough" fallback
    source: str = "colour"
    scores: Dict[str, float] = field(default_factory=dict)  # NCC per candidate template
    normal_world: Optional[np.ndarray] = None  # unit face normal (E, N, H) from the fitted plane, towards the camera
    # a supplementary plate (pipeline/plates.py): the sign's detection it belongs to, and its image for OCR
    plate_of: Optional[Detection] = None
    # the image OCR reads: a plate's or text panel's box, a speed limit's digits' band (grey, printed_numbers)
    crop: Optional[np.ndarray] = field(default=None, repr=False)
    printed_text: Optional[str] = None  # a pictogram plate: the words its drawing carries ("" for none)
    # a plate: the share of its crop seen whole: inside the image's edges and not hidden by something in front
    # (1.0 for a plate seen whole); its text is read from the views that saw most of it
    crop_seen: float = 1.0
    # the rule that held it for review whatever its indicator (review_reasons); "" for none or a low indicator
    review_reason: str = ""

    @property
    def is_plate(self) -> bool:
        return self.plate_of is not None
