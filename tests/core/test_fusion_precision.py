"""Positions from every view weighted by their precision, and the precision each sign reports (issue 45, item 2).

Views are simulated through the camera model, not the fusion's own covariance: the face centre is projected into
the left image, its column, row and disparity get normal errors of the settings' size, and it is placed again from
them, as the pipeline does, on a pose with the trajectory's error.
"""

from dataclasses import replace

import numpy as np
import pytest

from signmapper_core.drive.reader import PairRecord
from signmapper_core.fusion.precision import StereoPrecision, gate_distance
from signmapper_core.fusion.signs import FusionConfig, Observation, fuse_observations
from signmapper_core.geometry import Camera, Pose, pixel_to_world, world_to_pixel
from signmapper_core.pipeline.detection import Detection

KITTI = Camera(1242, 375, 721.5, 721.5, 609.6, 172.9, 0.54)  # KITTI's rectified colour camera
FULL_HD = Camera(1920, 1080, 1750.0, 1750.0, 959.5, 539.5, 0.9)  # the synthetic drives' camera
# the precision of views wherever they are: a sign seen once beyond far is kept (the mapping drops it, far_min_views;
# tested in test_fusion.py)
CONFIG = FusionConfig(far_min_views=1)
WEST = np.array([-1.0, 0.0, 0.0])
CAMERA_HEIGHT = 1.65


def view(camera, truth, pair_index, step_m, rng, template_id="2.30-50", config=CONFIG, exact=False):
    """A detection of the face centre ``truth`` from pair ``pair_index`` of a vehicle driving east at ``step_m`` a
    pair, with the errors the settings say (none when ``exact``)."""
    pose = Pose(step_m * pair_index, 0.0, CAMERA_HEIGHT, 90.0, 0.0, 0.0)
    u, v, z = (float(x) for x in world_to_pixel(camera, pose, np.asarray(truth, float)))
    d = camera.fx * camera.baseline_m / z
    if not exact:
        u, v = u + rng.normal(0.0, config.image_sigma_px), v + rng.normal(0.0, config.image_sigma_px)
        d += rng.normal(0.0, config.disparity_sigma_px)
    depth = camera.fx * camera.baseline_m / d
    position = pixel_to_world(camera, pose, u, v, depth)
    if not exact:
        position = position + rng.normal(0.0, config.pose_sigma_m, 3)
    detection = Detection(template_id, "", "red", "circle", 0.6, 0.6, "normal", 0.95, 0.99, "accepted", u, v,
                          (int(u) - 10, int(v) - 10, 20, 20), depth, position, normal_world=WEST)
    return Observation(detection, PairRecord(pair_index, f"{pair_index:06d}", 0.1 * pair_index, pose, None, None,
                                             None))


def pairs_between(truth, nearest_m, farthest_m, step_m):
    """The pairs whose camera is ``nearest_m``..``farthest_m`` behind ``truth`` (along x)."""
    return [k for k in range(int((truth[0] - farthest_m) / step_m) - 1, int(truth[0] / step_m) + 1)
            if nearest_m <= truth[0] - step_m * k <= farthest_m]


def seen_between(camera, truth, nearest_m, farthest_m, step_m, rng, **kwargs):
    """Views of ``truth`` from every pair whose camera is ``nearest_m``..``farthest_m`` behind it."""
    return [view(camera, truth, k, step_m, rng, **kwargs) for k in pairs_between(truth, nearest_m, farthest_m, step_m)]


def components(sign, truth):
    """(error along the sign's mean line of sight, error across it per axis) [m]."""
    sight = np.sum([(o.position - o.camera_centre) / np.linalg.norm(o.position - o.camera_centre)
                    for o in sign.observations], axis=0)
    sight /= np.linalg.norm(sight)
    error = sign.position - truth
    along = float(error @ sight)
    return along, float(np.linalg.norm(error - along * sight)) / np.sqrt(2.0)


