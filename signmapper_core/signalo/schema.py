"""Is this a Signalo database Sign Mapper can read and write? The version and the columns we use.

Signalo is installed with pum, which records each data-model version in
``signalo_db.pum_migrations``. Sign Mapper writes the 1.x model from version 1.2
on (the version that named the columns it uses: ``fk_hanging_mode``,
``fk_mounting_point``, ``needs_validation``); every column it touches is
checked too, so a database changed by hand is refused before anything is
written, with the table and column named.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

SCHEMA = "signalo_db"
MIN_VERSION = (1, 2)
MAX_MAJOR = 1

# table -> columns Sign Mapper reads or writes
COLUMNS = {
    "support": ("id", "geometry", "height_free_under_signal", "comment", "needs_validation",
                "_creation_user", "_last_modification_user", "_last_modification_date"),
    "azimut": ("id", "fk_support", "azimut", "_creation_user"),
    "frame": ("id", "fk_azimut", "rank", "dimension_1", "dimension_2", "fk_mounting_point", "comment",
              "_creation_user"),
    "sign": ("id", "fk_frame", "rank", "fk_sign_type", "fk_official_sign", "inscription_1", "inscription_2",
             "inscription_3", "fk_hanging_mode",
             "dimension_1", "dimension_2", "comment", "needs_validation", "_creation_user",
             "_last_modification_user", "_last_modification_date"),
    "vl_official_sign": ("id", "value_de", "no_dynamic_inscription"),
}
OFFICIAL_SIGN_TYPE = 11  # vl_sign_type: 'officiel'


class SignaloError(RuntimeError):
    """The database cannot be used; nothing was written."""


@dataclass(frozen=True)
class SignaloInfo:
    version: Optional[str]  # from pum_migrations, None where pum did not install it
    srid: int  # of signalo_db.support.geometry


def _version_tuple(text: str) -> tuple:
    try:
        return tuple(int(p) for p in text.split("."))
    except ValueError:
        return ()


def check_database(cursor, where: str = "the database") -> SignaloInfo:
    """The Signalo version and SRID, or SignaloError saying what does not fit."""
    cursor.execute("SELECT EXISTS (SELECT 1 FROM information_schema.schemata WHERE schema_name = %s)", (SCHEMA,))
    if not cursor.fetchone()[0]:
        raise SignaloError(f"{where} has no schema {SCHEMA}: not a Signalo database")
    version = None
    cursor.execute("SELECT EXISTS (SELECT 1 FROM information_schema.tables WHERE table_schema = %s "
                   "AND table_name = 'pum_migrations')", (SCHEMA,))
    if cursor.fetchone()[0]:
        cursor.execute(f"SELECT version FROM {SCHEMA}.pum_migrations")
        versions = [row[0] for row in cursor.fetchall() if _version_tuple(row[0])]
        version = max(versions, key=_version_tuple) if versions else None
    if version is not None:
        number = _version_tuple(version)
        if number[:2] < MIN_VERSION or number[0] > MAX_MAJOR:
            raise SignaloError(f"{where} holds Signalo data model {version}; Sign Mapper reads and writes versions "
                               f"{MIN_VERSION[0]}.{MIN_VERSION[1]} to {MAX_MAJOR}.x: upgrade it with pum first")
    cursor.execute("SELECT table_name, column_name FROM information_schema.columns WHERE table_schema = %s",
                   (SCHEMA,))
    present = {}
    for table, column in cursor.fetchall():
        present.setdefault(table, set()).add(column)
    missing = [f"{SCHEMA}.{table}.{column}" for table, columns in COLUMNS.items() for column in columns
               if column not in present.get(table, set())]
    if missing:
        shown = ", ".join(missing[:6]) + (f" and {len(missing) - 6} more" if len(missing) > 6 else "")
        raise SignaloError(f"{where} (Signalo {version or 'of unknown version'}) lacks {shown}: not the Signalo "
                           f"data model Sign Mapper writes ({MIN_VERSION[0]}.{MIN_VERSION[1]} to {MAX_MAJOR}.x)")
    cursor.execute(f"SELECT Find_SRID('{SCHEMA}', 'support', 'geometry')")
    return SignaloInfo(version, int(cursor.fetchone()[0]))


def official_signs(cursor) -> dict:
    """Official sign id -> German name."""
    cursor.execute(f"SELECT id, value_de FROM {SCHEMA}.vl_official_sign")
    return {row[0]: row[1] or "" for row in cursor.fetchall()}
