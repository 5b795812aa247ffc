"""A trajectory interpolated to the image times: positions linearly, orientations along the shortest turn.

The rotation between two epochs is interpolated on its axis (``R0 exp(s log(R0^T R1))``,
``cv2.Rodrigues`` for exp/log), which is what a constant turn rate between two
INS epochs gives. An image outside the trajectory's time span, or between two
epochs further apart than ``max_gap_s``, is an error naming the image: its pose
would be a guess.
"""

from __future__ import annotations

import numpy as np

from ..errors import ImportInputError

MAX_GAP_S = 1.0


def check_increasing(times: np.ndarray, path, lines) -> None:
    """Trajectory epochs must be strictly increasing."""
    steps = np.diff(times)
    bad = np.flatnonzero(steps <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise ImportInputError(path, f"time {times[i]:.6f} is not after the previous row's {times[i - 1]:.6f}; "
                               "trajectory epochs must increase", line=int(lines[i]), field="time")


def slerp(r0: np.ndarray, r1: np.ndarray, s: float) -> np.ndarray:
    """Rotation a fraction ``s`` of the way from ``r0`` to ``r1`` (shortest turn)."""
    import cv2

    step, _ = cv2.Rodrigues(r0.T @ r1)
    turn, _ = cv2.Rodrigues(step * s)
    return r0 @ turn


def interpolate(times: np.ndarray, centres: np.ndarray, rotations: np.ndarray, query: np.ndarray,
                names: list[str], path, where: str, max_gap_s: float = MAX_GAP_S) -> tuple[np.ndarray, np.ndarray]:
    """Centres (m, 3) and rotations (m, 3, 3) at ``query`` times; ``names`` and ``where`` name the images."""
    times = np.asarray(times, float)
    query = np.asarray(query, float)
    first, last = times[0], times[-1]
    out_c = np.empty((len(query), 3))
    out_r = np.empty((len(query), 3, 3))
    for k, t in enumerate(query):
        if not first <= t <= last:
            raise ImportInputError(path, f"the poses do not cover image {names[k]!r} at time {t:.3f} s ({where}); "
                                   f"they span {first:.3f} to {last:.3f} s: same clock for images and poses?",
                                   field="time")
        if len(times) == 1:  # t equals the only epoch
            out_c[k], out_r[k] = centres[0], rotations[0]
            continue
        j = min(int(np.searchsorted(times, t, side="right")) - 1, len(times) - 2)
        gap = times[j + 1] - times[j]
        if gap > max_gap_s:
            raise ImportInputError(path, f"the poses have a gap of {gap:.2f} s around image {names[k]!r} at "
                                   f"{t:.3f} s ({where}); at most {max_gap_s:g} s between epochs is interpolated",
                                   field="time")
        s = (t - times[j]) / gap
        out_c[k] = centres[j] + s * (centres[j + 1] - centres[j])
        out_r[k] = slerp(rotations[j], rotations[j + 1], s)
    return out_c, out_r