@pytest.mark.parametrize("seed", range(12))
def test_a_far_sign_seen_in_several_pairs_with_realistic_depth_noise_is_one_sign(seed):
    """KITTI, 10 pairs/s at 40 km/h: a sign 24-28 m ahead, depth uncertain by ~0.8 m (half a pixel), seen in four
    pairs. The fixed 0.6 m gate split such a sign into two 0.94 m apart along the line of sight."""
    rng = np.random.default_rng(seed)
    truth = np.array([60.0, 4.0, 2.2])
    views = seen_between(KITTI, truth, 23.5, 28.0, 1.1, rng)
    assert len(views) == 4
    (sign,) = fuse_observations(views, KITTI, CONFIG)
    assert sign.n_obs == 4
    along, across = components(sign, truth)
    assert abs(along) < 3.0 * sign.sigma_along_m and across < 3.0 * sign.sigma_across_m
    assert 0.2 < sign.sigma_along_m < 0.8 and sign.sigma_across_m < 0.1  # ~0.8 m / √4 along, a few cm across


def test_the_fixed_gate_alone_splits_the_far_sign():
    """The same views with the gates fixed at their metric size (gate_sigmas 0): more than one sign on most seeds,
    so the test above tests what it should."""
    split = 0
    for seed in range(12):
        views = seen_between(KITTI, np.array([60.0, 4.0, 2.2]), 23.5, 28.0, 1.1, np.random.default_rng(seed))
        split += len(fuse_observations(views, KITTI, replace(CONFIG, gate_sigmas=0.0))) > 1
    assert split >= 6


@pytest.mark.parametrize("camera", [KITTI, FULL_HD])
@pytest.mark.parametrize("offset", [(0.8, 0.0, 0.0), (0.0, 0.8, 0.0), (0.0, 0.0, 0.8)])
def test_two_near_signs_on_one_pole_08_m_apart_stay_two(camera, offset):
    """Two like signs 0.8 m apart (along the road, across it, stacked), seen together at 5-14 m."""
    rng = np.random.default_rng(3)
    lower = np.array([40.0, 4.0, 2.2])
    upper = lower + offset
    views = seen_between(camera, lower, 5.0, 14.0, 2.2, rng) + seen_between(camera, upper, 5.0, 14.0, 2.2, rng)
    signs = fuse_observations(views, camera, CONFIG)
    assert sorted(s.n_obs for s in signs) == [4, 4]
    found = sorted(signs, key=lambda s: float(s.position @ np.asarray(offset)))
    assert np.linalg.norm(found[0].position - lower) < 0.15 and np.linalg.norm(found[1].position - upper) < 0.15


def test_the_precision_weighted_position_beats_the_plain_mean():
    """A sign seen at 6, 12, 20 and 28 m: the far views' depth is ~20 times less sure than the nearest one's."""
    rng = np.random.default_rng(7)
    truth = np.array([60.0, 4.0, 2.2])
    weighted, plain = [], []
    for _ in range(200):
        views = [view(KITTI, truth, k, 1.0, rng) for k in (32, 40, 48, 54)]
        (sign,) = fuse_observations(views, KITTI, CONFIG)
        weighted.append(np.linalg.norm(sign.position - truth))
        plain.append(np.linalg.norm(np.mean([o.position for o in views], axis=0) - truth))
    rms_weighted, rms_plain = np.sqrt(np.mean(np.square(weighted))), np.sqrt(np.mean(np.square(plain)))
    assert rms_weighted < 0.5 * rms_plain


def test_reported_sigmas_match_the_errors_of_many_simulated_signs():
    """300 signs, each seen 1-6 times at 5-30 m by KITTI's camera: the RMS of error / σ is near 1 along the line of
    sight and across it (the σ grow when views scatter more than their precision says, so a little below 1)."""
    rng = np.random.default_rng(45)
    along, across = [], []
    for k in range(300):
        truth = np.array([100.0, rng.uniform(-8.0, 8.0), rng.uniform(1.5, 5.0)])
        last = pairs_between(truth, rng.uniform(5.0, 25.0), 40.0, 1.1)[-1]  # the nearest view, 5-25 m away
        views = [view(KITTI, truth, k, 1.1, rng) for k in range(last - int(rng.integers(0, 6)), last + 1)]
        (sign,) = fuse_observations(views, KITTI, CONFIG)
        a, c = components(sign, truth)
        along.append(a / sign.sigma_along_m)
        across.append(c / sign.sigma_across_m)
        assert sign.sigma_m == pytest.approx(np.hypot(sign.sigma_along_m, np.sqrt(2) * sign.sigma_across_m))
    rms_along, rms_across = np.sqrt(np.mean(np.square(along))), np.sqrt(np.mean(np.square(across)))
    assert 0.7 <= rms_along <= 1.5 and 0.7 <= rms_across <= 1.5, (rms_along, rms_across)


