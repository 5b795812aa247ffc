"""Wide streets of the synthetic drives (issue 45 item 6): signs far to the side, on both sides; the drives of
before unchanged."""

from __future__ import annotations

import numpy as np
import pytest

from signmapper_core.drive.reader import open_drive
from signmapper_core.simulate import SimulationConfig, generate_drive
from signmapper_core.simulate.__main__ import build_parser, config_from_args
from signmapper_core.simulate.generator import make_scene, make_street
from signmapper_core.simulate.scene_pieces import LANE_CENTRE

WIDE = (8.0, 25.0)
STACK_REACH_M = 1.6  # a post's further signs (pointers) may sit up to a sign's width beside its first


def lateral_from_track(street, easting: float, northing: float) -> float:
    """Metres right (+) or left (-) of the vehicle's nominal track (the right lane's middle) of a point."""
    grid = np.arange(-50.0, street.length, 0.1)
    track = street.point(grid, LANE_CENTRE, 0.0)[:, :2]
    p = np.array([easting, northing])
    k = int(np.argmin(np.linalg.norm(track - p, axis=1)))
    return float(np.dot(p - track[k], street.right(grid[k])[:2]))


def test_wide_street_puts_the_signs_between_the_lateral_bounds_on_both_sides(tmp_path):
    cfg = SimulationConfig(pairs=40, seed=8, width=96, height=64, fx=88.0, sign_offset_m=WIDE,
                           right_sign_share=0.5, noise=False, motion_blur=False, glare=False)
    generate_drive(tmp_path / "wide", cfg)
    truth = open_drive(tmp_path / "wide", require_truth=True).truth
    street = make_street(cfg)
    lateral = np.array([lateral_from_track(street, t.easting, t.northing) for t in truth])
    assert len(lateral) >= 8
    assert (np.abs(lateral) >= WIDE[0] - STACK_REACH_M).all() and (np.abs(lateral) <= WIDE[1] + STACK_REACH_M).all()
    inside = (np.abs(lateral) >= WIDE[0]) & (np.abs(lateral) <= WIDE[1])
    assert inside.mean() >= 0.8, lateral
    assert (lateral > 0).any() and (lateral < 0).any()  # both sides
    assert np.ptp(np.abs(lateral)) > 6.0  # spread over the range, not one distance


def test_defaults_leave_the_drives_of_before_as_they_were():
    """The truth of seed 5's 8 pairs, as written before wide streets existed."""
    truth = make_scene(SimulationConfig(pairs=8, seed=5)).truth
    assert [(t.template_id, round(t.easting, 4), round(t.northing, 4), round(t.height, 4)) for t in truth] == [
        ("4.03", 2599964.3884, 1200007.5497, 402.931)]
    explicit = make_scene(SimulationConfig(pairs=8, seed=5, sign_offset_m=None, right_sign_share=0.75)).truth
    assert explicit == truth


def test_wide_street_settings_are_checked():
    with pytest.raises(ValueError, match="sign_offset_m"):
        SimulationConfig(sign_offset_m=(9.0, 8.0)).validate()
    with pytest.raises(ValueError, match="right_sign_share"):
        SimulationConfig(right_sign_share=1.5).validate()


def test_command_line_sets_a_wide_street():
    wide = config_from_args(build_parser().parse_args(["out", "--sign-offset", "8", "25", "--right-share", "0.5"]))
    assert wide.sign_offset_m == (8.0, 25.0) and wide.right_sign_share == 0.5
    plain = config_from_args(build_parser().parse_args(["out"]))
    assert plain.sign_offset_m is None and plain.right_sign_share is None
