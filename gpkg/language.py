"""The output language QGIS is set to: its user-interface locale, when it is one we write (de, fr, it, en)."""

from __future__ import annotations

from qgis.core import QgsSettings
from qgis.PyQt.QtCore import QLocale

from ..signmapper_core.output.schema import language_of


def qgis_language() -> str:
    """de, fr, it or en from QGIS's locale (the override in its options, else the system's)."""
    settings = QgsSettings()
    locale = settings.value("locale/userLocale", "") or ""
    if not settings.value("locale/overrideFlag", False, type=bool) or not locale:
        locale = QLocale.system().name()
    return language_of(locale)
