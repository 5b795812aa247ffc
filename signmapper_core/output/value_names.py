"""The words of the output's coded values in each output language, declared once.

The GeoPackage keeps the codes ("review", "circle", "normal"): the review, the
exports and people's own expressions compare them, whatever language a run
was written in. People read them in the output language: the layer styles
show these words in the attribute table, the identify panel, forms and labels
(QGIS value maps), and the inventory export writes them.
"""

from __future__ import annotations

from typing import Any, Dict

from ..statuses import ACCEPTED, MANUAL, REJECTED, REVIEW
from .schema import LANGUAGES


def _words(en: str, de: str, fr: str, it: str) -> Dict[str, str]:
    return {"en": en, "de": de, "fr": fr, "it": it}


# field -> code -> language -> word
VALUE_NAMES: Dict[str, Dict[Any, Dict[str, str]]] = {
    "status": {
        ACCEPTED: _words("accepted", "akzeptiert", "accepté", "accettato"),
        REVIEW: _words("to review", "zu prüfen", "à contrôler", "da verificare"),
        REJECTED: _words("rejected", "verworfen", "rejeté", "respinto"),
        MANUAL: _words("added by hand", "von Hand erfasst", "ajouté à la main", "aggiunto a mano"),
    },
    "reviewed": {
        0: _words("no", "nein", "non", "no"),
        1: _words("yes", "ja", "oui", "sì"),
    },
    "colour": {
        "red": _words("red", "rot", "rouge", "rosso"),
        "blue": _words("blue", "blau", "bleu", "blu"),
        "yellow": _words("yellow", "gelb", "jaune", "giallo"),
        "white": _words("white", "weiss", "blanc", "bianco"),
        "green": _words("green", "grün", "vert", "verde"),
        "brown": _words("brown", "braun", "brun", "marrone"),
        "orange": _words("orange", "orange", "orange", "arancione"),
    },
    "shape": {
        "circle": _words("circle", "Kreis", "cercle", "cerchio"),
        "triangle": _words("triangle", "Dreieck", "triangle", "triangolo"),
        "triangle-down": _words("triangle, point down", "Dreieck, Spitze unten", "triangle pointe en bas",
                                "triangolo con la punta in basso"),
        "octagon": _words("octagon", "Achteck", "octogone", "ottagono"),
        "diamond": _words("diamond", "Raute", "losange", "rombo"),
        "square": _words("square", "Quadrat", "carré", "quadrato"),
        "rectangle": _words("rectangle", "Rechteck", "rectangle", "rettangolo"),
        "cross": _words("cross", "Kreuz", "croix", "croce"),
        "pointer": _words("pointer", "Wegweiser", "indicateur de direction", "indicatore di direzione"),
    },
    "format": {
        "small": _words("small", "klein", "petit", "piccolo"),
        "intermediate": _words("intermediate", "mittel", "intermédiaire", "intermedio"),
        "normal": _words("normal", "normal", "normal", "normale"),
        "large": _words("large", "gross", "grand", "grande"),
        "nominal": _words("nominal size", "Nenngrösse", "taille nominale", "dimensione nominale"),
        "measured": _words("as measured", "wie gemessen", "tel que mesuré", "come misurato"),
        "small-1": _words("small, 1 line", "klein, 1 Zeile", "petit, 1 ligne", "piccolo, 1 riga"),
        "small-2": _words("small, 2 lines", "klein, 2 Zeilen", "petit, 2 lignes", "piccolo, 2 righe"),
        "normal-1": _words("normal, 1 line", "normal, 1 Zeile", "normal, 1 ligne", "normale, 1 riga"),
        "normal-2": _words("normal, 2 lines", "normal, 2 Zeilen", "normal, 2 lignes", "normale, 2 righe"),
        "normal-3": _words("normal, 3 lines", "normal, 3 Zeilen", "normal, 3 lignes", "normale, 3 righe"),
        "large-1": _words("large, 1 line", "gross, 1 Zeile", "grand, 1 ligne", "grande, 1 riga"),
        "large-2": _words("large, 2 lines", "gross, 2 Zeilen", "grand, 2 lignes", "grande, 2 righe"),
    },
    "source": {
        "colour": _words("colour", "Farbe", "couleur", "colore"),
        "hole": _words("field inside a ring", "Feld im Ring", "champ dans l'anneau", "campo nell'anello"),
        "frame": _words("white frame", "weisser Rahmen", "cadre blanc", "cornice bianca"),
        "half": _words("half disc", "Halbscheibe", "demi-disque", "mezzo disco"),
        "hough": _words("circle search (Hough)", "Kreissuche (Hough)", "recherche de cercles (Hough)",
                        "ricerca di cerchi (Hough)"),
        "white": _words("white outline", "weisser Umriss", "contour blanc", "contorno bianco"),
        "plate": _words("below its sign", "unter seinem Signal", "sous son signal", "sotto il suo segnale"),
        "text-panel": _words("text panel", "Texttafel", "panneau de texte", "pannello di testo"),
    },
}
LOCALISED_FIELDS = tuple(VALUE_NAMES)


def value_name(field: str, value, language: str):
    """The word for ``value`` of ``field`` in ``language``; values without one (and other fields) as they are."""
    words = VALUE_NAMES.get(field, {}).get(value)
    return value if words is None else words.get(language, words["en"])


def value_map(field: str, language: str) -> Dict[str, Any]:
    """Word -> code of ``field`` in ``language``: what a QGIS value map shows instead of the code."""
    return {words.get(language, words["en"]): code for code, words in VALUE_NAMES[field].items()}


def _check() -> None:
    for field, values in VALUE_NAMES.items():
        for code, words in values.items():
            if set(words) != set(LANGUAGES):
                raise ValueError(f"value names: {field} '{code}' needs a word in each of {', '.join(LANGUAGES)}")
        for language in LANGUAGES:
            shown = [words[language] for words in values.values()]
            if len(set(shown)) != len(shown):
                raise ValueError(f"value names: two {field} values read the same in {language}")


_check()
