"""A throw-away PostgreSQL server for the database tests: a temporary data directory, a free local port.

Debian's ``postgresql`` and ``postgresql-15-postgis-3`` packages provide the
binaries (``make setup`` installs them). The server refuses to run as root, so
as root it runs as the ``postgres`` system user. Nothing here skips: a server
that cannot start raises :class:`PostgresUnavailable` with the reason, and the
fixture turns that into a failed test.
"""

from __future__ import annotations

import glob
import os
import pwd
import shutil
import socket
import subprocess
import tempfile
import time
from pathlib import Path

SUPERUSER = "signmapper"


class PostgresUnavailable(RuntimeError):
    """The test server could not be started; the message says why."""


def binary_dir() -> Path:
    """The newest Debian PostgreSQL bin directory that has initdb, pg_ctl and PostGIS next to it."""
    for folder in sorted(glob.glob("/usr/lib/postgresql/*/bin"), key=lambda p: int(Path(p).parent.name),
                         reverse=True):
        version = Path(folder).parent.name
        postgis = glob.glob(f"/usr/share/postgresql/{version}/extension/postgis.control")
        if (Path(folder) / "initdb").exists() and postgis:
            return Path(folder)
    raise PostgresUnavailable("no PostgreSQL with PostGIS found under /usr/lib/postgresql: install the Debian "
                              "packages postgresql and postgresql-15-postgis-3 (make setup does)")


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class PostgresServer:
    """Start with :meth:`start`, connect with :attr:`dsn` (libpq keywords), end with :meth:`stop`."""

    def __init__(self):
        self.bin = binary_dir()
        self.port = free_port()
        self.root = Path(tempfile.mkdtemp(prefix="signmapper-pg-"))
        self.data = self.root / "data"
        self.log = self.root / "server.log"
        self.user = None if os.geteuid() != 0 else "postgres"

    @property
    def dsn(self) -> str:
        return f"host=127.0.0.1 port={self.port} user={SUPERUSER} dbname=postgres connect_timeout=5"

    def dsn_for(self, dbname: str) -> str:
        return self.dsn.replace("dbname=postgres", f"dbname={dbname}")

    def _run(self, *args: str) -> subprocess.CompletedProcess:
        command = list(args)
        if self.user:
            command = ["runuser", "-u", self.user, "--"] + command
        return subprocess.run(command, capture_output=True, text=True, timeout=120)

    def start(self) -> PostgresServer:
        if self.user:
            try:
                entry = pwd.getpwnam(self.user)
            except KeyError:
                raise PostgresUnavailable("running as root and there is no 'postgres' user to run the server "
                                          "as (the Debian postgresql package creates it)") from None
            os.chown(self.root, entry.pw_uid, entry.pw_gid)
        done = self._run(str(self.bin / "initdb"), "-D", str(self.data), "-U", SUPERUSER, "--auth=trust",
                         "-E", "UTF8", "--locale=C.UTF-8")
        if done.returncode != 0:
            raise PostgresUnavailable(f"initdb failed: {done.stderr.strip() or done.stdout.strip()}")
        options = f"-p {self.port} -k {self.root} -c listen_addresses=127.0.0.1 -c fsync=off"
        done = self._run(str(self.bin / "pg_ctl"), "-D", str(self.data), "-l", str(self.log), "-o", options,
                         "-w", "-t", "60", "start")
        if done.returncode != 0:
            log = self.log.read_text(errors="replace")[-2000:] if self.log.exists() else ""
            raise PostgresUnavailable(f"pg_ctl start failed: {done.stderr.strip()} {log}")
        self._wait_ready()
        return self

    def _wait_ready(self, timeout_s: float = 30.0) -> None:
        import psycopg2

        deadline = time.monotonic() + timeout_s
        while True:
            try:
                psycopg2.connect(self.dsn).close()
                return
            except psycopg2.OperationalError as exc:
                if time.monotonic() > deadline:
                    raise PostgresUnavailable(f"server on port {self.port} does not accept connections: {exc}") \
                        from exc
                time.sleep(0.2)

    def create_database(self, name: str) -> str:
        """A new empty database; returns its DSN."""
        import psycopg2

        conn = psycopg2.connect(self.dsn)
        conn.autocommit = True
        try:
            with conn.cursor() as cur:
                cur.execute(f'DROP DATABASE IF EXISTS "{name}"')
                cur.execute(f'CREATE DATABASE "{name}"')
        finally:
            conn.close()
        return self.dsn_for(name)

    def stop(self) -> None:
        if self.data.exists():
            self._run(str(self.bin / "pg_ctl"), "-D", str(self.data), "-m", "immediate", "-w", "stop")
        shutil.rmtree(self.root, ignore_errors=True)
