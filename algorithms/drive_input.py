"""Opening a drive from an algorithm: core errors become QgsProcessingException messages."""

from __future__ import annotations

from qgis.core import QgsProcessingException


def open_drive_or_raise(folder: str, feedback=None):
    """Validate and open the drive; a format error is raised as the user-facing message.

    ``feedback`` (a ``CoreFeedback``) shows progress and cancels; a cancel raises ``progress.Cancelled``.
    """
    from ..signmapper_core.drive import open_drive
    from ..signmapper_core.errors import DriveFormatError

    if not folder:
        raise QgsProcessingException("No drive folder given.")
    try:
        if feedback is None:
            return open_drive(folder)
        return open_drive(folder, progress=feedback.progress, is_cancelled=feedback.is_cancelled)
    except DriveFormatError as exc:
        raise QgsProcessingException(f"Invalid drive: {exc}") from exc
