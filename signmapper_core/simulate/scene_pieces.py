"""What a street scene is laid out from: the cross-section, planar pieces along the street, and the
names and seeds of their textures.

Textures are numbered in the order the layout asks for them (:class:`TextureKeys`), so a scene is
the same for the same seed as long as the layout asks in the same order.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import cv2
import numpy as np

from .street import Street
from .surfaces import Surface, Texture, TextureSource, rect_surface, triangle_surface

ROAD_PX_M = 0.015
GROUND_PX_M = 0.03
FACADE_PX_M = 0.04
PIECE_M = 6.0
UP = np.array([0.0, 0.0, 1.0])

# Cross-section (l right of the centreline, metres).
CARRIAGEWAY = (-3.3, 3.3)
PARKING_LEFT = (-5.3, -3.3)
SIDEWALK_RIGHT = (3.3, 6.3)
SIDEWALK_LEFT = (-7.8, -5.3)
LANE_CENTRE = CARRIAGEWAY[1] / 2  # the vehicle's track: the middle of the right lane
KERB_H = 0.12


class TextureKeys:
    """Names and random generators of a scene's textures, from its seed."""

    def __init__(self, seed: int):
        self.seed = seed
        self._n = 0

    def rng(self, *tags) -> np.random.Generator:
        """A generator of the scene's seed and ``tags`` (the same tags, the same numbers)."""
        return np.random.default_rng([self.seed, *tags])

    def key(self, kind: str) -> tuple[str, np.random.Generator]:
        """The next texture's cache key and its own generator."""
        self._n += 1
        return f"{kind}:{self._n}", self.rng(2, self._n)


@dataclass
class Pieces:
    """The surfaces laid out along ``street`` so far, and the keys their textures are named by."""

    street: Street
    keys: TextureKeys
    surfaces: list[Surface] = field(default_factory=list)

    def strip(self, s0, s1, l0, l1, h, texture: TextureSource | None, colour=(128, 128, 128)):
        """Ground strip between s0..s1 and l0..l1 at height h, as two exact triangles."""
        st = self.street
        a, b = st.point(s0, l0, h), st.point(s0, l1, h)
        c, d = st.point(s1, l1, h), st.point(s1, l0, h)
        w, hh = (texture.width, texture.height) if texture else (1, 1)
        ta, tb, tc, td = (-0.5, -0.5), (w - 0.5, -0.5), (w - 0.5, hh - 0.5), (-0.5, hh - 0.5)
        rng_s = (s0 - 1.0, s1 + 1.0)
        self.surfaces.append(triangle_surface([a, b, d], [ta, tb, td], texture, colour, True, rng_s))
        self.surfaces.append(triangle_surface([b, c, d], [tb, tc, td], texture, colour, True, rng_s))

    def wall(self, p_left, p_right, bottom, top, texture: TextureSource | None, colour=(128, 128, 128),
             s_range=(0, 0), two_sided=True):
        """Vertical rectangle between two ground points seen from the front (left point on the left)."""
        corner = np.array([p_left[0], p_left[1], top])
        right = np.array([p_right[0] - p_left[0], p_right[1] - p_left[1], 0.0])
        down = np.array([0.0, 0.0, bottom - top])
        self.surfaces.append(rect_surface(corner, right, down, texture, colour, two_sided, s_range))

    def crossed(self, base, width, height, texture_a, texture_b, s, colour=(128, 128, 128)):
        """Two crossed vertical quads (poles, trees, cones): round things without a per-view billboard."""
        f = self.street.forward(s)
        r = self.street.right(s)
        for axis, tex in (((f + r) / np.sqrt(2)), texture_a), (((f - r) / np.sqrt(2)), texture_b):
            corner = base - axis * width / 2 + UP * height
            self.surfaces.append(rect_surface(corner, axis * width, -UP * height, tex, colour, True,
                                              (s - 2, s + 2)))


def fit_texture(tex: Texture, w: int, h: int) -> Texture:
    """Texture resized to exactly the declared pixel size (makers round metres to pixels their own way)."""
    if tex.bgr.shape[:2] == (h, w):
        return tex
    bgr = cv2.resize(tex.bgr, (w, h), interpolation=cv2.INTER_AREA)
    alpha = None if tex.alpha is None else cv2.resize(tex.alpha, (w, h), interpolation=cv2.INTER_AREA)
    return Texture(bgr, alpha)
