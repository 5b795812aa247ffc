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
