"""The street's centreline as a function of arc length: gentle curves and slopes.

Everything in the scene is laid out in street coordinates (s along the
centreline, l to the right of it, h above the road), so this module is the only
place that knows how the street bends. Lateral cross-sections are level; the cross-section itself is in ``layout``.
"""

from __future__ import annotations

import numpy as np

STEP_M = 0.25  # tabulation step of the centreline
MARGIN_M = 60.0


class Street:
    """Tabulated centreline; ``frame(s)`` gives position, forward and right unit vectors."""

    def __init__(self, length_m: float, start: tuple[float, float, float], rng: np.random.Generator):
        self.length = float(length_m)
        # tabulated with margins so objects laid out a little beyond either end still have a place
        n = int(np.ceil((self.length + 2 * MARGIN_M) / STEP_M)) + 2
        s = np.arange(n) * STEP_M - MARGIN_M
        heading0 = rng.uniform(0.0, 2 * np.pi)
        # Curvature: sum of two slow sinusoids, radius never below ~180 m.
        k = np.zeros(n)
        for amp, wavelength in ((1 / 400.0, rng.uniform(180, 320)), (1 / 600.0, rng.uniform(90, 160))):
            k += amp * rng.uniform(0.6, 1.0) * np.sin(2 * np.pi * s / wavelength + rng.uniform(0, 2 * np.pi))
        heading = heading0 + np.concatenate([[0.0], np.cumsum(0.5 * (k[1:] + k[:-1]) * STEP_M)])
        grade = 0.035 * np.sin(2 * np.pi * s / rng.uniform(150, 300) + rng.uniform(0, 2 * np.pi))
        fwd = np.stack([np.sin(heading), np.cos(heading)], axis=1)  # azimuth clockwise from north
        mid = 0.5 * (fwd[1:] + fwd[:-1]) * STEP_M
        xy = np.concatenate([[[0.0, 0.0]], np.cumsum(mid, axis=0)])
        z = np.concatenate([[0.0], np.cumsum(0.5 * (grade[1:] + grade[:-1]) * STEP_M)])
        i0 = int(round(MARGIN_M / STEP_M))  # s = 0 sits at the start point
        xy -= xy[i0]
        z -= z[i0]
        self._s = s
        self._xy = xy + np.array(start[:2])
        self._z = z + start[2]
        self._heading = heading
        self._grade = grade

    def _interp(self, s, table):
        return np.interp(s, self._s, table)

    def heading(self, s) -> np.ndarray:
        """Azimuth of the driving direction, radians clockwise from north."""
        return self._interp(s, self._heading)

    def grade(self, s) -> np.ndarray:
        return self._interp(s, self._grade)

    def point(self, s, lat=0.0, h=0.0) -> np.ndarray:
        """World point(s) (..., 3) at street coordinates; broadcasting over s, l, h."""
        s, lat, h = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (s, lat, h)))
        x = self._interp(s, self._xy[:, 0])
        y = self._interp(s, self._xy[:, 1])
        z = self._interp(s, self._z)
        head = self.heading(s)
        # right = forward rotated 90 deg clockwise
        return np.stack([x + lat * np.cos(head), y - lat * np.sin(head), z + h], axis=-1)

    def forward(self, s) -> np.ndarray:
        head = self.heading(s)
        return np.stack([np.sin(head), np.cos(head), np.zeros_like(head)], axis=-1)

    def right(self, s) -> np.ndarray:
        head = self.heading(s)
        return np.stack([np.cos(head), -np.sin(head), np.zeros_like(head)], axis=-1)
