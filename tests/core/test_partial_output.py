"""Outputs written whole or not at all, one writer per target, what killed runs left removed (issue 46, 14, 15)."""

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from signmapper_core.errors import OutputBusyError, OutputWriteError
from signmapper_core.output.file_paths import path_problem
from signmapper_core.output.partial_output import PartialOutput, remove_stale_partials, write_failure

REPO = Path(__file__).resolve().parents[2]


def test_a_second_writer_of_the_same_target_is_refused_naming_the_first(tmp_path):
    target = tmp_path / "out.gpkg"
    first = PartialOutput(target)
    with pytest.raises(OutputBusyError) as info:
        PartialOutput(target)  # another task of this process (QGIS runs algorithms side by side)
    assert str(info.value).startswith(f"{target}: another run is writing this output right now (process "
                                      f"{os.getpid()}, since ")
    assert str(info.value).endswith("); wait until it has ended, or choose another file")
    first.path.write_text("new")
    first.commit()
    assert target.read_text() == "new" and sorted(p.name for p in tmp_path.iterdir()) == ["out.gpkg"]
    PartialOutput(target).discard()  # free again once the first has committed


def test_a_discarded_output_leaves_the_earlier_file_and_nothing_else(tmp_path):
    target = tmp_path / "report.html"
    target.write_text("earlier")
    output = PartialOutput(target)
    output.path.write_text("half")
    output.discard()
    assert target.read_text() == "earlier" and [p.name for p in tmp_path.iterdir()] == ["report.html"]


HOLD = textwrap.dedent("""\
    import sys, time
    sys.path.insert(0, {repo!r})
    from signmapper_core.output.partial_output import PartialOutput
    output = PartialOutput({target!r}, folder={folder})
    (output.path / "left" if {folder} else output.path).parent.mkdir(parents=True, exist_ok=True)
    (output.path / "half.jpg" if {folder} else output.path).write_bytes(b"x" * 1000)
    print("written", flush=True)
    time.sleep(600)
""")


def writer(target: Path, folder: bool = False) -> subprocess.Popen:
    """A process holding a partial output of ``target`` until it is killed."""
    process = subprocess.Popen([sys.executable, "-c", HOLD.format(repo=str(REPO), target=str(target), folder=folder)],
                               stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "written"
    return process


def test_what_killed_runs_left_is_removed_by_the_next_run_writing_into_the_folder(tmp_path):
    killed = [writer(tmp_path / "signs.gpkg"), writer(tmp_path / "drive", folder=True)]
    alive = writer(tmp_path / "live.gpkg")
    for process in killed:
        os.kill(process.pid, signal.SIGKILL)  # as the system kills a run (out of memory, logout)
        process.wait()
    # what earlier versions left: a partial GeoPackage with its journal, a drive's partial folder with a pid
    (tmp_path / ".old.partial.gpkg").write_bytes(b"x" * 4096)
    (tmp_path / ".old.partial.gpkg-journal").write_bytes(b"x")
    (tmp_path / ".drive2.partial-99999999").mkdir()
    (tmp_path / ".notes").write_text("the user's own hidden file")
    left = sorted(p.name for p in tmp_path.iterdir())
    assert ".signs.gpkg.signmapper-partial" in left and ".signs.gpkg.signmapper-lock" in left
    assert ".drive.signmapper-partial" in left
    output = PartialOutput(tmp_path / "other.gpkg")  # another target in the same folder
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        ".live.gpkg.signmapper-lock", ".live.gpkg.signmapper-partial", ".notes", ".other.gpkg.signmapper-lock"]
    output.discard()
    alive.kill()
    alive.wait()
    assert [p.name for p in remove_stale_partials(tmp_path)] != []
    assert [p.name for p in tmp_path.iterdir()] == [".notes"]


def test_a_failed_write_on_a_full_disk_says_so(tmp_path):
    error = write_failure(tmp_path / "signs.gpkg", "the layer 'detections'", "database or disk is full")
    assert isinstance(error, OutputWriteError)
    assert str(error).startswith(f"{tmp_path / 'signs.gpkg'}: could not write the layer 'detections': database or "
                                 f"disk is full (the disk holding {tmp_path} is full, ")


@pytest.mark.parametrize("name, words", [
    ("a" * 300 + "/signs.gpkg", "has 300 characters, more than the 255 the file system allows; use a shorter name"),
    ("/".join(["abcdefghi"] * 1000), "characters, more than the 4096 the system allows for a path; use a shorter one"),
])
def test_a_path_too_long_is_said_in_words(tmp_path, name, words):
    problem = path_problem(tmp_path / name)
    assert problem is not None and problem.endswith(words) and len(problem) < 400
    assert path_problem(tmp_path / "signs.gpkg") is None and path_problem(tmp_path) is None


def test_the_lock_of_a_killed_writer_is_free_at_once(tmp_path):
    process = writer(tmp_path / "signs.gpkg")
    with pytest.raises(OutputBusyError, match=f"process {process.pid}, since"):
        PartialOutput(tmp_path / "signs.gpkg")
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    start = time.monotonic()
    PartialOutput(tmp_path / "signs.gpkg").discard()
    assert time.monotonic() - start < 5
