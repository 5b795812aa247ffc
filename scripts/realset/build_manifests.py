"""Write the real-photograph manifests (crops.csv, scenes.csv, scenes_images.csv) from GTSRB/GTSDB.

    python -m scripts.realset.build_manifests /work/data/real

Expects, below DATA (see scripts/realset/README.md for where they come from):

- ``gtsrb/Images/NNNNN.ppm`` and ``gtsrb/GT-final_test.csv`` (GTSRB final test set with class ids:
  ``Filename;Width;Height;Roi.X1;Roi.Y1;Roi.X2;Roi.Y2;ClassId``, Roi inclusive);
- ``gtsdb/images/NNNNN.jpg`` and ``gtsdb/gt.txt`` (GTSDB FullIJCNN2013, ``file;x1;y1;x2;y2;classId``,
  inclusive, file names ``.ppm`` in gt.txt for the JPEG conversions).

Classes are mapped to SSV ids with ``gtsrb_to_ssv.csv`` (same class ids for both sets); classes
without a catalogue counterpart are left out of the manifests (scenes: listed in scenes_other.csv so
that segments on them are not counted as false positives). The split is a deterministic half split by
a hash of the file name (GTSRB test crops carry no track id) or, for GTSDB, of the scene's first photograph
(``scenes.py``: consecutive photographs of one place are one scene, in one half; the ``scene`` column names
it, empty for GTSRB crops). Every image is opened once to check its size against the ground truth.
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import sys
from collections import Counter
from pathlib import Path

import cv2

from scripts.realset.scenes import SAME_PLACE_MATCHES, consecutive_matches, scene_groups, scene_of
from signmapper_core.catalogue import load_catalogue
from signmapper_core.validation import IMAGE_LIST_COLUMNS, MANIFEST_COLUMNS, SCENE_COLUMN

HERE = Path(__file__).resolve().parent

MAPPING = HERE / "gtsrb_to_ssv.csv"
GTSDB_SIZE = (1360, 800)


def half_split(key: str) -> str:
    """'tune' or 'report', half each, stable across runs and machines."""
    return "tune" if hashlib.sha1(key.encode("utf-8")).digest()[0] % 2 == 0 else "report"


def scene_halves(scenes: dict) -> dict:
    """Photograph name -> half, by its scene's id (``scene_of``): a scene is never split."""
    return {name: half_split(scene) for name, scene in scenes.items()}


def gtsdb_scenes(images) -> dict:
    """Photograph stem -> scene id for the GTSDB photographs, in name order (``scenes.py``)."""
    names = [path.stem for path in images]
    return scene_of(names, scene_groups(consecutive_matches(images), SAME_PLACE_MATCHES))


def scene_summary(scenes: dict) -> str:
    """Counts only: scenes, their sizes, photographs whose half differs from the split by photograph."""
    sizes = Counter(Counter(scenes.values()).values())
    moved = sum(1 for name, half in scene_halves(scenes).items() if half != half_split(name))
    return (f"{len(set(scenes.values()))} scenes of {len(scenes)} photographs (size: count "
            f"{', '.join(f'{k}: {n}' for k, n in sorted(sizes.items()))}); {moved} photographs in another half "
            "than split by photograph")


def read_mapping(path: Path, catalogue_ids) -> dict:
    """class id -> (ssv_id, group) for the mapped classes; checks every id against the catalogue."""
    mapping = {}
    with path.open(newline="", encoding="utf-8") as f:
        for line, row in enumerate(csv.DictReader(f), start=2):
            if row["group"] == "none":
                continue
            if row["group"] not in ("same", "differs"):
                raise SystemExit(f"{path}, line {line}: group {row['group']!r} is not same, differs or none")
            if row["ssv_id"] not in catalogue_ids:
                raise SystemExit(f"{path}, line {line}: {row['ssv_id']!r} is not in the catalogue")
            mapping[int(row["class_id"])] = (row["ssv_id"], row["group"])
    return mapping


def image_size(path: Path):
    image = cv2.imread(str(path), cv2.IMREAD_UNCHANGED)
    if image is None:
        raise SystemExit(f"{path}: missing or not decodable")
    return image.shape[1], image.shape[0]


