"""The drive viewer on a synthetic drive: stepping, signs projected onto their truth, the vehicle on the map,
opening a pair from the map, selecting a sign by its box, a zoom that stays."""

import time
from pathlib import Path

import cv2
import numpy as np
import pytest
from mapping_runs import map_drive
from qgis.core import QgsPointXY, QgsProject, QgsVectorLayer
from qgis.PyQt.QtCore import QThreadPool
from qgis.PyQt.QtGui import QImage
from qgis.PyQt.QtWidgets import QApplication

from signmapper_core.drive.reader import open_drive
from signmapper_core.geometry import world_to_pixel
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive, true_poses

SMALL = dict(width=960, height=540, fx=875.0)
EXACT_POSES = dict(position_sigma_m=0.0, angle_sigma_deg=0.0)  # recorded poses = the poses images were drawn from


@pytest.fixture(scope="module")
def drive_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("viewer") / "drive"
    generate_drive(out, SimulationConfig(pairs=10, seed=11, write_depth=True, **SMALL, **EXACT_POSES, **DRAWABLE_SIGNS))
    return out


@pytest.fixture(scope="module")
def mapped(drive_dir, tmp_path_factory, sign_mapper, qgis_processing):
    return map_drive(sign_mapper, drive_dir, tmp_path_factory.mktemp("viewer-run") / "run.gpkg", LANGUAGE=2)


def wait(condition, timeout_s=20.0):
    deadline = time.monotonic() + timeout_s
    while not condition() and time.monotonic() < deadline:
        QApplication.processEvents()
        time.sleep(0.003)
    QApplication.processEvents()
    assert condition(), "timed out"


@pytest.fixture
def viewer(sign_mapper, qgis_iface, mapped):
    from sign_mapper.ui.drive_viewer import DriveViewerDock
    from sign_mapper.viewer.controller import DriveViewerController

    layers = {}
    for name in ("signs", "detections"):
        layers[name] = QgsVectorLayer(f"{mapped}|layername={name}", name, "ogr")
        assert layers[name].isValid()
    QgsProject.instance().addMapLayers(list(layers.values()))
    canvas = qgis_iface.mapCanvas()
    canvas.resize(600, 400)
    canvas.setDestinationCrs(layers["signs"].crs())
    dock = DriveViewerDock()
    dock.resize(900, 600)
    dock.show()
    added = []
    controller = DriveViewerController(qgis_iface, dock, add_sign=lambda *args: added.append(args))
    qgis_iface.setActiveLayer(layers["signs"])
    controller.activate()
    wait(lambda: dock.index == 0)
    yield controller, dock, layers, added
    controller.shutdown()
    dock.close()
    # No map render may still read the layers removed below: none starts on them any more, the running one
    # ends, and so do the ones the canvas cancelled while stepping (they finish in Qt's global thread pool).
    canvas.setLayers([])
    canvas.waitWhileRendering()
    assert QThreadPool.globalInstance().waitForDone(60000), "map renders still running after 60 s"
    dock.deleteLater()
    QApplication.processEvents()
    QgsProject.instance().removeAllMapLayers()
    QApplication.processEvents()


def rgb_of(image: QImage) -> np.ndarray:
    image = image.convertToFormat(QImage.Format_RGB888)
    ptr = image.constBits()
    ptr.setsize(image.bytesPerLine() * image.height())
    rows = np.frombuffer(ptr, np.uint8).reshape(image.height(), image.bytesPerLine())
    return rows[:, : image.width() * 3].reshape(image.height(), image.width(), 3).copy()


