"""The sign colour table: every colour a run segments, and every colour the catalogue uses, is complete."""

from signmapper_core.catalogue import load_catalogue
from signmapper_core.sign_colours import DISPLAY_COLOURS, HOUGH_TINT_HUES, HSV_RANGES, SIGN_COLOURS, WEAK_HUES


def test_each_segmented_colour_has_its_bands_in_every_table():
    assert SIGN_COLOURS == tuple(HSV_RANGES)
    assert set(SIGN_COLOURS) <= set(DISPLAY_COLOURS)
    # the weak pass and the Hough tint name the colours faded faces of which are sought (the weak pass takes the
    # strong bands of the others: scene_colour.weak_ranges); none they name is unsegmented
    assert {"red", "blue", "yellow"} <= set(WEAK_HUES) <= set(SIGN_COLOURS)
    assert {"red", "blue", "yellow"} <= set(HOUGH_TINT_HUES) <= set(SIGN_COLOURS)


def test_each_catalogue_colour_is_drawn_in_its_own_colour_on_the_map():
    colours = {entry.colour for entry in load_catalogue()}
    assert colours <= set(DISPLAY_COLOURS) and "white" in colours
    assert all(value.startswith("#") and len(value) == 7 for value in DISPLAY_COLOURS.values())
    assert len(set(DISPLAY_COLOURS.values())) == len(DISPLAY_COLOURS)
