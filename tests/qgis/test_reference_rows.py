"""Reference and inventory rows that cannot count as they are (issue 46, cases 9 and 10): a sign recorded twice
is counted once and a row without geometry is left out, each with a warning naming the rows, never silently."""

from qgis.core import QgsFeature, QgsVectorLayer
from recorder import Recorder
from test_evaluate import REF, eastward_trajectory, point_layer
from test_inventory import changes_of, inventory_layer, mapped, mapped_ids  # noqa: F401 - mapped: a fixture


def with_a_row_without_geometry(layer: QgsVectorLayer, attributes: list) -> QgsVectorLayer:
    feature = QgsFeature(layer.fields())
    feature.setAttributes(attributes)  # no geometry: what a table joined without coordinates gives
    assert layer.dataProvider().addFeatures([feature])
    return layer


def test_evaluate_counts_a_reference_sign_recorded_twice_once_and_says_what_it_left_out(run, tmp_path):
    reference = with_a_row_without_geometry(point_layer(REF + REF[:1], "ref"), ["1.01", "accepted"])
    feedback = Recorder()
    result = run("signmapper:evaluate", {
        "SIGNS": point_layer(REF, "mapped"), "REFERENCE": reference, "REFERENCE_ID_FIELD": "template_id",
        "RADIUS": 1.0, "TRAJECTORY": eastward_trajectory(), "REPORT": str(tmp_path / "r.html"),
        "STATISTICS": "memory:", "MATCHES": "memory:"}, feedback=feedback)
    assert result["DETECTION_RATE"] == 1.0  # 4 of 5 (or 0.5 of the twins) when the repeat counted
    assert result["MATCHES"].featureCount() == 4
    assert feedback.warnings == [
        "ref: 1 feature has no geometry and is left out (e.g. fid 6)",
        "ref: 1 feature repeats another exactly (the same type at the same place, e.g. fid 5 = fid 1): each such "
        "sign is counted once"]


def test_changes_counts_an_inventory_sign_recorded_twice_once_and_says_what_it_left_out(run, mapped, tmp_path):  # noqa: F811
    path, drive = mapped
    read_as = mapped_ids(path, drive.truth)
    kept = [t for t in sorted(drive.truth, key=lambda t: t.sign_id) if t.sign_id in read_as]
    rows = [(read_as[t.sign_id], t.position, t.facing) for t in kept]
    inventory = with_a_row_without_geometry(inventory_layer(rows + rows[:1]), ["2.01", 90.0])
    feedback = Recorder()
    result = run("signmapper:changes", {
        "SIGNS": f"{path}|layername=signs", "INVENTORY": inventory, "TYPE_FIELD": "sign_type",
        "FACING_FIELD": "facing", "OUTPUT": str(tmp_path / "changes.gpkg")}, feedback=feedback)
    verdicts = sorted(c["verdict"] for c in changes_of(result["OUTPUT"]) if c["inventory_id"])
    assert verdicts == ["confirmed"] * len(kept)  # no "missing" twin of a confirmed sign
    assert (result["MISSING"], result["CONFIRMED"]) == (0, len(kept))
    first, repeat, no_geometry = 1, len(rows) + 1, len(rows) + 2
    assert f"inventory: 1 feature has no geometry and is left out (e.g. fid {no_geometry})" \
        in feedback.warnings, feedback.warnings
    assert f"layer inventory: 1 feature repeats another exactly (the same type at the same place, e.g. fid {repeat} " \
           f"= fid {first}): each such sign is counted once" in feedback.warnings, feedback.warnings
