"""Scene layout: which objects stand where along the street, as planar surfaces.

Geometry is decided up front (small); pixels are made lazily per object with
its own seed. Signs are only placed where the drive passes them, so each sign is
seen from several pairs between 14 m and 4 m; signs whose face is turned away
from the vehicle are distractors (grey backs) and are not in the truth.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import cv2
import numpy as np

from ..drive import TruthSign
from . import textures as tx
from .faces import SIGN_COLOURS, FaceOptions, SignKind, draw_sign_face, pick_format
from .street import Street
from .surfaces import Surface, Texture, TextureSource, rect_surface, triangle_surface

ROAD_PX_M = 0.015
GROUND_PX_M = 0.03
FACADE_PX_M = 0.04
PIECE_M = 6.0
BIN_M = 10.0
UP = np.array([0.0, 0.0, 1.0])

# Cross-section (l right of the centreline, metres).
CARRIAGEWAY = (-3.3, 3.3)
PARKING_LEFT = (-5.3, -3.3)
SIDEWALK_RIGHT = (3.3, 6.3)
SIDEWALK_LEFT = (-7.8, -5.3)
KERB_H = 0.12
CAR_COLOURS = {"red": (35, 35, 190), "blue": (150, 70, 25), "yellow": (25, 185, 230), "white": (225, 225, 225),
               "black": (30, 30, 32), "grey": (120, 120, 118), "silver": (175, 175, 170), "green": (60, 90, 40)}


@dataclass
class PlacedSign:
    """A sign panel as laid out: truth row when its face looks towards the vehicle."""

    truth: TruthSign | None
    colour: str
    centre: np.ndarray
    surfaces: list[Surface] = field(default_factory=list)


class Scene:
    """Surfaces binned along the street so a view only looks at what is near it."""

    def __init__(self, street: Street, surfaces: list[Surface], signs: list[PlacedSign]):
        self.street = street
        self.signs = signs
        self._bins: dict[int, list[Surface]] = {}
        for surf in surfaces:
            for b in range(int(np.floor(surf.s_min / BIN_M)), int(np.floor(surf.s_max / BIN_M)) + 1):
                self._bins.setdefault(b, []).append(surf)

    def surfaces_between(self, s0: float, s1: float) -> list[Surface]:
        seen: set[int] = set()
        out = []
        for b in range(int(np.floor(s0 / BIN_M)), int(np.floor(s1 / BIN_M)) + 1):
            for surf in self._bins.get(b, ()):
                if id(surf) not in seen:
                    seen.add(id(surf))
                    out.append(surf)
        return out

    @property
    def truth(self) -> list[TruthSign]:
        return [p.truth for p in self.signs if p.truth is not None]


class _Builder:
    def __init__(self, street: Street, seed: int, fx: float, realism: dict, face_options: FaceOptions):
        self.street = street
        self.face_options = face_options
        self.seed = seed
        self.fx = fx
        self.realism = realism
        self.surfaces: list[Surface] = []
        self.signs: list[PlacedSign] = []
        self._n = 0

    def rng(self, *tags) -> np.random.Generator:
        return np.random.default_rng([self.seed, *tags])

    def key(self, kind: str) -> tuple[str, np.random.Generator]:
        self._n += 1
        return f"{kind}:{self._n}", self.rng(2, self._n)

    # --- generic pieces -------------------------------------------------------------------

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

    # --- street body ----------------------------------------------------------------------

    def road(self, s_end: float, zebras: list[float]):
        st = self.street
        for s0 in np.arange(0.0, s_end, PIECE_M):
            s1 = s0 + PIECE_M
            self.strip(s0, s1, *CARRIAGEWAY, 0.0, self._carriageway_tex(s0, s1, zebras))
            self.strip(s0, s1, *PARKING_LEFT, 0.0, self._parking_tex(s0, s1))
            for l0, l1 in (SIDEWALK_RIGHT, SIDEWALK_LEFT):
                self.strip(s0, s1, l0, l1, KERB_H, self._paving_tex(s0, s1, l1 - l0))
            for l0, l1 in ((SIDEWALK_RIGHT[1], SIDEWALK_RIGHT[1] + 14), (SIDEWALK_LEFT[0] - 14, SIDEWALK_LEFT[0])):
                self.strip(s0, s1, l0, l1, KERB_H, self._verge_tex(l1 - l0))
            # kerb faces, following the slope (two triangles each)
            for l_kerb in (SIDEWALK_RIGHT[0], PARKING_LEFT[0]):
                a, b = st.point(s0, l_kerb), st.point(s1, l_kerb)
                a_up, b_up = a + UP * KERB_H, b + UP * KERB_H
                tc = [(0, 0), (1, 0), (0, 1)]
                for tri in ((a, b, a_up), (b, b_up, a_up)):
                    self.surfaces.append(triangle_surface(tri, tc, None, (150, 152, 150), True, (s0 - 1, s1 + 1)))

    def _carriageway_tex(self, s0, s1, zebras):
        key, rng = self.key("road")
        w = int(round((CARRIAGEWAY[1] - CARRIAGEWAY[0]) / ROAD_PX_M))
        h = int(round((s1 - s0) / ROAD_PX_M))

        shaded = self.realism["shadows"] and self.rng(1, 20, int(s0 * 10)).random() < 0.15

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

    def _parking_tex(self, s0, s1):
        key, rng = self.key("parking")
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

    def _paving_tex(self, s0, s1, width):
        key, rng = self.key("paving")
        w = int(round(width / GROUND_PX_M))
        h = int(round((s1 - s0) / GROUND_PX_M))
        return TextureSource(key, w, h, lambda: Texture(tx.paving(rng, h, w, GROUND_PX_M)))

    def _verge_tex(self, width):
        key, rng = self.key("verge")
        w = int(round(width / 0.06))
        h = int(round(PIECE_M / 0.06))

        def make():
            grass = tx.tint((60, 120, 85), tx.grain(rng, h, w, ((1.0, 0.5), (5.0, 0.5), (30.0, 0.6))), 25.0)
            return Texture(grass)

        return TextureSource(key, w, h, make)

    def buildings(self, s_end: float):
        """Façades on both sides, with side walls, and trees in the gaps."""
        for side in (1, -1):
            rng = self.rng(1, 10, side + 2)
            s = rng.uniform(-10, 0)
            while s < s_end:
                width = rng.uniform(8, 24)
                if rng.random() < 0.2:
                    gap = rng.uniform(4, 10)
                    l_tree = SIDEWALK_RIGHT[1] + rng.uniform(2, 6) if side > 0 else SIDEWALK_LEFT[0] - rng.uniform(2, 6)
                    self.tree(s + gap / 2, l_tree, rng)
                    s += gap
                setback = rng.uniform(0.0, 4.0)
                l_f = SIDEWALK_RIGHT[1] + setback if side > 0 else SIDEWALK_LEFT[0] - setback
                self.facade(s, s + width, l_f, rng.uniform(8, 18), side, rng)
                if setback > 2.0 and rng.random() < 0.6:
                    self.hedge(s + 0.5, s + width - 0.5, l_f - side * (setback - 0.6), rng)
                s += width + rng.uniform(0.0, 0.5)

    def facade(self, s0, s1, l_f, height, side, rng):
        st = self.street
        a, b = st.point(s0, l_f, KERB_H - 0.3), st.point(s1, l_f, KERB_H - 0.3)
        bottom = min(a[2], b[2])
        width = float(np.hypot(*(b - a)[:2]))
        key, trng = self.key("facade")
        wpx, hpx = max(8, int(width / FACADE_PX_M)), max(8, int(height / FACADE_PX_M))

        def make():
            return _fit(Texture(tx.facade(trng, width, height, FACADE_PX_M)), wpx, hpx)

        tex = TextureSource(key, wpx, hpx, make)
        left, right = (b, a) if side > 0 else (a, b)
        self.wall(left, right, bottom, bottom + height, tex, s_range=(s0 - 1, s1 + 1), two_sided=False)
        # side walls going back from the street, so gaps show depth and not paper
        depth = 10.0
        for p, s in ((a, s0), (b, s1)):
            back = p + self.street.right(s) * side * depth
            front_first = (p, back) if (s == s0) == (side > 0) else (back, p)
            self.wall(front_first[0], front_first[1], bottom, bottom + height, None,
                      tuple(int(c) for c in np.array(tx.FACADE_COLOURS[int(rng.integers(8))]) * 0.8),
                      (s - 1, s + 1), two_sided=True)
        self._facade_spans.append((s0, s1, l_f, side, bottom, height))

    def hedge(self, s0, s1, lat, rng):
        key, trng = self.key("hedge")
        length = s1 - s0
        w, h = max(8, int(length / 0.04)), int(1.2 / 0.04)
        tex = TextureSource(key, w, h, lambda: _opaque(tx.foliage(trng, h * 3, w, dark=True), h))
        a, b = self.street.point(s0, lat, KERB_H), self.street.point(s1, lat, KERB_H)
        self.wall(a, b, min(a[2], b[2]) - 0.3, max(a[2], b[2]) + 1.2, tex, s_range=(s0 - 1, s1 + 1))

    def tree(self, s, lat, rng):
        base = self.street.point(s, lat, KERB_H)
        crown_r = rng.uniform(1.5, 3.0)
        trunk_h = rng.uniform(2.5, 4.0)
        key, trng = self.key("bark")
        tw, th = 8, int(trunk_h / 0.04)
        bark = TextureSource(key, tw, th, lambda: Texture(tx.bark(trng, th, tw)))
        self.crossed(base, 0.3, trunk_h, bark, bark, s)
        ka, ra = self.key("crown")
        kb, rb = self.key("crown")
        n = int(2 * crown_r / 0.05)
        ta = TextureSource(ka, n, n, lambda: tx.foliage(ra, n, n))
        tb = TextureSource(kb, n, n, lambda: tx.foliage(rb, n, n))
        self.crossed(base + UP * (trunk_h - 0.8 * crown_r), 2 * crown_r, 2 * crown_r, ta, tb, s)

    def lamp_post(self, s, lat):
        base = self.street.point(s, lat, KERB_H)
        self.crossed(base, 0.12, 7.0, None, None, s, colour=(105, 110, 110))

    # --- signs ----------------------------------------------------------------------------

    def sign_panel(self, kind: SignKind, centre, facing_deg, tilt_deg, fmt, s, towards_vehicle: bool):
        """Face and grey back of one panel; returns the PlacedSign (truth if it faces the vehicle)."""
        _name, w_m, h_m = fmt
        phi, tau = np.radians(facing_deg), np.radians(tilt_deg)
        n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
        normal = n_h * np.cos(tau) + UP * np.sin(tau)
        right = np.array([-np.cos(phi), np.sin(phi), 0.0])
        up = UP * np.cos(tau) - n_h * np.sin(tau)
        size_px = int(np.clip(self.fx * max(w_m, h_m) / 3.0, 48, 640))
        fh, fw = _face_shape(size_px, w_m, h_m)
        key, rng = self.key("face")
        sign_face = draw_sign_face(kind.template_id, (fw, fh), float(w_m), rng, self.face_options,
                                   self.realism["weathering"], self.realism["shadows"])

        def make_face():
            return Texture(*sign_face.pixels())

        face_src = TextureSource(key, fw, fh, make_face)
        corner = centre - right * w_m / 2 + up * h_m / 2
        face = rect_surface(corner, right * w_m, -up * h_m, face_src, two_sided=False, s_range=(s - 2, s + 2))
        bkey, brng = self.key("back")

        def make_back():
            return Texture(*sign_face.back(brng))

        back_src = TextureSource(bkey, fw, fh, make_back)
        b_corner = centre - normal * 0.012 + right * w_m / 2 + up * h_m / 2
        back = rect_surface(b_corner, -right * w_m, -up * h_m, back_src, two_sided=False, s_range=(s - 2, s + 2))
        self.surfaces += [face, back]
        truth = None
        if towards_vehicle:
            truth = TruthSign("", kind.template_id, float(centre[0]), float(centre[1]), float(centre[2]),
                              float(w_m), float(h_m), float(facing_deg % 360.0))
        placed = PlacedSign(truth, kind.colour, centre, [face, back])
        self.signs.append(placed)
        return placed

    def sign_pole(self, s, kinds, rng, side, overhead=False, back_to_back=False, stacked=False, away=False):
        """A pole with one or two panels; right-side signs face approaching traffic."""
        st = self.street
        heading = np.degrees(st.heading(s))
        first = kinds[int(rng.integers(len(kinds)))]
        fmt = pick_format(first, rng)
        w_m, h_m = fmt[1], fmt[2]
        yaw = rng.uniform(-4, 4) + side * rng.uniform(0, 6)  # turned a little towards the road
        facing = heading + 180.0 - yaw if not away else heading + rng.uniform(-4, 4)
        tilt = rng.uniform(-3, 3)
        if overhead:
            l_c = CARRIAGEWAY[1] / 2 + rng.uniform(-0.6, 0.6)
            lower = rng.uniform(4.3, 4.7)
            centre = st.point(s, l_c, lower + h_m / 2)
            self.sign_panel(first, centre, facing, tilt, fmt, s, True)
            pole_l = SIDEWALK_RIGHT[0] + 0.5
            top = lower + h_m + 0.3
            self.crossed(st.point(s + 0.05, pole_l, KERB_H), 0.12, top - KERB_H + 0.1, None, None, s, (120, 125, 125))
            arm_a, arm_b = st.point(s + 0.05, l_c - w_m / 2 - 0.2, top), st.point(s + 0.05, pole_l, top)
            self.wall(arm_a, arm_b, top - 0.1, top, None, (120, 125, 125), (s - 2, s + 2))
            return
        edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
        offset = rng.uniform(0.3, 2.0)
        l_c = edge + side * (offset + w_m / 2)
        lower = rng.uniform(0.6, 2.5)
        ground = KERB_H
        centres = [(first, fmt, lower + h_m / 2)]
        if stacked:
            second = kinds[int(rng.integers(len(kinds)))]
            fmt2 = pick_format(second, rng)
            # about 0.7 m between the panel centres, never overlapping
            gap = max(0.7, (h_m + fmt2[2]) / 2 + 0.05)
            centres.append((second, fmt2, lower + h_m / 2 + gap))
        top = 0.0
        for kind, f, h_c in centres:
            centre = st.point(s, l_c, ground + h_c)
            self.sign_panel(kind, centre, facing, tilt + rng.uniform(-1, 1), f, s, not away)
            top = max(top, h_c + f[2] / 2)
        if back_to_back:
            other = kinds[int(rng.integers(len(kinds)))]
            f = pick_format(other, rng)
            n_h = np.array([np.sin(np.radians(facing)), np.cos(np.radians(facing)), 0.0])
            centre = st.point(s, l_c, ground + lower + h_m / 2) - n_h * 0.08
            self.sign_panel(other, centre, facing + 180.0, tilt, f, s, False)
        n_h = np.array([np.sin(np.radians(facing)), np.cos(np.radians(facing)), 0.0])
        pole_base = st.point(s, l_c, ground) - n_h * 0.04
        self.crossed(pole_base, 0.06, top + 0.1, None, None, s, (140, 145, 145))
        if self.realism["occlusion"] and rng.random() < 0.2:
            self.occluder(s, l_c, max(w_m, h_m), ground + lower + h_m / 2, rng)

    def occluder(self, s, l_sign, size_m, h_sign, rng):
        """A branch or a pole between the sign and the approaching vehicle, covering part of it.

        Placed next to the line of sight from about 9 m, offset so that it hides
        roughly a quarter to a half of the face rather than all of it.
        """
        d_before = rng.uniform(1.0, 2.5)
        l_cam = CARRIAGEWAY[1] / 2
        frac = d_before / 9.0  # where the line of sight from ~9 m crosses
        l_sight = l_sign + (l_cam - l_sign) * frac
        h_sight = h_sign + (2.4 - h_sign) * frac
        apparent = size_m * (1 - frac)  # the face's size where the occluder stands
        if rng.random() < 0.5:
            l_o = l_sight + rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 0.35) * apparent
            base = self.street.point(s - d_before, l_o, KERB_H)
            self.crossed(base, 0.1, h_sign + 2.0, None, None, s - d_before, (95, 100, 100))
        else:
            key, trng = self.key("branch")
            n = 64
            dark = bool(rng.random() < 0.5)
            size = rng.uniform(0.5, 0.8)
            src = TextureSource(key, n, n, lambda: tx.foliage(trng, n, n, dark=dark))
            ang = rng.uniform(0, 2 * np.pi)
            shift = (size / 2 + apparent / 2) * rng.uniform(0.55, 0.8)
            centre = self.street.point(s - d_before, l_sight + shift * np.cos(ang), h_sight + shift * np.sin(ang))
            self.crossed(centre - UP * size / 2, size, size, src, src, s - d_before)

    # --- distractors ----------------------------------------------------------------------

    def car(self, s, lat, colour_bgr, rng):
        st = self.street
        length, width, height = rng.uniform(3.9, 4.8), rng.uniform(1.7, 1.85), rng.uniform(1.35, 1.55)
        f, r = st.forward(s), st.right(s)
        c = st.point(s, lat, 0.0)
        body = np.array(colour_bgr, float)
        keys = [self.key("car") for _ in range(4)]
        low = 0.6 * height
        # sides (one-sided, facing out), seen with their rounded cabin outline
        for sgn, (key, trng) in zip((1, -1), keys[:2]):
            wpx, hpx = int(length / 0.03), int(height / 0.03)
            src = TextureSource(key, wpx, hpx, lambda trng=trng, wpx=wpx, hpx=hpx: _fit(
                tx.car_side(trng, length, height, 0.03, body), wpx, hpx))
            p_back, p_front = c - f * length / 2 + r * sgn * width / 2, c + f * length / 2 + r * sgn * width / 2
            left, right = (p_back, p_front) if sgn > 0 else (p_front, p_back)
            self.wall(left, right, c[2] + 0.1, c[2] + 0.1 + height, src, s_range=(s - 3, s + 3), two_sided=False)
        for sgn, (key, trng), front in zip((1, -1), keys[2:], (True, False)):
            wpx, hpx = int(width / 0.03), int(low / 0.03)
            src = TextureSource(key, wpx, hpx, lambda trng=trng, front=front, wpx=wpx, hpx=hpx: _fit(tx.car_end(
                trng, width, low, 0.03, body, front), wpx, hpx))
            p_l, p_r = c + f * sgn * length / 2 + r * sgn * width / 2, c + f * sgn * length / 2 - r * sgn * width / 2
            self.wall(p_l, p_r, c[2] + 0.1, c[2] + 0.1 + low, src, s_range=(s - 3, s + 3), two_sided=False)
        top = c + UP * (0.1 + height)
        roof_c = top - f * 0.3 * length - r * width / 2
        self.surfaces.append(rect_surface(roof_c + f * 0.6 * length, r * width, -f * 0.6 * length, None,
                                          tuple(int(v) for v in body * 0.9), True, (s - 3, s + 3)))
        glass = (50, 42, 38)
        for sgn in (1, -1):
            top_edge = c + UP * (0.1 + height) + f * sgn * 0.3 * length
            low_edge = c + UP * (0.1 + low) + f * sgn * 0.5 * length
            corner = top_edge - r * width / 2 * sgn
            self.surfaces.append(rect_surface(corner, r * width * sgn, low_edge - top_edge, None, glass, True,
                                              (s - 3, s + 3)))

    def distractors(self, s_lo, s_hi, density, rng, sign_spots):
        """Colour distractors spread along the drive: cars, cones, shop signs, patches, sign backs."""
        n = rng.poisson(density * (s_hi - s_lo) / 100.0)
        kinds = ["car", "car", "oncoming", "cones", "shop", "patch", "logo", "back"]
        spots = np.sort(rng.uniform(s_lo, s_hi, n))
        for s in spots:
            what = kinds[int(rng.integers(len(kinds)))]
            colour = SIGN_COLOURS[int(rng.integers(3))]
            if what in ("car", "oncoming"):
                if rng.random() < 0.4:
                    colour = ["white", "black", "grey", "silver", "green"][int(rng.integers(5))]
                lat = (PARKING_LEFT[0] + PARKING_LEFT[1]) / 2 if what == "car" else -CARRIAGEWAY[1] / 2
                self.car(s, lat, CAR_COLOURS[colour], rng)
            elif what == "cones":
                for k in range(int(rng.integers(2, 5))):
                    base = self.street.point(s + 1.2 * k, CARRIAGEWAY[1] - 0.35, 0.0)
                    key, trng = self.key("cone")
                    src = TextureSource(key, 30, 50, lambda trng=trng: tx.cone(trng, 50))
                    self.crossed(base, 0.45, 0.75, src, src, s + 1.2 * k)
            elif what in ("shop", "patch", "logo"):
                self.facade_distractor(s, colour, what, rng)
            elif all(abs(s - x) > 3 for x in sign_spots):
                self.sign_pole(s, self.kinds_of(colour), rng, side=-1, away=True)

    def kinds_of(self, colour):
        sel = [k for k in self.all_kinds if k.colour == colour]
        return sel or self.all_kinds

    def facade_distractor(self, s, colour, what, rng):
        span = next((f for f in self._facade_spans if f[0] + 1 < s < f[1] - 3), None)
        if span is None:
            return
        s0, _s1, l_f, side, bottom, _h = span
        if what == "logo":  # sign-like emblem of a shop, in sign colours and shapes, any size
            length = height = rng.uniform(0.25, 1.1)
            lift = rng.uniform(1.8, 3.4)
        else:
            length = rng.uniform(1.5, 3.0) if what == "shop" else rng.uniform(1.0, 2.5)
            height = rng.uniform(0.5, 0.9) if what == "shop" else rng.uniform(1.2, 2.5)
            lift = rng.uniform(2.6, 3.6) if what == "shop" else rng.uniform(0.0, 1.5)
        lat = l_f - side * 0.05
        a, b = self.street.point(s, lat), self.street.point(s + length, lat)
        left, right = (b, a) if side > 0 else (a, b)
        key, trng = self.key(what)
        w, h = int(length / 0.02), int(height / 0.02)
        if what == "logo":
            src = TextureSource(key, w, w, lambda: tx.emblem(trng, w, colour))
            h = w
        elif what == "shop":
            src = TextureSource(key, w, h, lambda: _fit(
                Texture(tx.shop_sign(trng, length, height, 0.02, colour)), w, h))
        else:
            src = TextureSource(key, w, h, lambda: Texture(tx.tint(
                tx.SIGNAL_COLOURS[colour], tx.grain(trng, h, w, ((1.0, 0.4), (8.0, 0.6))), 12.0)))
        self.wall(left, right, bottom + 0.3 + lift, bottom + 0.3 + lift + height, src, s_range=(s - 1, s + length + 1))


def _fit(tex: Texture, w: int, h: int) -> Texture:
    """Texture resized to exactly the declared pixel size (makers round metres to pixels their own way)."""
    if tex.bgr.shape[:2] == (h, w):
        return tex
    bgr = cv2.resize(tex.bgr, (w, h), interpolation=cv2.INTER_AREA)
    alpha = None if tex.alpha is None else cv2.resize(tex.alpha, (w, h), interpolation=cv2.INTER_AREA)
    return Texture(bgr, alpha)


def _opaque(tex: Texture, h: int) -> Texture:
    """Hedge: the middle band of a foliage texture, fully opaque."""
    top = (tex.bgr.shape[0] - h) // 2
    return Texture(np.ascontiguousarray(tex.bgr[top:top + h]))


def _face_shape(size_px: int, w_m: float, h_m: float) -> tuple[int, int]:
    """(height, width) in pixels of a face texture whose longer side is ``size_px``."""
    if w_m >= h_m:
        return max(1, int(round(size_px * h_m / w_m))), size_px
    return size_px, max(1, int(round(size_px * w_m / h_m)))


def build_scene(street: Street, seed: int, s_cam_first: float, s_cam_last: float, fx: float,
                sign_density: float, distractor_density: float, kinds: list[SignKind], realism: dict,
                face_options: FaceOptions | None = None) -> Scene:
    """Lay out the whole street: road, buildings, signs (where the drive passes them), distractors."""
    b = _Builder(street, seed, fx, realism, face_options or FaceOptions())
    b.all_kinds = kinds
    b._facade_spans = []
    rng = b.rng(1, 1)
    s_end = street.length
    # signs between 8 m ahead of the first pair and 12 m ahead of the last: each is seen within 4-14 m
    s_lo, s_hi = s_cam_first + 8.0, s_cam_last + 12.0
    spots: list[float] = []
    if s_hi > s_lo:
        n_poles = max(1, rng.poisson(sign_density * (s_hi - s_lo) / 100.0)) if sign_density > 0 else 0
        spots = sorted(rng.uniform(s_lo, s_hi, n_poles).tolist())
        # keep poles at least 4 m apart so panels do not overlap in the images
        kept: list[float] = []
        for s in spots:
            if not kept or s - kept[-1] >= 4.0:
                kept.append(s)
        spots = kept
    zebras = [float(s) for s in rng.uniform(s_cam_first + 10, s_end - 20, max(0, int((s_end - 30) // 150)))]
    b.road(s_end, zebras)
    b.buildings(s_end)
    for s in np.arange(rng.uniform(5, 25), s_end, rng.uniform(25, 35)):
        if all(abs(s - x) > 2 for x in spots):
            b.lamp_post(float(s), SIDEWALK_RIGHT[0] + 0.5)
    sign_rng = b.rng(1, 2)
    for s in spots:
        u = sign_rng.random()
        side = 1 if sign_rng.random() < 0.75 else -1
        if u < 0.08:
            b.sign_pole(s, kinds, sign_rng, 1, overhead=True)
        elif u < 0.30:
            b.sign_pole(s, kinds, sign_rng, side, stacked=True)
        elif u < 0.40:
            b.sign_pole(s, kinds, sign_rng, side, back_to_back=True)
        else:
            b.sign_pole(s, kinds, sign_rng, side)
    if distractor_density > 0:
        b.distractors(s_cam_first, s_end - 10, distractor_density, b.rng(1, 3), spots)
    signs = b.signs
    n = 0
    for p in signs:
        if p.truth is not None:
            n += 1
            t = p.truth
            p.truth = TruthSign(f"s{n:03d}", t.template_id, t.easting, t.northing, t.height, t.width_m, t.height_m,
                                t.facing)
    return Scene(street, b.surfaces, signs)
