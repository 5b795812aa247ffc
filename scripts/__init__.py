"""Developer tools, run from the repository root as modules: ``.venv/bin/python -m scripts.evaluate_mapping ...``.

Run as modules, the tools import ``signmapper_core``, each other (``scripts.drives``) and the test helpers
(``tests.postgres_server``) by package name from the repository root, without putting folders on ``sys.path``.
``desktop_check.py`` is the exception: QGIS desktop runs it as a file (``qgis --code``, ``make desktop-check``).
Not shipped in the plugin zip (``scripts.build_zip``).
"""
