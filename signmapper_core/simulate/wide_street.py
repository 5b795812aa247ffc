"""Wide streets (issue 45): every sign spot moved sideways as a whole, so its signs stand far from the track.

The street's cross-section stays as it is; a spot (panels, plates, poles, gantry, occluder) is laid out as on any
street and then shifted along the street's right vector until its first sign faces the vehicle from the drawn
lateral distance. Signs beyond the sidewalk stand on an open verge: the façades are set back behind the farthest
(``FACADE_BEHIND_M``). A sign 15-25 m to the side stands in for one across a junction; there is no junction
geometry (no cross street, no corner), so only the distances and viewing angles are a junction's.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .panels import PlacedSign
from .scene_pieces import LANE_CENTRE, Pieces

FACADE_BEHIND_M = 3.0  # façades set back this much beyond the farthest lateral distance of a wide street's signs


def lateral(pieces: Pieces, s: float, point) -> float:
    """Metres to the right of the street's centreline of ``point`` (a world point near ``s``)."""
    st = pieces.street
    return float(np.dot(np.asarray(point, float)[:2] - st.point(s)[:2], st.right(s)[:2]))


def move_aside(pieces: Pieces, placed: list[PlacedSign], first_surface: int, s: float, distance_m: float) -> None:
    """Shift the signs ``placed`` at ``s`` and every surface laid out since ``first_surface`` sideways, on the side
    they stand, so that the first sign facing the vehicle (else the first panel) is ``distance_m`` from the track."""
    if not placed:
        return
    anchor = next((p for p in placed if p.truth is not None), placed[0])
    l_now = lateral(pieces, s, anchor.centre)
    side = 1.0 if l_now >= LANE_CENTRE else -1.0
    shift = pieces.street.right(s) * (LANE_CENTRE + side * distance_m - l_now)
    moved = {}
    for k in range(first_surface, len(pieces.surfaces)):
        old = pieces.surfaces[k]
        pieces.surfaces[k] = moved[id(old)] = replace(old, origin=old.origin + shift)
    for p in placed:
        p.centre = p.centre + shift
        p.surfaces = [moved.get(id(sf), sf) for sf in p.surfaces]
        if p.truth is not None:
            p.truth = replace(p.truth, easting=p.truth.easting + float(shift[0]),
                              northing=p.truth.northing + float(shift[1]))
