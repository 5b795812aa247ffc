"""Where a pair's depth comes from: a given depth map, or semi-global matching of the pair.

A depth source supplies the depth of the searched window and its own noise policy: the
planarity residual it allows and how its search space is tidied before it cuts the colour
masks. The source is chosen once per pair (:func:`depth_source_for`); the detection steps
only ask it. Another matcher (or a learned one) is another class with these members:

- ``name``: for messages and timings;
- ``wants_candidate_boxes(config)``: whether it matches only around colour candidates found
  before depth (then the pipeline finds them and passes their boxes to ``depth_map``);
- ``depth_map(left, camera, config, roi, candidate_boxes)``: float32 metres, NaN = none;
- ``planarity_tolerance_px(config)``: the residual (disparity pixels) a plane may show;
- ``search_cut(search, config)``: the search-space mask as it cuts the colour masks.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Protocol, Tuple

import numpy as np

from ..geometry import Camera
from .depth import box_windows, match_windows, merge_row_bands, sgbm_depth
from .search_space import close_holes, grow

Box = Tuple[int, int, int, int]  # x, y, w, h
Roi = Tuple[int, int, int, int]  # x0, y0, x1, y1 (exclusive)


class DepthSource(Protocol):
    name: str

    def wants_candidate_boxes(self, config) -> bool: ...

    def depth_map(self, left: np.ndarray, camera: Camera, config, roi: Roi,
                  candidate_boxes: Optional[List[Box]]) -> np.ndarray: ...

    def planarity_tolerance_px(self, config) -> float: ...

    def search_cut(self, search: np.ndarray, config) -> np.ndarray: ...


@dataclass(frozen=True, eq=False)
class GivenDepth:
    """A depth map that came with the pair (a laser scan, a synthetic drive's true depth): used as it is.

    Its search space has small holes (a sign's uniform field, its pictogram) that are closed
    before it cuts the colour masks; planes fit it closely.
    """

    depth: np.ndarray
    name = "given"

    def wants_candidate_boxes(self, config) -> bool:
        return False

    def depth_map(self, left, camera, config, roi, candidate_boxes=None) -> np.ndarray:
        return np.asarray(self.depth, dtype=np.float32)

    def planarity_tolerance_px(self, config) -> float:
        return config.planarity.planarity_tolerance_px

    def search_cut(self, search: np.ndarray, config) -> np.ndarray:
        return close_holes(search, config.depth.search_close_px)


@dataclass(frozen=True, eq=False)
class StereoMatching:
    """Depth by semi-global matching of the left image against ``right`` (:func:`.depth.sgbm_depth`).

    With ``config.depth.sgbm_rows_only`` it matches only the rows of the colour candidates found before
    depth (with ``sgbm_box_windows`` only their boxes grown by a margin, else with ``sgbm_columns_only`` windows
    of their row bands around their columns), because matching dominates
    the time per pair; the Hough fallback then sees only these. Its depth is noisier than a given
    one: planes are allowed ``sgbm_planarity_tolerance_px`` and the search space is grown (SGBM
    loses a sign's left edge in front of a distant background) instead of only closed.
    """

    right: np.ndarray
    name = "sgbm"

    def wants_candidate_boxes(self, config) -> bool:
        return config.depth.sgbm_rows_only

    def depth_map(self, left, camera, config, roi, candidate_boxes=None) -> np.ndarray:
        """Depth over ``roi``'s rows, or only around ``candidate_boxes`` when given (none: no depth at all)."""
        x0, y0, x1, y1 = roi
        bands, windows = [(y0, y1)], None
        if candidate_boxes is not None:
            if config.depth.sgbm_box_windows:
                windows = box_windows(candidate_boxes, left.shape[1], left.shape[0], config.depth.sgbm_row_margin_px)
            elif config.depth.sgbm_columns_only:
                windows = match_windows(candidate_boxes, left.shape[1], left.shape[0], config.depth.sgbm_row_margin_px,
                                        config.depth.sgbm_row_margin_px)
            bands = merge_row_bands([(y, y + h) for _, y, _, h in candidate_boxes], left.shape[0],
                                    config.depth.sgbm_row_margin_px)
        if not bands:
            return np.full(left.shape[:2], np.nan, dtype=np.float32)
        return sgbm_depth(left, self.right, camera, config, bands, windows)

    def planarity_tolerance_px(self, config) -> float:
        return config.planarity.sgbm_planarity_tolerance_px

    def search_cut(self, search: np.ndarray, config) -> np.ndarray:
        return grow(search, config.depth.search_grow_px)


def depth_source_for(depth: Optional[np.ndarray], right: Optional[np.ndarray]) -> DepthSource:
    """The pair's depth source: its depth map where it has one, else matching against its right image."""
    if depth is not None:
        return GivenDepth(depth)
    if right is None:
        raise ValueError("no depth map and no right image: cannot compute depth")
    return StereoMatching(right)
