"""Command line: ``python -m signmapper_core.simulate OUT --pairs N --seed S [--depth] ...``."""

from __future__ import annotations

import argparse
import sys
from dataclasses import fields

from .config import DRAWABLE, DRAWABLE_SIGNS, LEGACY_FACES, WHOLE, SimulationConfig
from .generator import generate_drive

REALISM = ("noise", "motion_blur", "exposure_changes", "shadows", "weathering", "occlusion", "glare", "face_print",
           "face_sheeting", "face_wear", "face_dirt", "face_marks", "face_dents", "back_mounts")


def build_parser() -> argparse.ArgumentParser:
    d = SimulationConfig()
    p = argparse.ArgumentParser(
        prog="python -m signmapper_core.simulate",
        description="Write a synthetic stereo mobile-mapping drive (drive-format v1) with truth.csv: "
                    "a street with traffic signs, distractors and realistic camera effects.")
    p.add_argument("out", help="output drive folder (must not exist, or be empty)")
    p.add_argument("--pairs", type=int, default=d.pairs, help=f"number of stereo pairs (default {d.pairs})")
    p.add_argument("--seed", type=int, default=d.seed, help=f"random seed; same seed, same files (default {d.seed})")
    p.add_argument("--depth", action="store_true", help="also write true depth maps depth/<id>.npy")
    p.add_argument("--width", type=int, default=d.width, help=f"image width in pixels (default {d.width})")
    p.add_argument("--height", type=int, default=d.height, help=f"image height in pixels (default {d.height})")
    p.add_argument("--fx", type=float, default=None,
                   help=f"focal length in pixels (default {d.fx:g}, scaled with --width when that is given)")
    p.add_argument("--baseline", type=float, default=d.baseline_m,
                   help=f"stereo baseline, m (default {d.baseline_m})")
    p.add_argument("--speed", type=float, default=d.speed_kmh, help=f"vehicle speed, km/h (default {d.speed_kmh:g})")
    p.add_argument("--rate", type=float, default=d.rate_hz, help=f"pairs per second (default {d.rate_hz:g})")
    p.add_argument("--position-sigma", type=float, default=d.position_sigma_m,
                   help=f"GNSS noise of recorded positions per axis, m (default {d.position_sigma_m})")
    p.add_argument("--angle-sigma", type=float, default=d.angle_sigma_deg,
                   help=f"INS noise of recorded angles, degrees (default {d.angle_sigma_deg})")
    p.add_argument("--sign-density", type=float, default=d.sign_density,
                   help=f"sign poles per 100 m (default {d.sign_density:g})")
    p.add_argument("--distractor-density", type=float, default=d.distractor_density,
                   help=f"colour distractors per 100 m (default {d.distractor_density:g})")
    p.add_argument("--jpeg-quality", type=int, default=d.jpeg_quality, help=f"JPEG quality (default {d.jpeg_quality})")
    p.add_argument("--crs", default=d.crs, help=f"CRS of the coordinates (default {d.crs})")
    p.add_argument("--start", type=float, nargs=3, metavar=("E", "N", "H"),
                   default=(d.start_easting, d.start_northing, d.start_height), help="start point of the street")
    p.add_argument("--sign-set", choices=(WHOLE, DRAWABLE), default=d.sign_set,
                   help="'whole': signs of every family of the whole catalogue in the proportions of a Swiss street; "
                        "'drawable': the drives of before, only the signs the procedural drawer knows, each equally "
                        f"likely, printed from their masters only (default {d.sign_set})")
    p.add_argument("--no-face-variants", action="store_true",
                   help="print master faces from the entry's master drawing only, never from its variants "
                        "(other languages, the other pointing direction)")
    p.add_argument("--face-artwork", choices=("mixed", "procedural"), default=d.face_artwork,
                   help="sign faces from the catalogue master or the procedural drawer per sign ('mixed'), or "
                        f"procedural only (default {d.face_artwork})")
    p.add_argument("--master-share", type=float, default=d.master_share,
                   help=f"with 'mixed': share of faces printed from the catalogue master (default {d.master_share})")
    p.add_argument("--legacy-faces", action="store_true",
                   help="the faces of before the artwork mix: procedural only, no physical face variation")
    p.add_argument("--plain", action="store_true", help="switch off all camera, weathering and face effects")
    for name in REALISM:
        words = name.replace("_", " ")
        p.add_argument(f"--no-{name.replace('_', '-')}", action="store_true", help=f"switch off {words}")
    p.add_argument("--white-sign-share", type=float, default=d.white_sign_share,
                   help="with --sign-set drawable: share of sign poles with white and grey signs, plus white "
                        f"distractors (default {d.white_sign_share:g})")
    p.add_argument("--plate-share", type=float, default=d.plate_share,
                   help="share of sign poles whose lowest sign carries a supplementary plate, plus white text "
                        f"plates on façades (default {d.plate_share:g})")
    p.add_argument("--sign-offset", type=float, nargs=2, metavar=("MIN", "MAX"), default=d.sign_offset_m,
                   help="a wide street: each sign spot's first sign at a lateral distance from the vehicle's track "
                        "drawn uniformly between MIN and MAX metres, façades set back behind (default: at the kerb)")
    p.add_argument("--right-share", type=float, default=d.right_sign_share,
                   help="share of the sign spots on the right of the street (default: the generator's)")
    p.add_argument("--quiet", action="store_true", help="no progress output")
    return p


def config_from_args(args: argparse.Namespace) -> SimulationConfig:
    d = SimulationConfig()
    fx = args.fx if args.fx is not None else d.fx * args.width / d.width
    cfg = SimulationConfig(
        pairs=args.pairs, seed=args.seed, write_depth=args.depth, width=args.width, height=args.height, fx=fx,
        baseline_m=args.baseline, speed_kmh=args.speed, rate_hz=args.rate, position_sigma_m=args.position_sigma,
        angle_sigma_deg=args.angle_sigma, sign_density=args.sign_density,
        distractor_density=args.distractor_density, jpeg_quality=args.jpeg_quality, crs=args.crs,
        start_easting=args.start[0], start_northing=args.start[1], start_height=args.start[2],
        face_artwork=args.face_artwork, master_share=args.master_share, white_sign_share=args.white_sign_share,
        plate_share=args.plate_share,
        sign_offset_m=tuple(args.sign_offset) if args.sign_offset is not None else None,
        right_sign_share=args.right_share)
    if args.sign_set == DRAWABLE:
        for name, value in DRAWABLE_SIGNS.items():
            setattr(cfg, name, value)
    cfg.face_variants = cfg.face_variants and not args.no_face_variants
    if args.legacy_faces:
        for name, value in LEGACY_FACES.items():
            setattr(cfg, name, value)
    names = {f.name for f in fields(cfg)}
    for name in REALISM:
        if name in names and (args.plain or getattr(args, f"no_{name}")):
            setattr(cfg, name, False)
    return cfg


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    try:
        cfg = config_from_args(args)
        cfg.validate()
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2

    def progress(fraction, message):
        if not args.quiet:
            print(f"\r{fraction * 100:5.1f}%  {message}   ", end="", file=sys.stderr, flush=True)

    try:
        summary = generate_drive(args.out, cfg, progress=progress)
    except FileExistsError as exc:
        print(f"\nerror: {exc}", file=sys.stderr)
        return 2
    if not args.quiet:
        print(file=sys.stderr)
    print(f"{summary.out_dir}: {summary.pairs} pairs, {len(summary.signs)} signs in truth.csv, "
          f"{summary.bytes_written / 1e6:.1f} MB, {summary.seconds:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
