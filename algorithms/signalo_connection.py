"""Opening the Signalo database a user names: a QGIS PostgreSQL connection, a pg_service name, or libpq parameters."""

from __future__ import annotations

from qgis.core import (
    QgsDataSourceUri,
    QgsProcessingException,
    QgsProcessingParameterProviderConnection,
    QgsProviderRegistry,
)

from ..signmapper_core.signalo import SignaloError, connect

HELP = ("Signalo database: one of the PostgreSQL connections saved in QGIS (Browser ▸ PostgreSQL ▸ New "
        "Connection; a connection may name a pg_service.conf service). From qgis_process, a script or a model it "
        "may also be a service written service=NAME, or libpq parameters such as 'host=… dbname=signalo user=…'.")


def signalo_parameter(name: str, description: str, optional: bool = False):
    """The chooser of QGIS's saved PostgreSQL connections (its value stays text: see ``conninfo``)."""
    return QgsProcessingParameterProviderConnection(name, description, "postgres", optional=optional)


def conninfo(text: str) -> tuple[str, str]:
    """(libpq connection string, how to name it in messages) for what the user typed."""
    text = (text or "").strip()
    if not text:
        raise QgsProcessingException("No Signalo database given.")
    metadata = QgsProviderRegistry.instance().providerMetadata("postgres")
    connections = metadata.connections() if metadata is not None else {}
    if text in connections:
        uri = QgsDataSourceUri(connections[text].uri())
        return uri.connectionInfo(True), f"QGIS connection '{text}'"
    if "=" in text or text.startswith(("postgresql://", "postgres://")):
        shown = " ".join(p for p in text.split() if not p.startswith("password="))
        return text, f"database '{shown}'"
    saved = ", ".join(connections) or "none saved"
    raise QgsProcessingException(f"'{text}' is neither a QGIS PostgreSQL connection ({saved}) nor a service=NAME "
                                 "or libpq parameters.")


def open_signalo(text: str):
    """(psycopg2 connection, name for messages); QgsProcessingException with the reason if it cannot be opened."""

    info, where = conninfo(text)
    try:
        return connect(info, where), where
    except SignaloError as exc:
        raise QgsProcessingException(str(exc)) from exc
