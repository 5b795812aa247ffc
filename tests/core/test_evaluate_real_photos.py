"""``scripts.evaluate_real_photos`` and ``scripts.realset.make_subset`` on small constructed sets.

The constructed "photographs" are catalogue renderings pasted on a grey ground: they check the
plumbing (manifest -> candidates -> classifier / colour step -> tables), not recognition quality;
real figures come from the real set (and the smoke test on the committed subset).
"""

from __future__ import annotations

import os
from pathlib import Path

import cv2
import numpy as np
import pytest

from scripts import evaluate_real_photos as evaluate
from scripts.realset import make_subset
from signmapper_core.validation import IMAGE_LIST_COLUMNS, MANIFEST_COLUMNS, load_manifest, load_scene_list

REPO = Path(__file__).resolve().parents[2]



def _paste(canvas: np.ndarray, catalogue, template_id: str, x: int, y: int, size: int):
    bgr, alpha = catalogue.render(template_id, size)
    h, w = alpha.shape
    a = (alpha[..., None] / 255.0)
    region = canvas[y : y + h, x : x + w]
    canvas[y : y + h, x : x + w] = (bgr * a + region * (1 - a)).astype(np.uint8)
    ys, xs = np.nonzero(alpha > 127)
    return x + xs.min(), y + ys.min(), x + xs.max() + 1, y + ys.max() + 1


def _write_csv(path: Path, header, rows):
    path.write_text("\n".join([",".join(header)] + [",".join(map(str, r)) for r in rows]) + "\n", encoding="utf-8")


@pytest.fixture(scope="module")
def tiny_set(tmp_path_factory, catalogue):
    """Three crops, two scenes (one with a yield sign and a 50 limit, one empty) in the manifest format."""
    root = tmp_path_factory.mktemp("real")
    (root / "crops").mkdir()
    (root / "scenes").mkdir()
    crops = []
    for i, (tid, group, split) in enumerate([("3.02", "same", "tune"), ("2.30-50", "same", "report"),
                                             ("1.22", "differs", "report")]):
        canvas = np.full((70, 70, 3), 128, np.uint8)
        box = _paste(canvas, catalogue, tid, 8, 8, 54)
        cv2.imwrite(str(root / "crops" / f"{i}.png"), canvas)
        crops.append([f"crops/{i}.png", *box, tid, group, split, "constructed"])
    _write_csv(root / "crops.csv", MANIFEST_COLUMNS, crops)
    scene = np.full((300, 400, 3), 110, np.uint8)
    signs = [[*_paste(scene, catalogue, "3.02", 60, 80, 70), "3.02"],
             [*_paste(scene, catalogue, "2.30-50", 250, 90, 60), "2.30-50"]]
    cv2.imwrite(str(root / "scenes" / "a.png"), scene)
    cv2.imwrite(str(root / "scenes" / "b.png"), np.full((300, 400, 3), 110, np.uint8))
    _write_csv(root / "scenes.csv", MANIFEST_COLUMNS,
               [["scenes/a.png", x0, y0, x1, y1, tid, "same", "report", "constructed"]
                for x0, y0, x1, y1, tid in signs])
    _write_csv(root / "scenes_images.csv", IMAGE_LIST_COLUMNS,
               [["scenes/a.png", 400, 300, "report", "constructed", 2],
                ["scenes/b.png", 400, 300, "report", "constructed", 0]])
    return root


def _table_row(output: str, title: str, first: str, second: str) -> list:
    lines = output.split(title, 1)[1].splitlines()
    for line in lines:
        cells = line.split()
        if cells[:2] == [first, second]:
            return cells
    raise AssertionError(f"no row {first} {second} under {title!r}:\n{output}")


