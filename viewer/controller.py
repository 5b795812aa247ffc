"""The drive viewer's controller: follows the current Sign Mapper layer, steps through its drive, syncs the map.

The dock is reached only through its signals and slots. Frames are decoded in
worker threads (``frames``); playing advances only to frames already decoded,
so it never stalls the GUI. Clicking a box selects its feature (and makes its
layer current, so the review dock shows it); *Add missed sign* is handed to
the review (``add_sign`` callback).
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, Optional

from qgis.core import QgsCoordinateReferenceSystem, QgsCoordinateTransform, QgsPointXY, QgsProject, QgsVectorLayer
from qgis.PyQt.QtCore import QTimer
from qgis.PyQt.sip import isdeleted

from ..gpkg.fields import feature_values
from ..gpkg.output import read_run_table
from ..review.background import BackgroundRunner
from ..review.dock_controller import DockController
from ..review.drive_locator import DriveLocator
from ..review.layers import gpkg_layer, gpkg_source, layer_kind
from ..signmapper_core.drive.viewing import best_pair_for, nearest_pair
from ..signmapper_core.output.schema import DETECTIONS, SIGNS
from ..signmapper_core.pipeline.config import DepthConfig
from .frames import PREFETCH, FrameCache
from .map_items import PairPickTool, VehicleOnMap
from .overlays import detection_boxes, parse_key, sign_boxes

PLAY_INTERVAL_MS = 100  # 10 frames/s, twice the 5 pairs/s a vehicle records
PICK_TOLERANCE_PX = 8  # a click this close to a trajectory point opens that pair
# a layer's features changed: an edit in its buffer, or a commit (review decisions repaint the layer)
CHANGED_SIGNALS = ("layerModified", "repaintRequested")


class DriveViewerController(DockController):
    def __init__(self, iface, dock, ask_drive_folder=None, settings=None,
                 add_sign: Optional[Callable[[QgsVectorLayer, str, float, float], None]] = None, parent=None):
        super().__init__(iface, dock, parent)
        self.add_sign_callback = add_sign
        self.locator = DriveLocator(ask_drive_folder, settings)
        self.runner = BackgroundRunner(self)
        self.drive = None
        self.run: dict = {}
        self.gpkg = ""
        self.layers = {}  # kind -> QgsVectorLayer (the project's, else a private one)
        self.frames: Optional[FrameCache] = None
        self.index = -1
        self.wanted = -1  # the frame asked for last (shown when decoded)
        self.vehicle = VehicleOnMap(iface.mapCanvas())
        self.pick_tool = PairPickTool(iface.mapCanvas())
        self.pick_tool.picked.connect(self.open_at)
        self.pick_tool.deactivated.connect(lambda: self.dock.set_picking_on_map(False))
        self.timer = QTimer(self)
        self.timer.setInterval(PLAY_INTERVAL_MS)
        self.timer.timeout.connect(self._tick)
        self.connect_dock([
            (dock.frameRequested, self.go_to), (dock.playToggled, self.play), (dock.boxClicked, self.select_box),
            (dock.addSignClicked, self.add_sign), (dock.pickOnMapToggled, self.pick_on_map),
        ])

    # life cycle --------------------------------------------------------------------------------------
    def stop_following(self) -> None:
        """A hidden viewer stops playing and picking; the vehicle leaves the map."""
        self.play(False)
        self.pick_on_map(False)
        self.vehicle.hide()

    def release(self) -> None:
        self._watch({})
        if self.frames is not None:
            self.frames.clear()
        self.runner.shutdown()
        self.vehicle.remove()

    def busy(self) -> bool:
        return self.runner.busy()

    # which run ---------------------------------------------------------------------------------------
    def set_layer(self, layer) -> None:
        """Adopt the run of a Sign Mapper layer; any other layer leaves the viewer on its run."""
        kind = layer_kind(layer)
        if kind is None:
            return
        path = gpkg_source(layer)[0]
        if path and path == self.gpkg and self.drive is not None:
            self._watch({**self.layers, kind: layer})
            return
        self.gpkg = path
        self.run = read_run_table(path) if path else {}
        layers = {kind: layer}
        other = DETECTIONS if kind == SIGNS else SIGNS
        found = gpkg_layer(path, other)
        if found is not None:
            layers[other] = found
        self._watch(layers)
        self._open_drive(self.run.get("drive", ""))

    def _watch(self, layers: dict) -> None:
        """Show ``layers``; a change to them (a sign added, a decision) redraws the frame shown."""
        for layer in self.layers.values():
            if not isdeleted(layer):
                for signal in CHANGED_SIGNALS:
                    getattr(layer, signal).disconnect(self.redraw)
        self.layers = layers
        for layer in layers.values():
            for signal in CHANGED_SIGNALS:
                getattr(layer, signal).connect(self.redraw)

    def redraw(self) -> None:
        """The shown frame again with the layers as they are now (its image is in the cache)."""
        if self.drive is not None and self.index >= 0 and self.wanted == self.index:
            self.frames.get(self.index, lambda image, i=self.index: self._show(i, image))

    def _open_drive(self, recorded: str) -> None:
        self.play(False)
        if self.frames is not None:
            self.frames.clear()
        self.frames, self.drive, self.index, self.wanted = None, None, -1, -1
        try:
            drive = self.locator.open(recorded)
        except Exception as exc:  # noqa: BLE001 - a broken drive: say so, keep QGIS running
            self.dock.set_frames([])
            self.dock.show_message(f"Drive {recorded}: {exc}", error=True)
            return
        if drive is None:
            self.dock.set_frames([])
            self.dock.show_message(f"Drive folder {recorded or '(not recorded)'} not found", error=True)
            return
        self.drive = drive
        self.frames = FrameCache(self.runner, drive, self._frame_failed)
        self.dock.set_frames([r.id for r in drive.pairs])
        self.go_to(0)

    # stepping ----------------------------------------------------------------------------------------
    def go_to(self, index: int) -> None:
        if self.drive is None or not 0 <= index < len(self.drive.pairs):
            return
        self.wanted = index
        self.frames.forget_waiting()
        self.frames.get(index, lambda image, i=index: self._show(i, image))
        step = 1 if index >= self.index else -1
        self.frames.prefetch(index + step * k for k in range(1, PREFETCH + 1))

    def show_feature(self, layer, fid: int) -> None:
        """Select a feature of ``layer`` and open the pair it was seen best in (a sign) or detected in."""
        kind = layer_kind(layer)
        feature = layer.getFeature(fid) if kind in (SIGNS, DETECTIONS) else None
        if feature is None or not feature.isValid():
            self.dock.show_message(f"{layer.name()}: no Sign Mapper feature {fid}", error=True)
            return
        values = feature_values(feature, kind)
        layer.selectByIds([fid])
        self.show_pair(layer, values["best_pair_id"] if kind == SIGNS else values["pair_id"])

    def show_pair(self, layer, pair_id: str) -> None:
        """Open ``pair_id`` of ``layer``'s drive (the review's Follow); a pair the drive lacks is said."""
        self.set_layer(layer)
        if self.drive is None:
            return
        try:
            index = self.drive.pair(pair_id).index
        except KeyError:
            self.dock.show_message(f"Pair {pair_id} is not in drive {self.drive.root}", error=True)
            return
        if index != self.wanted:
            self.go_to(index)

    def step(self, delta: int) -> None:
        self.go_to(max(0, min(len(self.drive.pairs) - 1, (self.wanted if self.wanted >= 0 else 0) + delta)))

    def _show(self, index: int, image) -> None:
        if index != self.wanted or self.drive is None:
            return
        self.index = index
        record = self.drive.pairs[index]
        boxes = self.boxes(record)
        self.dock.show_frame(index, record.id, image, boxes, self.caption(record, boxes))
        self.vehicle.show(self.drive.camera, record.pose, float(self.run.get("far_m") or DepthConfig.far_m),
                          self.drive.crs, follow=self.dock.follow())

    def boxes(self, record):
        out = []
        signs, detections = self.layers.get(SIGNS), self.layers.get(DETECTIONS)
        if detections is not None and not isdeleted(detections):
            out += detection_boxes(detections, record)
        if signs is not None and not isdeleted(signs):
            out += sign_boxes(signs, self.drive.camera, record)
        return out

    def caption(self, record, boxes) -> str:
        n_signs = sum(b.key.startswith(SIGNS) for b in boxes)
        n_det = len(boxes) - n_signs
        return (f"Pair {record.id} · {record.index + 1} of {len(self.drive.pairs)} · t = {record.time:.2f} s · "
                f"{n_signs} mapped sign{'' if n_signs == 1 else 's'} in view, "
                f"{n_det} detection{'' if n_det == 1 else 's'} · {Path(self.drive.root).name}")

    def _frame_failed(self, index: int, message: str) -> None:
        self.dock.show_message(f"Pair {self.drive.pairs[index].id}: {message}", error=True)
        if self.timer.isActive():
            self.play(False)

    def play(self, playing: bool) -> None:
        if playing and self.drive is not None:
            self.timer.start()
        else:
            self.timer.stop()
        self.dock.set_playing(playing and self.drive is not None)

    def _tick(self) -> None:
        nxt = self.index + 1
        if self.drive is None or nxt >= len(self.drive.pairs):
            self.play(False)
            return
        if self.wanted == self.index:
            self.go_to(nxt)  # shown as soon as decoded; a tick while it is not yet shown waits


    # clicks ------------------------------------------------------------------------------------------
    def select_box(self, key: str) -> None:
        kind, fid = parse_key(key)
        layer = self.layers.get(kind)
        if layer is None or isdeleted(layer):
            return
        layer.selectByIds([fid])
        if QgsProject.instance().mapLayer(layer.id()) is not None:
            self.iface.setActiveLayer(layer)  # the review dock follows the current layer
            self.iface.mapCanvas().flashFeatureIds(layer, [fid])
        self.dock.show_message(f"Selected {kind} feature {fid}")

    def add_sign(self, pair_id: str, u: float, v: float) -> None:
        layer = self.layers.get(SIGNS) or self.layers.get(DETECTIONS)
        if self.add_sign_callback is None or layer is None:
            self.dock.show_message("Adding a sign needs the review (Sign Mapper ▸ Review signs)", error=True)
            return
        self.add_sign_callback(layer, pair_id, u, v)

    def pick_on_map(self, picking: bool) -> None:
        canvas = self.iface.mapCanvas()
        if picking:
            canvas.setMapTool(self.pick_tool)
        elif canvas.mapTool() is self.pick_tool:
            canvas.unsetMapTool(self.pick_tool)
        self.dock.set_picking_on_map(picking)

    def open_at(self, x: float, y: float, units_per_pixel: float) -> Optional[int]:
        """Open the pair at a clicked trajectory point, else the pair that sees the clicked place best."""
        if self.drive is None:
            return None
        crs = QgsCoordinateReferenceSystem(self.drive.crs)
        source = self.iface.mapCanvas().mapSettings().destinationCrs()
        point = QgsPointXY(x, y)
        tolerance = PICK_TOLERANCE_PX * units_per_pixel
        if source.isValid() and source != crs:
            transform = QgsCoordinateTransform(source, crs, QgsProject.instance())
            point, aside = transform.transform(point), transform.transform(QgsPointXY(x + tolerance, y))
            tolerance = point.distance(aside)  # the same screen distance in the drive's metres
        index, distance = nearest_pair(self.drive.pairs, point.x(), point.y())
        if distance > tolerance:
            near = float(self.run.get("near_m") or DepthConfig.near_m)
            far = float(self.run.get("far_m") or DepthConfig.far_m)
            index = best_pair_for(self.drive.camera, self.drive.pairs, point.x(), point.y(), None, near, far)
            if index is None:
                self.dock.show_message(f"No pair sees ({point.x():.1f}, {point.y():.1f}) within {near:g}–{far:g} m",
                                       error=True)
                return None
        self.go_to(index)
        return index
