"""Fault injection on the outputs (issue 46): nothing the user gave as output is lost, nothing fails silently.

An existing GeoPackage given to any algorithm keeps what the algorithm does not own (cases 1-3); two runs on one
output at once, what a killed run left behind, a kill at random moments (14, 15); long paths (6); a full disk
(7); what qgis_process prints (16). Each test runs the algorithm as a user does (``processing.run`` or
``qgis_process.bin``) and checks the message and the files.

The issue's other cases have their tests beside the code they exercise: a script without a main guard (4)
test_standalone_script.py; schedulers that are no Dask scheduler (5) tests/core/test_dask_mapping.py; recorded
settings of the wrong type or contradicting rows (8, 13) test_map_signs_settings.py and
tests/core/test_run_settings.py; duplicate and geometry-less reference rows (9, 10) test_reference_rows.py; images
without a pose row and unused image times (11, 12) tests/core/test_drive_reader.py and test_import_drive.py.
"""

import hashlib
import os
import random
import shutil
import signal
import sqlite3
import subprocess
import time
from pathlib import Path

import pytest
from drive_fixtures import make_drive
from qgis.core import QgsProcessingException, QgsProcessingUtils, QgsVectorLayer
from qgis_process_runner import QGIS_PROCESS, enable_plugin, qgis_process_env, run_algorithm
from recorder import Recorder
from test_evaluate import REF, eastward_trajectory, point_layer
from test_map_signs_faults import user_geopackage

SMALL_SYNTHETIC = {"PAIRS": 2, "SEED": 5, "WIDTH": 480, "HEIGHT": 270, "FX": 437.5}


@pytest.fixture(scope="module")
def cli_env(plugin_dir, tmp_path_factory):
    env = qgis_process_env(plugin_dir, tmp_path_factory.mktemp("profile"))
    enable_plugin(env)
    return env


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def contents(path: Path) -> dict:
    """Layers with their feature counts and descriptions, the styles and the run table of a GeoPackage."""
    with sqlite3.connect(path) as db:
        layers = {name: (db.execute(f'SELECT count(*) FROM "{name}"').fetchone()[0], description)
                  for name, description in db.execute("SELECT table_name, description FROM gpkg_contents")}
        styles = sorted(name for (name,) in db.execute("SELECT f_table_name FROM layer_styles"))
        run = dict(db.execute("SELECT key, value FROM signmapper_run"))
    return {"layers": layers, "styles": styles, "run": run}


def finished(path: Path) -> tuple:
    """What every complete mapsigns output of one drive shares: its layers' counts, styles and run settings."""
    found = contents(path)
    return found["layers"], found["styles"], {k: v for k, v in found["run"].items() if k != "run_id"}


@pytest.fixture
def project(run, tmp_path) -> Path:
    """keep.gpkg: a mapsigns output (layers, styles, run table) with the user's own layer 'roads' added."""
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    keep = user_geopackage(tmp_path / "keep.gpkg")
    run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(keep)})
    before = contents(keep)
    assert set(before["layers"]) == {"roads", "signs", "detections", "signmapper_run", "layer_styles"}
    assert before["styles"] == ["detections", "signs"] and before["run"]["drive"]
    return keep


def assert_kept(path: Path, before: dict, added: dict) -> None:
    """Everything of ``before`` is in ``path`` as it was, and the layers ``added`` (name -> features) besides."""
    after = contents(path)
    assert {k: v for k, v in after["layers"].items() if k not in added} == before["layers"]
    assert {k: v[0] for k, v in after["layers"].items() if k in added} == added
    for name in added:
        assert after["layers"][name][1].startswith("Sign Mapper: ")  # ours: a later run may replace it
    assert after["styles"] == before["styles"] and after["run"] == before["run"]
    roads = QgsVectorLayer(f"{path}|layername=roads", "roads", "ogr")
    assert [f["name"] for f in roads.getFeatures()] == ["Bahnhofstrasse"]


# 1-3. an existing GeoPackage given as output keeps what the algorithm does not own

