"""Each shared default has one home: written a second time anywhere in the project, a test here fails.

The project's .py files outside tests/ are read with ``ast`` (SHARED lists the
defaults and their homes). A default is "written again" when its value appears
as a literal that a name ties to it: a parameter's default, a keyword argument,
an assignment, a ``.get(key, value)``, an ``x or value``, a Processing
parameter's default beside its name, an argparse ``default=`` of an option
named so. Other uses of the same number (a 4-pair window, a 14-pixel radius)
have other names and are not counted.

A help text (argparse ``help=``/``description=``, a Processing parameter's
help, a ``HELP`` string) that states a default in its own words writes it again
too: it takes the value from the home with an f-string, or argparse's
``%(default)s``. And the sign colours' hue bands are declared in
sign_colours.py only: a hue compared with a number elsewhere fails.
"""

from __future__ import annotations

import ast
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator, Optional

import pytest

from signmapper_core.changes.compare import ChangeConfig
from signmapper_core.evaluation.visibility import READABLE_FACE_ANGLE_DEG
from signmapper_core.importdrive.generic import GenericInputs
from signmapper_core.importdrive.importer import ImportOptions
from signmapper_core.pipeline.classifiers import NccClassifier
from signmapper_core.pipeline.config import DepthConfig
from signmapper_core.run import MAX_SKIPPED_PERCENT

ROOT = Path(__file__).resolve().parents[2]
SIGN_COLOURS = "signmapper_core/sign_colours.py"
SKIPPED_FOLDERS = {"tests", "build", "node_modules", "__pycache__"}  # and every hidden one (.venv, .git)


def number(value) -> str:
    """A regex for ``value`` written as a number in prose: 4, 4.0, but not 14 or 4.5."""
    return r"(?<![\d.])" + re.escape(f"{value:g}") + r"(?:\.0+)?(?![\d.]*\d)"


@dataclass(frozen=True)
class SharedDefault:
    what: str
    value: object
    names: str  # regex (case-insensitive) of the names that tie a literal to this default
    home: str  # the one file that writes it
    said: tuple = ()  # regexes of help-text words that state the value
    elsewhere: tuple = ()  # files where the same value under such a name is another thing (reason beside)

    def ties(self, name: str) -> bool:
        return re.search(self.names, name, re.IGNORECASE) is not None


NEAR, FAR = DepthConfig.near_m, DepthConfig.far_m
DEPTH_RANGE_SAID = (number(NEAR) + r"\s*(?:-|–|to|\.\.)\s*" + number(FAR), number(NEAR) + r"\s*m\b",
                    number(FAR) + r"\s*m\b")
IMPORT_OPTIONS = "signmapper_core/importdrive/importer.py"
SHARED = [
    SharedDefault("near limit of the depth range", NEAR, r"near(?!est)", "signmapper_core/pipeline/config.py",
                  DEPTH_RANGE_SAID),
    SharedDefault("far limit of the depth range", FAR, r"far", "signmapper_core/pipeline/config.py",
                  DEPTH_RANGE_SAID),
    SharedDefault("largest share of unreadable pairs", MAX_SKIPPED_PERCENT, r"skip", "signmapper_core/run/__init__.py",
                  (number(MAX_SKIPPED_PERCENT) + r"\s*%",)),
    SharedDefault("tolerance of a confirmed sign", ChangeConfig.tolerance_m, r"^tolerance(_m)?$",
                  "signmapper_core/changes/compare.py"),
    SharedDefault("move radius", ChangeConfig.move_radius_m, r"move_radius", "signmapper_core/changes/compare.py"),
    SharedDefault("readable face angle", READABLE_FACE_ANGLE_DEG, r"face_angle",
                  "signmapper_core/evaluation/visibility.py"),
    SharedDefault("JPEG quality of an import", ImportOptions.jpeg_quality, r"jpeg_quality", IMPORT_OPTIONS,
                  elsewhere=("signmapper_core/simulate/raw_survey.py",)),  # the simulated raw camera's JPEGs
    SharedDefault("largest vertical disparity of an import", ImportOptions.max_vertical_disparity_px,
                  r"vertical_disparity", IMPORT_OPTIONS,
                  (number(ImportOptions.max_vertical_disparity_px) + r"\s*px",)),
    SharedDefault("output CRS of an import", ImportOptions.output_crs, r"output_crs", IMPORT_OPTIONS,
                  (r"(?i)(default|empty)\W{0,3}" + re.escape(ImportOptions.output_crs),),
                  elsewhere=("bench/bench_rectify.py",)),  # the bench's poses are in LV95, so is its drive
    SharedDefault("CRS of an import's poses", GenericInputs.input_crs, r"input_crs",
                  "signmapper_core/importdrive/generic.py"),
    SharedDefault("template matching's threshold for 'accepted'", NccClassifier.accept_threshold,
                  r"^accept_threshold$", "signmapper_core/pipeline/classifiers/ncc.py",
                  (number(NccClassifier.accept_threshold) + r"[^.]*template matching",)),
]


