"""``signmapper:exportinventory``: the reviewed signs as a deliverable in the output language."""

import csv
from pathlib import Path

import pytest
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeature,
    QgsFeatureSink,
    QgsGeometry,
    QgsPoint,
    QgsVectorLayer,
    QgsWkbTypes,
)
from recorder import Recorder

# sign_id, template_id, status, plate_of, text, (E, N, H), crop
SIGNS = [
    (1, "2.30-50", "accepted", None, None, (2600010.0, 1200004.0, 402.1), "run_crops/sign_00001.jpg"),
    (2, "1.01", "review", None, None, (2600020.0, 1199996.0, 402.4), None),
    (3, "2.37", "rejected", None, None, (2600030.0, 1200004.0, 401.8), None),
    (4, "3.03", "manual", None, None, (2600040.0, 1199996.0, 402.2), None),
    (5, "plate", "accepted", 1, "Mo–Fr", (2600010.0, 1200004.0, 401.7), None),
    (6, "plate", "accepted", 2, "200 m", (2600020.0, 1199996.0, 402.0), None),
]


@pytest.fixture
def run_gpkg(tmp_path, sign_mapper):
    """A reviewed mapping run written in French, with an image crop beside it."""
    from sign_mapper.gpkg.fields import layer_fields
    from sign_mapper.gpkg.output import GeoPackageLayers
    from sign_mapper.signmapper_core.output.geopackage_file import PartialGeoPackage

    fields = layer_fields("signs")
    output = PartialGeoPackage(tmp_path / "run.gpkg")
    gpkg = GeoPackageLayers(output)
    writer = gpkg.open_layer("signs", fields, QgsWkbTypes.PointZ, QgsCoordinateReferenceSystem("EPSG:2056"))
    for sign_id, template_id, status, plate_of, text, xyz, crop in SIGNS:
        feature = QgsFeature(fields)
        for name, value in {"sign_id": sign_id, "template_id": template_id, "name": f"nom {template_id}",
                            "status": status, "reviewed": int(status != "accepted" or sign_id == 5),
                            "plate_of": plate_of, "text": text, "format": "normal", "width_m": 0.6,
                            "height_m": 0.6, "n_obs": 2, "best_pair_id": "000003", "u": 1.0, "v": 1.0,
                            "bbox_x": 1, "bbox_y": 1, "bbox_w": 2, "bbox_h": 2, "crop_path": crop,
                            "timestamp": "2024-05-02T10:00:00.000"}.items():
            feature[name] = value
        feature.setGeometry(QgsGeometry(QgsPoint(*xyz)))
        writer.addFeature(feature, QgsFeatureSink.FastInsert)
    writer.close()
    gpkg.write_run_table({"drive": str(tmp_path / "drive"), "language": "fr", "run_id": "r1"})
    (tmp_path / "run_crops").mkdir()
    (tmp_path / "run_crops" / "sign_00001.jpg").write_bytes(b"\xff\xd8\xff")
    return Path(output.commit())


def export(run, run_gpkg, output, **extra):
    feedback = Recorder()
    result = run("signmapper:exportinventory", {"SIGNS": f"{run_gpkg}|layername=signs", "OUTPUT": str(output),
                                                **extra}, feedback=feedback)
    return result, feedback


def rows_of(path, layer="inventory"):
    source = f"{path}|layername={layer}" if str(path).endswith(".gpkg") else str(path)
    layer = QgsVectorLayer(source, "check", "ogr")
    assert layer.isValid(), source
    return layer, [dict(zip(layer.fields().names(), f.attributes())) for f in layer.getFeatures()]


def test_a_geopackage_deliverable_in_french_keeps_the_files_other_layers(run, run_gpkg, tmp_path):
    from sign_mapper.gpkg.output import GeoPackageLayers
    from sign_mapper.signmapper_core.output.geopackage_file import PartialGeoPackage

    target = tmp_path / "out" / "livrable.gpkg"
    target.parent.mkdir()
    other = PartialGeoPackage(target, ("notes",))  # the user's own layer in the file
    from qgis.core import QgsField, QgsFields
    from qgis.PyQt.QtCore import QVariant

    note_fields = QgsFields()
    note_fields.append(QgsField("note", QVariant.String))
    GeoPackageLayers(other).open_layer("notes", note_fields, QgsWkbTypes.NoGeometry,
                                       QgsCoordinateReferenceSystem()).close()
    other.commit()

    result, feedback = export(run, run_gpkg, target)
    assert result["SIGNS_WRITTEN"] == 3
    layer, rows = rows_of(target)
    assert layer.wkbType() == QgsWkbTypes.PointZ
    assert layer.fields().names()[1:6] == ["N° signal", "Type de signal (OSR)", "Désignation",
                                           "Plaque du signal n°", "Texte"]  # after the GeoPackage's fid
    assert [r["N° signal"] for r in rows] == [1, 5, 4]  # each plate right after its sign; review/rejected left out
    assert [r["Statut"] for r in rows] == ["accepté", "accepté", "ajouté à la main"]
    assert [r["Contrôlé"] for r in rows] == ["non", "oui", "oui"] and rows[0]["Format"] == "normal"
    assert rows[1]["Plaque du signal n°"] == 1 and rows[1]["Texte"] == "Mo–Fr"
    assert (rows[0]["E [m]"], rows[0]["N [m]"], rows[0]["H [m]"]) == pytest.approx((2600010.0, 1200004.0, 402.1))
    assert rows[0]["Extrait d'image"] == "../run_crops/sign_00001.jpg"  # from the deliverable's folder
    assert (target.parent / rows[0]["Extrait d'image"]).is_file()
    assert QgsVectorLayer(f"{target}|layername=notes", "notes", "ogr").isValid()  # the user's layer stays
    assert any("Plate 6: its sign 2 is not delivered" in line for line in feedback.lines)


