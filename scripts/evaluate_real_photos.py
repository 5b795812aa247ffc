"""Recognition figures on real photographs (GTSRB crops, GTSDB scenes) mapped to SSV ids.

    python -m scripts.evaluate_real_photos classify --data DIR [--split report] [--limit N] [--seed 0] [--read-digits]
    python -m scripts.evaluate_real_photos detect --data DIR [--split report] [--limit N] [--seed 0]
    python -m scripts.evaluate_real_photos open-set --catalogue DIR --data DIR [--split tune]

``DIR`` holds crops.csv, scenes.csv, scenes_images.csv and the photographs (see
scripts/realset/README.md); default: $SIGNMAPPER_REAL_DATA, else the committed subset
tests/data/real-signs. Tune on ``--split tune``; report ``--split report``.

classify: the face box is given (the ground-truth box, "perfect box"); the candidates are the
catalogue entries with the true entry's colour and shape. Prints the correct-id rate and, among
the signs scored >= the classification threshold (0.6, status "accepted"), the share with a wrong id.

detect: the colour step on the whole photograph without depth (``pipeline.candidates.colour_step``:
colour segments of all passes, split faces merged, Hough circles for weak rims -> shape ->
candidate templates with their face boxes, as in ``evaluate_segment`` before sizing). A sign's
face is found when a segment's face box has IoU >= 0.5 with the truth box and the true id is among
that reading's candidates; a segment is on the sign when IoU >= 0.3 or its centre lies in the box.

open-set: the signs of ids a catalogue lacks (``training.left_out``), read by the network trained for it among
its entries of the sign's colour and shape: how many come out as unknown (the open set's limit), as no sign, in
review or accepted with another id.

Every table is split by group (``same``: the Swiss pictogram; ``differs``: same meaning, other
drawing) and by the sign's size in the photograph (longer side < 30 px, >= 30 px).
"""

from __future__ import annotations

import argparse
import os
import random
import statistics
import sys
import time
from collections import Counter, defaultdict
from pathlib import Path
from typing import Callable, Dict, List, Sequence

from signmapper_core.catalogue import load_catalogue
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.boxes import box_iou
from signmapper_core.validation import load_manifest, load_scene_list, read_bgr

REPO = Path(__file__).resolve().parents[1]
SMALL_PX = 30
SUBSET_DIR = REPO / "tests" / "data" / "real-signs"

def make_classifier(name: str, catalogue, model: Path = None):
    """The pipeline's classifier ``name`` (``signmapper_core.pipeline.classifiers``), or the network in ``model``."""
    from signmapper_core.pipeline.classifiers import CLASSIFIERS, LearnedClassifier, load_model_card
    from signmapper_core.pipeline.classifiers import make_classifier as make

    if model is not None:
        return LearnedClassifier(load_model_card(Path(model) / "model.json"))
    if name not in CLASSIFIERS:
        raise SystemExit(f"unknown classifier {name!r}; known: {', '.join(CLASSIFIERS)}")
    return make(name, catalogue)


def default_data() -> Path:
    env = os.environ.get("SIGNMAPPER_REAL_DATA")
    return Path(env) if env else SUBSET_DIR


def select(signs: list, split: str, limit: int, seed: int) -> list:
    """Signs of ``split`` ('all' = both), a seeded random ``limit`` of them if given, in manifest order."""
    chosen = [s for s in signs if split == "all" or s.split == split]
    if limit and limit < len(chosen):
        keep = set(random.Random(seed).sample(range(len(chosen)), limit))
        chosen = [s for i, s in enumerate(chosen) if i in keep]
    return chosen


def size_bin(size_px: int) -> str:
    return f"<{SMALL_PX}px" if size_px < SMALL_PX else f">={SMALL_PX}px"


def pct(k: int, n: int) -> str:
    return f"{100.0 * k / n:5.1f}%" if n else "    -"


def _median(values) -> str:
    return f"{statistics.median(values):5.0f}" if values else "    -"


