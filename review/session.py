"""What the review is looking at: the followed layer, its run record, drive and catalogue, the shown feature.

The controller fills it when it follows a layer; the parts that read items,
load images, navigate and decide all read it, so none of them keeps its own copy.
"""

from __future__ import annotations

from typing import Callable, Optional

from ..signmapper_core.drive.clock import drive_start, first_time
from ..signmapper_core.output.run_settings import recorded_config
from ..signmapper_core.output.schema import OutputContext, run_language
from ..ui.review_item import ReviewItem


class ReviewSession:
    def __init__(self, show_message: Callable[..., None]):
        self.show_message = show_message  # the dock's show_message(text, error=False)
        self.layer = None  # QgsVectorLayer of kind "signs" or "detections", or None
        self.kind: Optional[str] = None
        self.run: dict = {}  # the GeoPackage's run table
        self.drive = None  # the opened Drive, None when its folder is not found
        self.catalogue = None
        self.fid: Optional[int] = None  # the shown feature
        self.item: Optional[ReviewItem] = None  # what the dock shows of it

    def clear(self) -> None:
        self.layer, self.kind, self.fid, self.item, self.drive = None, None, None, None, None

    def is_shown(self, item: ReviewItem) -> bool:
        """Still the shown feature: results of background work for older items are dropped."""
        return item is self.item and self.fid == item.fid

    def record(self, pair_id: str):
        """The PairRecord of ``pair_id`` in the drive, None (with a message if it is not there) otherwise."""
        if self.drive is None or not pair_id:
            return None
        try:
            return self.drive.pair(pair_id)
        except KeyError:
            self.show_message(f"Pair {pair_id} is not in drive {self.drive.root}", error=True)
            return None

    @property
    def language(self) -> str:
        """The language the run wrote its names in (German for files from before it was recorded)."""

        return run_language(self.run)

    def output_context(self):
        """How the run wrote its rows (language, drive clock): what an added sign is written with."""

        start = None
        if self.drive is not None:
            try:
                start = drive_start(self.drive)
            except ValueError:
                start = None
        return OutputContext(language=self.language, catalogue=self.catalogue, start=start,
                             first_time=first_time(self.drive) if self.drive is not None else 0.0)

    def pipeline_config(self):
        """The settings the run was mapped with (``run_settings.recorded_config``)."""
        return recorded_config(self.run)
