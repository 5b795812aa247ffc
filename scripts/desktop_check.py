"""Real-display check of the plugin in QGIS desktop: run it inside QGIS (``qgis --code``), as ``make screenshots`` does.

A surveyor's day, driven step by step with timers so QGIS keeps painting
between the steps:
  1. open *Map traffic signs* from the Processing dialog on a drive and press Run (every sign left for
     review: classification threshold 1);
  2. once Processing has loaded the layers, check they are styled (status classes and pictograms, aliases)
     and take a screenshot of the main window;
  3. open the drive viewer on a pair that sees signs, with the vehicle on the map;
  4. review with the keys only, Follow on: Space to the first sign, then Accept (A) each sign, one
     reclassified by key (C, /, its id typed, Enter; or C 1 where it has next choices), one rejected (R);
     at every step the sign must be on the map and the viewer on its best pair; a screenshot with the
     picker open;
  5. export the inventory (CSV) and print the inventory atlas (PDF, its layout added to the project); the
     atlas's first sheet as a picture;
  6. write the findings to SIGNMAPPER_CHECK_REPORT (JSON) and quit QGIS; ``ok`` only when every step held.

Environment: SIGNMAPPER_CHECK_DRIVE (drive folder), SIGNMAPPER_CHECK_OUT (folder
for screenshots and the report), SIGNMAPPER_CHECK_GPKG (output GeoPackage).
"""

from __future__ import annotations

# Run as a file, not as a module like the other scripts: QGIS desktop executes it in its own Python
# (``qgis --code``), with the plugin already loaded from QGIS_PLUGINPATH and reached through ``qgis.utils.plugins``
# and Processing. So it imports nothing of this repository by name and needs no path set-up; ``python -m
# scripts.desktop_check`` would fail, it needs the running desktop's ``iface``.
import json
import os
import traceback
from pathlib import Path

from qgis.core import QgsProject
from qgis.PyQt.QtCore import QTimer
from qgis.PyQt.QtWidgets import QApplication
from qgis.utils import iface, plugins

DRIVE = os.environ["SIGNMAPPER_CHECK_DRIVE"]
OUT = Path(os.environ.get("SIGNMAPPER_CHECK_OUT", "docs"))
GPKG = os.environ.get("SIGNMAPPER_CHECK_GPKG", str(OUT / "desktop-check.gpkg"))
REPORT = Path(os.environ.get("SIGNMAPPER_CHECK_REPORT", str(Path(GPKG).with_suffix(".json"))))
TIMEOUT_S = 1200  # mapping the demo drive from the dialog: 9 min with both cores busy (2026-12-06)

report = {"drive": DRIVE, "steps": [], "ok": False}
state = {"waited": 0.0}


def log(step: str, **facts) -> None:
    report["steps"].append({"step": step, **facts})
    REPORT.write_text(json.dumps(report, indent=1), encoding="utf-8")


def shot(name: str, widget=None) -> str:
    QApplication.processEvents()
    path = OUT / name
    (widget or iface.mainWindow()).grab().save(str(path))
    return str(path)


def later(ms: int, step) -> None:
    def run():
        try:
            step()
        except Exception:  # noqa: BLE001 - the report says what failed, then QGIS quits
            log("error", traceback=traceback.format_exc())
            finish(False)
    QTimer.singleShot(ms, run)


def finish(ok: bool) -> None:
    """Quit as a user would (File ▸ Exit) once the project is closed: QGIS tears down in its own order."""
    report["ok"] = ok
    log("done")
    QgsProject.instance().clear()
    QgsProject.instance().setDirty(False)
    QTimer.singleShot(1000, iface.actionExit().trigger)


def plugin():
    return plugins["sign_mapper"]


def step_dialog():
    import processing

    iface.mainWindow().setGeometry(0, 0, 1600, 1000)  # no window manager under Xvfb: maximise by hand
    for name in ("signs", "detections"):
        for layer in QgsProject.instance().mapLayersByName(name):
            QgsProject.instance().removeMapLayer(layer)
    dialog = processing.createAlgorithmDialog("signmapper:mapsigns", {"DRIVE": DRIVE, "OUTPUT": GPKG,
                                                                      "CLASSIFICATION_THRESHOLD": 1.0})
    dialog.show()
    state["dialog"] = dialog
    later(1500, step_run)


def step_run():
    dialog = state["dialog"]
    log("dialog", screenshot=shot("desktop-dialog.png", dialog), title=dialog.windowTitle())
    dialog.runAlgorithm()  # what the Run button does
    later(1000, step_wait_for_layers)


def loaded(kind: str):
    return [layer for layer in QgsProject.instance().mapLayers().values()
            if layer.source().endswith(f"layername={kind}") and Path(layer.source().split("|")[0]) == Path(GPKG)]


