"""Build the installable plugin zip: the tracked plugin files under ``sign_mapper/``, without tests, CI and benches."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

EXCLUDED_TOP = {"tests", ".ci", "bench", "scripts", "training", "docs", ".gitignore", "requirements-dev.txt",
                "requirements-train.txt", "pytest.ini", "ruff.toml", "Makefile", ".gitattributes"}


def plugin_files(repo: Path) -> list[str]:
    listing = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=repo, capture_output=True, text=True,
        check=True,
    ).stdout.splitlines()
    return sorted(f for f in listing if f.split("/")[0] not in EXCLUDED_TOP and (repo / f).is_file())


def build(repo: Path, out: Path, name: str = "sign_mapper") -> int:
    out.parent.mkdir(parents=True, exist_ok=True)
    files = plugin_files(repo)
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zf:
        for f in files:
            zf.write(repo / f, f"{name}/{f}")
    return len(files)


if __name__ == "__main__":
    repo_root = Path(__file__).resolve().parents[1]
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else repo_root / "dist" / "sign_mapper.zip"
    count = build(repo_root, target)
    print(f"{target}: {count} files")
