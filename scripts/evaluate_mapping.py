"""Map drives with the core pipeline and print Cavegn's Tables 1 and 2 against truth.csv.

    python -m scripts.evaluate_mapping DRIVE [DRIVE ...]
    python -m scripts.evaluate_mapping --generate 1001 1002 1003 --pairs 60 [--depth] [--workers 0]

``--generate`` writes held-out synthetic drives (cached under build/drives/) and
evaluates them. Seeds below 1000 are for tuning; report figures on seeds >= 1000.
Two tables per drive: the per-pair detections (several per sign; a sign is
detected when at least one detection lies within the matching radius, correctly
classified when the majority of its detections carry its template id), and the
fused signs (one feature per physical sign; duplicates = reference signs matched
by more than one fused sign). Signs in status "review" count like accepted ones;
the review step decides on them. Supplementary plates have rows of their own
(``plate_evaluation``): detected, linked to the right sign, text exactly right
for plates at least 40 px high. The white and grey signs and the coloured ones have rows of their own
too (``family_evaluation``): detected, correctly classified, false positives per 100 pairs; and a table of
the fused signs per colour family (red, blue, yellow, white and grey, green, brown, orange), faces printed from
the procedural designs apart: in view, detected, right id whatever the status, accepted, accepted with a wrong
id, 3D RMS. ``--ids`` adds how the signs of chosen ids came out (``id_outcomes``: mapped as unknown, accepted as
another id, missed), e.g. of ids left out of a classifier's training. Generated drives carry the whole
catalogue (``SimulationConfig`` defaults); ``--drawable`` generates the drives of before, and ``--white-share``
those with white signs and white distractors.
``--evidence`` lists, for every fused sign mapped with a wrong id, what each of its observations read
(``misread_evidence``): whether a vote could have found the true id, or the classifier never saw it; and
for every false positive the same per observation, with the pair and pixel box to look at; and every
supplementary plate missed, linked to another sign or read wrong, with its true and its mapped text.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Optional

import numpy as np

from scripts.drives import DRIVES, cached_drive
from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.evaluation.accuracy import combine_reports, evaluate, format_report, majority_id
from signmapper_core.evaluation.families import (
    COLOURED,
    WHITE,
    FamilyFigures,
    GroupFigures,
    catalogue_colour,
    family_figures,
    group_figures,
    group_lines,
)
from signmapper_core.evaluation.id_outcomes import id_outcomes, outcome_lines
from signmapper_core.evaluation.misread_evidence import (
    false_positive_lines,
    misread_lines,
    missed_lines,
    position_lines,
)
from signmapper_core.evaluation.panels import PanelFigures, evaluate_panels
from signmapper_core.evaluation.plates import PlateFigures, evaluate_plates
from signmapper_core.evaluation.visibility import mappable_signs
from signmapper_core.fusion.signs import sign_accept_threshold
from signmapper_core.output.classifier_alternatives import sign_alternatives
from signmapper_core.output.review_reasons import reason_shown
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.config import ClassificationConfig, DepthConfig, WhiteConfig
from signmapper_core.plates.fusion import is_plate
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate.face_artwork import OFFICIAL_PICTOGRAM, pictogram_group


def drive_config(seed: int, pairs: int, depth: bool, legacy_faces: bool = False, white_share: float = 0.0,
                 drawable: bool = False, plate_share: Optional[float] = None):
    """(folder under build/drives/, SimulationConfig) of a synthetic drive: the whole catalogue's signs, or with
    ``drawable`` (implied by ``legacy_faces`` and ``white_share``) the drives of before."""
    from signmapper_core.simulate import DRAWABLE_SIGNS, LEGACY_FACES, SimulationConfig
    from signmapper_core.simulate.config import WHOLE

    before = LEGACY_FACES if legacy_faces else DRAWABLE_SIGNS if drawable or white_share > 0 else {}
    plates = {} if plate_share is None else {"plate_share": plate_share}
    config = SimulationConfig(pairs=pairs, seed=seed, write_depth=depth, white_sign_share=white_share, **plates,
                              **before)
    faces = "legacy" if legacy_faces else f"{config.face_artwork}{config.master_share:g}"
    white = f"-white{white_share:g}" if white_share > 0 else ""
    # the drives of before keep their folder names; those of the whole catalogue have their own
    whole = "-whole" if config.sign_set == WHOLE else ""
    plated = f"-plates{plate_share:g}" if plate_share is not None else ""
    name = f"seed{seed}-{pairs}{'-depth' if depth else ''}-faces-{faces}{white}{whole}{plated}"
    return DRIVES / name, config


def depth_settings(near, far) -> DepthConfig:
    """The depth section of ``--near``/``--far``: the defaults and the camera's reach, or, where either is given,
    exactly that range (as ``mapsigns`` and ``python -m signmapper_core.map`` do)."""
    fixed = {k: v for k, v in (("near_m", near), ("far_m", far)) if v is not None}
    return DepthConfig(**fixed, range_from_camera=not fixed)


def add_depth_range_arguments(parser) -> None:
    """``--near`` and ``--far``, read by :func:`depth_settings`."""
    parser.add_argument("--near", type=float, default=None,
                        help=f"nearest depth searched [m] (default: {DepthConfig.near_m:g}, and the camera's reach "
                        "beyond far)")
    parser.add_argument("--far", type=float, default=None,
                        help=f"farthest depth searched [m] (default: {DepthConfig.far_m:g}); either fixes the range, "
                        "without reach")


def drive_folder(*args, **kwargs) -> Path:
    """The folder of :func:`drive_config`'s drive, which must have been generated."""
    out, _config = drive_config(*args, **kwargs)
    if not (out / "poses.csv").exists():
        raise SystemExit(f"{out} has not been generated")
    return out


