"""Pairs mapped on a Dask cluster (a LocalCluster of two worker processes on 127.0.0.1): the same GeoPackage as
the local run, a killed worker replaced without losing a pair, a clear error for an unreachable scheduler before
any work, cancel cancels the cluster's tasks, and Dask stays unimported and optional without a scheduler."""

import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import distributed  # requirements-dask.txt, part of requirements-dev.txt
import numpy as np
import pytest
from drive_fixtures import SMALL_SYNTHETIC
from gpkg_dump import differences, dump_gpkg

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.errors import ClusterError
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.progress import Cancelled
from signmapper_core.run.mapping import map_drive
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive

REPO = Path(__file__).resolve().parents[2]
PAIRS = 8


@pytest.fixture(scope="module")
def drive_dir(tmp_path_factory) -> Path:
    """JPEG pairs without depth maps (SGBM), 8 pairs: enough for several pairs in flight on each worker."""
    out = tmp_path_factory.mktemp("dask") / "drive"
    generate_drive(out, SimulationConfig(pairs=PAIRS, seed=11, write_depth=False, **SMALL_SYNTHETIC, **DRAWABLE_SIGNS))
    return out


@pytest.fixture(scope="module")
def cluster():
    """Two worker processes of one thread each on the loopback address, each with a nanny that replaces it."""
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=":0") as local:
        yield local


@pytest.fixture(scope="module")
def client(cluster):
    with distributed.Client(cluster, set_as_default=False) as connected:
        yield connected


@pytest.fixture(scope="module")
def catalogue():
    return load_catalogue()


@pytest.fixture(scope="module")
def local(drive_dir, catalogue):
    return map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), workers=1)


def _command(*args, timeout=300):
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=timeout, env=env,
                          cwd=str(REPO))


def _same(a, b):
    """Same detections (pairs, ids, classes, links) and signs, positions to the millimetre."""
    assert [(o.id, o.pair_id, o.template_id, o.sign_id, o.status, o.bbox) for o in a.detections] == \
        [(o.id, o.pair_id, o.template_id, o.sign_id, o.status, o.bbox) for o in b.detections]
    assert [(s.sign_id, s.template_id, s.n_obs, s.format, s.status) for s in a.signs] == \
        [(s.sign_id, s.template_id, s.n_obs, s.format, s.status) for s in b.signs]
    for x, y in zip(a.detections + a.signs, b.detections + b.signs):
        assert np.abs(x.position - y.position).max() < 0.001


def test_command_on_the_cluster_writes_the_same_geopackages_as_locally_for_two_drives(drive_dir, cluster, tmp_path):
    local_gpkg = tmp_path / "local.gpkg"
    # locally, in a process pool: Dask is never imported
    probe = ("import sys; from signmapper_core.map import main; "
             f"code = main([{str(drive_dir)!r}, '--out', {str(local_gpkg)!r}, '--workers', '2', '--language', 'de']); "
             "print('DASK', 'dask' in sys.modules, 'distributed' in sys.modules); sys.exit(code)")
    done = _command("-c", probe)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == "DASK False False"
    assert f"{PAIRS} pairs in" in done.stdout and "written to" in done.stdout
    # the same drive and a copy of it under another name, on the cluster, into one folder
    other = tmp_path / "other-drive"
    shutil.copytree(drive_dir, other)
    out = tmp_path / "cluster"
    done = _command("-m", "signmapper_core.map", str(drive_dir), str(other), "--out", str(out),
                    "--scheduler", cluster.scheduler_address, "--language", "de")
    assert done.returncode == 0, done.stderr
    assert "2 workers, 2 threads" in done.stderr
    expected = dump_gpkg(local_gpkg, drive_dir)
    signs = expected["tables"]["signs"]["features"]
    assert len(signs) >= 2 and len(expected["tables"]["detections"]["features"]) >= len(signs)
    assert sorted(expected["tables"]) == ["detections", "signmapper_run", "signs"]
    for drive, written in ((drive_dir, out / "drive.gpkg"), (other, out / "other-drive.gpkg")):
        assert differences(expected, dump_gpkg(written, drive)) == []


def test_a_worker_killed_in_the_middle_of_a_run_is_replaced_and_no_pair_is_lost(drive_dir, catalogue, client,
                                                                               local):
    before = client.run(os.getpid)
    killed = []

    def progress(fraction, message):
        if message.startswith("Pair ") and not killed:  # the first pair is back: the others are in flight
            victim = sorted(before.values())[0]
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    result = map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), progress=progress,
                       scheduler=client)
    assert killed and not result.skipped
    _same(result, local)
    client.wait_for_workers(2, timeout=60)
    after = client.run(os.getpid)
    assert killed[0] not in after.values() and len(after) == 2  # its nanny started a new worker


