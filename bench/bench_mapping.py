"""Pairs per second and memory of mapping a drive end to end, from the JPEG files, against the naive baseline.

    python -m bench.bench_mapping [--pairs 20] [--seed 2001] [--rounds 3] [--long 1000] [--dask] [--scheduler tcp://HOST:PORT]

A synthetic Full-HD drive of JPEG stereo pairs without depth maps (generated once,
cached under build/drives/) is mapped three ways, each in its own process so its
memory is its own, all timed by the wall clock from the first JPEG decoded to the
fused signs (worker start-up, decoding, SGBM, detection and fusion included):
  pipeline-1    ``map_drive`` with 1 worker (in the process)
  pipeline-all  ``map_drive`` with a worker process per core
  baseline      decoding the same JPEG pairs and full-frame, full-resolution SGBM
                over disparities 0..256 (no detection at all), a worker per core
``--dask`` adds the pairs mapped on a Dask LocalCluster on 127.0.0.1 with 1 and with
2 worker processes of one thread each (``dask-1``, ``dask-2``: cluster start-up not
timed, the connection, the workers' first pair with its classifier load and fusion
in the client are), ``--scheduler ADDRESS`` on a running cluster (``dask-scheduler``).
``--rounds K`` then maps with all workers and the baseline K - 1 more times, one after the
other, and prints each round's ratio: on a shared host the speed drifts over minutes, so a
ratio is fair only between runs close in time. ``--long N`` then maps a drive of N pairs
(the drive's pairs repeated under new ids) with all workers and prints the resident memory of the main process plus its
workers as it goes: memory must stay flat with drive length.
Each row also gives the CPU time per pair (user + system of the mode's process and its
worker processes, start-up included) and the load average at its start and end: on a
shared machine the wall clock varies with the other sessions' work, the CPU time much less.
The vehicle records 5 pairs/s; faster than that keeps up with the drive.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import os
import resource
import statistics
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

from scripts.drives import DRIVES, cached_drive

REPO = Path(__file__).resolve().parents[1]

MODES = ("pipeline-1", "pipeline-all", "baseline")
DASK_MODES = ("dask-1", "dask-2")


def baseline_depth(left, right, camera):
    """Full-frame SGBM over 0..256 disparities at full resolution: what the range restriction saves."""
    import cv2
    import numpy as np

    block = 5
    matcher = cv2.StereoSGBM_create(minDisparity=0, numDisparities=256, blockSize=block, P1=8 * block * block,
                                    P2=32 * block * block, disp12MaxDiff=2, uniquenessRatio=5,
                                    speckleWindowSize=60, speckleRange=2, preFilterCap=31,
                                    mode=cv2.STEREO_SGBM_MODE_SGBM_3WAY)
    grey_l = cv2.cvtColor(left, cv2.COLOR_BGR2GRAY)
    grey_r = cv2.cvtColor(right, cv2.COLOR_BGR2GRAY)
    disp = matcher.compute(grey_l, grey_r).astype(np.float32) / 16.0
    return camera.depth_from_disparity(np.where(disp > 0, disp, np.nan)).astype(np.float32)


def baseline_detect(left, depth, right, camera, pose, catalogue, config):
    """The baseline as a detector for ``map_drive``: the full-frame depth, no detections."""
    baseline_depth(left, right, camera)
    return []


def cpu_seconds() -> float:
    """User + system CPU seconds of this process and its ended worker processes."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def rss_mb(pid="self", key="VmRSS") -> float:
    """Resident (VmRSS) or peak resident (VmHWM) memory of a process in MB, from /proc."""
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith(key + ":"):
                return int(line.split()[1]) / 1024.0
    except OSError:  # a worker that just ended
        pass
    return 0.0


def total_rss_mb() -> float:
    """This process and its worker processes together."""
    return rss_mb() + sum(rss_mb(p.pid) for p in multiprocessing.active_children())


def repeated(drive, pairs: int):
    """The drive's pairs repeated under new ids up to ``pairs`` pairs: a long drive without more files."""
    records = [replace(r, index=i, id=f"{i:07d}") for i, r in
               ((i, drive.pairs[i % len(drive.pairs)]) for i in range(pairs))]
    return replace(drive, pairs=records)