def gtsrb_rows(data: Path, mapping: dict):
    """Manifest rows of the GTSRB test crops (perfect-box classification set)."""
    gt = data / "gtsrb" / "GT-final_test.csv"
    rows, skipped = [], Counter()
    with gt.open(newline="", encoding="utf-8") as f:
        for line, r in enumerate(csv.DictReader(f, delimiter=";"), start=2):
            cls = int(r["ClassId"])
            if cls not in mapping:
                skipped[cls] += 1
                continue
            rel = f"gtsrb/Images/{r['Filename']}"
            size = image_size(data / rel)
            if size != (int(r["Width"]), int(r["Height"])):
                raise SystemExit(f"{gt}, line {line}: image {rel} is {size}, ground truth says "
                                 f"{r['Width']}x{r['Height']}")
            x0, y0 = int(r["Roi.X1"]), int(r["Roi.Y1"])
            x1, y1 = int(r["Roi.X2"]) + 1, int(r["Roi.Y2"]) + 1  # inclusive -> exclusive
            x1, y1 = min(x1, size[0]), min(y1, size[1])
            ssv_id, group = mapping[cls]
            rows.append([rel, x0, y0, x1, y1, ssv_id, group, half_split(r["Filename"]), "gtsrb-test", ""])
    return rows, skipped


def gtsdb_rows(data: Path, mapping: dict, scenes: dict):
    """(manifest rows, image-list rows, unmapped-sign rows) of the GTSDB photographs; ``scenes``: stem -> scene."""
    gt = data / "gtsdb" / "gt.txt"
    images = sorted((data / "gtsdb" / "images").glob("*.jpg"))
    halves = scene_halves(scenes)
    signs, other = [], []
    count = Counter()
    seen = set()
    for line, text in enumerate(gt.read_text(encoding="utf-8").splitlines(), start=1):
        if not text.strip():
            continue
        if text.strip() in seen:  # gt.txt lists 00340.ppm;827;543;851;567;14 twice
            print(f"{gt}, line {line}: duplicate of an earlier line, dropped")
            continue
        seen.add(text.strip())
        name, x0, y0, x1, y1, cls = text.strip().split(";")
        rel = f"gtsdb/images/{Path(name).stem}.jpg"
        if not (data / rel).is_file():
            raise SystemExit(f"{gt}, line {line}: no image {rel}")
        box = [int(x0), int(y0), min(int(x1) + 1, GTSDB_SIZE[0]), min(int(y1) + 1, GTSDB_SIZE[1])]
        cls = int(cls)
        if cls in mapping:
            ssv_id, group = mapping[cls]
            stem = Path(name).stem
            signs.append([rel, *box, ssv_id, group, halves[stem], "gtsdb", scenes[stem]])
            count[rel] += 1
        else:
            other.append([rel, *box, cls])
    listing = []
    for path in images:
        rel = f"gtsdb/images/{path.name}"
        size = image_size(path)
        if size != GTSDB_SIZE:
            raise SystemExit(f"{path}: {size[0]}x{size[1]}, expected {GTSDB_SIZE[0]}x{GTSDB_SIZE[1]}")
        listing.append([rel, size[0], size[1], halves[path.stem], "gtsdb", count[rel], scenes[path.stem]])
    return signs, listing, other


def write(path: Path, header, rows):
    with path.open("w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", type=Path, help="folder holding gtsrb/ and gtsdb/ (manifests are written here)")
    parser.add_argument("--mapping", type=Path, default=MAPPING)
    args = parser.parse_args(argv)
    mapping = read_mapping(args.mapping, {e.id for e in load_catalogue()})
    crops, skipped = gtsrb_rows(args.data, mapping)
    places = gtsdb_scenes(sorted((args.data / "gtsdb" / "images").glob("*.jpg")))
    scenes, listing, other = gtsdb_rows(args.data, mapping, places)
    write(args.data / "crops.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN), crops)
    write(args.data / "scenes.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN), scenes)
    write(args.data / "scenes_images.csv", (*IMAGE_LIST_COLUMNS, SCENE_COLUMN), listing)
    write(args.data / "scenes_other.csv", ("image", "x0", "y0", "x1", "y1", "class_id"), other)
    print(f"crops.csv: {len(crops)} signs (left out, unmapped GTSRB classes: "
          f"{', '.join(f'{c}: {n}' for c, n in sorted(skipped.items()))})")
    print(f"scenes.csv: {len(scenes)} signs in {sum(1 for r in listing if r[5])} of {len(listing)} images; "
          f"{len(other)} unmapped signs in scenes_other.csv")
    print(scene_summary(places))
    return 0


if __name__ == "__main__":
    sys.exit(main())
