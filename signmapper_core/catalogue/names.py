"""Sign names in the output language; English names of the Swiss signs (SSV numbers) for the output language en.

Kept apart from the sign definitions (``signs_ch.py`` carries the official
German, French and Italian names); a catalogue of another country, or an id
not listed here, falls back on the entry's German name.
"""

from __future__ import annotations

NAMES_EN = {
    "1.01": "Bend to the right", "1.02": "Bend to the left", "1.03": "Double bend, first to the right",
    "1.04": "Double bend, first to the left", "1.05": "Slippery road", "1.06": "Uneven road",
    "1.07": "Road narrows", "1.08": "Road narrows on the right", "1.09": "Road narrows on the left",
    "1.10": "Dangerous descent", "1.11": "Steep ascent", "1.12": "Loose chippings", "1.13": "Falling rocks",
    "1.14": "Road works", "1.15": "Level crossing with barriers", "1.16": "Level crossing without barriers",
    "1.18": "Tramway", "1.22": "Pedestrian crossing", "1.23": "Children", "1.24": "Wild animals",
    "1.25": "Animals", "1.26": "Two-way traffic", "1.27": "Traffic lights", "1.30": "Other dangers",
    "1.31": "Queues", "1.32": "Cyclists",
    "2.01": "No vehicles in either direction", "2.02": "No entry", "2.03": "No motor cars",
    "2.04": "No motorcycles", "2.05": "No cycles or mopeds", "2.06": "No mopeds", "2.07": "No lorries",
    "2.08": "No coaches", "2.09": "No trailers", "2.10.1": "No vehicles carrying dangerous goods",
    "2.11": "No vehicles carrying goods that may pollute water", "2.12": "No animals",
    "2.13": "No motor cars or motorcycles", "2.14": "No motor cars, motorcycles or mopeds",
    "2.15": "No pedestrians", "2.16-3.5": "Maximum weight", "2.17-10": "Maximum axle load",
    "2.18-2.3": "Maximum width", "2.19-3.8": "Maximum height", "2.20-10": "Maximum length",
    "2.30-20": "Speed limit 20", "2.30-30": "Speed limit 30", "2.30-40": "Speed limit 40",
    "2.30-50": "Speed limit 50", "2.30-60": "Speed limit 60", "2.30-70": "Speed limit 70",
    "2.30-80": "Speed limit 80", "2.30-100": "Speed limit 100", "2.30-120": "Speed limit 120",
    "2.30.1": "General speed limit 50", "2.31-60": "Minimum speed", "2.32": "Turn right ahead (compulsory)",
    "2.33": "Turn left ahead (compulsory)", "2.34": "Keep right", "2.35": "Keep left", "2.36": "Ahead only",
    "2.37": "Turn right", "2.38": "Turn left", "2.39": "Turn right or left", "2.40": "Ahead or turn right",
    "2.41": "Ahead or turn left", "2.41.1": "Roundabout", "2.42": "No right turn", "2.43": "No left turn",
    "2.44": "No overtaking", "2.45": "No overtaking for lorries", "2.46": "No U-turn",
    "2.47-70": "Minimum distance", "2.48": "Snow chains compulsory", "2.49": "No stopping",
    "2.50": "No parking", "2.53-50": "End of speed limit", "2.53-60": "End of speed limit 60",
    "2.55": "End of no overtaking", "2.56": "End of no overtaking for lorries", "2.58": "End of all prohibitions",
    "2.53.1": "End of general speed limit 50",
    "2.59.1-30": "30 km/h zone", "2.59.2-30": "End of 30 km/h zone", "2.59.3": "Pedestrian zone",
    "2.59.4": "End of pedestrian zone", "2.59.5": "Shared zone", "2.59.6": "End of shared zone",
    "2.60": "Cycle path", "2.61": "Footpath", "2.62": "Bridleway", "2.63": "Segregated cycle and footpath",
    "2.63.1": "Shared cycle and footpath", "2.64": "Bus lane",
    "3.01": "Stop", "3.02": "Give way", "3.03": "Priority road", "3.04": "End of priority road",
    "3.05": "Junction with a minor road", "3.06": "Junction with priority to the right",
    "3.07": "Minor road joining from the right", "3.08": "Minor road joining from the left",
    "3.09": "Give way to oncoming traffic", "3.10": "Priority over oncoming traffic",
    "4.08": "One-way street", "4.09": "No through road", "4.11": "Pedestrian crossing here",
    "4.14": "Hospital", "4.17": "Parking", "4.18": "Parking with parking disc", "4.20": "Paid parking",
    "4.29": "Place name (secondary road)", "4.30": "End of place (secondary road)",
    "4.33": "Direction sign (secondary road)",
}


# the name of the open set's id (model.UNKNOWN_ID): a sign-like face no catalogue entry matches well
UNKNOWN_NAMES = {"de": "Unbekanntes Signal", "fr": "Signal inconnu", "it": "Segnale sconosciuto",
                 "en": "Unknown sign"}


def unknown_name(language: str) -> str:
    return UNKNOWN_NAMES.get(language, UNKNOWN_NAMES["en"])


def sign_name(entry, language: str) -> str:
    """The name of a catalogue entry in ``language`` (de, fr, it, en); German where that name is unknown."""
    if language == "en":
        return entry.names.get("en") or NAMES_EN.get(entry.id) or entry.name("de")
    return entry.names.get(language) or entry.name("de")