def test_drive_trajectory_into_an_existing_geopackage_keeps_its_layers(cli_env, project, tmp_path):
    before = contents(project)
    for _ in range(2):  # a second run replaces its own layer, nothing else
        code, data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=tmp_path / "drive",
                                        OUTPUT=project)
        assert code == 0, log
        assert data["results"]["OUTPUT"] == f"{project}|layername=keep"
        assert_kept(project, before, {"keep": 2})
    # no partial or lock file left; keep_crops holds the crops of the mapping run that made the file
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive", "keep.gpkg", "keep_crops"]


def test_evaluate_outputs_into_an_existing_geopackage_keep_its_layers(run, project, tmp_path):
    before = contents(project)
    result = run("signmapper:evaluate", {
        "SIGNS": point_layer(REF, "mapped"), "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": str(project), "MATCHES": f"{project}|layername=matches"})
    assert result["STATISTICS"] == f"{project}|layername=keep" and result["MATCHES"] == f"{project}|layername=matches"
    assert_kept(project, before, {"keep": 28, "matches": 4})  # 8 figures of Table 1, 4 of 5 rows of Table 2
    assert QgsVectorLayer(result["MATCHES"], "m", "ogr").featureCount() == 4


def test_synthetic_truth_into_an_existing_geopackage_keeps_its_layers(run, project, tmp_path):
    before = contents(project)
    result = run("signmapper:syntheticdrive", {**SMALL_SYNTHETIC, "OUTPUT": str(tmp_path / "new-drive"),
                                                "TRUTH": f"{project}|layername=truth"})
    truth = QgsVectorLayer(result["TRUTH"], "truth", "ogr")
    assert truth.isValid() and truth.featureCount() >= 1
    assert_kept(project, before, {"truth": truth.featureCount()})


def test_a_layer_of_the_users_with_the_same_name_is_refused_before_any_work(cli_env, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    roads = user_geopackage(tmp_path / "roads.gpkg")  # its layer 'roads' is what QGIS would name ours
    before = digest(roads)
    code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive, OUTPUT=roads)
    assert code != 0
    assert (f"Trajectory points: {roads} already holds a layer 'roads' that Sign Mapper did not write; it is left "
            "as it is. To add this output as a layer of its own, give the layer a name:") in log
    assert f"OUTPUT=\"{roads}|layername=trajectory_points\"" in log and "Traceback" not in log
    assert digest(roads) == before
    # as the message says: the same run with a layer name of its own
    code, data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive,
                                    OUTPUT=f"{roads}|layername=trajectory_points")
    assert code == 0, log
    assert QgsVectorLayer(f"{roads}|layername=roads", "r", "ogr").featureCount() == 1
    assert QgsVectorLayer(data["results"]["OUTPUT"], "t", "ogr").featureCount() == 2


def test_temporary_and_memory_outputs_still_chain(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=3)
    result = run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": "TEMPORARY_OUTPUT",
                                                "TRACK": "memory:"})
    points = result["OUTPUT"]  # processing.run hands a temporary feature output back as a memory layer
    assert points.featureCount() == 3 and points.providerType() == "memory"
    assert result["TRACK"].featureCount() == 1
    # a temporary file output stays QGIS's own: written in its temporary folder, nothing beside the drive
    report = run("signmapper:evaluate", {
        "SIGNS": point_layer(REF, "mapped"), "REFERENCE": point_layer(REF, "ref"), "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": "TEMPORARY_OUTPUT",
        "STATISTICS": "TEMPORARY_OUTPUT", "MATCHES": "memory:"})["REPORT"]
    assert report.startswith(QgsProcessingUtils.tempFolder()) and "<svg" in Path(report).read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive"]


# 14. two runs writing the same output at once

def test_a_second_run_on_the_same_output_says_another_run_is_writing_it(cli_env, small_drive, tmp_path):
    out = tmp_path / "signs.gpkg"
    first = subprocess.Popen([QGIS_PROCESS, "--json", "run", "signmapper:mapsigns", "--", f"DRIVE={small_drive}",
                              f"OUTPUT={out}", "WORKERS=1"], env=cli_env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    lock = tmp_path / ".signs.gpkg.signmapper-lock"
    deadline = time.monotonic() + 300
    while not lock.exists() and first.poll() is None and time.monotonic() < deadline:
        time.sleep(0.1)
    code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=small_drive, OUTPUT=out)
    first_out, first_err = first.communicate(timeout=900)
    assert first.returncode == 0, first_err
    assert code != 0
    assert f"Trajectory points: {out}: another run is writing this output right now (process {first.pid}" in log
    assert "readonly database" not in log
    assert QgsVectorLayer(f"{out}|layername=signs", "s", "ogr").featureCount() >= 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["signs.gpkg", "signs_crops"]  # crops are on by default


