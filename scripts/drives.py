"""Synthetic drives of the tools, generated once and kept under build/drives/ for the next run.

Generating a Full-HD drive takes minutes and the tools map the same drives again and again (evaluation seeds,
benchmark drives), so each tool names its drive's folder and asks :func:`cached_drive` for it; one function, so
every tool decides the same way whether a drive is there.
"""

from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DRIVES = REPO / "build" / "drives"


def cached_drive(out: Path, config) -> Path:
    """``out``, holding the synthetic drive of ``config`` (``SimulationConfig``): generated unless its poses.csv is
    there already (the generator writes into a temporary folder and moves the whole drive in place at the end)."""
    from signmapper_core.simulate import generate_drive

    if not (out / "poses.csv").exists():
        print(f"generating {out} ...", flush=True)
        generate_drive(out, config)
    return out