def test_steps_through_the_drive_with_buttons_keys_and_slider(viewer, drive_dir):
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtTest import QTest

    controller, dock, _, _ = viewer
    drive = open_drive(drive_dir)
    assert dock.count == len(drive.pairs) and dock.pair_id == drive.pairs[0].id
    dock.buttons["next"].click()
    wait(lambda: dock.index == 1)
    left = cv2.imread(str(drive.pairs[1].left_path))[:, :, ::-1]
    assert np.array_equal(rgb_of(dock.view.image()), left)
    dock.view.setFocus()
    QTest.keyClick(dock.view, Qt.Key_Right)
    wait(lambda: dock.index == 2)
    dock.slider.setValue(7)
    wait(lambda: dock.index == 7)
    assert dock.pair_id == drive.pairs[7].id and "Pair 000007 · 8 of 10" in dock.caption.text()
    dock.buttons["play"].setChecked(True)
    wait(lambda: dock.index == len(drive.pairs) - 1)
    wait(lambda: not dock.buttons["play"].isChecked())  # stops at the end


def _move_signs_to_truth(layer, truth):
    """Signs at their surveyed position: what the projection must put exactly onto the image."""
    layer.startEditing()
    moved = {}
    for feature in layer.getFeatures():
        p = feature.geometry().constGet()
        xyz = np.array([p.x(), p.y(), p.z()])
        sign = min(truth, key=lambda s: np.linalg.norm(s.position - xyz))
        assert np.linalg.norm(sign.position - xyz) < 0.2
        from qgis.core import QgsGeometry, QgsPoint

        layer.changeGeometry(feature.id(), QgsGeometry(QgsPoint(*(float(c) for c in sign.position))))
        moved[feature.id()] = sign
    assert layer.commitChanges()
    return moved


def test_a_mapped_sign_is_drawn_within_2_px_of_where_the_image_shows_it(viewer, drive_dir):
    controller, dock, layers, _ = viewer
    drive = open_drive(drive_dir)
    moved = _move_signs_to_truth(layers["signs"], drive.truth)
    poses = true_poses(SimulationConfig(pairs=10, seed=11, write_depth=True, **SMALL, **EXACT_POSES, **DRAWABLE_SIGNS))
    checked = 0
    for index in range(len(drive.pairs)):
        controller.go_to(index)
        wait(lambda i=index: dock.index == i)
        for box in dock.view.boxes():
            if not box.key.startswith("signs:"):
                continue
            sign = moved[int(box.key.split(":")[1])]
            u, v, _ = (float(np.ravel(a)[0]) for a in world_to_pixel(drive.camera, poses[index], sign.position))
            x, y, w, h = box.rect
            assert abs(x + w / 2 - u) < 2.0 and abs(y + h / 2 - v) < 2.0, (index, box, u, v)
            checked += 1
    assert checked >= 5
    # the mapped signs' boxes sit on the detections of the same pair
    controller.go_to(7)
    wait(lambda: dock.index == 7)
    detections = [b for b in dock.view.boxes() if b.key.startswith("detections:")]
    signs = [b for b in dock.view.boxes() if b.key.startswith("signs:")]
    assert detections and signs
    for d in detections:
        cx, cy = d.rect[0] + d.rect[2] / 2, d.rect[1] + d.rect[3] / 2
        assert any(abs(cx - (s.rect[0] + s.rect[2] / 2)) < 3 and abs(cy - (s.rect[1] + s.rect[3] / 2)) < 3
                   for s in signs)


def test_the_vehicle_and_its_view_cone_follow_on_the_map(viewer, drive_dir, qgis_iface):
    controller, dock, _, _ = viewer
    drive = open_drive(drive_dir)
    canvas = qgis_iface.mapCanvas()
    canvas.setExtent(canvas.extent().__class__(0, 0, 10, 10))  # somewhere else
    controller.go_to(4)
    wait(lambda: dock.index == 4)
    pose = drive.pairs[4].pose
    assert controller.vehicle.position.distance(QgsPointXY(pose.easting, pose.northing)) < 1e-6
    assert canvas.extent().contains(QgsPointXY(pose.easting, pose.northing))
    cone = controller.vehicle.cone.asGeometry()
    ahead = QgsPointXY(pose.easting + 8.0 * np.sin(np.radians(pose.heading)),
                       pose.northing + 8.0 * np.cos(np.radians(pose.heading)))
    assert cone.contains(ahead.__class__(ahead))  # 8 m straight ahead is in view
    behind = QgsPointXY(2 * pose.easting - ahead.x(), 2 * pose.northing - ahead.y())
    assert not cone.contains(behind)