# 15. a kill at random moments: the earlier output survives, the next run clears what the killed ones left

def test_kills_at_random_moments_never_damage_the_earlier_output(cli_env, run, small_drive, tmp_path):
    out = tmp_path / "signs.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "CROPS": True})
    before, crops = digest(out), sorted(p.name for p in (tmp_path / "signs_crops").iterdir())
    finished_before = finished(out)
    moments = random.Random(46).sample(range(1, 60), 4)  # tenths of the run: starting, mapping, writing
    started = time.monotonic()
    probe = subprocess.run([QGIS_PROCESS, "run", "signmapper:mapsigns", "--", f"DRIVE={small_drive}",
                            f"OUTPUT={tmp_path / 'probe.gpkg'}", "WORKERS=1"], env=cli_env, capture_output=True,
                           timeout=900)
    assert probe.returncode == 0
    span = time.monotonic() - started
    (tmp_path / "probe.gpkg").unlink()
    shutil.rmtree(tmp_path / "probe_crops")  # crops are on by default
    left_behind = set()
    for moment in moments:
        victim = subprocess.Popen([QGIS_PROCESS, "run", "signmapper:mapsigns", "--", f"DRIVE={small_drive}",
                                   f"OUTPUT={out}", "WORKERS=1", "CROPS=true"], env=cli_env,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        time.sleep(span * moment / 60)
        os.killpg(victim.pid, signal.SIGKILL)  # the run and any worker it started, as the system kills them
        victim.wait()
        if victim.returncode == 0:  # it finished first: its own complete output
            before, crops = digest(out), sorted(p.name for p in (tmp_path / "signs_crops").iterdir())
        elif digest(out) != before:  # killed after putting its output in place: complete, as the earlier one
            assert finished(out) == finished_before
            before = digest(out)
        assert digest(out) == before and QgsVectorLayer(f"{out}|layername=signs", "s", "ogr").featureCount() >= 2
        assert sorted(p.name for p in (tmp_path / "signs_crops").iterdir()) == crops
        left_behind |= {p.name for p in tmp_path.iterdir() if p.name.startswith(".")}
    assert left_behind  # some kill came while a partial output was being written
    # the next run writing into the folder, to another file, clears what the killed runs left
    code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=small_drive,
                                     OUTPUT=tmp_path / "trajectory.gpkg")
    assert code == 0, log
    assert sorted(p.name for p in tmp_path.iterdir()) == ["signs.gpkg", "signs_crops", "trajectory.gpkg"]


def test_what_killed_runs_left_is_cleared_by_the_next_run_into_the_folder(cli_env, tmp_path):
    """What a kill leaves, as earlier versions and this one name it, cleared by a run to another file of the
    folder (before: kept until a run to the same path); the user's own hidden files stay."""
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    (tmp_path / ".signs.partial.gpkg").write_bytes(b"\0" * 4 * 1024 * 1024)
    (tmp_path / ".signs.partial.gpkg-journal").write_bytes(b"\0")
    (tmp_path / ".drive2.partial-99999999").mkdir()
    (tmp_path / ".drive2.partial-99999999" / "poses.csv").write_text("id,time\n")
    (tmp_path / ".old.gpkg.signmapper-partial").mkdir()
    (tmp_path / ".old.gpkg.signmapper-lock").write_text("process 99999999, since 2026-12-06 09:00:00")
    (tmp_path / ".notes").write_text("the user's own hidden file")
    code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive,
                                     OUTPUT=tmp_path / "trajectory.gpkg")
    assert code == 0, log
    assert sorted(p.name for p in tmp_path.iterdir()) == [".notes", "drive", "trajectory.gpkg"]