def test_classify_runs_the_classifier_on_every_selected_crop(tiny_set, capsys, monkeypatch):
    from signmapper_core.pipeline.classify import ClassificationResult

    calls = []

    class Fake:
        name, accept_threshold = "fake", 0.6

        def knows(self, ids):
            return True

        def classify(self, image, bbox, candidates):
            calls.append((image.shape, tuple(bbox), set(candidates)))
            chosen = candidates[0] if len(candidates) == 1 else "2.30-50"
            return ClassificationResult(chosen, 0.9, {chosen: 0.9, "1.22": 0.05} if "1.22" in candidates else {})

    monkeypatch.setattr(evaluate, "make_classifier", lambda name, catalogue, model=None: Fake())
    assert evaluate.main(["classify", "--data", str(tiny_set), "--split", "all", "--classifier", "fake"]) == 0
    out = capsys.readouterr().out
    assert len(calls) == 3
    # candidates: entries with the true entry's colour and shape (3.02 is the only inverted triangle)
    assert calls[0][2] == {"3.02"}
    assert "2.30-50" in calls[1][2] and "2.01" in calls[1][2] and "3.01" not in calls[1][2]
    assert "1.22" in calls[2][2] and "1.30" in calls[2][2]
    # 3.02 and 2.30-50 right, 1.22 wrong and accepted (score 0.9 >= 0.6), its true id the next choice
    assert "misread signs: 1; the true id among their next choices (the review's suggestions): 1 (100.0%)" in out
    assert _table_row(out, "by group and size", "same", "all")[2:5] == ["2", "54", "100.0%"]
    assert _table_row(out, "by group and size", "differs", "all")[4:7] == ["0.0%", "100.0%", "100.0%"]
    assert _table_row(out, "per SSV id", "1.22", "differs")[-2:] == ["2.30-50", "1"]


def test_classify_with_ncc_gets_rendered_templates_right(tiny_set, capsys):
    assert evaluate.main(["classify", "--data", str(tiny_set), "--split", "report"]) == 0
    out = capsys.readouterr().out
    assert "split=report, 2 signs" in out
    assert _table_row(out, "per SSV id", "2.30-50", "same")[4] == "100.0%"


def test_classify_leaves_a_sign_whose_candidates_the_network_does_not_know_to_template_matching(
        catalogue, tmp_path, capsys):
    """A network trained before entries were added to the catalogue (as the white signs once were): as in the
    pipeline (``PairContext.classifier_knowing``), a sign whose candidates it does not all know is read by
    template matching (and counted), the others by the network. The shipped network's card, with 2.55's class
    renamed, is such a network."""
    import json
    import shutil

    from signmapper_core.pipeline.classifiers import model_card_path

    shipped = model_card_path(catalogue.folder)
    model = tmp_path / "model"
    model.mkdir()
    card = json.loads(shipped.read_text(encoding="utf-8"))
    shutil.copy(shipped.parent / card["onnx"], model / card["onnx"])
    card["classes"] = ["not-in-catalogue" if c == "2.55" else c for c in card["classes"]]
    (model / "model.json").write_text(json.dumps(card), encoding="utf-8")
    assert not evaluate.make_classifier("cnn", catalogue, model).knows(["2.55"])
    (tmp_path / "crops").mkdir()
    rows = []
    for i, tid in enumerate(("2.55", "2.30-50")):
        canvas = np.full((70, 70, 3), 128, np.uint8)
        box = _paste(canvas, catalogue, tid, 8, 8, 54)
        cv2.imwrite(str(tmp_path / "crops" / f"{i}.png"), canvas)
        rows.append([f"crops/{i}.png", *box, tid, "same", "report", "constructed"])
    _write_csv(tmp_path / "crops.csv", MANIFEST_COLUMNS, rows)
    assert evaluate.main(["classify", "--data", str(tmp_path), "--split", "all", "--classifier", "cnn",
                          "--model", str(model)]) == 0
    out = capsys.readouterr().out
    assert "read by template matching (accepted >= 0.6), the cnn classifier not knowing every candidate: " \
        "1 signs, 2.55 (1)" in out
    assert "split=all, 2 signs" in out
    assert _table_row(out, "per SSV id", "2.30-50", "same")[4] == "100.0%"
    white_circles = len(list(catalogue.filter(colours=["white"], shapes=["circle"])))
    assert _table_row(out, "per SSV id", "2.55", "same")[3:5] == [str(white_circles), "100.0%"]  # its candidates


def test_unknown_classifier_is_named():
    with pytest.raises(SystemExit, match="unknown classifier 'svm'; known: auto, cnn, ncc"):
        evaluate.make_classifier("svm", None)


def test_detect_finds_both_faces_and_counts_segments_per_image(tiny_set, capsys):
    assert evaluate.main(["detect", "--data", str(tiny_set), "--split", "report"]) == 0
    out = capsys.readouterr().out
    assert "2 images, 2 signs" in out
    assert _table_row(out, "by group and size", "same", "all")[4:6] == ["100.0%", "100.0%"]
    empty = _table_row(out, "Segments per image", "without", "signs")
    assert empty[2:] == ["1", "0.0", "0.0", "0.0"]


