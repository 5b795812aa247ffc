"""The review controller: follows QGIS's current layer and selection and connects the dock to the parts.

The parts: reading features into items (``items``), images (``images``),
navigation (``navigation``) and decisions (``decisions``), all on one
``ReviewSession``. The dock is reached only through its request signals and
its public slots; slow work runs in a small thread pool so the GUI never blocks.
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional

from qgis.PyQt.QtCore import pyqtSignal
from qgis.PyQt.sip import isdeleted

from ..gpkg.output import read_run_table
from ..signmapper_core.catalogue import load_catalogue
from ..signmapper_core.catalogue.names import sign_name
from ..ui.template_picker import TemplateChoice
from .background import BackgroundRunner, Jobs
from .decisions import DecisionTaker
from .dock_controller import DockController
from .drive_locator import DriveLocator
from .images import ImageLoader
from .items import read_item, review_progress
from .layers import gpkg_source, layer_kind
from .navigation import Navigator
from .progress_on_map import ReviewProgressItem
from .session import ReviewSession


class ReviewController(DockController):
    """Connects the review dock to the current Sign Mapper layer, its drive and the catalogue.

    With Follow on, each feature shown brings the map to it and emits ``featureFollowed(layer, pair id)``: the
    drive viewer opens that pair (``viewer.plugin_ui``).
    """

    featureFollowed = pyqtSignal(object, str)  # noqa: N815 - the layer, the best pair of the feature shown

    def __init__(self, iface, dock, ask_drive_folder=None, settings=None, parent=None):
        super().__init__(iface, dock, parent)
        self.locator = DriveLocator(ask_drive_folder, settings)
        self.background = BackgroundRunner(self)
        self.session = ReviewSession(dock.show_message)
        self.jobs = Jobs(self.background, lambda message: dock.show_message(message, error=True))
        self.images = ImageLoader(self.session, dock, self.jobs)
        self.navigator = Navigator(self.session, dock, iface, self.show_feature)
        self.decisions = DecisionTaker(self.session, dock, self.jobs, self.navigator, self.show_feature,
                                       self.show_selection)
        self.map_progress = ReviewProgressItem(iface.mapCanvas()) if iface is not None else None
        self._catalogues = {}  # catalogue folder (None = bundled) -> Catalogue
        self._catalogue_key = None
        d, n = self.decisions, self.navigator
        self.connect_dock([
            (dock.acceptRequested, d.accept), (dock.rejectRequested, d.reject),
            (dock.reclassifyRequested, d.reclassify), (dock.undoRequested, d.undo_last),
            (dock.textEdited, d.set_text),
            (dock.addSignClicked, d.add_sign), (dock.nextRequested, n.next), (dock.previousRequested, n.previous),
            (dock.nextReviewRequested, n.next_review), (dock.zoomRequested, n.zoom_to_feature),
            (dock.pairRequested, self.images.show_pair), (dock.observationRequested, self.images.show_observation),
            (dock.followToggled, self._follow_toggled),
        ])

    # what tests and the plugin read
    @property
    def layer(self):
        return self.session.layer

    @property
    def kind(self) -> Optional[str]:
        return self.session.kind

    @property
    def fid(self) -> Optional[int]:
        return self.session.fid

    @property
    def drive(self):
        return self.session.drive

    # life cycle --------------------------------------------------------------------------------------
    def stop_following(self) -> None:
        self._unfollow_layer()

    def release(self) -> None:
        """Wait for running jobs; the review progress leaves the map."""
        self.background.shutdown()
        if self.map_progress is not None:
            self.iface.mapCanvas().scene().removeItem(self.map_progress)
            self.map_progress = None

    def busy(self) -> bool:
        return self.background.busy()

    # layer and selection -------------------------------------------------------------------------------
    def set_layer(self, layer) -> None:
        """Follow ``layer`` if it is a Sign Mapper layer, else show why there is nothing to review."""
        self._unfollow_layer()
        kind = layer_kind(layer)
        if kind is None:
            self.dock.show_empty("Select a feature of a Sign Mapper 'signs', 'detections' or 'changes' layer")
            self.dock.set_pairs([])
            self.dock.set_navigation_enabled(False)
            self.dock.set_progress(0, 0, 0)  # nothing to review: no progress bar
            if self.map_progress is not None:
                self.map_progress.clear()
            return
        session = self.session
        session.layer, session.kind = layer, kind
        layer.selectionChanged.connect(self._selection_changed)
        layer.willBeDeleted.connect(self._layer_deleted)
        session.run = read_run_table(gpkg_source(layer)[0])
        self._load_catalogue()
        self._open_drive()
        self.dock.set_navigation_enabled(True, can_add=self.session.drive is not None)
        self.show_selection()

    def _unfollow_layer(self) -> None:
        self.jobs.forget_all()
        layer = self.session.layer
        if layer is not None and not isdeleted(layer):
            layer.selectionChanged.disconnect(self._selection_changed)
            layer.willBeDeleted.disconnect(self._layer_deleted)
        self.session.clear()

    def _layer_deleted(self) -> None:
        self.session.layer = None  # already being destroyed: do not disconnect from it
        self.set_layer(None)

    def _selection_changed(self, *_args) -> None:
        self.show_selection()

    def _open_drive(self) -> None:
        recorded = self.session.run.get("drive", "")
        try:
            drive = self.locator.open(recorded)
        except Exception as exc:  # a broken drive folder: the attributes can still be reviewed
            drive = None
            self.dock.show_message(f"Drive {recorded}: {exc}", error=True)
        else:
            if drive is None:
                self.dock.show_message(f"Drive folder {recorded or '(not recorded)'} not found: no images, "
                                       "decisions still work.", error=True)
            else:
                self.dock.show_message(f"Drive {drive.root} · {len(drive.pairs)} pairs")
        self.session.drive = drive
        self.dock.set_pairs([rec.id for rec in drive.pairs] if drive else [])

    def _load_catalogue(self) -> None:

        folder = self.session.run.get("catalogue")
        key = folder if folder and (Path(folder) / "catalogue.json").is_file() else None
        if key not in self._catalogues:
            self._catalogues[key] = load_catalogue(key)
        catalogue = self.session.catalogue = self._catalogues[key]
        if (key, self.session.language) != self._catalogue_key or not self.dock.has_template_choices():
            self._catalogue_key = key, self.session.language
            self.dock.set_template_choices([
                TemplateChoice(e.id, sign_name(e, self.session.language), e.colour, e.shape,
                               str(catalogue.pictogram_path(e.id, "png")))
                for e in catalogue
            ])

    def update_progress(self) -> None:
        layer = self.session.layer
        if layer is None:
            return
        to_review, reviewed, total = review_progress(layer, self.session.kind)
        self.dock.set_progress(to_review, reviewed, total)
        if self.map_progress is not None:
            self.map_progress.set_progress(layer.name(), to_review, reviewed, total)

    def show_selection(self) -> None:
        layer = self.session.layer
        if layer is None:
            return
        self.update_progress()
        ids = sorted(layer.selectedFeatureIds())
        if not ids:
            self.session.fid = self.session.item = None
            self.dock.show_empty(f"{layer.name()}: select a feature, or press Next / Next to review")
            return
        self.show_feature(self.session.fid if self.session.fid in ids else ids[0])

    def show_feature(self, fid: int) -> None:
        session = self.session
        feature = session.layer.getFeature(fid)
        if not feature.isValid():
            self.dock.show_empty(f"{session.layer.name()}: feature {fid} no longer exists")
            return
        session.fid = fid
        self.update_progress()
        session.item = item = read_item(session, feature)
        self.dock.show_item(item)
        self.images.show_item(item)
        if self.dock.following():
            self.follow()

    def follow(self) -> None:
        """The map to the feature shown, and its best pair to whoever shows pairs (the drive viewer)."""
        item = self.session.item
        if item is None:
            return
        self.navigator.follow()
        if item.pair_id:
            self.featureFollowed.emit(self.session.layer, item.pair_id)

    def _follow_toggled(self, on: bool) -> None:
        if on:
            self.follow()