def run_dask(mode: str, folder: Path, scheduler: str = "") -> dict:
    """The pairs mapped on a Dask cluster: a LocalCluster of 1 or 2 single-thread workers, or ``scheduler``'s."""
    from distributed import Client, LocalCluster

    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.run.mapping import map_drive

    drive = open_drive(folder)
    cluster = None
    if not scheduler:
        cluster = LocalCluster(n_workers=int(mode.split("-")[1]), threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=":0")
        scheduler = cluster.scheduler_address
    try:
        with Client(scheduler, set_as_default=False) as client:
            workers = len(client.nthreads())
            start = time.perf_counter()
            result = map_drive(drive, load_catalogue(), PipelineConfig(), scheduler=client)
            seconds = time.perf_counter() - start
            worker_peak = max(client.run(lambda: resource.getrusage(resource.RUSAGE_SELF).ru_maxrss).values())
    finally:
        if cluster is not None:
            cluster.close()
    return {"mode": mode, "pairs": len(drive.pairs), "workers": workers, "seconds": seconds,
            "detections": len(result.detections), "signs": len(result.signs),
            "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
            "peak_worker_rss_mb": worker_peak / 1024.0, "rss_mb": {}}


def run_mode(mode: str, folder: Path, long_pairs: int = 0) -> dict:
    from bench.bench_mapping import baseline_detect as baseline  # by module name: worker processes import it
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.run.mapping import map_drive
    from signmapper_core.run.pair_pool import available_cores

    drive = open_drive(folder)
    if long_pairs:
        drive = repeated(drive, long_pairs)
    workers = 1 if mode == "pipeline-1" else available_cores()
    samples = {}

    def progress(fraction, message):
        if message.startswith("Pair "):
            done = len(samples) + 1
            samples[done] = total_rss_mb() if done in (1, 100, 500, 1000, 2000, 5000, 10000) else None

    load = os.getloadavg()[0]
    start, cpu = time.perf_counter(), cpu_seconds()
    result = map_drive(drive, load_catalogue(), PipelineConfig(), progress=progress, workers=workers,
                       detect=baseline if mode == "baseline" else None)
    seconds, cpu = time.perf_counter() - start, cpu_seconds() - cpu  # the pool has ended: its CPU is counted
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    worker = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0 if workers > 1 else 0.0
    return {"mode": mode, "pairs": len(drive.pairs), "workers": workers, "seconds": seconds, "cpu_seconds": cpu,
            "load": [load, os.getloadavg()[0]], "detections": len(result.detections), "signs": len(result.signs),
            "peak_rss_mb": own, "peak_worker_rss_mb": worker,
            "rss_mb": {k: v for k, v in samples.items() if v is not None}}


def drive_folder(seed: int, pairs: int) -> Path:
    from signmapper_core.simulate import SimulationConfig

    return cached_drive(DRIVES / f"seed{seed}-{pairs}-stereo",
                        SimulationConfig(pairs=pairs, seed=seed, write_depth=False))


