"""Signalo export and reading against a real PostgreSQL/PostGIS with Signalo's own data model (no QGIS)."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import psycopg2
import pytest
from drive_fixtures import START, straight_poses

from signmapper_core.changes.compare import CONFIRMED, ChangeConfig, MappedSign, compare
from signmapper_core.drive.reader import PairRecord
from signmapper_core.geometry import Camera
from signmapper_core.signalo import SignaloError, connect
from signmapper_core.signalo.export import ExportSign, export_signs, plan_supports, sign_comment
from signmapper_core.signalo.inventory import read_inventory

E0, N0, H0 = START
RUN = "5b8f2d2e-1111-4c3e-9d9a-000000000001"


def sign(sign_id, type_id, ahead, dz=0.0, azimuth=270.0, shape="circle", status="accepted", right=4.0):
    return ExportSign(sign_id, type_id, np.array([E0 + ahead, N0 - right, H0 + dz]), azimuth, 0.6, 0.6, "normal",
                      shape, status, 0.91, 0.83, 5, 0.02, 1.9 + dz)


SIGNS = [
    sign(1, "2.30-50", 20.0, dz=0.35),
    sign(2, "3.05", 20.03, dz=-0.35),  # same pole as 1, below it
    sign(3, "2.02", 35.0, shape="triangle-down"),
    sign(4, "2.59.1-30", 50.0, shape="rectangle"),  # Tempo-30 zone: Signalo's 2.59.1-30
    sign(5, "2.10", 60.0),  # not in Signalo's list of official signs
    sign(6, "2.01", 35.05, azimuth=95.0, shape="octagon"),  # back to back with 3: same pole, other azimut
]


def rows(dsn, sql):
    conn = psycopg2.connect(dsn)
    try:
        with conn.cursor() as cur:
            cur.execute(sql)
            return cur.fetchall()
    finally:
        conn.close()


SIGN_ROWS = """SELECT s.fk_official_sign, s.inscription_1, ST_X(su.geometry), ST_Y(su.geometry), a.azimut, f.rank,
       s.dimension_1, s.dimension_2, s.comment, su.height_free_under_signal, su.id
