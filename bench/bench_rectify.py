"""Speed of epipolar rectification and of a whole import, Full-HD raw pairs (target: >= 20 pairs/s on 2 cores).

    .venv/bin/python -m bench.bench_rectify [--pairs 40] [--runs 3] [--folder /tmp/rawpairs]

Writes ``--pairs`` raw Full-HD JPEG pairs (quality 95, a smooth random texture) and a toed-in, distorted
stereo calibration once, then measures per run:

- maps: building the undistort+rectify maps of both cameras (once per calibration);
- rectify: ``cv2.remap`` of both images of every pair, decoded beforehand, on 1 and on 2 threads;
- import: ``import_drive`` of the whole set with 1 and 2 worker threads (decode, rectify, JPEG encode,
  write, the first pair's rows check and the drive's validation).

The machine is shared: several runs are printed with their spread (min / median / max), and with each
figure the CPU time the process got (user + system, all threads): ``cpu`` = pairs per CPU-second, what one
free core would give; wall-clock figures on a busy machine fall below ``cores x cpu``.
"""

from __future__ import annotations

import argparse
import csv
import resource
import shutil
import statistics
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

SIZE = (1920, 1080)


def write_inputs(folder: Path, pairs: int) -> None:
    import cv2
    import numpy as np

    from tests.stereo_scenes import texture

    if (folder / "stereo.yml").exists() and len(list((folder / "left").glob("*.jpg"))) == pairs:
        return
    shutil.rmtree(folder, ignore_errors=True)
    for side in ("left", "right"):
        (folder / side).mkdir(parents=True)
    base = cv2.resize(texture(11, 1024), (2200, 1240))
    for i in range(pairs):
        left = base[40 + i % 50: 40 + i % 50 + SIZE[1], 60 + i: 60 + i + SIZE[0]]
        right = base[41 + i % 50: 41 + i % 50 + SIZE[1], 30 + i: 30 + i + SIZE[0]]
        cv2.imwrite(str(folder / "left" / f"{i:05d}.jpg"), left, [cv2.IMWRITE_JPEG_QUALITY, 95])
        cv2.imwrite(str(folder / "right" / f"{i:05d}.jpg"), right, [cv2.IMWRITE_JPEG_QUALITY, 95])
    k1 = np.array([[1750.0, 0, 955.0], [0, 1752.0, 541.0], [0, 0, 1]])
    k2 = np.array([[1760.0, 0, 966.0], [0, 1758.0, 536.0], [0, 0, 1]])
    storage = cv2.FileStorage(str(folder / "stereo.yml"), cv2.FILE_STORAGE_WRITE)
    for key, value in (("K1", k1), ("D1", np.array([[-0.12, 0.05, 0.0008, -0.0004, 0.0]])), ("K2", k2),
                       ("D2", np.array([[-0.10, 0.04, -0.0006, 0.0005, 0.0]])),
                       ("R", cv2.Rodrigues(np.array([0.002, -0.03, 0.001]))[0]), ("T", np.array([[-0.9], [0.004],
                                                                                                 [0.01]]))):
        storage.write(key, value)
    storage.write("image_width", SIZE[0])
    storage.write("image_height", SIZE[1])
    storage.release()
    with open(folder / "eo.csv", "w", newline="") as fh:   # camera poses along a straight street in LV95
        writer = csv.writer(fh)
        writer.writerow(["id", "time", "easting", "northing", "height", "heading", "pitch", "roll"])
        for i in range(pairs):
            writer.writerow([f"{i:05d}", f"{i * 0.2:.3f}", f"{2600000 + 2.2 * i:.3f}", "1200000.000", "500.000",
                             "90.0", "0.0", "0.0"])


def cpu_seconds() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def spread(values) -> str:
    return f"min {min(values):.1f} / median {statistics.median(values):.1f} / max {max(values):.1f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=40)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--folder", type=Path, default=Path(tempfile.gettempdir()) / "signmapper-bench-rectify")
    args = parser.parse_args()
    import cv2

    from signmapper_core.drive.images import read_image
    from signmapper_core.importdrive import GenericInputs, ImportOptions, Orientation, generic_source, import_drive
    from signmapper_core.importdrive.calibration import read_calibrations
    from signmapper_core.importdrive.rectify import Rectifier

    write_inputs(args.folder, args.pairs)
    calibration = read_calibrations(args.folder / "stereo.yml")[0]
    source = generic_source(GenericInputs(
        left=args.folder / "left", right=args.folder / "right", calibration=args.folder / "stereo.yml",
        poses=args.folder / "eo.csv", orientation=Orientation("camera_hpr", "deg", "grid"), input_crs="EPSG:2056"))
    decoded = [(read_image(p.left), read_image(p.right)) for p in source.pairs]
    print(f"{args.pairs} raw Full-HD JPEG pairs, OpenCV {cv2.__version__} with {cv2.getNumThreads()} threads")
    results: dict[str, list[float]] = {}
    for run in range(args.runs):
        start = time.perf_counter()
        rectifier = Rectifier(calibration, SIZE)
        results.setdefault("maps (ms, both cameras)", []).append(1e3 * (time.perf_counter() - start))
        for threads in (1, 2):
            start, cpu = time.perf_counter(), cpu_seconds()
            with ThreadPoolExecutor(max_workers=threads) as pool:
                list(pool.map(rectifier.rectify, *zip(*decoded)))
            wall, cpu = time.perf_counter() - start, cpu_seconds() - cpu
            results.setdefault(f"rectify, {threads} thread(s), pairs/s", []).append(args.pairs / wall)
            results.setdefault(f"rectify, {threads} thread(s), pairs per CPU-s", []).append(args.pairs / cpu)
        for workers in (1, 2):
            out = args.folder.parent / f"{args.folder.name}-drive"
            shutil.rmtree(out, ignore_errors=True)
            # the texture pairs are not views of one scene: the rows check runs but must not stop the bench
            options = ImportOptions(output_crs="EPSG:2056", workers=workers, max_vertical_disparity_px=1e9)
            cpu = cpu_seconds()
            summary = import_drive(out, source, options)
            cpu = cpu_seconds() - cpu
            results.setdefault(f"import, {workers} worker(s), pairs/s", []).append(args.pairs / summary.seconds)
            results.setdefault(f"import, {workers} worker(s), pairs per CPU-s", []).append(args.pairs / cpu)
            shutil.rmtree(out, ignore_errors=True)
        print(f"run {run + 1}: " + "; ".join(f"{k} {v[-1]:.1f}" for k, v in results.items()), flush=True)
    for name, values in results.items():
        print(f"{name}: {spread(values)}")


if __name__ == "__main__":
    main()
