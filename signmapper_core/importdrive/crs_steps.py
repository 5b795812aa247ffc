"""Every coordinate step of an import, done by pyproj: positions, heights, grid convergence.

Positions go from the input CRS (geographic or projected, with or without a
vertical part) to the output CRS, a projected CRS in metres (drive-format.md).
Heights follow what the CRSs say: both with a vertical part, pyproj converts
them (a geoid grid PROJ lacks is an error naming the grid, never a silent
no-op); the output without one, they are copied as the input states them (a
warning says which heights they are); the input without one and the output
with one is an error, because nobody said what the input heights are.

Orientations are recorded against true north (navigation systems: the meridian
of the input's datum) or against the grid north of a projected input.
:meth:`CrsSteps.north_azimuths` gives, at each point, the azimuth in the output
grid of that north, from pyproj transforming the point and a small step north
of it; :meth:`CrsSteps.grid_rotations` turns the recorded east/north/up frame
into the output grid's, ``Rz(-azimuth)``. Where input and output share a datum
this is PROJ's meridian convergence with the opposite sign
(``Proj.get_factors``); where they do not (WGS 84 against LV95's CH1903+) it
also holds the 3.6 arc seconds by which the two meridians differ.
"""


from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from ..errors import ImportInputError
from ..geometry import rot_z

NORTH_STEP_DEG = 1e-6   # about 0.11 m along a meridian
NORTH_STEP_M = 0.1      # along a projected input's grid north


def parse_crs(text: str, role: str):
    from pyproj import CRS
    from pyproj.exceptions import CRSError

    if not isinstance(text, str) or not text.strip():
        raise ImportInputError(f"{role} CRS", "is empty; give a CRS such as 'EPSG:2056'")
    try:
        return CRS.from_user_input(text.strip())
    except CRSError:
        raise ImportInputError(f"{role} CRS", f"PROJ does not know {text!r}") from None


def horizontal(crs):
    """The horizontal part of a CRS (itself unless compound)."""
    return crs.sub_crs_list[0] if crs.is_compound else crs


def has_heights(crs) -> bool:
    """Whether the CRS says what its third coordinate is (compound, or geographic/projected 3D)."""
    return crs.is_compound or len(crs.axis_info) == 3


def height_name(crs) -> str:
    """What the heights of a CRS with heights are, in words."""
    if crs.is_compound:
        return f"{crs.sub_crs_list[1].name} ({crs.sub_crs_list[1].to_string()})"
    return f"ellipsoidal heights of {crs.name}"


def output_crs_problem(crs) -> str | None:
    """Why a CRS cannot hold a drive (not projected, not metres), or None."""
    flat = horizontal(crs)
    if not flat.is_projected:
        kind = "geographic (degrees)" if flat.is_geographic else "not projected"
        return f"{crs.to_string()} is {kind}; a drive needs a projected CRS in metres such as EPSG:2056"
    units = {axis.unit_name.lower() for axis in crs.axis_info}
    if units - {"metre", "meter"}:
        return f"{crs.to_string()} has units {sorted(units)}, not metres; a drive needs metres"
    return None


