"""The output of mapping a drive, declared once: layers, fields, status values, run table.

Writing the GeoPackage (``gpkg/fields.py``), recognising our layers,
the review's reading and writing, the layer styles, the review dock and the run
table all derive from the tables below. Adding an output field is one row in
:data:`FIELDS` (and a test; the golden GeoPackage in ``tests/qgis/golden`` is
regenerated).

A row says how the value is read from a fused sign (``FusedSign``, layer
``signs``), from a detection in its pair (``fusion.Observation``, layer
``detections``) and, for what a person may change by reclassifying, from a
catalogue entry and its chosen format. A layer carries the fields that have a
reader for it, in the order of the table. REAL values are rounded to
``decimals`` when written: more digits than the method measures are noise.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from dataclasses import field as dc_field
from datetime import datetime, timedelta
from typing import Any, Callable, Optional

from ..plates.formats import PLATE_ID, PLATE_NAMES
from ..statuses import ACCEPTED, MANUAL, REJECTED, REVIEW
from .classifier_alternatives import detection_alternatives, format_alternatives, sign_alternatives
from .review_reasons import reason_shown

SIGNS, DETECTIONS = "signs", "detections"
LAYERS = (SIGNS, DETECTIONS)

TEXT, INTEGER, REAL = "text", "integer", "real"

# Languages of names and field aliases: the Swiss catalogue's three and English (catalogue.names).
LANGUAGES = ("en", "de", "fr", "it")
LANGUAGE_NAMES = {"en": "English", "de": "Deutsch", "fr": "Français", "it": "Italiano"}  # as people choose them
DEFAULT_LANGUAGE = "de"

Reader = Callable[..., Any]


def run_language(run: dict) -> str:
    """The language a run table says its output was written in (German for files from before it was recorded)."""
    language = run.get("language")
    return language if language in LANGUAGES else DEFAULT_LANGUAGE


def language_of(locale: str) -> str:
    """The output language of a locale name ("fr_CH", "de", "C"): its language if we have it, else English."""
    code = (locale or "").replace("-", "_").split("_", 1)[0].lower()
    return code if code in LANGUAGES else "en"


@dataclass(frozen=True)
class OutputContext:
    """What a row's values depend on beyond the sign itself: language, the drive's clock, written crops."""

    language: str = DEFAULT_LANGUAGE
    catalogue: Any = None  # template id -> name in ``language``; None: the detection's own (German) name
    start: Optional[datetime] = None  # absolute time of the drive's first pair (drive.json "start_time")
    first_time: float = 0.0  # poses.csv time of the first pair
    crops: dict = dc_field(default_factory=dict)  # sign_id -> crop image path relative to the GeoPackage

    def name(self, template_id: str, fallback: str) -> str:
        from ..catalogue.model import UNKNOWN_ID  # delays OpenCV and numpy until used
        from ..catalogue.names import sign_name, unknown_name  # delays OpenCV and numpy until used

        if template_id == PLATE_ID:
            return PLATE_NAMES.get(self.language, PLATE_NAMES["en"])
        if template_id == UNKNOWN_ID:
            return unknown_name(self.language)
        if self.catalogue is not None and template_id in self.catalogue:
            return sign_name(self.catalogue[template_id], self.language)
        if self.catalogue is not None and getattr(self.catalogue, "folder", None) is not None:
            from ..plates.catalogue import load_plate_templates, template_by_id  # delays numpy until used

            plate = template_by_id(load_plate_templates(self.catalogue.folder), template_id)
            if plate is not None:  # a pictogram plate; English: the German name, as for signs without one
                return plate.name(self.language)
        return fallback

    def timestamp(self, time: Optional[float]) -> Optional[str]:
        """ISO 8601 time of a pair, None when the drive does not state its absolute start."""
        if self.start is None or time is None:
            return None
        return (self.start + timedelta(seconds=float(time) - self.first_time)).isoformat(timespec="milliseconds")


@dataclass(frozen=True)
class Field:
    """One attribute of the output layers.

    ``survey`` fields are what a surveyor reads (the layer lists them first);
    the others record pixels and internals for the review and for checking the method.
    """

    name: str
    kind: str  # TEXT, INTEGER or REAL
    help: str
    aliases: dict = dc_field(default_factory=dict)  # language -> column title
    sign: Optional[Reader] = None  # value of a FusedSign; None: not in the signs layer
    detection: Optional[Reader] = None  # value of an Observation; None: not in the detections layer
    template: Optional[Callable[..., Any]] = None  # (catalogue entry, format name, language) -> value on reclassify
    decimals: Optional[int] = None  # REAL: rounded to this many decimals when written
    length: int = 0  # TEXT: longest value, 0 = unlimited
    required: bool = False  # the review cannot show a feature without it: it marks our layers
    survey: bool = True
    contextual: bool = False  # readers take (item, OutputContext)

    def reader(self, layer: str) -> Optional[Reader]:
        return self.sign if layer == SIGNS else self.detection

    def value(self, layer: str, item, context: Optional[OutputContext] = None) -> Any:
        """The value written for ``item`` in ``layer``: typed, rounded, None for unknown."""
        read = self.reader(layer)
        return self.typed(read(item, context or OutputContext()) if self.contextual else read(item))

    def alias(self, language: str) -> str:
        return self.aliases.get(language) or self.aliases.get("en") or self.name

    def typed(self, value, rounded: bool = True) -> Any:
        """``value`` as this field's Python type (None stays None); REAL rounded to ``decimals`` if ``rounded``."""
        if value is None:
            return None
        if self.kind == REAL:
            value = float(value)
            return value if self.decimals is None or not rounded else round(value, self.decimals)
        return int(value) if self.kind == INTEGER else str(value)


