"""The reach a drive's camera gives (issue 45 item 1): beyond the paper's 4-14 m where a face leaves the view
before it comes within far, out to where it is still read and placed; and the run set up with it."""

import numpy as np
import pytest

from signmapper_core.geometry import Camera
from signmapper_core.pipeline.config import ColourConfig, DepthConfig, PipelineConfig
from signmapper_core.pipeline.depth_range import camera_reach, config_for_camera, depth_known_to, range_text
from signmapper_core.pipeline.search_range import (
    edge_share,
    edge_share_image,
    face_depth,
    face_depth_limits,
    face_in_range,
    in_search_range,
)
from signmapper_core.run.setup import assemble_run
from signmapper_core.simulate.config import SimulationConfig

PAPER = SimulationConfig().camera()  # 1920 x 1080, fx 1750 px, 0.9 m: the synthetic drives' and Cavegn's camera
KITTI = Camera(width=1242, height=375, fx=721.5, fy=721.5, cx=609.6, cy=172.9, baseline_m=0.537)
MIN_FACE_PX = ColourConfig().min_face_px


def test_the_papers_camera_reaches_56_m():
    depth = camera_reach(PAPER, DepthConfig(), MIN_FACE_PX)
    assert (depth.near_m, depth.far_m) == (4.0, 14.0)
    assert depth.reach_m == 56.0  # depth known to 1 m (a 60 cm disc would span 19 px there)
    assert range_text(depth) == "4-14 m (to 56 m for signs never seen within 14 m)"


def test_a_kitti_camera_reaches_the_far_sign_of_its_drive():
    depth = camera_reach(KITTI, DepthConfig(), MIN_FACE_PX)
    assert (depth.near_m, depth.far_m) == (4.0, 14.0)
    # the no-stopping sign of KITTI 0001 is seen at 24-27 m, 15-20 m left of the track: inside the reach
    assert depth.reach_m == 27.0
    assert depth_known_to(KITTI, 1.0, 0.5) == pytest.approx(27.8, abs=0.05)  # a 60 cm disc spans 16 px at 27.1 m


def test_a_range_set_by_hand_is_kept():
    fixed = PipelineConfig(depth=DepthConfig(near_m=3.0, far_m=30.0, range_from_camera=False))
    assert config_for_camera(fixed, KITTI) is fixed
    assert config_for_camera(PipelineConfig(), KITTI).depth.reach_m == 27.0


def test_edge_share_is_zero_at_the_principal_point_and_one_at_the_frame():
    assert float(edge_share(PAPER, PAPER.cx, PAPER.cy)) == 0.0
    assert float(edge_share(PAPER, 0, PAPER.cy)) == 1.0 and float(edge_share(PAPER, PAPER.cx, 1079)) == 1.0
    assert float(edge_share(PAPER, PAPER.cx + 0.5 * (1919 - PAPER.cx), PAPER.cy + 10)) == pytest.approx(0.5)
    image = edge_share_image(PAPER)
    assert image.shape == (1080, 1920) and not image.flags.writeable
    assert image[540, 100] == pytest.approx(float(edge_share(PAPER, 100, 540)))


def test_depth_times_edge_share_is_where_a_point_leaves_the_view():
    """Driving straight on, a point x metres to the side leaves the frame at Z = x fx / (W/2): what the reach's
    rule reads from one view (depth z at edge share e leaves at z e)."""
    lateral = 9.0
    for z in (20.0, 30.0, 50.0):
        u = PAPER.cx + PAPER.fx * lateral / z
        assert z * float(edge_share(PAPER, u, PAPER.cy)) == pytest.approx(lateral * PAPER.fx / (1919 - PAPER.cx))


def test_the_search_range_reaches_beyond_far_only_where_a_face_leaves_the_view_first():
    depth = camera_reach(PAPER, DepthConfig(), MIN_FACE_PX)  # 4-14 m, reach 56 m
    z = np.array([3.0, 10.0, 20.0, 20.0, 30.0, 30.0, 60.0])
    edge = np.array([0.0, 0.0, 0.0, 1.0, 0.4, 0.5, 1.0])
    assert in_search_range(z, edge, depth).tolist() == [False, True, False, True, False, True, False]
    assert not in_search_range(np.nan, 1.0, depth)
    assert in_search_range(16.0, 0.0, depth, slack=0.2)  # 14 m widened by a fifth
    assert not in_search_range(20.0, 1.0, DepthConfig())  # no reach: nothing beyond far


def test_a_face_keeps_its_plane_depth_inside_the_range_else_its_median():
    depth = camera_reach(PAPER, DepthConfig(), MIN_FACE_PX)
    assert face_depth(30.0, 29.0, PAPER, 10.0, PAPER.cy, depth, 0.0) == 30.0  # at the frame's edge: reach
    assert face_depth(30.0, 13.0, PAPER, PAPER.cx, PAPER.cy, depth, 0.0) == 13.0  # in the middle: beyond far
    assert face_depth(float("nan"), 8.0, PAPER, PAPER.cx, PAPER.cy, depth, 0.0) == 8.0


def test_a_run_takes_the_camera_range_unless_a_limit_is_given():
    assert assemble_run({("depth", "near_m"): None, ("depth", "far_m"): None}).config.depth.range_from_camera
    fixed = assemble_run({("depth", "far_m"): 30.0}).config.depth
    assert (fixed.near_m, fixed.far_m, fixed.reach_m, fixed.range_from_camera) == (4.0, 30.0, None, False)
    with pytest.raises(ValueError, match=r"Near limit \(20 m\) must be less than Far limit \(14 m\)"):
        assemble_run({("depth", "near_m"): 20.0})


def test_reach_below_far_is_refused():
    with pytest.raises(ValueError, match="reach_m >= far_m"):
        DepthConfig(far_m=14.0, reach_m=10.0)


def test_a_face_is_measured_out_to_the_reach_only_where_it_leaves_the_view_first():
    depth = camera_reach(PAPER, DepthConfig(), MIN_FACE_PX)  # 4-14 m, reach 56 m
    middle, edge = (950, 500, 20, 20), (20, 500, 20, 20)
    assert face_depth_limits(PAPER, middle, depth) == (4.0, 14.0)
    assert face_depth_limits(PAPER, edge, depth) == (4.0, 56.0)
    assert face_in_range(PAPER, edge, 30.0, depth) and not face_in_range(PAPER, middle, 30.0, depth)
    # a face the search space's growth took in beside one in range: 26 m at a quarter of the way out leaves the
    # view at 6.5 m, so it comes within 14 m later and is measured then
    quarter = (int(PAPER.cx + 0.27 * (1919 - PAPER.cx)) - 10, 530, 20, 20)
    assert not face_in_range(PAPER, quarter, 26.0, depth) and face_in_range(PAPER, quarter, 12.0, depth)
