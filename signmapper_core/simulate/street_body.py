"""The street itself: road, parking bays, sidewalks and verges, façades with hedges and trees, lamp posts."""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from . import textures as tx
from .scene_pieces import (
    CARRIAGEWAY,
    FACADE_PX_M,
    GROUND_PX_M,
    KERB_H,
    PARKING_LEFT,
    PIECE_M,
    ROAD_PX_M,
    SIDEWALK_LEFT,
    SIDEWALK_RIGHT,
    UP,
    Pieces,
    TextureKeys,
    fit_texture,
)
from .surfaces import Texture, TextureSource, triangle_surface


@dataclass(frozen=True)
class FacadeSpan:
    """Where a façade stands along the street: shop signs and emblems are hung on it."""

    s0: float
    s1: float
    l_f: float  # lateral position of its front
    side: int  # +1 right of the street, -1 left
    bottom: float
    height: float


def road(pieces: Pieces, s_end: float, zebras: list[float], shadows: bool) -> None:
    """Carriageway (with crossings at ``zebras`` and, with ``shadows``, cast shadows), parking bays,
    sidewalks, verges and kerbs, in pieces of ``PIECE_M`` up to ``s_end``."""
    st, keys = pieces.street, pieces.keys
    for s0 in np.arange(0.0, s_end, PIECE_M):
        s1 = s0 + PIECE_M
        pieces.strip(s0, s1, *CARRIAGEWAY, 0.0, _carriageway_texture(keys, s0, s1, zebras, shadows))
        pieces.strip(s0, s1, *PARKING_LEFT, 0.0, _parking_texture(keys, s0, s1))
        for l0, l1 in (SIDEWALK_RIGHT, SIDEWALK_LEFT):
            pieces.strip(s0, s1, l0, l1, KERB_H, _paving_texture(keys, s0, s1, l1 - l0))
        for l0, l1 in ((SIDEWALK_RIGHT[1], SIDEWALK_RIGHT[1] + 14), (SIDEWALK_LEFT[0] - 14, SIDEWALK_LEFT[0])):
            pieces.strip(s0, s1, l0, l1, KERB_H, _verge_texture(keys, l1 - l0))
        # kerb faces, following the slope (two triangles each)
        for l_kerb in (SIDEWALK_RIGHT[0], PARKING_LEFT[0]):
            a, b = st.point(s0, l_kerb), st.point(s1, l_kerb)
            a_up, b_up = a + UP * KERB_H, b + UP * KERB_H
            tc = [(0, 0), (1, 0), (0, 1)]
            for tri in ((a, b, a_up), (b, b_up, a_up)):
                pieces.surfaces.append(triangle_surface(tri, tc, None, (150, 152, 150), True, (s0 - 1, s1 + 1)))


def _carriageway_texture(keys: TextureKeys, s0, s1, zebras, shadows: bool) -> TextureSource:
    key, rng = keys.key("road")
    w = int(round((CARRIAGEWAY[1] - CARRIAGEWAY[0]) / ROAD_PX_M))
    h = int(round((s1 - s0) / ROAD_PX_M))

    shaded = shadows and keys.rng(1, 20, int(s0 * 10)).random() < 0.15

    def make():
        img = tx.asphalt(rng, h, w, ROAD_PX_M)
        shade = None
        if shaded:  # a building's shadow: straight slanted edge reaching in from one side
            side = 1.0 if rng.random() < 0.5 else -1.0
            reach = rng.uniform(-2.5, 2.5)
            slope = rng.uniform(-0.8, 0.8)
            yy, xx = np.mgrid[0:h, 0:w].astype(np.float32) * ROAD_PX_M
            edge = side * (xx + CARRIAGEWAY[0]) - reach - slope * (yy - h * ROAD_PX_M / 2)
            edge += 0.15 * tx.smooth_noise(rng, h, w, 0.4 / ROAD_PX_M)
            shade = np.where(edge > 0, 0.68, 1.0).astype(np.float32)
            shade = cv2.GaussianBlur(shade, (0, 0), 0.05 / ROAD_PX_M)
        rows_s = s0 + (np.arange(h) + 0.5) * ROAD_PX_M
        cols_l = CARRIAGEWAY[0] + (np.arange(w) + 0.5) * ROAD_PX_M
        paint = np.zeros((h, w), bool)
        dash = (rows_s % 9.0) < 3.0  # centre line: 3 m dash, 6 m gap
        paint |= dash[:, None] & (np.abs(cols_l) < 0.06)[None, :]
        edge = np.abs(np.abs(cols_l) - (CARRIAGEWAY[1] - 0.3)) < 0.075
        paint |= edge[None, :] & np.ones((h, 1), bool)
        img[paint] = (0.85 * img[paint] + 0.15 * 90 + [150, 150, 150]).clip(0, 255).astype(np.uint8)
        for z in zebras:  # Swiss pedestrian crossings are yellow: a colour distractor
            stripes = (np.abs(rows_s - z) < 2.0)[:, None] & ((np.floor((cols_l + 10) / 0.5) % 2) == 0)[None, :]
            img[stripes] = (0.35 * img[stripes] + np.array([20, 175, 215]) * 0.65).astype(np.uint8)
        if shade is not None:  # soft cast shadows of trees and buildings across the road
            img[:] = (img * shade[..., None]).astype(np.uint8)
        return Texture(img)

    return TextureSource(key, w, h, make)