def generated_drive(*args, **kwargs) -> Path:
    """The folder of :func:`drive_config`'s drive, generated unless there."""
    return cached_drive(*drive_config(*args, **kwargs))


FAMILIES = {"white and grey": WHITE, "coloured": COLOURED}
FAMILY_KINDS = {"detections": "per-pair detections", "signs": "fused signs"}


def azimuth_errors(signs, reference, report) -> list:
    """Signed face-azimuth differences (fused - truth facing) in degrees, of matched fused signs."""
    errors = []
    for sign, ref in zip(signs, report.match):
        if ref >= 0 and sign.azimuth is not None:
            errors.append((sign.azimuth - reference[ref].facing + 180.0) % 360.0 - 180.0)
    return errors


def accepted_but_wrong(signs, reference, report) -> tuple:
    """(accepted fused signs, of them matched to a reference sign of another id, of them matching none)."""
    accepted = [(sign, ref) for sign, ref in zip(signs, report.match) if sign.status == "accepted"]
    wrong = sum(1 for sign, ref in accepted if ref >= 0 and sign.template_id != reference[ref].template_id)
    return len(accepted), wrong, sum(1 for _, ref in accepted if ref < 0)


def review_outcomes(signs, reference, report) -> Counter:
    """{(review reason, outcome): fused signs in review}; outcome "right", "wrong" (another id than the reference
    sign's) or "no sign" (matching no reference sign). Says which rules hold right signs for nothing."""
    counts = Counter()
    for sign, ref in zip(signs, report.match):
        if sign.status != "review":
            continue
        outcome = "no sign" if ref < 0 else "right" if sign.template_id == reference[ref].template_id else "wrong"
        counts[(reason_shown(sign).split(":")[0], outcome)] += 1
    return counts


def review_lines(counts: Counter) -> list[str]:
    """One line per review reason, most frequent first: how many signs it held, of them right, wrong, no sign."""
    reasons = Counter()
    for (reason, _), n in counts.items():
        reasons[reason] += n
    lines = [f"Fused signs in review: {sum(reasons.values())}, by reason (right id / wrong id / no sign):"]
    for reason, n in reasons.most_common():
        lines.append(f"  {reason}: {n} ({counts[reason, 'right']} / {counts[reason, 'wrong']} / "
                     f"{counts[reason, 'no sign']})")
    return lines


def misread_offered(signs, reference, report) -> tuple:
    """(fused signs matched to a reference sign of another id, of them offering the true id among their next
    choices): how often the review's one-click suggestions hold the answer."""
    wrong = [(sign, reference[ref].template_id) for sign, ref in zip(signs, report.match)
             if ref >= 0 and sign.template_id != reference[ref].template_id]
    return len(wrong), sum(1 for sign, true_id in wrong if true_id in dict(sign_alternatives(sign)))


