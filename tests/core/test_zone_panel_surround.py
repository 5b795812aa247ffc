"""A disc inside a white panel at its own depth (a zone panel's disc read alone), on constructed images."""

import numpy as np
import pytest

from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.zone_panel_surround import ABOVE, LEFT, inside_white_panel, strip_box
from signmapper_core.plates.zone_panels import may_be_a_panels_disc, may_be_disc_of

CONFIG = PipelineConfig()
DISC = (150, 160, 80, 80)  # x, y, w, h
ZONES = {"2.59.1-30": "2.30-30", "2.59.3": "2.61"}


def scene(panel_depth=10.0, panel=(130, 100, 120, 170), white=(235, 235, 235), disc=DISC):
    """Grey background at 30 m; a white panel (x, y, w, h) at ``panel_depth``; a red disc on it at 10 m."""
    rng = np.random.default_rng(0)
    image = np.clip(rng.normal(100, 12, (400, 400, 3)), 0, 255).astype(np.uint8)
    depth = np.full((400, 400), 30.0, np.float32)
    if panel is not None:
        px, py, pw, ph = panel
        image[py : py + ph, px : px + pw] = white
        depth[py : py + ph, px : px + pw] = panel_depth
    x, y, w, h = disc
    image[y : y + h, x : x + w] = (30, 30, 200)
    depth[y : y + h, x : x + w] = 10.0
    return image, depth


def test_a_disc_inside_white_at_its_own_depth_is_a_panels_disc():
    image, depth = scene()
    assert inside_white_panel(image, depth, DISC, 10.0, CONFIG)
    image[130:135, 170:210] = (20, 20, 20)  # the panel's lettering above the disc leaves enough white
    assert inside_white_panel(image, depth, DISC, 10.0, CONFIG)


@pytest.mark.parametrize("change", ["wall behind", "no white above", "white above only", "grey panel"])
def test_white_behind_or_only_on_some_sides_is_no_panel(change):
    if change == "wall behind":  # a disc on a pole before a white wall 2 m behind it
        image, depth = scene(panel_depth=12.0)
    elif change == "no white above":  # white beside the disc only: the panel's top is missing
        image, depth = scene(panel=(130, 150, 120, 120))
    elif change == "white above only":  # a white plate above the disc, nothing beside it
        image, depth = scene(panel=(160, 100, 60, 60))
    else:  # the surround is grey (not white): a disc on a grey box
        image, depth = scene(white=(110, 110, 110))
    assert not inside_white_panel(image, depth, DISC, 10.0, CONFIG)


def test_no_depth_or_a_strip_past_the_image_is_not_read():
    image, depth = scene()
    assert not inside_white_panel(image, depth, DISC, float("nan"), CONFIG)
    no_depth = depth.copy()
    x0, y0, x1, y1 = strip_box(DISC, ABOVE)
    no_depth[y0:y1, x0:x1] = np.nan  # stereo matching found nothing above the disc
    assert not inside_white_panel(image, no_depth, DISC, 10.0, CONFIG)
    at_top = (150, 5, 80, 80)  # the strip above lies mostly past the image's top
    image, depth = scene(panel=(130, 0, 120, 120), disc=at_top)
    assert strip_box(at_top, ABOVE)[1] < 0
    assert not inside_white_panel(image, depth, at_top, 10.0, CONFIG)


def test_strips_lie_outside_the_disc_box():
    x0, y0, x1, y1 = strip_box(DISC, LEFT)
    assert x1 <= DISC[0] and y0 > DISC[1] and y1 < DISC[1] + DISC[3]
    x0, y0, x1, y1 = strip_box(DISC, ABOVE)
    assert y1 <= DISC[1] and x0 > DISC[0] and x1 < DISC[0] + DISC[2]


def test_readings_that_may_be_a_zone_panels_disc():
    assert may_be_disc_of("2.30-30", "2.30-80") and may_be_disc_of("2.61", "2.61")
    assert not may_be_disc_of("2.61", "2.62") and not may_be_disc_of("2.30-30", "2.14")
    assert may_be_a_panels_disc(ZONES, "2.30-120") and may_be_a_panels_disc(ZONES, "2.61")
    assert not may_be_a_panels_disc(ZONES, "2.36") and not may_be_a_panels_disc({}, "2.30-30")
