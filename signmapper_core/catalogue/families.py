"""Sign families (danger, priority, prohibition, mandatory, information): how a surveyor groups signs.

The map legend groups the pictograms by family instead of listing every id.
Swiss SSV numbers say the family in their first digit (1 danger, 3 priority,
4 information); the regulatory signs 2.xx split by colour into prohibitions
(red ring, and their white end signs) and mandatory signs (blue disc). A
catalogue of another country falls back on colour and shape alone.
"""

from __future__ import annotations

DANGER, PRIORITY, PROHIBITION, MANDATORY, INFORMATION = "danger", "priority", "prohibition", "mandatory", "information"
FAMILIES = (DANGER, PRIORITY, PROHIBITION, MANDATORY, INFORMATION)

# family -> name in each language of the output (legend groups)
FAMILY_NAMES = {
    DANGER: {"en": "Danger signs", "de": "Gefahrensignale", "fr": "Signaux de danger", "it": "Segnali di pericolo"},
    PRIORITY: {"en": "Priority signs", "de": "Vortrittssignale", "fr": "Signaux de priorité",
               "it": "Segnali di precedenza"},
    PROHIBITION: {"en": "Prohibitions", "de": "Verbote", "fr": "Interdictions", "it": "Divieti"},
    MANDATORY: {"en": "Mandatory signs", "de": "Gebote", "fr": "Prescriptions", "it": "Prescrizioni"},
    INFORMATION: {"en": "Information signs", "de": "Hinweissignale", "fr": "Signaux d'indication",
                  "it": "Segnali di indicazione"},
}
_SSV_FIRST_NUMBER = {"1": DANGER, "3": PRIORITY, "4": INFORMATION}


def family(entry) -> str:
    """The family of a catalogue entry (anything with ``id``, ``colour`` and ``shape``)."""
    first = entry.id.split(".", 1)[0]
    if first in _SSV_FIRST_NUMBER and "." in entry.id:
        return _SSV_FIRST_NUMBER[first]
    if first == "2" and "." in entry.id:
        return MANDATORY if entry.colour == "blue" and entry.shape == "circle" else (
            INFORMATION if entry.colour == "blue" else PROHIBITION)
    if entry.colour == "red" and entry.shape == "triangle":
        return DANGER
    if entry.colour == "yellow" or entry.shape in ("triangle-down", "octagon", "diamond"):
        return PRIORITY
    if entry.colour == "blue" and entry.shape == "circle":
        return MANDATORY
    if entry.colour in ("red", "white") and entry.shape == "circle":
        return PROHIBITION
    return INFORMATION


def family_name(name: str, language: str = "en") -> str:
    names = FAMILY_NAMES[name]
    return names.get(language) or names["en"]


def by_family(entries) -> dict:
    """family -> entries of that family in catalogue order; every family present, in FAMILIES order."""
    groups = {name: [] for name in FAMILIES}
    for entry in entries:
        groups[family(entry)].append(entry)
    return groups