def by_artwork(signs, reference, report) -> dict:
    """{(artwork, pictogram group): [reference signs, detected, correctly classified]} of the fused signs, for
    synthetic drives whose truth names the artwork each face was printed from (the catalogue's drawing or a
    procedural design); procedural designs of another pictogram (``face_artwork.OTHER_PICTOGRAM``) apart."""
    counts = {}
    for k, ref in enumerate(reference):
        if not ref.artwork:
            continue
        ids = [sign.template_id for sign, match in zip(signs, report.match) if match == k]
        row = counts.setdefault((ref.artwork, pictogram_group(ref.template_id, ref.artwork)), [0, 0, 0])
        row[0] += 1
        row[1] += bool(ids)
        row[2] += bool(ids) and majority_id(ids) == ref.template_id  # as evaluate() counts it
    return counts


def artwork_lines(totals: dict) -> list:
    """Report lines of :func:`by_artwork`'s sums: each artwork and group, then all faces of the official
    pictogram (the figure comparable to the real photographs' "same" group)."""

    def line(label, n, found, right):
        return (f"Fused signs whose face was printed from {label}: {n}; detected {found} "
                f"({100 * found / max(n, 1):.1f} %), correctly classified {right} "
                f"({100 * right / max(found, 1):.1f} % of the detected)")

    lines = [line(f"the {artwork} artwork ({group})", *row) for (artwork, group), row in sorted(totals.items())]
    official = [row for (_, group), row in totals.items() if group == OFFICIAL_PICTOGRAM]
    if official and len(totals) > 1:
        lines.append(line(f"any artwork showing the {OFFICIAL_PICTOGRAM}", *(sum(c) for c in zip(*official))))
    return lines


def read_ids(text: str) -> list[str]:
    """The ids of ``--ids``: comma-separated, or ``@FILE`` with one id a line (blank lines and # comments skipped)."""
    if text.startswith("@"):
        lines = Path(text[1:]).read_text(encoding="utf-8").splitlines()
        return [line.split("#")[0].strip() for line in lines if line.split("#")[0].strip()]
    return [part.strip() for part in text.split(",") if part.strip()]


