"""Supplementary plates across pairs: one feature per physical plate, linked to its sign, with its text.

The plates found in each pair (``pipeline/plates.py``) are fused like signs
(the same tracks, gates and robust position, :mod:`fusion`), after the signs,
so each plate is linked to the fused sign its observations' signs went into
(by weighted vote: ``plate_of``). Its text is then read from the crops of its
nearest observations, all plates of a run in one OCR call, and decided by vote
over what was read (normalised, :mod:`plate_text`); the text confidence is the
winner's summed OCR confidence over all readings of that plate. Without
Tesseract the plates are mapped without text, and the run says once how to
install it. A pictogram plate (classified in the pairs) is not read: its text is
the words its drawing carries.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import replace
from typing import Callable, Optional, Sequence

from ..catalogue.text_panels import is_text_panel
from ..fusion.precision import StereoPrecision
from ..fusion.signs import FusedSign, FusionConfig, Observation, _merge_tracks, build_tracks, fuse_track
from ..geometry import Camera
from ..progress import WarnCallback, send_warning
from .formats import PLATE_ID
from .ocr import OcrError, OcrUnavailable, read_texts
from .text import is_plate_line, normalise_text
from .types import text_plate_id


def is_plate(observation: Observation) -> bool:
    return getattr(observation.detection, "plate_of", None) is not None


def fuse_plates(observations: Sequence[Observation], signs: Sequence[FusedSign], camera: Camera,
                config: Optional[FusionConfig] = None) -> list[FusedSign]:
    """One :class:`FusedSign` per physical plate (``plate_of`` = its sign's id), numbered after ``signs``.

    ``observations``: every observation of the run (signs and plates); the signs'
    ``sign_id`` must be set (:func:`fusion.fuse_observations`). Each plate
    observation's ``sign_id`` is set to its plate. ``camera``: the drive's, as for the signs.
    """
    config = config or FusionConfig()
    precision = StereoPrecision.of(camera, config)
    sign_of = {id(o.detection): o.sign_id for o in observations if not is_plate(o)}
    plates = [o for o in observations if is_plate(o)]
    tracks = _merge_tracks(build_tracks(plates, config, precision), config, precision)
    tracks.sort(key=lambda t: (t[0].pair_index, t[0].position[0], t[0].position[1]))
    first = max((s.sign_id for s in signs), default=0) + 1
    # a plate's indicator is the plate step's own score, not the network's probability: the signs' margin
    # (accept_margin, set on the network's misreadings) does not apply to it
    plate_config = replace(config, accept_margin=0.0)
    fused = []
    for number, track in enumerate(tracks, start=first):
        plate = fuse_track(number, track, plate_config, precision)
        votes = defaultdict(float)
        for obs in track:
            host = sign_of.get(id(obs.detection.plate_of))
            if host is not None:
                votes[host] += max(obs.detection_indicator * obs.classification_indicator, 1e-3)
        plate.plate_of = max(votes, key=votes.get) if votes else None
        for obs in track:
            obs.sign_id = number
        fused.append(plate)
    return fused


def reading_crops(plate: FusedSign, per_plate: int, min_seen: float = 1.0) -> list:
    """The crops its text is read from: those of its ``per_plate`` largest (nearest) observations that saw it
    whole (``Detection.crop_seen`` at least ``min_seen``), then, if fewer, the largest of the others: a view
    cut by the image's edge or by a branch reads part of the text, and its larger letters do not make up for it.
    Only the observations of the plate's id give crops (a layout plate's crop holds its text field only, a text
    plate's all of it), unless none of them has one."""
    cropped = [o for o in plate.observations if getattr(o.detection, "crop", None) is not None]
    own = [o for o in cropped if o.template_id == plate.template_id] or cropped
    seen = sorted(own, key=lambda o: (getattr(o.detection, "crop_seen", 1.0) >= min_seen, o.bbox[3]), reverse=True)
    return [o.detection.crop for o in seen[:per_plate]]


def vote_text(readings, config: Optional[FusionConfig] = None) -> tuple[Optional[str], Optional[float]]:
    """(text, confidence) of one plate from its readings: the normalised text with the largest summed OCR
    confidence (x ``plate_well_formed_weight`` for a reading whose lines all have a form plates print,
    ``is_plate_line``); confidence = its summed OCR confidence over the number of readings. (None, None) when
    nothing was read."""
    well_formed = (config or FusionConfig()).plate_well_formed_weight
    weights = defaultdict(float)
    for reading in readings:
        text = normalise_text(reading.lines)
        if text:  # a reading in the forms plates print counts twice: a misreading rarely is one
            weights[text] += reading.confidence * (well_formed if _well_formed(text) else 1.0)
    if not weights:
        return None, None
    # a view that read only some of a plate's lines (one line cut, faint or hidden) supports the well-formed
    # reading that holds them too: 'Anwohner' is a part of 'ausgenommen / Anwohner', not a rival of it
    support = {text: weight + sum(w for other, w in weights.items() if _part_of(other, text))
               if _well_formed(text) else weight
               for text, weight in weights.items()}
    text = max(support, key=support.get)
    confidence = sum(r.confidence for r in readings if normalise_text(r.lines) == text)
    return text, confidence / len(readings)


def _well_formed(text: str) -> bool:
    """Whether every line of a normalised plate text has a form plates print (``is_plate_line``)."""
    return all(is_plate_line(line) for line in text.split(" / "))


def _part_of(part: str, text: str) -> bool:
    """Whether the lines of ``part`` are a run of fewer of the lines of ``text``."""
    a, b = part.split(" / "), text.split(" / ")
    return len(a) < len(b) and any(b[i:i + len(a)] == a for i in range(len(b) - len(a) + 1))


def read_by_ocr(feature: FusedSign) -> bool:
    """Whether a feature's text is read by OCR: a white text panel (a place's name, destinations), a text plate,
    or a layout plate (whose observations of its id carry no printed words: ``Detection.printed_text`` None)."""
    if is_text_panel(feature.template_id) or feature.template_id == PLATE_ID:
        return True
    own = [o for o in feature.observations if o.template_id == feature.template_id]
    return is_plate_feature(feature) and any(getattr(o.detection, "printed_text", "") is None for o in own)


def is_plate_feature(feature: FusedSign) -> bool:
    """Whether a fused feature is a plate: it has a sign (``plate_of``) or its observations are plates'."""
    return feature.plate_of is not None or any(is_plate(o) for o in feature.observations)


def read_plate_texts(plates: Sequence[FusedSign], warn: Optional[WarnCallback] = None,
                     read: Callable = read_texts, config: Optional[FusionConfig] = None) -> int:
    """Set each plate's (and text panel's) ``text`` and ``text_confidence``; returns the number with a text.

    One OCR run for all of them, shared over the cores (``config``: the run's fusion settings; default
    ``FusionConfig()``). Without
    Tesseract (or when it fails) they keep no text and ``warn`` hears once why and how to install it.
    """
    config = config or FusionConfig()
    owners, crops = [], []
    for k, plate in enumerate(plates):
        if not read_by_ocr(plate):  # a pictogram plate: the words of its drawing, no OCR
            plate.text, plate.text_confidence = printed_text(plate)
            continue
        for crop in reading_crops(plate, config.plate_readings, config.plate_min_seen_whole):
            owners.append(k)
            crops.append(crop)
    if not crops:
        return sum(p.text is not None for p in plates)
    try:
        readings = read(crops, config)
    except (OcrUnavailable, OcrError) as exc:
        send_warning(warn, f"{len(set(owners))} supplementary plates or text panels mapped without their text: {exc}")
        return sum(p.text is not None for p in plates)
    by_plate = defaultdict(list)
    for k, reading in zip(owners, readings):
        by_plate[k].append(reading)
    done = 0
    for k, plate in enumerate(plates):
        if read_by_ocr(plate):
            plate.text, plate.text_confidence = vote_text(by_plate.get(k, []), config)
            if plate.template_id == PLATE_ID:  # a text plate: typed by what it says
                plate.template_id = text_plate_id(plate.text)
        done += plate.text is not None
    return done


def printed_text(plate: FusedSign) -> tuple[Optional[str], Optional[float]]:
    """(words, share of its observations of its id that carry them) of a pictogram plate: the words of the
    drawing (language version) most of them matched; (None, None) for a pictogram alone."""
    votes = defaultdict(int)
    same = [o for o in plate.observations if o.template_id == plate.template_id]
    for obs in same:
        votes[getattr(obs.detection, "printed_text", None) or ""] += 1
    words = max(votes, key=votes.get) if votes else ""
    return (words, votes[words] / len(same)) if words else (None, None)
