"""The house plan: no import cycle, a core of few root modules in rooms, and late imports only where they pay."""

import pytest
from import_graph import REPO, read_graph

CORE = "signmapper_core"
MAX_ROOT_MODULES = 12
# QGIS entry points: QGIS calls them once it loads the plugin; their imports wait for QGIS, OpenCV's check or a GUI
ENTRY_POINTS = {"", "plugin"}
TOOLS = ("training", "scripts", "bench")  # not shipped: run by developers, where start-up time does not matter


@pytest.fixture(scope="module")
def graph():
    return read_graph()


def test_no_import_cycle_among_the_projects_modules(graph):
    assert graph.cycles() == []


def test_the_graph_sees_a_cycle_made_inside_a_function(graph):
    """The check above can fail: an import placed in a function still counts."""
    edges = graph.edges()
    assert f"{CORE}.run.pair" in edges[f"{CORE}.run.mapping"]
    assert f"{CORE}.run.pair" in edges[f"{CORE}.run.cluster_task"]  # imported inside map_pair_task
    graph.imports.append(type(graph.imports[0])(f"{CORE}.run.pair", 1, (f"{CORE}.run.mapping",), True, True))
    try:
        assert any({f"{CORE}.run.mapping", f"{CORE}.run.pair"} <= set(group) for group in graph.cycles())
    finally:
        graph.imports.pop()


def test_the_core_keeps_at_most_twelve_modules_at_its_root_the_rest_in_rooms():
    root = sorted(p.name for p in (REPO / CORE).glob("*.py"))
    assert len(root) <= MAX_ROOT_MODULES, root
    rooms = {p.parent.name for p in (REPO / CORE).glob("*/__init__.py")}
    assert {"run", "output", "plates", "evaluation", "fusion", "drive", "pipeline", "catalogue"} <= rooms


def test_an_import_inside_a_function_of_the_plugin_delays_a_heavy_dependency_and_says_so(graph):
    late = [i for i in graph.imports if i.in_function and graph.project(i.targets) and i.module not in ENTRY_POINTS
            and not i.module.startswith(TOOLS)]
    assert len(late) > 10  # the check reads them at all
    uncommented = [f"{graph.modules[i.module].relative_to(REPO)}:{i.line}" for i in late if not i.commented]
    assert uncommented == []
    gaining_nothing = []
    for i in late:
        gained = set().union(*(graph.heavy_of(t) for t in graph.project(i.targets))) - graph.heavy_of(i.module)
        if not gained:
            gaining_nothing.append(f"{graph.modules[i.module].relative_to(REPO)}:{i.line}")
    assert gaining_nothing == []


def test_the_core_imports_nothing_of_the_plugin_around_it(graph):
    outside = {m.split(".")[0] for m in graph.modules if m and not m.startswith(CORE)}
    leaks = [f"{i.module}:{i.line} -> {t}" for i in graph.imports if i.module.startswith(CORE)
             for t in i.targets if t.split(".")[0] in outside]
    assert leaks == []