def _parking_texture(keys: TextureKeys, s0, s1) -> TextureSource:
    key, rng = keys.key("parking")
    w = int(round((PARKING_LEFT[1] - PARKING_LEFT[0]) / ROAD_PX_M))
    h = int(round((s1 - s0) / ROAD_PX_M))

    def make():
        img = tx.asphalt(rng, h, w, ROAD_PX_M, base=(95, 97, 98))
        rows_s = s0 + (np.arange(h) + 0.5) * ROAD_PX_M
        blue = np.array([150, 80, 30])  # Swiss "blue zone" parking bays
        bay_line = (np.abs(((rows_s + 3.0) % 6.0) - 3.0) > 2.95)
        img[bay_line, :] = blue
        img[:, :int(0.1 / ROAD_PX_M)] = blue
        img[:, -int(0.1 / ROAD_PX_M):] = blue
        return Texture(img)

    return TextureSource(key, w, h, make)


def _paving_texture(keys: TextureKeys, s0, s1, width) -> TextureSource:
    key, rng = keys.key("paving")
    w = int(round(width / GROUND_PX_M))
    h = int(round((s1 - s0) / GROUND_PX_M))
    return TextureSource(key, w, h, lambda: Texture(tx.paving(rng, h, w, GROUND_PX_M)))


def _verge_texture(keys: TextureKeys, width) -> TextureSource:
    key, rng = keys.key("verge")
    w = int(round(width / 0.06))
    h = int(round(PIECE_M / 0.06))

    def make():
        grass = tx.tint((60, 120, 85), tx.grain(rng, h, w, ((1.0, 0.5), (5.0, 0.5), (30.0, 0.6))), 25.0)
        return Texture(grass)

    return TextureSource(key, w, h, make)


def buildings(pieces: Pieces, s_end: float, setback_m: float = 0.0) -> list[FacadeSpan]:
    """Façades on both sides, with side walls, and trees in the gaps; the façades' spans. ``setback_m``: façades
    and trees that much farther from the street (a wide street's open verge)."""
    spans = []
    for side in (1, -1):
        rng = pieces.keys.rng(1, 10, side + 2)
        s = rng.uniform(-10, 0)
        while s < s_end:
            width = rng.uniform(8, 24)
            if rng.random() < 0.2:
                gap = rng.uniform(4, 10)
                l_tree = SIDEWALK_RIGHT[1] + rng.uniform(2, 6) if side > 0 else SIDEWALK_LEFT[0] - rng.uniform(2, 6)
                l_tree += side * setback_m
                tree(pieces, s + gap / 2, l_tree, rng)
                s += gap
            setback = rng.uniform(0.0, 4.0)
            l_f = SIDEWALK_RIGHT[1] + setback if side > 0 else SIDEWALK_LEFT[0] - setback
            l_f += side * setback_m
            spans.append(facade(pieces, s, s + width, l_f, rng.uniform(8, 18), side, rng))
            if setback > 2.0 and rng.random() < 0.6:
                hedge(pieces, s + 0.5, s + width - 0.5, l_f - side * (setback - 0.6))
            s += width + rng.uniform(0.0, 0.5)
    return spans


