"""GTSDB scenes (``scripts.realset.scenes``) and the split by scene in ``build_manifests``, on constructed inputs.

A scene is a run of consecutive photographs of one place; all of it goes to one half, named by the hash of
its first photograph, so that no physical sign is seen in both halves.
"""

from __future__ import annotations

import cv2
import numpy as np
import pytest

from scripts.realset import build_manifests
from scripts.realset.build_manifests import half_split, scene_halves, scene_summary
from scripts.realset.scenes import (
    SAME_PLACE_MATCHES,
    consecutive_matches,
    place_matches,
    scene_groups,
    scene_of,
)
from signmapper_core.validation import (
    IMAGE_LIST_COLUMNS,
    MANIFEST_COLUMNS,
    SCENE_COLUMN,
    load_manifest,
    load_scene_list,
)

# consecutive GTSDB names: 00110-00112 hash to report, 00113-00115 to tune
REPORT_NAMES = ["00110", "00111", "00112"]
TUNE_NAMES = ["00113", "00114", "00115"]


def test_names_used_below_hash_to_the_halves_said():
    assert {half_split(n) for n in REPORT_NAMES} == {"report"}
    assert {half_split(n) for n in TUNE_NAMES} == {"tune"}


def test_scene_groups_chain_consecutive_photographs_at_or_above_the_threshold():
    # photographs 0-1 alike, 1-2 not, 2-3-4 alike (3-4 exactly at the threshold), 4-5 not
    assert scene_groups([50, 3, 30, 24, 23.9], 24) == [[0, 1], [2, 3, 4], [5]]
    assert scene_groups([], 24) == [[0]]
    assert scene_groups([0, 0, 0], 24) == [[0], [1], [2], [3]]
    assert scene_groups([99, 99, 99], 24) == [[0, 1, 2, 3]]


def test_scene_of_names_each_photograph_by_its_scene_s_first():
    names = ["00001", "00002", "00003", "00004"]
    assert scene_of(names, [[0, 1, 2], [3]]) == {"00001": "00001", "00002": "00001", "00003": "00001",
                                                 "00004": "00004"}


def test_a_scene_whose_photographs_hash_to_both_halves_stays_in_one():
    names = ["00112", "00113", "00114"]  # report, tune, tune by name
    scenes = scene_of(names, scene_groups([40, 40], SAME_PLACE_MATCHES))
    assert set(scene_halves(scenes).values()) == {"report"}  # the half of 00112, the scene's first
    alone = scene_of(names, scene_groups([0, 0], SAME_PLACE_MATCHES))
    assert scene_halves(alone) == {"00112": "report", "00113": "tune", "00114": "tune"}
    assert scene_summary(scenes) == ("1 scenes of 3 photographs (size: count 3: 1); 2 photographs in another half "
                                     "than split by photograph")
    assert scene_summary(alone) == ("3 scenes of 3 photographs (size: count 1: 3); 0 photographs in another half "
                                    "than split by photograph")


def _texture(seed: int, size=(400, 680)) -> np.ndarray:
    """Blocky random grey texture: corners for ORB everywhere."""
    small = np.random.default_rng(seed).integers(0, 256, (size[0] // 8, size[1] // 8), dtype=np.uint8)
    return cv2.resize(small, (size[1], size[0]), interpolation=cv2.INTER_NEAREST)


def test_place_matches_tell_the_same_place_moved_from_another_place(tmp_path):
    place = _texture(1)
    moved = np.roll(place, (6, -10), axis=(0, 1))  # the same place, the camera a little further on
    other = _texture(2)
    paths = []
    for k, image in enumerate((place, moved, other)):
        paths.append(tmp_path / f"{k:05d}.png")
        # written at twice the size: the photographs are read at half size, as GTSDB's 1360 x 800 are
        assert cv2.imwrite(str(paths[-1]), cv2.resize(image, None, fx=2, fy=2, interpolation=cv2.INTER_NEAREST))
    same, different = consecutive_matches(paths)
    assert same >= 10 * SAME_PLACE_MATCHES
    assert different < SAME_PLACE_MATCHES
    assert place_matches(None, None) == 0
    assert scene_groups([same, different], SAME_PLACE_MATCHES) == [[0, 1], [2]]


@pytest.fixture
def gtsdb_folder(tmp_path):
    """Six black 1360 x 800 photographs 00110-00115 and a gt.txt with a sign in four of them."""
    images = tmp_path / "gtsdb" / "images"
    images.mkdir(parents=True)
    black = np.zeros((800, 1360, 3), np.uint8)
    for name in REPORT_NAMES + TUNE_NAMES:
        assert cv2.imwrite(str(images / f"{name}.jpg"), black)
    (tmp_path / "gtsdb" / "gt.txt").write_text(
        "00111.ppm;10;10;40;40;14\n00112.ppm;10;10;40;40;14\n00113.ppm;10;10;40;40;14\n"
        "00115.ppm;10;10;40;40;14\n00115.ppm;100;10;140;40;99\n", encoding="utf-8")
    return tmp_path


def test_gtsdb_rows_split_by_scene_and_name_it_in_the_manifests(gtsdb_folder):
    # scenes: 00110-00111, 00112-00113-00114 (first photograph report, the others tune by name), 00115
    names = REPORT_NAMES + TUNE_NAMES
    scenes = scene_of(names, scene_groups([30, 0, 30, 30, 0], SAME_PLACE_MATCHES))
    signs, listing, other = build_manifests.gtsdb_rows(gtsdb_folder, {14: ("3.01", "same")}, scenes)
    assert [(r[0][-9:-4], r[7], r[9]) for r in signs] == [
        ("00111", "report", "00110"), ("00112", "report", "00112"), ("00113", "report", "00112"),
        ("00115", "tune", "00115")]
    assert [(r[0][-9:-4], r[3], r[5], r[6]) for r in listing] == [
        ("00110", "report", 0, "00110"), ("00111", "report", 1, "00110"), ("00112", "report", 1, "00112"),
        ("00113", "report", 1, "00112"), ("00114", "report", 0, "00112"), ("00115", "tune", 1, "00115")]
    assert len(other) == 1
    build_manifests.write(gtsdb_folder / "scenes.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN), signs)
    build_manifests.write(gtsdb_folder / "scenes_images.csv", (*IMAGE_LIST_COLUMNS, SCENE_COLUMN), listing)
    read = load_manifest(gtsdb_folder / "scenes.csv")
    assert [(s.image.stem, s.split, s.scene) for s in read] == [(r[0][-9:-4], r[7], r[9]) for r in signs]
    photographs = load_scene_list(gtsdb_folder / "scenes_images.csv")
    assert {s.scene for s in photographs if s.image.stem in ("00112", "00113", "00114")} == {"00112"}
