"""Command line: map the traffic signs of one or many drives without QGIS, locally or on a Dask cluster.

    python -m signmapper_core.map DRIVE --out OUT.gpkg [--scheduler tcp://HOST:PORT] [--workers N] [--crops]
    python -m signmapper_core.map DRIVE1 DRIVE2 ... --out FOLDER [--scheduler ...]

The same mapping and the same GeoPackage layers, fields and run table as
``mapsigns`` (``gpkg_writer``); with ``--crops``, as mapsigns' "Write an image
crop per sign", a JPEG per sign in ``<output name>_crops`` beside each
GeoPackage. Without ``--scheduler`` the pairs are mapped here in a process pool
(Dask is never imported); with it, on the Dask cluster whose scheduler is at
that address: its workers read the pairs from the drive paths given here (which
must be the same on every machine), only detections come back, and fusion runs
here, once per drive. Several drives share one connection to the cluster; each
gets its own GeoPackage, named after its folder.
Exit status 0 when every drive was written, 1 when one failed, 2 for wrong arguments.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Optional

from .drive.clock import drive_start, first_time
from .errors import ClusterError, DriveFormatError, MappingError
from .output.geopackage_file import OutputFileError
from .output.gpkg_writer import write_geopackage
from .output.schema import LANGUAGES, OutputContext, language_of
from .run import MAX_SKIPPED_PERCENT

PRINT_EVERY_S = 5.0  # a progress line at most this often


def build_parser() -> argparse.ArgumentParser:
    from .pipeline.config import DepthConfig, WhiteConfig  # the settings alone: no OpenCV

    p = argparse.ArgumentParser(
        prog="python -m signmapper_core.map",
        description="Map the traffic signs of drives into GeoPackages (the layers of mapsigns) without QGIS: "
                    "here in a process pool, or on a Dask cluster with --scheduler (docs/scale-out.md).")
    p.add_argument("drives", nargs="+", metavar="DRIVE", help="drive folder(s) (stereo-drive/1)")
    p.add_argument("--out", required=True,
                   help="output GeoPackage (.gpkg) for one drive; a folder for several (one <drive name>.gpkg each)")
    p.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                   help="map on the Dask cluster of this scheduler (needs requirements-dask.txt; docs/scale-out.md)")
    p.add_argument("--workers", type=int, default=0,
                   help="without --scheduler: worker processes here (0 = all cores, 1 = this process; "
                        "default %(default)s)")
    p.add_argument("--connect-timeout", type=float, default=10.0, metavar="S",
                   help="seconds to wait for the scheduler and its first worker (default %(default)g)")
    p.add_argument("--catalogue", help="template catalogue folder (default: the bundled Swiss catalogue); on a "
                                       "cluster a folder of your own must be at the same path on every worker")
    p.add_argument("--settings-from", metavar="GPKG",
                   help="map with the settings an earlier output's run table records (pipeline, fusion, catalogue)")
    for flag, limit in (("--near", "nearest"), ("--far", "farthest")):
        p.add_argument(flag, type=float, default=None, metavar="M",
                       help=f"{limit} depth searched [m] (default: {DepthConfig.near_m:g}-{DepthConfig.far_m:g} m "
                            "and, beyond, the reach the drive's camera gives; either fixes the range, without reach)")
    p.add_argument("--white-signs", action=argparse.BooleanOptionalAction, default=None,
                   help="look for white and grey signs (end-of-restriction discs and panels, white place-name and "
                        "direction panels), as the mapsigns option (default: "
                        f"{'on' if WhiteConfig().white_signs else 'off'}, or as the --settings-from record says)")
    p.add_argument("--language", choices=LANGUAGES,
                   help="language of sign names (default: the environment's locale, else English)")
    p.add_argument("--crops", action="store_true",
                   help="write an image crop per sign (JPEG of its best pair) in a folder <output name>_crops beside "
                        "the GeoPackage, its path in the field crop_path, as mapsigns does")
    p.add_argument("--max-skipped", type=float, default=MAX_SKIPPED_PERCENT, metavar="PERCENT",
                   help="largest share of unreadable pairs before a drive fails (default %(default)g %%, as mapsigns)")
    return p


def output_paths(drives: list[Path], out: Path) -> list[Path]:
    """The GeoPackage of each drive: ``out`` for one drive, ``out/<drive name>.gpkg`` for several."""
    if len(drives) == 1:
        if out.suffix.lower() != ".gpkg":
            raise ValueError(f"--out {out}: the output must be a GeoPackage file ending in .gpkg")
        return [out]
    if out.suffix.lower() == ".gpkg":
        raise ValueError(f"--out {out}: with {len(drives)} drives --out is a folder (one <drive name>.gpkg each)")
    names = [d.resolve().name for d in drives]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ValueError(f"drive folders named alike ({', '.join(twice)}) would write the same GeoPackage in {out}; "
                         "map them in separate runs")
    return [out / f"{name}.gpkg" for name in names]


def environment_language() -> str:
    """The output language of the environment's locale (LC_ALL, LC_MESSAGES, LANG), else English."""
    for name in ("LC_ALL", "LC_MESSAGES", "LANG"):
        if os.environ.get(name):
            return language_of(os.environ[name])
    return "en"


