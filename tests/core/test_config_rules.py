"""pipeline/config.py stays a list of rules: every setting with its one-line rule, and no tuning history.

How a value was found (tune splits, tune drives, seeds, figures before and after) belongs in
docs/measurements.md ("How the pipeline settings were found"); beside a setting stands what it is and why it
has that value, on one line: a comment at the end of the setting's line, or, where it would not fit there, the
one comment line right above it. The checks read the source text, so they run on any version of the file
(``rule_problems(source)``, ``history_in(source)``).
"""

import ast
import dataclasses
import io
import re
import tokenize
from pathlib import Path

from signmapper_core.pipeline import config as config_module
from signmapper_core.pipeline.config import SECTIONS, PipelineConfig, TemplateGeometry

CONFIG = Path(config_module.__file__)

# tuning history: how a value was found, not what it is
HISTORY = {
    "a tune split, tune drive or a tuned value": r"\btun(e|ed|es|ing)\b",
    "a drive's number": r"\bdrives?\s+\d{3,4}",
    "a seed": r"\bseeds?\s*\d+",
    "a figure before and after": r"\d\s*(->|→)\s*[\d.]",
    "a tally (N of M)": r"\b\d+ of \d+\b",
    "held-out or looked-at drives": r"\b(held-out|looked-at)\b",
    "a measurement on synthetic drives": r"\bsynthetic (drives?|images?|crops?)\b",
    "a date": r"\b20\d\d-\d\d-\d\d\b",
}

# unit a setting's name promises -> what its rule must say in brackets
UNITS = {"_m": r"\[m\b", "_px": r"\[px", "_deg": r"\[deg\b"}
# names whose suffix is not their unit (kept: run records name them)
NOT_THEIR_UNIT = {"weak_surround_px"}  # a share of the segment's size

MIN_RULE_WORDS = 3
LINE_LENGTH = 120  # ruff.toml


def _comments(source: str):
    """line number -> (comment text without '#', whether the comment stands on a line of its own)."""
    lines = source.splitlines()
    out = {}
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            row = tok.start[0]
            out[row] = (tok.string.lstrip("#").strip(), lines[row - 1].lstrip().startswith("#"))
    return out


def _is_dataclass(node: ast.ClassDef) -> bool:
    for deco in node.decorator_list:
        target = deco.func if isinstance(deco, ast.Call) else deco
        if isinstance(target, ast.Name) and target.id == "dataclass":
            return True
    return False


def settings_in(source: str):
    """(class, setting, first line, last line, body's first and last line) of every field of every dataclass."""
    out = []
    for node in ast.parse(source).body:
        if isinstance(node, ast.ClassDef) and _is_dataclass(node):
            for stmt in node.body:
                if isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name):
                    out.append((node.name, stmt.target.id, stmt.lineno, stmt.end_lineno,
                                node.body[0].lineno, node.end_lineno))
    return out


def rule_problems(source: str):
    """What keeps a setting of ``source`` from having exactly one rule line (empty: none)."""
    comments = _comments(source)
    lines = source.splitlines()
    problems = []
    starts = set()
    bodies = set()
    for cls, name, first, last, body_first, body_last in settings_in(source):
        where = f"{cls}.{name} (line {first})"
        starts.add(first)
        bodies.add((cls, body_first, body_last))
        trailing = comments.get(first) if first in comments and not comments[first][1] else None
        above = comments.get(first - 1) if first - 1 in comments and comments[first - 1][1] else None
        if trailing and above:
            problems.append(f"{where}: a rule at the end of its line and another above it")
        rule = trailing or above
        if above and not trailing and len(lines[first - 1].rstrip()) + 3 + len(above[0]) <= LINE_LENGTH:
            problems.append(f"{where}: its rule stands above it but would fit at the end of its line")
        if rule is None:
            problems.append(f"{where}: no rule (a comment at the end of its line or the line above)")
        elif len(rule[0].split()) < MIN_RULE_WORDS:
            problems.append(f"{where}: rule too short: {rule[0]!r}")
        else:
            problems += [f"{where}: {problem}" for problem in _unit_problems(name, rule[0])]
        if any(row in comments for row in range(first + 1, last + 1)):
            problems.append(f"{where}: a comment inside the setting's lines")
    # a comment line of its own in a class of settings is the rule of the setting right below it: no rule runs
    # on over a second line, no comment stands loose between settings
    for cls, body_first, body_last in sorted(bodies):
        for row, (text, own_line) in sorted(comments.items()):
            if own_line and body_first <= row <= body_last and row + 1 not in starts:
                problems.append(f"{cls} line {row}: a comment line that is no setting's rule: {text[:60]!r}")
    return problems