def test_an_unreachable_scheduler_is_a_clear_error_before_any_work(drive_dir, catalogue, monkeypatch, tmp_path):
    from signmapper_core.run import dask_pairs

    with socket.socket() as s:  # a port where nothing listens
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    monkeypatch.setattr(dask_pairs, "CONNECT_TIMEOUT_S", 1.0)
    seen = []
    start = time.monotonic()
    with pytest.raises(ClusterError, match=f"the Dask scheduler tcp://127.0.0.1:{port} cannot be reached "
                                           r"\(waited 1 s: .*start it with 'dask scheduler'"):
        map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), progress=lambda f, m: seen.append(m),
                  scheduler=f"127.0.0.1:{port}")
    assert time.monotonic() - start < 20
    assert not [m for m in seen if m.startswith("Pair ")]
    # the command says it and writes nothing
    out = tmp_path / "signs.gpkg"
    done = _command("-m", "signmapper_core.map", str(drive_dir), "--out", str(out), "--scheduler",
                    f"tcp://127.0.0.1:{port}", "--connect-timeout", "1")
    assert done.returncode == 1
    assert f"error: the Dask scheduler tcp://127.0.0.1:{port} cannot be reached (waited 1 s" in done.stderr
    assert not out.exists() and not list(tmp_path.iterdir())


@pytest.fixture(params=["an HTTP server", "a listener that never answers"])
def not_a_scheduler(request):
    """The port of a program that accepts connections but is no Dask scheduler (an HTTP server's reply is no
    Dask message either: Dask reads its first bytes as a length and waits for the rest)."""
    import http.server
    import threading

    if request.param == "an HTTP server":
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), http.server.SimpleHTTPRequestHandler)
        thread = threading.Thread(target=server.serve_forever, daemon=True)
        thread.start()
        yield server.server_address[1]
        server.shutdown()
        server.server_close()
    else:
        with socket.socket() as silent:  # the system accepts the connections; the program never reads them
            silent.bind(("127.0.0.1", 0))
            silent.listen(8)
            yield silent.getsockname()[1]


def test_an_address_where_no_scheduler_answers_is_a_clear_error_not_a_hang(drive_dir, tmp_path, not_a_scheduler):
    """Issue 46, case 5: before, the run waited forever (killed at 180 s); a closed port already said so in 10 s."""
    port = not_a_scheduler
    out = tmp_path / "signs.gpkg"
    start = time.monotonic()
    done = _command("-m", "signmapper_core.map", str(drive_dir), "--out", str(out), "--scheduler",
                    f"127.0.0.1:{port}", "--connect-timeout", "2", timeout=120)
    assert time.monotonic() - start < 60
    assert done.returncode == 1, done.stderr
    assert f"error: the address tcp://127.0.0.1:{port} is no Dask scheduler's: check the port ('dask scheduler' " \
           "prints its address as 'Scheduler at'); a program there accepts connections but does not answer as one " \
           "(waited 2 s)" in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and not out.exists() and not list(tmp_path.iterdir())


def test_a_malformed_scheduler_address_is_refused_naming_the_expected_form():
    from signmapper_core.run.dask_pairs import scheduler_address

    assert scheduler_address(" 10.0.0.5:8786 ") == "tcp://10.0.0.5:8786"
    assert scheduler_address("tls://[::1]:8786") == "tls://[::1]:8786"
    for wrong in ("localhost", "http://host:8786", "tcp://host:99999", ""):
        with pytest.raises(ClusterError, match="expected tcp://HOST:PORT, e.g. tcp://10.0.0.5:8786"):
            scheduler_address(wrong)


def test_cancel_cancels_the_run_s_tasks_on_the_cluster(drive_dir, catalogue, cluster, client):
    class Transitions(distributed.diagnostics.plugin.SchedulerPlugin):
        name = "signmapper-test-transitions"

        def __init__(self):
            self.states = {}

        def transition(self, key, start, finish, *args, **kwargs):
            if str(key).startswith("signmapper-pair-"):
                self.states.setdefault(key, []).append(finish)

    seen, plugin = [], Transitions()
    cluster.scheduler.add_plugin(plugin)
    try:
        with pytest.raises(Cancelled, match="mapping drive"):
            map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), progress=lambda f, m: seen.append(m),
                      is_cancelled=lambda: len([m for m in seen if m.startswith("Pair ")]) >= 2, scheduler=client)
        deadline = time.monotonic() + 10
        while cluster.scheduler.tasks and time.monotonic() < deadline:
            time.sleep(0.05)
    finally:
        cluster.scheduler.remove_plugin(name=plugin.name)
    assert not cluster.scheduler.tasks  # nothing of the run left on the scheduler
    assert not client.futures
    computed = [k for k, states in plugin.states.items() if "memory" in states]
    cancelled = [k for k, states in plugin.states.items() if "memory" not in states]
    assert len(computed) >= 2 and cancelled  # tasks in flight when cancel came were cancelled, never computed