def settings(args, say):
    """(catalogue, PipelineConfig, FusionConfig) of the arguments and, when given, an earlier output's record."""
    from .run.setup import assemble_run  # delays OpenCV and numpy until used

    choices = {} if args.white_signs is None else {("white", "white_signs"): args.white_signs}  # given, it wins
    choices.update({("depth", "near_m"): args.near, ("depth", "far_m"): args.far})  # None: not given
    run = assemble_run(choices, args.settings_from, args.catalogue, warn=say,
                       labels={"settings_from": "--settings-from", "catalogue": "--catalogue", "near_m": "--near",
                               "far_m": "--far"})
    return run.catalogue, run.config, run.fusion


class Printer:
    """Progress on stderr: a line every PRINT_EVERY_S seconds and every warning."""

    def __init__(self, drive_name: str):
        self.drive_name = drive_name
        self.last = 0.0

    def progress(self, fraction: float, message: str) -> None:
        now = time.monotonic()
        if now - self.last >= PRINT_EVERY_S or fraction >= 1.0:
            self.last = now
            print(f"{self.drive_name}: {100 * fraction:5.1f} % {message}", file=sys.stderr, flush=True)

    @staticmethod
    def warn(message: str) -> None:
        print(f"warning: {message}", file=sys.stderr, flush=True)


def map_one(folder: Path, target: Path, catalogue, config, fusion, args, scheduler) -> str:
    """Map the drive at ``folder`` (on the cluster when ``scheduler`` is a client) and write ``target``."""
    from .drive.reader import open_drive  # delays numpy until used
    from .output.sign_crops import CropFolder  # delays OpenCV until used
    from .run.mapping import map_drive  # delays OpenCV and numpy until used

    printer = Printer(folder.name)
    drive = open_drive(folder, progress=None)
    for message in drive.warnings:
        printer.warn(message)
    start = time.perf_counter()
    result = map_drive(drive, catalogue, config, printer.progress, warn=printer.warn, fusion=fusion,
                       max_skipped_share=args.max_skipped / 100.0, workers=args.workers, scheduler=scheduler)
    seconds = time.perf_counter() - start
    crops = CropFolder(target) if args.crops else None
    try:
        written = crops.write(drive, result.signs, warn=printer.warn) if crops is not None else {}
        context = OutputContext(language=args.language or environment_language(), catalogue=catalogue,
                                start=drive_start(drive), first_time=first_time(drive), crops=written)
        path = write_geopackage(target, result, context)
        if crops is not None:
            crops.commit()
    except BaseException:
        if crops is not None:
            crops.discard()
        raise
    skipped = f"; {result.failure_summary()}" if result.skipped else ""
    in_folder = f", {len(written)} crops in {crops.folder}" if crops is not None else ""
    print(f"{folder}: {len(drive.pairs)} pairs in {seconds:.1f} s ({len(drive.pairs) / max(seconds, 1e-9):.2f} "
          f"pairs/s), {len(result.detections)} detections fused into {len(result.signs)} signs, written to "
          f"{path}{in_folder}{skipped}", flush=True)
    return path


def main(argv: Optional[list[str]] = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)

    drives = [Path(d) for d in args.drives]
    try:
        targets = output_paths(drives, Path(args.out))
        missing = [str(d) for d in drives if not (d / "drive.json").is_file()]
        if missing:
            raise ValueError(f"no drive.json in {', '.join(missing)}: not a stereo-drive/1 folder")
        if args.workers < 0:
            raise ValueError(f"--workers must be 0 (all cores) or more, not {args.workers}")
    except ValueError as exc:
        parser.error(str(exc))
    client = None
    try:
        catalogue, config, fusion = settings(args, Printer.warn)
        if args.scheduler:
            from .run.dask_pairs import connect  # delays numpy until used

            client = connect(args.scheduler, args.connect_timeout)  # before any work: an unreachable one says so
            threads = sum(client.nthreads().values())
            print(f"Dask scheduler {client.scheduler.address}: {len(client.nthreads())} workers, {threads} threads",
                  file=sys.stderr, flush=True)
        for folder, target in zip(drives, targets):
            map_one(folder, target, catalogue, config, fusion, args, client)
    except (ClusterError, MappingError, DriveFormatError, OutputFileError, ValueError) as exc:
        print(f"error: {exc}", file=sys.stderr, flush=True)
        return 1
    finally:
        if client is not None:
            client.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