def project_files() -> Iterator[Path]:
    for folder, subfolders, files in os.walk(ROOT):
        subfolders[:] = sorted(s for s in subfolders if not s.startswith(".") and s not in SKIPPED_FOLDERS)
        for name in sorted(files):
            if name.endswith(".py"):
                yield Path(folder) / name


@dataclass
class Scan:
    """What the tests look at in each file, read once: its literals, help texts and comparisons."""

    literals: list = field(default_factory=list)  # (path, ast.Constant), parents linked
    helps: list = field(default_factory=list)  # (path, line, literal text)
    compares: list = field(default_factory=list)  # (path, ast.Compare)

    def add(self, path: str, tree: ast.AST) -> Scan:
        for node in ast.walk(tree):
            for child in ast.iter_child_nodes(node):
                child.parent = node
            if isinstance(node, ast.Constant):
                self.literals.append((path, node))
            elif isinstance(node, ast.Compare):
                self.compares.append((path, node))
        self.helps += [(path, line, text) for line, text in help_texts(tree)]
        return self


@pytest.fixture(scope="module")
def scan():
    out = Scan()
    for path in project_files():
        out.add(path.relative_to(ROOT).as_posix(), ast.parse(path.read_text(encoding="utf-8"), str(path)))
    return out


def words(node: Optional[ast.AST]) -> set:
    """Identifiers, attribute names and string constants in ``node``."""
    found = set()
    for sub in ast.walk(node) if node is not None else ():
        if isinstance(sub, ast.Name):
            found.add(sub.id)
        elif isinstance(sub, ast.Attribute):
            found.add(sub.attr)
        elif isinstance(sub, ast.Constant) and isinstance(sub.value, str) and len(sub.value) < 80:
            found.add(sub.value)
        elif isinstance(sub, ast.keyword) and sub.arg:
            found.add(sub.arg)
    return found


def parameter_of(arguments: ast.arguments, default: ast.AST) -> Optional[str]:
    positional = arguments.posonlyargs + arguments.args
    for arg, value in zip(positional[len(positional) - len(arguments.defaults):], arguments.defaults):
        if value is default:
            return arg.arg
    for arg, value in zip(arguments.kwonlyargs, arguments.kw_defaults):
        if value is default:
            return arg.arg
    return None


def target_names(target: ast.AST, value: ast.AST, node: ast.AST) -> set:
    """The names an assignment gives ``node`` (a part of ``value``): tuples are matched element by element."""
    if isinstance(target, (ast.Tuple, ast.List)) and isinstance(value, (ast.Tuple, ast.List)) \
            and len(target.elts) == len(value.elts):
        for t, v in zip(target.elts, value.elts):
            if any(sub is node for sub in ast.walk(v)):
                return target_names(t, v, node)
    return words(target)


