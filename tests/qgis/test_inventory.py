"""``changes`` and ``exporttosignalo`` on a mapped synthetic drive, with a real Signalo database read through QGIS."""

import numpy as np
import pytest
from qgis.core import (
    QgsDataSourceUri,
    QgsFeature,
    QgsField,
    QgsGeometry,
    QgsPoint,
    QgsProcessingException,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import QVariant

from signmapper_core.drive.reader import open_drive


@pytest.fixture(scope="module")
def mapped(small_drive, tmp_path_factory, sign_mapper, qgis_processing):
    """The small drive mapped once for the module: (signs GeoPackage, drive)."""
    import processing

    plugin = sign_mapper.classFactory(None)
    plugin.initProcessing()
    out = tmp_path_factory.mktemp("inventory") / "signs.gpkg"
    processing.run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out)})
    plugin.unload()
    return out, open_drive(small_drive)


def signs_of(path):
    layer = QgsVectorLayer(f"{path}|layername=signs", "signs", "ogr")
    assert layer.isValid()
    out = {}
    for f in layer.getFeatures():
        p = f.geometry().constGet()
        out[f["sign_id"]] = (f["template_id"], (p.x(), p.y(), p.z()))
    return out


def mapped_ids(path, truth, radius=0.5):
    """Truth sign id -> the template id of the one mapped sign within ``radius`` of it."""
    out = {}
    for t in truth:
        near = [tid for tid, xyz in signs_of(path).values() if np.linalg.norm(np.subtract(xyz, t.position)) < radius]
        if len(near) == 1:
            out[t.sign_id] = near[0]
    return out


def inventory_layer(rows):
    layer = QgsVectorLayer("PointZ?crs=EPSG:2056", "inventory", "memory")
    layer.dataProvider().addAttributes([QgsField("sign_type", QVariant.String), QgsField("facing", QVariant.Double)])
    layer.updateFields()
    for type_id, xyz, facing in rows:
        feature = QgsFeature(layer.fields())
        feature.setAttributes([type_id, facing])
        feature.setGeometry(QgsGeometry(QgsPoint(*xyz)))
        layer.dataProvider().addFeature(feature)
    return layer


def changes_of(path):
    layer = QgsVectorLayer(f"{path}|layername=changes", "changes", "ogr")
    assert layer.isValid()
    return [{name: f[name] for name in layer.fields().names()} for f in layer.getFeatures()]


