"""Rows of a reference or inventory layer that cannot count as they are, and the words for leaving them out.

A row that repeats another exactly is one sign recorded twice: counted twice, it
is found once and "missed" once (a detection rate of 0.5, a "missing" twin of a
confirmed sign), so it is counted once. A row without geometry has no place to
compare. Either is left out with a warning naming the rows, never silently.
"""

from __future__ import annotations

import math

DECIMALS = 3  # positions equal to the millimetre are the same place (a reprojection leaves noise below it)


def exact_duplicates(types, positions) -> dict[int, int]:
    """Row -> the earlier row it repeats: the same type at the same place (a missing height matches a missing
    height)."""
    first: dict[tuple, int] = {}
    repeats = {}
    for row, (kind, position) in enumerate(zip(types, positions)):
        key = (kind,) + tuple(round(float(c), DECIMALS) if math.isfinite(c) else None for c in position)
        if key in first:
            repeats[row] = first[key]
        else:
            first[key] = row
    return repeats


def repeats_note(where: str, repeats: dict[int, int], names) -> str:
    """The warning for ``repeats`` (:func:`exact_duplicates`) of the rows called ``names`` in ``where``."""
    row, earlier = next(iter(repeats.items()))
    return (f"{where}: {len(repeats)} feature{'s repeat' if len(repeats) > 1 else ' repeats'} another exactly (the "
            f"same type at the same place, e.g. {names[row]} = {names[earlier]}): each such sign is counted once")


def no_geometry_note(where: str, names) -> str:
    """The warning for rows called ``names`` of ``where`` that have no geometry."""
    return (f"{where}: {len(names)} feature{'s have' if len(names) > 1 else ' has'} no geometry and "
            f"{'are' if len(names) > 1 else 'is'} left out (e.g. {names[0]})")
