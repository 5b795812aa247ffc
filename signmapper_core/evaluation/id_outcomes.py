"""How the reference signs of chosen ids came out of a run: for a classifier trained with some ids left out.

Each reference sign of a chosen id falls in one outcome, the worst that applies first: ``missed`` (no fused sign
matches it), ``accepted as another id`` (a fused sign matching it is accepted under another id: the error an
open-set classifier must not make), ``unknown`` (a fused sign matching it carries :data:`UNKNOWN_ID`, the id the
mapping gives a sign-like face that matches no catalogue entry well; it is in review), ``right id`` (most of its
fused signs carry its id) or ``another id in review``.
"""

from __future__ import annotations

from collections import Counter
from typing import Iterable, Sequence

import numpy as np

from ..statuses import ACCEPTED
from .accuracy import majority_id, share_text

UNKNOWN_ID = "unknown"
MISSED, ACCEPTED_OTHER, UNKNOWN, RIGHT, REVIEW_OTHER = (
    "missed", "accepted as another id", "unknown", "right id", "another id in review")
OUTCOMES = (UNKNOWN, ACCEPTED_OTHER, MISSED, RIGHT, REVIEW_OTHER)  # the columns, in the order reports list them


def outcome(true_id: str, matched: Sequence) -> str:
    """The outcome of one reference sign of ``true_id`` given the fused signs matched to it."""
    if not matched:
        return MISSED
    if any(s.status == ACCEPTED and s.template_id not in (true_id, UNKNOWN_ID) for s in matched):
        return ACCEPTED_OTHER
    if any(s.template_id == UNKNOWN_ID for s in matched):
        return UNKNOWN
    return RIGHT if majority_id([s.template_id for s in matched]) == true_id else REVIEW_OTHER


def id_outcomes(signs: Sequence, reference: Sequence, match, ids: Iterable[str]) -> dict[str, Counter]:
    """{id: Counter of outcomes} of the reference signs whose id is in ``ids``; ``match``: per fused sign the index
    of the reference sign it matches, or -1 (:func:`evaluation.evaluate`)."""
    wanted = set(ids)
    match = np.asarray(match, int).reshape(-1)
    table: dict[str, Counter] = {}
    for k, ref in enumerate(reference):
        if ref.template_id in wanted:
            matched = [signs[i] for i in np.flatnonzero(match == k)]
            table.setdefault(ref.template_id, Counter())[outcome(ref.template_id, matched)] += 1
    return table


def outcome_lines(table: dict[str, Counter], title: str) -> list[str]:
    """One line per id (in view, then each outcome), then all of them together."""
    header = f"{'id':<14} {'in view':>7} " + " ".join(f"{name:>23}" for name in OUTCOMES)
    lines = [title, header]
    total = Counter()
    for template_id in sorted(table):
        total += table[template_id]
        lines.append(_line(template_id, table[template_id]))
    lines.append(_line("all", total))
    return lines


def _line(label: str, counts: Counter) -> str:
    n = sum(counts.values())
    return f"{label:<14} {n:>7} " + " ".join(f"{share_text(counts[name], n):>23}" for name in OUTCOMES)
