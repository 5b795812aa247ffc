"""Pairs mapped on a Dask cluster (``dask.distributed``), their results handed back in driving order.

The second implementation of the seam :mod:`pair_pool` offers: ``map_pairs``
yields one ``PairResult`` per pair in driving order, whoever mapped it, so
progress, cancel, skipped-pair reporting and fusion (once, at the end, in this
process) stay as they are. A task per pair reads the pair's files from the path
all machines share and sends back only its detections (:mod:`cluster_task`);
a few pairs per worker thread are in flight at a time, so a drive of millions of
pairs holds a few futures, not millions. A worker that dies is replaced (its
nanny) and its pairs rerun elsewhere by the scheduler; a pair that kills
workers again and again is a ``MappingError`` naming it. Cancel cancels every
task of the run on the cluster before ``Cancelled`` propagates.

Dask is optional: it is imported only here, only when a scheduler is given.
"""

from __future__ import annotations

import re
import time
import uuid
from typing import Iterator, Optional

from .. import __version__
from ..errors import ClusterError, MappingError
from ..progress import CancelCheck, check_cancelled
from .cluster_task import pair_job, pair_result, worker_function
from .pair_pool import AHEAD, python_executable

# the pins of requirements-dask.txt (a test keeps them equal): what the error for a missing Dask installs
DASK_PACKAGES = ("dask==2026.8.0", "distributed==2026.8.0")
CONNECT_TIMEOUT_S = 10.0  # to reach the scheduler, and for a worker to be there
WAIT_S = 0.02  # how often a pair's future and the cancel button are looked at while waiting for it
REFRESH_PAIRS = 32  # the cluster's thread count is asked again after this many pairs (workers come and go)
ADDRESS = re.compile(r"(tcp|tls)://(\[[0-9A-Fa-f:.]+\]|[^\s:/\[\]]+):(\d{1,5})")


def install_command() -> str:
    """The pip command that installs Dask for the Python running this code."""
    try:
        python = python_executable()
    except RuntimeError:
        python = "python3"
    return f"{python} -m pip install {' '.join(DASK_PACKAGES)}"


def require_distributed():
    """The ``distributed`` module, or a ``ClusterError`` naming the package and the command that installs it."""
    try:
        import distributed
    except ImportError as exc:
        raise ClusterError(f"mapping on a Dask cluster needs the Python package 'distributed' (Dask), which this "
                           f"Python cannot import ({exc}); install it with: {install_command()}") from None
    return distributed


def scheduler_address(text: str) -> str:
    """``text`` as a scheduler address ``tcp://HOST:PORT`` (a bare ``HOST:PORT`` means tcp); ``ClusterError`` if
    it is none."""
    address = (text or "").strip()
    if "://" not in address:
        address = f"tcp://{address}"
    match = ADDRESS.fullmatch(address)
    if not match or not 0 < int(match.group(3)) < 65536:
        raise ClusterError(f"Dask scheduler address '{text}': expected tcp://HOST:PORT, e.g. tcp://10.0.0.5:8786 "
                           "(what 'dask scheduler' prints as 'Scheduler at')")
    return address


def connect(address: str, timeout_s: Optional[float] = None):
    """A ``distributed.Client`` of the scheduler at ``address`` whose workers can run the core.

    ``ClusterError`` before any work when Dask is missing, the address is malformed, the scheduler cannot be
    reached within ``timeout_s``, no worker joins within it, or a worker cannot import the core and OpenCV or
    runs another version of it.
    """
    timeout_s = CONNECT_TIMEOUT_S if timeout_s is None else timeout_s
    address = scheduler_address(address)
    distributed = require_distributed()
    probe_scheduler(address, timeout_s)
    try:
        client = distributed.Client(address, timeout=timeout_s, set_as_default=False)
    except (OSError, TimeoutError) as exc:
        raise ClusterError(f"the Dask scheduler {address} cannot be reached (waited {timeout_s:g} s: {exc}); start "
                           "it with 'dask scheduler' on that machine and check the address, the port and the "
                           "firewall") from None
    try:
        check_workers(client, timeout_s)
    except BaseException:
        client.close()
        raise
    return client


