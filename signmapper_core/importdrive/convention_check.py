"""Were the angles read with the right convention? The forward direction they give against the direction of travel.

Read with the wrong convention (NED yaw/pitch/roll as ENU, or the reverse),
the poses still make a drive, with headings tens of degrees or half a turn
off, and mapping it finds signs behind the vehicle. The body's forward axis (a
vehicle's forward, a camera's optical axis) follows the track, so the median
miss over the track's legs (``travel``) tells. When it exceeds
``HEADING_OFF_DEG``, the other conventions whose angles the table's columns
hold are tried on the same numbers; the one that follows the track is named in
the error. When none does (a camera looking sideways or backwards, a vehicle
reversing all the way), it is a warning: nothing says which reading is right.
So is a vehicle that stands still or moves too little for a direction of travel.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from ..errors import ImportInputError
from .attitude import CONVENTIONS, Convention
from .pose_table import same_columns
from .travel import MIN_LEGS, MIN_STEP_M, Legs, heading_miss

HEADING_OFF_DEG = 15.0   # median miss of forward axis and direction of travel beyond which a reading is wrong


def check_convention(stated: Convention, legs: Legs, table, forward_headings: Callable[[Convention], np.ndarray],
                     note: Callable[[str], None]) -> None:
    """ImportInputError naming the likely convention when ``stated`` misses the direction of travel and another
    follows it; ``note`` a warning when nothing can be said (see module).

    ``legs`` are the track's legs of the table's rows; ``forward_headings(convention)`` gives the grid azimuth of
    the body's forward axis per row with the table's angles read in that convention.
    """
    if len(legs) < MIN_LEGS:
        moved = "stands still" if not len(legs) else (f"moves too little ({len(legs)} stretch(es) of "
                                                      f"{MIN_STEP_M:g} m, {MIN_LEGS} needed)")
        note(f"{table.path}: the angle convention ({stated.name}) could not be checked against the direction of "
             f"travel: the vehicle {moved}")
        return
    miss = heading_miss(legs, forward_headings(stated))
    if miss <= HEADING_OFF_DEG:
        return
    others = [c for c in CONVENTIONS.values() if c.name != stated.name and same_columns(c.angle_names,
                                                                                       stated.angle_names)]
    fits = sorted((c.camera_like != stated.camera_like, m, c.name) for c in others
                  if (m := heading_miss(legs, forward_headings(c))) <= HEADING_OFF_DEG)
    what = (f"the forward direction of the {stated.name} angles differs from the direction of travel by "
            f"{miss:.0f} degrees (median over {len(legs)} moving epochs)")
    if not fits:
        note(f"{table.path}: {what}, and no other angle convention follows the travel: is the camera looking "
             "sideways or backwards, is the vehicle reversing? Look at the poses (Drive trajectory) before mapping")
        return
    _, fit_miss, name = fits[0]
    path, line = table.where(int(legs.starts[0]))
    raise ImportInputError(path, f"{what}; the angles look like {name} ({CONVENTIONS[name].title}): read so, they "
                           f"follow it (median miss {fit_miss:.0f} degrees); set the angle convention to {name}",
                           line=line, field=stated.angle_names[0])
