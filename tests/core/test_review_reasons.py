"""Why a detection or a sign waits for review: the first rule that held it, as a fixed phrase."""

from types import SimpleNamespace

from signmapper_core.output import review_reasons as rr
from signmapper_core.output.schema import DETECTIONS, SIGNS, fields


def _view(status="accepted", reason=""):
    return SimpleNamespace(status=status, review_reason=reason)


def _reason(voters, share=1.0, indicator=0.99, needed=0.97):
    return rr.sign_reason(voters, share, indicator, needed, 2, 0.6, "accepted")


def test_a_sign_names_the_first_condition_it_failed_in_fusions_order():
    two = [_view(), _view()]
    assert _reason(two) is None
    assert _reason([_view()]) == rr.ONE_VIEW
    assert rr.sign_reason([_view(), _view()], 1.0, 0.99, 0.97, 3, 0.6, "accepted") == rr.TOO_FEW_VIEWS
    assert _reason([_view()], share=0.5, indicator=0.5) == rr.ONE_VIEW  # one view first, whatever else
    assert _reason(two, share=0.5, indicator=0.5) == rr.VIEWS_DISAGREE
    assert _reason(two, indicator=0.96) == rr.BELOW_SIGN_THRESHOLD
    held = [_view("review", rr.FAINT_HOUGH_RING), _view("review")]
    assert _reason(held) == f"{rr.NO_VIEW_ACCEPTED}: {rr.FAINT_HOUGH_RING}; {rr.LOW_INDICATOR}"


def test_a_detection_in_review_without_a_rule_fell_short_of_its_threshold():
    assert rr.reason_shown(_view("accepted", rr.ZONE_PANEL_DISC)) is None
    assert rr.reason_shown(_view("manual")) is None
    assert rr.reason_shown(_view("review")) == rr.LOW_INDICATOR
    assert rr.reason_shown(_view("review", rr.ZONE_PANEL_DISC)) == rr.ZONE_PANEL_DISC
    assert rr.digits_reason("30") == "digits read as 30"


def test_both_layers_write_the_reason_only_for_features_in_review():
    (sign_field,) = [f for f in fields(SIGNS) if f.name == "review_reason"]
    (det_field,) = [f for f in fields(DETECTIONS) if f.name == "review_reason"]
    assert sign_field.value(SIGNS, SimpleNamespace(status="review", review_reason=rr.ONE_VIEW)) == rr.ONE_VIEW
    assert sign_field.value(SIGNS, SimpleNamespace(status="review", review_reason=None)) == rr.LOW_INDICATOR
    assert sign_field.value(SIGNS, SimpleNamespace(status="accepted", review_reason=None)) is None
    assert det_field.value(DETECTIONS, SimpleNamespace(detection=_view("review", rr.WHITE_UNREAD))) == \
        rr.WHITE_UNREAD
    assert det_field.value(DETECTIONS, SimpleNamespace(detection=_view("accepted"))) is None
