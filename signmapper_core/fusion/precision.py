"""How precisely a stereo view places a sign face, and one position from several views weighted by it.

Stereo measures a face centre far less precisely along its line of sight than across it: a disparity error of
σ_d pixels moves a point at depth Z by σ_Z = Z²·σ_d/(f·B) in depth (f·B: focal length [px] x baseline [m]), and by
σ_Z x range/Z along its ray; an error of σ_px in its image position moves it by about Z·σ_px/f across. Half a pixel
of disparity is 0.9 m of depth at 26 m on KITTI's camera (f·B = 389 px·m) and 2 cm at 8 m on a Full-HD one
(f·B = 1575). A view's covariance is that ellipsoid, turned to its line of sight, plus the trajectory's own
uncertainty in every direction. Views are combined by their information (inverse covariance), so a near view
outweighs a far one along the far one's line of sight but less across it, and two positions are compared by their
difference in the covariance of that difference: one far sign whose views scatter along their lines of sight is
one sign, two near signs a hand apart are two.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ..geometry import Camera

ROBUST_SIGMA = 1.4826  # a normal distribution's σ per median absolute deviation


@dataclass(frozen=True)
class StereoPrecision:
    """What a view's precision depends on: the drive's camera and the fusion's uncertainties (``FusionConfig``)."""

    focal_px: float  # the camera's fx
    baseline_m: float
    disparity_sigma_px: float
    image_sigma_px: float
    pose_sigma_m: float

    @classmethod
    def of(cls, camera: Camera, config) -> StereoPrecision:
        """Of a drive's ``geometry.Camera`` and a ``FusionConfig``."""
        return cls(float(camera.fx), float(camera.baseline_m), config.disparity_sigma_px, config.image_sigma_px,
                   config.pose_sigma_m)

    def sigmas(self, depth_m: float, range_m: float) -> tuple[float, float]:
        """(σ along the line of sight, σ across it) [m] of a view at depth ``depth_m`` and ``range_m`` along its ray,
        the trajectory's uncertainty not included."""
        depth = max(float(depth_m), 1e-6)
        along = depth ** 2 * self.disparity_sigma_px / (self.focal_px * self.baseline_m) * max(range_m, depth) / depth
        return along, depth * self.image_sigma_px / self.focal_px

    def covariance(self, position: np.ndarray, camera_centre: np.ndarray, depth_m: float) -> np.ndarray:
        """The 3 x 3 covariance (E, N, H) of a face centre at ``position`` seen from ``camera_centre``."""
        ray = np.asarray(position, float) - np.asarray(camera_centre, float)
        range_m = float(np.linalg.norm(ray))
        sight = ray / range_m if range_m > 0 else np.array([0.0, 1.0, 0.0])
        along, across = self.sigmas(depth_m, range_m)
        on_sight = np.outer(sight, sight)
        return along ** 2 * on_sight + across ** 2 * (np.eye(3) - on_sight) + self.pose_sigma_m ** 2 * np.eye(3)


@dataclass(frozen=True)
class Estimate:
    """A position and its covariance."""

    position: np.ndarray
    covariance: np.ndarray


def combined(positions: Sequence[np.ndarray], covariances: Sequence[np.ndarray]) -> Estimate:
    """The information-weighted mean Σ W_i x_i / Σ W_i (W_i = C_i⁻¹) and its covariance (Σ W_i)⁻¹: the least-squares
    position of views with independent errors. The same for any order of the views."""
    information = np.zeros((3, 3))
    weighted = np.zeros(3)
    for x, c in zip(positions, covariances):
        w = np.linalg.inv(c)
        information += w
        weighted += w @ np.asarray(x, float)
    covariance = np.linalg.inv(information)
    return Estimate(covariance @ weighted, covariance)


def gate_distance(delta: np.ndarray, covariance: np.ndarray, floor_m: float, sigmas: float) -> float:
    """How far apart two positions are, in units of a gate that reaches ``sigmas`` standard deviations of their
    difference (``covariance``: the sum of theirs) in each direction, and at least ``floor_m``: within it when at
    most 1. Near, precise views meet the floor, so the gate is the fixed distance; far views' gate reaches along
    their lines of sight as far as their depths are uncertain."""
    delta = np.atleast_1d(np.asarray(delta, float))
    reach = sigmas ** 2 * np.atleast_2d(covariance) + floor_m ** 2 * np.eye(len(delta))
    try:
        return float(np.sqrt(delta @ np.linalg.solve(reach, delta)))
    except np.linalg.LinAlgError:  # no gate at all (no floor, no σ): only the same position is within it
        return 0.0 if not delta.any() else float("inf")


def along_across(covariance: np.ndarray, sight: np.ndarray) -> tuple[float, float]:
    """(σ along the unit direction ``sight``, σ across it, per axis of the plane across) of a covariance [m]."""
    along_variance = float(sight @ covariance @ sight)
    across_variance = max(float(np.trace(covariance)) - along_variance, 0.0) / 2.0
    return float(np.sqrt(max(along_variance, 0.0))), float(np.sqrt(across_variance))


def inliers(positions: Sequence[np.ndarray], covariances: Sequence[np.ndarray], floor_m: float,
            sigmas: float) -> list[int]:
    """Indices of the views that agree with the others: within ``sigmas`` of their own precision (and
    ``floor_m``) of the views' median, or within ``sigmas`` robust σ of the views' spread about it when that is
    wider (the views of one sign agree less than the model says: a face's centre found a little off). All when
    none would be left."""
    points = np.array(positions, float)
    median = np.median(points, axis=0)
    distances = np.array([gate_distance(x - median, c, floor_m, sigmas) for x, c in zip(points, covariances)])
    limit = max(1.0, sigmas * ROBUST_SIGMA * float(np.median(distances)))
    kept = [i for i, d in enumerate(distances) if d <= limit]
    return kept or list(range(len(points)))


def variance_factor(positions: Sequence[np.ndarray], covariances: Sequence[np.ndarray], estimate: Estimate) -> float:
    """How much more the views scatter about ``estimate`` than their covariances say (χ² per degree of freedom,
    at least 1): their covariance scaled by it is an estimate's honest precision. 1 for one view."""
    if len(positions) < 2:
        return 1.0
    chi2 = sum(float((x - estimate.position) @ np.linalg.solve(c, x - estimate.position))
               for x, c in zip(np.asarray(positions, float), covariances))
    return max(1.0, chi2 / (3.0 * (len(positions) - 1)))
