"""Readers of KITTI raw's text files: ``key: numbers`` calibrations, OXTS packets, timestamps.

Formats as the KITTI raw data development kit describes them (Geiger et al. 2013):
calibration lines ``name: v1 v2 ...`` (``calib_time`` is text); one OXTS packet
of 30 numbers per frame in ``oxts/data/<frame>.txt`` (lat, lon, alt, roll,
pitch, yaw first; angles in radians); ``timestamps.txt`` with one
``YYYY-MM-DD HH:MM:SS.fffffffff`` per frame.
"""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import numpy as np

from ..errors import ImportInputError

OXTS_VALUES = 30


def read_key_values(path) -> dict[str, np.ndarray]:
    """Numeric entries of a KITTI calibration file; text entries (calib_time) are skipped."""
    path = Path(path)
    values: dict[str, np.ndarray] = {}
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise ImportInputError(path, f"cannot read it ({exc})") from None
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        key, sep, rest = line.partition(":")
        if not sep:
            raise ImportInputError(path, f"expected 'name: values', found {line.strip()[:60]!r}", line=number)
        try:
            values[key.strip()] = np.array([float(v) for v in rest.split()], dtype=float)
        except ValueError:
            continue  # a text entry such as calib_time
    return values


def read_oxts(path) -> np.ndarray:
    """The 30 numbers of one OXTS packet file."""
    path = Path(path)
    try:
        numbers = np.array(path.read_text(encoding="utf-8").split(), dtype=float)
    except (OSError, UnicodeDecodeError) as exc:
        raise ImportInputError(path, f"cannot read it ({exc})") from None
    except ValueError:
        raise ImportInputError(path, "holds something that is not a number", line=1) from None
    if numbers.size != OXTS_VALUES:
        raise ImportInputError(path, f"an OXTS packet has {OXTS_VALUES} numbers, found {numbers.size}", line=1)
    return numbers


def read_timestamps(path) -> list[datetime]:
    """One datetime per line of a KITTI ``timestamps.txt`` (nanoseconds cut to microseconds)."""
    path = Path(path)
    if not path.is_file():
        raise ImportInputError(path, "required file is missing")
    stamps = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        text = line.strip()
        if not text:
            continue
        day, _, clock = text.partition(" ")
        whole, _, fraction = clock.partition(".")
        try:
            stamps.append(datetime.fromisoformat(f"{day} {whole}.{(fraction + '000000')[:6]}"))
        except ValueError:
            raise ImportInputError(path, f"{text!r} is not a time like 2011-09-26 13:02:25.964389445",
                                   line=number) from None
    return stamps