def facade(pieces: Pieces, s0, s1, l_f, height, side, rng) -> FacadeSpan:
    """A building front from s0 to s1 with side walls going back from the street (``rng``: their colour)."""
    st = pieces.street
    a, b = st.point(s0, l_f, KERB_H - 0.3), st.point(s1, l_f, KERB_H - 0.3)
    bottom = min(a[2], b[2])
    width = float(np.hypot(*(b - a)[:2]))
    key, trng = pieces.keys.key("facade")
    wpx, hpx = max(8, int(width / FACADE_PX_M)), max(8, int(height / FACADE_PX_M))

    def make():
        return fit_texture(Texture(tx.facade(trng, width, height, FACADE_PX_M)), wpx, hpx)

    tex = TextureSource(key, wpx, hpx, make)
    left, right = (b, a) if side > 0 else (a, b)
    pieces.wall(left, right, bottom, bottom + height, tex, s_range=(s0 - 1, s1 + 1), two_sided=False)
    # side walls going back from the street, so gaps show depth and not paper
    depth = 10.0
    for p, s in ((a, s0), (b, s1)):
        back = p + st.right(s) * side * depth
        front_first = (p, back) if (s == s0) == (side > 0) else (back, p)
        pieces.wall(front_first[0], front_first[1], bottom, bottom + height, None,
                    tuple(int(c) for c in np.array(tx.FACADE_COLOURS[int(rng.integers(8))]) * 0.8),
                    (s - 1, s + 1), two_sided=True)
    return FacadeSpan(s0, s1, l_f, side, bottom, height)


def hedge(pieces: Pieces, s0, s1, lat) -> None:
    key, trng = pieces.keys.key("hedge")
    length = s1 - s0
    w, h = max(8, int(length / 0.04)), int(1.2 / 0.04)
    tex = TextureSource(key, w, h, lambda: _middle_band(tx.foliage(trng, h * 3, w, dark=True), h))
    a, b = pieces.street.point(s0, lat, KERB_H), pieces.street.point(s1, lat, KERB_H)
    pieces.wall(a, b, min(a[2], b[2]) - 0.3, max(a[2], b[2]) + 1.2, tex, s_range=(s0 - 1, s1 + 1))


def _middle_band(tex: Texture, h: int) -> Texture:
    """Hedge: the middle band of a foliage texture, fully opaque."""
    top = (tex.bgr.shape[0] - h) // 2
    return Texture(np.ascontiguousarray(tex.bgr[top:top + h]))


def tree(pieces: Pieces, s, lat, rng) -> None:
    base = pieces.street.point(s, lat, KERB_H)
    crown_r = rng.uniform(1.5, 3.0)
    trunk_h = rng.uniform(2.5, 4.0)
    key, trng = pieces.keys.key("bark")
    tw, th = 8, int(trunk_h / 0.04)
    bark = TextureSource(key, tw, th, lambda: Texture(tx.bark(trng, th, tw)))
    pieces.crossed(base, 0.3, trunk_h, bark, bark, s)
    ka, ra = pieces.keys.key("crown")
    kb, rb = pieces.keys.key("crown")
    n = int(2 * crown_r / 0.05)
    ta = TextureSource(ka, n, n, lambda: tx.foliage(ra, n, n))
    tb = TextureSource(kb, n, n, lambda: tx.foliage(rb, n, n))
    pieces.crossed(base + UP * (trunk_h - 0.8 * crown_r), 2 * crown_r, 2 * crown_r, ta, tb, s)


def lamp_post(pieces: Pieces, s, lat) -> None:
    base = pieces.street.point(s, lat, KERB_H)
    pieces.crossed(base, 0.12, 7.0, None, None, s, colour=(105, 110, 110))