def test_clicking_the_map_opens_the_pair_at_a_point_or_the_pair_that_sees_a_place(viewer, drive_dir):
    from signmapper_core.drive.viewing import best_pair_for

    controller, dock, _, _ = viewer
    drive = open_drive(drive_dir)
    pose = drive.pairs[6].pose
    assert controller.open_at(pose.easting + 0.05, pose.northing, 0.05) == 6
    wait(lambda: dock.index == 6)
    sign = drive.truth[0]
    index = controller.open_at(sign.easting, sign.northing, 0.05)
    assert index == best_pair_for(drive.camera, drive.pairs, sign.easting, sign.northing, None, 4.0, 14.0)
    assert index is not None
    wait(lambda: dock.index == index)
    assert controller.open_at(pose.easting, pose.northing + 500.0, 0.05) is None
    assert "No pair sees" in dock.message.text()


def test_clicking_a_box_selects_its_sign_and_makes_its_layer_current(viewer, qgis_iface):
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtTest import QTest

    controller, dock, layers, _ = viewer
    controller.go_to(7)
    wait(lambda: dock.index == 7)
    for kind in ("detections", "signs"):
        x, y, w, h = next(b for b in dock.view.boxes() if b.key.startswith(kind)).rect
        u, v = x + w / 2 - 0.5, y + h / 2 - 0.5
        hit = dock.view.box_at(u, v)  # nested boxes: the smaller one is clicked
        QTest.mouseClick(dock.view.viewport(), Qt.LeftButton, Qt.NoModifier, dock.view.image_to_view(u, v))
        hit_kind, fid = hit.key.split(":")
        assert layers[hit_kind].selectedFeatureIds() == [int(fid)]
        assert qgis_iface.activeLayer() is layers[hit_kind]


def test_zoom_and_pan_stay_while_stepping_and_add_sign_is_handed_on(viewer):
    controller, dock, layers, added = viewer
    view = dock.view
    view.zoom_by(3.0)
    view.centerOn(200, 150)
    scale, centre = view.transform().m11(), view.visible_image_rect().center()
    dock.resize(880, 640)  # the dock changing size does not snap back
    QApplication.processEvents()
    dock.step(1)
    wait(lambda: dock.index == 1)
    assert view.transform().m11() == pytest.approx(scale)
    assert (view.visible_image_rect().center() - centre).manhattanLength() < 40
    dock.buttons["add_sign"].setChecked(True)
    view.imageClicked.emit(300.0, 120.0)
    assert added == [(layers["signs"], dock.pair_id, 300.0, 120.0)]


def test_pick_on_map_opens_the_pair_of_a_clicked_trajectory_point(viewer, drive_dir, qgis_iface):
    """The whole path from the dock's button through the map tool: a click on the canvas at a pair's camera."""
    from qgis.core import QgsRectangle
    from qgis.PyQt.QtCore import QPoint, Qt
    from qgis.PyQt.QtTest import QTest

    controller, dock, _, _ = viewer
    drive = open_drive(drive_dir)
    canvas = qgis_iface.mapCanvas()
    dock.follow_box.setChecked(False)  # the vehicle must not move the map under the click
    pose = drive.pairs[5].pose
    canvas.setExtent(QgsRectangle(pose.easting - 30, pose.northing - 20, pose.easting + 30, pose.northing + 20))
    QApplication.processEvents()
    dock.buttons["pick"].click()
    assert canvas.mapTool() is controller.pick_tool
    pixel = canvas.getCoordinateTransform().transform(pose.easting, pose.northing)
    QTest.mouseClick(canvas.viewport(), Qt.LeftButton, Qt.NoModifier, QPoint(round(pixel.x()), round(pixel.y())))
    wait(lambda: dock.index == 5)
    assert dock.pair_id == drive.pairs[5].id
    dock.buttons["pick"].click()  # off again: the map tool is handed back
    assert canvas.mapTool() is not controller.pick_tool and not dock.buttons["pick"].isChecked()


