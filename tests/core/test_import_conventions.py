"""Angles read with the wrong convention are caught against the direction of travel (issue 45, item 4.1).

Pose tables of a vehicle driving a long bend (headings from 20 to 220 degrees) are
written here with the angles of one convention and read with another; the
vehicle's heading is its course, so every reading can be judged by hand.
"""

import numpy as np
import pytest
from pyproj import Transformer

from signmapper_core.errors import ImportInputError
from signmapper_core.importdrive import Orientation
from signmapper_core.importdrive.camera_poses import body_poses
from signmapper_core.importdrive.crs_steps import CrsSteps
from signmapper_core.importdrive.kitti import INPUT_CRS as KITTI_CRS
from signmapper_core.importdrive.kitti import oxts_table
from signmapper_core.importdrive.pose_table import read_pose_table

ORIGIN = np.array([2600000.0, 1200000.0])   # LV95 at Bern: grid and true north agree within 0.001 degrees
NAMES = {"ned_ypr": ("yaw", "pitch", "roll"), "enu_ypr": ("yaw", "pitch", "roll"),
         "camera_hpr": ("heading", "pitch", "roll")}


def bend(n=60, step=1.0, first=20.0, turn=200.0):
    """(positions (n, 2), headings (n,)): a vehicle driving a bend (steps along the mean heading of their ends, as
    the chords of an arc run)."""
    headings = first + turn * np.linspace(0.0, 1.0, n)
    middle = np.radians((headings[:-1] + headings[1:]) / 2.0)
    steps = step * np.column_stack([np.sin(middle), np.cos(middle)])
    return ORIGIN + np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)]), headings


def recorded(name, headings):
    """The angles a system recording in convention ``name`` writes for a level vehicle with these headings."""
    yaw = 90.0 - headings if name == "enu_ypr" else headings
    return np.column_stack([yaw % 360.0, np.full(len(yaw), 0.4), np.full(len(yaw), -0.3)])


def write_table(path, name, positions, angles):
    a, b, c = NAMES[name]
    rows = [f"time,easting,northing,height,{a},{b},{c}"]
    rows += [f"{i * 0.1:.1f},{e:.3f},{n:.3f},500.0,{x:.4f},{y:.4f},{z:.4f}"
             for i, ((e, n), (x, y, z)) in enumerate(zip(positions, angles))]
    path.write_text("\n".join(rows) + "\n")
    return path


def read_as(path, name, unit="deg"):
    """``body_poses`` of a table read in convention ``name``; returns the warnings."""
    table = read_pose_table(path, NAMES[name], need_ids=False, need_times=True, geographic=False)
    warnings = []
    body_poses(table, Orientation(name, unit, "auto"), CrsSteps("EPSG:2056", "EPSG:2056"), warnings.append)
    return warnings


@pytest.mark.parametrize("written, read", [("ned_ypr", "enu_ypr"), ("enu_ypr", "ned_ypr")])
def test_navigation_angles_read_in_the_other_frame_are_refused_naming_the_right_one(tmp_path, written, read):
    positions, headings = bend()
    path = write_table(tmp_path / "trajectory.csv", written, positions, recorded(written, headings))
    # read in the other frame a heading h becomes 90 - h: misses |2h - 90| wrapped, for h from 20 to 220 a median
    # of 81 degrees (uniform over -50..350: 50 share below 50, 180 below 180, 170 from 180 down to 10)
    with pytest.raises(ImportInputError) as caught:
        read_as(path, read)
    message = str(caught.value)
    assert message.startswith(f"{path}, line 2, field 'yaw': the forward direction of the {read} angles differs from "
                              "the direction of travel by ")
    miss = float(message.split("by ")[1].split(" degrees")[0])
    assert 78 <= miss <= 84
    assert "(median over 59 moving epochs)" in message
    assert message.endswith(f"read so, they follow it (median miss 0 degrees); set the angle convention to {written}")
    # read as written, the same table passes without a word
    assert read_as(path, written) == []


