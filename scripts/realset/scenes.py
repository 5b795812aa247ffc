"""GTSDB photographs grouped into scenes, so that one place, and a sign seen there twice, stays in one half.

GTSDB's 900 photographs were picked from drives; a few consecutive ones show the same place seconds apart
(the same lorry ahead, the same façades). Split by photograph, such a pair could put one physical sign into
both halves. A scene is a run of consecutive photographs in which each shows the place of the one before.

"Shows the same place" is measured by local features: ORB keypoints (``cv2.ORB_create``) of each photograph
at half size, matched by Hamming distance with Lowe's ratio test (OpenCV's feature-matching tutorial); the
number of matches that pass is the pair's similarity. Correlation of small grey thumbnails was tried first
and does not tell places apart: every motorway photograph has sky, verges and road where the others have
them (different places reached 0.90-0.96, one place seen while turning -0.22).

The threshold was chosen by eye on 2026-12-07 (pairs of the full set, counts of matches): 43-118 matches
were the same place or seconds apart (00308/9 the same lorries, 00847/8 the same façades, 00746/7,
00793/4, 00485/6, 00425/6) but for 00476/7 (46, a motorway's barrier); 26-30 were other places of the
same drive (00419/20, 00858/9, 00702/3, 00556/7, 00861/2, 00782/3); 00424/5 (25) shows the same white car
seconds apart. Joining two places costs the split some balance, splitting one costs its independence, so
the threshold sits just under that pair. Repeated signs along one motorway (00366-00369: four photographs,
each a 120 with a no-passing-for-lorries sign, under other bridges) are other physical signs and stay apart.
"""

from __future__ import annotations

from pathlib import Path
from typing import Dict, List, Sequence

import cv2

ORB_FEATURES = 1500
RATIO = 0.75  # Lowe's ratio test: the best match must be this much closer than the second best
SAME_PLACE_MATCHES = 24  # matches from which two consecutive photographs count as one place (see above)


def _features(path: Path):
    grey = cv2.imread(str(path), cv2.IMREAD_REDUCED_GRAYSCALE_2)
    if grey is None:
        raise SystemExit(f"{path}: missing or not decodable")
    return cv2.ORB_create(ORB_FEATURES).detectAndCompute(grey, None)[1]


def place_matches(a, b) -> int:
    """Matches between two photographs' ORB descriptors that pass the ratio test (0 when either has none)."""
    if a is None or b is None or len(a) < 2 or len(b) < 2:
        return 0
    pairs = cv2.BFMatcher(cv2.NORM_HAMMING).knnMatch(a, b, k=2)
    return sum(1 for p in pairs if len(p) == 2 and p[0].distance < RATIO * p[1].distance)


def consecutive_matches(paths: Sequence[Path]) -> List[int]:
    """``place_matches`` of each photograph with the next, in the given order (one fewer than ``paths``)."""
    previous, out = None, []
    for k, path in enumerate(paths):
        current = _features(path)
        if k:
            out.append(place_matches(previous, current))
        previous = current
    return out


def scene_groups(similarities: Sequence[float], threshold: float) -> List[List[int]]:
    """Indices of ``len(similarities) + 1`` photographs in runs: photograph k+1 joins k's run when their
    similarity (``similarities[k]``) reaches ``threshold``. Chaining is transitive, as a drive past one place is."""
    groups = [[0]]
    for k, value in enumerate(similarities):
        if value >= threshold:
            groups[-1].append(k + 1)
        else:
            groups.append([k + 1])
    return groups


def scene_of(names: Sequence[str], groups: Sequence[Sequence[int]]) -> Dict[str, str]:
    """Photograph name -> its scene's id: the name of the scene's first photograph."""
    return {names[k]: names[group[0]] for group in groups for k in group}
