"""The digits of each sign mapped as a speed limit, read by OCR: a second reading that can send it to review.

The classifier and Tesseract fail differently: the network reads a face whole and
can take a heavy "30" for "80" with 0.98, Tesseract reads the digits alone and
mostly reads nothing where it is unsure. So a sign whose views' digits say
another speed limit's number more often than its own goes to review (its id is
left as the vote gave it: the person decides), and every speed limit gets the
number read as its ``text``. Without Tesseract the signs keep their status and
``warn`` hears once why.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

from ..fusion.signs import FusedSign, FusionConfig
from ..output.review_reasons import digits_reason
from ..progress import WarnCallback, send_warning
from ..statuses import ACCEPTED, REVIEW
from .ocr import OcrError, OcrUnavailable, read_numbers
from .printed_numbers import prepared_band, printed_number


@dataclass(frozen=True)
class NumberVerdict:
    """What a sign's digits say: the number most views read (None: none read a speed limit's number), the
    share of views that read it, and whether they speak against the mapped id."""

    number: Optional[str]
    share: float
    contradicts: bool


def judge_numbers(mapped: str, readings: Sequence[str], known: frozenset) -> NumberVerdict:
    """The verdict of ``readings`` (the digits read per view) on a sign mapped as the speed limit printing
    ``mapped``: only readings of a number some speed limit prints (``known``) count; they contradict the id
    when more of them read another number than ``mapped``. A reading that is ``mapped`` with a digit lost or
    gained at an end ("20" on a 120, whose thin "1" the band's edge or the ring swallowed) says nothing."""
    counts = Counter(r for r in readings if r in known and (r == mapped or (r not in mapped and mapped not in r)))
    if not counts:
        return NumberVerdict(None, 0.0, False)
    number = max(counts, key=lambda n: (counts[n], n == mapped))
    others = sum(c for n, c in counts.items() if n != mapped)
    return NumberVerdict(number, counts[number] / len(readings), others > counts.get(mapped, 0))


def number_views(sign: FusedSign, views: int) -> list:
    """The digits' bands (``Detection.crop``) of the ``views`` largest observations that voted for the sign's
    id: the nearest views read best."""
    voters = [o for o in sign.observations if o.template_id == sign.template_id and o.detection.crop is not None]
    voters.sort(key=lambda o: o.bbox[3], reverse=True)
    return [o.detection.crop for o in voters[:views]]


def speed_limit_signs(signs: Sequence[FusedSign]) -> list:
    """The signs mapped as a speed limit: those whose digits :func:`check_speed_numbers` reads."""
    return [sign for sign in signs if printed_number(sign.template_id) is not None]


def check_speed_numbers(signs: Sequence[FusedSign], known: frozenset, warn: Optional[WarnCallback] = None,
                        read: Callable = read_numbers, config: Optional[FusionConfig] = None) -> int:
    """Read the digits of every sign mapped as a speed limit; set its ``text`` (the number read) and
    ``text_confidence`` (the share of views that read it), and send an accepted one to review when its digits
    contradict it (:func:`judge_numbers`). ``known``: the numbers the catalogue's speed limits print
    (``printed_numbers.printed_numbers``). One OCR run for all. Returns the number of signs sent to review."""
    config = config or FusionConfig()
    signs = speed_limit_signs(signs)
    owners, images = [], []
    for k, sign in enumerate(signs):
        for band in number_views(sign, config.number_readings):
            owners.append(k)
            images.append(prepared_band(band))
    if not images:
        return 0
    try:
        readings = read(images)
    except (OcrUnavailable, OcrError) as exc:
        count = len(set(owners))
        send_warning(warn, f"digits not read on {count} speed-limit sign{'s' if count > 1 else ''}: their status "
                           f"stands on the classifier alone ({exc})")
        return 0
    by_sign = {}
    for k, reading in zip(owners, readings):
        by_sign.setdefault(k, []).append(reading)
    demoted = 0
    for k, sign_readings in by_sign.items():
        sign = signs[k]
        verdict = judge_numbers(printed_number(sign.template_id), sign_readings, known)
        if verdict.number is not None:
            sign.text, sign.text_confidence = verdict.number, verdict.share
        if verdict.contradicts and sign.status == ACCEPTED:
            sign.status, sign.review_reason = REVIEW, digits_reason(verdict.number or "")
            demoted += 1
    return demoted
