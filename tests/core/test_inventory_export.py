"""The inventory deliverable's rows: which signs, in which order, in which words."""

from signmapper_core.output.inventory_export import COLUMNS, columns, rebased, row, select, short_names


def sign(sign_id, status, plate_of=None, **extra):
    return {"sign_id": sign_id, "status": status, "plate_of": plate_of, **extra}


def test_delivered_signs_in_number_order_with_their_plates_and_orphans_named():
    chosen = select([sign(3, "manual"), sign(7, "accepted", plate_of=1), sign(1, "accepted"), sign(2, "rejected"),
                     sign(8, "accepted", plate_of=2), sign(6, "accepted", plate_of=1), sign(4, "review")])
    assert [s["sign_id"] for s in chosen.signs] == [1, 6, 7, 3]
    assert chosen.left_out == 2 and chosen.orphan_plates == [(8, 2)]
    with_review = select([sign(4, "review"), sign(9, "accepted", plate_of=4)], ("accepted", "manual", "review"))
    assert [s["sign_id"] for s in with_review.signs] == [4, 9] and not with_review.orphan_plates


def test_columns_are_titled_and_coded_values_worded_in_the_language():
    titles = [c.title for c in columns("it")]
    assert titles[:2] == ["N. segnale", "Tipo di segnale (OSS)"] and len(titles) == len(COLUMNS)
    assert {c.name: c.kind for c in columns("en")}["status"] == "text"
    values = dict(zip(COLUMNS, row(sign(1, "review", reviewed=0, format="large", template_id="1.01"), "it")))
    assert (values["status"], values["reviewed"], values["format"], values["template_id"]) == (
        "da verificare", "no", "grande", "1.01")


def test_shapefile_names_are_short_unique_ascii():
    names = short_names(["Höhe Signalfläche [m]", "Höhe Signalfläche [°]", "N° signal", "E [m]", "---"])
    assert names == ["Hohe_Signa", "Hohe_Sign2", "N_signal", "E_m", "field"]


def test_a_crop_path_leads_from_the_deliverable(tmp_path):
    assert rebased("run_crops/sign_00001.jpg", tmp_path / "a", tmp_path / "b") == "../a/run_crops/sign_00001.jpg"
    assert rebased(None, tmp_path, tmp_path) is None
