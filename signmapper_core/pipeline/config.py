"""Settings of the detection pipeline, one frozen dataclass so a run is reproducible.

Defaults follow Cavegn (2011): a 4-14 m search space in front of the camera and
HSV thresholds for the three sign colours. Hue is OpenCV's 0-179 scale.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, Optional, Tuple

# (hue_lo, hue_hi, sat_lo, sat_hi, val_lo, val_hi); several ranges per colour are OR-ed.
HsvRange = Tuple[int, int, int, int, int, int]

DEFAULT_HSV_RANGES: Dict[str, Tuple[HsvRange, ...]] = {
    # red wraps around hue 0, so it needs both ends of the hue circle
    "red": ((0, 10, 90, 255, 50, 255), (165, 179, 90, 255, 50, 255)),
    "blue": ((100, 130, 110, 255, 40, 255),),
    "yellow": ((16, 35, 110, 255, 90, 255),),
}


@dataclass(frozen=True)
class PipelineConfig:
    """All thresholds of the detection steps; the first six are the documented contract."""

    near_m: float = 4.0
    far_m: float = 14.0
    colours: Tuple[str, ...] = ("red", "blue", "yellow")
    exclude: Tuple[str, ...] = ()
    detection_threshold: float = 0.5  # planar share of a segment needed to keep it
    classification_threshold: Optional[float] = None  # indicator needed for "accepted"; None = the classifier's own
    classifier: str = "auto"  # "cnn" (learned network of the catalogue), "ncc" (template matching), "auto" (cnn if
    # the catalogue has a network)
    size_tolerance: float = 0.15  # relative deviation from a standard format

    # colour segmentation
    hsv_ranges: Dict[str, Tuple[HsvRange, ...]] = field(default_factory=lambda: dict(DEFAULT_HSV_RANGES))
    morph_open_px: int = 3  # removes speckle
    morph_close_px: int = 5  # bridges small gaps in a sign's ring
    min_segment_px: int = 150  # smaller segments cannot be sized or classified reliably
    min_bbox_px: int = 12
    search_close_px: int = 15  # holes of a given depth's search space this small are closed before it cuts colours
    search_grow_px: int = 31  # with SGBM depth the search space is grown by this much instead
    border_margin_px: int = 2  # segments this close to the image border are cut and rejected
    max_merge_pieces: int = 40  # rejected segments tried in pairs (faces split by an occluder)

    # shape
    min_shape_fit: float = 0.72  # IoU with the best ideal outline

    # depth from stereo (used when no depth map is given)
    sgbm_scale: float = 0.5  # SGBM on a downscaled pair: ~8x faster, disparity still sub-pixel
    sgbm_block_size: int = 5
    sgbm_rows_only: bool = True  # match only the row bands holding colour candidates
    sgbm_row_margin_px: int = 24
    sgbm_far_factor: float = 2.0  # search disparities down to far*2: far points then match outside the range
    sgbm_uniqueness: int = 15

    # planarity (detection indicator)
    planarity_window_px: int = 7
    planarity_tolerance_px: float = 0.6  # residual in full-resolution disparity pixels, given depth
    sgbm_planarity_tolerance_px: float = 1.0  # the same for half-scale SGBM depth (noisier: 17% of true
    # signs fell below 0.5 at 0.6 px on a synthetic drive, 3% at 1.0 px)
    max_slant_deg: float = 45.0  # signs face the road, roughly along the optical axis
    min_depth_coverage: float = 0.3  # share of a segment's pixels needing a valid depth

    # classification
    min_surround_score: float = 0.5  # a panel reading needs its part outside the colour segment to match
    min_classification_score: Optional[float] = None  # below this the segment is not reported; None = classifier's
    scales: Tuple[float, ...] = (0.92, 1.0, 1.08)
    shift_fraction: float = 0.08  # shift search, as a fraction of the segment size
    max_template_px: int = 96  # larger segments are compared downscaled

    # Hough fallback for faded or white/grey round signs
    hough_enabled: bool = True
    hough_scale: float = 0.5
    hough_circularity: float = 0.85  # param2 of HOUGH_GRADIENT_ALT
    hough_edge_threshold: float = 150.0  # param1 of HOUGH_GRADIENT_ALT
    hough_max_status: str = "review"  # status cap of Hough finds whose ring is not in full colour
    hough_max_diameter_m: float = 0.6  # larger round formats only by colour: the radius range sets the cost

    def __post_init__(self):
        if not 0 < self.near_m < self.far_m:
            raise ValueError(f"need 0 < near_m < far_m, got {self.near_m}, {self.far_m}")
        from .classifiers import CLASSIFIERS

        if self.classifier not in CLASSIFIERS:
            raise ValueError(f"unknown classifier {self.classifier!r}; choose one of {', '.join(CLASSIFIERS)}")
        unknown = set(self.colours) - set(self.hsv_ranges)
        if unknown:
            raise ValueError(f"no HSV thresholds for colours {sorted(unknown)}")
