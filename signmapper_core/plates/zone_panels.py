"""Zone panels (2.59.1, 2.59.3): white panels that carry a disc sign, and the readings of that disc alone.

A view that misses the panel's white reads its disc as a sign of its own (2.59.1's ring as a speed limit, 2.59.3's
disc as 2.61). Where the disc sits inside white at its own depth (``pipeline.zone_panel_surround``), detection
reads the panel or holds such a reading for review; fusion counts doubtful ones for a panel read elsewhere on the
track.
"""

from __future__ import annotations

from typing import Mapping

from .printed_numbers import printed_number


def may_be_disc_of(panel_disc: str, reading: str) -> bool:
    """Whether ``reading`` may be a zone panel's disc (``panel_disc``, the disc sign it carries) read alone: that
    sign, or, for a speed ring, any speed limit (its digits are what a view of the disc alone misreads)."""
    return reading == panel_disc or (printed_number(panel_disc) is not None and printed_number(reading) is not None)


def may_be_a_panels_disc(carried_discs: Mapping[str, str], reading: str) -> bool:
    """Whether ``reading`` may be the disc of any of the zone panels ``carried_discs`` (panel id -> its disc)."""
    return any(may_be_disc_of(disc, reading) for disc in carried_discs.values())