def test_detect_leaves_white_signs_out_as_labelled_boxes(catalogue, tmp_path, capsys):
    """The colour step does not look for white signs: a 2.55 in a photograph is no sign it missed, and a
    segment on it (its grey cars) is not "away" from the labelled signs; a photograph with only white signs
    counts as one without signs."""
    (tmp_path / "scenes").mkdir()
    scene = np.full((300, 400, 3), 110, np.uint8)
    yield_box = _paste(scene, catalogue, "3.02", 60, 80, 70)
    white_box = _paste(scene, catalogue, "2.55", 250, 90, 60)
    cv2.imwrite(str(tmp_path / "scenes" / "a.png"), scene)
    only_white = np.full((300, 400, 3), 110, np.uint8)
    white_only_box = _paste(only_white, catalogue, "2.55", 150, 90, 60)
    cv2.imwrite(str(tmp_path / "scenes" / "b.png"), only_white)
    _write_csv(tmp_path / "scenes.csv", MANIFEST_COLUMNS,
               [["scenes/a.png", *yield_box, "3.02", "same", "report", "constructed"],
                ["scenes/a.png", *white_box, "2.55", "same", "report", "constructed"],
                ["scenes/b.png", *white_only_box, "2.55", "same", "report", "constructed"]])
    _write_csv(tmp_path / "scenes_images.csv", IMAGE_LIST_COLUMNS,
               [["scenes/a.png", 400, 300, "report", "constructed", 2],
                ["scenes/b.png", 400, 300, "report", "constructed", 1]])
    _write_csv(tmp_path / "crops.csv", MANIFEST_COLUMNS, [])
    assert evaluate.main(["detect", "--data", str(tmp_path), "--split", "report"]) == 0
    out = capsys.readouterr().out
    assert "2 images, 1 signs" in out and "2 white signs left out" in out
    assert _table_row(out, "per SSV id", "3.02", "same")[-2:] == ["100.0%", "100.0%"]
    assert "2.55" not in out.split("Detection per SSV id", 1)[1].split("Segments per image")[0]
    assert _table_row(out, "Segments per image", "with", "signs")[2] == "1"
    assert _table_row(out, "Segments per image", "without", "signs")[2] == "1"
    assert _table_row(out, "Segments per image", "all", "2")[-1] == "0.0"  # nothing away from the labels


def test_limit_draws_a_seeded_sample():
    signs = list(range(100))

    class S:
        def __init__(self, i):
            self.i, self.split = i, "tune" if i % 2 else "report"

    items = [S(i) for i in signs]
    a = evaluate.select(items, "tune", 10, seed=3)
    assert len(a) == 10 and all(s.split == "tune" for s in a)
    assert [s.i for s in a] == [s.i for s in evaluate.select(items, "tune", 10, seed=3)]
    assert [s.i for s in a] != [s.i for s in evaluate.select(items, "tune", 10, seed=4)]
    assert len(evaluate.select(items, "all", 0, seed=0)) == 100


def test_round_robin_spreads_over_ids_and_sizes():
    class S:
        def __init__(self, sid, size):
            self.ssv_id, self.size_px = sid, size

    pool = [S("2.30-50", 40) for _ in range(50)] + [S("2.30-50", 20) for _ in range(5)] + [S("1.22", 40)]
    chosen = make_subset.round_robin(pool, 8, seed=0)
    assert len(chosen) == 8
    assert sum(s.ssv_id == "1.22" for s in chosen) == 1
    # cells take turns: 1.22 (1, then empty), 2.30-50 large, 2.30-50 small -> 1 + 4 large + 3 small
    assert sum(s.size_px < 30 for s in chosen) == 3
    assert make_subset.margin_box((10, 10, 100, 50), 115, 200) == (0, 0, 115, 70)
    assert make_subset.margin_box((20, 20, 30, 30), 100, 100) == (15, 15, 55, 55)


def test_make_subset_writes_readable_manifests_from_the_report_half(tiny_set, tmp_path):
    out = tmp_path / "subset"
    crops, scenes, signs, size = make_subset.build(tiny_set, out, n_crops=10, n_scenes=2, with_gtsrb=False,
                                                   seed=0, max_mb=5)
    assert (crops, scenes, signs) == (2, 2, 2)
    assert size < 1
    cut = load_manifest(out / "crops.csv")
    assert {s.ssv_id for s in cut} == {"3.02", "2.30-50"}
    assert all(s.source == "gtsdb-crop" or s.source == "constructed" for s in cut)
    for s in cut:
        image = s.load_image()
        x, y, w, h = s.bbox
        assert x >= 5 and y >= 5 and image.shape[1] - (x + w) >= 5  # the margin around the face
    assert len(load_scene_list(out / "scenes_images.csv")) == 2
    assert "Licences" in (out / "README.md").read_text(encoding="utf-8")