def step_wait_for_layers():
    state["waited"] += 1.0
    if not (loaded("signs") and loaded("detections")):
        if state["waited"] > TIMEOUT_S:
            log("layers", error="Processing did not load the layers in time")
            finish(False)
            return
        later(1000, step_wait_for_layers)
        return
    state["dialog"].close()
    signs, detections = loaded("signs")[0], loaded("detections")[0]
    facts = {
        "signs_renderer": signs.renderer().type(),
        "signs_groups": [g.label() for g in signs.renderer().rootRule().children()],
        "crops": sum(1 for f in signs.getFeatures() if f["crop_path"]),
        "signs_labels": signs.labelsEnabled(),
        "detections_renderer": detections.renderer().type(),
        "template_alias": signs.fields().field("template_id").alias(),
        "signs": signs.featureCount(), "detections": detections.featureCount(),
    }
    state["signs"], state["detections"] = signs, detections
    iface.setActiveLayer(signs)
    extent = signs.extent()
    extent.grow(12.0)
    iface.mapCanvas().setExtent(extent)
    iface.mapCanvas().refresh()
    facts["styled"] = facts["signs_renderer"] == "RuleRenderer" and facts["signs_labels"] and \
        facts["detections_renderer"] == "categorizedSymbol"
    state["facts"] = facts
    processing_run_trajectory()
    later(2500, step_result_shot)


def processing_run_trajectory():
    """The drive's trajectory points on the map too: what a click opens in the viewer."""
    import processing

    processing.runAndLoadResults("signmapper:drivetrajectory", {
        "DRIVE": DRIVE, "OUTPUT": str(Path(GPKG).with_name("trajectory.gpkg"))})
    iface.setActiveLayer(state["signs"])


def step_result_shot():
    log("result", screenshot=shot("desktop-result.png"), **state["facts"])
    viewer = plugin().viewer_ui
    viewer.action.setChecked(True)
    iface.mainWindow().resizeDocks([viewer.dock], [520], 2)  # 2 = Qt.Vertical: a taller image
    later(1500, step_viewer)


def step_viewer():
    controller = plugin().viewer_ui.controller
    drive = controller.drive
    if drive is None:
        log("viewer", error="the viewer found no drive")
        finish(False)
        return
    state["fps"] = step_through(controller, plugin().viewer_ui.dock)
    # the pair with most signs and detections in view: what shows the overlay best
    scores = [(len(controller.boxes(record)), record.index) for record in drive.pairs]
    best = max(scores)[1]
    state["pair"] = best
    controller.go_to(best)
    later(2500, step_viewer_shot)


def step_through(controller, dock) -> float:
    """Frames per second stepping through the whole drive on this display, each frame painted before the next."""
    import time

    n = len(controller.drive.pairs)
    start = time.perf_counter()
    for index in range(n):
        controller.go_to(index)
        deadline = time.monotonic() + 30.0
        while dock.index != index and time.monotonic() < deadline:
            QApplication.processEvents()
        dock.view.viewport().repaint()
    return round(n / (time.perf_counter() - start), 1)


def step_viewer_shot():
    controller = plugin().viewer_ui.controller
    dock = plugin().viewer_ui.dock
    boxes = dock.view.boxes()
    vehicle = controller.vehicle.position
    mapped_signs = sum(b.key.startswith("signs:") for b in boxes)
    on_map = vehicle is not None and iface.mapCanvas().extent().contains(vehicle)
    state["viewer_ok"] = mapped_signs > 0 and on_map
    log("viewer", screenshot=shot("desktop-viewer.png"), pair=dock.pair_id, boxes=len(boxes),
        stepping_frames_per_s=state["fps"], mapped_signs=mapped_signs,
        vehicle=[vehicle.x(), vehicle.y()] if vehicle is not None else None, vehicle_on_map=on_map)
    later(1500, step_review)


def press(key, modifier=None):
    """A key press where the keyboard is, as a user's reaches the review dock (the pointer over it)."""
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtTest import QTest

    state["presses"] = state.get("presses", 0) + 1
    target = QApplication.focusWidget() or plugin().review_ui.dock.image_view
    QTest.keyClick(target, key, modifier or Qt.NoModifier)
    QApplication.processEvents()


def settle(seconds: float = 1.5) -> None:
    import time

    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        QApplication.processEvents()
        time.sleep(0.02)


def follows(timeout_s: float = 15.0) -> dict:
    """Where the sign under review is: on the map, and in the viewer on its best pair (decoded by then)."""
    import time

    review = plugin().review_ui.controller
    viewer = plugin().viewer_ui.dock
    if review.fid is None:
        return {"sign": None, "on_map": False, "in_viewer": False}
    feature = state["signs"].getFeature(review.fid)
    deadline = time.monotonic() + timeout_s
    while viewer.pair_id != feature["best_pair_id"] and time.monotonic() < deadline:
        settle(0.1)
    on_map = iface.mapCanvas().extent().contains(feature.geometry().asPoint())
    in_viewer = viewer.pair_id == feature["best_pair_id"] and \
        f"signs:{review.fid}" in [b.key for b in viewer.view.boxes()]
    return {"sign": feature["sign_id"], "type": feature["template_id"], "on_map": on_map, "in_viewer": in_viewer}


