"""Build a small real-photograph subset (<= 20 MB) that may be shared: crops and scenes, report half only.

    python -m scripts.realset.make_subset /work/data/real /work/data/real-subset [--crops 600] [--scenes 60]
                                             [--with-gtsrb] [--seed 0] [--max-mb 20]

Crops: cut from the GTSDB ``report`` scenes with a margin of 10 % of the sign (at least 5 px), as
GTSRB crops are, and saved as PNG (lossless from the decoded photograph); with ``--with-gtsrb`` the
GTSRB ``report`` crops join the pool (their licence is unclear, see SOURCES.md). The pool is
drawn round-robin over (SSV id, size bin) cells so rare ids and small signs are not crowded out.
Scenes: GTSDB ``report`` photographs copied unchanged, chosen first to cover every SSV id, then
at random, about a sixth without any sign (false positives). The output folder gets the same
manifests as the full set (crops.csv, scenes.csv, scenes_images.csv, scenes_other.csv) and a
README.md with sources, commits and licences.
"""

from __future__ import annotations

import argparse
import csv
import random
import shutil
import sys
from collections import defaultdict
from pathlib import Path

import cv2

from signmapper_core.validation import (
    IMAGE_LIST_COLUMNS,
    MANIFEST_COLUMNS,
    SCENE_COLUMN,
    load_manifest,
    load_scene_list,
)

HERE = Path(__file__).resolve().parent
SMALL_PX = 30


def margin_box(bbox, width: int, height: int):
    """Crop window around a face box: 10 % of the longer side, at least 5 px, inside the image."""
    x, y, w, h = bbox
    m = max(5, int(round(0.1 * max(w, h))))
    return max(0, x - m), max(0, y - m), min(width, x + w + m), min(height, y + h + m)


def round_robin(pool: list, n: int, seed: int) -> list:
    """Up to ``n`` signs drawn in turn from each (SSV id, size bin) cell, each cell in seeded order."""
    cells = defaultdict(list)
    for sign in pool:
        cells[(sign.ssv_id, sign.size_px < SMALL_PX)].append(sign)
    rng = random.Random(seed)
    queues = []
    for key in sorted(cells):
        items = cells[key][:]
        rng.shuffle(items)
        queues.append(items)
    chosen = []
    while len(chosen) < n and any(queues):
        for q in queues:
            if q and len(chosen) < n:
                chosen.append(q.pop())
    return chosen