def print_table(title: str, header: Sequence[str], rows: List[Sequence[str]]):
    widths = [max(len(str(c)) for c in col) for col in zip(header, *rows)] if rows else [len(h) for h in header]
    print(f"\n{title}")
    print("  " + "  ".join(str(h).rjust(w) for h, w in zip(header, widths)))
    for row in rows:
        print("  " + "  ".join(str(c).rjust(w) for c, w in zip(row, widths)))


def breakdowns(records: list, columns: Callable[[list], List[str]], header: Sequence[str], what: str):
    """Tables per group x size bin, per split, per SSV id of ``records`` (dicts with sign, ...)."""
    rows = []
    for group in ("same", "differs", "all"):
        for bin_name in (f"<{SMALL_PX}px", f">={SMALL_PX}px", "all"):
            sel = [r for r in records if (group == "all" or r["sign"].group == group)
                   and (bin_name == "all" or size_bin(r["sign"].size_px) == bin_name)]
            rows.append([group, bin_name, len(sel), _median([r["sign"].size_px for r in sel])] + columns(sel))
    print_table(f"{what} by group and size (longer side of the face box)",
                ["group", "size", "n", "median px"] + list(header), rows)
    rows = []
    for split in ("tune", "report"):
        for group in ("same", "differs"):
            sel = [r for r in records if r["sign"].split == split and r["sign"].group == group]
            if sel:
                rows.append([split, group, len(sel), _median([r["sign"].size_px for r in sel])] + columns(sel))
    print_table(f"{what} by split", ["split", "group", "n", "median px"] + list(header), rows)


def check_digits(records: list, catalogue) -> None:
    """The mapping's digits check (``number_check``) on each accepted speed-limit reading, from its one view:
    a reading whose digits say another speed limit's number is no longer accepted. Prints what it changed."""
    from signmapper_core.plates.number_check import judge_numbers
    from signmapper_core.plates.ocr import read_numbers
    from signmapper_core.plates.printed_numbers import number_band, prepared_band, printed_number, printed_numbers

    known = printed_numbers(catalogue.ids())
    checked, bands = [], []
    for r in records:
        band = number_band(r["sign"].load_image(), r["sign"].bbox) if r["accepted"] and printed_number(r["id"]) \
            else None
        if band is not None:
            checked.append(r)
            bands.append(prepared_band(band))
    demoted = Counter()
    for r, digits in zip(checked, read_numbers(bands)):
        if judge_numbers(printed_number(r["id"]), [digits], known).contradicts:
            r["accepted"] = False
            demoted["right" if r["id"] == r["sign"].ssv_id else "wrong"] += 1
    wrong = sum(r["id"] != r["sign"].ssv_id for r in checked)
    print(f"digits read on {len(checked)} accepted speed-limit readings ({wrong} of them wrong): "
          f"{demoted['wrong']} wrong and {demoted['right']} right ones no longer accepted (their digits read "
          f"another speed limit's number)")


