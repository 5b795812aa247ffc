"""Does a static point map to one place from several pairs? The check of an imported drive's poses.

Corners of one pair's left image, matched into its right image, are placed in
the world by their disparity and the pair's pose; then followed into the next
pairs' left images (Lucas-Kanade, forward-backward) and matched again into
their right images. A point of the static scene gets one world position per
pair; with right poses, calibration and rectification they coincide up to the
matching noise, while a pose error (a heading off, a lever arm forgotten, a
wrong convergence) moves them apart from pair to pair. The spread of a point is
the RMS distance of its positions to their mean; moving objects spread far and
are why the figures are medians and percentiles.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geometry import pixel_to_world
from ..pipeline.config import DepthConfig
from .epipolar import grey, match_features, track

MAX_DY_PX = 1.0   # a left-right match off its row by more than this is no match in a normal pair


@dataclass(frozen=True)
class PointSpread:
    """World positions of points followed through ``pairs`` consecutive pairs."""

    pairs: list[str]            # ids of the pairs
    positions: np.ndarray       # (points, pairs, 3): E, N, H per pair

    @property
    def spread_3d(self) -> np.ndarray:
        """RMS distance (m) of each point's positions to their mean."""
        centred = self.positions - self.positions.mean(axis=1, keepdims=True)
        return np.sqrt((centred ** 2).sum(axis=2).mean(axis=1))

    @property
    def spread_plan(self) -> np.ndarray:
        centred = self.positions[:, :, :2] - self.positions[:, :, :2].mean(axis=1, keepdims=True)
        return np.sqrt((centred ** 2).sum(axis=2).mean(axis=1))

    def text(self) -> str:
        if not len(self.positions):
            return f"no point followed through pairs {self.pairs[0]}..{self.pairs[-1]}"
        s3, s2 = self.spread_3d, self.spread_plan
        return (f"{len(s3)} static points through {len(self.pairs)} pairs ({self.pairs[0]}..{self.pairs[-1]}): "
                f"spread median {100 * np.median(s3):.1f} cm 3D / {100 * np.median(s2):.1f} cm planimetric, "
                f"68 % within {100 * np.percentile(s3, 68):.1f} cm, 90 % within {100 * np.percentile(s3, 90):.1f} cm")


def _world(drive, record, left_grey, right_grey, points_left: np.ndarray, near_m: float, far_m: float):
    """World positions of left-image points matched into the right image (NaN where no trustworthy match)."""
    found, ok = track(left_grey, right_grey, points_left)
    out = np.full((len(points_left), 3), np.nan)
    if not len(points_left):
        return out
    ok &= np.abs(found[:, 1] - points_left[:, 1]) < MAX_DY_PX
    depth = drive.camera.depth_from_disparity(points_left[:, 0] - found[:, 0])
    ok &= np.isfinite(depth) & (depth >= near_m) & (depth <= far_m)
    out[ok] = pixel_to_world(drive.camera, record.pose, points_left[ok, 0], points_left[ok, 1], depth[ok])
    return out


def static_point_spread(drive, start: int, pairs: int = 4, near_m: float = DepthConfig.near_m,
                        far_m: float = 20.0) -> PointSpread:
    """Points of pair ``start`` followed through ``pairs`` consecutive pairs (see module)."""
    records = drive.pairs[start:start + pairs]
    first = records[0]
    left, right = drive.load_left(first), drive.load_right(first)
    if right is None:
        raise ValueError(f"pair {first.id} has no right image: the spread needs stereo pairs")
    matched = match_features(left, right)
    points = matched.left
    previous = grey(left)
    positions = [_world(drive, first, previous, grey(right), points, near_m, far_m)]
    alive = np.isfinite(positions[0]).all(axis=1)
    for record in records[1:]:
        left_grey, right_grey = grey(drive.load_left(record)), grey(drive.load_right(record))
        moved, ok = track(previous, left_grey, points)
        points = np.where(ok[:, None], moved, points)
        alive &= ok
        world = _world(drive, record, left_grey, right_grey, points, near_m, far_m)
        alive &= np.isfinite(world).all(axis=1)
        positions.append(world)
        previous = left_grey
    stacked = np.stack(positions, axis=1)[alive]
    return PointSpread([r.id for r in records], stacked)
