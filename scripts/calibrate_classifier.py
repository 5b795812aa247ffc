"""Calibrate the learned classifier's indicator on the tune half of the real photographs.

    python -m scripts.calibrate_classifier --data /work/data/real [--source gtsrb|gtsdb] [--max-wrong 0.015]

The network is trained on synthetic faces only; on real photographs it is more
sure of itself than it should be. This fits three numbers on real photographs
(never the network): the softmax temperature that makes the indicator a
probability, the acceptance threshold above which at most ``--max-wrong`` of
the accepted signs carry a wrong id, and the open set's limit: the logit that
``--unknown-percentile`` % of the real signs read right stay below (a face matching
its best candidate less well is mapped as unknown). Both are written into the model card with
what they were fitted on. Report figures on the other half (``--split report``
of ``scripts.evaluate_real_photos``), never on this one.

``--source`` picks the photographs: ``gtsrb``, the GTSRB test crops (``crops.csv``; the shipped card's),
whose tune and report halves share physical signs (the test set has no track ids to split by), or
``gtsdb``, the sign boxes of the GTSDB tune scenes (``scenes.csv``, read from the photograph as a crop is),
split by scene, so that no physical sign is on both sides.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from signmapper_core.catalogue import load_catalogue
from signmapper_core.pipeline.classifiers import LearnedClassifier, load_model_card, model_card_path
from signmapper_core.pipeline.classifiers.calibration import acceptance_threshold
from signmapper_core.validation import load_manifest

# --source -> (manifest, what the card says it was calibrated on)
SOURCES = {
    "gtsrb": ("crops.csv", "real photographs (GTSRB test crops), tune half of scripts/realset manifests; never "
                           "trained on; its halves share physical signs (no track ids)"),
    "gtsdb": ("scenes.csv", "real photographs (GTSDB sign boxes of the tune scenes), tune half of "
                            "scripts/realset manifests, split by scene; never trained on"),
}


def model_catalogue(model: Path | None) -> Path | None:
    """The catalogue folder a model folder sits in (``<catalogue>/classifier``), or None (the bundled one)."""
    if model is not None and (Path(model).resolve().parent / "catalogue.json").is_file():
        return Path(model).resolve().parent
    return None


def calibration_signs(data: Path, source: str, split: str, network_ids, catalogue, limit: int = 0):
    """The signs of ``source``'s manifest in ``split`` that the catalogue and the network (``network_ids``) know;
    the first ``limit`` of them if given (to try the code path). The manifest holds ids of the bundled catalogue,
    also those an open-set network was trained without."""
    manifest = data / SOURCES[source][0]
    signs = [s for s in load_manifest(manifest, known_ids=set(load_catalogue().ids()))
             if s.split == split and s.ssv_id in catalogue and s.ssv_id in network_ids]
    return signs[:limit] if limit else signs


def candidate_logits(classifier: LearnedClassifier, catalogue, signs):
    """Per sign: the network's logits restricted to its candidates (true colour and shape) + background, and
    the index of the true id among them."""
    rows = []
    for sign in signs:
        entry = catalogue[sign.ssv_id]
        ids = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape])]
        z = classifier.logits(sign.load_image(), [sign.bbox])[0]
        picked = [classifier.card.index(t) for t in ids] + [classifier.card.index("__background__")]
        rows.append((z[picked], ids.index(sign.ssv_id)))
    return rows


def probabilities(rows, temperature: float):
    """(probability of the best candidate, whether it is the true one) per sign."""
    best, right = [], []
    for z, truth in rows:
        zz = z / temperature
        p = np.exp(zz - zz.max())
        p /= p.sum()
        k = int(np.argmax(p[:-1]))
        best.append(p[k])
        right.append(k == truth)
    return np.array(best), np.array(right)


def fit_temperature(rows) -> float:
    """The temperature with the least negative log-likelihood of the true ids."""
    def nll(t):
        total = 0.0
        for z, truth in rows:
            zz = z / t
            total -= zz[truth] - (zz.max() + np.log(np.exp(zz - zz.max()).sum()))
        return total

    grid = np.exp(np.linspace(np.log(0.3), np.log(10.0), 80))
    return float(min(grid, key=nll))


def unknown_limit(rows, right: np.ndarray, percentile: float) -> float:
    """The true id's logit below which ``percentile`` % of the signs read right fall."""
    fits = [z[truth] for (z, truth), ok in zip(rows, right) if ok]
    return float(np.percentile(fits, percentile))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", type=Path, required=True,
                        help="folder with crops.csv and scenes.csv (scripts/realset)")
    parser.add_argument("--source", default="gtsrb", choices=sorted(SOURCES),
                        help="gtsrb: the GTSRB tune crops (crops.csv), whose halves share physical signs; gtsdb: the "
                             "sign boxes of the GTSDB tune scenes (scenes.csv), split by scene (default: "
                             "%(default)s)")
    parser.add_argument("--split", default="tune", choices=("tune",), help="only the tune half may be fitted on")
    parser.add_argument("--limit", type=int, default=0,
                        help="only the first N signs, to try the code path (needs --dry-run)")
    parser.add_argument("--catalogue", type=Path, default=None,
                        help="catalogue folder the network reads for (default: the one holding --model, else the "
                             "bundled one): a sign's candidates are its entries of the same colour and shape")
    parser.add_argument("--model", type=Path, default=None, help="model folder (default: the catalogue's)")
    parser.add_argument("--max-wrong", type=float, default=0.015, help="wrong share allowed among accepted signs")
    parser.add_argument("--unknown-percentile", type=float, default=2.0,
                        help="real signs read right that the open set's limit may take for unknown, in %%")
    parser.add_argument("--dry-run", action="store_true", help="print, do not write the model card")
    args = parser.parse_args(argv)
    if args.limit and not args.dry_run:
        parser.error("--limit calibrates on a few signs only: use it with --dry-run")
    catalogue = load_catalogue(args.catalogue or model_catalogue(args.model))
    card_path = (args.model / "model.json") if args.model else model_card_path(catalogue.folder)
    classifier = LearnedClassifier(load_model_card(card_path))
    signs = calibration_signs(args.data, args.source, args.split, set(classifier.card.classes), catalogue,
                              args.limit)
    manifest = args.data / SOURCES[args.source][0]
    if not signs:
        print(f"{manifest}: no {args.split} signs of an id that catalogue {catalogue.folder} and the network "
              f"{card_path} both know", file=sys.stderr)
        return 1
    rows = candidate_logits(classifier, catalogue, signs)
    before = classifier.card.temperature
    temperature = fit_temperature(rows)
    best, right = probabilities(rows, temperature)
    threshold = acceptance_threshold(best, right, args.max_wrong)
    accepted = best >= threshold
    limit = unknown_limit(rows, right, args.unknown_percentile)
    print(f"open set: unknown below logit {limit:.2f} (synthetic: {classifier.card.unknown_logit})")
    print(f"{len(rows)} real signs ({manifest}, split {args.split}): correct {right.mean():.3f}; "
          f"temperature {before:.3f} -> {temperature:.3f}; threshold {threshold:.3f} accepts {accepted.mean():.3f} "
          f"with {(~right[accepted]).mean() if accepted.any() else 0:.4f} wrong")
    if args.dry_run:
        return 0
    card = json.loads(card_path.read_text(encoding="utf-8"))
    card["temperature"] = round(temperature, 4)
    card["accept_threshold"] = round(threshold, 4)
    card["unknown_logit"] = round(limit, 3)
    card["calibration"] = {
        "data": SOURCES[args.source][1],
        "signs": len(rows), "max_wrong": args.max_wrong,
        "accepted_share": round(float(accepted.mean()), 4),
        "wrong_among_accepted": round(float((~right[accepted]).mean()) if accepted.any() else 0.0, 4),
        "synthetic_temperature": before if "calibration" not in card else card["calibration"]["synthetic_temperature"],
        "unknown_percentile": args.unknown_percentile,
        "synthetic_unknown_logit": card.get("calibration", {}).get("synthetic_unknown_logit",
                                                                    classifier.card.unknown_logit),
    }
    card_path.write_text(json.dumps(card, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {card_path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