def run_classify(args, catalogue, config: PipelineConfig) -> int:
    from signmapper_core.output.classifier_alternatives import ranked_alternatives
    from signmapper_core.pipeline.classifiers import NccClassifier, accept_threshold

    clf = make_classifier(args.classifier, catalogue, args.model)
    matcher = NccClassifier(catalogue, config)
    signs = select(load_manifest(args.data / args.manifest, known_ids={e.id for e in catalogue}), args.split,
                   args.limit, args.seed)
    records, by_matching = [], Counter()
    start = time.perf_counter()
    for sign in signs:
        entry = catalogue[sign.ssv_id]
        candidates = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape])]
        # as the pipeline does (PairContext.classifier_knowing): a network that does not know every candidate
        # (one trained before the white family was catalogued) leaves the sign to template matching
        reader = clf if clf.knows(candidates) else matcher
        if reader is not clf:
            by_matching[sign.ssv_id] += 1
        result = reader.classify(sign.load_image(), sign.bbox, candidates)
        records.append({"sign": sign, "id": result.template_id, "score": result.score, "n_cand": len(candidates),
                        "accepted": result.score >= accept_threshold(reader, config),
                        "next": [t for t, _ in ranked_alternatives(result.scores, result.template_id)]})
    seconds = time.perf_counter() - start
    if args.read_digits:
        check_digits(records, catalogue)
    which = f"{clf.name} {args.model}" if args.model else clf.name
    print(f"classify ({which}) on {args.data / args.manifest}: split={args.split}, {len(records)} signs, "
          f"{seconds:.0f} s ({1000 * seconds / max(1, len(records)):.0f} ms/sign); perfect box, candidates = "
          f"catalogue entries of the true colour and shape; accepted = score >= "
          f"{accept_threshold(clf, config)}")
    if by_matching:
        print(f"read by template matching (accepted >= {accept_threshold(matcher, config)}), the {clf.name} "
              f"classifier not knowing every candidate: {sum(by_matching.values())} signs, "
              f"{', '.join(f'{t} ({n})' for t, n in sorted(by_matching.items()))}")

    def columns(sel):
        correct = sum(r["id"] == r["sign"].ssv_id for r in sel)
        accepted = [r for r in sel if r["accepted"]]
        wrong_acc = sum(r["id"] != r["sign"].ssv_id for r in accepted)
        return [pct(correct, len(sel)), pct(len(accepted), len(sel)), pct(wrong_acc, len(accepted)),
                f"{statistics.mean(r['score'] for r in sel):.2f}" if sel else "-"]

    header = ["correct", "accepted", "wrong|acc", "mean score"]
    breakdowns(records, columns, header, "Classification")
    misread = [r for r in records if r["id"] != r["sign"].ssv_id]
    offered = sum(r["sign"].ssv_id in r["next"] for r in misread)
    print(f"misread signs: {len(misread)}; the true id among their next choices (the review's suggestions): "
          f"{offered} ({pct(offered, len(misread))})")
    by_id = defaultdict(list)
    for r in records:
        by_id[r["sign"].ssv_id].append(r)
    rows = []
    for sid in sorted(by_id, key=lambda s: (by_id[s][0]["sign"].group, s)):
        sel = by_id[sid]
        wrong = Counter(r["id"] for r in sel if r["id"] != sid)
        rows.append([sid, sel[0]["sign"].group, len(sel), sel[0]["n_cand"]] + columns(sel)[:3]
                    + [", ".join(f"{k} {v}" for k, v in wrong.most_common(3)) or "-"])
    print_table("Classification per SSV id (confusions: most frequent wrong ids)",
                ["ssv_id", "group", "n", "cands", "correct", "accepted", "wrong|acc", "confused with"], rows)
    return 0


OPEN_SET_OUTCOMES = ("unknown", "no sign", "review as another id", "accepted as another id", "no candidate")


def open_set_outcome(result, clf, config: PipelineConfig) -> str:
    """How a face of an id the network never saw comes out of its reading, as the pipeline judges a reading
    (``detect.matches_no_entry``, then the indicator's floors): mapped as unknown, not reported (no sign, or below
    the floor), in review or accepted with another id; no candidate: the network knows none of its colour and
    shape (the pipeline then asks template matching)."""
    from signmapper_core.pipeline.classifiers import accept_threshold, min_score
    from signmapper_core.pipeline.detect import matches_no_entry

    if result.template_id is None:
        return "no candidate"
    if matches_no_entry(result, clf, config):
        return "unknown"
    if result.score < min_score(clf, config):
        return "no sign"
    return "accepted as another id" if result.score >= accept_threshold(clf, config) else "review as another id"