def _unit_problems(name: str, rule: str):
    if name in NOT_THEIR_UNIT:
        return []
    return [f"its name ends in {suffix!r}: the rule gives the unit as {pattern!r}"
            for suffix, pattern in UNITS.items() if name.endswith(suffix) and not re.search(pattern, rule)]


def history_in(source: str):
    """Comments of ``source`` that tell tuning history: (line, what, comment)."""
    return [(row, what, text) for row, (text, _) in sorted(_comments(source).items())
            for what, pattern in HISTORY.items() if re.search(pattern, text)]


def test_the_checks_see_every_setting():
    """The source reading finds exactly the fields of every section, of PipelineConfig and TemplateGeometry."""
    found = {(cls, name) for cls, name, *_ in settings_in(CONFIG.read_text(encoding="utf-8"))}
    classes = [*SECTIONS.values(), PipelineConfig, TemplateGeometry]
    expected = {(cls.__name__, f.name) for cls in classes for f in dataclasses.fields(cls)}
    assert found == expected


def test_every_setting_has_a_one_line_rule():
    problems = rule_problems(CONFIG.read_text(encoding="utf-8"))
    assert not problems, "\n".join(problems)


def test_no_tuning_history_in_the_settings():
    found = history_in(CONFIG.read_text(encoding="utf-8"))
    assert not found, "tuning history belongs in docs/measurements.md:\n" + "\n".join(
        f"line {row} ({what}): {text}" for row, what, text in found)


HEADER = 'from dataclasses import dataclass\n\n\n@dataclass(frozen=True)\nclass Section:\n    """Why it exists."""\n\n'


def _section(*lines: str) -> str:
    return HEADER + "".join(f"    {line}\n" for line in lines)


def test_the_checks_pass_a_clean_section():
    clean = _section("near_m: float = 4.0  # nearest depth searched [m]: closer faces are cut by the frame",
                     "# HSV thresholds per colour [hue 0-179, saturation and value 0-255], read from sign_colours.py",
                     "hsv_ranges: Dict[str, Tuple[HsvRange, ...]] = field(default_factory=lambda: dict(RANGES))")
    assert rule_problems(clean) == []
    assert history_in(clean) == []


def test_the_checks_catch_what_they_guard():
    """A setting without a rule, a rule over two lines, a loose comment, a missing unit and history are found."""
    cases = {
        "no rule": ["bare: int = 3"],
        "rule too short": ["short: int = 3  # short"],
        "a rule at the end of its line and another above it": ["# one rule here", "both: int = 3  # and another here"],
        "no setting's rule": ["# a heading over", "# a rule above", "fine: int = 2"],
        "would fit at the end of its line": ["runs_on: float = 0.5  # a rule that runs", "# on over a second line",
                                             "next_one: int = 2"],
        "'_m'": ["far_m: float = 14.0  # farthest depth searched, its unit missing"],
        "a comment inside the setting's lines": ["split: tuple = (1,  # the first value", "    2)  # the second"],
    }
    for expected, lines in cases.items():
        problems = "\n".join(rule_problems(_section(*lines)))
        assert expected in problems, (expected, problems)
    history = _section("fit: float = 0.68  # least IoU (tune split: 0.72 -> 0.68 found 2.3 % more faces)",
                       "window: bool = True  # boxes, not bands (seed 2001: 925k pixels, drive 1002: 3 of 4 pairs)")
    assert set(HISTORY) - {what for _, what, _ in history_in(history)} == {
        "held-out or looked-at drives", "a measurement on synthetic drives", "a date"}
