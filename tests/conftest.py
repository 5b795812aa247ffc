"""Shared test set-up.

Core tests import ``signmapper_core`` from the repo root. QGIS tests import the
plugin as ``sign_mapper`` through a symlink in a temporary plugin folder, the
way QGIS installs it, whatever this checkout's folder is called.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[1]
if str(REPO_ROOT) not in sys.path:
    sys.path.insert(0, str(REPO_ROOT))
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import pytest  # noqa: E402


@pytest.fixture(scope="session")
def postgres():
    """A PostgreSQL + PostGIS server of our own on a free port, removed after the session; fails (never skips)
    when it cannot start."""
    from postgres_server import PostgresServer, PostgresUnavailable

    try:
        server = PostgresServer().start()
    except PostgresUnavailable as exc:
        pytest.fail(f"the database tests need PostgreSQL with PostGIS: {exc}", pytrace=False)
    yield server
    server.stop()


@pytest.fixture(scope="session")
def signalo_database(postgres):
    """make(name, up_to=None) -> DSN of a new database holding Signalo's data model (up to that version)."""
    from signalo_schema import install_signalo

    def make(name: str, up_to=None) -> str:
        dsn = postgres.create_database(name)
        install_signalo(dsn, up_to)
        return dsn

    return make


@pytest.fixture(scope="session")
def shipped_catalogue():
    """The catalogue the plugin ships (official artwork, with its network where there is one)."""
    from signmapper_core.catalogue import load_catalogue

    return load_catalogue()


@pytest.fixture(scope="module")
def catalogue(request):
    """The catalogue a test module's scenes and templates come from: the shipped one, or where the module
    sets ``CATALOGUE = "reference drawing"`` the one its thresholds were tuned with (below)."""
    if getattr(request.module, "CATALOGUE", "shipped") == "reference drawing":
        return request.getfixturevalue("reference_drawing_catalogue")
    return request.getfixturevalue("shipped_catalogue")


@pytest.fixture(scope="session")
def reference_drawing_catalogue(tmp_path_factory):
    """The Swiss catalogue drawn by our own procedural drawer instead of the official artwork (make catalogue
    without SVG). Constructed-scene tests of the colour step pin thresholds tuned with these faces and templates;
    the shipped official catalogue is measured on real photographs (tests/core/test_real_photographs.py)."""
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.catalogue.build import build

    folder = tmp_path_factory.mktemp("reference-catalogue")
    build(folder, None)
    return load_catalogue(folder)
