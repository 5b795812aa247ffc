"""What OCR read on a supplementary plate, written the way the plate means it.

Swiss plates (SSV 5.xx) say a few things in German, French or Italian:
distances ("200 m", "2 km"), times ("7–19 h"), weekday ranges ("Mo–Fr",
"lu–ve"), exceptions ("ausgenommen Zubringerdienst", "excepté riverains",
"eccetto bus"). Normalising makes one spelling of each: digits OCR mistook for
letters in numbers, any dash between numbers or weekdays an en dash, a space
before the unit (a time range always has its "h"), words close to the plates'
vocabulary spelt as in it, stray symbols (a frame's edge read as "|") dropped, and so is a
single character at a line's end when without it the line is one plates print ("1 6–18 h": a
pole's edge read as a "1"). Lines are joined by " / " (the drive format's way of writing a
plate's text).
"""

from __future__ import annotations

import difflib
import re
from typing import Iterable

EN_DASH = "–"
WEEKDAYS = {
    "de": ("Mo", "Di", "Mi", "Do", "Fr", "Sa", "So"),
    "fr": ("lu", "ma", "me", "je", "ve", "sa", "di"),
    "it": ("lu", "ma", "me", "gi", "ve", "sa", "do"),
}
EXCEPT_WORDS = {"de": "ausgenommen", "fr": "excepté", "it": "eccetto"}
DISTANCE = re.compile(r"\d+(?:[.,]\d+)? (?:m|km)")  # a normalised distance or length: "200 m", "2,5 km"
# Words of Swiss supplementary plates: what a plate's text is spelt against.
VOCABULARY = (
    "ausgenommen", "excepté", "eccetto", "Zubringerdienst", "Anwohner", "Velos", "Anstösser",
    "Landwirtschaft", "Zufahrt", "gestattet", "riverains", "livraisons", "service", "autorisé", "cycles",
    "servizio", "domicilio", "confinanti", "biciclette", "autorizzato", "Schule", "école", "scuola", "Kinder",
    "enfants", "bambini", "Gegenverkehr", "Parkieren", "Stationnement", "Parcheggio",
)
_LOOKUP = {w.lower(): w for w in VOCABULARY}
# what plates commonly except, by language: short words the vocabulary leaves out (its words have 5+ letters)
_EXCEPTED = {"de": ("Bus", "Taxi", "Velos", "Anwohner"), "fr": ("bus", "taxi", "cycles"),
             "it": ("bus", "taxi")}
_DIGIT_LOOKALIKES = str.maketrans({"O": "0", "o": "0", "D": "0", "Q": "0", "l": "1", "I": "1", "i": "1", "|": "1",
                                   "S": "5", "s": "5", "B": "8", "Z": "2", "z": "2", "g": "9"})
_DASHES = "-–—~_=‐‑‒―"
_NUMBERLIKE = re.compile(r"^[0-9OoDQlIi|SsBZzg]*[0-9][0-9OoDQlIi|SsBZzg.,:]*$")
_ALL_DAYS = {d.lower() for days in WEEKDAYS.values() for d in days}
_CANONICAL_DAY = {d.lower(): d for d in WEEKDAYS["de"]}  # German days are capitalised, others as written


def _fix_number(token: str) -> str:
    """Numbers in a token with letters OCR confused for digits as digits: "2OOm" -> "200m", "7-l9h" -> "7-19h"."""
    pieces = re.split(rf"([{_DASHES}])", token)
    for i, piece in enumerate(pieces):
        unit = re.search(r"(km|m|h)$", piece)
        number = piece[: unit.start()] if unit and unit.start() > 0 else piece
        if _NUMBERLIKE.match(number):
            pieces[i] = number.translate(_DIGIT_LOOKALIKES) + piece[len(number):]
    return "".join(pieces)


def _fix_word(token: str) -> str:
    """A word of 5+ letters spelt as in the plates' vocabulary when OCR came close (case-insensitive, ratio >= 0.8)."""
    core = token.strip(".,;:")
    if len(core) < 5 or not core.isalpha():  # short words ("bus", "Bus", "Mo") are read well and differ by language
        return token
    match = difflib.get_close_matches(core.lower(), list(_LOOKUP), n=1, cutoff=0.8)
    return token.replace(core, _LOOKUP[match[0]]) if match else token


_DAY_LOOKALIKES = str.maketrans({"5": "S", "0": "o", "1": "l", "8": "B"})


def _completed_day(part: str, days: tuple, first: bool) -> str | None:
    """The weekday of ``days`` (one language's, Monday first) that ``part`` is, or is the start (end) of when OCR
    lost its last (first) letter; a range's first day where several fit is the earliest (plates' ranges start
    on Monday), its last day the latest."""
    part = part.translate(_DAY_LOOKALIKES)
    exact = [d for d in days if d.lower() == part.lower()]
    if exact:
        return exact[0]
    if len(part) != 1:
        return None
    fits = [d for d in days if d.lower().startswith(part.lower()) or d.lower().endswith(part.lower())]
    if not fits:
        return None
    return fits[0] if first else fits[-1]


