"""The drive's absolute clock: poses.csv times are seconds on any clock; drive.json may say when the drive began.

``start_time`` is a writer key of drive.json (the format lets writers add keys):
the ISO 8601 date and time of the first pair, e.g. ``"2026-05-04T09:12:03.200+02:00"``.
With it the output gets ISO timestamps; without it, only the seconds of poses.csv.
"""

from __future__ import annotations

from datetime import datetime
from typing import Optional

from ..errors import DriveFormatError

START_KEY = "start_time"


def drive_start(drive) -> Optional[datetime]:
    """When the first pair was recorded, None when drive.json does not say; a malformed value is an error."""
    text = drive.metadata.get(START_KEY)
    if text is None or text == "":
        return None
    path = drive.root / "drive.json"
    if not isinstance(text, str):
        raise DriveFormatError(path, f"must be an ISO 8601 date and time as text, not {text!r}", field=START_KEY)
    try:
        return datetime.fromisoformat(text.strip().replace("Z", "+00:00"))
    except ValueError:
        raise DriveFormatError(path, f"{text!r} is not an ISO 8601 date and time such as "
                               "2026-05-04T09:12:03+02:00", field=START_KEY) from None


def first_time(drive) -> float:
    return drive.pairs[0].time if drive.pairs else 0.0