def probe_scheduler(address: str, timeout_s: float) -> None:
    """``ClusterError`` unless a Dask scheduler answers at ``address`` within ``timeout_s``.

    Asked before ``distributed.Client``, which waits forever for a program that accepts the connection and never
    answers, and reads an HTTP server's reply as the length of a message (exabytes). The question runs on an
    event loop of its own in a thread of its own, so a caller's running loop (a Jupyter kernel) is no obstacle.
    """
    import asyncio
    from concurrent.futures import ThreadPoolExecutor

    from distributed.comm import connect as open_comm

    _wait_for_listener(address, timeout_s)

    async def identity():
        comm = await open_comm(address, timeout=timeout_s)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    async def within_time():
        return await asyncio.wait_for(identity(), timeout_s)

    not_dask = (f"the address {address} is no Dask scheduler's: check the port ('dask scheduler' prints its address "
                "as 'Scheduler at')")
    try:
        with ThreadPoolExecutor(1, thread_name_prefix="signmapper-dask-probe") as thread:
            answer = thread.submit(asyncio.run, within_time()).result()
    except (asyncio.TimeoutError, TimeoutError):  # something listens there (it accepted), but answers nothing
        raise ClusterError(f"{not_dask}; a program there accepts connections but does not answer as one (waited "
                           f"{timeout_s:g} s)") from None
    except Exception as exc:  # noqa: BLE001 - whatever else answered, its reply is no Dask message
        raise ClusterError(f"{not_dask}; a program there answers in another protocol ({type(exc).__name__}: "
                           f"{exc})") from None
    kind = answer.get("type") if isinstance(answer, dict) else None
    if kind != "Scheduler":
        raise ClusterError(f"{not_dask}; a Dask {kind or 'program'} answers there, not the scheduler")


def _wait_for_listener(address: str, timeout_s: float) -> None:
    """``ClusterError`` unless a program accepts connections at ``address`` within ``timeout_s``.

    Asked apart from the Dask question, whose own connect hangs in its handshake with a program that accepts and
    never answers: a timeout then means "no Dask there", never "nothing there". A refused connection is tried
    again until the time is up (a scheduler may be starting).
    """
    import socket

    host, port = ADDRESS.fullmatch(address).group(2, 3)
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            socket.create_connection((host.strip("[]"), int(port)), max(0.1, deadline - time.monotonic())).close()
            return
        except OSError as exc:
            if time.monotonic() + 0.2 >= deadline:
                raise ClusterError(f"the Dask scheduler {address} cannot be reached (waited {timeout_s:g} s: "
                                   f"{exc.strerror or exc or 'no answer'}); start it with 'dask scheduler' on that "
                                   "machine and check the address, the port and the firewall") from None
            time.sleep(0.2)


