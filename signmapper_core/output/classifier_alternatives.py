"""The ids a classifier ranked next after the one a detection or sign carries, for the review to offer.

A misread sign is most often read as a neighbour of its true id, and the true id is
then often the classifier's second choice: the review shows these ids first, so a
person reclassifies such a sign with one click instead of searching the catalogue.
Scores are the classifier's own (a probability for the network, a correlation for
template matching). Written as text, ``"2.12 0.22, 2.30-40 0.06"``: catalogue ids
hold no spaces or commas (``catalogue.model.ID_PATTERN``).
"""

from __future__ import annotations

import math
from typing import Iterable, Mapping, Optional, Sequence

MAX_ALTERNATIVES = 3
MIN_SCORE = 0.02  # below this an id is no suggestion, only noise of the ranking


def ranked_alternatives(scores: Mapping[str, float], chosen: Optional[str], limit: int = MAX_ALTERNATIVES,
                        min_score: float = MIN_SCORE) -> list[tuple[str, float]]:
    """The best-scored ids other than ``chosen``, best first, at most ``limit``, each scored at least ``min_score``.

    Non-finite scores are left out; ties are broken by id so the result does not depend on dict order.
    """
    usable = [(tid, float(s)) for tid, s in scores.items()
              if tid != chosen and s is not None and math.isfinite(float(s)) and float(s) >= min_score]
    usable.sort(key=lambda kv: (-kv[1], kv[0]))
    return usable[:limit]


def pooled_scores(score_maps: Iterable[Mapping[str, float]]) -> dict[str, float]:
    """Mean score per id over the views of one sign that were classified at all.

    A view in which an id was not a candidate (its colour or shape cut it) counts 0 for it: an id seen
    in one view of five is a weaker suggestion than one seen in all.
    """
    maps = [m for m in score_maps if m]
    if not maps:
        return {}
    total: dict[str, float] = {}
    for m in maps:
        for tid, s in m.items():
            if s is not None and math.isfinite(float(s)):
                total[tid] = total.get(tid, 0.0) + float(s)
    return {tid: s / len(maps) for tid, s in total.items()}


def detection_alternatives(detection) -> list[tuple[str, float]]:
    """What the classifier ranked after the detection's own id in its pair."""
    return ranked_alternatives(getattr(detection, "scores", None) or {}, detection.template_id)


def sign_alternatives(sign) -> list[tuple[str, float]]:
    """What the classifier ranked after the sign's id, pooled over the sign's observations."""
    pooled = pooled_scores(getattr(obs.detection, "scores", None) or {} for obs in sign.observations)
    return ranked_alternatives(pooled, sign.template_id)


def format_alternatives(alternatives: Sequence[tuple[str, float]]) -> Optional[str]:
    """``"2.12 0.22, 2.30-40 0.06"``, or None when there is nothing to suggest."""
    if not alternatives:
        return None
    return ", ".join(f"{tid} {score:.2f}" for tid, score in alternatives)


def parse_alternatives(text: Optional[str]) -> list[tuple[str, float]]:
    """The (id, score) pairs of a written value; parts that do not read as "<id> <score>" are skipped.

    The field is plain text a person can edit, so a damaged value loses its damaged parts, never the review.
    """
    pairs = []
    for part in (text or "").split(","):
        words = part.split()
        if len(words) != 2:
            continue
        try:
            score = float(words[1])
        except ValueError:
            continue
        if math.isfinite(score):
            pairs.append((words[0], score))
    return pairs
