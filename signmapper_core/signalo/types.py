"""Our catalogue ids and Signalo's official signs (``signalo_db.vl_official_sign``), both ways.

Both use SSV numbers. Signalo keeps one entry for a sign that carries a number
and writes the number as the sign's first inscription (``2.30`` with
inscription ``50``); our catalogue has one template per value (``2.30-50``).
Two zone signs are named differently: Signalo splits the SSV 2.59.1/2.59.2
zone signs by content, and our 2.59.1/2.59.2 are the Tempo-30 zone (names
"Tempo-30-Zone" / "Zonensignal Tempo-30-Zone"). Anything else without an
entry is reported, never guessed.
"""

from __future__ import annotations

from typing import Optional

# our id -> Signalo id, where the names say they are the same sign
ALIASES = {"2.59.1": "2.59.1-30", "2.59.2": "2.59.2-30"}


def to_signalo(template_id: str, official_ids) -> Optional[tuple[str, Optional[str]]]:
    """(Signalo official sign id, first inscription or None) of one of our ids, None if Signalo has no such sign."""
    if template_id in ALIASES and ALIASES[template_id] in official_ids:
        return ALIASES[template_id], None
    if template_id in official_ids:
        return template_id, None
    base, dash, value = template_id.rpartition("-")
    if dash and base in official_ids:
        return base, value
    return None


def from_signalo(official_id: Optional[str], inscription: Optional[str], template_ids) -> Optional[str]:
    """Our template id of a Signalo official sign (with its first inscription), None if our catalogue lacks it."""
    if not official_id:
        return None
    for ours, theirs in ALIASES.items():
        if theirs == official_id and ours in template_ids:
            return ours
    if inscription:
        candidate = f"{official_id}-{inscription.strip()}"
        if candidate in template_ids:
            return candidate
    return official_id if official_id in template_ids else None
