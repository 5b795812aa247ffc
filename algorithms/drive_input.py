"""Opening a drive from an algorithm: core errors become QgsProcessingException messages."""

from __future__ import annotations

from qgis.core import QgsProcessingException


def open_drive_or_raise(folder: str, progress=None):
    """Validate and open the drive; a format error is raised as the user-facing message."""
    from ..signmapper_core.drive import open_drive
    from ..signmapper_core.errors import DriveFormatError

    if not folder:
        raise QgsProcessingException("No drive folder given.")
    try:
        return open_drive(folder, progress=progress)
    except DriveFormatError as exc:
        raise QgsProcessingException(f"Invalid drive: {exc}") from exc