def test_changes_on_an_edited_inventory_gives_the_expected_verdicts(run, mapped, tmp_path):
    path, drive = mapped
    truth = sorted(drive.truth, key=lambda t: t.sign_id)
    read_as = mapped_ids(path, truth)  # the inventory states what the mapping read: this tests the comparison only
    assert len(truth) == 3 and len(read_as) == 3
    removed, moved, retyped = truth
    track = np.array([r.pose.centre for r in drive.pairs])
    heading = np.radians(drive.pairs[0].pose.heading)
    across = np.array([np.cos(heading), -np.sin(heading), 0.0])
    rows = [
        (read_as[moved.sign_id], moved.position + np.array([0.6, 0.8, 0.0]), moved.facing),  # moved 1 m
        ("2.01" if read_as[retyped.sign_id] != "2.01" else "2.02", retyped.position, retyped.facing),  # type changed
        ("3.02", track[len(track) // 2] + 50.0 * across, 0.0),  # added outside the drive's view
    ]
    result = run("signmapper:changes", {
        "SIGNS": f"{path}|layername=signs", "INVENTORY": inventory_layer(rows), "TYPE_FIELD": "sign_type",
        "FACING_FIELD": "facing", "OUTPUT": str(tmp_path / "changes.gpkg"), "REPORT": str(tmp_path / "r.html")})
    verdicts = {(c["inventory_id"] or f"new {c['template_id']}"): c["verdict"] for c in changes_of(result["OUTPUT"])}
    assert verdicts == {"1": "moved", "2": "changed", "3": "not covered", f"new {read_as[removed.sign_id]}": "new"}
    assert (result["MOVED"], result["CHANGED"], result["NOT_COVERED"], result["NEW"]) == (1, 1, 1, 1)
    lines = QgsVectorLayer(f"{result['OUTPUT']}|layername=displacements", "d", "ogr")
    lengths = {f["verdict"]: f.geometry().length() for f in lines.getFeatures()}
    assert lengths["moved"] == pytest.approx(1.0, abs=0.15)
    page = (tmp_path / "r.html").read_text()
    assert "<svg" in page and "1 moved, 1 changed, 0 missing, 1 not covered; 1 new" in page


@pytest.fixture
def missing_run(run, mapped, tmp_path):
    """changes against an inventory of one sign whose mapped counterpart was rejected: (output, change, sign)."""
    path, drive = mapped
    read_as = mapped_ids(path, drive.truth)
    gone = next(t for t in drive.truth if read_as.get(t.sign_id) == t.template_id)  # one the mapping reads right
    rows = [(gone.template_id, gone.position, gone.facing)]
    layer = QgsVectorLayer(f"{path}|layername=signs", "signs", "ogr")
    near = [f.id() for f in layer.getFeatures() if f.geometry().constGet().distance3D(QgsPoint(*gone.position)) < 0.5]
    assert len(near) == 1
    status = layer.fields().indexOf("status")
    layer.startEditing()
    layer.changeAttributeValue(near[0], status, "rejected")
    assert layer.commitChanges()
    try:
        result = run("signmapper:changes", {"SIGNS": f"{path}|layername=signs", "INVENTORY": inventory_layer(rows),
                                            "TYPE_FIELD": "sign_type", "FACING_FIELD": "facing",
                                            "OUTPUT": str(tmp_path / "c.gpkg")})
    finally:
        layer.startEditing()
        layer.changeAttributeValue(near[0], status, "accepted")
        layer.commitChanges()
    missing = [c for c in changes_of(result["OUTPUT"]) if c["verdict"] == "missing"]
    assert len(missing) == 1
    return result["OUTPUT"], missing[0], gone


def test_missing_sign_names_the_pairs_and_where_it_should_be_seen(missing_run, mapped):
    _, change, gone = missing_run
    drive = mapped[1]
    pairs = change["visible_pairs"].split()
    assert change["pair_id"] in pairs and change["n_pairs"] == len(pairs) and change["status"] == "review"
    from signmapper_core.geometry import world_to_pixel

    u, v, z = world_to_pixel(drive.camera, drive.pair(change["pair_id"]).pose, gone.position)
    assert (change["u"], change["v"]) == pytest.approx((float(u), float(v)), abs=0.5)
    assert change["bbox_x"] <= u <= change["bbox_x"] + change["bbox_w"]


def test_review_dock_opens_a_missing_sign_at_its_pair_and_a_click_confirms_it(missing_run, sign_mapper, qgis_iface):
    import time

    from qgis.core import QgsProject, QgsSettings
    from qgis.PyQt.QtWidgets import QApplication
    from sign_mapper.review.controller import ReviewController
    from sign_mapper.ui.review_dock import ReviewDock

    path, change, gone = missing_run
    layer = QgsVectorLayer(f"{path}|layername=changes", "changes", "ogr")
    QgsProject.instance().addMapLayer(layer)
    dock = ReviewDock()
    dock.advance_box.setChecked(False)
    controller = ReviewController(qgis_iface, dock, ask_drive_folder=lambda old: None, settings=QgsSettings())

    def idle():
        deadline = time.monotonic() + 60
        while controller.busy() and time.monotonic() < deadline:
            QApplication.processEvents()
            time.sleep(0.005)
        QApplication.processEvents()

    try:
        qgis_iface.setActiveLayer(layer)
        controller.activate()
        assert controller.kind == "changes"
        fid = next(f.id() for f in layer.getFeatures() if f["verdict"] == "missing")
        layer.selectByIds([fid])
        idle()
        item = dock.item
        assert item.pair_id == change["pair_id"] and item.template_id == gone.template_id
        assert item.bbox == (change["bbox_x"], change["bbox_y"], change["bbox_w"], change["bbox_h"])
        assert item.image is not None and dock.pair_id == change["pair_id"]
        dock.addSignClicked.emit(change["pair_id"], change["u"], change["v"])  # the sign is there after all
        idle()
        after = QgsVectorLayer(f"{path}|layername=changes", "check", "ogr").getFeature(fid)
        assert (after["verdict"], after["template_id"], after["status"], after["reviewed"]) == \
            ("confirmed", gone.template_id, "manual", 1)
    finally:
        controller.shutdown()
        dock.deleteLater()
        QgsProject.instance().removeAllMapLayers()
        QApplication.processEvents()


def signalo_dsn_parts(dsn):
    return dict(part.split("=", 1) for part in dsn.split())


def read_signalo(dsn):
    """(support points, [(official id, inscription)]) through QGIS's PostgreSQL provider."""
    parts = signalo_dsn_parts(dsn)
    uri = QgsDataSourceUri()
    uri.setConnection(parts["host"], parts["port"], parts["dbname"], parts["user"], "")
    uri.setDataSource("signalo_db", "support", "geometry", "", "id")
    supports = QgsVectorLayer(uri.uri(False), "support", "postgres")
    assert supports.isValid(), supports.error().summary()
    points = [f.geometry().asPoint() for f in supports.getFeatures()]
    uri.setDataSource("signalo_db", "sign", None, "", "id")
    signs = QgsVectorLayer(uri.uri(False), "sign", "postgres")
    assert signs.isValid()
    types = [(f["fk_official_sign"], f["inscription_1"] or None) for f in signs.getFeatures()]
    return points, types


def test_signalo_export_round_trip(run, mapped, signalo_database, tmp_path):
    path, drive = mapped
    dsn = signalo_database("qgis_roundtrip")
    mapped_signs = signs_of(path)
    params = {"SIGNS": f"{path}|layername=signs", "SIGNALO": dsn, "INCLUDE_REVIEW": True}
    first = run("signmapper:exporttosignalo", params)
    assert (first["ADDED"], first["UNKNOWN"], first["SIGNALO_VERSION"]) == (len(mapped_signs), 0, "1.4")
    points, types = read_signalo(dsn)
    assert len(points) == first["SUPPORTS"]
    from signmapper_core.signalo.export import ExportSign, plan_supports

    planned = plan_supports([ExportSign(i, t, np.array(xyz), 0.0, 0.6, 0.6) for i, (t, xyz) in mapped_signs.items()])
    assert len(planned) == len(points)
    for plan in planned:  # each pole at the mean of its signs, read back within 1 mm
        assert min(np.hypot(p.x() - plan.easting, p.y() - plan.northing) for p in points) < 1e-3
        assert all(np.hypot(*(s.position[:2] - (plan.easting, plan.northing))) < 0.3 for s in plan.signs)
    expected = sorted((t.rsplit("-", 1)[0], t.rsplit("-", 1)[1]) if "-" in t else (t, None)
                      for t, _ in mapped_signs.values())
    assert sorted(types, key=str) == sorted(expected, key=str)

    second = run("signmapper:exporttosignalo", params)
    assert (second["ADDED"], second["ALREADY"]) == (0, len(mapped_signs))
    assert len(read_signalo(dsn)[1]) == len(mapped_signs)

    back = run("signmapper:changes", {"SIGNS": f"{path}|layername=signs", "SIGNALO": dsn,
                                      "OUTPUT": str(tmp_path / "c.gpkg")})
    assert back["CONFIRMED"] == len(mapped_signs)
    assert sum(back[k] for k in ("MOVED", "CHANGED", "MISSING", "NOT_COVERED", "NEW")) == 0


def test_export_to_an_unreachable_database_says_so(run, mapped, postgres):
    path, _ = mapped
    with pytest.raises(QgsProcessingException, match="cannot connect"):
        run("signmapper:exporttosignalo", {"SIGNS": f"{path}|layername=signs",
                                           "SIGNALO": postgres.dsn_for("not_there")})


def test_export_to_another_signalo_version_writes_nothing(run, mapped, signalo_database):
    path, _ = mapped
    dsn = signalo_database("qgis_old", up_to="1.0")
    with pytest.raises(QgsProcessingException, match=r"Signalo data model 1\.0"):
        run("signmapper:exporttosignalo", {"SIGNS": f"{path}|layername=signs", "SIGNALO": dsn})
    assert read_signalo(dsn) == ([], [])


def test_the_signalo_database_is_chosen_from_qgis_saved_connections(run, mapped, signalo_database, registered_plugin):
    """The dialog offers QGIS's saved PostgreSQL connections; the export writes through the one chosen by name."""
    from qgis.core import QgsApplication, QgsProcessingParameterProviderConnection, QgsProviderRegistry

    for algorithm in ("signmapper:exporttosignalo", "signmapper:changes"):
        parameter = QgsApplication.processingRegistry().algorithmById(algorithm).parameterDefinition("SIGNALO")
        assert isinstance(parameter, QgsProcessingParameterProviderConnection) and parameter.providerId() == \
            "postgres"
    path, _ = mapped
    dsn = signalo_database("qgis_saved_connection")
    metadata = QgsProviderRegistry.instance().providerMetadata("postgres")
    connection = metadata.createConnection(QgsDataSourceUri(dsn).uri(False), {"saveUsername": True,
                                                                            "savePassword": True})
    metadata.saveConnection(connection, "Signalo (test)")
    try:
        result = run("signmapper:exporttosignalo", {"SIGNS": f"{path}|layername=signs", "SIGNALO": "Signalo (test)",
                                                    "INCLUDE_REVIEW": True})
        assert result["ADDED"] == len(signs_of(path)) and len(read_signalo(dsn)[1]) == result["ADDED"]
    finally:
        metadata.deleteConnection("Signalo (test)")
