"""Supplementary plates under signs, and white distractors, in a synthetic street.

A plate hangs right below the lowest sign of some poles, as wide as the sign
(``plate_formats_for``). It is one of the three kinds of ``catalogue.plates_ch``:
a text plate (one to three lines in German, French or Italian: a distance, a
time, weekdays, an exception) set in a real font; a layout plate, its official
drawing printed with its own free text in its text field (5.03's length between
the arrows); or a pictogram plate printed from its official drawing, every one of
the official set alike. Drawings are printed in colour and worn like the sign
faces. Its truth row names its sign (``plate_of``), its SSV id (a text plate's by
what it says: 5.01 a distance, 5.00-exception an exception, 5.00-1/2/3 any other
text by its lines) and its text, lines joined by " / ", exactly as the normalised
OCR output writes it (a layout plate: its free text; a pictogram plate: the words
of its drawing). White distractors (house-number and notice plates on façades,
with text) are white rectangles no sign stands above. Plates and distractors draw
from random streams of their own, so the rest of the scene is the same with or
without them.
"""

from __future__ import annotations

import numpy as np

from ..catalogue.model import DEFAULT_CATALOGUE_DIR
from ..catalogue.plates_ch import signalo_id
from ..drive.reader import TruthSign
from ..plates.catalogue import load_plate_templates
from ..plates.formats import plate_formats_for
from ..plates.text import EXCEPT_WORDS, WEEKDAYS
from . import face_dirt, face_print, face_wear
from .face_layers import ink_layers
from .panels import PlacedSign, face_shape
from .plate_faces import draw_in_field, draw_plate
from .surfaces import Texture, TextureSource, rect_surface

UP = np.array([0.0, 0.0, 1.0])
PLATE_MAX_GAP_M = 0.06  # between a sign's lower edge and its plate's upper edge (at least 2 cm)
# of the plates: text plates, layout plates (a drawing with free text), pictogram plates (a drawing alone)
KIND_SHARES = (("text", 0.45), ("layout", 0.2), ("pictogram", 0.35))
LANGUAGE_SHARES = (("de", 0.6), ("fr", 0.25), ("it", 0.15))
DISTANCES_M = (20, 30, 50, 80, 100, 150, 200, 250, 300, 400, 500, 800)
EXCEPTIONS = {
    "de": ("Zubringerdienst", "Anwohner", "Velos", "Bus", "Taxi"),
    "fr": ("riverains", "livraisons", "cycles", "bus", "taxi"),
    "it": ("confinanti", "biciclette", "bus", "taxi"),
}
BICYCLES = {"Velos", "cycles", "biciclette"}  # a 5.31-3 (bicycles and ...) already excepts them
# the free text of the layout plates, by Signalo id: what each says
LAYOUT_TEXTS = {
    "5.02": tuple(f"{d} m" for d in DISTANCES_M),  # distance to where the arrow turns
    "5.03": ("200 m", "300 m", "500 m", "800 m", "1,2 km", "2,5 km", "4 km"),  # length of the stretch
    "5.15": ("2,30 m", "2,50 m", "2,80 m", "3,20 m", "3,50 m"),  # width of the carriageway
    "5.17": ("12 km", "25 km", "31 km", "48 km", "60 km"),  # to the next fuel station but one
}
# a text plate: (what it says, share of the text plates, its SSV id)
TEXT_KINDS = (("distance", 0.28, "5.01"), ("hours", 0.12, "5.00-1"), ("days", 0.08, "5.00-1"),
              ("days_hours", 0.17, "5.00-2"), ("days_two_times", 0.07, "5.00-3"),
              ("except", 0.28, "5.00-exception"))
SECOND_EXCEPTION_SHARE = 0.3  # of the exception plates: two things excepted, on two lines
STREETS = ("Bahnhofstrasse", "Hauptstrasse", "Rue du Lac", "Via Cantonale", "Dorfplatz", "Kirchweg")


def _language(rng) -> str:
    names, shares = zip(*LANGUAGE_SHARES)
    return str(rng.choice(names, p=np.array(shares) / sum(shares)))


def _choice(rng, table):
    """One row of ``table`` (rows whose second item is their share), drawn by share."""
    shares = np.array([row[1] for row in table], float)
    return table[int(rng.choice(len(table), p=shares / shares.sum()))]


def _hours(rng) -> str:
    start = int(rng.choice([6, 7, 8, 9]))
    return f"{start}–{int(rng.choice([17, 18, 19, 20]))} h"


def _days(rng, language) -> str:
    days = WEEKDAYS[language]
    return f"{days[0]}–{days[int(rng.choice([4, 5]))]}"


def text_plate(rng, language: str = "") -> tuple:
    """(SSV id, lines) of a text plate, the lines in the spelling normalised OCR output has (``language`` drawn if
    not given)."""
    language = language or _language(rng)
    kind, _, ssv = _choice(rng, TEXT_KINDS)
    if kind == "distance":
        return ssv, [f"{int(rng.choice(DISTANCES_M))} m"]
    if kind == "hours":
        return ssv, [_hours(rng)]
    if kind == "days":
        return ssv, [_days(rng, language)]
    if kind == "days_hours":
        return ssv, [_days(rng, language), _hours(rng)]
    if kind == "days_two_times":
        return ssv, [_days(rng, language), f"{int(rng.choice([7, 8]))}–12 h", f"{int(rng.choice([13, 14]))}–18 h"]
    excepted = [str(w) for w in rng.permutation(EXCEPTIONS[language])]
    count = 2 if rng.random() < SECOND_EXCEPTION_SHARE else 1
    return ssv, [EXCEPT_WORDS[language]] + excepted[:count]


