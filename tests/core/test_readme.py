"""The README stays short, keeps the two set-up commands, and every relative link of it and of docs/ resolves."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
README = REPO / "README.md"
MARKDOWN = [README, *sorted((REPO / "docs").glob("*.md"))]
MAX_README_LINES = 250
# the two commands for a fresh Debian 12 machine; .ci/run runs the second
SETUP_COMMANDS = (
    "sudo apt-get update && sudo apt-get install -y make && make demo",
    "sudo apt-get update && sudo apt-get install -y make && make test",
)
FENCE = re.compile(r"^\s*(```|~~~)")
INLINE_CODE = re.compile(r"(`+).*?\1")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def prose_lines(text: str, keep_code: bool = False):
    """(line number, line) outside fenced code blocks, inline code removed unless ``keep_code``."""
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line if keep_code else INLINE_CODE.sub("", line)


def anchors(path: Path) -> set[str]:
    """The anchors GitHub gives the headings of a Markdown file."""
    seen: dict[str, int] = {}
    result = set()
    for _, line in prose_lines(path.read_text(encoding="utf-8"), keep_code=True):
        match = HEADING.match(line)
        if not match:
            continue
        title = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", match.group(2))  # a link in a heading: its text
        slug = re.sub(r"[^\w\- ]", "", title.replace("`", "").lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        result.add(slug if count == 0 else f"{slug}-{count}")
    return result


def broken_links(path: Path, text: str, root: Path = REPO) -> list[str]:
    """Relative links of a Markdown file whose file (or, for a Markdown file, heading) does not exist."""
    broken = []
    for number, line in prose_lines(text):
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):  # http:, https:, mailto:
                continue
            file_part, _, anchor = target.partition("#")
            linked = (path.parent / file_part).resolve() if file_part else path
            where = f"{path.relative_to(root)}:{number}: {target}"
            if not linked.exists():
                broken.append(f"{where} (no such file)")
            elif anchor and linked.suffix == ".md" and anchor not in anchors(linked):
                broken.append(f"{where} (no such heading)")
    return broken


def test_readme_is_at_most_250_lines():
    lines = README.read_text(encoding="utf-8").count("\n")
    assert lines <= MAX_README_LINES, f"README.md has {lines} lines; move detail into docs/ and link to it"


def test_readme_keeps_the_two_set_up_commands():
    text = README.read_text(encoding="utf-8")
    for command in SETUP_COMMANDS:
        assert f"\n{command}\n" in text, command
    assert "make test" in (REPO / ".ci" / "run").read_text(encoding="utf-8")


@pytest.mark.parametrize("path", MARKDOWN, ids=lambda p: str(p.relative_to(REPO)))
def test_relative_links_resolve(path):
    assert broken_links(path, path.read_text(encoding="utf-8")) == []


def test_the_link_check_sees_a_broken_link(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "README.md").write_text("# Sign Mapper\n\n## Quick start on a fresh Debian 12 machine\n")
    page = tmp_path / "docs" / "example.md"
    text = ("# Example: `code` in a heading\n"
            "[ok](../README.md#quick-start-on-a-fresh-debian-12-machine) [gone](nowhere.md) `[code](nowhere.md)`\n"
            "[web](https://example.org/x) [heading](../README.md#no-such-heading) [here](#example-code-in-a-heading)\n"
            "![picture](missing.png) [there](#nothing)\n```\n[fenced](nowhere.md)\n```\n")
    page.write_text(text)
    assert broken_links(page, text, tmp_path) == [
        "docs/example.md:2: nowhere.md (no such file)",
        "docs/example.md:3: ../README.md#no-such-heading (no such heading)",
        "docs/example.md:4: missing.png (no such file)",
        "docs/example.md:4: #nothing (no such heading)",
    ]