def run_open_set(args, catalogue, config: PipelineConfig) -> int:
    """The signs of ids ``--catalogue`` lacks (a network trained without them, ``training.left_out``), read by its
    network among its entries of the sign's true colour and shape (the bundled catalogue's entry gives them)."""
    from signmapper_core.pipeline.classifiers import LearnedClassifier, load_model_card, model_card_path

    bundled = load_catalogue()
    model = args.model or model_card_path(catalogue.folder).parent
    clf = LearnedClassifier(load_model_card(Path(model) / "model.json"))
    signs = select([s for s in load_manifest(args.data / args.manifest, known_ids={e.id for e in bundled})
                    if s.ssv_id not in catalogue], args.split, args.limit, args.seed)
    records = []
    for sign in signs:
        entry = bundled[sign.ssv_id]
        candidates = [e.id for e in catalogue.filter(colours=[entry.colour], shapes=[entry.shape])]
        result = clf.classify(sign.load_image(), sign.bbox, candidates)
        records.append({"sign": sign, "outcome": open_set_outcome(result, clf, config), "id": result.template_id})
    print(f"open set ({clf.name} {model}, catalogue {catalogue.folder}) on {args.data / args.manifest}: "
          f"split={args.split}, {len(records)} signs of ids the catalogue lacks; perfect box")

    def columns(sel):
        return [pct(sum(r["outcome"] == o for r in sel), len(sel)) for o in OPEN_SET_OUTCOMES]

    breakdowns(records, columns, OPEN_SET_OUTCOMES, "Open set")
    by_id = defaultdict(list)
    for r in records:
        by_id[r["sign"].ssv_id].append(r)
    rows = [[sid, by_id[sid][0]["sign"].group, len(by_id[sid])] + columns(by_id[sid])
            + [", ".join(f"{k} {v}" for k, v in Counter(r["id"] for r in by_id[sid] if r["outcome"] in
                                                         OPEN_SET_OUTCOMES[2:4]).most_common(3)) or "-"]
            for sid in sorted(by_id, key=lambda s: (by_id[s][0]["sign"].group, s))]
    print_table("Open set per SSV id (read as: most frequent other ids)",
                ["ssv_id", "group", "n"] + list(OPEN_SET_OUTCOMES) + ["read as"], rows)
    return 0


def _centre_in(a, b) -> bool:
    cx, cy = a[0] + a[2] / 2.0, a[1] + a[3] / 2.0
    return b[0] <= cx < b[0] + b[2] and b[1] <= cy < b[1] + b[3]


def segment_readings(image, catalogue, config: PipelineConfig):
    """[(segment bbox, [(face box, candidate ids)])] of the colour step on a whole photograph.

    The colour step as ``pipeline.candidates.colour_step`` runs it without depth: all colour
    passes, split faces merged, ring fields, measured rims, Hough circles for weak rims, shape;
    segments that are no face candidate have no readings.
    """
    from signmapper_core.pipeline.candidates import colour_step

    segments, candidates = colour_step(image, catalogue, config)
    readings = {id(c.segment): [(r.bbox, list(r.template_ids)) for r in c.readings] for c in candidates}
    return [(seg.bbox, readings.get(id(seg), [])) for seg in segments]