def test_a_csv_for_spreadsheets_in_german_with_the_signs_still_to_review(run, run_gpkg, tmp_path):
    target = tmp_path / "inventar.csv"
    result, _ = export(run, run_gpkg, target, LANGUAGE=2, INCLUDE_REVIEW=True)  # Deutsch
    raw = target.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")  # a BOM: spreadsheets read UTF-8 as such
    table = list(csv.reader(raw.decode("utf-8-sig").splitlines(), delimiter=";"))
    assert table[0][:3] == ["Signal-Nr.", "Signaltyp (SSV)", "Bezeichnung"] and "E [m]" in table[0]
    assert [r[0] for r in table[1:]] == ["1", "5", "2", "6", "4"]
    status = table[0].index("Status")
    assert [r[status] for r in table[1:]] == ["akzeptiert", "akzeptiert", "zu prüfen", "akzeptiert",
                                              "von Hand erfasst"]
    assert result["SIGNS_WRITTEN"] == 5 and not list(tmp_path.glob(".*partial*"))


def test_a_shapefile_gets_short_column_names_and_the_log_says_which_is_which(run, run_gpkg, tmp_path):
    target = tmp_path / "inventory.shp"
    _, feedback = export(run, run_gpkg, target, LANGUAGE=1)  # English
    layer, rows = rows_of(target)
    assert layer.wkbType() == QgsWkbTypes.PointZ
    names = layer.fields().names()
    assert names[:4] == ["Sign_no", "Sign_type_", "Name", "Plate_of_s"] and all(len(n) <= 10 for n in names)
    assert [r["Sign_no"] for r in rows] == [1, 5, 4] and rows[2]["Status"] == "added by hand"
    assert any("Sign_no = Sign no." in line for line in feedback.lines)
    assert {p.suffix for p in tmp_path.glob("inventory.*")} >= {".shp", ".dbf", ".shx", ".prj", ".cpg"}


def test_a_wrong_suffix_is_refused_and_a_cancelled_run_leaves_the_earlier_file(run, run_gpkg, tmp_path):
    from qgis.core import QgsProcessingException

    with pytest.raises(QgsProcessingException, match=r"inventory\.xlsx: give a file ending in \.gpkg, \.csv or"):
        export(run, run_gpkg, tmp_path / "inventory.xlsx")
    target = tmp_path / "inventory.csv"
    target.write_text("earlier\n", encoding="utf-8")

    class CancelAtOnce(Recorder):
        def isCanceled(self):  # noqa: N802
            return True

    with pytest.raises(QgsProcessingException, match="Cancelled"):
        run("signmapper:exportinventory", {"SIGNS": f"{run_gpkg}|layername=signs", "OUTPUT": str(target)},
            feedback=CancelAtOnce())
    assert target.read_text(encoding="utf-8") == "earlier\n" and not list(tmp_path.glob(".*partial*"))


def test_the_inventory_is_written_under_its_lock_and_a_second_export_into_the_geopackage_replaces_only_it(
        run, run_gpkg, tmp_path):
    """The one output mechanism (issue 46): a file another run is writing is refused, the earlier file as it was;
    an export into a GeoPackage holding an earlier inventory replaces that layer and keeps the others."""
    from qgis.core import QgsProcessingException
    from sign_mapper.signmapper_core.output.geopackage_file import geopackage_tables
    from sign_mapper.signmapper_core.output.target_lock import TargetLock

    target = tmp_path / "inventory.csv"
    target.write_text("earlier\n", encoding="utf-8")
    with TargetLock(target):  # another run writing it now
        with pytest.raises(QgsProcessingException, match="another run is writing this output right now"):
            export(run, run_gpkg, target)
    assert target.read_text(encoding="utf-8") == "earlier\n"
    export(run, run_gpkg, target)
    assert target.read_text(encoding="utf-8-sig").startswith("N° signal;")  # the run's language: French
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []  # no partial, no lock

    both = tmp_path / "both.gpkg"
    export(run, run_gpkg, both)
    export(run, run_gpkg, both, INCLUDE_REVIEW=True)  # again, with the signs still to review
    _, rows = rows_of(both)
    assert len(rows) == 5
    assert "inventory" in geopackage_tables(both)