def step_review():
    """The review dock with Follow on (its default), the keyboard in it as when the pointer is over it."""
    review = plugin().review_ui
    review.action.setChecked(True)
    iface.mainWindow().resizeDocks([review.dock], [470], 1)  # 1 = Qt.Horizontal
    iface.setActiveLayer(state["signs"])
    later(2000, step_walk)


def step_walk():
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtTest import QTest

    dock = plugin().review_ui.dock
    QApplication.setActiveWindow(iface.mainWindow())  # no window manager under Xvfb to activate it
    dock.image_view.setFocus()  # where the pointer over the dock puts it (ui/hover_focus)
    QApplication.processEvents()
    if not dock.isAncestorOf(QApplication.focusWidget()):  # keys would reach QGIS's own shortcuts instead
        log("review", error=f"the keyboard is not in the review dock but in {QApplication.focusWidget()!r}")
        finish(False)
        return
    press(Qt.Key_Space)  # to the first sign needing review
    settle()
    walk, total = [], state["signs"].featureCount()
    for step in range(total):
        facts = follows()
        item = dock.item
        if step == 1:  # reclassified by key: its first next choice, or its own type typed into the search
            press(Qt.Key_C)
            settle(0.5)
            if not state.get("picker_shot"):
                state["picker_shot"] = shot("desktop-review.png")
                facts["picker_in_view"] = dock.picker_box.isVisible() and \
                    dock.scroll.verticalScrollBar().maximum() == 0
            if dock.picker.suggested_ids():
                press(Qt.Key_1)
                facts["decision"] = "C 1"
            else:
                press(Qt.Key_Slash)  # the search (an id starts with a digit)
                for char in item.template_id:
                    QTest.keyClicks(QApplication.focusWidget(), char)
                    state["presses"] += 1
                press(Qt.Key_Return)
                facts["decision"] = f"C / {item.template_id} Enter"
        elif step == total - 1 and total > 2:
            press(Qt.Key_R)
            facts["decision"] = "R"
        else:
            press(Qt.Key_A)
            facts["decision"] = "A"
        walk.append(facts)
        settle()
        if "no other feature needs review" in dock.message.text():
            break
    state["walk"] = walk
    statuses = sorted(f["status"] for f in state["signs"].getFeatures())
    log("review", screenshot=state.get("picker_shot"), walk=walk, key_presses=state["presses"],
        statuses=statuses, progress=dock.progress.text())
    state["review_ok"] = bool(walk) and all(w["on_map"] and w["in_viewer"] for w in walk) and \
        "review" not in statuses and any(w.get("picker_in_view") for w in walk)
    later(500, step_deliverables)


def step_deliverables():
    """The deliverables from the reviewed layer: the inventory as CSV, the atlas as PDF with its layout."""
    import re

    import processing

    signs = state["signs"]
    out = Path(GPKG).parent
    delivered = sum(f["status"] in ("accepted", "manual") for f in signs.getFeatures())
    inventory = processing.run("signmapper:exportinventory", {"SIGNS": signs.id(),
                                                              "OUTPUT": str(out / "inventory.csv")})
    rows = len(Path(inventory["OUTPUT"]).read_text(encoding="utf-8-sig").splitlines()) - 1
    atlas = processing.run("signmapper:inventoryatlas", {"SIGNS": signs.id(), "OUTPUT": str(out / "atlas.pdf")})
    pages = len(re.findall(rb"/Type\s*/Page[^s]", Path(atlas["OUTPUT"]).read_bytes()))
    layout = QgsProject.instance().layoutManager().layoutByName(f"Sign Mapper inventory: {signs.name()}")
    sheet = None
    if layout is not None:
        from qgis.core import QgsLayoutExporter

        layout.atlas().beginRender()
        layout.atlas().first()
        sheet = str(OUT / "desktop-atlas.png")
        QgsLayoutExporter(layout).renderPageToImage(0, dpi=70).save(sheet)
        layout.atlas().endRender()
    log("deliverables", delivered=delivered, inventory=inventory["OUTPUT"], inventory_rows=rows,
        atlas=atlas["OUTPUT"], atlas_pages=pages, layout_in_project=layout is not None, atlas_sheet=sheet)
    state["deliverables_ok"] = delivered > 0 and rows == delivered and pages == delivered and layout is not None
    later(1500, step_final_shot)


def step_final_shot():
    log("final", screenshot=shot("desktop-final.png"))
    ok = state["facts"]["styled"] and state["viewer_ok"] and state.get("review_ok", False) and \
        state.get("deliverables_ok", False)
    finish(ok)


later(3000, step_dialog)
