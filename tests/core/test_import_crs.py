"""CRS steps of an import: positions, heights as the CRSs say, grid convergence, clear errors (pyproj)."""

import numpy as np
import pytest
from pyproj import Transformer
from pyproj.transformer import TransformerGroup

from signmapper_core.errors import ImportInputError
from signmapper_core.geometry import angles_from_rotation, camera_rotation
from signmapper_core.importdrive.crs_steps import CrsSteps


def finite_difference_convergence(crs, lon, lat):
    """Grid azimuth of true north (degrees) by projecting a step north."""
    t = Transformer.from_crs("EPSG:4326", crs, always_xy=True)
    e0, n0 = t.transform(lon, lat)
    e1, n1 = t.transform(lon, lat + 1e-6)
    return np.degrees(np.arctan2(e1 - e0, n1 - n0))


@pytest.mark.parametrize("crs, lon, lat", [("EPSG:2056", 6.1, 46.2), ("EPSG:2056", 10.3, 46.9),
                                           ("EPSG:32632", 8.43, 49.01), ("EPSG:32632", 11.5, 48.1)])
def test_a_camera_looking_true_north_has_the_grid_azimuth_of_true_north(crs, lon, lat):
    steps = CrsSteps("EPSG:4979", crs)
    to_grid = steps.grid_rotations(np.array([[lon, lat, 400.0]]), "true")[0]
    heading, pitch, roll = angles_from_rotation(to_grid @ camera_rotation(0.0, 3.0, -1.0))
    expected = finite_difference_convergence(crs, lon, lat)
    assert abs(expected) > 0.3   # far enough from the central meridian for the test to mean something
    assert (heading + 180) % 360 - 180 == pytest.approx(expected, abs=1e-6)
    assert (pitch, roll) == pytest.approx((3.0, -1.0), abs=1e-9)


def test_grid_angles_of_the_output_crs_itself_are_kept():
    steps = CrsSteps("EPSG:2056", "EPSG:2056")
    to_grid = steps.grid_rotations(np.array([[2700000.0, 1250000.0, 500.0]]), "grid")[0]
    assert to_grid == pytest.approx(np.eye(3), abs=1e-12)


def test_grid_angles_of_another_projection_turn_by_the_difference_of_convergences():
    point = np.array([[2560000.0, 1190000.0, 500.0]])   # west Switzerland: LV95 and UTM 32 disagree on north
    steps = CrsSteps("EPSG:2056", "EPSG:32632")
    heading, _, _ = angles_from_rotation(steps.grid_rotations(point, "grid")[0] @ camera_rotation(0, 0, 0))
    lon, lat = Transformer.from_crs("EPSG:2056", "EPSG:4326", always_xy=True).transform(*point[0, :2])
    expected = finite_difference_convergence("EPSG:32632", lon, lat) - finite_difference_convergence(
        "EPSG:2056", lon, lat)
    assert (heading + 180) % 360 - 180 == pytest.approx(expected, abs=1e-6)


def test_where_input_and_output_share_a_datum_north_is_projs_meridian_convergence():
    from pyproj import CRS, Proj

    steps = CrsSteps("EPSG:4979", "EPSG:32632")
    azimuth = steps.north_azimuths(np.array([[8.43, 49.01, 120.0], [11.5, 48.1, 500.0]]), "true")
    factors = Proj(CRS("EPSG:32632")).get_factors([8.43, 11.5], [49.01, 48.1])
    assert azimuth == pytest.approx(-np.asarray(factors.meridian_convergence), abs=1e-6)


def test_positions_from_wgs84_to_lv95_copy_the_heights_and_say_which_they_are():
    steps = CrsSteps("EPSG:4979", "EPSG:2056")
    out = steps.positions(np.array([[7.4386, 46.9511, 603.2]]))
    e, n, _ = Transformer.from_crs("EPSG:4979", "EPSG:2056", always_xy=True).transform(7.4386, 46.9511, 603.2)
    assert out[0] == pytest.approx([e, n, 603.2], abs=1e-6)
    assert any("ellipsoidal heights of WGS 84" in w for w in steps.warnings)


def test_heights_are_converted_when_both_crs_say_what_they_are():
    source, target = "EPSG:4979", "EPSG:32632+5773"   # ellipsoidal to EGM96 heights
    if TransformerGroup(source, target, always_xy=True, allow_ballpark=False).best_available:
        out = CrsSteps(source, target).positions(np.array([[8.43, 49.01, 164.0]]))
        assert -55.0 < out[0, 2] - 164.0 < -40.0   # the geoid lies about 48 m above the ellipsoid there
        assert not CrsSteps(source, target).warnings
    else:
        with pytest.raises(ImportInputError, match="egm96"):
            CrsSteps(source, target)


def test_a_missing_geoid_grid_is_an_error_naming_it_never_a_silent_copy():
    source, target = "EPSG:4979", "EPSG:2056+5728"    # LN02 heights need swisstopo's CHGeo2004 grid
    group = TransformerGroup(source, target, always_xy=True, allow_ballpark=False)
    if group.best_available:
        out = CrsSteps(source, target).positions(np.array([[7.4386, 46.9511, 603.2]]))
        assert 540 < out[0, 2] < 560   # about 49 m lower than the ellipsoidal height in Bern
    else:
        with pytest.raises(ImportInputError, match="chgeo2004"):
            CrsSteps(source, target)


def test_input_without_heights_cannot_feed_an_output_with_heights():
    with pytest.raises(ImportInputError, match="does not say what its heights are"):
        CrsSteps("EPSG:4326", "EPSG:32632+5773")


@pytest.mark.parametrize("output, message", [("EPSG:4326", "geographic"), ("EPSG:2229", "not metres"),
                                             ("EPSG:99999999", "PROJ does not know"), ("", "empty")])
def test_an_output_crs_a_drive_cannot_have_is_refused(output, message):
    with pytest.raises(ImportInputError, match=message):
        CrsSteps("EPSG:4979", output)


def test_geocentric_input_is_refused():
    with pytest.raises(ImportInputError, match="geocentric"):
        CrsSteps("EPSG:4978", "EPSG:2056")


def test_grid_north_of_a_geographic_input_is_an_error():
    steps = CrsSteps("EPSG:4979", "EPSG:2056")
    with pytest.raises(ImportInputError, match="no grid north"):
        steps.grid_rotations(np.array([[7.4, 46.9, 500.0]]), "grid")


def test_a_position_that_cannot_be_transformed_names_its_row():
    steps = CrsSteps("EPSG:2056", "EPSG:32632")
    with pytest.raises(ImportInputError, match="row 2"):
        steps.positions(np.array([[2600000.0, 1200000.0, 0.0], [np.inf, 1200000.0, 0.0]]))