@dataclass
class CrsSteps:
    """The pyproj transformations from an input CRS to a drive's output CRS."""

    input_text: str
    output_text: str
    warnings: list[str] = field(default_factory=list)

    def __post_init__(self):
        self.input = parse_crs(self.input_text, "input")
        self.output = parse_crs(self.output_text, "output")
        problem = output_crs_problem(self.output)
        if problem:
            raise ImportInputError("output CRS", problem)
        flat_in = horizontal(self.input)
        if not (flat_in.is_geographic or flat_in.is_projected):
            raise ImportInputError("input CRS", f"{self.input.to_string()} is neither geographic nor projected "
                                   "(geocentric coordinates are not supported)")
        self.input_geographic = flat_in.is_geographic
        self.heights_converted = has_heights(self.input) and has_heights(self.output)
        if has_heights(self.output) and not has_heights(self.input):
            raise ImportInputError(
                "input CRS", f"{self.input.to_string()} does not say what its heights are, but the output CRS "
                f"{self.output.to_string()} has {height_name(self.output)}; give the input CRS with its heights "
                "(EPSG:4979 for WGS 84 ellipsoidal heights, a compound CRS such as EPSG:4326+5773 for EGM96 "
                "heights, EPSG:2056+5728 for LV95 with LN02 heights) or an output CRS without heights")
        if not has_heights(self.input):
            self.warnings.append(f"the input CRS {self.input.to_string()} does not say what its heights are: they "
                                 "are copied as given")
        elif not has_heights(self.output):
            self.warnings.append(f"the output CRS {self.output.to_string()} has no heights: the heights are copied "
                                 f"as the input states them, {height_name(self.input)}")
        self._positions = self._transformer(self.input, self.output)
        geographic, flat_out = self.input.geodetic_crs, horizontal(self.output)
        self._to_input_geographic = self._transformer(self.input, geographic)
        self._geographic_to_grid = self._transformer(geographic, flat_out)
        self._input_to_grid = self._transformer(self.input, flat_out)

    def _transformer(self, source, target):
        """The best transformation PROJ has, refusing a ballpark one or one whose grids are missing."""
        import pyproj
        from pyproj.transformer import TransformerGroup

        with warnings.catch_warnings():  # pyproj warns of a missing grid; the error below names it
            warnings.simplefilter("ignore", UserWarning)
            group = TransformerGroup(source, target, always_xy=True, allow_ballpark=False)
        if group.transformers and group.best_available:
            return group.transformers[0]
        missing = sorted({grid.short_name for op in group.unavailable_operations for grid in op.grids
                          if not grid.available})
        where = f"from {source.to_string()} to {target.to_string()}"
        if missing:
            raise ImportInputError(
                "CRS", f"PROJ lacks the grid(s) {', '.join(missing)} to transform {where}; put them into "
                f"{pyproj.datadir.get_data_dir()} (e.g. `projsync --file {missing[0]}`) or choose CRSs without "
                "that height system")
        if group.transformers:
            return group.transformers[0]
        raise ImportInputError("CRS", f"PROJ knows no transformation {where} better than a ballpark guess")

    def positions(self, xyz: np.ndarray) -> np.ndarray:
        """(n, 3) input coordinates (x = longitude or easting, y = latitude or northing, z = height) in the
        output CRS (easting, northing, height)."""
        xyz = np.asarray(xyz, dtype=float).reshape(-1, 3)
        e, n, h = self._positions.transform(xyz[:, 0], xyz[:, 1], xyz[:, 2])
        out = np.column_stack([e, n, h if self.heights_converted else xyz[:, 2]])
        bad = ~np.isfinite(out).all(axis=1)
        if bad.any():
            first = int(np.flatnonzero(bad)[0])
            raise ImportInputError("CRS", f"position {tuple(xyz[first])} (row {first + 1}) cannot be transformed "
                                   f"from {self.input.to_string()} to {self.output.to_string()}; is it in the "
                                   "input CRS's axis order (longitude/easting first)?")
        return out

    def north_azimuths(self, xyz: np.ndarray, north: str) -> np.ndarray:
        """Azimuth (degrees clockwise from the output's grid north) of the north the angles were recorded against:
        ``"true"``, the input datum's meridian, or ``"grid"``, a projected input's grid north."""
        if north not in ("true", "grid"):
            raise ValueError(f"north must be 'true' or 'grid', not {north!r}")
        xyz = np.asarray(xyz, dtype=float).reshape(-1, 3)
        if north == "grid" and self.input_geographic:
            raise ImportInputError("input CRS", f"{self.input.to_string()} is geographic: it has no grid north; "
                                   "its angles are against true north")
        if north == "grid":
            start, step, to_grid = xyz, xyz + [0.0, NORTH_STEP_M, 0.0], self._input_to_grid
        else:
            lon, lat, h = self._to_input_geographic.transform(xyz[:, 0], xyz[:, 1], xyz[:, 2])
            start = np.column_stack([lon, lat, h])
            step, to_grid = start + [0.0, NORTH_STEP_DEG, 0.0], self._geographic_to_grid
        e0, n0, _ = to_grid.transform(start[:, 0], start[:, 1], start[:, 2])
        e1, n1, _ = to_grid.transform(step[:, 0], step[:, 1], step[:, 2])
        return np.degrees(np.arctan2(np.asarray(e1) - e0, np.asarray(n1) - n0))

    def grid_rotations(self, xyz: np.ndarray, north: str) -> np.ndarray:
        """(n, 3, 3) rotations from the frame the angles were recorded in to the output grid's east/north/up.

        ``north``: ``"true"`` (local level frame, true north) or ``"grid"`` (the projected input's grid).
        """
        return np.stack([rot_z(-np.radians(a)) for a in self.north_azimuths(xyz, north)])
