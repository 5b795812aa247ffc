"""The ids a classifier is trained without, to measure how signs it never saw come out (the open set).

The ids are drawn by a seed written down before the training (``docs/measurements.md``), from every catalogue
entry the network is asked about (not the generic text panels, which are told by their layout), so that nobody
picks them after seeing results.
"""

from __future__ import annotations

import numpy as np

from signmapper_core.catalogue.text_panels import is_text_panel

LEFT_OUT_SHARE = 0.1
IDS_FILE = "left_out.txt"  # the ids left out, one a line: what evaluate_mapping's --ids @FILE reads


REPORT_SEED = 4401  # the measured split (docs/measurements.md)
DEVELOPMENT_SEED = 4402  # a split to develop the open-set rule on, drawn from the ids the measured one keeps


def left_out_ids(catalogue_ids, seed: int, share: float = LEFT_OUT_SHARE, besides=()) -> list:
    """A ``share`` of the ids (not counting ``besides``), drawn with ``seed`` from those not in ``besides``,
    in id order."""
    pool = sorted(t for t in catalogue_ids if not is_text_panel(t))
    n = int(round(share * len(pool)))
    pool = [t for t in pool if t not in set(besides)]
    picked = np.random.default_rng(seed).choice(len(pool), size=n, replace=False)
    return sorted(pool[i] for i in picked)


def catalogue_without(source, target, ids) -> list:
    """Write catalogue folder ``target``: ``source``'s catalogue without the entries ``ids`` (images linked, no
    classifier) and the ids in its :data:`IDS_FILE`. Returns the ids left out. The open-set run maps with it and
    a network trained on it."""
    import json
    from pathlib import Path

    source, target = Path(source), Path(target)
    data = json.loads((source / "catalogue.json").read_text(encoding="utf-8"))
    ids = set(ids)
    unknown = ids - {e["id"] for e in data["entries"]}
    if unknown:
        raise ValueError(f"{source}: no entries {sorted(unknown)}")
    data["entries"] = [e for e in data["entries"] if e["id"] not in ids]
    data["name"] = f"{data.get('name', source.name)} without {len(ids)} signs (open-set measurement)"
    target.mkdir(parents=True, exist_ok=True)
    for folder in ("png", "svg"):
        link = target / folder
        if not link.exists():
            link.symlink_to((source / folder).resolve())
    (target / "catalogue.json").write_text(json.dumps(data, ensure_ascii=False, indent=1) + "\n", encoding="utf-8")
    (target / IDS_FILE).write_text("".join(f"{t}\n" for t in sorted(ids)), encoding="utf-8")
    return sorted(ids)


def main(argv=None) -> int:
    import argparse

    from signmapper_core.catalogue import load_catalogue

    parser = argparse.ArgumentParser(description="Write a catalogue folder without the open-set ids of a seed.")
    parser.add_argument("target", help="folder to write")
    parser.add_argument("--seed", type=int, required=True, help="the seed written down before training")
    parser.add_argument("--catalogue", default=None, help="source catalogue folder (default: the bundled one)")
    args = parser.parse_args(argv)
    source = load_catalogue(args.catalogue)
    besides = left_out_ids(source.ids(), REPORT_SEED) if args.seed == DEVELOPMENT_SEED else ()
    ids = catalogue_without(source.folder, args.target, left_out_ids(source.ids(), args.seed, besides=besides))
    print(f"wrote {args.target}: {len(source) - len(ids)} entries, without {len(ids)}: {', '.join(ids)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