def test_a_vehicle_reversing_briefly_passes(tmp_path):
    positions, headings = bend(n=40, turn=30.0)
    back = positions[-1] - np.linspace(0.5, 5.0, 10)[:, None] * np.array([np.sin(np.radians(50.0)),
                                                                          np.cos(np.radians(50.0))])
    again = back[-1] + np.linspace(1.0, 12.0, 12)[:, None] * np.array([np.sin(np.radians(50.0)),
                                                                      np.cos(np.radians(50.0))])
    track = np.vstack([positions, back, again])
    facing = np.concatenate([headings, np.full(22, 50.0)])   # reversing keeps the vehicle's heading
    path = write_table(tmp_path / "reversing.csv", "ned_ypr", track, recorded("ned_ypr", facing))
    assert read_as(path, "ned_ypr") == []
    with pytest.raises(ImportInputError, match="look like ned_ypr"):
        read_as(path, "enu_ypr")


def test_a_vehicle_standing_still_cannot_be_checked_and_says_so(tmp_path):
    jitter = np.random.default_rng(4).normal(0.0, 0.02, (200, 2))    # a standing receiver's 2 cm
    positions = ORIGIN + jitter
    path = write_table(tmp_path / "still.csv", "ned_ypr", positions, recorded("ned_ypr", np.full(200, 20.0)))
    # ENU read as NED would be refused if the vehicle moved: standing still it is a warning
    assert read_as(path, "enu_ypr") == [
        f"{path}: the angle convention (enu_ypr) could not be checked against the direction of travel: the vehicle "
        "stands still"]
    short, headings = bend(n=3, step=0.6)
    path = write_table(tmp_path / "short.csv", "ned_ypr", short, recorded("ned_ypr", headings))
    assert read_as(path, "enu_ypr") == [
        f"{path}: the angle convention (enu_ypr) could not be checked against the direction of travel: the vehicle "
        "moves too little (2 stretch(es) of 0.5 m, 3 needed)"]


def test_a_camera_looking_sideways_is_a_warning_not_an_error(tmp_path):
    """Camera heading/pitch/roll of a camera turned 90 degrees to the right: no convention follows the travel."""
    positions, headings = bend()
    path = write_table(tmp_path / "eo.csv", "camera_hpr", positions, recorded("camera_hpr", headings + 90.0))
    warnings = read_as(path, "camera_hpr")
    assert len(warnings) == 1 and warnings[0].startswith(
        f"{path}: the forward direction of the camera_hpr angles differs from the direction of travel by 90 degrees "
        "(median over 59 moving epochs), and no other angle convention follows the travel")


def test_radians_of_the_wrong_frame_are_named_too(tmp_path):
    positions, headings = bend()
    angles = np.radians(recorded("enu_ypr", headings))
    path = write_table(tmp_path / "rad.csv", "enu_ypr", positions, angles)
    assert read_as(path, "enu_ypr", "rad") == []
    with pytest.raises(ImportInputError, match="the angles look like enu_ypr"):
        read_as(path, "ned_ypr", "rad")


def write_oxts(folder, n=50):
    """KITTI OXTS packets of a car in Karlsruhe driving a bend: lat, lon, alt, roll, pitch, yaw (radians, counter-
    clockwise from east), the other 24 values zero."""
    positions, headings = bend(n=n, step=0.9, first=250.0, turn=-120.0)
    local = positions - ORIGIN + np.array([456000.0, 5429000.0])          # UTM 32N
    lon, lat = Transformer.from_crs("EPSG:32632", "EPSG:4326", always_xy=True).transform(local[:, 0], local[:, 1])
    data = folder / "oxts" / "data"
    data.mkdir(parents=True)
    ids = [f"{i:010d}" for i in range(n)]
    for frame, x, y, heading in zip(ids, lon, lat, headings):
        values = [y, x, 116.0, 0.02, 0.01, np.radians(90.0 - heading)] + [0.0] * 24
        (data / f"{frame}.txt").write_text(" ".join(f"{v:.12g}" for v in values) + "\n")
    return ids


def test_kitti_oxts_pass_as_enu_and_are_named_when_read_as_ned(tmp_path):
    ids = write_oxts(tmp_path)
    table = oxts_table(tmp_path, ids)
    steps = CrsSteps(KITTI_CRS, "EPSG:32632+5773")
    warnings = []
    body_poses(table, Orientation("enu_ypr", "rad", "true"), steps, warnings.append)
    assert warnings == []
    with pytest.raises(ImportInputError, match=r"0000000000\.txt, line 1, field 'yaw': the forward direction of the "
                                               r"ned_ypr angles .* look like enu_ypr"):
        body_poses(table, Orientation("ned_ypr", "rad", "true"), steps)
