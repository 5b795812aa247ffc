"""Pairs mapped in worker processes: the same result as in one process, cancel stops them, a failing pair is
reported with its traceback."""

import functools
import multiprocessing
import re
import shutil
from pathlib import Path

import numpy as np
import pytest
from drive_fixtures import SMALL_SYNTHETIC
from failing_detection import detect_failing_at, exit_at

from signmapper_core.drive.reader import open_drive
from signmapper_core.machine import available_cores
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.progress import Cancelled
from signmapper_core.run.mapping import map_drive
from signmapper_core.run.pair_pool import TemplateHandoff, python_executable, worker_count
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive


@pytest.fixture(scope="module")
def stereo_drive(tmp_path_factory) -> Path:
    """JPEG pairs without depth maps: depth by SGBM, as with real drives."""
    out = tmp_path_factory.mktemp("pool") / "drive"
    generate_drive(out, SimulationConfig(pairs=10, seed=11, write_depth=False, **SMALL_SYNTHETIC, **DRAWABLE_SIGNS))
    return out


@pytest.fixture(scope="module")
def one_worker(stereo_drive, catalogue):
    return map_drive(open_drive(stereo_drive), catalogue, PipelineConfig(), workers=1)


def _run(drive_dir, catalogue, **kwargs):
    progress, warnings = [], []
    result = map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), progress=lambda f, m: progress.append(m),
                       warn=warnings.append, **kwargs)
    return result, progress, warnings


def test_two_workers_give_the_same_detections_and_signs_as_one(stereo_drive, catalogue, one_worker):
    pooled, progress, warnings = _run(stereo_drive, catalogue, workers=2)
    assert len(one_worker.signs) >= 2 and not pooled.skipped and not warnings
    assert [(o.id, o.pair_id, o.template_id, o.sign_id, o.status) for o in pooled.detections] == \
        [(o.id, o.pair_id, o.template_id, o.sign_id, o.status) for o in one_worker.detections]
    for a, b in zip(pooled.detections, one_worker.detections):
        assert np.abs(a.position - b.position).max() < 0.001
        assert a.classification_indicator == pytest.approx(b.classification_indicator, abs=1e-6)
    assert [(s.sign_id, s.template_id, s.n_obs, s.format) for s in pooled.signs] == \
        [(s.sign_id, s.template_id, s.n_obs, s.format) for s in one_worker.signs]
    for a, b in zip(pooled.signs, one_worker.signs):
        assert np.abs(a.position - b.position).max() < 0.001
    # progress in driving order, one message per pair, as with one worker
    pair_ids = [m.split(":")[0].split()[1] for m in progress if m.startswith("Pair ")]
    assert pair_ids == [r.id for r in open_drive(stereo_drive).pairs]


def test_cancel_mid_run_stops_the_workers(stereo_drive, catalogue):
    seen = []
    with pytest.raises(Cancelled, match="mapping drive"):
        map_drive(open_drive(stereo_drive), catalogue, PipelineConfig(), progress=lambda f, m: seen.append(m),
                  is_cancelled=lambda: len([m for m in seen if m.startswith("Pair ")]) >= 3, workers=2)
    assert len([m for m in seen if m.startswith("Pair ")]) == 3
    assert multiprocessing.active_children() == []  # no worker left running


def test_pair_failing_in_a_worker_is_reported_with_its_traceback_and_the_run_goes_on(stereo_drive, catalogue,
                                                                                     one_worker):
    failing = open_drive(stereo_drive).pairs[3]
    result, _, warnings = _run(stereo_drive, catalogue, workers=2,
                               detect=functools.partial(detect_failing_at, failing.pose))
    (failed,) = result.skipped
    assert failed.record.id == failing.id and failed.stage == "detect"
    assert failed.error == "detection failed: IndexError: list index out of range"
    assert "Traceback (most recent call last)" in failed.traceback and "detect_failing_at" in failed.traceback
    (warning,) = warnings
    assert warning.startswith(f"Skipped pair {failing.id}: detection failed: IndexError")
    assert failed.traceback in warning
    assert [o.pair_id for o in result.detections] == [o.pair_id for o in one_worker.detections
                                                     if o.pair_id != failing.id]


def test_unreadable_pair_is_skipped_by_a_worker_like_in_process(stereo_drive, catalogue, tmp_path):
    drive = tmp_path / "corrupt"
    shutil.copytree(stereo_drive, drive)
    broken = sorted((drive / "right").iterdir())[2]
    broken.write_bytes(broken.read_bytes()[:2000])
    pooled, _, warnings = _run(drive, catalogue, workers=2)
    alone, _, _ = _run(drive, catalogue, workers=1)
    assert [(r.record.id, r.stage, r.error) for r in pooled.skipped] == \
        [(r.record.id, r.stage, r.error) for r in alone.skipped] == [(broken.stem, "read", alone.skipped[0].error)]
    assert broken.name in warnings[0]
    assert [o.pair_id for o in pooled.detections] == [o.pair_id for o in alone.detections]


