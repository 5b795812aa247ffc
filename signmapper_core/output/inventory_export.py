"""The inventory as delivered: the signs a person may hand over, plates after their sign, in people's words.

A deliverable holds the accepted signs and those added by hand (optionally those
still to review), each supplementary plate right after the sign it belongs to.
Its column titles are the output schema's field titles in the chosen language and
its coded values (status, format) the words of ``value_names``; a shapefile,
whose column names are at most ten ASCII characters, gets short names made from
the titles. No QGIS here: ``algorithms/export_inventory.py`` writes the rows.
"""

from __future__ import annotations

import os
import re
import unicodedata
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Sequence, Tuple

from ..statuses import ACCEPTED, MANUAL
from .schema import SIGNS, TEXT, field
from .value_names import LOCALISED_FIELDS, value_name

# the columns of the deliverable, in their order: what a surveyor hands over, not how the method worked
COLUMNS = ("sign_id", "template_id", "name", "plate_of", "text", "status", "reviewed", "easting", "northing",
           "elevation", "azimuth", "mount_height_m", "width_m", "height_m", "format", "timestamp", "crop_path")
DELIVERED = (ACCEPTED, MANUAL)  # statuses handed over; signs still to review only when asked for
SHAPEFILE_NAME_LENGTH = 10


@dataclass(frozen=True)
class Column:
    name: str  # the output schema's field
    title: str  # its title in the deliverable's language
    kind: str  # TEXT, INTEGER or REAL as written (coded values become TEXT words)


def columns(language: str) -> List[Column]:
    """The deliverable's columns: titles in ``language``; coded fields are written as words (text)."""
    out = []
    for name in COLUMNS:
        declared = field(SIGNS, name)
        kind = TEXT if name in LOCALISED_FIELDS else declared.kind
        out.append(Column(name, declared.alias(language), kind))
    return out


@dataclass
class Selection:
    """The signs delivered, in order, and what was left out."""

    signs: List[dict]  # value dicts of the signs layer (output.schema names), signs each followed by their plates
    left_out: int  # signs and plates whose status is not delivered
    orphan_plates: List[Tuple[int, int]]  # (plate's sign_id, its sign's) of plates whose sign is not delivered


def select(signs: Sequence[dict], statuses: Sequence[str] = DELIVERED) -> Selection:
    """The signs with a delivered status in sign number order, each plate right after its sign; a plate whose
    sign is not delivered (rejected, still to review) is left out with it and listed."""
    chosen = [s for s in signs if s.get("status") in statuses]
    left_out = len(signs) - len(chosen)
    plates: Dict[int, List[dict]] = {}
    mains = []
    for sign in chosen:
        if sign.get("plate_of") is None:
            mains.append(sign)
        else:
            plates.setdefault(sign["plate_of"], []).append(sign)
    number = lambda s: (s.get("sign_id") is None, s.get("sign_id") or 0)  # noqa: E731 - a sort key
    ordered = []
    for sign in sorted(mains, key=number):
        ordered.append(sign)
        ordered += sorted(plates.pop(sign.get("sign_id"), []), key=number)
    orphans = [(p.get("sign_id"), host) for host, group in sorted(plates.items()) for p in group]
    return Selection(ordered, left_out, orphans)


def row(sign: dict, language: str) -> list:
    """The values of one sign in the column order, coded ones as words in ``language``."""
    return [value_name(name, sign.get(name), language) if name in LOCALISED_FIELDS else sign.get(name)
            for name in COLUMNS]


def short_names(titles: Sequence[str], length: int = SHAPEFILE_NAME_LENGTH) -> List[str]:
    """Column names a shapefile can hold, made from the titles: ASCII letters and digits joined by '_', at most
    ``length`` characters, unique ('Signal-Nr.' -> 'Signal_Nr', 'Höhe Signalfläche [m]' -> 'Hohe_Signa')."""
    names: List[str] = []
    for title in titles:
        ascii_title = unicodedata.normalize("NFKD", title).encode("ascii", "ignore").decode("ascii")
        base = "_".join(re.findall(r"[A-Za-z0-9]+", ascii_title))[:length] or "field"
        name, k = base, 1
        while name.lower() in (n.lower() for n in names):
            k += 1
            name = f"{base[:length - len(str(k))]}{k}"
        names.append(name)
    return names



def rebased(crop_path, gpkg_folder, deliverable_folder):
    """A crop's path (relative to the GeoPackage) as the deliverable should hold it: relative to the
    deliverable's folder, absolute where no relative path leads there (another drive); None stays None."""
    if not crop_path:
        return None
    crop = (Path(gpkg_folder) / crop_path).resolve()
    try:
        return os.path.relpath(crop, Path(deliverable_folder).resolve())
    except ValueError:  # another drive letter on Windows
        return str(crop)