def names_of(literal: ast.Constant) -> set:
    """The names that tie ``literal`` to a meaning (see module)."""
    names, node = set(), literal
    while True:
        parent = getattr(node, "parent", None)
        if parent is None or isinstance(parent, ast.stmt) and not isinstance(parent, (ast.Assign, ast.AnnAssign)):
            return names
        if isinstance(parent, ast.arguments):
            name = parameter_of(parent, node)
            return names | ({name} if name else set())
        if isinstance(parent, ast.keyword):
            names.add(parent.arg or "")
            call = parent.parent
            if parent.arg in ("default", "defaultValue") and isinstance(call, ast.Call):
                names |= {a.value for a in call.args if isinstance(a, ast.Constant) and isinstance(a.value, str)}
            return names
        if isinstance(parent, ast.Call):
            return names | set().union(*(words(a) for a in parent.args if a is not node))
        if isinstance(parent, ast.Assign):
            return names | set().union(*(target_names(t, parent.value, literal) for t in parent.targets))
        if isinstance(parent, ast.AnnAssign):
            return names | words(parent.target)
        if isinstance(parent, ast.Dict):
            keys = [k for k, v in zip(parent.keys, parent.values) if v is node]
            return names | set().union(*(words(k) for k in keys))
        if isinstance(parent, (ast.BoolOp, ast.IfExp, ast.Compare, ast.BinOp)):
            names |= set().union(*(words(c) for c in ast.iter_child_nodes(parent) if c is not node))
        node = parent


def is_number(node: ast.AST, value) -> bool:
    return isinstance(node, ast.Constant) and type(node.value) in (int, float) and node.value == value


def is_value(node: ast.AST, value) -> bool:
    """``node`` is the literal ``value`` (a number, or the very string)."""
    if isinstance(value, str):
        return isinstance(node, ast.Constant) and node.value == value
    return is_number(node, value)


def written_again(scan: Scan, shared: SharedDefault) -> list:
    """'file:line (names)' of each literal of ``shared``'s value that a name ties to it, outside its home."""
    found = set()
    for path, node in scan.literals:
        if path != shared.home and path not in shared.elsewhere and is_value(node, shared.value):
            names = sorted(n for n in names_of(node) if shared.ties(n))
            if names:
                found.add((path, node.lineno, f"{path}:{node.lineno} ({', '.join(names)})"))
    return [text for _path, _line, text in sorted(found)]


def help_texts(tree) -> Iterator[tuple]:
    """(line, literal text) of the help texts of ``tree``: argparse help/description, Processing parameters'
    help (``add_parameter``'s text), class attributes named ``HELP`` or ``*_HELP``. An f-string's literal parts
    count, its values not."""
    for node in ast.walk(tree):
        texts = []
        if isinstance(node, ast.keyword) and node.arg in ("help", "description"):
            texts.append(node.value)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr in ("add_parameter", "add_language_parameter"):
            texts.extend(node.args[1:])
        elif isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and re.fullmatch(r"(\w+_)?HELP", t.id)
                                                  for t in node.targets):
            texts.append(node.value)
        for text in texts:
            for sub in ast.walk(text):
                if isinstance(sub, ast.Constant) and isinstance(sub.value, str):
                    yield sub.lineno, sub.value


def said_again(scan: Scan, shared: SharedDefault) -> list:
    """'file:line (words)' of each help text that states ``shared``'s value in its own words."""
    found = set()
    for path, line, text in scan.helps:
        for pattern in shared.said:
            match = re.search(pattern, text)
            if match:
                found.add((path, line, f"{path}:{line} ('{match.group(0)}')"))
    return [text for _path, _line, text in sorted(found)]


@pytest.mark.parametrize("shared", SHARED, ids=[s.what for s in SHARED])
def test_a_shared_default_is_written_only_in_its_home(scan, shared):
    assert (ROOT / shared.home).is_file()
    assert written_again(scan, shared) == [], f"the {shared.what} ({shared.value}) is written again; take it " \
                                              f"from {shared.home}"