def _both(name: str) -> dict:
    """The same attribute of a fused sign and of an observation."""
    read = operator.attrgetter(name)
    return {"sign": read, "detection": read}


def _best(name: str) -> dict:
    """Of an observation; a fused sign gives its best observation's (the one the review shows first)."""
    return {"sign": lambda sign: getattr(sign.best, name), "detection": lambda obs: getattr(obs, name)}


def _bbox(i: int) -> dict:
    return {"sign": lambda sign: sign.best.bbox[i], "detection": lambda obs: obs.bbox[i]}


def _coordinate(i: int) -> dict:
    return {"sign": lambda item: item.position[i], "detection": lambda item: item.position[i]}


def _sign_name(entry, language: str) -> str:
    from ..catalogue.names import sign_name  # delays OpenCV and numpy until used

    return sign_name(entry, language)


def _review_reason(item) -> Optional[str]:

    return reason_shown(item)


def _alternatives_text(item, sign: bool = False) -> Optional[str]:

    return format_alternatives(sign_alternatives(item) if sign else detection_alternatives(item))


def _names(en: str, de: str, fr: str, it: str) -> dict:
    return {"aliases": {"en": en, "de": de, "fr": fr, "it": it}}


FIELDS = (
    Field("sign_id", INTEGER, "Number of the physical sign, from 1 in order of first sight.", required=True,
          sign=lambda s: s.sign_id, **_names("Sign no.", "Signal-Nr.", "N° signal", "N. segnale")),
    Field("template_id", TEXT, "Catalogue id (SSV number, '-<value>' for a sign with a number), by weighted vote "
          "for a sign.", required=True, template=lambda entry, fmt, lang: entry.id, **_both("template_id"),
          **_names("Sign type (SSV)", "Signaltyp (SSV)", "Type de signal (OSR)", "Tipo di segnale (OSS)")),
    Field("name", TEXT, "Name of the template in the output language (German, French, Italian or English).",
          template=lambda entry, fmt, lang: _sign_name(entry, lang), contextual=True,
          sign=lambda s, ctx: ctx.name(s.template_id, s.name), detection=lambda o, ctx: ctx.name(o.template_id, o.name),
          **_names("Name", "Bezeichnung", "Désignation", "Denominazione")),
    Field("status", TEXT, f"{ACCEPTED}, {REVIEW} (a person should look), {REJECTED} (by a person) or {MANUAL} "
          "(added by a person).", required=True, **_both("status"), **_names("Status", "Status", "Statut", "Stato")),
    Field("reviewed", INTEGER, "1 once a person decided on the feature, else 0.", required=True,
          sign=lambda s: int(s.status == MANUAL), detection=lambda o: int(o.status == MANUAL),
          **_names("Reviewed", "Geprüft", "Contrôlé", "Verificato")),
    Field("review_reason", TEXT, "Why the mapping left it for review: the rule that held it (\"seen in one pair "
          "only\", \"a zone panel's disc read alone\", \"digits read as 50\", ...) or an indicator below its "
          "threshold; empty when the mapping accepted it. A person's decision leaves it as it was.",
          sign=_review_reason, detection=lambda o: _review_reason(o.detection),
          **_names("Review reason", "Prüfgrund", "Motif de contrôle", "Motivo della verifica")),
    Field("easting", REAL, "E coordinate of the face centre in the drive's CRS [m] (as the point geometry).",
          decimals=3, **_coordinate(0), **_names("E [m]", "E [m]", "E [m]", "E [m]")),
    Field("northing", REAL, "N coordinate of the face centre in the drive's CRS [m].", decimals=3, **_coordinate(1),
          **_names("N [m]", "N [m]", "N [m]", "N [m]")),
    Field("elevation", REAL, "Height H of the face centre in the drive's CRS [m].", decimals=3, **_coordinate(2),
          **_names("H [m]", "H [m]", "H [m]", "H [m]")),
    Field("azimuth", REAL, "Direction the face looks towards, degrees clockwise from grid north.", decimals=1,
          sign=lambda s: s.azimuth, **_names("Face azimuth [°]", "Azimut Signalfläche [°]",
                                             "Azimut de la face [°]", "Azimut della faccia [°]")),
    Field("mount_height_m", REAL, "Lower edge of the face above the road [m]; empty when the drive does not state "
          "its camera height.", decimals=2, sign=lambda s: s.mount_height_m,
          **_names("Mounting height [m]", "Montagehöhe [m]", "Hauteur de pose [m]", "Altezza di posa [m]")),
    Field("width_m", REAL, "Standard width of the format [m] (the face's bounding box).",
          template=lambda entry, fmt, lang: entry.formats[fmt][0], **_both("width_m"),
          **_names("Width [m]", "Breite [m]", "Largeur [m]", "Larghezza [m]")),
    Field("height_m", REAL, "Standard height of the format [m] (the face's bounding box).",
          template=lambda entry, fmt, lang: entry.formats[fmt][1], **_both("height_m"),
          **_names("Height of face [m]", "Höhe Signalfläche [m]", "Hauteur de la face [m]",
                   "Altezza della faccia [m]")),
    Field("format", TEXT, "Standard format the measured size was rounded to (e.g. normal, large).",
          template=lambda entry, fmt, lang: fmt, **_both("format"),
          **_names("Format", "Format", "Format", "Formato")),
    Field("plate_of", INTEGER, "A supplementary plate: the number of the sign it belongs to (signs.sign_id); empty "
          "for a sign.", sign=lambda s: s.plate_of,
          **_names("Plate of sign no.", "Zusatztafel zu Signal-Nr.", "Plaque du signal n°", "Tavola del segnale n.")),
    Field("text", TEXT, "Text of a plate or of a white text panel (place name, destinations) as read by OCR, "
          "normalised (\"200 m\", \"7–19 h\", \"Mo–Fr\"), lines joined by ' / '; for a speed limit the number "
          "its digits read (a sign whose digits read another speed limit's number goes to review); empty when "
          "not read (no Tesseract) or none of these.", sign=lambda s: s.text,
          **_names("Text", "Text", "Texte", "Testo")),
    Field("text_confidence", REAL, "Confidence of the text, 0-1: OCR confidence of the readings that agree on it, "
          "over all readings of the plate (a speed limit: the share of its views that read that number).",
          decimals=3, sign=lambda s: s.text_confidence,
          **_names("Text confidence", "Textsicherheit", "Fiabilité du texte", "Affidabilità del testo")),
    Field("timestamp", TEXT, "Date and time (ISO 8601) of the pair the sign was seen best in (a detection: its "
          "pair); empty when drive.json does not state the drive's start_time.", contextual=True,
          sign=lambda s, ctx: ctx.timestamp(s.best.time), detection=lambda o, ctx: ctx.timestamp(o.time),
          **_names("Recorded", "Aufnahmezeit", "Date de prise de vue", "Data di ripresa")),
    Field("detection_indicator", REAL, "Planar share of the face, 0-1: is it a sign? Mean of the voters for a sign.",
          decimals=4, **_both("detection_indicator"),
          **_names("Detection indicator", "Detektionsindikator", "Indicateur de détection",
                   "Indicatore di rilevamento")),
    Field("classification_indicator", REAL, "Classification score, 0-1: is it this sign? The network's calibrated "
          "probability (template matching: its correlation). Mean of the voters for a sign.", decimals=4,
          **_both("classification_indicator"),
          **_names("Classification indicator", "Klassifikationsindikator", "Indicateur de classification",
                   "Indicatore di classificazione")),
    Field("alternatives", TEXT, "The classifier's next choices after this id, best first, with their scores "
          "(\"2.12 0.22, 2.30-40 0.06\"; a sign's pooled over its observations): the review offers them first.",
          sign=lambda s: _alternatives_text(s, sign=True), detection=lambda o: _alternatives_text(o.detection),
          **_names("Next choices", "Nächste Wahl", "Choix suivants", "Scelte successive")),
    Field("n_obs", INTEGER, "Number of detections fused into the sign.", required=True, sign=lambda s: s.n_obs,
          **_names("Observations", "Beobachtungen", "Observations", "Osservazioni")),
    Field("vote_share", REAL, "Share of the weighted vote its template won, 0-1.", decimals=3,
          sign=lambda s: s.vote_share, **_names("Vote share", "Stimmenanteil", "Part des votes", "Quota di voti")),
    Field("sigma_m", REAL, "Estimated 3D standard error of the position [m]: from each view's stereo precision "
          "(worse along the line of sight, with the square of the depth), widened when the views scatter more than "
          "that; empty where it cannot be estimated (a sign added by hand).", decimals=4,
          sign=lambda s: s.sigma_m, **_names("Position σ [m]", "Positions-σ [m]", "σ de position [m]",
                                            "σ della posizione [m]")),
    Field("sigma_along_m", REAL, "Its part along the mean line of sight from the camera [m]: depth from stereo is "
          "least sure there.", decimals=4, sign=lambda s: s.sigma_along_m,
          **_names("σ along line of sight [m]", "σ längs Sichtlinie [m]", "σ le long de la visée [m]",
                   "σ lungo la linea di vista [m]")),
    Field("sigma_across_m", REAL, "Its part across the line of sight, per axis (sideways and in height) [m].",
          decimals=4, sign=lambda s: s.sigma_across_m,
          **_names("σ across line of sight [m]", "σ quer zur Sichtlinie [m]", "σ en travers de la visée [m]",
                   "σ trasversale alla linea di vista [m]")),
    Field("crop_path", TEXT, "Image crop of the sign from its best pair, relative to the GeoPackage (written when "
          "asked for), so the sign can be checked without the drive.", contextual=True,
          sign=lambda s, ctx: ctx.crops.get(s.sign_id),
          **_names("Image crop", "Bildausschnitt", "Extrait d'image", "Ritaglio d'immagine")),
    Field("colour", TEXT, "Dominant colour segmented: red, blue, yellow (or white).", survey=False,
          template=lambda entry, fmt, lang: entry.colour, **_both("colour"),
          **_names("Colour", "Farbe", "Couleur", "Colore")),
    Field("shape", TEXT, "Shape of the face: circle, triangle, triangle-down, octagon, diamond, square, rectangle.",
          survey=False, template=lambda entry, fmt, lang: entry.shape, **_both("shape"),
          **_names("Shape", "Form", "Forme", "Forma")),
    Field("source", TEXT, "How the face was found: colour segmentation or the Hough fallback for round signs.",
          survey=False, **_best("source"), **_names("Found by", "Gefunden durch", "Trouvé par", "Trovato da")),
    Field("best_pair_id", TEXT, "Pair of the best observation, the one the review shows first.", required=True,
          survey=False, sign=lambda s: s.best.pair_id,
          **_names("Best pair", "Bestes Bildpaar", "Meilleure paire", "Coppia migliore")),
    Field("pair_id", TEXT, "Stereo pair (poses.csv id) the detection was made in.", required=True, survey=False,
          detection=lambda o: o.pair_id, **_names("Pair", "Bildpaar", "Paire", "Coppia")),
    Field("time", REAL, "Time of that pair as in poses.csv [s].", survey=False, **_best("time"),
          **_names("Pair time [s]", "Zeit Bildpaar [s]", "Temps de la paire [s]", "Tempo della coppia [s]")),
    Field("u", REAL, "Column of the face centre in the left image [px].", decimals=2, required=True, survey=False,
          **_best("u"), **_names("u [px]", "u [px]", "u [px]", "u [px]")),
    Field("v", REAL, "Row of the face centre in the left image [px].", decimals=2, required=True, survey=False,
          **_best("v"), **_names("v [px]", "v [px]", "v [px]", "v [px]")),
    Field("bbox_x", INTEGER, "Left column of the face's box in the left image [px].", required=True, survey=False,
          **_bbox(0), **_names("Box x [px]", "Box x [px]", "Cadre x [px]", "Riquadro x [px]")),
    Field("bbox_y", INTEGER, "Top row of the face's box [px].", required=True, survey=False, **_bbox(1),
          **_names("Box y [px]", "Box y [px]", "Cadre y [px]", "Riquadro y [px]")),
    Field("bbox_w", INTEGER, "Width of the face's box [px].", required=True, survey=False, **_bbox(2),
          **_names("Box width [px]", "Box Breite [px]", "Cadre largeur [px]", "Riquadro larghezza [px]")),
    Field("bbox_h", INTEGER, "Height of the face's box [px].", required=True, survey=False, **_bbox(3),
          **_names("Box height [px]", "Box Höhe [px]", "Cadre hauteur [px]", "Riquadro altezza [px]")),
    Field("depth_m", REAL, "Depth of the face centre along the optical axis [m].", decimals=3, survey=False,
          **_best("depth_m"), **_names("Depth [m]", "Tiefe [m]", "Profondeur [m]", "Profondità [m]")),
    Field("sign_id", INTEGER, "The sign this detection was fused into (signs.sign_id).", survey=False,
          detection=lambda o: o.sign_id, **_names("Sign no.", "Signal-Nr.", "N° signal", "N. segnale")),
)