def test_missing_dask_is_a_clear_error_naming_the_package_and_the_install_command(drive_dir, catalogue,
                                                                                  monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed raises ImportError
    with pytest.raises(ClusterError, match=r"needs the Python package 'distributed' \(Dask\), which this Python "
                                           r"cannot import .*install it with: .*python3?[.0-9]* -m pip install "
                                           r"dask==2026\.8\.0 distributed==2026\.8\.0"):
        map_drive(open_drive(drive_dir), catalogue, PipelineConfig(), scheduler="tcp://127.0.0.1:8786")


def test_the_pins_of_the_error_message_are_requirements_dask_and_dev_installs_them():
    from signmapper_core.run.dask_pairs import DASK_PACKAGES

    pins = [line.strip() for line in (REPO / "requirements-dask.txt").read_text().splitlines()
            if line.strip() and not line.startswith("#")]
    assert pins == list(DASK_PACKAGES)
    assert "-r requirements-dask.txt" in (REPO / "requirements-dev.txt").read_text().splitlines()
    assert "dask" not in (REPO / "requirements.txt").read_text()  # optional: the plugin runs without it


def test_a_scheduler_or_worker_of_another_core_version_is_refused_before_any_work(client, monkeypatch):
    from signmapper_core import __version__
    from signmapper_core.run import cluster_task, dask_pairs

    monkeypatch.setattr(dask_pairs, "__version__", "9.9.9")  # this client
    with pytest.raises(ClusterError, match=rf"the Dask scheduler tcp://127\.0\.0\.1:\d+ has Sign Mapper core "
                                           rf"{re.escape(__version__)}, this client 9\.9\.9: install the same "
                                           "plugin version on every machine"):
        dask_pairs.check_workers(client)
    monkeypatch.setattr(cluster_task, "__version__", "9.9.9")  # the LocalCluster's scheduler runs in this process
    with pytest.raises(ClusterError, match=rf"Dask worker tcp://127\.0\.0\.1:\d+ runs Sign Mapper core "
                                           rf"{re.escape(__version__)}, this client 9\.9\.9: install the same "
                                           "plugin version on every machine"):
        dask_pairs.check_workers(client)


def test_a_scheduler_that_cannot_import_the_core_is_refused_before_any_work(drive_dir, tmp_path):
    """The scheduler unpickles every task: started without the plugin folder on its PYTHONPATH it cannot."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    scheduler = subprocess.Popen([str(Path(sys.executable).parent / "dask"), "scheduler", "--host", "127.0.0.1",
                                  "--port", str(port), "--dashboard-address", ":0"], cwd=str(tmp_path), env=env,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        out = tmp_path / "signs.gpkg"
        done = _command("-m", "signmapper_core.map", str(drive_dir), "--out", str(out), "--scheduler",
                        f"tcp://127.0.0.1:{port}", "--connect-timeout", "20")
    finally:
        scheduler.terminate()
        scheduler.wait(timeout=30)
    assert done.returncode == 1
    assert f"error: the Dask scheduler tcp://127.0.0.1:{port} cannot read Sign Mapper's tasks: ModuleNotFoundError: " \
           "No module named 'signmapper_core'; start it with the plugin folder on its PYTHONPATH" in done.stderr
    assert not out.exists()


def test_a_worker_started_with_malloc_trim_threshold_takes_image_buffers_from_the_heap_again():
    """Dask's nanny sets MALLOC_TRIM_THRESHOLD_, which turns glibc's adaptive mmap threshold off (1.6x the time
    per pair); the task raises the threshold once per worker process, and leaves other processes alone."""
    probe = "from signmapper_core.run.cluster_task import heap_for_images; print(heap_for_images(), heap_for_images())"
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    env.pop("MALLOC_TRIM_THRESHOLD_", None)
    plain = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, check=True)
    nanny = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True,
                           env={**env, "MALLOC_TRIM_THRESHOLD_": "65536"})
    assert plain.stdout.split() == ["False", "False"]
    assert nanny.stdout.split() == ["True", "True"]
