"""Mapping a drive: every pair through the pipeline, the detections fused into signs, their mounting heights
and plausibility.

This is the one capability every front end uses (the ``mapsigns`` algorithm,
``scripts/evaluate_mapping.py``, the benchmarks, the review's "add missed sign").
Pairs are decoded lazily, one at a time; a pair whose files are corrupt, or
whose detection raises (a bug met by unusual image content), is reported with
the reason (and the traceback) and skipped rather than ending the run, unless
more than a set share of the pairs (or all of them) had to be skipped: then the
run is a :class:`~signmapper_core.errors.MappingError`, since an output of the
rest would silently lack signs. Cancellation is checked between pairs
(:mod:`signmapper_core.progress`).
"""

from __future__ import annotations

import uuid
from contextlib import closing
from dataclasses import dataclass, field, replace
from typing import Iterator, Optional

import numpy as np

from ..catalogue.text_panels import is_text_panel
from ..drive.path_ahead import with_path_ahead
from ..drive.reader import Drive, PairRecord
from ..errors import MappingError
from ..fusion.mounting import camera_height_above_road, mounting_height
from ..fusion.plausibility import hold_implausible
from ..fusion.signs import FusedSign, FusionConfig, Observation, azimuth_deg, fuse_observations
from ..output.run_table import run_record
from ..pipeline import detect_in_window
from ..pipeline.classifiers import accept_threshold, classifier_for
from ..pipeline.depth_range import config_for_camera, range_text
from ..pipeline.face_extent import carried_discs
from ..pipeline.search_range import path_limit_m
from ..plates.fusion import fuse_plates, is_plate, read_plate_texts
from ..plates.number_check import check_speed_numbers, speed_limit_signs
from ..plates.printed_numbers import printed_numbers
from ..progress import CancelCheck, ProgressCallback, WarnCallback, check_cancelled, report, send_warning
from ..statuses import MANUAL
from .dask_pairs import dask_pairs
from .pair import DETECT, PairResult, load_pair, map_pair
from .pair_pool import PoolNotStarted, pooled_pairs, worker_count

PAIRS_SHARE = 0.95  # of the progress: the pairs; fusion and mounting heights take the rest
LARGEST_FACE_M = 1.5  # a click is the sign's centre: the search window must hold half the largest face


@dataclass
class MappingResult:
    """Everything a run produced: detections with their pairs, fused signs and what the run was."""

    drive: Drive
    catalogue: object
    config: object  # pipeline.PipelineConfig
    detections: list[Observation]  # ids from 1 in driving order; each names its sign (sign_id)
    signs: list[FusedSign]  # ids from 1 in order of first sight; mount_height_m set where known
    skipped: list[PairResult]  # pairs that could not be read or whose detection failed, with the reason
    seconds: float  # time spent on the pairs (loading and detecting)
    load_seconds: float = 0.0  # of which decoding the files
    classifier_name: str = ""  # the strategy that ran ("cnn" or "ncc")
    classification_threshold: Optional[float] = None  # the indicator "accepted" needed in this run
    fusion: FusionConfig = field(default_factory=FusionConfig)  # as fused, with that indicator
    run_id: str = field(default_factory=lambda: str(uuid.uuid4()))  # recorded by exports to recognise the run

    def detections_of(self, sign: FusedSign) -> list[Observation]:
        return [o for o in self.detections if o.sign_id == sign.sign_id]

    def failure_summary(self) -> Optional[str]:
        """One line for the run summary, e.g. "3 of 120 pairs skipped: 1 unreadable, 2 detection errors";
        None when every pair went through."""
        return failure_summary(self.skipped, len(self.drive.pairs))

    def run_record(self) -> dict:
        """What the run table records (``output.run_table.RUN_KEYS``): software, drive, catalogue and settings."""
        return run_record(self)


def map_pairs(drive: Drive, catalogue, config, is_cancelled: Optional[CancelCheck] = None, workers: int = 1,
              detect=None, scheduler=None, warn: Optional[WarnCallback] = None) -> Iterator[PairResult]:
    """Yield a :class:`PairResult` per pair in driving order; raises ``Cancelled`` between pairs.

    ``scheduler`` (a Dask scheduler address or a connected ``distributed.Client``)
    maps the pairs on that cluster (:mod:`dask_pairs`); else ``workers`` > 1 maps
    them in that many processes (:mod:`pair_pool`), or, when no worker process can
    start, here with a warning through ``warn``; the results are in driving
    order either way. ``detect`` replaces ``pipeline.detect_pair`` (a
    module-level function, so worker processes can import it).
    """
    if scheduler is not None:
        yield from dask_pairs(drive, catalogue, config, scheduler, is_cancelled, detect)
        return
    if workers > 1:
        try:
            yield from pooled_pairs(drive, catalogue, config, workers, is_cancelled, detect)
            return
        except PoolNotStarted as exc:  # raised before the first pair: every pair is still to be mapped
            send_warning(warn, f"The {workers} worker processes could not start ({exc}); mapping the pairs in this "
                               "process instead, on one core")
    for record in drive.pairs:
        check_cancelled(is_cancelled, f"mapping drive {drive.root}")
        yield map_pair(drive, record, catalogue, config, detect)