def choose_scenes(scenes: list, signs_by_image: dict, n: int, seed: int) -> list:
    """``n`` report scenes: greedy cover of all SSV ids, then random ones; ~1/6 without signs."""
    rng = random.Random(seed)
    with_signs = [s for s in scenes if s.signs]
    empty = [s for s in scenes if not s.signs]
    rng.shuffle(with_signs)
    rng.shuffle(empty)
    n_empty = min(len(empty), max(1, n // 6)) if n > 1 else 0
    chosen, covered = [], set()
    for scene in with_signs:
        ids = {s.ssv_id for s in signs_by_image[scene.image]}
        if ids - covered and len(chosen) < n - n_empty:
            chosen.append(scene)
            covered |= ids
    rest = [s for s in with_signs if s not in chosen]
    chosen += rest[: max(0, n - n_empty - len(chosen))]
    return chosen + empty[:n_empty]


def folder_mb(path: Path) -> float:
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file()) / 1e6


def write(path: Path, header, rows):
    with path.open("w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def build(data: Path, out: Path, n_crops: int, n_scenes: int, with_gtsrb: bool, seed: int, max_mb: float):
    if out.exists():
        shutil.rmtree(out)
    (out / "gtsdb" / "images").mkdir(parents=True)
    (out / "gtsdb" / "crops").mkdir(parents=True)
    scene_signs = [s for s in load_manifest(data / "scenes.csv") if s.split == "report"]
    by_image = defaultdict(list)
    for s in scene_signs:
        by_image[s.image].append(s)
    scenes = [s for s in load_scene_list(data / "scenes_images.csv") if s.split == "report"]

    # scenes: copied byte for byte
    chosen_scenes = choose_scenes(scenes, by_image, n_scenes, seed)
    listing, scene_rows = [], []
    for scene in sorted(chosen_scenes, key=lambda s: s.image.name):
        rel = f"gtsdb/images/{scene.image.name}"
        shutil.copyfile(scene.image, out / rel)
        listing.append([rel, scene.width, scene.height, scene.split, scene.source, scene.signs, scene.scene])
        for s in by_image[scene.image]:
            x, y, w, h = s.bbox
            scene_rows.append([rel, x, y, x + w, y + h, s.ssv_id, s.group, s.split, s.source, s.scene])
    other_rows = []
    names = {f"gtsdb/images/{s.image.name}" for s in chosen_scenes}
    other_path = data / "scenes_other.csv"
    if other_path.is_file():
        with other_path.open(newline="", encoding="utf-8") as f:
            other_rows = [list(r.values()) for r in csv.DictReader(f) if r["image"] in names]

    # crops: GTSDB report signs cut with a margin (+ GTSRB report crops on request)
    pool = list(scene_signs)
    if with_gtsrb:
        (out / "gtsrb" / "Images").mkdir(parents=True)
        pool += [s for s in load_manifest(data / "crops.csv") if s.split == "report"]
    from_scenes = {id(s) for s in scene_signs}
    crop_rows = []
    for sign in sorted(round_robin(pool, n_crops, seed), key=lambda s: (s.source, s.image.name, s.bbox)):
        image = sign.load_image()
        x, y, w, h = sign.bbox
        if id(sign) in from_scenes:
            cx0, cy0, cx1, cy1 = margin_box(sign.bbox, image.shape[1], image.shape[0])
            rel = f"gtsdb/crops/{sign.image.stem}_{x}_{y}.png"
            source = "gtsdb-crop"
        else:
            cx0, cy0, cx1, cy1 = 0, 0, image.shape[1], image.shape[0]
            rel = f"gtsrb/Images/{sign.image.stem}.png"
            source = sign.source
        if not cv2.imwrite(str(out / rel), image[cy0:cy1, cx0:cx1]):
            raise SystemExit(f"cannot write {out / rel}")
        crop_rows.append([rel, x - cx0, y - cy0, x - cx0 + w, y - cy0 + h, sign.ssv_id, sign.group, sign.split,
                          source, sign.scene])

    write(out / "crops.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN), crop_rows)
    write(out / "scenes.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN), scene_rows)
    write(out / "scenes_images.csv", (*IMAGE_LIST_COLUMNS, SCENE_COLUMN), listing)
    write(out / "scenes_other.csv", ("image", "x0", "y0", "x1", "y1", "class_id"), other_rows)
    for name in ("gtsdb/ReadMe.txt",) + (("gtsrb/Readme-Images-Final-test.txt",) if with_gtsrb else ()):
        if (data / name).is_file():
            shutil.copyfile(data / name, out / name)
    sources = (HERE / "SOURCES.md").read_text(encoding="utf-8")
    (out / "README.md").write_text(
        "# Real sign photographs: committed subset\n\n"
        f"{len(crop_rows)} crops (crops.csv) and {len(listing)} whole scenes ({len(scene_rows)} signs, scenes.csv; "
        f"every scene in scenes_images.csv, {sum(1 for r in listing if not r[5])} without a sign), all from the "
        "`report` half. Built by `python -m scripts.realset.make_subset "
        f"--crops {n_crops} --scenes {n_scenes}{' --with-gtsrb' if with_gtsrb else ''} --seed {seed}`. "
        "Crops under gtsdb/crops/ are cut from the GTSDB scenes with a 10 % (>= 5 px) margin and saved as "
        "PNG; scenes are the JPEGs as fetched. Manifest format: `signmapper_core/validation/realset.py`.\n\n"
        + sources.split("\n", 1)[1], encoding="utf-8")
    # the result must read back with the loader, and fit the budget
    load_manifest(out / "crops.csv")
    load_manifest(out / "scenes.csv")
    load_scene_list(out / "scenes_images.csv")
    for s in load_manifest(out / "crops.csv"):
        s.load_image()
    size = folder_mb(out)
    if size > max_mb:
        raise SystemExit(f"{out}: {size:.1f} MB, over the {max_mb} MB budget; use fewer --scenes or --crops")
    return len(crop_rows), len(listing), len(scene_rows), size


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", type=Path, help="the full set (manifests from build_manifests.py)")
    parser.add_argument("out", type=Path, help="output folder (replaced)")
    parser.add_argument("--crops", type=int, default=600)
    parser.add_argument("--scenes", type=int, default=60)
    parser.add_argument("--with-gtsrb", action="store_true", help="add GTSRB crops (licence unclear)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-mb", type=float, default=20.0)
    args = parser.parse_args(argv)
    crops, scenes, signs, size = build(args.data, args.out, args.crops, args.scenes, args.with_gtsrb, args.seed,
                                       args.max_mb)
    print(f"{args.out}: {crops} crops, {scenes} scenes with {signs} signs, {size:.1f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