def _read_other(path: Path) -> Dict[str, list]:
    """Boxes of labelled signs left out of scenes.csv (no SSV counterpart), by image."""
    import csv

    other = defaultdict(list)
    if path.is_file():
        with path.open(newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                x0, y0, x1, y1 = (int(row[k]) for k in ("x0", "y0", "x1", "y1"))
                other[row["image"]].append((x0, y0, x1 - x0, y1 - y0))
    return other


def run_detect(args, catalogue, config: PipelineConfig) -> int:
    scenes = select(load_scene_list(args.data / "scenes_images.csv"), args.split, args.limit, args.seed)
    signs = load_manifest(args.data / "scenes.csv", known_ids={e.id for e in catalogue})
    other = _read_other(args.data / "scenes_other.csv")
    # the colour step does not look for white signs (the white step needs depth): theirs are labelled boxes
    # like the unmapped classes', not signs it could have found
    white, by_image = [], defaultdict(list)
    for s in signs:
        if catalogue[s.ssv_id].colour == "white":
            white.append(s)
            other.setdefault(s.image.relative_to(args.data).as_posix(), []).append(s.bbox)
        else:
            by_image[s.image].append(s)
    records, per_image = [], []
    start = time.perf_counter()
    for scene in scenes:
        segments = segment_readings(read_bgr(scene.image), catalogue, config)
        truth = by_image.get(scene.image, [])
        labelled = [s.bbox for s in truth] + other.get(scene.image.relative_to(args.data).as_posix(), [])
        for sign in truth:
            on = any(box_iou(b, sign.bbox) >= 0.3 or _centre_in(b, sign.bbox) for b, _ in segments)
            found = any(box_iou(face, sign.bbox) >= 0.5 and sign.ssv_id in ids
                        for _, readings in segments for face, ids in readings)
            records.append({"sign": sign, "on": on, "found": found})
        with_cands = [b for b, readings in segments if readings]
        away = [b for b in with_cands if not any(box_iou(b, t) > 0 for t in labelled)]
        per_image.append((bool(truth), len(segments), len(with_cands), len(away)))
    seconds = time.perf_counter() - start
    print(f"detect (colour step, no depth) on {args.data / 'scenes_images.csv'}: split={args.split}, "
          f"{len(per_image)} images, {len(records)} signs, {seconds:.0f} s "
          f"({seconds / max(1, len(per_image)):.2f} s/image); {len(white)} white signs left out (all splits)")

    def columns(sel):
        return [pct(sum(r["found"] for r in sel), len(sel)), pct(sum(r["on"] for r in sel), len(sel))]

    breakdowns(records, columns, ["face found", "segment on sign"], "Detection")
    by_id = defaultdict(list)
    for r in records:
        by_id[r["sign"].ssv_id].append(r)
    rows = [[sid, by_id[sid][0]["sign"].group, len(by_id[sid]), _median([r["sign"].size_px for r in by_id[sid]])]
            + columns(by_id[sid]) for sid in sorted(by_id, key=lambda s: (by_id[s][0]["sign"].group, s))]
    print_table("Detection per SSV id", ["ssv_id", "group", "n", "median px", "face found", "segment on sign"], rows)
    rows = []
    for label, sel in (("with signs", [p for p in per_image if p[0]]),
                       ("without signs", [p for p in per_image if not p[0]]), ("all", per_image)):
        if sel:
            rows.append([label, len(sel)] + [f"{statistics.mean(p[i] for p in sel):.1f}" for i in (1, 2, 3)])
    print_table("Segments per image (mean); 'away' = with candidates and touching no labelled sign "
                "(GTSDB labels only its 43 classes, so not all of these are false)",
                ["images", "n", "segments", "with candidates", "away"], rows)
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mode", choices=("classify", "detect", "open-set"))
    parser.add_argument("--data", type=Path, default=None,
                        help="folder with the manifests (default $SIGNMAPPER_REAL_DATA or tests/data/real-signs)")
    parser.add_argument("--split", choices=("tune", "report", "all"), default="tune")
    parser.add_argument("--limit", type=int, default=0, help="a seeded random sample of this many signs/images")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--classifier", default="auto", help="auto, cnn or ncc (the pipeline's classifiers)")
    parser.add_argument("--manifest", default="crops.csv",
                        help="classify: the signs to classify (crops.csv: GTSRB crops; scenes.csv: the signs of the "
                             "GTSDB photographs, split by photograph)")
    parser.add_argument("--model", type=Path, default=None, help="evaluate the network in this model folder instead")
    parser.add_argument("--catalogue", type=Path, default=None,
                        help="open-set: the catalogue the network was trained for (training.left_out writes one); "
                             "its network is its classifier folder unless --model names another")
    parser.add_argument("--read-digits", action="store_true",
                        help="classify: the mapping's digits check on accepted speed-limit readings (Tesseract): a "
                             "reading whose digits say another speed limit's number no longer counts as accepted")
    args = parser.parse_args(argv)
    args.data = (args.data or default_data()).resolve()
    if not (args.data / "crops.csv").is_file():
        raise SystemExit(f"{args.data}: no crops.csv; pass --data or set SIGNMAPPER_REAL_DATA")
    if args.mode == "open-set" and args.catalogue is None:
        parser.error("open-set needs --catalogue: the catalogue without the ids the network never saw")
    catalogue = load_catalogue(args.catalogue)
    config = PipelineConfig()
    run = {"classify": run_classify, "detect": run_detect, "open-set": run_open_set}[args.mode]
    return run(args, catalogue, config)


if __name__ == "__main__":
    sys.exit(main())