def subset_folder():
    """The committed subset tests/data/real-signs, or $SIGNMAPPER_REAL_SUBSET."""
    env = os.environ.get("SIGNMAPPER_REAL_SUBSET")
    return Path(env) if env else REPO / "tests" / "data" / "real-signs"


def test_smoke_on_the_committed_subset(catalogue, capsys):
    folder = subset_folder()
    ids = {e.id for e in catalogue}
    crops = load_manifest(folder / "crops.csv", known_ids=ids)
    scenes = load_manifest(folder / "scenes.csv", known_ids=ids)
    listing = load_scene_list(folder / "scenes_images.csv")
    assert len(crops) >= 100 and len(scenes) >= 20
    assert {s.split for s in crops + scenes} == {"report"}
    assert {s.image for s in scenes} <= {s.image for s in listing}
    for sign in crops[:50] + scenes[:10]:
        sign.load_image()  # box inside, image decodable
    assert evaluate.main(["classify", "--data", str(folder), "--split", "report", "--limit", "20"]) == 0
    assert "split=report, 20 signs" in capsys.readouterr().out
    assert evaluate.main(["detect", "--data", str(folder), "--split", "report", "--limit", "5"]) == 0
    assert "5 images" in capsys.readouterr().out


def test_open_set_outcomes_follow_the_pipelines_judgement():
    """A reading of an id the network never saw: unknown below the open set's limit (unless the network calls it
    no sign), then the indicator's floors, as ``detect`` judges it."""
    from types import SimpleNamespace

    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.pipeline.classify import ClassificationResult

    clf = SimpleNamespace(unknown_logit=5.0, accept_threshold=0.9, min_score=0.25)
    config = PipelineConfig()
    outcome = evaluate.open_set_outcome
    assert outcome(ClassificationResult(None, 0.0), clf, config) == "no candidate"
    assert outcome(ClassificationResult("2.30-60", 0.99, fit=4.0, background=0.1), clf, config) == "unknown"
    assert outcome(ClassificationResult("2.30-60", 0.99, fit=4.0, background=0.8), clf, config) == \
        "accepted as another id"
    assert outcome(ClassificationResult("2.30-60", 0.7, fit=6.0), clf, config) == "review as another id"
    assert outcome(ClassificationResult("2.30-60", 0.95, fit=6.0), clf, config) == "accepted as another id"
    assert outcome(ClassificationResult("2.30-60", 0.01, fit=6.0), clf, config) == "no sign"


def test_open_set_reads_the_signs_of_ids_the_catalogue_lacks_among_its_other_entries(tiny_set, catalogue, tmp_path,
                                                                                     capsys):
    """The shipped network with a catalogue lacking 3.02 and 2.30-50 (as ``training.left_out`` writes one): the
    two crops of those ids are read, the 1.22 it keeps is not; 2.30-50 is never given its own id (not a
    candidate); 3.02 has no other entry of its colour and shape."""
    from signmapper_core.pipeline.classifiers import model_card_path
    from training.left_out import catalogue_without

    catalogue_without(catalogue.folder, tmp_path / "without", ["3.02", "2.30-50"])
    model = model_card_path(catalogue.folder).parent
    assert evaluate.main(["open-set", "--data", str(tiny_set), "--split", "all", "--catalogue",
                          str(tmp_path / "without"), "--model", str(model)]) == 0
    out = capsys.readouterr().out
    assert "split=all, 2 signs of ids the catalogue lacks" in out
    others = [e for e in catalogue.filter(colours=[catalogue["3.02"].colour], shapes=[catalogue["3.02"].shape])
              if e.id != "3.02"]
    row = _table_row(out, "Open set per SSV id", "3.02", "same")
    assert row[2] == "1" and (row[7] == "100.0%") == (not others)
    row = _table_row(out, "Open set per SSV id", "2.30-50", "same")
    assert row[2] == "1" and row[7] == "0.0%" and "2.30-50" not in row[8:]
    with pytest.raises(SystemExit) as stop:
        evaluate.main(["open-set", "--data", str(tiny_set)])
    assert stop.value.code == 2
