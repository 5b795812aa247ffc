"""Pose tables, trajectory interpolation to image times, angle units, image pairing."""

import numpy as np
import pytest

from signmapper_core.errors import ImportInputError
from signmapper_core.importdrive.angle_units import check_radians_as_degrees, to_degrees
from signmapper_core.importdrive.attitude import convention, forward_heading
from signmapper_core.importdrive.image_pairs import list_pairs
from signmapper_core.importdrive.interpolate import check_increasing, interpolate
from signmapper_core.importdrive.pose_table import read_image_times, read_pose_table
from signmapper_core.importdrive.travel import travel_legs

NED = convention("ned_ypr")


def write(path, text):
    path.write_text(text)
    return path


def test_columns_are_found_by_their_usual_names_and_separators(tmp_path):
    path = write(tmp_path / "eo.txt", "# exported by some software\nImage;Easting;Northing;H;Omega;Phi;Kappa\n"
                 "a.jpg;2600000.5;1200000.25;500;90;1;2\n\nb.jpg;2600001.5;1200000.75;501;91;0;-2\n")
    table = read_pose_table(path, ("omega", "phi", "kappa"), need_ids=True, need_times=False, geographic=False)
    assert table.ids == ["a.jpg", "b.jpg"] and table.times is None
    assert table.xyz[1] == pytest.approx([2600001.5, 1200000.75, 501]) and table.angles[1] == pytest.approx([91, 0, -2])
    assert table.lines.tolist() == [3, 5]
    spaced = write(tmp_path / "traj.txt", "time lat lon alt yaw pitch roll\n10.0  47.1 7.5 500 30 1 2\n")
    table = read_pose_table(spaced, ("yaw", "pitch", "roll"), need_ids=False, need_times=True, geographic=True)
    assert table.xyz[0] == pytest.approx([7.5, 47.1, 500])   # x is the longitude whatever the column order


def test_pose_table_errors_name_file_line_and_column(tmp_path):
    def read(text, **kw):
        return read_pose_table(write(tmp_path / "p.csv", text), ("yaw", "pitch", "roll"), need_ids=True,
                               need_times=False, geographic=kw.get("geographic", False))

    with pytest.raises(ImportInputError, match=r"line 1, field 'roll': header lacks a column for roll"):
        read("id,x,y,z,yaw,pitch\n1,0,0,0,0,0\n")
    with pytest.raises(ImportInputError, match=r"p.csv, line 3, field 'pitch': 'n/a' is not a number"):
        read("id,x,y,z,yaw,pitch,roll\n1,0,0,0,0,0,0\n2,0,0,0,0,n/a,0\n")
    with pytest.raises(ImportInputError, match=r"line 3, field 'id': image '1' repeats line 2"):
        read("id,x,y,z,yaw,pitch,roll\n1,0,0,0,0,0,0\n1,0,0,0,0,0,0\n")
    with pytest.raises(ImportInputError, match="is not a latitude.*projected"):
        read("id,x,y,z,yaw,pitch,roll\n1,2600000,1200000,0,0,0,0\n", geographic=True)
    with pytest.raises(ImportInputError, match="has 6 fields, the header has 7"):
        read("id,x,y,z,yaw,pitch,roll\n1,0,0,0,0,0\n")


def test_image_times(tmp_path):
    times = read_image_times(write(tmp_path / "t.csv", "image,gps_time\na,100.5\nb,100.7\n"))
    assert times == {"a": (100.5, 2), "b": (100.7, 3)}


def rotations(yaws):
    return np.stack([NED.rotation((y, 0, 0)) for y in yaws])


def test_interpolation_halfway_in_position_and_turn():
    centres = np.array([[0, 0, 0], [10, 20, 2.0]])
    centre, rotation = interpolate(np.array([0.0, 1.0]), centres, rotations([350.0, 30.0]), np.array([0.5, 0.25]),
                                   ["a", "b"], "traj.csv", "image times")
    assert centre[0] == pytest.approx([5, 10, 1]) and centre[1] == pytest.approx([2.5, 5, 0.5])
    # the shortest turn from 350 to 30 degrees passes north: 10 at half way, 0 at a quarter
    assert forward_heading(rotation[0], NED) == pytest.approx(10)
    assert (forward_heading(rotation[1], NED) + 180) % 360 - 180 == pytest.approx(0, abs=1e-9)