def test_worker_count_defaults_to_all_cores_and_never_exceeds_the_pairs():
    assert worker_count(None, 1000) == worker_count(0, 1000) == available_cores()
    assert worker_count(8, 3) == 3 and worker_count(2, 0) == 1
    with pytest.raises(ValueError, match="0 \\(all cores\\) or more, not -1"):
        worker_count(-1, 10)
    assert Path(python_executable()).name.startswith("python")


def test_a_worker_that_dies_is_a_mapping_error_naming_the_pair(stereo_drive, catalogue):
    from signmapper_core.errors import MappingError

    failing = open_drive(stereo_drive).pairs[2]
    with pytest.raises(MappingError, match="a worker process ended abruptly while mapping pairs ") as caught:
        map_drive(open_drive(stereo_drive), catalogue, PipelineConfig(), workers=2,
                  detect=functools.partial(exit_at, failing.pose))
    # the pairs still in flight when the worker died: which of them finished first depends on the machine's load
    first, last = re.search(r"mapping pairs (\S+) to (\S+) of ", str(caught.value)).groups()
    assert first <= failing.id <= last
    assert "mapping with 1 worker process shows which pair" in str(caught.value)
    assert multiprocessing.active_children() == []


def test_template_handoff_gives_what_was_sent_or_nothing_and_leaves_no_file():
    context = multiprocessing.get_context("spawn")
    sent = TemplateHandoff(context)
    sent.send({"1.01": (np.full((3, 4, 3), 7, np.uint8), np.full((3, 4), 255, np.uint8))})
    (bgr, alpha), = sent.receive().values()
    assert bgr.shape == (3, 4, 3) and int(bgr.max()) == 7 and int(alpha.min()) == 255
    sent.close()
    assert not Path(sent.path).exists() and sent.receive() is None
    nothing = TemplateHandoff(context)
    nothing.send(None)  # a catalogue without templates to give: the worker renders its own
    assert nothing.ready.is_set() and nothing.receive() is None
    nothing.close()


def test_templates_that_cannot_be_rendered_end_the_run_with_that_error_and_release_the_waiting_workers(
        stereo_drive, catalogue, monkeypatch):
    import signmapper_core.pipeline.classify as classify

    def broken(*args, **kwargs):
        raise OSError("template PNG unreadable")

    monkeypatch.setattr(classify, "canonical_templates", broken)
    with pytest.raises(OSError, match="template PNG unreadable"):
        map_drive(open_drive(stereo_drive), catalogue, PipelineConfig(), workers=2)
    assert multiprocessing.active_children() == []  # the workers waiting for the templates did not hang


# issue 46: a pool that cannot start maps in the calling process, with a warning

@pytest.mark.parametrize("cause", ["no python", "no OpenCV in the workers"])
def test_a_pool_that_cannot_start_maps_in_this_process_with_a_warning(stereo_drive, catalogue, one_worker,
                                                                      monkeypatch, tmp_path, cause):
    from signmapper_core.run import pair_pool

    if cause == "no python":
        def missing():
            raise RuntimeError("no Python interpreter found for worker processes")
        monkeypatch.setattr(pair_pool, "python_executable", missing)
    else:  # every worker fails as it starts, before its first pair (workers take this process's sys.path)
        import cv2  # noqa: F401 - here it is imported already: only the workers meet the one below

        (tmp_path / "cv2.py").write_text("raise ImportError('no OpenCV for this Python')\n")
        monkeypatch.syspath_prepend(str(tmp_path))
    result, _progress, warnings = _run(stereo_drive, catalogue, workers=2)
    (warning,) = warnings
    assert warning.startswith("The 2 worker processes could not start (")
    assert warning.endswith("); mapping the pairs in this process instead, on one core")
    assert not result.skipped and [(o.pair_id, o.template_id) for o in result.detections] == \
        [(o.pair_id, o.template_id) for o in one_worker.detections]


def test_starting_workers_leaves_the_callers_main_module_as_it_was(monkeypatch):
    import sys
    import types

    from signmapper_core.run.pair_pool import _main_kept_from_workers

    main = types.ModuleType("__main__")
    main.__file__, main.__spec__ = "/somewhere/script.py", None
    monkeypatch.setitem(sys.modules, "__main__", main)
    with _main_kept_from_workers():
        from multiprocessing import spawn

        data = spawn.get_preparation_data("worker")
        assert "init_main_from_path" not in data and "init_main_from_name" not in data
    assert main.__file__ == "/somewhere/script.py" and main.__spec__ is None
