"""Golden GeoPackage: ``mapsigns`` on a small synthetic drive writes exactly the recorded schema and values.

Guards the output format against unintended change. When a change of the
output is intended (a new field, a better classifier, another generator), run

    SIGNMAPPER_UPDATE_GOLDEN=1 make test

and commit the regenerated ``tests/qgis/golden/mapsigns-seed11.json``: its diff
shows exactly what changed in the users' files.
"""

import os
from pathlib import Path

from golden import differences, dump_gpkg, read_golden, write_golden

GOLDEN = Path(__file__).parent / "golden" / "mapsigns-seed11.json"


def test_mapsigns_output_matches_the_golden_geopackage(registered_plugin, small_drive, tmp_path):
    import processing

    out = tmp_path / "golden.gpkg"
    # German names and aliases whatever the machine's locale (LANGUAGE 2 = de)
    processing.run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "LANGUAGE": 2})
    dump = dump_gpkg(out, small_drive)
    if os.environ.get("SIGNMAPPER_UPDATE_GOLDEN"):
        write_golden(GOLDEN, dump)
    found = differences(read_golden(GOLDEN), dump)
    assert not found, (
        f"{len(found)} differences from {GOLDEN.name} (if intended, regenerate with "
        f"SIGNMAPPER_UPDATE_GOLDEN=1 and commit the file):\n" + "\n".join(found[:40])
    )


def test_the_golden_file_covers_both_layers_links_and_the_run_table():
    """The recorded drive is not trivial: several fused signs, more detections, every detection linked."""
    golden = read_golden(GOLDEN)["tables"]
    signs, detections = golden["signs"]["features"], golden["detections"]["features"]
    assert len(signs) >= 3 and len(detections) > len(signs)
    sign_ids = {f["attributes"]["sign_id"] for f in signs}
    assert {f["attributes"]["sign_id"] for f in detections} == sign_ids
    assert sum(f["attributes"]["n_obs"] for f in signs) == len(detections)
    assert {"drive", "near_m", "far_m", "colours", "catalogue"} <= set(golden["signmapper_run"]["rows"])
