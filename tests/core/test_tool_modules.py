"""The tools of scripts/, bench/ and training/ are modules run from the repository root (``python -m scripts.X``),
importing by package name: none puts a folder on ``sys.path`` or needs an import below code (``noqa: E402``).

Two files are let off, each for a reason of its own: ``scripts/desktop_check.py``, which QGIS desktop runs as a file
(``qgis --code``), and ``scripts/qgis_plugin.py``, which loads the plugin the way QGIS does, by its plugin folders
on ``sys.path``.
"""

from __future__ import annotations

import ast
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TOOL_FOLDERS = ("scripts", "bench", "training")
RUN_AS_A_FILE = {"scripts/desktop_check.py"}
LOADS_THE_PLUGIN = {"scripts/qgis_plugin.py"}


def _tool_files():
    for folder in TOOL_FOLDERS:
        for path in sorted((REPO / folder).rglob("*.py")):
            yield path.relative_to(REPO).as_posix(), path


def _sys_path_uses(tree: ast.AST) -> list[int]:
    """Lines naming ``sys.path`` (reading or changing it) or importing ``path`` from ``sys``."""
    lines = []
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and node.attr == "path" and isinstance(node.value, ast.Name)
                and node.value.id == "sys"):
            lines.append(node.lineno)
        elif isinstance(node, ast.ImportFrom) and node.module == "sys" and any(a.name == "path" for a in node.names):
            lines.append(node.lineno)
    return lines


def test_no_tool_puts_folders_on_sys_path():
    offenders = []
    for name, path in _tool_files():
        if name in RUN_AS_A_FILE | LOADS_THE_PLUGIN:
            continue
        offenders += [f"{name}:{line}" for line in _sys_path_uses(ast.parse(path.read_text(encoding="utf-8")))]
    assert offenders == [], "import by package name (python -m scripts.X from the repository root) instead"


def test_no_tool_needs_an_import_below_code():
    offenders = [f"{name}:{k}" for name, path in _tool_files() if name not in RUN_AS_A_FILE
                 for k, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1)
                 if "noqa: E402" in line]
    assert offenders == []


def test_tool_folders_are_packages():
    folders = {path.parent for _, path in _tool_files()}
    assert sorted(f.relative_to(REPO).as_posix() for f in folders if not (f / "__init__.py").is_file()) == []


def test_the_exceptions_are_still_there():
    """The files let off above exist: the list must not outlive them."""
    assert all((REPO / name).is_file() for name in RUN_AS_A_FILE | LOADS_THE_PLUGIN)
