"""Frames per second of the drive viewer stepping through a Full-HD drive (JPEG left images).

    QT_QPA_PLATFORM=offscreen python -m bench.bench_viewer [--pairs 40] [--seed 2002]

Generates a Full-HD synthetic drive once (cached under build/drives/), maps it
with Map traffic signs (so every frame has its signs and detections drawn over
it), then opens the viewer dock and its controller on a map canvas and times:
  step      the next frame asked for as soon as the previous one is on screen
            (decoding ahead in the background, overlays, vehicle on the map)
  play      the Play button (paced at 10 frames/s; reports the rate reached)
  decode    one JPEG decoded and converted on the calling thread, for scale
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

from scripts.drives import DRIVES, cached_drive
from scripts.qgis_plugin import load_plugin

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")


def drive_folder(pairs: int, seed: int) -> Path:
    from signmapper_core.simulate import SimulationConfig

    return cached_drive(DRIVES / f"viewer-{seed}-{pairs}", SimulationConfig(pairs=pairs, seed=seed, write_depth=True))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=40)
    parser.add_argument("--seed", type=int, default=2002)
    args = parser.parse_args()
    drive_dir = drive_folder(args.pairs, args.seed)

    from qgis.core import QgsApplication, QgsProject, QgsVectorLayer
    from qgis.gui import QgsMapCanvas
    from qgis.PyQt.QtCore import QObject, pyqtSignal
    from qgis.PyQt.QtWidgets import QMainWindow

    app = QgsApplication([], True)
    app.initQgis()
    plugins = Path(tempfile.mkdtemp()) / "plugins"
    plugins.mkdir()
    plugin = load_plugin(plugins)
    import processing
    from sign_mapper.ui.drive_viewer import DriveViewerDock
    from sign_mapper.viewer.controller import DriveViewerController
    from sign_mapper.viewer.frames import bgr_to_rgb32

    gpkg = plugins.parent / "bench.gpkg"
    processing.run("signmapper:mapsigns", {"DRIVE": str(drive_dir), "OUTPUT": str(gpkg)})
    layers = [QgsVectorLayer(f"{gpkg}|layername={n}", n, "ogr") for n in ("signs", "detections")]
    QgsProject.instance().addMapLayers(layers)

    class Iface(QObject):
        currentLayerChanged = pyqtSignal(object)

        def __init__(self):
            super().__init__()
            self.window = QMainWindow()
            self.canvas = QgsMapCanvas(self.window)
            self.window.setCentralWidget(self.canvas)
            self.window.resize(1600, 900)
            self.layer = None

        def mapCanvas(self):  # noqa: N802
            return self.canvas

        def activeLayer(self):  # noqa: N802
            return self.layer

        def setActiveLayer(self, layer):  # noqa: N802
            self.layer = layer
            self.currentLayerChanged.emit(layer)

    iface = Iface()
    iface.canvas.setDestinationCrs(layers[0].crs())
    iface.canvas.setLayers(layers)
    iface.window.show()
    dock = DriveViewerDock(iface.window)
    dock.resize(1100, 700)
    dock.show()
    controller = DriveViewerController(iface, dock)
    iface.layer = layers[0]
    controller.activate()

    def wait_for(index, timeout=30.0):
        deadline = time.monotonic() + timeout
        while dock.index != index and time.monotonic() < deadline:
            app.processEvents()
        app.processEvents()  # paint
        assert dock.index == index

    wait_for(0)
    n = len(controller.drive.pairs)
    boxes = 0
    start = time.perf_counter()
    for i in range(1, n):
        controller.go_to(i)
        wait_for(i)
        dock.view.viewport().repaint()
        boxes += len(dock.view.boxes())
    step = (n - 1) / (time.perf_counter() - start)

    controller.go_to(0)
    wait_for(0)
    start = time.perf_counter()
    dock.buttons["play"].setChecked(True)
    wait_for(n - 1, timeout=120.0)
    play = (n - 1) / (time.perf_counter() - start)

    record = controller.drive.pairs[0]
    start = time.perf_counter()
    for _ in range(10):
        bgr_to_rgb32(controller.drive.load_left(record))
    decode_ms = (time.perf_counter() - start) * 100.0

    print(f"drive {drive_dir.name}: {n} pairs {controller.drive.camera.width}x{controller.drive.camera.height} "
          f"{record.left_path.suffix}, {os.cpu_count()} cores")
    print(f"step  {step:6.1f} frames/s (next frame asked for when the previous is shown, incl. overlays; "
          f"{boxes / (n - 1):.1f} boxes per frame)")
    print(f"play  {play:6.1f} frames/s (paced at 10/s)")
    print(f"decode {decode_ms:5.1f} ms per frame on one thread (JPEG -> QImage)")
    controller.shutdown()
    plugin.unload()
    QgsProject.instance().removeAllMapLayers()
    sys.stdout.flush()
    os._exit(0)  # skip Qt's teardown of a half-wired test application

if __name__ == "__main__":
    main()
