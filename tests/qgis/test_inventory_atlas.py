"""``signmapper:inventoryatlas``: a PDF sheet per delivered sign, from a mapped drive, and its print layout."""

import re
import shutil

import numpy as np
import pytest
from mapping_runs import map_drive
from qgis.core import QgsLayoutExporter, QgsProcessingContext, QgsProcessingException, QgsProject, QgsVectorLayer
from qgis.PyQt.QtGui import QImage

from signmapper_core.catalogue import load_catalogue


@pytest.fixture(scope="module")
def mapped(small_drive, tmp_path_factory, sign_mapper, qgis_processing):
    """The small drive mapped once (crops are written by default) and reviewed: its first sign rejected, the
    others confirmed."""
    out = map_drive(sign_mapper, small_drive, tmp_path_factory.mktemp("atlas") / "signs.gpkg", LANGUAGE=2)
    layer = QgsVectorLayer(f"{out}|layername=signs", "signs", "ogr")
    signs = sorted(layer.getFeatures(), key=lambda f: f["sign_id"])
    assert len(signs) >= 3
    status = layer.fields().indexOf("status")
    layer.startEditing()
    layer.changeAttributeValue(signs[0].id(), status, "rejected")
    for feature in signs[1:]:
        layer.changeAttributeValue(feature.id(), status, "accepted")
    assert layer.commitChanges()
    return out


@pytest.fixture
def project_signs(mapped):
    layer = QgsVectorLayer(f"{mapped}|layername=signs", "signs", "ogr")
    QgsProject.instance().addMapLayer(layer)
    yield layer
    for layout in QgsProject.instance().layoutManager().layouts():
        layout.atlas().endRender()  # a test may leave it rendering; removing it then crashed QGIS
        QgsProject.instance().layoutManager().removeLayout(layout)
    QgsProject.instance().removeAllMapLayers()


def pdf_pages(path) -> int:
    return len(re.findall(rb"/Type\s*/Page[^s]", path.read_bytes()))


def test_an_atlas_pdf_with_a_sheet_per_delivered_sign_and_its_layout_in_the_project(run, project_signs, mapped,
                                                                                      tmp_path):
    layer = project_signs
    delivered = sorted(f["sign_id"] for f in layer.getFeatures() if f["status"] in ("accepted", "manual"))
    assert len(delivered) >= 2
    out = tmp_path / "atlas.pdf"
    result = run("signmapper:inventoryatlas", {"SIGNS": layer.id(), "OUTPUT": str(out), "LANGUAGE": 3})  # fr
    assert result["PAGES"] == len(delivered)
    assert out.read_bytes().startswith(b"%PDF") and pdf_pages(out) == len(delivered)
    layout = QgsProject.instance().layoutManager().layoutByName("Sign Mapper inventory: signs")
    assert layout is not None  # to adjust and print again

    # the first sheet: the first delivered sign's number, French name and words, its coordinates, photo, pictogram
    atlas = layout.atlas()
    assert atlas.beginRender() and atlas.first()
    feature = atlas.layout().reportContext().feature()
    assert feature["sign_id"] == delivered[0]
    entry = load_catalogue()[feature["template_id"]]
    assert layout.itemById("title").currentText() == f"{entry.id}  {entry.name('fr')}"
    word = {"accepted": "accepté", "manual": "ajouté à la main"}[feature["status"]]
    # the synthetic drive states no start time: no date, and no empty title for it
    assert layout.itemById("status").currentText() == f"N° signal {feature['sign_id']}  ·  {word}"
    facts = layout.itemById("facts").currentText()
    point = feature.geometry().constGet()
    assert f"E [m]: {round(point.x(), 3)}" in facts and f"H [m]: {round(point.z(), 3)}" in facts
    assert "Contrôlé: non" in facts
    photo, pictogram = layout.itemById("photo"), layout.itemById("pictogram")
    photo.refreshPicture()
    pictogram.refreshPicture()
    assert photo.evaluatedPath() == str(mapped.parent / feature["crop_path"]) and not photo.isMissingImage()
    assert pictogram.evaluatedPath() == str(load_catalogue().pictogram_path(entry.id, "png"))
    assert not pictogram.isMissingImage()
    item_map = layout.itemById("map")  # on the sheet whatever the shape of the layer's extent
    assert (item_map.sizeWithUnits().width(), item_map.sizeWithUnits().height()) == pytest.approx((180.0, 125.0))
    assert (item_map.positionWithUnits().x(), item_map.positionWithUnits().y()) == pytest.approx((15.0, 145.0))
    assert item_map.scale() == pytest.approx(250.0)
    assert item_map.extent().contains(feature.geometry().asPoint())  # around this sheet's sign
    image = QgsLayoutExporter(layout).renderPageToImage(0)
    atlas.endRender()
    rgb = image.convertToFormat(QImage.Format_RGB888)
    ptr = rgb.constBits()
    ptr.setsize(rgb.bytesPerLine() * rgb.height())
    pixels = np.frombuffer(ptr, np.uint8).reshape(rgb.height(), rgb.bytesPerLine())[:, :rgb.width() * 3]
    px_per_mm = rgb.width() / 210.0
    photo_area = pixels[int(45 * px_per_mm):int(125 * px_per_mm), int(75 * px_per_mm) * 3:int(190 * px_per_mm) * 3]
    assert photo_area.std() > 20  # a photograph, not an empty frame