FROM signalo_db.sign s JOIN signalo_db.frame f ON f.id = s.fk_frame JOIN signalo_db.azimut a ON a.id = f.fk_azimut
JOIN signalo_db.support su ON su.id = a.fk_support ORDER BY s.comment"""


def test_supports_group_poles_and_face_directions():
    plans = plan_supports(SIGNS)
    assert [sorted(s.sign_id for s in p.signs) for p in plans] == [[1, 2], [3, 6], [4], [5]]
    assert [v for v, _ in plans[0].azimuts] == [270] and [s.sign_id for s in plans[0].azimuts[0][1]] == [1, 2]
    assert [v for v, _ in plans[1].azimuts] == [95, 270]
    assert plans[0].free_height_m == pytest.approx(1.9 - 0.35)
    assert plans[0].easting == pytest.approx(E0 + 20.015)


def test_export_writes_supports_azimuts_frames_and_official_signs(signalo_database):
    dsn = signalo_database("export")
    result = export_signs(connect(dsn), RUN, SIGNS)
    assert result.version == "1.4" and result.supports == 3
    assert sorted(i for i, _ in result.added) == [1, 2, 3, 4, 6] and result.unknown == [(5, "2.10")]
    found = rows(dsn, SIGN_ROWS)
    assert len(found) == 5
    by_sign = {int(r[8].split("sign=")[1].split("]")[0]): r for r in found}
    assert by_sign[1][:2] == ("2.30", "50") and by_sign[2][:2] == ("3.05", None)
    assert by_sign[4][0] == "2.59.1-30" and by_sign[3][0] == "2.02" and by_sign[6][0] == "2.01"
    assert by_sign[1][2] == pytest.approx(E0 + 20.015, abs=1e-3) and by_sign[1][3] == pytest.approx(N0 - 4, abs=1e-3)
    assert by_sign[3][2] == pytest.approx(E0 + 35.025, abs=1e-3)
    assert (by_sign[1][4], by_sign[1][5], by_sign[2][5]) == (270, 1, 2)  # upper frame first
    assert (by_sign[3][4], by_sign[6][4]) == (270, 95) and by_sign[3][10] == by_sign[6][10]
    assert float(by_sign[1][6]) == pytest.approx(0.3) and by_sign[1][7] is None  # round: radius
    assert (float(by_sign[3][6]), float(by_sign[3][7])) == (0.6, 0.6)
    assert by_sign[1][8].startswith(f"[signmapper run={RUN} sign=1] Sign Mapper 2.30-50")
    assert "classification 0.83" in by_sign[1][8] and float(by_sign[1][9]) == pytest.approx(1.55)


def plate(plate_id, of, template_id, text, dz, ahead=20.0, height=0.2):
    return ExportSign(plate_id, template_id, np.array([E0 + ahead, N0 - 4.0, H0 + dz]), 270.0, 0.6, height,
                      "normal-1", "rectangle", "accepted", 0.95, 0.9, 4, 0.02, None, plate_of=of, text=text)


PLATES = [
    plate(11, 2, "5.00-2", "Mo–Fr / 7–19 h", -0.35 - 0.3 - 0.2, height=0.3),  # below 3.05, the lower sign of pole 1
    plate(12, 1, "5.01", "200 m", 0.35 + 0.3 + 0.15),  # above 2.30-50
    plate(13, 3, "5.00-exception", "ausgenommen / Zubringerdienst", -0.6, ahead=35.0, height=0.3),
    plate(14, 4, "5.31", None, -0.6, ahead=50.0),  # a pictogram plate: bicycles
    plate(15, 5, "5.01", "50 m", -0.45, ahead=60.0),  # its sign 2.10 is not in Signalo
    plate(16, 6, "5.02-r", "150 m", -0.6, ahead=35.05, height=0.42),  # a direction plate, pointing right
    plate(17, 1, "plate", "excepté / bus / taxi", 0.35 + 0.3 + 0.15 + 0.25),  # untyped: typed by its text
]

PLATE_ROWS = """SELECT s.comment, s.fk_official_sign, s.inscription_1, s.inscription_2, s.rank, s.fk_frame,
       s.dimension_1, s.dimension_2, s.fk_parent, s.id, s.natural_direction_or_left FROM signalo_db.sign s"""


def test_plates_are_written_into_their_signs_frame_as_their_official_type(signalo_database):
    dsn = signalo_database("plates")
    result = export_signs(connect(dsn), RUN, SIGNS + PLATES)
    assert sorted(i for i, _ in result.added) == [1, 2, 3, 4, 6, 11, 12, 13, 14, 16, 17]
    assert result.plates_without_sign == [(15, 5)] and result.supports == 3
    assert "1 plates not written (their sign is not written by this export: plate 15 of sign 5)" in result.summary()
    by_sign = {int(r[0].split("sign=")[1].split("]")[0]): r[1:] for r in rows(dsn, PLATE_ROWS)}
    assert by_sign[11][:4] == ("5.00-2", "Mo–Fr", "7–19 h", 2) and by_sign[11][4] == by_sign[2][4]
    assert by_sign[2][3] == 1  # the sign first in its frame, its plate below it second
    assert by_sign[17][:4] == ("5.00-exception", "bus", "taxi", 1)  # two plates above 2.30-50: the top one first
    assert by_sign[12][:4] == ("5.01", "200 m", None, 2) and by_sign[1][3] == 3
    assert by_sign[12][4] == by_sign[1][4] != by_sign[2][4]
    assert by_sign[13][:3] == ("5.00-exception", "Zubringerdienst", None)
    assert by_sign[14][:3] == ("5.31", None, None) and by_sign[14][4] == by_sign[4][4]
    assert (float(by_sign[11][5]), float(by_sign[11][6])) == (0.3, 0.6)  # a rectangle: height, width
    # each plate's parent is the sign of its frame; signs have none
    for plate_id, sign_id in ((11, 2), (12, 1), (13, 3), (14, 4), (16, 6), (17, 1)):
        assert by_sign[plate_id][7] == by_sign[sign_id][8]
    assert all(by_sign[i][7] is None for i in (1, 2, 3, 4, 6))
    # a direction plate: Signalo's id, its direction on the sign (left, Signalo's default, for every other sign)
    assert by_sign[16][:3] == ("5.02", "150 m", None) and by_sign[16][9] is False
    assert all(by_sign[i][9] is True for i in by_sign if i != 16)
    comment = rows(dsn, "SELECT comment FROM signalo_db.sign WHERE fk_official_sign = '5.00-2'")[0][0]
    assert 'plate of sign 2, text "Mo–Fr / 7–19 h"' in comment
    frames = rows(dsn, "SELECT count(*) FROM signalo_db.frame")[0][0]
    assert frames == 5  # plates add no frame of their own


def test_second_export_of_the_same_run_adds_nothing(signalo_database):
    dsn = signalo_database("twice")
    export_signs(connect(dsn), RUN, SIGNS)
    again = export_signs(connect(dsn), RUN, SIGNS)
    assert again.added == [] and sorted(again.already) == [1, 2, 3, 4, 6] and again.supports == 0
    assert rows(dsn, "SELECT count(*) FROM signalo_db.sign")[0][0] == 5
    assert rows(dsn, "SELECT count(*) FROM signalo_db.support")[0][0] == 3
    other = export_signs(connect(dsn), "another-run", SIGNS[:1])
    assert len(other.added) == 1


def test_update_instead_of_adding_moves_a_lonely_pole(signalo_database):
    dsn = signalo_database("update")
    first = dict(export_signs(connect(dsn), RUN, SIGNS).added)
    moved = ExportSign(**{**sign(9, "2.59.1-30", 51.0).__dict__, "update_id": first[4], "moved": True})
    result = export_signs(connect(dsn), "run-2", [moved])
    assert result.updated == [(9, first[4])] and result.added == []
    (x, comment), = rows(dsn, f"SELECT ST_X(su.geometry), s.comment FROM signalo_db.sign s JOIN signalo_db.frame f "
                              f"ON f.id = s.fk_frame JOIN signalo_db.azimut a ON a.id = f.fk_azimut JOIN "
                              f"signalo_db.support su ON su.id = a.fk_support WHERE s.id = '{first[4]}'")
    assert x == pytest.approx(E0 + 51.0, abs=1e-3) and comment.startswith("[signmapper run=run-2 sign=9]")
    assert rows(dsn, "SELECT count(*) FROM signalo_db.sign")[0][0] == 5


def test_older_data_model_is_refused_and_nothing_written(signalo_database):
    dsn = signalo_database("old", up_to="1.1")
    with pytest.raises(SignaloError, match=r"Signalo data model 1\.1.*1\.2 to 1\.x"):
        export_signs(connect(dsn), RUN, SIGNS)
    assert rows(dsn, "SELECT count(*) FROM signalo_db.support")[0][0] == 0


def test_changed_columns_are_named_and_nothing_written(signalo_database):
    dsn = signalo_database("edited")
    conn = psycopg2.connect(dsn)
    with conn, conn.cursor() as cur:
        cur.execute("ALTER TABLE signalo_db.sign RENAME COLUMN inscription_1 TO inscription_one")
    conn.close()
    with pytest.raises(SignaloError, match=r"lacks signalo_db\.sign\.inscription_1"):
        export_signs(connect(dsn), RUN, SIGNS)
    assert rows(dsn, "SELECT count(*) FROM signalo_db.sign")[0][0] == 0


def test_a_failure_midway_rolls_everything_back(signalo_database):
    dsn = signalo_database("rollback")
    conn = psycopg2.connect(dsn)
    with conn, conn.cursor() as cur:  # the 3.05 insert fails after other rows were written
        cur.execute("ALTER TABLE signalo_db.sign ADD CONSTRAINT no_305 CHECK (fk_official_sign <> '3.05')")
    conn.close()
    with pytest.raises(SignaloError, match="nothing was written"):
        export_signs(connect(dsn), RUN, SIGNS)
    assert rows(dsn, "SELECT count(*) FROM signalo_db.support")[0][0] == 0


def test_broken_connection_is_a_clear_error(postgres):
    with pytest.raises(SignaloError, match="cannot connect to test db"):
        connect(postgres.dsn_for("no_such_database"), "test db")
    with pytest.raises(SignaloError, match="cannot connect"):
        connect(f"host=127.0.0.1 port={postgres.port + 1 if postgres.port < 65535 else 1} dbname=x connect_timeout=2")


def test_round_trip_reads_back_every_sign_confirmed(signalo_database):
    dsn = signalo_database("roundtrip")
    export_signs(connect(dsn), RUN, SIGNS)
    catalogue_ids = {"2.30-50", "3.05", "2.02", "2.59.1-30", "2.10", "2.01"}
    inventory, others, crs = read_inventory(connect(dsn), catalogue_ids)
    assert crs == "EPSG:2056" and others == 0
    assert sorted(s.template_id for s in inventory) == ["2.01", "2.02", "2.30-50", "2.59.1-30", "3.05"]
    by_type = {s.template_id: s for s in inventory}
    assert by_type["2.01"].facing == 95.0 and by_type["2.02"].facing == 270.0
    # heights rebuilt from the free height under the lowest sign and the sizes above it
    assert by_type["3.05"].height_above_road_m == pytest.approx(1.55 + 0.3)
    assert by_type["2.30-50"].height_above_road_m == pytest.approx(1.55 + 0.6 + 0.3)
    camera = Camera(width=1920, height=1080, fx=1750.0, fy=1750.0, cx=959.5, cy=539.5, baseline_m=0.9)
    records = [PairRecord(i, pid, t, pose, Path(f"{pid}.jpg"), None, None)
               for i, (pid, t, pose) in enumerate(straight_poses(40))]
    mapped = [MappedSign(s.sign_id, s.template_id, s.position) for s in SIGNS if s.sign_id != 5]
    report = compare(inventory, mapped, camera, records, ChangeConfig(camera_height_m=2.4))
    assert [c.verdict for c in report.changes] == [CONFIRMED] * 5


def test_a_sign_for_review_says_why_in_its_signalo_comment():
    """needs_validation says that a person should look; the comment says what to look for."""
    held = replace(sign(7, "2.30-50", 20.0, status="review"), review_reason="seen in one pair only")
    comment = sign_comment(RUN, held)
    assert comment.endswith("status review (seen in one pair only)")
    assert sign_comment(RUN, sign(8, "2.30-50", 20.0)).endswith("status accepted")
