"""What the white text panels of a synthetic drive say: real Swiss place names and distances.

Names come from the German, French and Italian speaking regions with their accents, hyphens and
abbreviations as they are signposted, so OCR meets what it will meet on the road ("Châtel-St-Denis",
"Wädenswil", "Biasca"). Each name carries its canton for the optional second line of a 4.29 panel.
"""

from __future__ import annotations

from typing import List

import numpy as np

from ..catalogue.text_panels import DIRECTION, PLACE_END, PLACE_NAME, TEXT_PANELS

PLACES = (
    # German
    ("Mönchaltorf", "ZH"), ("Rüti", "ZH"), ("Küsnacht", "ZH"), ("Wädenswil", "ZH"), ("Maur", "ZH"),
    ("Uster", "ZH"), ("Dübendorf", "ZH"), ("Opfikon", "ZH"), ("Wetzikon", "ZH"), ("Hinwil", "ZH"),
    ("Bülach", "ZH"), ("Zürich", "ZH"), ("Basel", "BS"), ("Liestal", "BL"), ("Münchenstein", "BL"),
    ("Aarau", "AG"), ("Brugg", "AG"), ("Lenzburg", "AG"), ("Zug", "ZG"), ("Küssnacht", "SZ"),
    ("Einsiedeln", "SZ"), ("Luzern", "LU"), ("Sursee", "LU"), ("Sarnen", "OW"), ("Altdorf", "UR"),
    ("Näfels", "GL"), ("Rapperswil-Jona", "SG"), ("St. Gallen", "SG"), ("Frauenfeld", "TG"),
    ("Weinfelden", "TG"), ("Schaffhausen", "SH"), ("Thun", "BE"), ("Münsingen", "BE"), ("Burgdorf", "BE"),
    ("Solothurn", "SO"), ("Olten", "SO"), ("Chur", "GR"), ("Thusis", "GR"),
    # French
    ("Estavayer-le-Lac", "FR"), ("Châtel-St-Denis", "FR"), ("Bulle", "FR"), ("Romont", "FR"),
    ("Yverdon-les-Bains", "VD"), ("Échallens", "VD"), ("Moudon", "VD"), ("Payerne", "VD"), ("Nyon", "VD"),
    ("Neuchâtel", "NE"), ("La Chaux-de-Fonds", "NE"), ("Le Locle", "NE"), ("Delémont", "JU"),
    ("Porrentruy", "JU"), ("Genève", "GE"), ("Sion", "VS"), ("Martigny", "VS"),
    # Italian
    ("Bellinzona", "TI"), ("Airolo", "TI"), ("Biasca", "TI"), ("Lugano", "TI"), ("Locarno", "TI"),
    ("Mendrisio", "TI"), ("Faido", "TI"), ("Giubiasco", "TI"), ("Poschiavo", "GR"),
)
CANTON_LINE_SHARE = 0.35  # of the 4.29 panels: the canton on a second line
SECOND_DESTINATION_SHARE = 0.25  # of the 4.30 panels: two places below the bar
KM_RANGE = (1, 25)


def _places(rng: np.random.Generator, n: int) -> List[tuple]:
    """``n`` different places."""
    return [PLACES[int(i)] for i in rng.choice(len(PLACES), size=n, replace=False)]


def panel_lines(kind_id: str, rng: np.random.Generator) -> List[str]:
    """The lines a ``kind_id`` panel prints, top to bottom, drawn from ``rng``."""
    layout = TEXT_PANELS[kind_id].layout
    if layout == PLACE_NAME:
        (name, canton), = _places(rng, 1)
        return [name, f"({canton})"] if rng.random() < CANTON_LINE_SHARE else [name]
    if layout == PLACE_END:
        n_next = 2 if rng.random() < SECOND_DESTINATION_SHARE else 1
        places = _places(rng, 1 + n_next)
        km = sorted(int(rng.integers(KM_RANGE[0], KM_RANGE[1] + 1)) for _ in range(n_next))
        return [places[0][0]] + [f"{name} {d} km" for (name, _), d in zip(places[1:], km)]
    if layout == DIRECTION:
        return [name for name, _ in _places(rng, int(rng.integers(1, 4)))]
    raise ValueError(f"no wording for a {kind_id} panel")
