"""Why the mapping left a detection or a sign for a person to look at: the ``review_reason`` field.

A sign in review with a classification indicator of 0.99 puzzles a reviewer unless
it says which rule held it (one view only, a zone panel's disc read alone, ...).
The reasons are short fixed phrases, so a layer can be filtered by them; the first
rule that held a sign is named. Pure functions of the values fusion and the
pipeline already decided on: naming a reason never changes a status.
"""

from __future__ import annotations

from typing import Optional, Sequence

from ..statuses import REVIEW

# a detection, in its pair
LOW_INDICATOR = "indicator below the acceptance threshold"
ZONE_PANEL_DISC = "a zone panel's disc read alone"
ZONE_PANEL_BY_DEPTH = "zone panel read by its depth, its drawing unmatched"
FAINT_HOUGH_RING = "Hough circle without a full-colour ring"
WHITE_UNREAD = "resembles a white sign the network reads as none"
NO_ENTRY_MATCHES = "matches no catalogue sign well"
OFF_FORMAT = "size fits no standard format"
DOUBTFUL_READINGS = (OFF_FORMAT, NO_ENTRY_MATCHES)  # a sign read only so must be seen again (fusion)
# a fused sign
ONE_VIEW = "seen in one pair only"
TOO_FEW_VIEWS = "too few views"
VIEWS_DISAGREE = "views disagree on the id"
BELOW_SIGN_THRESHOLD = "views' mean indicator below the sign's threshold"
NO_VIEW_ACCEPTED = "no view accepted"
DIGITS_PREFIX = "digits read as "
# a fused sign that cannot be where or as it was mapped (fusion/plausibility.py)
MOUNTED_TOO_LOW = "face lower than any sign is mounted"
FACES_AWAY = "face turned away from the road"
FAR_FROM_ROAD = "farther from the road than any sign"


def reason_shown(item) -> Optional[str]:
    """The reason written for a detection, observation or fused sign: the rule that held it, or for one in review
    without a named rule (a plate, a detection short of its threshold) its indicator. None when not in review."""
    if item.status != REVIEW:
        return None
    return getattr(item, "review_reason", "") or LOW_INDICATOR


def sign_reason(voters: Sequence, vote_share: float, indicator: float, needed: float, min_views: int,
                min_share: float, accepted_status: str) -> Optional[str]:
    """A fused sign's acceptance test (:func:`fusion.fuse_track`): None when it passes, else the first condition
    it failed. ``voters``: the observations that read the sign's id; ``needed``: the mean indicator the voters
    need (``sign_accept_threshold``). The last condition: one view at least accepted its reading, as views a
    detection rule held for review whatever their score (a Hough circle without a full-colour ring, a disc inside
    a white panel) make no accepted sign on their own."""
    if len(voters) < min_views:
        return ONE_VIEW if len(voters) == 1 else TOO_FEW_VIEWS
    if vote_share < min_share:
        return VIEWS_DISAGREE
    if indicator < needed:
        return BELOW_SIGN_THRESHOLD
    if not any(o.status == accepted_status for o in voters):
        held = sorted({reason_shown(o) or LOW_INDICATOR for o in voters})
        return f"{NO_VIEW_ACCEPTED}: {'; '.join(held)}"
    return None


def digits_reason(number: str) -> str:
    """A speed limit whose digits read as another limit's number (``number_check``)."""
    return f"{DIGITS_PREFIX}{number}"
