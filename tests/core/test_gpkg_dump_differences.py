"""The golden comparison: the next-choices text tolerates a last-digit flip of a score, never another id."""

from gpkg_dump import differences


def _row(text):
    return {"attributes": {"alternatives": text}}


def test_a_score_one_unit_off_is_the_same_value():
    assert differences(_row("2.12 0.22, 2.30-40 0.06"), _row("2.12 0.23, 2.30-40 0.06")) == []


def test_another_id_another_order_or_a_score_two_units_off_differ():
    assert differences(_row("2.12 0.22, 2.30-40 0.06"), _row("2.13 0.22, 2.30-40 0.06"))
    assert differences(_row("2.12 0.22, 2.30-40 0.06"), _row("2.30-40 0.06, 2.12 0.22"))
    assert differences(_row("2.12 0.22"), _row("2.12 0.24"))
    assert differences(_row("2.12 0.22"), _row(None))
    assert differences(_row("not a list"), _row("not a list")) == []
