"""Which official ASTRA drawing shows each Swiss catalogue entry (file names of signalo's official SVG set).

The drawings are those of opengisch/signalo (``project/images/official/original``,
GPL-2.0; drawings by the Swiss Federal Roads Office ASTRA), at 1:20 of the
normal format. The file of each SSV number comes from signalo's table of
official signs (``vl_official_sign``). Element indices count the drawable
elements of a file in document order; they were read off the signalo commit
named in ``templates/README.md`` and are checked against the element counts
below before use.

Entries missing here have no faithful official drawing and keep the project's
own drawing (``OWN_DRAWING`` says why).
"""

from __future__ import annotations

from .official import Cutout, Drawing, Glyph, Relettered

ARTWORK_SOURCE = {
    "repository": "https://github.com/opengisch/signalo",
    "commit": "76127fcb74801c21bff1f1f1442e3125b8733366",
    "path": "project/images/official/original",
    "licence": "GPL-2.0",
    "author": "Swiss Federal Roads Office (ASTRA / FEDRO), official drawings of the SSV signs",
}

# Speed-limit digits (the narrow typeface of round prohibition signs), each with its drawing's "0".
_SPEED_BASE = "230.svg"  # 2.30 "60"
_SPEED_SLOTS = ((2, 4), (3, 5))  # "6" (outline, counter), "0" (outline, counter)
_SPEED_DIGITS = {
    "2": Glyph("259-5-a.svg", (23,), reference=(24, 27)),  # the 20 disc of the 2.59.5 meeting zone
    "3": Glyph("259-1-a.svg", (11,), reference=(12, 13)),  # the 30 disc of the 2.59.1 zone sign
    "5": Glyph("230-1-a.svg", (12,), reference=(11, 13)),  # 2.30.1 "50 generell"
    "6": Glyph("230.svg", (2, 4), reference=(3, 5)),
    "8": Glyph("477-10-2.svg", (8, 10, 11), reference=(9, 12)),  # the 80 disc of lane sign 4.77
}
_ELEMENT_COUNTS = {"230.svg": 6, "230-1-a.svg": 14, "231.svg": 5, "259-1-a.svg": 14, "259-5-a.svg": 33,
                   "477-10-2.svg": 13, "216.svg": 6, "219.svg": 8}


def _counts(*files) -> tuple:
    return tuple((f, _ELEMENT_COUNTS[f]) for f in files)


def _speed_limit(first_digit: str) -> Relettered:
    glyph = _SPEED_DIGITS[first_digit]
    return Relettered(_SPEED_BASE, _SPEED_SLOTS, ((0, glyph),), reference=1,
                      elements=_counts(_SPEED_BASE, glyph.file))


_DIRECT = {
    **{f"1.{n:02d}": f"1{n:02d}.svg" for n in (1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 18, 22, 23,
                                               24, 25, 26, 27, 30, 31, 32)},
    **{f"2.{n:02d}": f"2{n:02d}.svg" for n in (1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14, 15, 32, 33, 34, 35, 36,
                                               37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 48, 49, 50, 60, 61, 62, 63,
                                               64)},
    "2.10.1": "210-1.svg",
    "4.29": "429-1.svg",  # the text panels: one example wording of each kind (catalogue/text_panels.py)
    "4.30": "430.svg",
    "4.33": "433-1-r.svg",
    "2.20-10": "220.svg",
    "2.30-60": "230.svg",
    "2.30.1": "230-1-a.svg",
    "2.41.1": "241-1.svg",
    "2.53-60": "253.svg",
    "2.53.1": "253-1-a.svg",
    "2.55": "255.svg",
    "2.56": "256.svg",
    "2.58": "258.svg",
    "2.59.1-30": "259-1-a.svg",
    "2.59.2-30": "259-2-a.svg",
    "2.59.3": "259-3-a.svg",
    "2.59.4": "259-4-a.svg",
    "2.59.5": "259-5-a.svg",
    "2.59.6": "259-6-a.svg",
    "2.63.1": "263-1.svg",
    **{f"3.{n:02d}": f"3{n:02d}.svg" for n in range(1, 11)},
    **{f"4.{n:02d}": f"4{n:02d}.svg" for n in (8, 9, 11, 14, 17, 18, 20)},
}

ARTWORK: dict = {tid: Drawing(f) for tid, f in _DIRECT.items()}
ARTWORK.update({f"2.30-{v}": _speed_limit(str(v)[0]) for v in (20, 30, 50, 80)})
ARTWORK.update({
    # 100 and 120: the official artwork has these discs only inside 4.93 (general speed limits).
    "2.30-100": Cutout("493.svg", (58.5, 113.2, 89.5, 144.2), (255, 23, 33)),
    "2.30-120": Cutout("493.svg", (58.5, 153.7, 89.5, 184.7), (255, 23, 33)),
    # 2.31 "30" (white on blue) with the "6" of 2.30, recoloured white with a blue counter.
    "2.31-60": Relettered("231.svg", ((2,), (3, 4)), ((0, _SPEED_DIGITS["6"]),), reference=1,
                          recolour=("rgb(100%,100%,100%)", "rgb(10.112%,40.585327%,73.280334%)"),
                          elements=_counts("231.svg", "230.svg")),
    # 2.16 "5,5t" with the units digit "3" of 2.19 "3,5m" (same type size, same 1:20 scale).
    "2.16-3.5": Relettered("216.svg", ((2,), (3,), (4,), (5,)), ((0, Glyph("219.svg", (4,))),),
                           elements=_counts("216.svg", "219.svg")),
})

# Entries whose field (value, symbols) is set into the empty red ring of 2.01, so that every round
# prohibition has the same official rim: the own drawings with a value the official glyphs cannot write,
# and the 100 and 120 discs of 4.93, drawn there with a brighter red and a narrower rim.
FRAMED = {tid: "201.svg" for tid in ("2.17-10", "2.18-2.3", "2.19-3.8", "2.30-40", "2.30-70", "2.47-70",
                                     "2.30-100", "2.30-120")}

OWN_DRAWING = {
    "2.17-10": "no official 1 or 0 in the type of 2.17 (only 2.17 \"2,4t\")",
    "2.18-2.3": "2.18 \"2m\" has no room for \"2,3m\" between its arrowheads; no official layout",
    "2.19-3.8": "no official 8 in the type of 2.19 (only \"3,5m\")",
    "2.30-40": "no official 4 in the narrow type of speed limits",
    "2.30-70": "no official 7 in the narrow type of speed limits",
    "2.47-70": "no official 7 (only 2.47 \"50 m\")",
    "2.53-50": "2.53 \"60\" is cut by its stripes; no official striped 50",
}
