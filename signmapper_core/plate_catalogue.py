"""Pictogram plate templates (SSV 5.xx with a pictogram): loaded from a catalogue's ``plates/`` folder.

``plates/plates.json`` (written by ``catalogue.plate_build``) lists each rendering
of an official drawing: id, language variant, names, the words printed on it and
its aspect (width / height). A catalogue without that folder has no pictogram
plates: its plates are all read as text. No OpenCV at import: front ends read the
names and sizes.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Optional

import numpy as np

from .errors import InputFileError
from .plate_formats import PLATE_FORMATS

FORMAT = "signmapper-plates/1"
PLATE_WIDTHS_M = sorted({w for w, _ in PLATE_FORMATS.values()})


class PlateCatalogueError(InputFileError):
    """plates.json or one of its images cannot be used."""


@dataclass(frozen=True)
class PlateTemplate:
    id: str
    variant: str
    names: dict
    text: str  # words printed on the plate ("" for a pictogram alone)
    aspect: float  # width / height
    grey: np.ndarray  # the master, grey uint8

    def name(self, lang: str = "de") -> str:
        return self.names.get(lang) or next(iter(self.names.values()), self.id)

    def size_m(self, width_m: float) -> tuple:
        """(width, height) of this plate as wide as ``width_m``."""
        return float(width_m), round(float(width_m) / self.aspect, 3)


def plates_folder(catalogue_folder) -> Path:
    return Path(catalogue_folder) / "plates"


def pictogram_png(catalogue, template_id: str) -> str:
    """The PNG a person sees for a type (review dock, atlas): its catalogue drawing, else a pictogram plate's
    (German version first); "" for a text plate or an id the catalogue lacks."""
    if template_id and template_id in catalogue:
        return str(catalogue.pictogram_path(template_id, "png"))
    for path in sorted((plates_folder(catalogue.folder) / "png").glob(f"{template_id}_*.png")):
        return str(path)
    return ""


@lru_cache(maxsize=4)
def load_plate_templates(catalogue_folder) -> tuple:
    """The pictogram plate templates of the catalogue in ``catalogue_folder`` (empty without ``plates/``)."""
    import cv2

    path = plates_folder(catalogue_folder) / "plates.json"
    if not path.is_file():
        return ()
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise PlateCatalogueError(path, f"not readable as JSON: {exc}") from exc
    if data.get("format") != FORMAT:
        raise PlateCatalogueError(path, f"format {data.get('format')!r} is not {FORMAT!r}")
    out = []
    for k, entry in enumerate(data.get("plates", [])):
        try:
            png = path.parent / entry["png"]
            grey = cv2.imread(str(png), cv2.IMREAD_GRAYSCALE)
            if grey is None:
                raise PlateCatalogueError(path, f"plate {k + 1}: image {png} is missing or unreadable")
            out.append(PlateTemplate(str(entry["id"]), str(entry["variant"]), dict(entry["names"]),
                                     str(entry.get("text", "")), float(entry["aspect"]), grey))
        except KeyError as exc:
            raise PlateCatalogueError(path, f"plate {k + 1} lacks the field {exc}") from exc
    return tuple(out)


def template_by_id(templates, template_id: str) -> Optional[PlateTemplate]:
    return next((t for t in templates if t.id == template_id), None)


def pictogram_formats(templates) -> dict:
    """Plate sizes the pictogram plates add to the text plates' (``PLATE_FORMATS``): name -> (width, height)."""
    return {f"{t.id}@{w:.2f}": t.size_m(w) for t in templates for w in PLATE_WIDTHS_M}
