"""Signalo's table of the official Swiss signs (``signalo_db.vl_official_sign``), as the catalogue's list of ids.

``signalo_official_signs.csv`` beside this module is that table, dumped unchanged
(every column, ordered by id) from Signalo's data model as its changelogs build it:
repository https://github.com/opengisch/signalo, commit
76127fcb74801c21bff1f1f1442e3125b8733366 (data model 1.4), licence GPL-2.0. It
names each SSV sign (de/fr/it), the drawing of each language version and, for
direction signs, of the left- and right-pointing version.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

TABLE = Path(__file__).with_name("signalo_official_signs.csv")
LANGUAGES = ("de", "fr", "it")
DRAWING_LANGUAGES = LANGUAGES + ("ro",)  # Romansh has a drawing of its own on some signs (2.30.1 -d)


@dataclass(frozen=True)
class OfficialSign:
    """One row of Signalo's ``vl_official_sign``."""

    id: str
    names: dict  # language -> name
    drawings: tuple  # distinct drawing file names in table order: de, fr, it, ro, then the right-pointing ones
    left_drawing: str  # the German drawing (the left-pointing one of a direction sign)
    right_drawing: str  # the right-pointing German drawing of a direction sign, else ""
    size_px: tuple  # (width, height) of Signalo's symbol, proportional to the drawing
    inscriptions: int  # lines of free text Signalo lets the user write on it
    directional: bool


def _row(row: dict) -> OfficialSign:
    files = [row[f"img_{lang}"] for lang in DRAWING_LANGUAGES] + [row[f"img_{lang}_right"]
                                                                  for lang in DRAWING_LANGUAGES]
    return OfficialSign(
        id=row["id"],
        names={lang: row[f"value_{lang}"].strip() for lang in LANGUAGES if row[f"value_{lang}"].strip()},
        drawings=tuple(dict.fromkeys(f for f in files if f)),
        left_drawing=row["img_de"],
        right_drawing=row["img_de_right"] or "",
        size_px=(int(row["img_width"]), int(row["img_height"])),
        inscriptions=int(row["no_dynamic_inscription"] or 0),
        directional=row["directional_sign"] == "True",
    )


@lru_cache(maxsize=1)
def official_signs() -> dict:
    """Signalo id -> :class:`OfficialSign`, every active row of the table, in id order."""
    with TABLE.open(encoding="utf-8", newline="") as f:
        return {r["id"]: _row(r) for r in csv.DictReader(f) if r["active"] == "True"}
