"""Installs Signalo's data model from the vendored changelogs (``tests/data/signalo``) the way pum does.

pum applies the changelog folders in version order and each folder's files in
name order, with ``{SRID}`` replaced, and records every version in
``signalo_db.pum_migrations``; this does the same in one transaction, offline.
``up_to`` installs an older version (a database "of another version").
"""

from __future__ import annotations

import json
from pathlib import Path

CHANGELOGS = Path(__file__).resolve().parent / "data" / "signalo" / "changelogs"
SRID = 2056


def version_key(name: str) -> tuple:
    return tuple(int(part) for part in name.split("."))


def changelog_versions() -> list[Path]:
    return sorted((p for p in CHANGELOGS.iterdir() if p.is_dir()), key=lambda p: version_key(p.name))


def install_signalo(dsn: str, up_to: str | None = None, srid: int = SRID) -> str:
    """Create ``signalo_db`` in the database ``dsn``; returns the version installed."""
    import psycopg2

    versions = [p for p in changelog_versions() if up_to is None or version_key(p.name) <= version_key(up_to)]
    conn = psycopg2.connect(dsn)
    try:
        with conn, conn.cursor() as cur:
            for folder in versions:
                files = sorted(folder.glob("*.sql"))
                for path in files:
                    cur.execute(path.read_text(encoding="utf-8").replace("{SRID}", str(srid)))
            cur.execute("""CREATE TABLE signalo_db.pum_migrations (
                id uuid DEFAULT gen_random_uuid() PRIMARY KEY,
                date_installed timestamp without time zone NOT NULL DEFAULT now(),
                module character varying(50) NOT NULL, version character varying(50) NOT NULL,
                beta_testing boolean NOT NULL DEFAULT false, changelog_files text[], parameters jsonb,
                migration_table_version integer NOT NULL DEFAULT 3,
                pum_version character varying(50) NOT NULL DEFAULT '1.4.0')""")
            for folder in versions:
                cur.execute("INSERT INTO signalo_db.pum_migrations (module, version, changelog_files, parameters) "
                            "VALUES ('signalo', %s, %s, %s)",
                            (folder.name, [p.name for p in sorted(folder.glob("*.sql"))], json.dumps({"SRID": srid})))
    finally:
        conn.close()
    return versions[-1].name
