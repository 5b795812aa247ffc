"""The review's images: a feature's left image and crop, the thumbnails of a sign's observations, whole pairs.

Decoding runs in worker threads (``background.Jobs``); a result reaches the dock
only if what it belongs to is still shown.
"""

from __future__ import annotations

from .imaging import bgr_to_qimage, crop_rect, thumbnail


def _pair_or_none(drive, pair_id):
    try:
        return drive.pair(pair_id)
    except KeyError:  # a thumbnail left empty says enough
        return None


class ImageLoader:
    def __init__(self, session, dock, jobs):
        self.session, self.dock, self.jobs = session, dock, jobs

    def _left_image(self, record):
        drive = self.session.drive
        return lambda: bgr_to_qimage(drive.load_left(record))

    def show_item(self, item) -> None:
        """The item's whole left image, opened at its crop; then the thumbnails of its observations."""
        record = self.session.record(item.pair_id)
        if record is None:
            self.dock.clear_image()
        else:
            def shown(image):
                if self.session.is_shown(item):
                    item.image = image
                    self.dock.set_image(item.pair_id, image, item.crop, item.bbox, item.centroid)

            self.jobs.submit("image", self._left_image(record), shown)
        if item.observations:
            self._load_thumbnails(item)

    def _load_thumbnails(self, item) -> None:
        session = self.session
        drive = session.drive
        if drive is None:
            return
        records = {o.pair_id: _pair_or_none(drive, o.pair_id) for o in item.observations}
        wanted = [(records[o.pair_id], o.bbox) for o in item.observations]

        def work():
            images = {}
            thumbs = []
            for record, bbox in wanted:
                if record is None:
                    thumbs.append(None)
                    continue
                if record.id not in images:
                    images[record.id] = drive.load_left(record)
                thumbs.append(thumbnail(images[record.id], bbox))
            return thumbs

        def shown(thumbs):
            if session.is_shown(item):
                for observation, thumb in zip(item.observations, thumbs):
                    observation.thumbnail = thumb
                self.dock.set_observations(item.observations)

        self.jobs.submit("thumbnails", work, shown)

    def show_observation(self, index: int) -> None:
        """One observation of the shown sign in the image view (the attributes stay the sign's)."""
        item = self.session.item
        if item is None or not item.observations or not 0 <= index < len(item.observations):
            return
        observation = item.observations[index]
        record = self.session.record(observation.pair_id)
        if record is None:
            return
        x, y, w, h = bbox = observation.bbox
        crop = crop_rect(bbox, self.session.drive.image_size)
        centroid = (x + w / 2.0 - 0.5, y + h / 2.0 - 0.5)
        self.jobs.submit("image", self._left_image(record),
                         lambda image: self.dock.set_image(record.id, image, crop, bbox, centroid))

    def show_pair(self, pair_id: str) -> None:
        """A whole pair (no feature), e.g. to add a sign in a pair without detections."""
        record = self.session.record(pair_id)
        if record is not None:
            self.jobs.submit("image", self._left_image(record), lambda image: self.dock.set_image(pair_id, image))
