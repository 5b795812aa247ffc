"""The classifier's next choices: ranked per detection, pooled per sign, written as text and read back."""

import math
from types import SimpleNamespace

from signmapper_core.output.classifier_alternatives import (
    format_alternatives,
    parse_alternatives,
    pooled_scores,
    ranked_alternatives,
    sign_alternatives,
)
from signmapper_core.output.schema import DETECTIONS, SIGNS, fields


def _obs(template_id, scores):
    return SimpleNamespace(detection=SimpleNamespace(template_id=template_id, scores=scores))


def test_ranking_leaves_out_the_chosen_id_weak_and_broken_scores():
    scores = {"2.06": 0.62, "2.12": 0.22, "2.30-40": 0.06, "2.01": 0.01, "2.02": math.nan, "2.03": 0.06}
    assert ranked_alternatives(scores, "2.06") == [("2.12", 0.22), ("2.03", 0.06), ("2.30-40", 0.06)]
    assert ranked_alternatives(scores, "2.06", limit=1) == [("2.12", 0.22)]
    assert ranked_alternatives({"2.06": 1.0}, "2.06") == []


def test_a_sign_pools_its_views_and_an_id_missing_from_a_view_counts_zero_there():
    views = [_obs("2.06", {"2.06": 0.7, "2.12": 0.3}), _obs("2.06", {"2.06": 0.5, "2.12": 0.1, "2.30-40": 0.4}),
             _obs(None, {})]  # a view the classifier never scored (a Hough field, a manual sign) is no vote
    assert pooled_scores(o.detection.scores for o in views) == {"2.06": 0.6, "2.12": 0.2, "2.30-40": 0.2}
    sign = SimpleNamespace(template_id="2.06", observations=views)
    assert sign_alternatives(sign) == [("2.12", 0.2), ("2.30-40", 0.2)]
    assert sign_alternatives(SimpleNamespace(template_id="2.06", observations=[])) == []


def test_written_text_reads_back_and_a_damaged_value_loses_only_its_damaged_parts():
    text = format_alternatives([("2.12", 0.2249), ("2.30-40", 0.06)])
    assert text == "2.12 0.22, 2.30-40 0.06"
    assert parse_alternatives(text) == [("2.12", 0.22), ("2.30-40", 0.06)]
    assert format_alternatives([]) is None
    assert parse_alternatives(None) == [] and parse_alternatives("") == []
    assert parse_alternatives("2.12 x, 1.01 0.5,, 3 words here, 2.07 nan, 4.18 0.1") == [("1.01", 0.5), ("4.18", 0.1)]


def test_both_layers_carry_the_next_choices_and_a_sign_writes_its_pooled_ones():
    (field,) = [f for f in fields(SIGNS) if f.name == "alternatives"]
    assert "alternatives" in [f.name for f in fields(DETECTIONS)]
    sign = SimpleNamespace(template_id="1.26", observations=[_obs("1.26", {"1.26": 0.84, "1.09": 0.14})])
    assert field.value(SIGNS, sign) == "1.09 0.14"
    assert field.value(DETECTIONS, _obs("1.26", {"1.26": 0.84, "1.09": 0.14})) == "1.09 0.14"
    assert field.value(DETECTIONS, _obs("1.26", {"1.26": 1.0})) is None