def test_a_layer_outside_the_project_gives_the_pdf_only_and_nothing_to_print_is_said(run, mapped, tmp_path):
    copy = tmp_path / "copy.gpkg"
    shutil.copy(mapped, copy)
    out = tmp_path / "only.pdf"
    result = run("signmapper:inventoryatlas", {"SIGNS": f"{copy}|layername=signs", "OUTPUT": str(out)})
    assert pdf_pages(out) == result["PAGES"] > 0
    assert not QgsProject.instance().layoutManager().layouts()
    layer = QgsVectorLayer(f"{copy}|layername=signs", "signs", "ogr")
    layer.startEditing()
    for feature in layer.getFeatures():
        layer.changeAttributeValue(feature.id(), layer.fields().indexOf("status"), "review")
    assert layer.commitChanges()
    del layer
    with pytest.raises(QgsProcessingException, match="no sign with status accepted, manual"):
        run("signmapper:inventoryatlas", {"SIGNS": f"{copy}|layername=signs", "OUTPUT": str(tmp_path / "no.pdf")})
    assert not (tmp_path / "no.pdf").exists()


def test_without_a_project_as_in_qgis_process_the_atlas_is_printed_all_the_same(run, mapped, tmp_path):
    """qgis_process without --PROJECT_PATH gives the algorithm no project: the layout once crashed QGIS there."""
    out = tmp_path / "no-project.pdf"
    context = QgsProcessingContext()
    assert context.project() is None
    result = run("signmapper:inventoryatlas", {"SIGNS": f"{mapped}|layername=signs", "OUTPUT": str(out)},
                 context=context)
    assert pdf_pages(out) == result["PAGES"] > 0


def test_an_atlas_is_written_under_its_lock_and_a_failed_run_leaves_the_earlier_pdf(run, mapped, tmp_path):
    """The one output mechanism (issue 46): the PDF is moved in when the run succeeds; a file another run is
    writing is refused, the earlier PDF as it was, nothing left beside it."""
    from sign_mapper.signmapper_core.output.target_lock import TargetLock

    out = tmp_path / "atlas.pdf"
    out.write_bytes(b"%PDF earlier")
    with TargetLock(out):
        with pytest.raises(QgsProcessingException, match="another run is writing this output right now"):
            run("signmapper:inventoryatlas", {"SIGNS": f"{mapped}|layername=signs", "OUTPUT": str(out)})
    assert out.read_bytes() == b"%PDF earlier"
    with pytest.raises(QgsProcessingException, match=r"atlas\.txt: give a file ending in \.pdf"):
        run("signmapper:inventoryatlas", {"SIGNS": f"{mapped}|layername=signs", "OUTPUT": str(tmp_path / "atlas.txt")})
    result = run("signmapper:inventoryatlas", {"SIGNS": f"{mapped}|layername=signs", "OUTPUT": str(out)})
    assert result["OUTPUT"] == str(out) and pdf_pages(out) == result["PAGES"] > 0
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]