def fields(layer: str) -> tuple[Field, ...]:
    """The fields of ``layer`` in their order."""
    if layer not in LAYERS:
        raise ValueError(f"no output layer '{layer}'; the layers are {', '.join(LAYERS)}")
    return tuple(f for f in FIELDS if f.reader(layer) is not None)


def field(layer: str, name: str) -> Field:
    for f in fields(layer):
        if f.name == name:
            return f
    raise KeyError(f"layer '{layer}' has no field '{name}'")


def required_names(layer: str) -> set[str]:
    """Names a layer must have to be one of ours: what the review cannot do without."""
    return {f.name for f in fields(layer) if f.required}


def values(layer: str, item, context: Optional[OutputContext] = None) -> dict:
    """Field name -> written value of a fused sign (``signs``) or an observation (``detections``)."""
    return {f.name: f.value(layer, item, context) for f in fields(layer)}


def template_values(layer: str, entry, format_name: str, language: str = DEFAULT_LANGUAGE) -> dict:
    """What reclassifying as catalogue ``entry`` in format ``format_name`` writes (its name in ``language``)."""
    return {f.name: f.typed(f.template(entry, format_name, language)) for f in fields(layer)
            if f.template is not None}


def _check() -> None:
    for layer in LAYERS:
        names = [f.name for f in fields(layer)]
        duplicates = {n for n in names if names.count(n) > 1}
        if duplicates:
            raise ValueError(f"output schema: layer '{layer}' lists {', '.join(sorted(duplicates))} twice")
        survey = [f.survey for f in fields(layer)]
        if True in survey[survey.index(False):] if False in survey else False:
            raise ValueError(f"output schema: layer '{layer}' lists a survey field after an internal one")
    for f in FIELDS:
        if f.kind not in (TEXT, INTEGER, REAL) or not f.help or (f.sign is None and f.detection is None):
            raise ValueError(f"output schema: field '{f.name}' needs a kind, help text and a layer")
        if set(f.aliases) != set(LANGUAGES):
            raise ValueError(f"output schema: field '{f.name}' needs an alias in each of {', '.join(LANGUAGES)}")


_check()
