"""The project's imports read from its source (no module is imported): who imports whom, at module level and
inside functions, for the architecture tests."""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Iterable, Optional

REPO = Path(__file__).resolve().parents[1]
# third-party modules worth importing late: the plugin loads, and says what is missing, without them
HEAVY = ("cv2", "numpy", "pyproj", "PIL", "distributed", "dask", "osgeo", "psycopg", "psycopg2", "shapely")
# served lazily by a package's module-level __getattr__: (package, name) -> the module that defines it
LAZY_NAMES = {("signmapper_core.pipeline", "detect_pair"): "signmapper_core.pipeline.detect",
              ("signmapper_core.pipeline", "detect_in_window"): "signmapper_core.pipeline.detect",
              **{("signmapper_core.simulate", name): "signmapper_core.simulate.generator"
                 for name in ("generate_drive", "recorded_poses", "true_poses")}}
PLUGIN_PREFIX = "sign_mapper."  # how tests and QGIS name the plugin package


@dataclass(frozen=True)
class Import:
    """One import statement of a module: the modules it makes Python import (project or third-party)."""

    module: str  # importing module, dotted from the repository root ("" is the plugin's __init__)
    line: int
    targets: tuple[str, ...]
    in_function: bool
    commented: bool  # a comment on its lines or on the line above says why it stands where it does


@dataclass(eq=False)  # hashed by identity: its closures are cached
class ImportGraph:
    modules: dict[str, Path]  # dotted name -> file
    imports: list[Import] = field(default_factory=list)

    def project(self, names: Iterable[str]) -> list[str]:
        return [n for n in names if n in self.modules]

    def edges(self, include_functions: bool = True) -> dict[str, set[str]]:
        out: dict[str, set[str]] = {m: set() for m in self.modules}
        for imp in self.imports:
            if include_functions or not imp.in_function:
                out[imp.module].update(t for t in imp.targets if t in self.modules and t != imp.module)
        return out

    def cycles(self) -> list[list[str]]:
        """Strongly connected groups of more than one module (Tarjan), every import counted."""
        graph = self.edges()
        index: dict[str, int] = {}
        low: dict[str, int] = {}
        stack: list[str] = []
        on_stack: set[str] = set()
        groups: list[list[str]] = []

        def visit(v: str) -> None:
            index[v] = low[v] = len(index)
            stack.append(v)
            on_stack.add(v)
            for w in graph[v]:
                if w not in index:
                    visit(w)
                    low[v] = min(low[v], low[w])
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
            if low[v] == index[v]:
                group = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    group.append(w)
                    if w == v:
                        break
                if len(group) > 1:
                    groups.append(sorted(group))

        for v in sorted(graph):
            if v not in index:
                visit(v)
        return groups

    @cache  # noqa: B019 - one graph per test session
    def loaded_with(self, module: str) -> frozenset:
        """Every module Python imports with ``module`` at module level (its own included)."""
        top = self.edges_with_externals()
        seen: set[str] = set()
        todo = [module]
        while todo:
            m = todo.pop()
            if m not in seen:
                seen.add(m)
                todo.extend(top.get(m, ()))
        return frozenset(seen)

    @cache  # noqa: B019
    def edges_with_externals(self) -> dict:
        out: dict[str, set[str]] = {}
        for imp in self.imports:
            if not imp.in_function:
                out.setdefault(imp.module, set()).update(imp.targets)
        return out

    def heavy_of(self, module: str) -> set[str]:
        return {h for h in HEAVY for m in self.loaded_with(module) if m == h or m.startswith(h + ".")}


def _dotted(path: Path) -> tuple[str, bool]:
    parts = list(path.relative_to(REPO).with_suffix("").parts)
    is_package = parts[-1] == "__init__"
    if is_package:
        parts = parts[:-1]
    return ".".join(parts), is_package


def _resolve(module: str, is_package: bool, level: int, name: Optional[str]) -> str:
    base = module.split(".") if module else []
    if not is_package:
        base = base[:-1]
    if level > 1:
        base = base[:len(base) - (level - 1)]
    return ".".join(base + (name.split(".") if name else []))


def _targets(graph_modules: dict, module: str, is_package: bool, node) -> list[str]:
    names = []
    if isinstance(node, ast.Import):
        names = [a.name for a in node.names]
    else:
        base = _resolve(module, is_package, node.level, node.module) if node.level else node.module
        base = base.removeprefix(PLUGIN_PREFIX)
        for alias in node.names:
            lazy = LAZY_NAMES.get((base, alias.name))
            sub = f"{base}.{alias.name}"
            names.append(lazy or (sub if sub in graph_modules else base))
    out = []
    for name in names:
        name = name.removeprefix(PLUGIN_PREFIX)
        while name not in graph_modules and "." in name and name.split(".")[0] in _top_packages(graph_modules):
            name = name.rsplit(".", 1)[0]
        out.append(name)
        parts = name.split(".")
        for k in range(1, len(parts)):  # importing a.b.c runs a/__init__ and a/b/__init__ first
            parent = ".".join(parts[:k])
            if parent in graph_modules and parent != module and not module.startswith(parent + "."):
                out.append(parent)
    return out


def _top_packages(graph_modules: dict) -> set:
    return {m.split(".")[0] for m in graph_modules if m}


def _commented(lines: list[str], node) -> bool:
    own = lines[node.lineno - 1:node.end_lineno]
    above = lines[node.lineno - 2].strip() if node.lineno > 1 else ""
    return any("#" in line for line in own) or above.startswith("#")


def read_graph(folders: Iterable[str] = (), skip: Iterable[str] = (".venv", "build", "dist", "tests")) -> ImportGraph:
    """The import graph of the plugin's Python files (every folder but ``skip``)."""
    skipped = set(skip)
    files = [p for p in REPO.rglob("*.py") if not skipped & set(p.relative_to(REPO).parts[:1])
             and "__pycache__" not in p.parts and not any(part.startswith(".") for part in p.relative_to(REPO).parts)]
    modules = dict(_dotted(p)[0:1] + (p,) for p in files)
    graph = ImportGraph(modules)
    for path in files:
        graph.imports.extend(_imports_of(path, modules))
    return graph


def _imports_of(path: Path, modules: dict) -> list[Import]:
    module, is_package = _dotted(path)
    source = path.read_text()
    lines = source.split("\n")
    found: list[Import] = []

    def visit(node, in_function: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                visit(child, True)
            elif isinstance(child, ast.If) and "TYPE_CHECKING" in ast.dump(child.test):
                continue  # never runs
            elif isinstance(child, (ast.Import, ast.ImportFrom)):
                if isinstance(child, ast.ImportFrom) and child.module == "__future__":
                    continue
                found.append(Import(module, child.lineno, tuple(_targets(modules, module, is_package, child)),
                                    in_function, _commented(lines, child)))
            else:
                visit(child, in_function)

    visit(ast.parse(source), False)
    return found