def test_a_live_runs_partial_output_is_left_alone(cli_env, tmp_path):
    """The files of a run still writing (its lock held, here by this test) are not stale."""
    from signmapper_core.output.target_lock import TargetLock

    drive = make_drive(tmp_path / "drive", n_pairs=2)
    with TargetLock(tmp_path / "live.gpkg"):
        (tmp_path / ".live.gpkg.signmapper-partial").mkdir()
        code, _data, log = run_algorithm(cli_env, "signmapper:drivetrajectory", DRIVE=drive,
                                         OUTPUT=tmp_path / "trajectory.gpkg")
        assert code == 0, log
        assert sorted(p.name for p in tmp_path.iterdir()) == [
            ".live.gpkg.signmapper-lock", ".live.gpkg.signmapper-partial", "drive", "trajectory.gpkg"]


# 6. paths too long for the file system: a message, never a traceback or an abort

@pytest.mark.parametrize("algorithm", ["signmapper:mapsigns", "signmapper:drivetrajectory"])
@pytest.mark.parametrize("where", ["drive", "output"])
def test_a_path_too_long_is_a_message(cli_env, small_drive, tmp_path, algorithm, where):
    long_name = tmp_path / ("a" * 300)
    drive, out = (long_name, tmp_path / "out.gpkg") if where == "drive" else (small_drive, long_name / "out.gpkg")
    code, _data, log = run_algorithm(cli_env, algorithm, DRIVE=drive, OUTPUT=out)
    assert code == 1, log  # not 134: qgis_process aborted on the traceback
    assert "Traceback" not in log and "OSError" not in log
    label = "Drive folder" if where == "drive" else ("Output GeoPackage" if algorithm.endswith("mapsigns")
                                                     else "Trajectory points")
    assert f"{label}: the name aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa…aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa in " in log
    assert "has 300 characters, more than the 255 the file system allows; use a shorter name" in log


def test_a_nested_path_too_long_is_a_message(cli_env, small_drive, tmp_path):
    deep = tmp_path.joinpath(*["abcdefghi"] * 1000)
    code, _data, log = run_algorithm(cli_env, "signmapper:mapsigns", DRIVE=deep, OUTPUT=tmp_path / "o.gpkg")
    assert code == 1 and "Traceback" not in log
    assert "characters, more than the 4096 the system allows for a path; use a shorter one" in log


# 7. a full disk: said where it happens, the earlier output as it was

FULL_DISK = """\
set -e
{prepare}
cp {earlier} {disk}/signs.gpkg
sha256sum {disk}/signs.gpkg | cut -d' ' -f1 > {report}/before
{fill}
set +e
{limit}
{qgis_process} run signmapper:mapsigns -- DRIVE={drive} OUTPUT={disk}/signs.gpkg WORKERS=1 > {report}/log 2>&1
echo $? > {report}/code
sha256sum {disk}/signs.gpkg | cut -d' ' -f1 > {report}/after
ls -A {disk} > {report}/files
"""


def tmpfs_allowed() -> bool:
    """Whether a private mount namespace can mount a small tmpfs here (as root, or in a user namespace)."""
    try:
        return subprocess.run(["unshare", "-rm", "sh", "-c", "mount -t tmpfs -o size=64k tmpfs /mnt"],
                              capture_output=True, timeout=30).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


