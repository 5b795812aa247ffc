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


def ids_from_numbers(numbers, known_ids) -> tuple[list, list[str], str]:
    """Catalogue ids (text) for the values of an id field that was typed as a number (a CSV read with field types
    detected turns "1.30" into 1.3), and what could not be read back.

    A number stands for the one id of ``known_ids`` that reads as it; where none or several do, it stays as
    written. Values that are no number (NULL) are kept. Returns (ids, the numbers left unresolved, an example
    "1.3 as 1.30" or "").
    """
    by_number: dict[float, set] = {}
    for text in known_ids:
        try:
            by_number.setdefault(float(text), set()).add(text)
        except ValueError:
            continue
    ids, unresolved, example = [], [], ""
    for value in numbers:
        try:
            number = float(value)
        except (TypeError, ValueError):  # NULL
            ids.append(value)
            continue
        candidates = by_number.get(number, set())
        ids.append(next(iter(candidates)) if len(candidates) == 1 else f"{number:g}")
        if len(candidates) != 1:
            unresolved.append(f"{number:g}")
        elif not example and ids[-1] != f"{number:g}":
            example = f"{number:g} as {ids[-1]}"
    return ids, unresolved, example


def numeric_ids_note(field_name: str, kind: str, unresolved: list[str], example: str) -> str:
    """The warning for a reference whose id field is numeric: what to do, and how its numbers were read back."""
    text = (f"Reference field '{field_name}' is numeric ({kind}), but sign types are catalogue ids compared as "
            "text ('1.30' is not '1.3'). Load the reference with this field as text (for a delimited-text "
            "layer: switch off 'Detect field types').")
    if example:
        text += f" Numbers were read back as the catalogue ids they stand for (e.g. {example})."
    if unresolved:
        text += f" {len(unresolved)} stand for no single catalogue id and stay numbers (e.g. {unresolved[0]})."
    return text
