"""Verdict accuracy of ``signmapper:changes`` on synthetic drives with an edited inventory.

For each drive: the inventory is the drive's truth.csv with seeded edits (signs
removed from the inventory, moved 1 m, given another type, added where the drive
sees nothing, added outside its view); every row carries the verdict it should
get. The drive is mapped with ``signmapper:mapsigns`` and compared with
``signmapper:changes`` (both through ``qgis_process.bin``); the script prints
every wrong verdict and the accuracy. Next to it, the same inventory compared with a
perfect mapping (every truth sign the drive could have seen, at its true position
with its true type): what ``changes`` decides by itself, apart from mapping
errors. With ``--signalo`` it then does the Signalo
round trip on each mapped drive: a throw-away PostgreSQL (as the database tests
start it) with Signalo's data model, ``signmapper:exporttosignalo`` of the run
(signs awaiting review included), ``signmapper:changes`` against that database;
every written sign should come back ``confirmed`` and only the types Signalo does
not list ``new``. ::

    python -m scripts.inventory_changes --generate 1100 1101 1102 --out /tmp/changes --signalo
"""

from __future__ import annotations

import argparse
import csv
import os
import sqlite3
import subprocess
import sys
import sysconfig
from pathlib import Path

import numpy as np

from signmapper_core.catalogue import load_catalogue
from signmapper_core.changes.compare import (
    CHANGED,
    CONFIRMED,
    MISSING,
    MOVED,
    NEW,
    NOT_COVERED,
    ChangeConfig,
    InventorySign,
    MappedSign,
    compare,
    pose_arrays,
    sign_views,
)
from signmapper_core.drive.reader import open_drive
from signmapper_core.fusion.mounting import camera_height_above_road

REPO = Path(__file__).resolve().parents[1]

EDITS = {"removed": 4, "moved": 5, "type": 4}  # of signs the drive sees; then signs added, at least 3 of each kind
MIN_EDITS = 22


def qgis_env(work: Path) -> dict:
    plugins = work / "plugins"
    plugins.mkdir(parents=True, exist_ok=True)
    link = plugins / "sign_mapper"
    if not link.exists():
        link.symlink_to(REPO, target_is_directory=True)
    site = sysconfig.get_paths()["purelib"]  # OpenCV of this venv for the system Python that QGIS runs
    path = os.pathsep.join(p for p in (site, os.environ.get("PYTHONPATH", "")) if p)
    env = dict(os.environ, QGIS_PLUGINPATH=str(plugins), QGIS_CUSTOM_CONFIG_PATH=str(work / "profile"),
               QT_QPA_PLATFORM="offscreen", PYTHONPATH=path)
    subprocess.run(["qgis_process.bin", "plugins", "enable", "sign_mapper"], env=env, capture_output=True)
    return env