def failure_summary(skipped: list[PairResult], total: int) -> Optional[str]:
    """"N of M pairs skipped: X unreadable, Y detection errors" for the run summary; None if none was."""
    if not skipped:
        return None
    unreadable = sum(1 for r in skipped if r.stage != DETECT)
    errors = len(skipped) - unreadable
    parts = ([f"{unreadable} unreadable"] if unreadable else []) + \
        ([f"{errors} detection error{'s' if errors > 1 else ''}"] if errors else [])
    return f"{len(skipped)} of {total} pairs skipped: {', '.join(parts)}"


def set_mounting_heights(drive: Drive, signs: list[FusedSign]) -> None:
    """Each sign's lower edge above the road where the drive states its camera height (``mounting``)."""
    centres = np.array([r.pose.centre for r in drive.pairs])
    camera_height = camera_height_above_road(drive.metadata)
    for sign in signs:
        sign.mount_height_m = mounting_height(sign.position, sign.height_m, centres, camera_height)


def check_plausibility(drive: Drive, signs: list[FusedSign], fusion: FusionConfig) -> int:
    """Accepted signs that cannot be where or as they were mapped (too low, turned away from the road, too far
    beside it: ``plausibility``) sent to review with the reason; returns how many."""
    path = np.array([r.pose.centre for r in drive.pairs])
    return hold_implausible(signs, path, camera_height_above_road(drive.metadata), fusion)


