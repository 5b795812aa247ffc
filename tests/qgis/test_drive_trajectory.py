"""``signmapper:drivetrajectory`` through processing.run."""

import pytest
from drive_fixtures import make_drive, rewrite_line
from qgis.core import QgsProcessingException, QgsVectorLayer, QgsWkbTypes


def test_trajectory_points_and_track(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=5)
    out, track = tmp_path / "traj.gpkg", tmp_path / "track.gpkg"
    result = run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(out), "TRACK": str(track)})
    layer = QgsVectorLayer(result["OUTPUT"], "traj", "ogr")
    assert layer.isValid()
    assert layer.featureCount() == 5
    assert layer.wkbType() == QgsWkbTypes.PointZ
    assert layer.crs().authid() == "EPSG:2056"
    names = layer.fields().names()
    for field in ("pair_id", "pair_index", "time", "heading", "pitch", "roll", "image"):
        assert field in names
    features = sorted(layer.getFeatures(), key=lambda f: f["pair_index"])
    assert [f["pair_id"] for f in features] == ["000000", "000001", "000002", "000003", "000004"]
    last = features[-1].geometry().constGet()
    assert (last.x(), last.y(), last.z()) == pytest.approx((2600008.0, 1200000.0, 400.0))
    assert features[2]["time"] == pytest.approx(0.4)
    assert features[2]["heading"] == pytest.approx(90.0)
    assert features[2]["image"].endswith("left/000002.png")
    line_layer = QgsVectorLayer(result["TRACK"], "track", "ogr")
    assert line_layer.wkbType() == QgsWkbTypes.LineStringZ
    line = next(line_layer.getFeatures()).geometry()
    assert line.constGet().numPoints() == 5
    assert line.length() == pytest.approx(8.0)


def test_track_is_optional(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    result = run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "t.gpkg")})
    assert "TRACK" not in result or not result["TRACK"]


def test_invalid_drive_names_file_line_and_field(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=3)
    rewrite_line(drive / "poses.csv", 3, "000001,0.200,2600002.0,north,400.0,90.0,0.0,0.0")
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "t.gpkg")})
    message = str(info.value)
    assert "poses.csv, line 3, field 'northing'" in message


def test_non_default_crs_reaches_the_layer(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2, crs="EPSG:25832")
    result = run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "t.gpkg")})
    assert QgsVectorLayer(result["OUTPUT"], "t", "ogr").crs().authid() == "EPSG:25832"


@pytest.mark.parametrize("crs, authid", [
    ("EPSG:2056+5728", "EPSG:2056"),  # compound: LV95 + LN02 heights; QGIS 3.22 carries the horizontal part
    ("+proj=somerc +lat_0=46.9524055555556 +lon_0=7.43958333333333 +k_0=1 +x_0=2600000 +y_0=1200000 "
     "+ellps=bessel +towgs84=674.374,15.056,405.346,0,0,0,0 +units=m +no_defs +type=crs", "EPSG:2056"),
    ("+proj=utm +zone=32 +datum=WGS84 +units=m +no_defs", "EPSG:32632"),
])
def test_compound_crs_and_proj_strings_reach_the_layer(run, tmp_path, crs, authid):
    drive = make_drive(tmp_path / "drive", n_pairs=2, crs=crs)
    result = run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(tmp_path / "t.gpkg"),
                                                "TRACK": str(tmp_path / "track.gpkg")})
    for key in ("OUTPUT", "TRACK"):
        layer = QgsVectorLayer(result[key], "t", "ogr")
        assert layer.crs().isValid() and layer.crs().authid() == authid, layer.crs().description()
        assert not layer.crs().isGeographic()


def test_cancel_writes_nothing(run, tmp_path):
    from qgis.core import QgsProcessingFeedback

    drive = make_drive(tmp_path / "drive", n_pairs=20)
    out, track = tmp_path / "traj.gpkg", tmp_path / "track.gpkg"
    feedback = QgsProcessingFeedback()
    feedback.progressChanged.connect(lambda p: feedback.cancel() if p > 60 else None)
    with pytest.raises(QgsProcessingException, match="Cancelled; nothing written"):
        run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(out), "TRACK": str(track)},
            feedback=feedback)
    assert not out.exists() and not track.exists()


def test_output_that_is_a_folder_is_refused_before_reading_the_drive(run, tmp_path):
    drive = make_drive(tmp_path / "drive", n_pairs=2)
    folder = tmp_path / "trajectory.gpkg"
    folder.mkdir()
    with pytest.raises(QgsProcessingException) as info:
        run("signmapper:drivetrajectory", {"DRIVE": str(drive), "OUTPUT": str(folder)})
    assert str(info.value).splitlines()[-1] == f"Trajectory points: {folder} is an existing folder; give a file name"
