"""Review controller on a synthetic drive: crops, decisions on disk, undo, review walk, added signs, moved drives."""

import shutil
import time
from pathlib import Path

import cv2
import numpy as np
import pytest
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsPoint,
    QgsPointXY,
    QgsProject,
    QgsSettings,
    QgsVectorLayer,
    QgsWkbTypes,
)
from qgis.PyQt.QtGui import QImage
from qgis.PyQt.QtWidgets import QApplication

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.geometry import world_to_pixel
from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive

SMALL = dict(width=960, height=540, fx=875.0)
REVIEW_EVERY = 2  # every second detection gets status "review" so the walk has several stops


@pytest.fixture(scope="module")
def drive_dir(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("review") / "drive"
    generate_drive(out, SimulationConfig(pairs=8, seed=11, write_depth=True, **SMALL, **DRAWABLE_SIGNS))
    return out


@pytest.fixture(scope="module")
def detections(drive_dir):
    """(pair record, Detection) of every detection of the drive, in driving order."""
    drive, catalogue = open_drive(drive_dir), load_catalogue()
    found = []
    for record in drive.pairs:
        for det in detect_pair(drive.load_left(record), drive.load_depth(record), None, drive.camera, record.pose,
                               catalogue, PipelineConfig()):
            found.append((record, det))
    assert len(found) >= 4
    return found


def _attrs(det, record, status):
    x, y, w, h = det.bbox
    return {
        "template_id": det.template_id, "name": det.name, "colour": det.colour, "shape": det.shape,
        "width_m": det.width_m, "height_m": det.height_m, "format": det.format,
        "detection_indicator": det.detection_indicator, "classification_indicator": det.classification_indicator,
        "status": status, "reviewed": 0, "source": det.source, "pair_id": record.id, "time": record.time,
        "u": det.u, "v": det.v, "bbox_x": x, "bbox_y": y, "bbox_w": w, "bbox_h": h, "depth_m": det.depth_m,
    }


def _write_layer(gpkg, name, rows, crs):
    from sign_mapper.gpkg.fields import layer_fields

    fields = layer_fields(name)
    writer = gpkg.open_layer(name, fields, QgsWkbTypes.PointZ, crs)
    for values, position in rows:
        feature = QgsFeature(fields)
        for key, value in values.items():
            if fields.indexOf(key) >= 0:  # signs name their pair best_pair_id
                feature[key] = value.item() if isinstance(value, np.generic) else value
        feature.setGeometry(QgsGeometry(QgsPoint(*(float(c) for c in position))))
        writer.addFeature(feature, QgsFeatureSink.FastInsert)
    writer.close()


def build_gpkg(path: Path, drive_dir: Path, detections, recorded_drive=None, skip=(), language=None) -> Path:
    """A GeoPackage like mapsigns writes: detections, signs fused by template, and the run table."""
    from sign_mapper.gpkg.output import GeoPackageLayers
    from sign_mapper.signmapper_core.output.geopackage_file import PartialGeoPackage

    crs = QgsCoordinateReferenceSystem("EPSG:2056")
    sign_ids = {t: i + 1 for i, t in enumerate(sorted({d.template_id for _, d in detections}))}
    rows = []
    for i, (record, det) in enumerate(detections):
        if i in skip:
            continue
        values = _attrs(det, record, "review" if i % REVIEW_EVERY == 0 else "accepted")
        values["sign_id"] = sign_ids[det.template_id]
        rows.append((values, det.position))
    signs = []
    for template_id, sign_id in sign_ids.items():
        obs = [(r, d) for r, d in detections if d.template_id == template_id]
        record, best = max(obs, key=lambda rd: rd[1].classification_indicator)
        values = _attrs(best, record, "review")
        values.update(sign_id=sign_id, n_obs=len(obs), vote_share=1.0, sigma_m=0.02, best_pair_id=record.id)
        signs.append((values, np.mean([d.position for _, d in obs], axis=0)))
    output = PartialGeoPackage(path)
    gpkg = GeoPackageLayers(output)
    _write_layer(gpkg, "detections", rows, crs)
    _write_layer(gpkg, "signs", signs, crs)
    gpkg.write_run_table({"drive": str(recorded_drive or drive_dir), "crs": "EPSG:2056", "near_m": 4.0,
                          "far_m": 14.0, "colours": ["red", "blue", "yellow"], **({"language": language}
                                                                                   if language else {})})
    return Path(output.commit())


def wait_idle(controller, timeout_s=30.0):
    deadline = time.monotonic() + timeout_s
    while controller.busy() and time.monotonic() < deadline:
        QApplication.processEvents()
        time.sleep(0.005)
    QApplication.processEvents()
    assert not controller.busy(), "background work did not finish"


def on_disk(gpkg, layer_name="detections"):
    """Features as a fresh reader sees them in the file: fid -> attribute dict (+ geometry)."""
    layer = QgsVectorLayer(f"{gpkg}|layername={layer_name}", "check", "ogr")
    assert layer.isValid()
    out = {}
    for f in layer.getFeatures():
        values = dict(zip(layer.fields().names(), f.attributes()))
        p = f.geometry().constGet()
        values["xyz"] = np.array([p.x(), p.y(), p.z()])
        out[f.id()] = values
    return out


class Asker:
    def __init__(self, answer):
        self.answer, self.calls = answer, []

    def __call__(self, old_path):
        self.calls.append(old_path)
        return self.answer


@pytest.fixture
def review(sign_mapper, qgis_iface, tmp_path):
    """Returns open(gpkg, layer_name, ask=None) -> (controller, dock, layer); everything is torn down after."""
    from sign_mapper.review.controller import ReviewController
    from sign_mapper.ui.review_dock import ReviewDock

    made = []

    def open_layer(gpkg, layer_name="detections", ask=None, settings=None):
        layer = QgsVectorLayer(f"{gpkg}|layername={layer_name}", layer_name, "ogr")
        assert layer.isValid()
        QgsProject.instance().addMapLayer(layer)
        dock = ReviewDock()
        dock.resize(440, 900)
        dock.advance_box.setChecked(False)
        controller = ReviewController(qgis_iface, dock, ask_drive_folder=ask or Asker(None),
                                      settings=settings or QgsSettings())
        qgis_iface.setActiveLayer(layer)
        controller.activate()
        made.append((controller, dock))
        return controller, dock, layer

    yield open_layer
    for controller, dock in made:
        controller.shutdown()
        dock.deleteLater()
    QgsProject.instance().removeAllMapLayers()
    QApplication.processEvents()


@pytest.fixture
def gpkg(tmp_path, drive_dir, detections):
    return build_gpkg(tmp_path / "run.gpkg", drive_dir, detections)


def qimage_rgb(image: QImage) -> np.ndarray:
    image = image.convertToFormat(QImage.Format_RGB888)
    ptr = image.constBits()
    ptr.setsize(image.bytesPerLine() * image.height())
    rows = np.frombuffer(ptr, np.uint8).reshape(image.height(), image.bytesPerLine())
    return rows[:, : image.width() * 3].reshape(image.height(), image.width(), 3).copy()


def select(controller, layer, fid):
    layer.selectByIds([fid])
    wait_idle(controller)


def test_selecting_a_detection_loads_its_crop_from_the_left_image(review, gpkg, drive_dir):
    controller, dock, layer = review(gpkg)
    feature = sorted(layer.getFeatures(), key=lambda f: f.id())[1]
    select(controller, layer, feature.id())
    item = dock.item
    assert item.fid == feature.id() and item.pair_id == feature["pair_id"]
    assert item.template_id == feature["template_id"] and item.status == feature["status"]
    bbox = (feature["bbox_x"], feature["bbox_y"], feature["bbox_w"], feature["bbox_h"])
    assert item.bbox == bbox
    x, y, w, h = item.crop
    assert x <= bbox[0] and y <= bbox[1] and x + w >= bbox[0] + bbox[2] and y + h >= bbox[1] + bbox[3]
    left = cv2.imread(str(open_drive(drive_dir).pair(feature["pair_id"]).left_path))
    expected = left[y:y + h, x:x + w, ::-1]
    assert np.array_equal(qimage_rgb(item.crop_image()), expected)
    # the view shows that crop with the feature's bbox drawn
    rect = dock.image_view.bbox_rect()
    assert (rect.x(), rect.y(), rect.width(), rect.height()) == bbox
    assert dock.image_view.visible_image_rect().contains(dock.image_view.bbox_rect())


def test_a_fused_sign_shows_its_observations(review, gpkg):
    controller, dock, layer = review(gpkg, "signs")
    sign = next(iter(layer.getFeatures()))
    select(controller, layer, sign.id())
    detections = on_disk(gpkg)
    expected = sorted((d["time"], d["pair_id"]) for d in detections.values() if d["sign_id"] == sign["sign_id"])
    assert [o.pair_id for o in dock.item.observations] == [p for _, p in expected]
    assert all(o.thumbnail is not None and not o.thumbnail.isNull() for o in dock.item.observations)
    assert dock.strip.count() == len(expected)
    assert dock.item.pair_id == sign["best_pair_id"]


@pytest.mark.parametrize("decision", ["accept", "reject"])
def test_accept_and_reject_are_saved_and_undone_on_disk(review, gpkg, decision):
    controller, dock, layer = review(gpkg)
    fid = next(f.id() for f in layer.getFeatures() if f["status"] == "review")
    before = on_disk(gpkg)[fid]
    select(controller, layer, fid)
    getattr(dock, f"{decision}Requested").emit()
    wait_idle(controller)
    after = on_disk(gpkg)[fid]
    assert after["status"] == {"accept": "accepted", "reject": "rejected"}[decision]
    assert after["reviewed"] == 1
    assert not layer.isEditable()  # committed, not left in an edit session
    assert dock.buttons["undo"].isEnabled()
    dock.undoRequested.emit()
    wait_idle(controller)
    restored = on_disk(gpkg)[fid]
    assert (restored["status"], restored["reviewed"]) == (before["status"], before["reviewed"])
    assert not dock.buttons["undo"].isEnabled()


def test_reclassify_writes_the_catalogue_entry_and_format_and_undo_restores(review, gpkg):
    catalogue = load_catalogue()
    controller, dock, layer = review(gpkg)
    feature = next(iter(layer.getFeatures()))
    fid, old_format = feature.id(), feature["format"]
    before = on_disk(gpkg)[fid]
    target = next(e for e in catalogue if e.id != feature["template_id"] and old_format in e.formats)
    select(controller, layer, fid)
    dock.reclassifyRequested.emit(target.id)
    wait_idle(controller)
    after = on_disk(gpkg)[fid]
    assert (after["template_id"], after["name"], after["format"]) == (target.id, target.name("de"), old_format)
    assert (after["width_m"], after["height_m"]) == pytest.approx(target.formats[old_format])
    assert (after["status"], after["reviewed"]) == ("accepted", 1)
    # a template without the current format gets its "normal" one
    odd = next((e for e in catalogue if old_format not in e.formats and "normal" in e.formats), None)
    if odd is not None:
        dock.reclassifyRequested.emit(odd.id)
        wait_idle(controller)
        assert on_disk(gpkg)[fid]["format"] == "normal"
        dock.undoRequested.emit()
        wait_idle(controller)
    dock.undoRequested.emit()
    wait_idle(controller)
    restored = on_disk(gpkg)[fid]
    for key in ("template_id", "name", "format", "width_m", "height_m", "status", "reviewed"):
        assert restored[key] == before[key], key


def test_the_next_choices_of_a_feature_reclassify_it_with_one_click(review, gpkg):
    from qgis.PyQt.QtWidgets import QToolButton

    catalogue = load_catalogue()
    controller, dock, layer = review(gpkg)
    feature = next(iter(layer.getFeatures()))
    fid, current = feature.id(), feature["template_id"]
    target = next(e for e in catalogue if e.id != current and e.colour == feature["colour"])
    layer.startEditing()
    layer.changeAttributeValue(fid, layer.fields().indexOf("alternatives"), f"{target.id} 0.22, no.such.id 0.05")
    layer.changeAttributeValue(fid, layer.fields().indexOf("review_reason"), "seen in one pair only")
    assert layer.commitChanges()
    select(controller, layer, fid)
    assert dock.item.alternatives == [(target.id, 0.22), ("no.such.id", 0.05)]
    assert dock.item.review_reason == "seen in one pair only"
    assert dock.picker.suggested_ids() == [target.id]  # what the catalogue lacks is not offered
    (button,) = dock.picker.suggestions.findChildren(QToolButton)
    button.click()
    wait_idle(controller)
    after = on_disk(gpkg)[fid]
    assert (after["template_id"], after["status"], after["reviewed"]) == (target.id, "accepted", 1)
    assert dock.picker.suggested_ids() == []  # the feature now carries the suggested id itself


def test_decision_in_the_users_edit_session_goes_on_the_undo_stack(review, gpkg):
    controller, dock, layer = review(gpkg)
    fid = next(f.id() for f in layer.getFeatures() if f["status"] == "review")
    select(controller, layer, fid)
    layer.startEditing()
    depth = layer.undoStack().count()
    dock.acceptRequested.emit()
    wait_idle(controller)
    assert layer.isEditable() and layer.undoStack().count() == depth + 1
    assert layer.getFeature(fid)["status"] == "accepted"
    assert on_disk(gpkg)[fid]["status"] == "review"  # the user saves their session
    layer.undoStack().undo()
    assert layer.getFeature(fid)["status"] == "review"
    layer.rollBack()


def test_next_needing_review_walks_exactly_the_review_features(review, gpkg):
    controller, dock, layer = review(gpkg)
    review_fids = {f.id() for f in layer.getFeatures() if f["status"] == "review"}
    assert len(review_fids) >= 2
    visited = []
    for _ in range(len(review_fids)):
        dock.nextReviewRequested.emit()
        wait_idle(controller)
        visited.append(controller.fid)
        assert layer.selectedFeatureIds() == [controller.fid]
    assert sorted(visited) == sorted(review_fids)
    # next / previous walk every feature in driving order
    dock.nextRequested.emit()
    dock.previousRequested.emit()
    assert controller.fid == visited[-1]


def test_accept_then_advance_leaves_no_review_features(review, gpkg):
    controller, dock, layer = review(gpkg)
    dock.advance_box.setChecked(True)
    dock.nextReviewRequested.emit()
    for _ in range(20):
        if controller.fid is None or layer.getFeature(controller.fid)["status"] != "review":
            break
        dock.acceptRequested.emit()
        wait_idle(controller)
    assert {d["status"] for d in on_disk(gpkg).values()} == {"accepted"}


def test_zoom_centres_the_canvas_on_the_feature(review, gpkg, qgis_iface):
    controller, dock, layer = review(gpkg)
    feature = next(iter(layer.getFeatures()))
    canvas = qgis_iface.mapCanvas()
    canvas.setDestinationCrs(layer.crs())
    select(controller, layer, feature.id())
    dock.zoomRequested.emit()
    point = feature.geometry().asPoint()
    extent = canvas.extent()
    assert extent.center().distance(point) < 0.5
    assert min(extent.width(), extent.height()) == pytest.approx(40.0, abs=1.0)  # +-20 m; the canvas sets the aspect


def _truth_click(drive, record, sign):
    u, v, _ = (float(np.ravel(a)[0]) for a in world_to_pixel(drive.camera, record.pose, sign.position))
    return u + 1.5, v - 1.0  # a person clicks near, not exactly on, the centre


@pytest.mark.parametrize("layer_name", ["detections", "signs"])
def test_add_missed_sign_places_it_within_10_cm_of_the_truth(review, tmp_path, drive_dir, detections, layer_name):
    drive = open_drive(drive_dir)
    # a sign seen well (mid-range, right class) is the one a person would click
    target = next(i for i, (_, d) in enumerate(detections) if 7 < d.depth_m < 12
                  and min(np.linalg.norm(t.position - d.position) for t in drive.truth) < 0.1)
    record, missed = detections[target]
    gpkg = build_gpkg(tmp_path / "missed.gpkg", drive_dir, detections, skip={target})
    controller, dock, layer = review(gpkg, layer_name)
    questions = []
    dock.confirm = lambda title, text: questions.append(text) or True  # the signs layer still has this sign
    count = layer.featureCount()
    truth = min(drive.truth, key=lambda s: np.linalg.norm(s.position - missed.position))
    u, v = _truth_click(drive, record, truth)
    dock.addSignClicked.emit(record.id, u, v)
    wait_idle(controller)
    assert len(questions) == (1 if layer_name == "signs" else 0)
    features = on_disk(gpkg, layer_name)
    assert len(features) == count + 1
    added = features[controller.fid]
    assert added["status"] == "manual" and added["reviewed"] == 1
    assert added["template_id"] == truth.template_id
    assert added.get("pair_id", added.get("best_pair_id")) == record.id
    assert np.linalg.norm(added["xyz"] - truth.position) < 0.10
    if layer_name == "signs":
        assert added["sign_id"] == max(f["sign_id"] for f in features.values() if f is not added) + 1
        assert added["best_pair_id"] == record.id and added["n_obs"] == 1
    # undo deletes it from the file again
    dock.undoRequested.emit()
    wait_idle(controller)
    assert len(on_disk(gpkg, layer_name)) == count


def test_click_on_nothing_adds_nothing(review, gpkg, detections):
    controller, dock, layer = review(gpkg)
    count = layer.featureCount()
    dock.addSignClicked.emit(detections[0][0].id, 20.0, 520.0)  # road surface, bottom left
    wait_idle(controller)
    assert layer.featureCount() == count and "No sign found" in dock.message.text()


def test_moved_drive_is_asked_for_once_and_remembered(review, tmp_path, drive_dir, detections):
    moved = tmp_path / "moved-drive"
    shutil.copytree(drive_dir, moved)
    gone = tmp_path / "old-disk" / "drive"  # recorded, no longer there
    gpkg = build_gpkg(tmp_path / "moved.gpkg", drive_dir, detections, recorded_drive=gone)
    settings = QgsSettings()
    ask = Asker(str(moved))
    controller, dock, layer = review(gpkg, ask=ask, settings=settings)
    assert ask.calls == [str(gone)]
    fid = next(iter(layer.getFeatures())).id()
    select(controller, layer, fid)
    assert dock.item.image is not None
    assert Path(controller.drive.root) == moved
    controller.set_layer(None)
    controller.set_layer(layer)
    assert ask.calls == [str(gone)]  # not asked a second time
    # a new session (new controller) finds the answer in the settings
    ask_again = Asker(None)
    review(gpkg, ask=ask_again, settings=settings)
    assert ask_again.calls == []


def test_non_sign_mapper_layer_shows_nothing_to_review(review, gpkg, tmp_path):
    controller, dock, layer = review(gpkg)
    other = QgsVectorLayer("Point?crs=EPSG:2056&field=name:string", "other", "memory")
    controller.set_layer(other)
    assert dock.item is None and not dock.buttons["accept"].isEnabled()
    assert "Sign Mapper" in dock.title.text()


def test_dock_screenshot(review, gpkg, tmp_path):
    """Renders the dock on a fused sign; REVIEW_DOCK_SCREENSHOT=docs/review-dock.png keeps the picture."""
    import os

    controller, dock, layer = review(gpkg, "signs")
    dock.resize(460, 760)  # about what it gets beside the map on a 1000 px screen: the open picker fits
    dock.show()
    feature = next(iter(layer.getFeatures()))
    near = [e.id for e in load_catalogue() if e.colour == feature["colour"] and e.shape == feature["shape"]
            and e.id != feature["template_id"]][:2]
    layer.startEditing()
    layer.changeAttributeValue(feature.id(), layer.fields().indexOf("alternatives"),
                               ", ".join(f"{tid} {score}" for tid, score in zip(near, ("0.21", "0.04"))))
    assert layer.commitChanges()
    select(controller, layer, feature.id())
    dock.show_picker(True)
    QApplication.processEvents()
    assert dock.picker.suggested_ids() == near
    out = Path(os.environ.get("REVIEW_DOCK_SCREENSHOT", tmp_path / "review-dock.png"))
    assert dock.grab().save(str(out))
    assert 10_000 < out.stat().st_size < 600_000


def test_pair_box_and_observation_strip_show_their_images(review, gpkg, drive_dir):
    controller, dock, layer = review(gpkg, "signs")
    drive = open_drive(drive_dir)
    assert [dock.pair_box.itemText(i) for i in range(dock.pair_box.count())] == [r.id for r in drive.pairs]
    dock.pairRequested.emit(drive.pairs[0].id)  # a pair no feature points to, to add a sign there
    wait_idle(controller)
    assert dock.pair_id == drive.pairs[0].id
    assert dock.image_view.image().size().width() == drive.camera.width
    sign = next(iter(layer.getFeatures()))
    select(controller, layer, sign.id())
    last = dock.item.observations[-1]
    dock.strip.itemClicked.emit(dock.strip.item(len(dock.item.observations) - 1))
    wait_idle(controller)
    assert dock.pair_id == last.pair_id
    expected = cv2.imread(str(drive.pair(last.pair_id).left_path))[:, :, ::-1]
    assert np.array_equal(qimage_rgb(dock.image_view.image()), expected)


def test_mapsigns_output_is_reviewable(review, registered_plugin, drive_dir, tmp_path):
    """The contract with the Processing algorithm: its GeoPackage is recognised and its drive found."""
    import processing

    out = processing.run("signmapper:mapsigns", {"DRIVE": str(drive_dir), "OUTPUT": str(tmp_path / "m.gpkg")})
    controller, dock, layer = review(out["OUTPUT"])
    assert controller.kind == "detections" and Path(controller.drive.root) == drive_dir.resolve()
    fid = next(iter(layer.getFeatures())).id()
    select(controller, layer, fid)
    assert dock.item.image is not None
    dock.rejectRequested.emit()
    wait_idle(controller)
    assert on_disk(out["OUTPUT"])[fid]["status"] == "rejected"


def test_adding_a_sign_next_to_one_of_its_type_asks_first(review, gpkg, drive_dir, detections):
    drive = open_drive(drive_dir)
    target = next(i for i, (_, d) in enumerate(detections) if 7 < d.depth_m < 12
                  and min(np.linalg.norm(t.position - d.position) for t in drive.truth) < 0.1)
    record, seen = detections[target]
    controller, dock, layer = review(gpkg, "signs")
    questions = []
    dock.confirm = lambda title, text: questions.append(text) or False
    count = layer.featureCount()
    truth = min(drive.truth, key=lambda s: np.linalg.norm(s.position - seen.position))
    dock.addSignClicked.emit(record.id, *_truth_click(drive, record, truth))
    wait_idle(controller)
    assert len(questions) == 1 and seen.template_id in questions[0] and " m from the clicked sign" in questions[0]
    assert layer.featureCount() == count and "Not added" in dock.message.text()
    twin = layer.getFeature(controller.fid)  # the existing sign is shown instead
    assert twin["template_id"] == seen.template_id


def test_review_progress_in_the_dock_and_on_the_map(review, gpkg):
    controller, dock, layer = review(gpkg)
    total = layer.featureCount()
    to_review = sum(f["status"] == "review" for f in layer.getFeatures())
    fid = next(f.id() for f in layer.getFeatures() if f["status"] == "review")
    select(controller, layer, fid)
    assert dock.progress.text() == f"{to_review} to review · 0 of {total} reviewed"
    assert controller.map_progress.isVisible()
    assert controller.map_progress.text.endswith(f"{to_review} to review · 0 of {total} reviewed")
    dock.acceptRequested.emit()
    wait_idle(controller)
    assert dock.progress.text() == f"{to_review - 1} to review · 1 of {total} reviewed"
    assert controller.map_progress.text.endswith(f"{to_review - 1} to review · 1 of {total} reviewed")
    controller.set_layer(None)  # no Sign Mapper layer: no progress in the dock
    assert not dock.progress.isVisibleTo(dock)


def test_an_added_sign_shows_its_one_observation_and_undo_leaves_no_stale_image(review, tmp_path, drive_dir,
                                                                                  detections):
    drive = open_drive(drive_dir)
    target = next(i for i, (_, d) in enumerate(detections) if 7 < d.depth_m < 12
                  and min(np.linalg.norm(t.position - d.position) for t in drive.truth) < 0.1)
    record, missed = detections[target]
    others = [d for i, d in enumerate(detections) if d[1].template_id != missed.template_id]
    gpkg = build_gpkg(tmp_path / "one.gpkg", drive_dir, others, language="fr")  # the sign is in neither layer
    controller, dock, layer = review(gpkg, "signs")
    truth = min(drive.truth, key=lambda s: np.linalg.norm(s.position - missed.position))
    dock.addSignClicked.emit(record.id, *_truth_click(drive, record, truth))
    wait_idle(controller)
    assert dock.item.template_id == truth.template_id
    assert dock.item.name == load_catalogue()[truth.template_id].name("fr")  # the layer's language, as written
    assert f"Added {truth.template_id} {dock.item.name} at" in dock.message.text()  # and as said
    assert dock.strip_box.title() == "Observations (1)" and dock.strip.count() == 1
    assert dock.item.observations[0].pair_id == record.id
    dock.undoRequested.emit()
    wait_idle(controller)
    assert dock.item is None and not dock.image_view.has_image()


def gpkg_with_plates(path, drive_dir, detections):
    """The review GeoPackage plus two plates in its signs layer: a text plate (misread) and a pictogram plate."""
    built = build_gpkg(path, drive_dir, detections)
    signs = on_disk(built, "signs")
    host = min(signs.values(), key=lambda s: s["sign_id"])
    rows = []
    for k, (template_id, text, confidence) in enumerate((("plate", "20O m", 0.41), ("5.31-2", "ausgenommen", 1.0))):
        values = {key: host[key] for key in ("best_pair_id", "time", "u", "v", "bbox_x", "bbox_y", "bbox_w",
                                             "bbox_h", "depth_m")}
        values.update(sign_id=100 + k, template_id=template_id, name="Zusatztafel", colour="white",
                      shape="rectangle", width_m=0.6, height_m=0.2, format="normal-1", status="review", reviewed=0,
                      detection_indicator=0.9, classification_indicator=0.8, n_obs=3, vote_share=1.0,
                      plate_of=host["sign_id"], text=text, text_confidence=confidence)
        rows.append((values, host["xyz"] - [0.0, 0.0, 0.45 + 0.3 * k]))
    from sign_mapper.gpkg.fields import layer_fields

    fields = layer_fields("signs")
    layer = QgsVectorLayer(f"{built}|layername=signs", "signs", "ogr")  # appended to the signs layer
    layer.startEditing()
    for values, position in rows:
        feature = QgsFeature(layer.fields())
        for key, value in values.items():
            if fields.indexOf(key) >= 0:
                feature[key] = value.item() if isinstance(value, np.generic) else value
        feature.setGeometry(QgsGeometry(QgsPoint(*(float(c) for c in position))))
        layer.addFeature(feature)
    assert layer.commitChanges(), layer.commitErrors()
    return built, host["sign_id"]


def test_a_plate_shows_its_sign_and_text_and_a_person_corrects_the_text(review, tmp_path, drive_dir, detections):
    gpkg, host = gpkg_with_plates(tmp_path / "plates.gpkg", drive_dir, detections)
    controller, dock, layer = review(gpkg, "signs")
    plate = next(f for f in layer.getFeatures() if f["template_id"] == "plate")
    select(controller, layer, plate.id())
    assert not dock.plate_box.isHidden() and dock.plate_text.text() == "20O m"
    assert dock.info["plate"].text() == f"plate of sign {host} · “20O m” · text confidence 0.41"
    before = on_disk(gpkg, "signs")[plate.id()]
    dock.plate_text.setText("200m")  # spelt as the mapping writes texts when set
    dock.set_text_button.click()
    wait_idle(controller)
    after = on_disk(gpkg, "signs")[plate.id()]
    assert (after["text"], after["text_confidence"], after["status"], after["reviewed"]) == ("200 m", 1.0,
                                                                                              "accepted", 1)
    assert after["plate_of"] == host  # still the plate of its sign
    assert (after["template_id"], after["name"]) == ("5.01", "Distanztafel")  # typed by what it now says
    dock.undoRequested.emit()
    wait_idle(controller)
    restored = on_disk(gpkg, "signs")[plate.id()]
    assert (restored["text"], restored["status"], restored["template_id"]) == (before["text"], before["status"],
                                                                               "plate")
    pictogram = next(f for f in layer.getFeatures() if f["template_id"] == "5.31-2")
    select(controller, layer, pictogram.id())
    dock.plate_text.setText("excepté")
    dock.set_text_button.click()
    wait_idle(controller)
    assert on_disk(gpkg, "signs")[pictogram.id()]["template_id"] == "5.31-2"  # a drawing's id stays
    select(controller, layer, plate.id())
    dock.rejectRequested.emit()  # a plate that is none: rejected like a sign
    wait_idle(controller)
    assert on_disk(gpkg, "signs")[plate.id()]["status"] == "rejected"


def test_a_speed_limit_shows_the_number_its_digits_read(review, tmp_path, drive_dir, detections):
    gpkg = build_gpkg(tmp_path / "digits.gpkg", drive_dir, detections)
    layer = QgsVectorLayer(f"{gpkg}|layername=signs", "signs", "ogr")
    host = min(layer.getFeatures(), key=lambda f: f["sign_id"])
    layer.startEditing()
    layer.changeAttributeValue(host.id(), layer.fields().indexOf("text"), "30")
    layer.changeAttributeValue(host.id(), layer.fields().indexOf("text_confidence"), 0.667)
    assert layer.commitChanges(), layer.commitErrors()
    controller, dock, signs = review(gpkg, "signs")
    select(controller, signs, host.id())
    assert dock.plate_box.isHidden() and dock.info["plate"].text() == "digits read “30” · in 0.67 of its views"


def test_a_pictogram_plate_shows_its_drawing_and_a_sign_no_plate_text(review, tmp_path, drive_dir, detections):
    gpkg, host = gpkg_with_plates(tmp_path / "plates.gpkg", drive_dir, detections)
    controller, dock, layer = review(gpkg, "signs")
    pictogram = next(f for f in layer.getFeatures() if f["template_id"] == "5.31-2")
    select(controller, layer, pictogram.id())
    assert dock.item.pictogram_path.endswith("5.31-2_de.png") and dock.pictogram.pixmap() is not None
    assert not dock.pictogram.pixmap().isNull()
    assert "“ausgenommen”" in dock.info["plate"].text()
    sign = next(f for f in layer.getFeatures() if f["sign_id"] == host)
    select(controller, layer, sign.id())
    assert dock.plate_box.isHidden() and dock.info["plate"].text() == "–"


def test_follow_moves_the_map_only_as_far_as_needed(review, gpkg, qgis_iface):
    from qgis.core import QgsRectangle

    controller, dock, layer = review(gpkg)
    assert dock.following()  # on by default
    canvas = qgis_iface.mapCanvas()
    canvas.resize(600, 400)
    canvas.setDestinationCrs(layer.crs())
    fid = next(iter(layer.getFeatures())).id()
    point = layer.getFeature(fid).geometry().asPoint()
    canvas.setExtent(QgsRectangle(point.x() - 30, point.y() - 20, point.x() + 30, point.y() + 20))
    before = canvas.extent()
    select(controller, layer, fid)  # in the middle of the map: left alone
    assert canvas.extent() == before
    width = canvas.extent().width()
    canvas.setCenter(QgsPointXY(point.x() - (width / 2 - 1.0), point.y()))  # 1 m inside the right edge
    QApplication.processEvents()
    assert canvas.extent().contains(point)
    layer.removeSelection()
    select(controller, layer, fid)  # at the edge: panned to it, the scale kept
    assert canvas.extent().center().distance(point) < 0.5 and canvas.extent().width() == pytest.approx(width)
    canvas.setExtent(QgsRectangle(point.x() - 5000, point.y() - 5000, point.x() + 5000, point.y() + 5000))
    layer.removeSelection()
    select(controller, layer, fid)  # 10 km across: zoomed in to ±20 m
    assert canvas.extent().center().distance(point) < 0.5
    assert min(canvas.extent().width(), canvas.extent().height()) == pytest.approx(40.0, abs=1.0)
    dock.follow_box.setChecked(False)
    canvas.setExtent(QgsRectangle(point.x() - 5000, point.y() - 5000, point.x() + 5000, point.y() + 5000))
    layer.removeSelection()
    select(controller, layer, fid)  # Follow off: the map stays
    assert canvas.extent().width() > 9000
