"""Real-display check of the plugin in QGIS desktop: run it inside QGIS (``qgis --code``), as ``make screenshots`` does.

What a surveyor does first, driven step by step with timers so QGIS keeps
painting between the steps:
  1. open *Map traffic signs* from the Processing dialog on a drive and press Run;
  2. once Processing has loaded the layers, check they are styled (rule-based
     pictograms, aliases) and take a screenshot of the main window;
  3. open the drive viewer on a pair that sees signs, with the vehicle on the map;
  4. open the review dock on a sign; screenshots after each step;
  5. write the findings to SIGNMAPPER_CHECK_REPORT (JSON) and quit QGIS; ``ok`` only when the layers came out
     styled, the viewer drew mapped signs over its image with the vehicle inside the map's extent, and the
     review showed the sign with its image.

Environment: SIGNMAPPER_CHECK_DRIVE (drive folder), SIGNMAPPER_CHECK_OUT (folder
for screenshots and the report), SIGNMAPPER_CHECK_GPKG (output GeoPackage).
"""

from __future__ import annotations

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
TIMEOUT_S = 600

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
    dialog = processing.createAlgorithmDialog("signmapper:mapsigns", {"DRIVE": DRIVE, "OUTPUT": GPKG})
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
    review = plugin().review_ui
    review.action.setChecked(True)
    iface.mainWindow().resizeDocks([review.dock], [470], 1)  # 1 = Qt.Horizontal
    later(1500, step_review)


def step_review():
    """Select the sign the viewer shows (a click on its box), then accept it with the dock's button."""
    signs = state["signs"]
    dock = plugin().viewer_ui.dock
    keys = [b.key for b in dock.view.boxes() if b.key.startswith("signs:")]
    fid = int(keys[0].split(":")[1]) if keys else next(signs.getFeatures()).id()
    plugin().viewer_ui.controller.select_box(f"signs:{fid}")
    state["sign"] = fid
    later(3000, step_accept)


def step_accept():
    review = plugin().review_ui.dock
    review.advance_box.setChecked(False)
    log("review-before", shown=review.item.template_id if review.item else None, progress=review.progress.text())
    review.buttons["accept"].click()
    later(2500, step_review_shot)


def step_review_shot():
    dock = plugin().review_ui.dock
    item = dock.item
    log("review", screenshot=shot("desktop-review.png"), feature=state["sign"],
        shown=item.template_id if item is not None else None,
        image=dock.image_view.has_image(), progress=dock.progress.text())
    ok = state["facts"]["styled"] and state["viewer_ok"] and item is not None and dock.image_view.has_image()
    finish(ok)


later(3000, step_dialog)
