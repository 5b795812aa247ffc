"""Reading a Signalo database as the inventory ``changes`` compares a run with.

Each official sign becomes an :class:`~signmapper_core.changes.compare.InventorySign` at
its support's position, facing its azimut (a verso sign the opposite way, a
recto-verso sign both ways). Signalo has no heights; where the support records
the free height under its signs, each face's height above the road is rebuilt
from its frame's rank and the sizes of the faces below it.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from ..changes.compare import InventorySign
from .schema import OFFICIAL_SIGN_TYPE, SCHEMA, check_database
from .types import from_signalo

QUERY = f"""
SELECT s.id::text, s.fk_official_sign, s.inscription_1, s.dimension_1, s.dimension_2, s.fk_hanging_mode,
       ST_X(su.geometry), ST_Y(su.geometry), a.azimut, a.id::text, su.height_free_under_signal, f.rank, s.rank
FROM {SCHEMA}.sign s
JOIN {SCHEMA}.frame f ON f.id = s.fk_frame
JOIN {SCHEMA}.azimut a ON a.id = f.fk_azimut
JOIN {SCHEMA}.support su ON su.id = a.fk_support
WHERE s.fk_sign_type = %s
ORDER BY a.id, f.rank, s.rank
"""


def _size(d1, d2) -> tuple:
    """(width, height) [m] from Signalo's dimensions: a radius alone is a round face; None where not given."""
    if d1 is None:
        return None, None
    if d2 is None:
        return 2.0 * float(d1), 2.0 * float(d1)
    return float(d2), float(d1)


def read_inventory(connection, template_ids, where: str = "the database") -> tuple[list, int, str]:
    """(inventory signs in the database's SRID, number of non-official signs left out, SRID as 'EPSG:n').

    ``template_ids``: the catalogue's ids, to name each sign by our template id
    where we have its type (else by its Signalo id, which ``changes`` reports as
    not mappable).
    """
    with connection, connection.cursor() as cursor:
        info = check_database(cursor, where)
        cursor.execute(QUERY, (OFFICIAL_SIGN_TYPE,))
        rows = cursor.fetchall()
        cursor.execute(f"SELECT count(*) FROM {SCHEMA}.sign WHERE fk_sign_type IS DISTINCT FROM %s",
                       (OFFICIAL_SIGN_TYPE,))
        others = cursor.fetchone()[0]
    stacks = defaultdict(list)
    for row in rows:
        stacks[row[9]].append(row)
    signs = []
    for stack in stacks.values():
        # frames ranked from the top: rebuild heights from the bottom up where the free height is known
        above_road = {}
        free = stack[0][10]
        if free is not None:
            level = float(free)
            for row in reversed(stack):
                height = _size(row[3], row[4])[1] or 0.6
                above_road[row[0]] = level + height / 2.0
                level += height
        for (key, official, inscription, d1, d2, hanging, x, y, azimut, _a, _free, _fr, _sr) in stack:
            width, height = _size(d1, d2)
            turn = 180.0 if hanging == "verso" else 0.0
            facing = None if hanging == "recto-verso" else (float(azimut) + turn) % 360
            ours = from_signalo(official, inscription, template_ids)
            label = official + (f" {inscription}" if inscription else "") if official else "(no official type)"
            signs.append(InventorySign(key, ours or (official or ""), np.array([x, y, np.nan]), facing, width, height,
                                       above_road.get(key), label))
    return signs, others, f"EPSG:{info.srid}"
