"""Fixtures for tests that run inside QGIS: the plugin imported as ``sign_mapper``."""

from __future__ import annotations

import importlib
import os
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def plugin_dir(tmp_path_factory) -> Path:
    """A QGIS plugin folder holding ``sign_mapper`` as a link to this checkout."""
    plugins = tmp_path_factory.mktemp("plugins")
    os.symlink(REPO_ROOT, plugins / "sign_mapper", target_is_directory=True)
    return plugins


@pytest.fixture(scope="session")
def sign_mapper(plugin_dir, qgis_app):
    """The plugin package, imported the way QGIS imports it."""
    if str(plugin_dir) not in sys.path:
        sys.path.insert(0, str(plugin_dir))
    return importlib.import_module("sign_mapper")


@pytest.fixture
def registered_plugin(sign_mapper, qgis_processing):
    """The plugin constructed with iface None (as qgis_process does) and its provider registered."""
    plugin = sign_mapper.classFactory(None)
    plugin.initProcessing()
    yield plugin
    plugin.unload()


@pytest.fixture
def run(registered_plugin):
    """``processing.run`` with the plugin's algorithms registered."""
    import processing

    return processing.run


@pytest.fixture(scope="session")
def small_drive(tmp_path_factory) -> Path:
    """12 half-HD pairs with true depth maps (seed 11, the signs of before the whole catalogue): the drive
    mapsigns tests and the golden file use."""
    from drive_fixtures import SMALL_SYNTHETIC

    from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive

    out = tmp_path_factory.mktemp("drives") / "drive"
    generate_drive(out, SimulationConfig(pairs=12, seed=11, write_depth=True, **SMALL_SYNTHETIC, **DRAWABLE_SIGNS))
    return out
