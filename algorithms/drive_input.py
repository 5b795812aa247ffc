"""Opening a drive from an algorithm: core errors become QgsProcessingException messages, warnings the log;
the drive's CRS as QGIS 3.22 can hold it."""

from __future__ import annotations

from qgis.core import QgsCoordinateReferenceSystem, QgsProcessingException

from ..signmapper_core.errors import DriveFormatError


def open_drive_or_raise(folder: str, feedback=None):
    """Validate and open the drive; a format error is raised as the user-facing message.

    ``feedback`` (a ``CoreFeedback``) shows progress, cancels (``progress.Cancelled``) and logs the
    drive's warnings (implausible values, an ignored truth.csv).
    """
    from ..signmapper_core.drive.reader import open_drive  # delays numpy until used

    if not folder:
        raise QgsProcessingException("No drive folder given.")
    try:
        if feedback is None:
            return open_drive(folder)
        drive = open_drive(folder, progress=feedback.progress, is_cancelled=feedback.is_cancelled)
    except DriveFormatError as exc:
        raise QgsProcessingException(f"Invalid drive: {exc}") from exc
    for warning in drive.warnings:
        feedback.warn(warning)
    return drive


def qgis_crs(crs_text: str) -> tuple[QgsCoordinateReferenceSystem, str]:
    """(QGIS CRS, note for the log) of a drive's CRS string; the note is empty when nothing was changed.

    QGIS 3.22 reads neither a compound CRS (``EPSG:2056+5728``) nor every PROJ
    string by name; a layer would then say "Undefined geographic SRS". Such a CRS
    becomes its horizontal part (by authority code where it has one, else from
    PROJ's WKT): positions are written as they are, heights keep their meaning.
    """
    crs = QgsCoordinateReferenceSystem(crs_text)
    if crs.isValid():
        return crs, ""
    from pyproj import CRS

    parsed = CRS.from_user_input(crs_text)
    horizontal = parsed.sub_crs_list[0] if parsed.is_compound else parsed
    authority = horizontal.to_authority(min_confidence=90)
    candidates = [QgsCoordinateReferenceSystem(":".join(authority))] if authority else []
    if crs_text.lstrip().startswith("+"):
        candidates.append(QgsCoordinateReferenceSystem.fromProj(crs_text))
    candidates.append(QgsCoordinateReferenceSystem.fromWkt(horizontal.to_wkt()))
    crs = next((c for c in candidates if c.isValid()), None)
    if crs is None:
        raise QgsProcessingException(f"QGIS cannot represent the drive's CRS {crs_text!r}")
    name = crs.authid() or crs.description() or "a custom CRS"
    if parsed.is_compound:
        return crs, (f"CRS {crs_text}: the layers carry its horizontal part {name} (QGIS 3.22 has no compound CRS); "
                     f"heights are those of {parsed.sub_crs_list[1].name}")
    return crs, f"CRS {crs_text}: the layers carry it as {name}"
