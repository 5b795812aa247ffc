
import cv2
import numpy as np
import pytest
from pipeline_scenes import CAMERA

from signmapper_core.geometry import Camera
from signmapper_core.pipeline.config import PipelineConfig, with_settings
from signmapper_core.pipeline.planarity import segment_planarity

CONFIG = PipelineConfig()
GIVEN = CONFIG.planarity.planarity_tolerance_px  # the residual allowed with given depth maps

BBOX = (300, 150, 60, 60)
H, W = CAMERA.height, CAMERA.width
VV, UU = np.mgrid[0:H, 0:W].astype(float)
RAYS = np.stack([(UU - CAMERA.cx) / CAMERA.fx, (VV - CAMERA.cy) / CAMERA.fy, np.ones_like(UU)], -1)


def _disc():
    mask = np.zeros((60, 60), np.uint8)
    cv2.circle(mask, (30, 30), 29, 255, -1)
    return mask


def _plane_depth(normal, distance):
    """Depth of the plane n.X = distance along each pixel's ray."""
    return (distance / (RAYS @ np.asarray(normal, float))).astype(np.float32)


def test_flat_sign_facing_the_camera_is_planar():
    depth = np.full((H, W), 25.0, np.float32)
    depth[150:210, 300:360] = 8.0  # the sign in front of a far background
    result = segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN)
    assert result.indicator > 0.97
    assert result.depth_at(CAMERA, 329.5, 179.5) == pytest.approx(8.0, rel=1e-3)


def test_noisy_flat_sign_with_holes_is_still_planar():
    rng = np.random.default_rng(0)
    depth = (8.0 + rng.normal(0, 0.02, (H, W))).astype(np.float32)  # ~2 cm noise
    depth[rng.random((H, W)) < 0.1] = np.nan
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN).indicator > 0.9


def test_sign_turned_20_degrees_is_planar():
    a = np.radians(20)
    depth = _plane_depth((np.sin(a), 0, np.cos(a)), 8.0 * np.cos(a))
    result = segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN)
    assert result.indicator > 0.95
    assert result.slant_deg == pytest.approx(20.0, abs=0.5)


def test_patch_on_a_facade_along_the_road_is_not_planar_enough():
    a = np.radians(70)  # a wall nearly parallel to the driving direction
    depth = _plane_depth((np.sin(a), 0, np.cos(a)), 8.0 * np.cos(a))
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN).indicator < 0.1


def test_patch_on_a_curved_surface_is_not_planar():
    # a 0.6 m sign-coloured patch wrapped on a column of 0.3 m radius, 6 m ahead, seen by the
    # vehicle's camera (fx 1750 px, 0.9 m baseline) with 0.25 px disparity noise
    cam = Camera(1920, 1080, 1750.0, 1750.0, 959.5, 539.5, 0.9)
    fb = cam.fx * cam.baseline_m
    x = (np.arange(cam.width) - cam.cx) / cam.fx
    zc, r = 6.3, 0.3
    a, b, c = x**2 + 1, -2 * zc, zc**2 - r**2
    disc = b**2 - 4 * a * c
    row = np.where(disc > 0, (-b - np.sqrt(np.maximum(disc, 0))) / (2 * a), np.nan)
    disparity = fb / np.tile(row, (cam.height, 1)) + np.random.default_rng(0).normal(0, 0.25, (cam.height, cam.width))
    depth = (fb / disparity).astype(np.float32)
    side = int(0.6 * cam.fx / 6.0)
    bbox = (int(cam.cx - side / 2), 450, side, side)
    mask = np.full((side, side), 255, np.uint8)
    assert segment_planarity(cam, depth, bbox, mask, CONFIG, GIVEN).indicator < 0.4
    flat = (fb / (fb / 6.0 + np.random.default_rng(1).normal(0, 0.25, depth.shape))).astype(np.float32)
    assert segment_planarity(cam, flat, bbox, mask, CONFIG, GIVEN).indicator > 0.9  # same noise, flat: a sign


def test_segment_without_enough_depth_has_indicator_zero():
    depth = np.full((H, W), np.nan, np.float32)
    depth[150:160, 300:360] = 8.0  # one sixth of the box has depth
    result = segment_planarity(CAMERA, depth, BBOX, np.full((60, 60), 255, np.uint8), CONFIG, GIVEN)
    assert result.indicator == 0.0 and result.plane is None


def test_empty_mask_has_indicator_zero():
    result = segment_planarity(CAMERA, np.full((H, W), 8.0, np.float32), BBOX, np.zeros((60, 60), np.uint8), CONFIG,
                               GIVEN)
    assert result.indicator == 0.0


def test_background_depth_on_the_signs_edge_is_ignored():
    # SGBM gives a sign's left edge the depth of the background behind it
    depth = np.full((H, W), 8.0, np.float32)
    depth[150:210, 300:315] = 30.0
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN).indicator > 0.95
    all_depths = with_settings(CONFIG, {"planarity": {"max_depth_deviation": None}})
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), all_depths, GIVEN).indicator < 0.9


def test_a_window_needs_its_share_of_pixels_with_depth_to_fit_a_plane():
    """Depth on every other row (a stereo pair matched on half its rows): a 7 x 7 window holds 21-28 pixels with
    depth, above a third of it; asking for 60 % leaves no window to fit, and no planar pixel."""
    depth = np.full((H, W), np.nan, np.float32)
    depth[150:210, 300:360] = 8.0
    depth[::2, :] = np.nan
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), CONFIG, GIVEN).indicator > 0.8
    stricter = with_settings(CONFIG, {"planarity": {"planarity_window_min_share": 0.6}})
    assert segment_planarity(CAMERA, depth, BBOX, _disc(), stricter, GIVEN).indicator == 0.0