def test_images_outside_the_trajectory_or_in_a_gap_are_errors_naming_them():
    times = np.array([0.0, 0.1, 0.2, 2.0])
    centres, rots = np.zeros((4, 3)), rotations([0, 0, 0, 0])
    with pytest.raises(ImportInputError, match=r"do not cover image 'late' at time 2\.500 s.*0\.000 to 2\.000"):
        interpolate(times, centres, rots, np.array([0.05, 2.5]), ["ok", "late"], "traj.csv", "image times")
    with pytest.raises(ImportInputError, match=r"gap of 1\.80 s around image 'in_gap'"):
        interpolate(times, centres, rots, np.array([1.0]), ["in_gap"], "traj.csv", "image times")
    with pytest.raises(ImportInputError, match=r"line 4, field 'time'.*must increase"):
        check_increasing(np.array([0.0, 0.1, 0.1]), "traj.csv", np.array([2, 3, 4]))


class Table:
    angle_names = ("yaw", "pitch", "roll")

    def where(self, row):
        return "traj.csv", row + 2


def track(heading_deg, n=20, step=1.0):
    d = np.array([np.sin(np.radians(heading_deg)), np.cos(np.radians(heading_deg))])
    return np.column_stack([np.outer(np.arange(n) * step, d), np.zeros(n)])


def headings(rows):
    return np.array([forward_heading(NED.rotation(r), NED) for r in rows])


def test_radians_given_as_degrees_are_recognised_against_the_direction_of_travel():
    course = 100.0
    radians = np.tile([np.radians(course), 0.01, -0.02], (20, 1))
    with pytest.raises(ImportInputError, match="look like radians given as degrees.*set the angle unit to radians"):
        check_radians_as_degrees(radians, travel_legs(track(course)), Table(), headings)
    # small angles in degrees that really are degrees: a drive heading 3 degrees east of north
    degrees = np.tile([3.0, 0.5, -0.3], (20, 1))
    check_radians_as_degrees(degrees, travel_legs(track(3.0)), Table(), headings)
    # a standing vehicle gives no course: nothing to judge
    check_radians_as_degrees(radians, travel_legs(np.zeros((20, 3))), Table(), headings)


def test_degrees_given_as_radians_are_an_error_naming_the_row():
    with pytest.raises(ImportInputError, match=r"line 3, field 'yaw': 95 is more than a full turn in radians"):
        to_degrees(np.array([[1.0, 0, 0], [95.0, 0, 0]]), "rad", Table())
    assert to_degrees(np.array([[np.pi, 0, 0]]), "rad", Table())[0, 0] == pytest.approx(180)


def test_pairs_from_two_folders_or_one_folder_with_patterns(tmp_path):
    for side in ("left", "right"):
        (tmp_path / side).mkdir()
        for name in ("img_2.png", "img_10.png", "notes.txt"):
            (tmp_path / side / name).write_bytes(b"")
    pairs = list_pairs(tmp_path / "left", tmp_path / "right")
    assert [p.id for p in pairs] == ["img_2", "img_10"]
    one = tmp_path / "one"
    one.mkdir()
    for name in ("0001_L.jpg", "0001_R.jpg", "0002_L.jpg", "0002_R.jpg"):
        (one / name).write_bytes(b"")
    pairs = list_pairs(one, None, "*_L.jpg", "*_R.jpg")
    assert [(p.id, p.left.name, p.right.name) for p in pairs] == [("0001", "0001_L.jpg", "0001_R.jpg"),
                                                                  ("0002", "0002_L.jpg", "0002_R.jpg")]


def test_an_image_without_its_partner_is_an_error_naming_it(tmp_path):
    for side in ("left", "right"):
        (tmp_path / side).mkdir()
    for name in ("a.png", "b.png"):
        (tmp_path / "left" / name).write_bytes(b"")
    (tmp_path / "right" / "a.png").write_bytes(b"")
    with pytest.raises(ImportInputError, match=r"b\.png: has no partner .*1 left image\(s\) without one, e\.g\. b"):
        list_pairs(tmp_path / "left", tmp_path / "right")
    with pytest.raises(ImportInputError, match="give a pattern for each"):
        list_pairs(tmp_path / "left")
    with pytest.raises(ImportInputError, match="exactly one"):
        list_pairs(tmp_path / "left", None, "*_*.png", "*_R.png")
