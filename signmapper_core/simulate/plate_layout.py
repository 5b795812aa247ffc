"""Supplementary plates under signs, and white distractors, in a synthetic street.

A plate hangs right below the lowest sign of some poles, as wide as the sign
(``plate_formats_for``), one or two lines high, with a text in German, French or
Italian: a distance, a time, weekdays, an exception. Its truth row names its sign
(``plate_of``) and its text, lines joined by " / ", exactly as the normalised
OCR output writes it. White distractors (house-number and notice plates on
façades, with text) are white rectangles no sign stands above. Plates and
distractors draw from random streams of their own, so the rest of the scene is
the same with or without them.
"""

from __future__ import annotations

import numpy as np

from ..drive import TruthSign
from ..plate_formats import PLATE_ID, plate_formats_for
from ..plate_text import EXCEPT_WORDS, WEEKDAYS
from .plate_faces import draw_plate
from .surfaces import Texture, TextureSource, rect_surface

UP = np.array([0.0, 0.0, 1.0])
LANGUAGE_SHARES = (("de", 0.6), ("fr", 0.25), ("it", 0.15))
DISTANCES_M = (20, 30, 50, 80, 100, 150, 200, 250, 300, 400, 500, 800)
EXCEPTIONS = {
    "de": ("Zubringerdienst", "Anwohner", "Velos", "Bus", "Taxi"),
    "fr": ("riverains", "livraisons", "cycles", "bus", "taxi"),
    "it": ("confinanti", "biciclette", "bus", "taxi"),
}
STREETS = ("Bahnhofstrasse", "Hauptstrasse", "Rue du Lac", "Via Cantonale", "Dorfplatz", "Kirchweg")


def _language(rng) -> str:
    names, shares = zip(*LANGUAGE_SHARES)
    return str(rng.choice(names, p=np.array(shares) / sum(shares)))


def _hours(rng) -> str:
    start = int(rng.choice([6, 7, 8, 9]))
    return f"{start}–{int(rng.choice([17, 18, 19, 20]))} h"


def _days(rng, language) -> str:
    days = WEEKDAYS[language]
    return f"{days[0]}–{days[int(rng.choice([4, 5]))]}"


def plate_lines(rng) -> list:
    """The lines of a plate's text, in the spelling normalised OCR output has."""
    language = _language(rng)
    kind = rng.choice(["distance", "hours", "days", "days_hours", "except"], p=[0.3, 0.15, 0.1, 0.2, 0.25])
    if kind == "distance":
        return [f"{int(rng.choice(DISTANCES_M))} m"]
    if kind == "hours":
        return [_hours(rng)]
    if kind == "days":
        return [_days(rng, language)]
    if kind == "days_hours":
        return [_days(rng, language), _hours(rng)]
    what = str(rng.choice(EXCEPTIONS[language]))
    return [EXCEPT_WORDS[language], what]


def _weathered(bgr: np.ndarray, rng) -> np.ndarray:
    """A little grime from the bottom and sensor-like grain: a plate that has hung outside for a while."""
    h, w = bgr.shape[:2]
    grime = 1.0 - rng.uniform(0.0, 0.12) * np.linspace(0.0, 1.0, h)[:, None] ** 2
    grain = rng.normal(0.0, 3.0, (h, w, 1))
    return np.clip(bgr * grime[..., None] + grain, 0, 255).astype(np.uint8)


def _next(pieces, kind: str):
    """A texture key and generator of a stream of their own: placing plates leaves every other draw as it was."""
    keys = pieces.keys
    keys.plate_count = getattr(keys, "plate_count", 0) + 1
    return f"{kind}:{keys.plate_count}", keys.rng(3, keys.plate_count)


def add_plate(pieces, look, host, centre, facing_deg: float, tilt_deg: float, sign_fmt, s: float) -> list:
    """[the plate] right below the sign ``host`` (a PlacedSign) with probability ``look.plate_share``, else []."""
    from .sign_poles import PlacedSign, face_shape

    key, rng = _next(pieces, "plate")
    if host.truth is None or rng.random() >= look.plate_share:
        return []
    lines = plate_lines(rng)
    formats = plate_formats_for(float(sign_fmt[1]))
    name = next((n for n in formats if n.endswith(f"-{len(lines)}")), max(formats))
    width_m, height_m = formats[name]
    phi, tau = np.radians(facing_deg), np.radians(tilt_deg)
    n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
    right = np.array([-np.cos(phi), np.sin(phi), 0.0])
    up = UP * np.cos(tau) - n_h * np.sin(tau)
    gap = rng.uniform(0.02, 0.06)
    plate_centre = centre - up * (sign_fmt[2] / 2 + gap + height_m / 2)
    size_px = int(np.clip(look.fx * width_m / 2.5, 64, 720))
    fh, fw = face_shape(size_px, width_m, height_m)
    face_rng = np.random.default_rng(rng.integers(1 << 32))

    def make_face():
        return Texture(_weathered(draw_plate(lines, fw, fh), face_rng))

    face = rect_surface(plate_centre - right * width_m / 2 + up * height_m / 2, right * width_m, -up * height_m,
                        TextureSource(key, fw, fh, make_face), two_sided=False, s_range=(s - 2, s + 2))
    back = rect_surface(plate_centre - n_h * 0.01 + right * width_m / 2 + up * height_m / 2, -right * width_m,
                        -up * height_m, None, (150, 152, 150), two_sided=False, s_range=(s - 2, s + 2))
    pieces.surfaces += [face, back]
    truth = TruthSign("", PLATE_ID, *(float(c) for c in plate_centre), float(width_m), float(height_m),
                      float(facing_deg % 360.0), text=" / ".join(lines))
    return [PlacedSign(truth, "white", plate_centre, [face, back], host=host)]


def white_distractors(pieces, s_lo: float, s_hi: float, density: float, rng, facades) -> None:
    """House-number and notice plates on the ``facades`` (FacadeSpan): white, framed, with text, no sign above."""
    for s in np.sort(rng.uniform(s_lo, s_hi, rng.poisson(density * max(s_hi - s_lo, 0.0) / 100.0))):
        span = next((f for f in facades if f.s0 + 1 < s < f.s1 - 2), None)
        if span is None:
            continue
        width, height = rng.uniform(0.25, 1.2), rng.uniform(0.15, 0.6)
        lines = [str(rng.choice(STREETS))] if rng.random() < 0.5 else [str(int(rng.integers(1, 120)))]
        if height > 0.35 and rng.random() < 0.5:
            lines.append(plate_lines(rng)[0])
        key, trng = _next(pieces, "white")
        w, h = max(8, int(width / 0.004)), max(8, int(height / 0.004))
        src = TextureSource(key, w, h, lambda lines=lines, w=w, h=h, trng=trng: Texture(
            _weathered(draw_plate(lines, w, h), trng)))
        lat = span.l_f - span.side * 0.03
        a, b = pieces.street.point(s, lat), pieces.street.point(s + width, lat)
        left, right = (b, a) if span.side > 0 else (a, b)
        lift = span.bottom + 0.3 + rng.uniform(1.2, 3.0)
        pieces.wall(left, right, lift, lift + height, src, s_range=(s - 1, s + width + 1))