def test_a_sign_added_while_a_frame_is_shown_is_drawn_at_once(viewer):
    """Add missed sign writes into the signs layer; the viewer shows it without stepping (it once kept saying
    '1 mapped sign in view')."""
    from qgis.core import QgsFeature, QgsGeometry, QgsPoint

    controller, dock, layers, _ = viewer
    controller.go_to(7)
    wait(lambda: dock.index == 7)
    before = [b.key for b in dock.view.boxes() if b.key.startswith("signs:")]
    assert before and f"{len(before)} mapped sign" in dock.caption.text()
    signs = layers["signs"]
    shown = signs.getFeature(int(before[0].split(":")[1]))
    p = shown.geometry().constGet()
    added = QgsFeature(shown)
    added.setAttribute("fid", None)  # a new row
    added.setGeometry(QgsGeometry(QgsPoint(p.x(), p.y(), p.z() + 1.0)))  # a second sign on its pole
    signs.startEditing()
    assert signs.addFeature(added)
    assert signs.commitChanges()
    QApplication.processEvents()
    after = [b.key for b in dock.view.boxes() if b.key.startswith("signs:")]
    assert dock.index == 7 and len(after) == len(before) + 1
    assert f"{len(after)} mapped signs in view" in dock.caption.text()


def test_a_signs_photo_and_the_action_that_opens_the_viewer_at_it(sign_mapper, qgis_iface, mapped, drive_dir):
    """Crops are written by default; the layer as opened from its file shows each sign's photo (form, map tip)
    and its action 'Open in the drive viewer' opens the viewer at the sign's best pair, the sign selected."""
    import qgis.utils
    from plugin_iface import RecordingIface
    from qgis.core import QgsExpression

    layer = QgsVectorLayer(f"{mapped}|layername=signs", "signs", "ogr")  # the embedded default style
    QgsProject.instance().addMapLayer(layer)
    feature = max(layer.getFeatures(), key=lambda f: int(f["best_pair_id"]))
    context = layer.createExpressionContext()
    context.setFeature(feature)
    crop = mapped.parent / feature["crop_path"]
    assert crop.is_file() and crop.parent.name == f"{mapped.stem}_crops"
    # the form's image widget finds the crop from the GeoPackage's folder
    setup = layer.editorWidgetSetup(layer.fields().indexOf("crop_path"))
    root = setup.config()["PropertyCollection"]["properties"]["propertyRootPath"]["expression"]
    assert setup.type() == "ExternalResource" and setup.config()["DocumentViewer"] == 1
    assert Path(QgsExpression(root).evaluate(context)) / feature["crop_path"] == crop
    tip = QgsExpression.replaceExpressionText(layer.mapTipTemplate(), context)
    assert f'src="file://{crop}"' in tip and feature["template_id"] in tip
    actions = {a.name(): a for a in layer.actions().actions()}
    assert {"Open in the drive viewer", "Show the image crop"} <= set(actions)

    plugin = sign_mapper.classFactory(RecordingIface(qgis_iface))
    plugin.initGui()
    qgis.utils.plugins["sign_mapper_under_test"] = plugin
    try:
        code = QgsExpression.replaceExpressionText(actions["Open in the drive viewer"].command(), context)
        exec(compile(code, "action", "exec"), {})  # what QGIS runs when the action is clicked
        dock = plugin.viewer_ui.dock
        assert dock is not None and plugin.viewer_ui.action.isChecked()
        wait(lambda: dock.pair_id == feature["best_pair_id"])
        assert layer.selectedFeatureIds() == [feature.id()]
        assert f"signs:{feature.id()}" in [b.key for b in dock.view.boxes()]
    finally:
        del qgis.utils.plugins["sign_mapper_under_test"]
        plugin.unload()
        # as the viewer fixture: no map render may still read the layer removed below
        canvas = qgis_iface.mapCanvas()
        canvas.setLayers([])
        canvas.waitWhileRendering()
        assert QThreadPool.globalInstance().waitForDone(60000), "map renders still running after 60 s"
        QApplication.processEvents()
        QgsProject.instance().removeMapLayer(layer)
        QApplication.processEvents()