def map_drive(drive: Drive, catalogue, config, progress: Optional[ProgressCallback] = None,
              is_cancelled: Optional[CancelCheck] = None, warn: Optional[WarnCallback] = None,
              fusion: Optional[FusionConfig] = None, max_skipped_share: float = 1.0,
              workers: Optional[int] = None, detect=None, scheduler=None) -> MappingResult:
    """Detect the signs of every pair, fuse them into physical signs and give each its mounting height; an
    accepted sign that cannot be where or as it was mapped goes to review (:func:`check_plausibility`).

    Skipped pairs, and pairs without usable depth or colour, are passed to
    ``warn`` as they happen; skipped pairs are listed in the result.
    ``config``'s depth range follows the drive's camera where it asks so (:func:`.depth_range.config_for_camera`),
    and each pair's also the path ahead of it (``drive/path_ahead.py``); the result holds the range used.
    ``fusion``'s ``accept_classification`` is replaced by the classifier's threshold (``config`` may set it), its
    ``far_m`` by ``config.depth.far_m``.
    ``Cancelled`` is raised when ``is_cancelled()`` turns true; ``MappingError``
    as soon as more than ``max_skipped_share`` (0..1) of the pairs are skipped,
    and when no pair could be mapped at all. ``workers``: processes mapping the
    pairs (None or 0 = all cores; 1 = in this process); the result does not
    depend on it. ``scheduler``: a Dask scheduler address (``tcp://HOST:PORT``)
    or a connected ``distributed.Client``: the pairs are mapped on that cluster
    instead (``workers`` is then not used), with the same result; fusion runs
    here. ``ClusterError`` when the cluster cannot be used, before any pair.
    ``detect``: see :func:`map_pairs`.
    """

    config = config_for_camera(config, drive.camera)
    if path_limit_m(config.depth) > 0:  # faces the drive's end or a turn keeps beyond far are searched to the reach
        drive = with_path_ahead(drive, config.depth.turn_deg, path_limit_m(config.depth))
    report(progress, 0.0, f"Searching {range_text(config.depth)} ahead of the camera"
           + (" (the reach its focal length and baseline give)" if config.depth.range_from_camera else ""))
    classifier = classifier_for(catalogue, config)  # a missing or broken model fails here, before any pair
    unread = classifier.unknown(catalogue.ids()) if hasattr(classifier, "unknown") else []
    if unread:
        listed = ", ".join(unread[:5]) + (", ..." if len(unread) > 5 else "")
        send_warning(warn, f"The classifier of {catalogue.folder} was trained without {len(unread)} of the "
                           f"catalogue's {len(catalogue)} signs ({listed}): faces that may be one of them are read "
                           "by template matching instead; retrain it (make train-classifier)")
    accept = accept_threshold(classifier, config)
    # always the classifier's threshold and the run's depth range
    fusion = replace(fusion or FusionConfig(), accept_classification=accept, far_m=config.depth.far_m,
                     disparity_sigma_px=config.depth.disparity_sigma_px)
    detections, skipped, seconds, load_seconds, total = [], [], 0.0, 0.0, len(drive.pairs)
    workers = worker_count(workers, total)
    with closing(map_pairs(drive, catalogue, config, is_cancelled, workers, detect, scheduler, warn)) as results:
        for done, result in enumerate(results, start=1):  # closing: a pool stops when the loop raises
            seconds += result.seconds
            load_seconds += result.load_seconds
            for message in result.warnings:
                send_warning(warn, message)
            if result.error:
                skipped.append(result)
                trace = f"\n{result.traceback}" if result.traceback else ""
                send_warning(warn, f"Skipped pair {result.record.id}: {result.error}{trace}")
                if len(skipped) > max_skipped_share * total:
                    raise MappingError(f"{len(skipped)} of {total} pairs skipped, more than the "
                                       f"{100 * max_skipped_share:g} % allowed (first: pair "
                                       f"{skipped[0].record.id}: {skipped[0].error})", limit_exceeded=True)
            for detection in result.detections:
                detections.append(Observation(detection, result.record, id=len(detections) + 1))
            report(progress, PAIRS_SHARE * done / max(total, 1),
                   f"Pair {result.record.id}: {len(result.detections)} signs ({result.seconds:.2f} s)")
    check_cancelled(is_cancelled, f"mapping drive {drive.root}")
    if total and len(skipped) == total:
        raise MappingError(f"no pair could be mapped: {total} of {total} pairs skipped (first: pair "
                           f"{skipped[0].record.id}: {skipped[0].error})")
    report(progress, PAIRS_SHARE, f"Fusing {len(detections)} detections into signs")
    signs = fuse_observations([o for o in detections if not is_plate(o)], drive.camera, fusion,
                              carried_discs(catalogue, config.colour.hsv_ranges))
    plates = fuse_plates(detections, signs, drive.camera, fusion)
    panels = [s for s in signs if is_text_panel(s.template_id)]
    if plates or panels:
        report(progress, PAIRS_SHARE, f"Reading the text of {len(plates)} supplementary plates and {len(panels)} "
               "text panels")
        read_plate_texts(plates + panels, warn, config=fusion)
    speed_limits = len(speed_limit_signs(signs))
    if speed_limits:
        report(progress, PAIRS_SHARE, f"Reading the digits of {speed_limits} speed-limit signs")
        demoted = check_speed_numbers(signs, printed_numbers(catalogue.ids()), warn, config=fusion)
        if demoted:
            send_warning(warn, f"{demoted} speed-limit sign{'s' if demoted > 1 else ''} sent to review: the digits "
                               "read another number")
    signs += plates
    set_mounting_heights(drive, signs)
    held = check_plausibility(drive, signs, fusion)
    if held:
        send_warning(warn, f"{held} sign{'s' if held > 1 else ''} sent to review: mapped where or as no sign can be "
                           "(below any sign's mounting, turned away from the road, or far beside it)")
    report(progress, 1.0, f"{len(detections)} detections fused into {len(signs)} signs")
    return MappingResult(drive, catalogue, config, detections, signs, skipped, seconds, load_seconds,
                         classifier.name, accept, fusion)


def search_half_size(drive: Drive, config) -> int:
    """Half the side of the window searched around a click: the largest face at the near limit, in pixels."""
    return int(min(max(drive.camera.fx * LARGEST_FACE_M / 2.0 / config.depth.near_m, 64.0), max(drive.image_size)))


def detect_at(drive: Drive, record: PairRecord, catalogue, config, u: float, v: float) -> Optional[Observation]:
    """The sign a person clicked at (u, v) in the left image of ``record``, with status "manual", or None.

    The same detection steps run in a window around the click (``detect_in_window``).
    """

    left, depth, right = load_pair(drive, record)
    detection = detect_in_window(left, depth, right, drive.camera, record.pose, catalogue, config, (u, v),
                                 search_half_size(drive, config))
    return None if detection is None else Observation(replace(detection, status=MANUAL), record)


def manual_sign(observation: Observation, sign_id: int) -> FusedSign:
    """A sign a person added from one clicked observation: its own class and size, facing the camera."""
    observation.sign_id = sign_id
    return FusedSign(
        sign_id=sign_id, template_id=observation.template_id, width_m=float(observation.width_m),
        height_m=float(observation.height_m), format=observation.format,
        position=np.asarray(observation.position, float), n_obs=1, vote_share=1.0, sigma_m=None,
        azimuth=azimuth_deg(observation.camera_centre - observation.position),
        detection_indicator=observation.detection_indicator,
        classification_indicator=observation.classification_indicator, status=MANUAL, best=observation,
        observations=[observation],
    )