def plate_lines(rng, language: str = "") -> list:
    """The lines of a text plate (:func:`text_plate`)."""
    return text_plate(rng, language)[1]


def layout_text(rng, template, language: str) -> str:
    """The free text a layout plate carries in its field."""

    official = signalo_id(template.id)
    if official in LAYOUT_TEXTS:
        return str(rng.choice(LAYOUT_TEXTS[official]))
    # 5.31-3: bicycles and something else excepted
    return str(rng.choice([w for w in EXCEPTIONS[language] if w not in BICYCLES]))


def drawn_plate(rng, language: str, kind: str):
    """A plate template of ``kind`` (pictogram or layout), each id alike, in the plate's language version (German
    where the drawing has no other), or None when the catalogue has none."""

    templates = [t for t in load_plate_templates(DEFAULT_CATALOGUE_DIR) if t.kind == kind]
    ids = sorted({t.id for t in templates})
    if not ids:
        return None
    chosen = ids[int(rng.integers(len(ids)))]
    variants = {t.variant: t for t in templates if t.id == chosen}
    return variants.get(language) or variants.get("de") or next(iter(variants.values()))


def pictogram_face(template, width_px: int, height_px: int, rng, text: str = "") -> np.ndarray:
    """BGR of a physical plate printed from its drawing (in colour), a layout plate's ``text`` set in its field:
    placed on the blank with a small error, its own print run, UV ageing and grime (as the drives' sign faces
    get), never the template's pixels."""
    import cv2


    master = cv2.imread(template.png) if template.png else None
    if master is None:  # a template without its file (a test's): its grey
        master = cv2.cvtColor(template.grey, cv2.COLOR_GRAY2BGR)
    bgr = cv2.resize(master, (width_px, height_px), interpolation=cv2.INTER_AREA
                     if width_px < master.shape[1] else cv2.INTER_LINEAR)
    if template.field:
        bgr = draw_in_field(bgr, [text], template.field)
    matrix = cv2.getRotationMatrix2D(((width_px - 1) / 2.0, (height_px - 1) / 2.0), rng.uniform(-0.5, 0.5),
                                     1.0 + rng.uniform(-0.01, 0.01))
    matrix[:, 2] += rng.uniform(-0.006, 0.006, 2) * (width_px, height_px)
    bgr = cv2.warpAffine(bgr, matrix, (width_px, height_px), borderMode=cv2.BORDER_REPLICATE)
    labels = ink_layers(bgr)
    img = face_print.print_variation(bgr.astype(np.float32), labels, rng, float(rng.uniform(0.3, 1.0)),
                                     width_px / 0.6)
    img = face_wear.uv_ageing(img, labels, rng, float(rng.beta(1.1, 4.0)))
    img = face_dirt.grime(img, rng, float(rng.beta(1.2, 3.0)))
    return np.clip(img, 0, 255).astype(np.uint8)


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
    key, rng = _next(pieces, "plate")
    if host.truth is None or rng.random() >= look.plate_share:
        return []
    language = _language(rng)
    kind = _choice(rng, KIND_SHARES)[0]
    drawn = drawn_plate(rng, language, kind) if kind != "text" else None
    formats = plate_formats_for(float(sign_fmt[1]))
    if drawn is None:
        template_id, lines = text_plate(rng, language)
        name = next((n for n in formats if n.endswith(f"-{len(lines)}")), max(formats))
        width_m, height_m = formats[name]
        text = " / ".join(lines)
    else:
        width_m, height_m = drawn.size_m(next(iter(formats.values()))[0])
        template_id, lines = drawn.id, []
        text = layout_text(rng, drawn, language) if drawn.field else drawn.text
    phi, tau = np.radians(facing_deg), np.radians(tilt_deg)
    n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
    right = np.array([-np.cos(phi), np.sin(phi), 0.0])
    up = UP * np.cos(tau) - n_h * np.sin(tau)
    gap = rng.uniform(0.02, PLATE_MAX_GAP_M)
    plate_centre = centre - up * (sign_fmt[2] / 2 + gap + height_m / 2)
    size_px = int(np.clip(look.fx * max(width_m, height_m) / 2.5, 64, 720))
    fh, fw = face_shape(size_px, width_m, height_m)
    face_rng = np.random.default_rng(rng.integers(1 << 32))

    def make_face():
        printed = draw_plate(lines, fw, fh) if drawn is None else pictogram_face(drawn, fw, fh, face_rng, text)
        return Texture(_weathered(printed, face_rng))

    face = rect_surface(plate_centre - right * width_m / 2 + up * height_m / 2, right * width_m, -up * height_m,
                        TextureSource(key, fw, fh, make_face), two_sided=False, s_range=(s - 2, s + 2))
    back = rect_surface(plate_centre - n_h * 0.01 + right * width_m / 2 + up * height_m / 2, -right * width_m,
                        -up * height_m, None, (150, 152, 150), two_sided=False, s_range=(s - 2, s + 2))
    pieces.surfaces += [face, back]
    truth = TruthSign("", template_id, *(float(c) for c in plate_centre), float(width_m), float(height_m),
                      float(facing_deg % 360.0), text=text)
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