def check_workers(client, timeout_s: Optional[float] = None) -> None:
    """``ClusterError`` unless the scheduler can read our tasks, a worker is connected and every worker runs this
    version of the core."""
    timeout_s = CONNECT_TIMEOUT_S if timeout_s is None else timeout_s
    address = client.scheduler.address
    try:
        answer = client.run_on_scheduler(worker_function("scheduler_report"))
    except Exception as exc:  # noqa: BLE001 - whatever the scheduler could not do, it cannot read our tasks
        raise ClusterError(f"the Dask scheduler {address} cannot read Sign Mapper's tasks: {type(exc).__name__}: "
                           f"{exc}; start it with the plugin folder on its PYTHONPATH (it imports "
                           "signmapper_core.run.cluster_task; see docs/scale-out.md)") from None
    if answer.get("version") != __version__:
        raise ClusterError(f"the Dask scheduler {address} has Sign Mapper core {answer.get('version')}, this client "
                           f"{__version__}: install the same plugin version on every machine")
    try:
        client.wait_for_workers(1, timeout=timeout_s)
    except TimeoutError:
        raise ClusterError(f"no Dask worker is connected to the scheduler {address} (waited {timeout_s:g} s); start "
                           f"workers with 'dask worker {address}' (see docs/scale-out.md)") from None
    answers = client.run(worker_function("worker_report"), on_error="return")
    for worker, answer in sorted(answers.items()):
        if isinstance(answer, BaseException):
            raise ClusterError(f"Dask worker {worker} cannot run Sign Mapper's core: {type(answer).__name__}: "
                               f"{answer}; each worker needs the plugin folder on its PYTHONPATH (the package "
                               "signmapper_core) and OpenCV (see docs/scale-out.md)")
        if answer.get("version") != __version__:
            raise ClusterError(f"Dask worker {worker} runs Sign Mapper core {answer.get('version')}, this client "
                               f"{__version__}: install the same plugin version on every machine")


def dask_pairs(drive, catalogue, config, scheduler, is_cancelled: Optional[CancelCheck] = None,
               detect=None) -> Iterator:
    """Yield a ``mapping.PairResult`` per pair in driving order, the pairs mapped on a Dask cluster.

    ``scheduler``: the scheduler's address (a client is connected for this drive and closed after it) or a
    connected ``distributed.Client`` (left open: one connection for many drives). ``detect`` (None =
    ``pipeline.detect_pair``) must be importable by name on the workers. ``Cancelled`` is raised between pairs
    and while waiting for one, after every task of this run was cancelled on the cluster.
    """
    client = connect(scheduler) if isinstance(scheduler, str) else scheduler
    own = isinstance(scheduler, str)
    what = f"mapping drive {drive.root}"
    pairs = drive.pairs
    task = worker_function("map_pair_task")
    run = uuid.uuid4().hex[:12]
    pending: dict = {}
    try:
        submitted, window = 0, 0
        for index, record in enumerate(pairs):
            if index % REFRESH_PAIRS == 0:
                window = max(2, sum(client.nthreads().values()) * (1 + AHEAD))
            while submitted < len(pairs) and submitted < index + window:
                job = pair_job(drive, pairs[submitted], catalogue, config, detect)
                pending[submitted] = client.submit(task, job, key=f"signmapper-pair-{run}-{submitted}",
                                                   pure=False)
                submitted += 1
            data = _result(pending[index], record, drive, client, is_cancelled, what)
            pending.pop(index).release()  # the worker may forget it: only a window of pairs is held anywhere
            yield pair_result(data, record)
    finally:
        if pending:
            client.cancel(list(pending.values()), force=True)
        if own:
            client.close()


def _result(future, record, drive, client, is_cancelled, what):
    """The answer of one pair's task, asking ``is_cancelled`` every WAIT_S; cluster failures as errors."""
    from distributed import KilledWorker
    from distributed.client import FutureCancelledError

    while not future.done():  # the future's own state, no round trip (result(timeout) races under load)
        check_cancelled(is_cancelled, what)
        time.sleep(WAIT_S)
    check_cancelled(is_cancelled, what)
    try:
        return future.result()
    except KilledWorker as exc:
        raise MappingError(f"Dask workers died repeatedly while mapping pair {record.id} of {drive.root} (out of "
                           f"memory, or a crash: see the workers' logs): {exc}") from exc
    except FutureCancelledError as exc:
        raise ClusterError(f"the Dask scheduler {client.scheduler.address} dropped pair {record.id} of "
                           f"{drive.root} (scheduler restarted or connection lost): {exc}") from exc
    except Exception as exc:  # noqa: BLE001 - the task itself failed on the worker (map_pair catches the rest)
        raise ClusterError(f"pair {record.id} of {drive.root} could not run on a Dask worker: "
                           f"{type(exc).__name__}: {exc}") from exc
