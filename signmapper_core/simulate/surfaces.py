"""Planar textured polygons in world coordinates: the only primitive the rasteriser knows.

A surface maps texture pixel coordinates (s, t) (pixel centres at integers) to
world points ``origin + s * axis_u + t * axis_v``; its outline is a convex
polygon in texture coordinates. Textures are made lazily by a
:class:`TextureSource` so a long street does not hold all its pixels at once.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import cv2
import numpy as np


@dataclass
class Texture:
    """BGR uint8 pixels, optional alpha, and a lazily built mip pyramid against aliasing."""

    bgr: np.ndarray
    alpha: np.ndarray | None = None
    _levels: list = field(default_factory=list, repr=False)

    def level(self, n: int) -> tuple[np.ndarray, np.ndarray | None]:
        """Pyramid level ``n`` (0 = full resolution), each level half the previous size."""
        if not self._levels:
            self._levels.append((self.bgr, self.alpha))
        while len(self._levels) <= n:
            bgr, alpha = self._levels[-1]
            if min(bgr.shape[:2]) < 4:
                break
            self._levels.append((cv2.pyrDown(bgr), None if alpha is None else cv2.pyrDown(alpha)))
        return self._levels[min(n, len(self._levels) - 1)]


@dataclass
class TextureSource:
    """Recipe for a texture of a known size; ``key`` identifies it in the renderer's cache."""

    key: str
    width: int
    height: int
    make: Callable[[], Texture]


@dataclass
class Surface:
    """One planar polygon of the scene.

    ``colour`` (BGR) is used when ``texture`` is None. One-sided surfaces are only
    seen from their front, the side ``axis_v x axis_u`` points to (the side from
    which the texture reads left-to-right, top-to-bottom).
    """

    origin: np.ndarray
    axis_u: np.ndarray
    axis_v: np.ndarray
    polygon: np.ndarray
    texture: TextureSource | None = None
    colour: tuple[int, int, int] = (128, 128, 128)
    two_sided: bool = True
    s_min: float = 0.0
    s_max: float = 0.0

    def __post_init__(self):
        n = np.cross(self.axis_v, self.axis_u)
        self.front_normal = n / np.linalg.norm(n)
        poly = np.asarray(self.polygon, float)
        if len(poly) not in (3, 4):
            raise ValueError("surfaces are triangles or quadrilaterals")
        quad = poly if len(poly) == 4 else np.vstack([poly, poly[-1:]])
        # one row for the rasteriser's vectorised culling: origin, u, v, normal, 4 polygon vertices
        self.packed = np.concatenate([self.origin, self.axis_u, self.axis_v, self.front_normal, quad.ravel(),
                                      [0.0 if self.two_sided else 1.0]])


def rect_surface(corner: np.ndarray, right: np.ndarray, down: np.ndarray, texture: TextureSource | None = None,
                 colour=(128, 128, 128), two_sided: bool = True, s_range=(0.0, 0.0)) -> Surface:
    """Rectangle (parallelogram) from its top-left corner and its full right and down edge vectors.

    The texture (if any) covers it exactly; its front is the side from which
    ``right`` points right and ``down`` points down.
    """
    w, h = (texture.width, texture.height) if texture is not None else (1, 1)
    axis_u = np.asarray(right, float) / w
    axis_v = np.asarray(down, float) / h
    origin = np.asarray(corner, float) + 0.5 * axis_u + 0.5 * axis_v
    poly = np.array([[-0.5, -0.5], [w - 0.5, -0.5], [w - 0.5, h - 0.5], [-0.5, h - 0.5]])
    return Surface(origin, axis_u, axis_v, poly, texture, tuple(int(c) for c in colour), two_sided,
                   float(s_range[0]), float(s_range[1]))


def triangle_surface(points: np.ndarray, tex_coords: np.ndarray, texture: TextureSource | None = None,
                     colour=(128, 128, 128), two_sided: bool = True, s_range=(0.0, 0.0)) -> Surface:
    """Triangle from three world points and their texture coordinates (exactly planar)."""
    points = np.asarray(points, float)
    st = np.asarray(tex_coords, float)
    a = np.column_stack([np.ones(3), st])
    origin, axis_u, axis_v = np.linalg.solve(a, points)
    return Surface(origin, axis_u, axis_v, st.copy(), texture, tuple(int(c) for c in colour), two_sided,
                   float(s_range[0]), float(s_range[1]))
