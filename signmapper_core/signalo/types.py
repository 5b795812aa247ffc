"""Our catalogue ids and Signalo's official signs (``signalo_db.vl_official_sign``), both ways.

Both use SSV numbers. Signalo keeps one entry for a sign that carries a number
and writes the number as the sign's first inscription (``2.30`` with
inscription ``50``); our catalogue has one template per value (``2.30-50``).
Signalo keeps one id per number of text lines of the white place-name and
direction panels (4.29-1 ... 4.33-3); our catalogue has one generic panel each
(``catalogue.text_panels``), whose lines give the Signalo id. Anything else
without an entry is reported, never guessed.
"""

from __future__ import annotations

from typing import Optional

from ..catalogue.text_panels import COVERED_BY_PANEL


def _panel_id(template_id: str, lines: int, official_ids) -> Optional[str]:
    """Signalo's id of a generic text panel with ``lines`` lines (1 to 3), if Signalo has one."""
    ids = sorted(o for o, panel in COVERED_BY_PANEL.items() if panel == template_id and o in official_ids)
    if not ids:
        return None
    return ids[min(max(lines, 1), len(ids)) - 1]


def to_signalo(template_id: str, official_ids, lines: int = 1) -> Optional[tuple[str, Optional[str]]]:
    """(Signalo official sign id, first inscription or None) of one of our ids, None if Signalo has no such sign.

    ``lines``: lines of text on a generic text panel (4.29, 4.33), which Signalo tells apart by id.
    """
    panel = _panel_id(template_id, lines, official_ids)
    if panel is not None:
        return panel, None
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
    if COVERED_BY_PANEL.get(official_id) in template_ids:
        return COVERED_BY_PANEL[official_id]
    if inscription:
        candidate = f"{official_id}-{inscription.strip()}"
        if candidate in template_ids:
            return candidate
    return official_id if official_id in template_ids else None
