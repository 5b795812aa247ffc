"""Signalo (opengisch/signalo), the PostgreSQL/PostGIS sign inventory Swiss road owners keep in QGIS.

``export`` writes mapped signs into it, ``inventory`` reads it for change
detection, ``schema`` checks a database is a Signalo version we can use,
``types`` translates sign types. The caller passes a DB-API connection
(psycopg2), ``connect`` opens one from libpq connection parameters.
"""

from .schema import SignaloError

# how mapped signs become Signalo's supports and azimuts (export.plan_supports)
POLE_RADIUS_M = 0.3  # signs closer than this on the plan stand on one pole
AZIMUTH_GAP_DEG = 30.0  # faces of one pole whose directions differ less than this share an azimut


def connect(conninfo: str, where: str = ""):
    """A psycopg2 connection; SignaloError naming the database and the reason if it cannot be opened."""
    try:
        import psycopg2
    except ImportError as exc:  # Debian: python3-psycopg2
        raise SignaloError("psycopg2 is not installed (Debian package python3-psycopg2)") from exc
    try:
        return psycopg2.connect(conninfo, connect_timeout=10)
    except psycopg2.Error as exc:
        raise SignaloError(f"cannot connect to {where or 'the Signalo database'}: {str(exc).strip()}") from exc


__all__ = ["AZIMUTH_GAP_DEG", "POLE_RADIUS_M", "SignaloError", "connect"]
