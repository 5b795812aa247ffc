"""Swiss pictogram plates (SSV 5.xx) Sign Mapper classifies: which official drawing each is rendered from.

A supplementary plate with a pictogram (a vehicle class, bicycles "allowed" or
"excepted") means the same whatever its size; it is told apart by its drawing,
not by OCR. Each entry names the drawing of the official set (as published in
opengisch/signalo, ``project/images/official/original``) per language version
(German ``a``, French ``b`` where the words differ) and the words printed on it,
spelt as a person reads them. Names from Signalo's table of official signs
(``vl_official_sign``). Plates of text only (distances, times, "ausgenommen
..." with free text) are not here: they are read by OCR.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PictogramPlate:
    id: str  # SSV number as Signalo names it
    names: dict
    drawings: dict  # variant ("de", "fr") -> (SVG file name, words printed on it, "" for none)


PICTOGRAM_PLATES = (
    PictogramPlate("5.20", {"de": "Leichte Motorwagen", "fr": "Voiture automobile légère",
                            "it": "Autoveicoli leggeri"}, {"de": ("520.svg", "")}),
    PictogramPlate("5.22", {"de": "Lastwagen", "fr": "Camion", "it": "Autocarro"}, {"de": ("522.svg", "")}),
    PictogramPlate("5.25", {"de": "Gesellschaftswagen", "fr": "Autocar", "it": "Autobus"}, {"de": ("525.svg", "")}),
    PictogramPlate("5.31", {"de": "Fahrrad", "fr": "Cycle", "it": "Velocipede"}, {"de": ("531.svg", "")}),
    PictogramPlate("5.31-1", {"de": "Fahrräder gestattet", "fr": "Cycles autorisés", "it": "Cicli autorizzati"},
                   {"de": ("531-1-a.svg", "gestattet"), "fr": ("531-1-b.svg", "autorisés")}),
    PictogramPlate("5.31-2", {"de": "Ausgenommen Fahrräder", "fr": "Exceptés cycles", "it": "Esclusi i cicli"},
                   {"de": ("531-2-a.svg", "ausgenommen"), "fr": ("531-2-b.svg", "exceptés")}),
    PictogramPlate("5.25-5.30-5.31", {"de": "Ausgenommen Busse, Mofas, Fahrräder",
                                      "fr": "Exceptés bus, cyclomoteurs, cycles",
                                      "it": "Esclusi autobus, ciclomotori, cicli"},
                   {"de": ("525-530-531-a.svg", "ausgenommen"), "fr": ("525-530-531-b.svg", "exceptés")}),
)
