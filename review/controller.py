"""The review controller: follows QGIS's current layer and selection, fills the dock, writes decisions.

It is the only piece that touches layers, the drive and the core; the dock only
emits requests. Images are decoded and ``detect_in_window`` runs in a small
thread pool so the GUI never blocks on them.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import List, Optional, Tuple

from qgis.core import NULL, QgsCoordinateTransform, QgsFeatureRequest, QgsProject, QgsRectangle
from qgis.PyQt.QtCore import QObject
from qgis.PyQt.sip import isdeleted

from ..algorithms.gpkg_output import read_run_table
from ..algorithms.sign_fields import feature_values
from ..signmapper_core.output_schema import REVIEW
from ..ui.review_item import Observation, ReviewItem
from ..ui.template_picker import TemplateChoice
from .background import BackgroundRunner
from .decisions import DecisionLog, EditError, add_feature, change_attributes
from .drive_locator import DriveLocator
from .imaging import bgr_to_qimage, crop_rect, thumbnail
from .layers import detections_layer_for, features_where, gpkg_source, layer_kind
from .values import accept_values, manual_feature, reclassify_values, reject_values

ZOOM_HALF_SIZE_M = 20.0


def _value(feature, name):
    """An attribute as plain Python, None for NULL or a missing field."""
    if feature.fields().indexOf(name) < 0:
        return None
    value = feature[name]
    return None if value == NULL or value is None else value


class ReviewController(QObject):
    """Connects the review dock to the current Sign Mapper layer, its drive and the catalogue."""

    def __init__(self, iface, dock, ask_drive_folder=None, settings=None, parent=None):
        super().__init__(parent)
        self.iface, self.dock = iface, dock
        self.locator = DriveLocator(ask_drive_folder, settings)
        self.background = BackgroundRunner(self)
        self.log = DecisionLog()
        self.layer = None
        self.kind: Optional[str] = None
        self.fid: Optional[int] = None
        self.run: dict = {}
        self.drive = None
        self._catalogues = {}
        self._catalogue_key = None
        self._jobs = {}  # purpose -> token of the job whose result is still wanted
        self._observations: List[Tuple[str, Tuple[int, int, int, int]]] = []
        self._active = False
        self._dock_connections = [
            (dock.acceptRequested, self.accept), (dock.rejectRequested, self.reject),
            (dock.reclassifyRequested, self.reclassify), (dock.nextRequested, self.next),
            (dock.previousRequested, self.previous), (dock.nextReviewRequested, self.next_review),
            (dock.zoomRequested, self.zoom_to_feature), (dock.addSignClicked, self.add_sign),
            (dock.undoRequested, self.undo_last), (dock.pairRequested, self.show_pair),
            (dock.observationRequested, self.show_observation),
        ]
        for signal, slot in self._dock_connections:
            signal.connect(slot)

    # life cycle --------------------------------------------------------------------------------------
    def activate(self) -> None:
        """Start following the current layer (the dock became visible)."""
        if self._active:
            return
        self._active = True
        self.iface.currentLayerChanged.connect(self.set_layer)
        self.set_layer(self.iface.activeLayer())

    def deactivate(self) -> None:
        if not self._active:
            return
        self._active = False
        self.iface.currentLayerChanged.disconnect(self.set_layer)
        self._unfollow_layer()

    def shutdown(self) -> None:
        """Disconnect everything and wait for running jobs (plugin unload)."""
        self.deactivate()
        for signal, slot in self._dock_connections:
            signal.disconnect(slot)
        self._dock_connections = []
        self.background.shutdown()

    def busy(self) -> bool:
        return self.background.busy()

    # layer and selection -------------------------------------------------------------------------------
    def set_layer(self, layer) -> None:
        """Follow ``layer`` if it is a Sign Mapper layer, else show why there is nothing to review."""
        self._unfollow_layer()
        kind = layer_kind(layer)
        if kind is None:
            self.dock.show_empty("Select a feature of a Sign Mapper 'signs' or 'detections' layer")
            self.dock.set_pairs([])
            return
        self.layer, self.kind = layer, kind
        layer.selectionChanged.connect(self._selection_changed)
        layer.willBeDeleted.connect(self._layer_deleted)
        self.run = read_run_table(gpkg_source(layer)[0])
        self._load_catalogue()
        self._open_drive()
        self.show_selection()

    def _unfollow_layer(self) -> None:
        for job in list(self._jobs):
            self.background.forget(self._jobs.pop(job))
        if self.layer is not None and not isdeleted(self.layer):
            self.layer.selectionChanged.disconnect(self._selection_changed)
            self.layer.willBeDeleted.disconnect(self._layer_deleted)
        self.layer, self.kind, self.fid, self.drive = None, None, None, None

    def _layer_deleted(self) -> None:
        self.layer = None  # already being destroyed: do not disconnect from it
        self.set_layer(None)

    def _selection_changed(self, *_args) -> None:
        self.show_selection()

    def _open_drive(self) -> None:
        recorded = self.run.get("drive", "")
        try:
            self.drive = self.locator.open(recorded)
        except Exception as exc:  # a broken drive folder: the attributes can still be reviewed
            self.drive = None
            self.dock.show_message(f"Drive {recorded}: {exc}", error=True)
        else:
            if self.drive is None:
                self.dock.show_message(f"Drive folder {recorded or '(not recorded)'} not found: no images, "
                                       "decisions still work.", error=True)
            else:
                self.dock.show_message(f"Drive {self.drive.root} · {len(self.drive.pairs)} pairs")
        self.dock.set_pairs([rec.id for rec in self.drive.pairs] if self.drive else [])

    def _load_catalogue(self) -> None:
        from ..signmapper_core.catalogue import load_catalogue

        folder = self.run.get("catalogue")
        key = folder if folder and (Path(folder) / "catalogue.json").is_file() else None
        if key not in self._catalogues:
            self._catalogues[key] = load_catalogue(key)
        if key != self._catalogue_key or not self.dock.picker.visible_ids():
            self._catalogue_key = key
            self.dock.set_template_choices([
                TemplateChoice(e.id, e.name("de"), e.colour, e.shape, str(self.catalogue.pictogram_path(e.id, "png")))
                for e in self.catalogue
            ])

    @property
    def catalogue(self):
        return self._catalogues.get(self._catalogue_key)

    def show_selection(self) -> None:
        if self.layer is None:
            return
        ids = sorted(self.layer.selectedFeatureIds())
        if not ids:
            self.fid = None
            self.dock.show_empty(f"{self.layer.name()}: select a feature, or press Next / Next to review")
            return
        self.show_feature(self.fid if self.fid in ids else ids[0])

    def show_feature(self, fid: int) -> None:
        feature = self.layer.getFeature(fid)
        if not feature.isValid():
            self.dock.show_empty(f"{self.layer.name()}: feature {fid} no longer exists")
            return
        self.fid = fid
        item = self._item(feature)
        self.dock.show_item(item)
        self._load_image(item)
        if item.observations:
            self._load_thumbnails(item)

    def _item(self, feature) -> ReviewItem:
        get = feature_values(feature, self.kind).get
        order = self._order()
        position = next((i for i, (fid, _) in enumerate(order) if fid == feature.id()), 0) + 1
        to_review = sum(status == REVIEW for _, status in order)
        what = f"sign {get('sign_id')}" if self.kind == "signs" else f"feature {feature.id()}"
        pair_id = get("best_pair_id") if self.kind == "signs" and get("best_pair_id") else get("pair_id")
        bbox = tuple(get(k) for k in ("bbox_x", "bbox_y", "bbox_w", "bbox_h"))
        bbox = tuple(int(c) for c in bbox) if all(c is not None for c in bbox) else None
        centroid = (float(get("u")), float(get("v"))) if get("u") is not None and get("v") is not None else None
        point = feature.geometry().constGet() if feature.hasGeometry() else None
        item = ReviewItem(
            self.kind, feature.id(), f"{self.layer.name()} · {what} · {position} of {len(order)} · "
                                     f"{to_review} to review",
            template_id=get("template_id") or "", name=get("name") or "", colour=get("colour") or "",
            shape=get("shape") or "", format=get("format") or "",
            size_m=(float(get("width_m") or 0.0), float(get("height_m") or 0.0)),
            status=get("status") or "", reviewed=bool(get("reviewed")),
            detection_indicator=get("detection_indicator"), classification_indicator=get("classification_indicator"),
            pair_id=str(pair_id or ""), time=get("time"), depth_m=get("depth_m"), bbox=bbox, centroid=centroid,
            position=(point.x(), point.y(), point.z()) if point is not None else None,
        )
        if item.template_id and self.catalogue is not None and item.template_id in self.catalogue:
            item.pictogram_path = str(self.catalogue.pictogram_path(item.template_id, "png"))
        if self.kind == "signs":
            shown = (("n_obs", "observations", "{}"), ("vote_share", "vote share", "{:.2f}"),
                     ("sigma_m", "σ", "{:.2f} m"))
            item.extra = [(label, fmt.format(get(key))) for key, label, fmt in shown if get(key) is not None]
            item.observations = self._observations_of(get("sign_id"))
        if bbox is not None and self.drive is not None:
            item.crop = crop_rect(bbox, self.drive.image_size)
        return item

    def _observations_of(self, sign_id) -> List[Observation]:
        self._observations = []
        detections = detections_layer_for(self.layer) if sign_id is not None else None
        if detections is None:
            return []
        found = sorted(features_where(detections, "sign_id", sign_id), key=lambda f: (_value(f, "time") or 0, f.id()))
        observations = []
        for f in found:
            bbox = tuple(int(_value(f, k) or 0) for k in ("bbox_x", "bbox_y", "bbox_w", "bbox_h"))
            self._observations.append((str(_value(f, "pair_id")), bbox))
            score = _value(f, "classification_indicator")
            label = f"{_value(f, 'pair_id')}\n{score:.2f}" if score is not None else str(_value(f, "pair_id"))
            observations.append(Observation(str(_value(f, "pair_id")), label, None, _value(f, "template_id") or ""))
        return observations

    # images (worker threads) ------------------------------------------------------------------------
    def _record(self, pair_id: str):
        if self.drive is None or not pair_id:
            return None
        try:
            return self.drive.pair(pair_id)
        except KeyError:
            self.dock.show_message(f"Pair {pair_id} is not in drive {self.drive.root}", error=True)
            return None

    def _submit(self, purpose: str, work, on_done) -> None:
        self.background.forget(self._jobs.pop(purpose, None))

        def done(result):
            self._jobs.pop(purpose, None)
            on_done(result)

        def failed(message):
            self._jobs.pop(purpose, None)
            self.dock.show_message(message.splitlines()[0], error=True)

        self._jobs[purpose] = self.background.submit(work, done, failed)

    def _load_image(self, item: ReviewItem) -> None:
        record = self._record(item.pair_id)
        if record is None:
            self.dock.image_view.clear_image()
            return
        drive, fid = self.drive, item.fid

        def shown(image):
            if self.fid == fid and self.dock.item is item:
                item.image = image
                self.dock.set_image(item.pair_id, image, item.crop, item.bbox, item.centroid)

        self._submit("image", lambda: bgr_to_qimage(drive.load_left(record)), shown)

    def _load_thumbnails(self, item: ReviewItem) -> None:
        drive, wanted = self.drive, list(self._observations)
        if drive is None:
            return
        records = {}
        for pair_id, _ in wanted:
            try:
                records[pair_id] = drive.pair(pair_id)
            except KeyError:
                pass

        def work():
            images, thumbs = {}, []
            for pair_id, bbox in wanted:
                if pair_id not in records:
                    thumbs.append(None)
                    continue
                if pair_id not in images:
                    images[pair_id] = drive.load_left(records[pair_id])
                thumbs.append(thumbnail(images[pair_id], bbox))
            return thumbs

        def shown(thumbs):
            if self.dock.item is item:
                for obs, thumb in zip(item.observations, thumbs):
                    obs.thumbnail = thumb
                self.dock.set_observations(item.observations)

        self._submit("thumbnails", work, shown)

    def show_observation(self, index: int) -> None:
        """Show one observation of the fused sign in the image view (the attributes stay the sign's)."""
        if not 0 <= index < len(self._observations):
            return
        pair_id, bbox = self._observations[index]
        record = self._record(pair_id)
        if record is None:
            return
        drive = self.drive
        crop = crop_rect(bbox, drive.image_size)
        centroid = (bbox[0] + bbox[2] / 2.0 - 0.5, bbox[1] + bbox[3] / 2.0 - 0.5)
        self._submit("image", lambda: bgr_to_qimage(drive.load_left(record)),
                     lambda image: self.dock.set_image(pair_id, image, crop, bbox, centroid))

    def show_pair(self, pair_id: str) -> None:
        """Show a whole pair (no feature), e.g. to add a sign in a pair without detections."""
        record = self._record(pair_id)
        if record is None:
            return
        drive = self.drive
        self._submit("image", lambda: bgr_to_qimage(drive.load_left(record)),
                     lambda image: self.dock.set_image(pair_id, image))

    # navigation ------------------------------------------------------------------------------------------
    def _order(self) -> List[Tuple[int, str]]:
        """(fid, status) of all features in driving order (time, then fid)."""
        if self.layer is None:
            return []
        request = QgsFeatureRequest().setFlags(QgsFeatureRequest.NoGeometry)
        request.setSubsetOfAttributes(["time", "status"], self.layer.fields())
        rows = []
        for f in self.layer.getFeatures(request):
            t = _value(f, "time")
            rows.append((t if t is not None else math.inf, f.id(), _value(f, "status") or ""))
        return [(fid, status) for _, fid, status in sorted(rows)]

    def select(self, fid: int) -> None:
        self.layer.selectByIds([fid])
        if self.fid != fid:  # selecting an already selected feature emits nothing
            self.show_feature(fid)

    def _step(self, step: int) -> None:
        order = [fid for fid, _ in self._order()]
        if not order:
            return
        if self.fid in order:
            target = order[(order.index(self.fid) + step) % len(order)]
        else:
            target = order[0] if step > 0 else order[-1]
        self.select(target)

    def next(self) -> None:
        self._step(1)

    def previous(self) -> None:
        self._step(-1)

    def next_review(self) -> bool:
        """Select the next feature (in driving order, wrapping) with status 'review'; False if there is none."""
        if self.layer is None:
            return False
        order = self._order()
        start = next((i for i, (fid, _) in enumerate(order) if fid == self.fid), -1)
        for k in range(1, len(order) + 1):
            fid, status = order[(start + k) % len(order)]
            if status == REVIEW and fid != self.fid:
                self.select(fid)
                return True
        self.dock.show_message(f"{self.layer.name()}: no other feature needs review")
        return False

    def zoom_to_feature(self) -> None:
        if self.layer is None or self.fid is None:
            return
        feature = self.layer.getFeature(self.fid)
        if not feature.hasGeometry():
            return
        point = feature.geometry().asPoint()
        d = ZOOM_HALF_SIZE_M
        extent = QgsRectangle(point.x() - d, point.y() - d, point.x() + d, point.y() + d)
        canvas = self.iface.mapCanvas()
        target = canvas.mapSettings().destinationCrs()
        if target.isValid() and target != self.layer.crs():
            transform = QgsCoordinateTransform(self.layer.crs(), target, QgsProject.instance())
            extent = transform.transformBoundingBox(extent)
        canvas.setExtent(extent)
        canvas.refresh()
        canvas.flashFeatureIds(self.layer, [self.fid])

    # decisions ----------------------------------------------------------------------------------------
    def _decide(self, values: dict, what: str) -> None:
        """Write ``values`` to the shown feature; ``what`` describes the decision, "{fid}" is the feature id."""
        if self.layer is None or self.fid is None:
            return
        fid = self.fid
        label = what.format(fid=fid)
        try:
            decision = change_attributes(self.layer, fid, values, f"Sign Mapper: {label}")
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        self._after_decision(decision)
        saved = "saved" if decision.committed else "in your edit session, not saved yet"
        self.dock.show_message(f"{label[0].upper()}{label[1:]} ({saved})")
        if not (self.dock.advance_after_decision() and self.next_review()):
            self.show_feature(fid)

    def _after_decision(self, decision) -> None:
        self.log.push(decision)
        self.dock.set_undo_enabled(True, decision.label)
        self.layer.triggerRepaint()

    def accept(self) -> None:
        self._decide(accept_values(), "accept feature {fid}")

    def reject(self) -> None:
        self._decide(reject_values(), "reject feature {fid}")

    def reclassify(self, template_id: str) -> None:
        if self.layer is None or self.fid is None or self.catalogue is None:
            return
        if template_id not in self.catalogue:
            self.dock.show_message(f"Template {template_id} is not in the catalogue", error=True)
            return
        feature = self.layer.getFeature(self.fid)
        values = reclassify_values(self.kind, self.catalogue[template_id], _value(feature, "format"),
                                   _value(feature, "status") or "")
        self.dock.show_picker(False)
        self._decide(values, "reclassify feature {fid} as " + template_id)

    def undo_last(self) -> None:
        try:
            decision = self.log.undo()
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        last = self.log.last()
        self.dock.set_undo_enabled(last is not None, last.label if last else "")
        if decision is None:
            return
        self.dock.show_message(f"Undone: {decision.label}")
        decision.layer.triggerRepaint()
        if decision.layer is not self.layer:
            return
        if decision.added:
            self.layer.removeSelection()
            self.fid = None
            self.show_selection()
        else:
            self.select(decision.fid)
            self.show_feature(decision.fid)

    # a missed sign --------------------------------------------------------------------------------------
    def pipeline_config(self):
        """The run's recorded pipeline settings (defaults for anything missing or invalid)."""
        from ..signmapper_core.pipeline import PipelineConfig

        keys = ("near_m", "far_m", "detection_threshold", "classification_threshold")
        kwargs = {k: float(self.run[k]) for k in keys if isinstance(self.run.get(k), (int, float))}
        for key in ("colours", "exclude"):
            if isinstance(self.run.get(key), list):
                kwargs[key] = tuple(self.run[key])
        try:
            return PipelineConfig(**kwargs)
        except (TypeError, ValueError):
            return PipelineConfig()

    def add_sign(self, pair_id: str, u: float, v: float) -> None:
        """Run the detection steps in a window around a click on the sign's centre; add what they find."""
        record = self._record(pair_id)
        if self.layer is None or record is None or self.catalogue is None:
            self.dock.show_message("Adding a sign needs a Sign Mapper layer and its drive's images", error=True)
            return
        from ..signmapper_core.mapping import detect_at

        drive, catalogue, config, layer = self.drive, self.catalogue, self.pipeline_config(), self.layer

        def found(observation):
            if isdeleted(layer) or layer is not self.layer:
                return
            if observation is None:
                self.dock.show_message(f"No sign found around ({u:.0f}, {v:.0f}) in pair {pair_id}: click the "
                                       "centre of a sign face inside the search range", error=True)
                return
            self._add_observation(observation)

        self.dock.show_message(f"Looking for a sign around ({u:.0f}, {v:.0f}) in pair {pair_id}…")
        self._submit("add", lambda: detect_at(drive, record, catalogue, config, u, v), found)

    def _add_observation(self, observation) -> None:
        from ..signmapper_core.mapping import manual_sign

        item = observation
        if self.kind == "signs":
            ids = [_value(f, "sign_id") for f in self.layer.getFeatures()]
            item = manual_sign(observation, max([i for i in ids if i is not None], default=0) + 1)
        feature = manual_feature(self.layer, self.kind, item)
        label = f"Sign Mapper: add {observation.template_id} in pair {observation.pair_id}"
        try:
            decision = add_feature(self.layer, feature, label)
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        self._after_decision(decision)
        self.dock.show_message(f"Added {observation.template_id} {observation.name} at {observation.depth_m:.1f} m "
                               f"(pair {observation.pair_id})")
        self.select(decision.fid)