def _fix_days(text: str) -> str:
    """A weekday range in one spelling: "Mo-Fr" -> "Mo–Fr"; a day OCR read with a digit for a letter ("Mo-5a")
    or lost a letter of ("Mo-F", "o-Sa") completed where the other day of the range names the language."""
    def day(name: str) -> str:
        return _CANONICAL_DAY.get(name.lower(), name) if name[0].isupper() else name

    pattern = re.compile(rf"(?<![\w.])([A-Za-z0-9]{{1,2}})\s*[{_DASHES}]\s*([A-Za-z0-9]{{1,2}})(?![\w.])")

    def replace(match):
        a, b = match.group(1), match.group(2)
        if a.isdigit() and b.isdigit():
            return match.group(0)
        for days in WEEKDAYS.values():
            first, last = _completed_day(a, days, True), _completed_day(b, days, False)
            if first and last and (len(a) == 2 or len(b) == 2):  # one day read whole names the language
                case = str.lower if (a if len(a) == 2 else b)[0].islower() else (lambda d: d)
                return f"{day(case(first))}{EN_DASH}{day(case(last))}"
        return match.group(0)

    return pattern.sub(replace, text)


def is_plate_line(line: str) -> bool:
    """Whether a normalised line is one of the forms Swiss plates print: a distance, a time range, a weekday
    range, or words of the plates' vocabulary and exceptions (a reading of such lines only is more likely right)."""
    number = r"\d{1,2}(?:\.\d\d)?"
    if DISTANCE.fullmatch(line) or re.fullmatch(rf"{number}{EN_DASH}{number} h", line):
        return True
    days = re.fullmatch(rf"(\w\w){EN_DASH}(\w\w)", line)
    if days and days.group(1).lower() in _ALL_DAYS and days.group(2).lower() in _ALL_DAYS:
        return True
    known = set(_LOOKUP) | {w.lower() for words in _EXCEPTED.values() for w in words}
    return bool(line) and all(word.lower() in known for word in line.split())


_STRAY_MARKS = "'\"`‚‘’“”„\\/|"  # quotes, slashes and bars at a token's ends: a frame's edge or dirt, not print


def normalise_line(line: str) -> str:
    """One line of a plate in its one spelling (see the module docstring)."""
    text = _normalised(line)
    if is_plate_line(text):
        return text
    # a single character at either end that keeps the rest from being a line plates print is a frame's edge or
    # a pole read as a letter ("1 6–18 h", "J excepté livraisons"): the line without it, if that is one
    tokens = text.split()
    for start, end in ((1, len(tokens)), (0, len(tokens) - 1), (1, len(tokens) - 1)):
        dropped = tokens[:start] + tokens[end:]
        if start < end and all(len(t) == 1 for t in dropped):
            shorter = _normalised(" ".join(tokens[start:end]))
            if is_plate_line(shorter):
                return shorter
    return text


def _normalised(line: str) -> str:
    # a token without a letter, digit or dash ("|", "=") is an edge of the frame or dirt, not print; nor is a
    # lone dash at either end of the line (a dash joins two things)
    tokens = [t.strip(_STRAY_MARKS) for t in line.split()]
    tokens = [_fix_word(_fix_number(t)) for t in tokens if any(c.isalnum() or c in "-–—" for c in t)]
    while tokens and not any(c.isalnum() for c in tokens[-1]):
        tokens.pop()
    while tokens and not any(c.isalnum() for c in tokens[0]):
        tokens.pop(0)
    text = " ".join(tokens)
    text = re.sub(rf"(\d)\s*[{_DASHES}]\s*(\d)", rf"\1{EN_DASH}\2", text)  # 7 - 19 -> 7–19
    text = re.sub(r"(\d)\s*(km|m|h|Std)\b\.?", r"\1 \2", text)  # 200m -> 200 m, 19h -> 19 h
    text = re.sub(r"(\d)[.:](\d\d)\b", r"\1.\2", text)  # 7:30 -> 7.30 (Swiss clock times)
    text = _fix_days(text)
    # a time range is followed by its unit: the one letter OCR made of a small "h" is that h
    text = re.sub(rf"^(\d{{1,2}}(?:\.\d\d)?{EN_DASH}\d{{1,2}}(?:\.\d\d)?)(?:\s*[A-Za-z])?$", r"\1 h", text.strip())
    return re.sub(r"\s+", " ", text).strip(" .,;:")


def normalise_text(lines: Iterable[str]) -> str:
    """The lines of a plate, each normalised, empty ones dropped, joined by " / ".

    A line of one character beside other lines is a pole or the frame's edge read as a letter ("1", "l"): no
    plate prints a lone character on a line of its own.
    """
    kept = [line for line in (normalise_line(line) for line in lines) if line]
    if len(kept) > 1:
        kept = [line for line in kept if len(line) > 1]
    return " / ".join(kept)
