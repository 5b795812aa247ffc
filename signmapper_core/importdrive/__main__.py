"""Command line: ``python -m signmapper_core.importdrive OUT --left L --right R --calibration C --poses P ...``
or ``python -m signmapper_core.importdrive OUT --kitti <date>_drive_<nnnn>_sync``."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import DriveFormatError, ImageReadError, ImportInputError
from ..progress import Cancelled
from .attitude import CONVENTIONS
from .camera_poses import NORTHS, Orientation
from .generic import GenericInputs, generic_source
from .importer import IMAGE_FORMATS, ImportOptions, import_drive
from .kitti import CAMERAS, is_kitti_drive, kitti_source, utm_crs


def build_parser() -> argparse.ArgumentParser:
    d, o = GenericInputs(Path(), Path(), Path()), ImportOptions()
    p = argparse.ArgumentParser(
        prog="python -m signmapper_core.importdrive",
        description="Build a drive folder (drive-format v1) from raw or rectified stereo images, a stereo "
                    "calibration and the poses of a navigation system or a photogrammetric exterior orientation.")
    p.add_argument("out", type=Path, help="drive folder to write (must not exist, or be empty)")
    p.add_argument("--kitti", type=Path, help="a KITTI raw drive folder (..._sync or ..._extract): the preset; "
                   "the calibration, images and poses are found in it")
    p.add_argument("--kitti-cameras", choices=tuple(CAMERAS), default="colour",
                   help="KITTI cameras: colour (02/03) or grey (00/01); default %(default)s")
    p.add_argument("--left", type=Path, help="folder of the left images")
    p.add_argument("--right", type=Path, help="folder of the right images (default: --left, with patterns)")
    p.add_argument("--left-pattern", default="", help="file name pattern of left images, '*' = image id "
                   "(e.g. '*_L.jpg'); default: every image, id = file name without suffix")
    p.add_argument("--right-pattern", default="", help="file name pattern of right images (e.g. '*_R.jpg')")
    p.add_argument("--calibration", type=Path, help="stereo calibration: OpenCV YAML/JSON (K1 D1 K2 D2 R T), KITTI "
                   "calib_cam_to_cam.txt, or a pinhole JSON (fx fy cx cy baseline_m) for rectified pairs")
    p.add_argument("--poses", type=Path, help="CSV of poses: one row per image (id column) or, with --trajectory, "
                   "a time-stamped trajectory")
    p.add_argument("--trajectory", action="store_true", help="the poses are a trajectory interpolated to the "
                   "image times (needs --image-times)")
    p.add_argument("--image-times", type=Path, help="CSV with id,time of every image (same clock as the poses)")
    p.add_argument("--angles", choices=tuple(CONVENTIONS), default=d.orientation.convention,
                   help="angle convention: " + "; ".join(f"{c.name}: {c.title}" for c in CONVENTIONS.values()))
    p.add_argument("--angle-unit", choices=("deg", "rad"), default=d.orientation.unit, help="unit of the angles")
    p.add_argument("--north", choices=NORTHS, default="auto", help="north of the angles: true north, the grid "
                   "north of a projected input CRS, or auto (navigation conventions true, camera conventions "
                   "the input grid)")
    p.add_argument("--input-crs", default=d.input_crs, help=f"CRS of the pose positions (default {d.input_crs}: "
                   "WGS 84 longitude/latitude with ellipsoidal heights)")
    p.add_argument("--output-crs", default=None, help=f"projected CRS of the drive (default {o.output_crs}, LV95; "
                   "KITTI: the UTM zone with EGM96 heights)")
    p.add_argument("--lever-arm", type=float, nargs=3, default=d.lever_arm_m, metavar=("X", "Y", "Z"),
                   help="left camera's projection centre in the body axes of the convention, metres")
    p.add_argument("--boresight", type=float, nargs=3, default=d.boresight_deg, metavar=("H", "P", "R"),
                   help="camera heading/pitch/roll relative to the body (0 0 0 = looking forward), degrees")
    p.add_argument("--image-format", choices=IMAGE_FORMATS, default=o.image_format, help="format of the written "
                   "images; auto keeps normal images as they are and writes JPEG otherwise")
    p.add_argument("--jpeg-quality", type=int, default=o.jpeg_quality, help="JPEG quality (default %(default)s)")
    p.add_argument("--max-vertical-disparity", type=float, default=o.max_vertical_disparity_px,
                   help="largest mean vertical disparity (px) of the first pair's features after rectification")
    p.add_argument("--check-image", type=Path, help="write the first pair with epipolar lines to this PNG")
    p.add_argument("--workers", type=int, default=o.workers, help="threads converting pairs (default %(default)s)")
    p.add_argument("--quiet", action="store_true", help="no progress output")
    return p


def source_from_args(args: argparse.Namespace):
    if args.kitti is not None:
        return kitti_source(args.kitti, args.kitti_cameras)
    if args.left is not None and is_kitti_drive(args.left):
        raise SystemExit(f"error: {args.left} is a KITTI raw drive folder, which the generic import does not read: "
                         f"give it as --kitti {args.left}")
    missing = [name for name in ("left", "calibration", "poses") if getattr(args, name) is None]
    if missing:
        raise SystemExit(f"error: give --kitti, or --{', --'.join(missing)}")
    return generic_source(GenericInputs(
        left=args.left, right=args.right, left_pattern=args.left_pattern, right_pattern=args.right_pattern,
        calibration=args.calibration, poses=args.poses, trajectory=args.trajectory, image_times=args.image_times,
        orientation=Orientation(args.angles, args.angle_unit, args.north), input_crs=args.input_crs,
        lever_arm_m=tuple(args.lever_arm), boresight_deg=tuple(args.boresight)))


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)

    def progress(fraction, message):
        if not args.quiet:
            print(f"\r{fraction * 100:5.1f}%  {message}   ", end="", file=sys.stderr, flush=True)

    def warn(message):
        print(f"\nwarning: {message}", file=sys.stderr)

    try:
        source = source_from_args(args)
        output_crs = args.output_crs or (utm_crs(source) if args.kitti is not None else ImportOptions.output_crs)
        options = ImportOptions(output_crs=output_crs, image_format=args.image_format,
                                jpeg_quality=args.jpeg_quality, max_vertical_disparity_px=args.max_vertical_disparity,
                                check_image=args.check_image, workers=args.workers)
        summary = import_drive(args.out, source, options, progress=progress, warn=warn)
    except (ImportInputError, DriveFormatError, ImageReadError, FileExistsError, ValueError) as exc:
        print(f"\nerror: {exc}", file=sys.stderr)
        return 2
    except (Cancelled, KeyboardInterrupt):
        print("\ncancelled; nothing written", file=sys.stderr)
        return 130
    if not args.quiet:
        print(file=sys.stderr)
    camera = summary.camera
    print(f"{summary.out_dir}: {summary.pairs} pairs in {summary.crs}, "
          f"{'rectified' if summary.resampled else 'normal images kept'}; camera {camera.width}x{camera.height} "
          f"fx {camera.fx:.2f} baseline {camera.baseline_m:.4f} m; first pair: {summary.check.text()}; "
          f"{summary.seconds:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
