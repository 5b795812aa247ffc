"""Procedural textures of the synthetic street: edge cases of their geometry."""

from __future__ import annotations

import numpy as np

from signmapper_core.simulate import textures as tx


def test_shop_window_reaching_past_the_facade_foot_is_painted_up_to_it():
    """A window whose pane ends below the façade's last row (the seed 1608 crash: 56 vs 55 rows) is cut there."""
    img = np.full((100, 80, 3), 200, np.uint8)
    frame = (235, 235, 235)
    # 0.04 m per pixel: the window spans rows 50..105, its pane (2 px inside the frame) rows 52..103 of 100
    tx._window(img, np.random.default_rng(0), 1.0, 2.0, 1.2, 2.2, 0.04, frame)
    pane = img[52:100, 28:53]
    assert pane.mean() < 160 and (pane != 200).all()  # dark glass down to the last row
    assert tuple(img[50, 30]) == frame  # the frame above it
    assert (img[:50] == 200).all()  # nothing above the window


def test_facade_of_seed_1608s_shape_is_drawn():
    """The façade that made seed 1608's drive fail (its ground-floor window 0.1 m past the foot)."""
    width_m, height_m = 26.095706479787914, 9.5560556269964
    img = tx.facade(np.random.default_rng(2458), width_m, height_m, 0.04)
    assert img.shape == (int(height_m / 0.04), int(width_m / 0.04), 3)
