"""The plugin and QGIS's Processing framework in a standalone QGIS application, loaded the way QGIS loads them.

For tools that need the plugin's Processing algorithms in their own process (``scripts.make_import_model``,
``bench.bench_viewer``). QGIS finds plugins by putting its plugin folders on ``sys.path`` and importing each
plugin's folder by name, so this does the same: QGIS's own plugin folder (for ``processing``) and a folder of the
caller's holding a link to this checkout as ``sign_mapper``, the name QGIS installs it under whatever the checkout's
folder is called. This is the one module of scripts/ and bench/ that may touch ``sys.path``
(``tests/core/test_tool_modules.py``): the tools themselves are run as modules and import by package name.
"""

from __future__ import annotations

import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def load_plugin(plugins: Path):
    """The plugin object of this checkout, its Processing provider registered, in a QGIS application already started
    (``QgsApplication.initQgis()``). ``plugins`` is an empty folder of the caller's, to keep while the plugin is used;
    call the plugin's ``unload()`` when done."""
    from qgis.core import QgsApplication

    sys.path.append(str(Path(QgsApplication.pkgDataPath()) / "python" / "plugins"))  # QGIS's own Processing plugin
    from processing.core.Processing import Processing

    Processing.initialize()
    (Path(plugins) / "sign_mapper").symlink_to(REPO, target_is_directory=True)
    sys.path.insert(0, str(plugins))
    import sign_mapper

    plugin = sign_mapper.classFactory(None)
    plugin.initProcessing()
    return plugin