@pytest.mark.parametrize("free", [0.5, 0.9], ids=["half an output free", "nearly an output free"])
@pytest.mark.parametrize("disk_kind", ["tmpfs", "file size limit"])
def test_a_full_disk_is_said_and_the_earlier_output_survives(cli_env, run, small_drive, tmp_path, free, disk_kind):
    earlier = tmp_path / "earlier.gpkg"
    run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(earlier)})
    size_kb = earlier.stat().st_size // 1024
    report, disk = tmp_path / "report", tmp_path / "disk"
    report.mkdir()
    disk.mkdir()
    if disk_kind == "tmpfs":  # a small file system of its own: the new output runs out of space part way
        if not tmpfs_allowed():
            pytest.skip("no private mount namespace for a small tmpfs on this machine (the file size limit runs)")
        prepare = f"mount -t tmpfs -o size={2 * size_kb}k tmpfs {disk}"
        fill, limit = f"head -c {int((1 - free) * size_kb)}k /dev/zero > {disk}/filler", ""
        command = ["unshare", "-rm", "sh", "-c"]
    else:  # anywhere: no file may grow beyond the limit, so the writes fail as on a full disk
        prepare, fill = "", f"touch {disk}/filler"
        limit = f"trap '' XFSZ; ulimit -f {int(2 * free * size_kb)}"  # in 512-byte blocks
        command = ["sh", "-c"]
    script = FULL_DISK.format(prepare=prepare, disk=disk, earlier=earlier, report=report, fill=fill, limit=limit,
                              qgis_process=QGIS_PROCESS, drive=small_drive)
    done = subprocess.run(command + [script], env=cli_env, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    log = (report / "log").read_text()
    assert (report / "code").read_text().strip() == "1", log
    assert f"{disk / 'signs.gpkg'}: could not write " in log, log
    if disk_kind == "tmpfs":
        assert f"(the disk holding {disk} is full, " in log, log
    assert f"Nothing written; {disk / 'signs.gpkg'} is as it was." in log and "Traceback" not in log
    assert (report / "after").read_text() == (report / "before").read_text()
    assert (report / "files").read_text().split() == ["filler", "signs.gpkg"]


# 16. what qgis_process prints: warnings as warnings, each error once

def test_warnings_are_no_errors_and_an_error_is_shown_once(cli_env, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    with open(drive / "truth.csv", "a") as fh:
        fh.write("s002,2.01,2600010,1200003,north,0.6,0.6,270\n")
    done = subprocess.run([QGIS_PROCESS, "run", "signmapper:drivetrajectory", "--", f"DRIVE={drive}",
                           f"OUTPUT={tmp_path / 't.gpkg'}"], env=cli_env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    log = done.stdout + done.stderr
    assert "WARNING:\t" + str(drive / "truth.csv") in log and "ERROR:" not in log
    missing = tmp_path / "missing"
    message = f"Invalid drive: {missing}: drive folder does not exist or is not a folder"
    for json_mode in ([], ["--json"]):  # --json prints no feedback of a failed run: the message is still there once
        done = subprocess.run([QGIS_PROCESS, *json_mode, "run", "signmapper:drivetrajectory", "--", f"DRIVE={missing}",
                               f"OUTPUT={tmp_path / 'u.gpkg'}"], env=cli_env, capture_output=True, text=True,
                              timeout=300)
        assert done.returncode == 1
        assert (done.stdout + done.stderr).count(message) == 1, done.stdout + done.stderr
        assert (f"ERROR:\t{message}" if not json_mode else message) in done.stderr


def test_mapsigns_warnings_reach_qgis_process_as_warnings(cli_env, tmp_path):
    """The drive's warnings (here case 11: an image whose poses.csv row is missing) while mapping with workers."""
    drive = make_drive(tmp_path / "drive", n_pairs=4)
    lines = (drive / "poses.csv").read_text().splitlines()
    (drive / "poses.csv").write_text("\n".join(lines[:3] + lines[4:]) + "\n")
    done = subprocess.run([QGIS_PROCESS, "run", "signmapper:mapsigns", "--", f"DRIVE={drive}",
                           f"OUTPUT={tmp_path / 'signs.gpkg'}", "WORKERS=2"], env=cli_env, capture_output=True,
                          text=True, timeout=600)
    log = done.stdout + done.stderr
    assert done.returncode == 0, log
    assert f"WARNING:\t{drive / 'left'}/: 1 image has no row in poses.csv and is not mapped (first: 000002.png)" \
        in log, log
    assert "ERROR" not in log and "Traceback" not in log, log


def test_an_output_error_in_processing_run_names_the_file(run, tmp_path, monkeypatch):
    from sign_mapper.gpkg import output

    def full(self, feature, flags=None):
        raise output.write_failure(self.target, self.what, "database or disk is full")

    monkeypatch.setattr(output.CheckedSink, "addFeature", full)
    monkeypatch.setattr(output.CheckedSink, "addFeatures", full)
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    out = user_geopackage(tmp_path / "keep.gpkg")
    before = digest(out)
    feedback = Recorder()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": f"{out}|layername=trajectory"},
            feedback=feedback)
    assert str(info.value).startswith(f"{out}: could not write the layer 'trajectory' (Trajectory points): "
                                      "database or disk is full")
    assert str(info.value).endswith(f"Nothing written; {out} is as it was.")
    assert digest(out) == before and sorted(p.name for p in tmp_path.iterdir()) == ["drive", "keep.gpkg"]
    shutil.rmtree(tmp_path / "drive")
