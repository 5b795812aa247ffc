"""Text plates typed by what they say, and the inscriptions Signalo records of a plate."""

from __future__ import annotations

import pytest

from signmapper_core.catalogue.plates_ch import LAYOUT, PICTOGRAM, TEXT, direction_of, kind_of, signalo_id
from signmapper_core.plates.formats import PLATE_ID
from signmapper_core.plates.types import inscriptions, text_plate_id


@pytest.mark.parametrize("text, expected", [
    ("200 m", "5.01"),
    ("2,5 km", "5.01"),
    ("ausgenommen / Zubringerdienst", "5.00-exception"),
    ("excepté / riverains / bus", "5.00-exception"),
    ("eccetto / bus", "5.00-exception"),
    ("7–19 h", "5.00-1"),
    ("Mo–Fr", "5.00-1"),
    ("Mo–Fr / 7–19 h", "5.00-2"),
    ("200 m / Mo–Fr", "5.00-2"),  # a distance with more: free text
    ("lu–ve / 7–12 h / 14–18 h", "5.00-3"),
    ("a / b / c / d", "5.00-3"),  # more lines than any plate: the three-line plate
    ("", PLATE_ID),
    (None, PLATE_ID),
])
def test_a_text_plate_is_typed_by_what_it_says(text, expected):
    assert text_plate_id(text) == expected


def test_inscriptions_are_the_free_text_a_pictogram_plate_has_none():
    assert inscriptions("5.00-exception", "ausgenommen / Zubringerdienst") == ["Zubringerdienst"]
    assert inscriptions("5.00-2", "Mo–Fr / 7–19 h") == ["Mo–Fr", "7–19 h"]
    assert inscriptions("5.01", "200 m") == ["200 m"]
    assert inscriptions("5.00-3", "a / b / c / d") == ["a", "b", "c d"]  # Signalo has three: the rest in the last
    assert inscriptions(PLATE_ID, "excepté / bus") == ["bus"]
    assert inscriptions(PLATE_ID, None) == []
    assert inscriptions("5.03", "2,5 km") == ["2,5 km"] and inscriptions("5.31-3", "Taxi") == ["Taxi"]
    assert inscriptions("5.31-2", "ausgenommen") == [] and inscriptions("5.20", None) == []


def test_direction_plates_are_two_ids_of_one_signalo_id():
    assert (signalo_id("5.02-l"), direction_of("5.02-l")) == ("5.02", "l")
    assert (signalo_id("5.07-r"), direction_of("5.07-r")) == ("5.07", "r")
    assert (signalo_id("5.31-2"), direction_of("5.31-2")) == ("5.31-2", "")  # -2 is part of the id
    assert (signalo_id("2.30-50"), direction_of("5.03")) == ("2.30-50", "")
    assert (kind_of("5.02-r"), kind_of("5.01"), kind_of("5.22"), kind_of(PLATE_ID)) == (LAYOUT, TEXT, PICTOGRAM,
                                                                                        TEXT)
