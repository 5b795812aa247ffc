"""Entries that differ only by their lines of text: one direction sign with one, two or three destinations.

Signalo keeps a number per line count (0.1, 0.1-2, 0.1-3 for a tourist pointer; 4.34, 4.34-2, 4.34-3 for a
diversion pointer) and says the count in the German name, "(1 Linie)", "(2 Linien)". A network reading a face at
32 px cannot count lines of text a few pixels high; the pipeline counts them in the image and picks the entry of
the group with that count (:mod:`signmapper_core.pipeline.text_lines`).
"""

from __future__ import annotations

import re
from typing import Dict, Tuple

_LINES_IN_NAME = re.compile(r"\s*\((\d) Linien?\)\s*$")


def line_groups(catalogue) -> Dict[str, Tuple[str, int]]:
    """{id: (group, lines)} of the entries of ``catalogue`` that share colour, outline and name but for their
    lines of text, in groups of at least two."""
    found = {}
    for entry in catalogue:
        match = _LINES_IN_NAME.search(entry.names.get("de", ""))
        if match:
            group = f"{entry.colour} {entry.shape} {entry.names['de'][:match.start()]}"
            found[entry.id] = (group, int(match.group(1)))
    sizes: Dict[str, int] = {}
    for group, _ in found.values():
        sizes[group] = sizes.get(group, 0) + 1
    return {tid: (group, lines) for tid, (group, lines) in found.items() if sizes[group] > 1}


def with_lines(groups: Dict[str, Tuple[str, int]], template_id: str, lines: int):
    """The id of ``template_id``'s group with ``lines`` lines of text; None when the group has none (or
    ``template_id`` is in no group)."""
    if template_id not in groups:
        return None
    group = groups[template_id][0]
    return next((tid for tid, (g, n) in sorted(groups.items()) if g == group and n == lines), None)
