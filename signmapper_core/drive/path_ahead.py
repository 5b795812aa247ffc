"""How far each pair's camera still moves towards what it sees: to the drive's end, or to where the vehicle turns.

A face straight ahead at depth Z comes to about Z - d after the camera has moved d along its optical axis. Where the
drive ends, or the vehicle turns away (a junction), before that brings the face within the far limit, the face is
never seen closer, and its views beyond the far limit are the best the drive holds (``pipeline/search_range.py``).
"""

from __future__ import annotations

import dataclasses

import numpy as np


def optical_axes(poses) -> np.ndarray:
    """Unit horizontal directions (N, 2) of the cameras' optical axes (east, north); (0, 0) for a camera looking
    straight up or down."""
    axes = np.array([p.rotation[:2, 2] for p in poses], dtype=float).reshape(-1, 2)
    norms = np.linalg.norm(axes, axis=1, keepdims=True)
    return np.divide(axes, norms, out=np.zeros_like(axes), where=norms > 0)


def path_ahead(poses, turn_deg: float, limit_m: float) -> np.ndarray:
    """Per pose, the largest distance [m] the camera moves along its own optical axis (horizontally) in the poses
    after it, before one of them looks more than ``turn_deg`` away from it; at most ``limit_m`` (the search stops
    there: only whether the path ahead is shorter than that matters)."""
    centres = np.array([p.centre[:2] for p in poses], dtype=float).reshape(-1, 2)
    axes = optical_axes(poses)
    steps = np.linalg.norm(np.diff(centres, axis=0), axis=1)
    travelled = np.concatenate([[0.0], np.cumsum(steps)])
    cos_turn = np.cos(np.radians(turn_deg))
    count = len(centres)
    ahead = np.zeros(count)
    for i in range(count):
        # up to the first pose more than limit_m of path on: the camera cannot have moved farther along its axis
        end = min(count, int(np.searchsorted(travelled, travelled[i] + limit_m, side="right")) + 1)
        turned = np.flatnonzero(axes[i + 1:end] @ axes[i] < cos_turn)
        if turned.size:
            stop = i + 1 + int(turned[0])
        elif end < count:  # straight on beyond the limit
            ahead[i] = limit_m
            continue
        else:
            stop = count  # the drive ends
        moved = (centres[i + 1:stop] - centres[i]) @ axes[i]
        ahead[i] = min(limit_m, max(0.0, float(moved.max(initial=0.0))))
    return ahead


def with_path_ahead(drive, turn_deg: float, limit_m: float):
    """``drive`` with each pair's ``ahead_m`` (:func:`path_ahead`)."""
    ahead = path_ahead([record.pose for record in drive.pairs], turn_deg, limit_m)
    pairs = [dataclasses.replace(record, ahead_m=float(a)) for record, a in zip(drive.pairs, ahead)]
    return dataclasses.replace(drive, pairs=pairs)
