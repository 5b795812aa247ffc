"""CPU time per pair of two checkouts of the core, in one process, the same pairs alternately.

    python -m bench.ab_cpu BASE_CHECKOUT NEW_CHECKOUT [--drive DRIVE] [--pairs 40] [--rounds 3]

``--drive``: a drive folder (default build/drives/seed2001-100-stereo, the one ``bench.bench_mapping`` generates).

Each checkout's ``signmapper_core`` is imported under a name of its own (the package imports
itself only relatively), both map pair 1, then pairs 1..N again and again: each pair by one
checkout and then by the other, the order swapped every pair, OpenCV on one thread as in a
worker. On a machine shared with other work, separate runs of the two differ by ±15 % with the
load of the moment; alternating pair by pair, both see the same load. Prints the process CPU
time per pair of each (the sum over all rounds, and the sum of each pair's least time over the
rounds) and whether the first round's detections are the same (template, box, indicators).
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import os
import sys
import time
from pathlib import Path

from scripts.drives import DRIVES


def import_core(checkout: Path, name: str) -> None:
    """``checkout``'s ``signmapper_core`` imported as the package ``name``, its modules below it by that name (the
    package imports itself only relatively): two checkouts side by side in one process, no folder on sys.path."""
    folder = checkout.resolve() / "signmapper_core"
    spec = importlib.util.spec_from_file_location(name, folder / "__init__.py",
                                                  submodule_search_locations=[str(folder)])
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)


def core_function(package: str, modules, function: str):
    """``function`` of the first of ``modules`` (below ``package``) that has it: where it lives in the core now,
    then where it lived before (a base checkout may be older)."""
    for module in modules:
        try:
            found = getattr(importlib.import_module(f"{package}.{module}"), function, None)
        except ModuleNotFoundError:
            continue
        if found is not None:
            return found
    raise SystemExit(f"{package}: no {function} in {', '.join(modules)}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base", type=Path)
    parser.add_argument("new", type=Path)
    parser.add_argument("--drive", type=Path, default=DRIVES / "seed2001-100-stereo")
    parser.add_argument("--pairs", type=int, default=40)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    import cv2

    cv2.setNumThreads(1)
    names = {"base": "ab_base_core", "new": "ab_new_core"}
    runs = {}
    for key, name in names.items():
        import_core(getattr(args, key), name)
        catalogue = importlib.import_module(name + ".catalogue").load_catalogue()
        drive = core_function(name, ("drive.reader", "drive"), "open_drive")(args.drive)
        config = importlib.import_module(name + ".pipeline").PipelineConfig()
        map_pair = core_function(name, ("run.pair", "run.mapping", "mapping"), "map_pair")
        map_pair(drive, drive.pairs[0], catalogue, config)  # warm-up: classifier, templates
        runs[key] = (drive, catalogue, config, map_pair)
    seconds = {key: {} for key in runs}
    found = {key: [] for key in runs}
    turn = 0
    for round_ in range(args.rounds):
        for i in range(1, 1 + args.pairs):
            for key in (("base", "new") if turn % 2 == 0 else ("new", "base")):
                drive, catalogue, config, map_pair = runs[key]
                start = time.process_time()
                result = map_pair(drive, drive.pairs[i], catalogue, config)
                seconds[key].setdefault(i, []).append(time.process_time() - start)
                if round_ == 0:
                    found[key].append([(d.template_id, tuple(d.bbox), round(d.detection_indicator, 6),
                                        round(d.classification_indicator, 6)) for d in result.detections])
            turn += 1
    mean = {k: sum(sum(v) for v in s.values()) * 1000 / (args.pairs * args.rounds) for k, s in seconds.items()}
    least = {k: sum(min(v) for v in s.values()) * 1000 / args.pairs for k, s in seconds.items()}
    print(f"{args.drive.name}, pairs 1-{args.pairs}, {args.rounds} rounds, load average {os.getloadavg()[0]:.1f}")
    print(f"mean:  base {mean['base']:.1f}  new {mean['new']:.1f} ms CPU/pair "
          f"({(mean['new'] / mean['base'] - 1) * 100:+.1f} %)")
    print(f"least: base {least['base']:.1f}  new {least['new']:.1f} ms CPU/pair "
          f"({(least['new'] / least['base'] - 1) * 100:+.1f} %)")
    print(f"same detections: {found['base'] == found['new']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
