"""Step 6: planarity of a segment from the depth map, the detection indicator.

A plane has a disparity ``d = fx*B/Z`` that is affine in (u, v), so planarity
is measured in disparity pixels: a weighted least-squares plane is fitted in a
small window around each pixel of the segment (weights = segment pixels with
depth, so the background beyond the sign's edge does not spoil the fit). A pixel
is planar when the window's residual is small and it agrees with the segment's
dominant plane. The planar share of the segment's pixels with depth is the
detection indicator; it is 0 when the dominant plane does not face the camera
(slant from the optical axis above a limit: signs face the road, façades along
the road do not).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Tuple

import cv2
import numpy as np

from ..geometry import Camera
from .search_space import valid_depth


@dataclass(frozen=True)
class PlanarityResult:
    indicator: float  # planar share, 0..1
    coverage: float  # share of the segment's pixels with a depth
    plane: Optional[Tuple[float, float, float]]  # disparity = a + b*u + c*v, full-image pixels
    slant_deg: float  # of the dominant plane from the optical axis; NaN without plane

    def depth_at(self, camera: Camera, u: float, v: float) -> float:
        """Depth of the dominant plane at pixel (u, v); NaN without plane."""
        if self.plane is None:
            return float("nan")
        a, b, c = self.plane
        d = a + b * u + c * v
        return float(camera.fx * camera.baseline_m / d) if d > 0 else float("nan")


def _slant_deg(camera: Camera, d, du, dv, u, v):
    """Angle between the plane normal and the optical axis; arrays or scalars."""
    nx, ny = du * camera.fx, dv * camera.fy
    nz = d - du * (u - camera.cx) - dv * (v - camera.cy)
    norm = np.sqrt(nx * nx + ny * ny + nz * nz)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.degrees(np.arccos(np.clip(np.abs(nz) / norm, 0.0, 1.0)))


def _fit_plane(u, v, d, weights=None):
    design = np.column_stack([np.ones_like(u), u, v])
    if weights is not None:
        design, d = design[weights], d[weights]
    if len(d) < 3:
        return None
    coef, *_ = np.linalg.lstsq(design, d, rcond=None)
    return coef


def local_plane_fit(disparity: np.ndarray, weight: np.ndarray, window: int, min_valid: int):
    """Per-pixel weighted plane fit in a window: (residual_rms, d, du, dv, ok) maps; ok where the window holds at
    least ``min_valid`` pixels of weight."""
    k = (window, window)

    def box(a):
        return cv2.boxFilter(a, cv2.CV_64F, k, normalize=False, borderType=cv2.BORDER_CONSTANT)

    h, w = disparity.shape
    ys, xs = np.mgrid[0:h, 0:w].astype(np.float64)
    # window-centred coordinates keep the normal equations well conditioned
    wgt = weight.astype(np.float64)
    dw = disparity * wgt
    s1, sx, sy = box(wgt), box(wgt * xs), box(wgt * ys)
    sxx, sxy, syy = box(wgt * xs * xs), box(wgt * xs * ys), box(wgt * ys * ys)
    sd, sdx, sdy, sdd = box(dw), box(dw * xs), box(dw * ys), box(dw * disparity)
    ok = (weight > 0) & (s1 >= min_valid)
    idx = np.nonzero(ok)
    rms = np.full((h, w), np.inf)
    d0 = np.zeros((h, w))
    du = np.zeros((h, w))
    dv = np.zeros((h, w))
    if idx[0].size == 0:
        return rms, d0, du, dv, ok
    # shift moments to the window centre (x0, y0) to avoid cancellation
    x0, y0 = xs[idx], ys[idx]
    n = s1[idx]
    mx, my = sx[idx] - x0 * n, sy[idx] - y0 * n
    mxx = sxx[idx] - 2 * x0 * sx[idx] + x0 * x0 * n
    mxy = sxy[idx] - x0 * sy[idx] - y0 * sx[idx] + x0 * y0 * n
    myy = syy[idx] - 2 * y0 * sy[idx] + y0 * y0 * n
    md = sd[idx]
    mdx, mdy = sdx[idx] - x0 * md, sdy[idx] - y0 * md
    a = np.stack([np.stack([n, mx, my], -1), np.stack([mx, mxx, mxy], -1), np.stack([my, mxy, myy], -1)], -2)
    b = np.stack([md, mdx, mdy], -1)
    a += np.eye(3) * 1e-9
    beta = np.linalg.solve(a, b[..., None])[..., 0]
    sse = np.maximum(sdd[idx] - np.einsum("ij,ij->i", beta, b), 0.0)
    rms[idx] = np.sqrt(sse / n)
    d0[idx], du[idx], dv[idx] = beta[:, 0], beta[:, 1], beta[:, 2]
    return rms, d0, du, dv, ok


def segment_planarity(
    camera: Camera,
    depth: np.ndarray,
    bbox,
    mask: np.ndarray,
    config,
    tolerance_px: float,
) -> PlanarityResult:
    """Detection indicator of a segment (filled ``mask`` inside ``bbox``) from the depth map.

    ``config`` (a PipelineConfig) gives the planarity settings; ``tolerance_px`` is the
    residual allowed for the depth's kind (given or matched: ``planarity_tolerance_px``,
    ``sgbm_planarity_tolerance_px``).
    """
    window, max_slant_deg = config.planarity.planarity_window_px, config.planarity.max_slant_deg
    min_coverage, max_depth_deviation = config.planarity.min_depth_coverage, config.planarity.max_depth_deviation
    x, y, w, h = bbox
    z = depth[y : y + h, x : x + w].astype(np.float64)
    inside = mask > 0
    n_inside = int(np.count_nonzero(inside))
    has_depth = inside & valid_depth(z)
    if has_depth.any() and max_depth_deviation is not None:
        # Depths far from the segment's median are matching artefacts (SGBM gives a sign's left
        # edge the background's depth) or background seen through the outline, not evidence
        # about the face's shape: a slanted or curved patch stays within a few per cent.
        median = float(np.median(z[has_depth]))
        with np.errstate(invalid="ignore"):
            has_depth &= np.abs(z - median) <= max_depth_deviation * median
    n_depth = int(np.count_nonzero(has_depth))
    coverage = n_depth / n_inside if n_inside else 0.0
    if n_depth < 3 or coverage < min_coverage:
        return PlanarityResult(0.0, coverage, None, float("nan"))
    fb = camera.fx * camera.baseline_m
    disparity = np.zeros_like(z)
    disparity[has_depth] = fb / z[has_depth]

    # The slant is judged on the dominant plane only: a window's gradient is too noisy for it
    # (0.05 px/px of SGBM noise at d = 140 px reads as 30 deg).
    settings = config.planarity
    min_valid = max(settings.planarity_window_min_px, int(window * window * settings.planarity_window_min_share))
    rms, _, _, _, ok = local_plane_fit(disparity, has_depth, window, min_valid)
    ys, xs = np.nonzero(has_depth)
    u_img, v_img = xs + x, ys + y
    local_ok = ok[ys, xs] & (rms[ys, xs] <= tolerance_px)

    # dominant plane: fit, then refit on the pixels near it (robust to a few outliers)
    d = disparity[ys, xs]
    coef = _fit_plane(u_img.astype(float), v_img.astype(float), d, local_ok if local_ok.sum() >= 3 else None)
    if coef is None:
        return PlanarityResult(0.0, coverage, None, float("nan"))
    for _ in range(2):
        resid = np.abs(d - (coef[0] + coef[1] * u_img + coef[2] * v_img))
        near = resid <= config.planarity.planarity_refit_band * tolerance_px
        if near.sum() < 3:
            break
        coef = _fit_plane(u_img.astype(float), v_img.astype(float), d, near)
    resid = np.abs(d - (coef[0] + coef[1] * u_img + coef[2] * v_img))
    planar = local_ok & (resid <= tolerance_px)
    uc, vc = float(u_img.mean()), float(v_img.mean())
    dc = coef[0] + coef[1] * uc + coef[2] * vc
    plane_slant = float(_slant_deg(camera, dc, coef[1], coef[2], uc, vc))
    indicator = float(np.count_nonzero(planar)) / n_depth
    if plane_slant > max_slant_deg:
        indicator = 0.0
    return PlanarityResult(indicator, coverage, (float(coef[0]), float(coef[1]), float(coef[2])), plane_slant)