def positions_ids(items):
    return np.array([o.position for o in items]).reshape(-1, 3), [o.template_id for o in items]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("drives", nargs="*", type=Path, help="drive folders with truth.csv")
    parser.add_argument("--generate", nargs="*", type=int, default=[], help="seeds of synthetic drives to evaluate")
    parser.add_argument("--pairs", type=int, default=60, help="pairs per generated drive")
    parser.add_argument("--depth", action="store_true", help="generated drives carry true depth maps")
    parser.add_argument("--legacy-faces", action="store_true",
                        help="generated drives with the faces of before the artwork mix (procedural only)")
    parser.add_argument("--white-share", type=float, default=0.0,
                        help="generated drives of before (--drawable): share of sign poles with white and grey "
                             "signs (and white distractors)")
    parser.add_argument("--drawable", action="store_true",
                        help="generated drives of before the whole catalogue: only the signs the procedural drawer "
                             "knows, each equally likely (the seeds figures were taken on until 2026-12-06)")
    parser.add_argument("--ids", default="",
                        help="comma-separated ids, or @FILE with one id a line: how their signs came out (mapped "
                             "as unknown, accepted as another id, missed, ...), e.g. the ids left out of training")
    parser.add_argument("--plate-share", type=float, default=None,
                        help="generated drives: share of sign poles whose lowest sign carries a plate (default: the "
                             "generator's)")
    parser.add_argument("--radius", type=float, default=0.75, help="matching radius in metres")
    add_depth_range_arguments(parser)
    parser.add_argument("--catalogue", type=Path, default=None)
    parser.add_argument("--classifier", default="auto", help="auto, cnn or ncc")
    parser.add_argument("--workers", type=int, default=0, help="worker processes (0 = all cores)")
    parser.add_argument("--white-signs", action=argparse.BooleanOptionalAction, default=WhiteConfig().white_signs,
                        help="look for white and grey signs (the white step; default: "
                             f"{'on' if WhiteConfig().white_signs else 'off'})")
    parser.add_argument("--evidence", action="store_true",
                        help="per-observation readings of every fused sign mapped with a wrong id or matching no "
                             "reference sign")
    parser.add_argument("--positions", type=float, default=None, metavar="METRES",
                        help="list every fused sign whose 3D error is at least METRES, largest first, observation "
                             "by observation")
    args = parser.parse_args(argv)

    folders = list(args.drives) + [generated_drive(s, args.pairs, args.depth, args.legacy_faces, args.white_share,
                                                   args.drawable, args.plate_share) for s in args.generate]
    chosen_ids = read_ids(args.ids)
    if not folders:
        parser.error("give drive folders or --generate SEEDS")
    catalogue = load_catalogue(args.catalogue)
    config = PipelineConfig(depth=depth_settings(args.near, args.far),
                            classification=ClassificationConfig(classifier=args.classifier),
                            white=WhiteConfig(white_signs=args.white_signs))
    reports = {"detections": [], "signs": []}
    all_azimuth_errors = []
    accepted_total, accepted_wrong, accepted_unmatched = 0, 0, 0
    misread_total, offered_total = 0, 0
    review_totals = Counter()
    total_pairs, total_seconds = 0, 0.0
    plate_totals = PlateFigures()
    panel_totals = PanelFigures()
    artwork_totals = {}  # (artwork, pictogram group) -> [reference signs, detected, correct]
    colour_of = catalogue_colour(catalogue)
    family_totals = {(family, kind): FamilyFigures() for family in FAMILIES for kind in ("detections", "signs")}
    group_totals: dict[str, GroupFigures] = {}
    outcome_totals: dict = {}
    for folder in folders:
        drive = open_drive(folder, require_truth=True)
        traj = np.array([[r.pose.easting, r.pose.northing] for r in drive.pairs])
        start = time.perf_counter()
        result = map_drive(drive, catalogue, config, warn=lambda message: print(message, file=sys.stderr),
                           workers=args.workers)
        seconds = time.perf_counter() - start  # wall clock: workers map side by side
        searched = result.config.depth  # the range the drive's camera gave, unless --near/--far fixed it
        reference = mappable_signs(drive, searched)
        ref_xyz, ref_ids = [s.position for s in reference], [s.template_id for s in reference]
        signs = [s for s in result.signs if s.plate_of is None]  # plates have their own rows
        sign_detections = [o for o in result.detections if not is_plate(o)]
        head = f"== {folder} ({len(drive.pairs)} pairs, {len(result.skipped)} skipped, " \
               f"{len(drive.pairs) / max(seconds, 1e-9):.2f} pairs/s)"
        for kind, items in (("detections", sign_detections), ("signs", signs)):
            report = evaluate(*positions_ids(items), ref_xyz, ref_ids, traj, args.radius)
            reports[kind].append(report)
            if kind == "signs":
                plate_evidence = [] if args.evidence else None
                plates = evaluate_plates(drive, result.signs, reference, report.match, searched,
                                         args.radius, evidence=plate_evidence)
                plate_totals = plates + plate_totals
                panel_evidence = [] if args.evidence else None
                panels = evaluate_panels(drive, signs, reference, report.match, searched,
                                         evidence=panel_evidence)
                panel_totals = panels + panel_totals
                all_azimuth_errors += azimuth_errors(signs, reference, report)
                for artwork, row in by_artwork(signs, reference, report).items():
                    artwork_totals[artwork] = [a + b for a, b in zip(artwork_totals.get(artwork, [0, 0, 0]), row)]
                misread, offered = misread_offered(signs, reference, report)
                review_totals += review_outcomes(signs, reference, report)
                misread_total, offered_total = misread_total + misread, offered_total + offered
                groups = group_figures(signs, reference, report.match, colour_of)
                group_totals = {g: row + group_totals.get(g, GroupFigures()) for g, row in groups.items()}
                for template_id, counts in id_outcomes(signs, reference, report.match, chosen_ids).items():
                    outcome_totals[template_id] = outcome_totals.get(template_id, Counter()) + counts
                n, wrong, unmatched = accepted_but_wrong(signs, reference, report)
                accepted_total, accepted_wrong, accepted_unmatched = (accepted_total + n, accepted_wrong + wrong,
                                                                      accepted_unmatched + unmatched)
            print(format_report(report, f"{head}: {'per-pair detections' if kind == 'detections' else 'fused signs'}"))
            misread = misread_lines(signs, ref_ids, report.match) if kind == "signs" and args.evidence else []
            if misread:
                print("\n".join(["Fused signs with a wrong id, observation by observation:"] + misread))
            missed = missed_lines(reference, report.match) if kind == "signs" and args.evidence else []
            if missed:
                print("\n".join(["Reference signs not detected:"] + missed))
            false = false_positive_lines(signs, report.match) if kind == "signs" and args.evidence else []
            if false:
                print("\n".join(["False positives, observation by observation:"] + false))
            far_off = (position_lines(signs, reference, report.match, report.differences, args.positions)
                       if kind == "signs" and args.positions is not None else [])
            if far_off:
                print("\n".join([f"Fused signs at least {args.positions} m off:"] + far_off))
            print()
        print("\n".join(plates.lines(f"{head}: supplementary plates")))
        if plate_evidence:
            print("\n".join(["Plates missed, linked wrong or read wrong:"] + plate_evidence))
        print()
        if panels.reference:
            print("\n".join(panels.lines(f"{head}: white text panels")))
            if panel_evidence:
                print("\n".join(["Text panels missed or read wrong:"] + panel_evidence))
            print()
        for family, colours in FAMILIES.items():
            for kind, items in (("detections", sign_detections), ("signs", signs)):
                figures = family_figures(items, reference, colour_of, colours, traj, len(drive.pairs), args.radius)
                family_totals[family, kind] += figures
                print("\n".join(figures.lines(f"{head}: {family} signs, {FAMILY_KINDS[kind]}")))
            print()
        total_pairs += len(drive.pairs)
        total_seconds += seconds
    print(f"Fused signs with status accepted ({result.classifier_name}, threshold "
          f"{result.classification_threshold:.3f} a view, {sign_accept_threshold(result.fusion):.3f} a sign's "
          f"voters): {accepted_total}; with a wrong id {accepted_wrong} "
          f"({100 * accepted_wrong / max(accepted_total, 1):.1f} %), matching no reference sign {accepted_unmatched}")
    print(f"Fused signs with a wrong id: {misread_total}; the true id among their next choices (the review's "
          f"suggestions): {offered_total}")
    for line in review_lines(review_totals):
        print(line)
    for line in artwork_lines(artwork_totals):
        print(line)
    if all_azimuth_errors:
        err = np.abs(all_azimuth_errors)
        print(f"Face azimuth of fused signs vs truth facing: n={len(err)}, median |d| {np.median(err):.1f} deg, "
              f"90% {np.percentile(err, 90):.1f} deg, max {err.max():.1f} deg")
        print()
    if len(folders) > 1:
        for kind in ("detections", "signs"):
            print(format_report(combine_reports(reports[kind]),
                                f"== all {len(folders)} drives, {total_pairs} pairs, "
                                f"{total_pairs / max(total_seconds, 1e-9):.2f} pairs/s: {kind}"))
            print()
        print("\n".join(plate_totals.lines(f"== all {len(folders)} drives: supplementary plates")))
        print()
        if panel_totals.reference:
            print("\n".join(panel_totals.lines(f"== all {len(folders)} drives: white text panels")))
            print()
        for (family, kind), figures in family_totals.items():
            print("\n".join(figures.lines(f"== all {len(folders)} drives: {family} signs, {FAMILY_KINDS[kind]}")))
        print()
    print("\n".join(group_lines(group_totals, f"== all {len(folders)} drives: fused signs per colour family, faces "
                                             "of the procedural designs apart (accepted of the signs in view; "
                                             "'acc., none': accepted matching no sign, by their id's colour)")))
    print()
    if chosen_ids:
        print("\n".join(outcome_lines(outcome_totals, f"== all {len(folders)} drives: the {len(chosen_ids)} ids asked "
                                                     f"for, {len(outcome_totals)} of them in view")))
        print()
    return 0


if __name__ == "__main__":
    t0 = time.time()
    code = main()
    print(f"total wall time {time.time() - t0:.1f} s")
    sys.exit(code)