def test_a_sign_seen_once_reports_its_views_precision_not_zero():
    rng = np.random.default_rng(1)
    truth = np.array([60.0, 4.0, 2.2])
    (sign,) = fuse_observations([view(KITTI, truth, 35, 1.0, rng, exact=True)], KITTI, CONFIG)  # 25 m ahead
    precision = StereoPrecision.of(KITTI, CONFIG)
    along, across = precision.sigmas(25.0, float(np.linalg.norm(truth - sign.best.camera_centre)))
    assert sign.sigma_along_m == pytest.approx(np.hypot(along, CONFIG.pose_sigma_m), rel=0.02)
    assert sign.sigma_across_m == pytest.approx(np.hypot(across, CONFIG.pose_sigma_m), rel=0.02)
    assert sign.sigma_along_m == pytest.approx(25.0 ** 2 * 0.5 / (721.5 * 0.54), rel=0.05)  # σ_Z = Z²σ_d/(f·B)


def test_views_that_scatter_more_than_their_precision_widen_the_sigma():
    """Four near views whose centres scatter by 10 cm (a face's centre found off): the σ reported follows the
    scatter, not the 1-2 cm that stereo and the trajectory give each view."""
    rng = np.random.default_rng(2)
    truth = np.array([40.0, 4.0, 2.2])
    views = seen_between(FULL_HD, truth, 5.0, 14.0, 2.2, rng, exact=True)
    (exact,) = fuse_observations(views, FULL_HD, CONFIG)
    for o in views:
        o.detection.position = o.position + rng.normal(0.0, 0.10, 3)
    (scattered,) = fuse_observations(views, FULL_HD, CONFIG)
    assert scattered.n_obs == 4 and scattered.sigma_m > 2.5 * exact.sigma_m
    assert np.linalg.norm(scattered.position - truth) < 3.0 * scattered.sigma_m


def test_fusion_does_not_depend_on_the_order_of_the_observations():
    rng = np.random.default_rng(11)
    views = []
    for truth in ([40.0, 4.0, 2.2], [40.0, 4.0, 3.0], [70.0, -5.0, 2.5], [90.0, 4.0, 2.2]):
        views += seen_between(KITTI, np.array(truth), 5.0, 28.0, 1.1, rng)
    first = fuse_observations(views, KITTI, CONFIG)
    shuffled = list(views)
    np.random.default_rng(0).shuffle(shuffled)
    second = fuse_observations(shuffled, KITTI, CONFIG)
    assert [(s.n_obs, s.template_id) for s in first] == [(s.n_obs, s.template_id) for s in second]
    for a, b in zip(first, second):
        assert np.allclose(a.position, b.position, atol=1e-9)
        assert a.sigma_along_m == pytest.approx(b.sigma_along_m) and a.sigma_across_m == pytest.approx(b.sigma_across_m)


def test_the_gate_is_the_fixed_distance_for_precise_views_and_follows_the_sigma_of_uncertain_ones():
    precise = np.diag([1e-6, 1e-6, 1e-6])
    uncertain_along_x = np.diag([0.5 ** 2, 1e-4, 1e-4])
    assert gate_distance(np.array([0.59, 0.0, 0.0]), precise, 0.6, 3.0) < 1.0
    assert gate_distance(np.array([0.0, 0.61, 0.0]), precise, 0.6, 3.0) > 1.0
    assert gate_distance(np.array([1.5, 0.0, 0.0]), uncertain_along_x, 0.6, 3.0) < 1.0  # 3 σ along
    assert gate_distance(np.array([0.0, 0.65, 0.0]), uncertain_along_x, 0.6, 3.0) > 1.0  # not across


@pytest.mark.parametrize("setting, value", [("disparity_sigma_px", 0.0), ("image_sigma_px", -1.0),
                                            ("pose_sigma_m", -0.01), ("gate_sigmas", -3.0)])
def test_precision_settings_that_would_break_the_model_are_refused_by_name(setting, value):
    with pytest.raises(ValueError, match=setting):
        FusionConfig(**{setting: value})