def run(env, algorithm: str, **params) -> str:
    args = ["qgis_process.bin", "run", algorithm, "--"] + [f"{k}={v}" for k, v in params.items()]
    done = subprocess.run(args, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{algorithm} failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
    return done.stdout


def outputs(stdout: str) -> dict:
    """The 'Results' block qgis_process prints: name -> value (text)."""
    found, results = {}, False
    for line in stdout.splitlines():
        if line.strip() == "Results":
            results = True
        elif results and ":\t" in line:
            name, value = line.split(":\t", 1)
            found[name.strip()] = value.strip()
    return found


def signs_by_status(gpkg: Path) -> dict:
    db = sqlite3.connect(gpkg)
    try:
        return dict(db.execute("SELECT status, count(*) FROM signs GROUP BY status").fetchall())
    finally:
        db.close()


def signalo_round_trip(env, out: Path, seeds) -> bool:
    """Export every mapped drive into its own Signalo database and compare the run with it; True if all came
    back confirmed (apart from types Signalo does not list, which must be the only 'new' signs)."""
    from tests.postgres_server import PostgresServer
    from tests.signalo_schema import install_signalo

    server = PostgresServer().start()
    all_right = True
    try:
        for seed in seeds:
            mapped = out / f"map{seed}.gpkg"
            dsn = server.create_database(f"roundtrip{seed}")
            version = install_signalo(dsn)
            sent = outputs(run(env, "signmapper:exporttosignalo", SIGNS=f"{mapped}|layername=signs", SIGNALO=dsn,
                               INCLUDE_REVIEW="true"))
            back = outputs(run(env, "signmapper:changes", SIGNS=f"{mapped}|layername=signs", SIGNALO=dsn,
                               OUTPUT=out / f"roundtrip{seed}.gpkg", REPORT=out / f"roundtrip{seed}.html"))
            counts = {k: int(float(back[k])) for k in ("CONFIRMED", "MOVED", "CHANGED", "MISSING", "NOT_COVERED",
                                                         "NEW")}
            added, unknown = int(float(sent["ADDED"])), int(float(sent["UNKNOWN"]))
            right = (counts["CONFIRMED"] == added and counts["NEW"] == unknown
                     and not any(counts[k] for k in ("MOVED", "CHANGED", "MISSING", "NOT_COVERED")))
            all_right &= right
            print(f"drive {seed} Signalo {version} round trip: signs by status {signs_by_status(mapped)}; exported "
                  f"{added} on {sent['SUPPORTS']} supports, {unknown} of types Signalo does not list; read back: "
                  + ", ".join(f"{n} {k.lower().replace('_', ' ')}" for k, n in counts.items())
                  + ("" if right else "  <-- not all confirmed"))
    finally:
        server.stop()
    return all_right


def in_view(drive, poses, config, position, facing, size) -> bool:
    return bool(sign_views(drive.camera, drive.pairs, poses, position, facing, size[0], size[1], config))


def edited_inventory(drive, catalogue, config, seed: int) -> list[dict]:
    """Truth rows with edits; each row: inventory fields + the verdict it should get ('new' rows: no inventory)."""
    rng = np.random.default_rng(seed)
    poses = pose_arrays(drive.pairs)
    rows, visible = [], []
    for t in drive.truth:
        mappable = t.template_id in catalogue
        seen = mappable and in_view(drive, poses, config, t.position, t.facing, (t.width_m, t.height_m))
        rows.append({"truth": t.sign_id, "template_id": t.template_id, "easting": t.easting, "northing": t.northing,
                     "height": t.height, "facing": t.facing, "edit": "",
                     "expected": CONFIRMED if seen else NOT_COVERED})
        visible.append(seen)
    candidates = [i for i, seen in enumerate(visible) if seen]
    rng.shuffle(candidates)
    picks = iter(candidates)
    ids = sorted(e.id for e in catalogue)
    for edit in ("removed", "moved", "type"):
        for _ in range(EDITS[edit]):
            i = next(picks, None)
            if i is None:
                break
            row = rows[i]
            row["edit"] = edit
            if edit == "removed":
                row["expected"] = NEW  # the inventory lost it; the drive maps it as new
            elif edit == "moved":
                angle = rng.uniform(0, 2 * np.pi)
                row["easting"] += np.cos(angle)
                row["northing"] += np.sin(angle)
                row["expected"] = MOVED
            else:
                row["template_id"] = str(rng.choice([x for x in ids if x != row["template_id"]]))
                row["expected"] = CHANGED
    truth_xy = np.array([[t.easting, t.northing] for t in drive.truth])
    centres = poses[1]
    to_add = max(6, MIN_EDITS - sum(1 for r in rows if r["edit"]))
    for edit, expected, count in (("gone", MISSING, (to_add + 1) // 2), ("outside", NOT_COVERED, to_add // 2)):
        added = 0
        while added < count:
            k = rng.integers(len(centres))
            heading = np.radians(drive.pairs[k].pose.heading)
            ahead, side = np.array([np.sin(heading), np.cos(heading)]), np.array([np.cos(heading), -np.sin(heading)])
            if edit == "gone":  # beside the road 8-12 m ahead, facing the vehicle, no sign within 3 m
                xy = centres[k, :2] + ahead * rng.uniform(8, 12) + side * rng.choice([-1, 1]) * rng.uniform(3, 5)
            else:  # 40-60 m beside the track: no pair sees it
                xy = centres[k, :2] + side * rng.choice([-1, 1]) * rng.uniform(40, 60)
            if np.hypot(*(truth_xy - xy).T).min() < 3.0:
                continue
            facing = float(np.degrees(heading) + 180.0) % 360.0
            position = np.array([xy[0], xy[1], centres[k, 2]])
            if in_view(drive, poses, config, position, facing, (0.6, 0.6)) != (edit == "gone"):
                continue
            rows.append({"truth": "", "template_id": "2.30-50", "easting": xy[0], "northing": xy[1],
                         "height": centres[k, 2], "facing": facing, "edit": edit, "expected": expected})
            added += 1
    return rows


def write_csv(path: Path, rows) -> None:
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(r for r in rows if r["expected"] != NEW)


def read_changes(gpkg: Path) -> list[dict]:
    db = sqlite3.connect(gpkg)
    db.row_factory = sqlite3.Row
    try:
        return [dict(r) for r in db.execute("SELECT * FROM changes")]
    finally:
        db.close()


def score(rows, changes, inventory_fids) -> tuple[int, int, list[str]]:
    """(right, total, wrong verdicts explained by id)."""
    by_fid = {c["inventory_id"]: c for c in changes if c["inventory_id"]}
    wrong, right, total = [], 0, 0
    for fid, row in zip(inventory_fids, [r for r in rows if r["expected"] != NEW]):
        total += 1
        got = by_fid[str(fid)]["verdict"]
        if got == row["expected"]:
            right += 1
        else:
            wrong.append(f"inventory {fid} ({row['truth'] or row['edit']}, {row['template_id']}, edit "
                         f"'{row['edit'] or 'none'}'): expected {row['expected']}, got {got} "
                         f"({by_fid[str(fid)]['reason']})")
    news = [c for c in changes if c["verdict"] == NEW]
    removed = [r for r in rows if r["expected"] == NEW]
    for row in removed:
        total += 1
        near = [c for c in news if c["template_id"] == row["template_id"]]
        if any(c for c in near):
            right += 1
        else:
            wrong.append(f"truth {row['truth']} ({row['template_id']}) removed from the inventory: no 'new' sign")
    extra = len(news) - sum(1 for row in removed if any(c["template_id"] == row["template_id"] for c in news))
    if extra > 0:
        total += extra
        wrong.append(f"{extra} 'new' signs where the inventory was not edited: "
                     + ", ".join(f"sign {c['sign_id']} {c['template_id']}" for c in news
                                 if c["template_id"] not in {r['template_id'] for r in removed}))
    return right, total, wrong


def perfect_mapping_changes(drive, catalogue, rows) -> tuple[list[dict], list[int]]:
    """``changes`` rows (as read from its GeoPackage) of the inventory against a perfect mapping, and the
    inventory's feature ids: the inventory built as the algorithm builds it from a point layer (catalogue
    'normal' sizes), the mapping = every truth sign of a catalogue type that some pair shows by the same
    visibility test, at its true position with its true type."""
    config = ChangeConfig(camera_height_m=camera_height_above_road(drive.metadata))
    poses = pose_arrays(drive.pairs)
    inventory = []
    for fid, row in enumerate((r for r in rows if r["expected"] != NEW), start=1):
        size = catalogue[row["template_id"]].formats.get("normal") if row["template_id"] in catalogue else None
        inventory.append(InventorySign(str(fid), row["template_id"],
                                       np.array([row["easting"], row["northing"], row["height"]], float),
                                       float(row["facing"]), size[0] if size else None, size[1] if size else None))
    mapped = [MappedSign(k, t.template_id, np.asarray(t.position, float)) for k, t in enumerate(drive.truth, start=1)
              if t.template_id in catalogue and in_view(drive, poses, config, t.position, t.facing,
                                                        (t.width_m, t.height_m))]
    report = compare(inventory, mapped, drive.camera, drive.pairs, config, mappable_types={e.id for e in catalogue})
    changes = [{"inventory_id": c.inventory.key if c.inventory is not None else None, "verdict": c.verdict,
                "template_id": c.mapped.template_id if c.mapped is not None else c.inventory.template_id,
                "sign_id": c.mapped.sign_id if c.mapped is not None else None, "reason": c.reason}
               for c in report.changes]
    return changes, list(range(1, len(inventory) + 1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--generate", type=int, nargs="+", required=True, help="seeds of the drives")
    parser.add_argument("--out", type=Path, required=True, help="work folder (drives, GeoPackages, reports)")
    parser.add_argument("--pairs", type=int, default=100)
    parser.add_argument("--signalo", action="store_true",
                        help="then export each mapped drive to a throw-away Signalo database and compare it back")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    env = qgis_env(args.out)
    catalogue = load_catalogue()
    grand_right = grand_total = ideal_grand_right = ideal_grand_total = 0
    for seed in args.generate:
        drive_dir = args.out / f"drive{seed}"
        if not (drive_dir / "poses.csv").exists():
            subprocess.run([sys.executable, "-m", "signmapper_core.simulate", str(drive_dir), "--pairs",
                            str(args.pairs), "--seed", str(seed), "--quiet"], cwd=REPO, check=True)
        mapped = args.out / f"map{seed}.gpkg"
        if not mapped.exists():
            run(env, "signmapper:mapsigns", DRIVE=drive_dir, OUTPUT=mapped)
        drive = open_drive(drive_dir, check_images=False)
        rows = edited_inventory(drive, catalogue, ChangeConfig(), seed)
        csv_path = args.out / f"inventory{seed}.csv"
        write_csv(csv_path, rows)
        inventory = args.out / f"inventory{seed}.gpkg"
        run(env, "native:createpointslayerfromtable", INPUT=csv_path, XFIELD="easting", YFIELD="northing",
            ZFIELD="height", TARGET_CRS=drive.crs, OUTPUT=inventory)
        out = args.out / f"changes{seed}.gpkg"
        run(env, "signmapper:changes", SIGNS=f"{mapped}|layername=signs", INVENTORY=inventory,
            TYPE_FIELD="template_id", FACING_FIELD="facing", OUTPUT=out, REPORT=args.out / f"changes{seed}.html")
        db = sqlite3.connect(inventory)
        table = db.execute("SELECT table_name FROM gpkg_contents WHERE data_type = 'features'").fetchone()[0]
        fids = [r[0] for r in db.execute(f'SELECT fid FROM "{table}" ORDER BY fid')]
        db.close()
        right, total, wrong = score(rows, read_changes(out), fids)
        edits = sum(1 for r in rows if r["edit"])
        print(f"drive {seed}: {len(drive.truth)} truth signs, {edits} edits, verdicts right {right}/{total}")
        for line in wrong:
            print("   ", line)
        grand_right += right
        grand_total += total
        ideal_right, ideal_total, ideal_wrong = score(rows, *perfect_mapping_changes(drive, catalogue, rows))
        print(f"drive {seed} with a perfect mapping: verdicts right {ideal_right}/{ideal_total}")
        for line in ideal_wrong:
            print("   ", line)
        ideal_grand_right += ideal_right
        ideal_grand_total += ideal_total
    print(f"all: {grand_right}/{grand_total} verdicts right ({100.0 * grand_right / max(grand_total, 1):.1f} %); "
          f"with a perfect mapping {ideal_grand_right}/{ideal_grand_total}")
    if args.signalo and not signalo_round_trip(env, args.out, args.generate):
        raise SystemExit("the Signalo round trip did not confirm every exported sign")


if __name__ == "__main__":
    main()