@pytest.mark.parametrize("shared", [s for s in SHARED if s.said], ids=[s.what for s in SHARED if s.said])
def test_a_help_text_takes_a_default_from_its_home(scan, shared):
    assert said_again(scan, shared) == [], f"a help text states the {shared.what} ({shared.value}) in words; " \
                                           f"take it from {shared.home} (an f-string)"


STATED_DEFAULT = re.compile(r"\bdefault\b\W{0,3}(-?\d|EPSG:)", re.IGNORECASE)


def test_a_help_text_states_no_default_in_its_own_words(scan):
    """'(default 10)' beside ``default=10`` is the value written twice: argparse's ``%(default)s`` or an
    f-string of the home says it (a Processing dialog shows its parameters' defaults by itself)."""
    found = [f"{path}:{line} ({text[max(0, m.start() - 30):m.end() + 10]!r})"
             for path, line, text in scan.helps for m in [STATED_DEFAULT.search(text)] if m]
    assert found == []


def is_hue(node: ast.AST) -> bool:
    """A hue: a name with 'hue' in it, or the first channel of an HSV image (``hsv[..., 0]``, ``hsv[:, :, 0]``)."""
    if isinstance(node, ast.Name):
        return "hue" in node.id.lower()
    if isinstance(node, ast.Subscript):
        index = node.slice.elts[-1] if isinstance(node.slice, ast.Tuple) else node.slice
        return is_number(index, 0) and any("hsv" in w.lower() for w in words(node.value))
    return False


def hue_thresholds(scan: Scan) -> list:
    """'file:line (comparison)' of each hue compared with a number outside sign_colours.py."""
    found = set()
    for path, node in scan.compares:
        sides = [node.left, *node.comparators]
        if path != SIGN_COLOURS and any(is_hue(s) for s in sides) and any(isinstance(s, ast.Constant) for s in sides):
            found.add((path, node.lineno, f"{path}:{node.lineno} ({ast.unparse(node)})"))
    return [text for _path, _line, text in sorted(found)]


def test_hue_thresholds_are_declared_with_the_sign_colours(scan):
    """The sign colours' hue bands (red's above all, at both ends of the hue circle) are declared in
    sign_colours.py, each named for its use; code compares hues with those bands (``in_hue_bands``)."""
    assert hue_thresholds(scan) == []


def test_the_scan_sees_what_it_is_meant_to():
    """Each way of writing a default again is caught, other uses of the number are not."""
    source = '''
NEAR_M, FAR_M = 4.0, 14.0
def f(drive, near_m: float = 4.0, far_m=14.0, pairs: int = 4): ...
g(x, near=4.0, far=14)
far = run.get("far_m", 14.0)
near = float(run.get("near_m") or 4.0)
p.add_argument("--near", type=float, default=4.0, help="nearest point, default 4 m")
QgsProcessingParameterNumber(self.FAR, self.tr("Far limit [m]"), Double, 14.0)
settings = {"far_m": 14.0, "radius_px": 14}
radius = 14
window = x[4:14]
'''
    example = Scan().add("example.py", ast.parse(source))
    near, far = written_again(example, SHARED[0]), written_again(example, SHARED[1])
    assert [n.split(" ")[0] for n in near] == [f"example.py:{i}" for i in (2, 3, 4, 6, 7)]
    assert [n.split(" ")[0] for n in far] == [f"example.py:{i}" for i in (2, 3, 4, 5, 8, 9)]
    assert said_again(example, SHARED[0]) == ["example.py:7 ('4 m')"]
    hues = ast.parse("red = (hue <= 12) | (hsv[..., 0] > 165) | (img[..., 0] > 3) | (hsv[..., 1] > 90)")
    found = [h.split(" ", 1)[1] for h in hue_thresholds(Scan().add("x.py", hues))]
    assert found == ["(hsv[..., 0] > 165)", "(hue <= 12)"]