def child(mode: str, folder: Path, long_pairs: int = 0, scheduler: str = "") -> dict:
    command = [sys.executable, "-m", "bench.bench_mapping", "--mode", mode, "--drive", str(folder), "--long",
               str(long_pairs)]
    command += ["--scheduler", scheduler] if scheduler else []
    out = subprocess.run(command, capture_output=True, text=True, check=True, cwd=REPO)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=20, help="pairs of the generated drive (>= 100 for figures)")
    parser.add_argument("--seed", type=int, default=2001)
    parser.add_argument("--long", type=int, default=0, metavar="N",
                        help="then map N pairs (the drive repeated) with all workers and print memory as it goes")
    parser.add_argument("--rounds", type=int, default=1, metavar="K",
                        help="then map with all workers and the baseline again, one after the other, K - 1 more "
                             "times: the host's speed drifts over minutes, and each round's ratio compares runs "
                             "minutes apart only")
    parser.add_argument("--dask", action="store_true",
                        help="also map on a Dask LocalCluster (127.0.0.1) of 1 and of 2 worker processes")
    parser.add_argument("--scheduler", default="", metavar="tcp://HOST:PORT",
                        help="also map on the running Dask cluster of this scheduler")
    parser.add_argument("--mode", choices=MODES + DASK_MODES + ("dask-scheduler",),
                        help=argparse.SUPPRESS)  # child process
    parser.add_argument("--drive", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.mode in DASK_MODES or args.mode == "dask-scheduler":
        print(json.dumps(run_dask(args.mode, args.drive, args.scheduler)))
        return 0
    if args.mode:
        print(json.dumps(run_mode(args.mode, args.drive, args.long)))
        return 0
    folder = drive_folder(args.seed, args.pairs)
    print(f"drive {folder}: 1920x1080 JPEG pairs, no depth maps, {args.pairs} pairs; "
          f"{multiprocessing.cpu_count()} cores; the vehicle records 5 pairs/s")
    print(f"{'mode':<13} {'workers':>7} {'pairs/s':>8} {'x baseline':>10} {'CPU ms/pair':>11} {'detections':>10} "
          f"{'signs':>6} {'peak RSS MB (main + largest worker)':>36} {'load avg':>11}")
    modes = MODES + (DASK_MODES if args.dask else ()) + (("dask-scheduler",) if args.scheduler else ())
    results = {mode: child(mode, folder, scheduler=args.scheduler if mode == "dask-scheduler" else "")
               for mode in modes}
    base = results["baseline"]["pairs"] / results["baseline"]["seconds"]
    for mode, r in results.items():
        rate = r["pairs"] / r["seconds"]
        peak = f"{r['peak_rss_mb']:.0f}" + (f" + {r['workers']} x {r['peak_worker_rss_mb']:.0f}"
                                            if r["workers"] > 1 or mode.startswith("dask") else "")
        cpu = f"{1000 * r['cpu_seconds'] / r['pairs']:.0f}" if "cpu_seconds" in r else "-"
        load = "{:.1f}-{:.1f}".format(*r["load"]) if "load" in r else "-"
        print(f"{mode:<13} {r['workers']:7d} {rate:8.2f} {rate / base:10.2f} {cpu:>11} {r['detections']:10d} "
              f"{r['signs']:6d} {peak:>36} {load:>11}", flush=True)
    ratios = [(results["pipeline-all"]["pairs"] / results["pipeline-all"]["seconds"], base)]
    for k in range(2, args.rounds + 1):
        pool, baseline = (child(mode, folder) for mode in ("pipeline-all", "baseline"))
        ratios.append((pool["pairs"] / pool["seconds"], baseline["pairs"] / baseline["seconds"]))
        rate, base_rate = ratios[-1]
        pool_cpu, base_cpu = (1000 * r["cpu_seconds"] / r["pairs"] for r in (pool, baseline))
        print(f"round {k}: pipeline-all {rate:.2f} pairs/s ({pool_cpu:.0f} ms CPU/pair), baseline {base_rate:.2f} "
              f"pairs/s ({base_cpu:.0f} ms CPU/pair), x {rate / base_rate:.2f}", flush=True)
    if args.rounds > 1:
        rates = sorted(p for p, _ in ratios)
        factors = sorted(p / b for p, b in ratios)
        print(f"{args.rounds} rounds: pipeline-all {rates[0]:.2f}-{rates[-1]:.2f} pairs/s (median "
              f"{statistics.median(rates):.2f}), x baseline {factors[0]:.2f}-{factors[-1]:.2f} (median "
              f"{statistics.median(factors):.2f}); both targets (>= 10 pairs/s, >= 4x) in the same round: "
              f"{sum(p >= 10 and p / b >= 4 for p, b in ratios)} of {args.rounds}")
    if args.long:
        r = child("pipeline-all", folder, args.long)
        memory = ", ".join(f"{k} pairs {v:.0f} MB" for k, v in r["rss_mb"].items())
        print(f"long drive, {r['pairs']} pairs ({args.pairs} repeated), {r['workers']} workers: "
              f"{r['pairs'] / r['seconds']:.2f} pairs/s; resident memory of main + workers after {memory}; "
              f"peak {r['peak_rss_mb']:.0f} MB main + {r['workers']} x {r['peak_worker_rss_mb']:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
