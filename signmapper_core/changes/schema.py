"""The output of ``changes``, declared once: the layers ``changes`` (points) and ``displacements`` (lines).

Like :mod:`output.schema` for a mapping run: the GeoPackage writer, the review
(which opens a change at the pair where the sign is or should be) and the
algorithm's help derive from :data:`FIELDS`. A row reads its value from a
:class:`~signmapper_core.changes.compare.Change`.
"""

from __future__ import annotations

from ..output.schema import INTEGER, REAL, TEXT, Field
from ..statuses import ACCEPTED, REVIEW
from .compare import CHANGED, CONFIRMED, MISSING, MOVED, NEW, NOT_COVERED, Change

CHANGES, DISPLACEMENTS = "changes", "displacements"
# verdicts a person should look at: the review walks them with "Next to review"
TO_REVIEW = {MOVED: REVIEW, CHANGED: REVIEW, MISSING: REVIEW, NEW: REVIEW, CONFIRMED: ACCEPTED,
             NOT_COVERED: ACCEPTED}


def _inventory(name: str):
    return lambda c: getattr(c.inventory, name) if c.inventory is not None else None


def _mapped(name: str):
    return lambda c: getattr(c.mapped, name) if c.mapped is not None else None


def _view(c: Change):
    """Pair, (u, v), box and depth the review shows: where the mapped sign was seen, else where the inventory
    sign should be seen."""
    found = c.mapped
    if found is not None and found.best_pair_id:
        return found.best_pair_id, found.u, found.v, found.bbox, None
    view = c.best_view
    if view is None:
        return None
    return view.pair_id, view.u, view.v, view.bbox, view.depth_m


def _view_part(index: int, sub: int = -1):
    def read(c):
        view = _view(c)
        if view is None or view[index] is None:
            return None
        return view[index] if sub < 0 else view[index][sub]
    return read


def _time(c: Change):
    view = c.best_view
    return view.time if c.mapped is None and view is not None else None


FIELDS = (
    Field("verdict", TEXT, "confirmed, moved, changed, missing, not covered (the drive could not see it) or new "
          "(mapped, not in the inventory).", required=True, sign=lambda c: c.verdict),
    Field("inventory_id", TEXT, "Id of the inventory sign (feature id, Signalo sign id); empty for a new sign.",
          required=True, sign=_inventory("key")),
    Field("inventory_type", TEXT, "Its type as a catalogue id where the catalogue has it, else the inventory's.",
          sign=_inventory("template_id")),
    Field("inventory_label", TEXT, "Its type as the inventory writes it.", sign=_inventory("label")),
    Field("sign_id", INTEGER, "Mapped sign (signs.sign_id) it was compared with, or the new sign.",
          sign=_mapped("sign_id")),
    Field("template_id", TEXT, "Type of that mapped sign.", required=True, sign=_mapped("template_id")),
    Field("distance_m", REAL, "Planimetric distance inventory - mapped sign [m].", decimals=3,
          sign=lambda c: c.distance_m),
    Field("dz_m", REAL, "Height of the mapped sign minus the inventory's, where it has heights [m].", decimals=3,
          sign=lambda c: c.height_difference_m),
    Field("n_pairs", INTEGER, "Number of pairs that should have shown the inventory sign.",
          sign=lambda c: len(c.views) if c.inventory is not None else None),
    Field("visible_pairs", TEXT, "Ids of those pairs, space-separated, in driving order.",
          sign=lambda c: " ".join(c.visible_pair_ids) if c.inventory is not None else None),
    Field("pair_id", TEXT, "Pair the review opens: where the mapped sign was seen best, else where the inventory "
          "sign should be seen best (nearest, whole face in the image).", required=True, sign=_view_part(0)),
    Field("time", REAL, "Time of that pair where the inventory sign should be seen [s].", sign=_time),
    Field("u", REAL, "Column of the sign's centre in that pair's left image [px].", decimals=2, required=True,
          sign=_view_part(1)),
    Field("v", REAL, "Row of the sign's centre [px].", decimals=2, required=True, sign=_view_part(2)),
    Field("bbox_x", INTEGER, "Left column of the face's box [px].", required=True, sign=_view_part(3, 0)),
    Field("bbox_y", INTEGER, "Top row of the face's box [px].", required=True, sign=_view_part(3, 1)),
    Field("bbox_w", INTEGER, "Width of the face's box [px].", required=True, sign=_view_part(3, 2)),
    Field("bbox_h", INTEGER, "Height of the face's box [px].", required=True, sign=_view_part(3, 3)),
    Field("depth_m", REAL, "Depth at which the inventory sign should be seen in that pair [m].", decimals=2,
          sign=_view_part(4)),
    Field("reason", TEXT, "Why this verdict.", sign=lambda c: c.reason),
    Field("status", TEXT, "review for verdicts a person should look at (moved, changed, missing, new), else accepted; "
          "accepted or rejected once a person decided.", required=True, sign=lambda c: TO_REVIEW[c.verdict]),
    Field("reviewed", INTEGER, "1 once a person decided on the verdict, else 0.", required=True, sign=lambda c: 0),
)

LINE_FIELDS = (
    Field("verdict", TEXT, "confirmed, moved or changed.", sign=lambda c: c.verdict),
    Field("inventory_id", TEXT, "Id of the inventory sign.", sign=_inventory("key")),
    Field("sign_id", INTEGER, "Mapped sign.", sign=_mapped("sign_id")),
    Field("distance_m", REAL, "Planimetric length of the displacement [m].", decimals=3, sign=lambda c: c.distance_m),
)


def fields(layer: str = CHANGES) -> tuple:
    if layer not in (CHANGES, DISPLACEMENTS):
        raise ValueError(f"no changes layer '{layer}'")
    return FIELDS if layer == CHANGES else LINE_FIELDS


def values(change: Change, layer: str = CHANGES) -> dict:
    """Field name -> written value of a change."""
    return {f.name: f.typed(f.sign(change)) for f in fields(layer)}


def required_names() -> set:
    return {f.name for f in FIELDS if f.required}
