"""Pose tables as navigation and photogrammetry software export them: CSV with named columns.

One row per image (exterior orientation; ``id`` names the image) or per
trajectory epoch (``time``, interpolated to the image times later). Columns are
found by name, case-insensitive, with the usual aliases; comma, semicolon, tab
or space separated. Positions: ``x`` = longitude or easting, ``y`` = latitude
or northing, ``z`` = height, in the input CRS. Angles: the three named by the
convention (e.g. ``omega, phi, kappa``), in degrees or radians as stated.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ImportInputError

ALIASES = {
    "id": ("id", "image", "image_id", "name", "file", "filename", "photo", "frame"),
    "time": ("time", "t", "timestamp", "gps_time", "gpstime", "seconds", "time_s"),
    "x": ("easting", "x", "e", "lon", "longitude", "long"),
    "y": ("northing", "y", "n", "lat", "latitude"),
    "z": ("height", "z", "h", "alt", "altitude", "ellipsoidal_height", "elevation"),
    "yaw": ("yaw", "heading", "azimuth"),
    "pitch": ("pitch",),
    "roll": ("roll",),
    "heading": ("heading", "yaw", "azimuth"),
    "omega": ("omega", "ω"),
    "phi": ("phi", "φ"),
    "kappa": ("kappa", "κ"),
}
GEOGRAPHIC_X = ("lon", "longitude", "long")



def same_columns(names: tuple[str, ...], others: tuple[str, ...]) -> bool:
    """Whether two conventions' angle names are found under the same column names (yaw/heading, pitch, roll):
    then a table read for one holds the other's angles too."""
    return all(set(ALIASES.get(a, (a,))) == set(ALIASES.get(b, (b,))) for a, b in zip(names, others))

@dataclass(frozen=True)
class PoseTable:
    """Rows of a pose file: positions and angles as given, with the file's line numbers for messages."""

    path: Path
    lines: np.ndarray              # (n,) line numbers
    ids: list[str] | None          # image ids (stems), per-image tables
    times: np.ndarray | None       # (n,) seconds
    xyz: np.ndarray                # (n, 3) x = lon/easting, y = lat/northing, z = height
    angles: np.ndarray             # (n, 3) as given (degrees or radians)
    angle_names: tuple[str, str, str]
    row_files: list[Path] | None = None   # one file per row (KITTI OXTS) instead of lines of ``path``

    def __len__(self) -> int:
        return len(self.lines)

    def where(self, row: int) -> tuple[Path, int]:
        """File and line of a row, for messages."""
        if self.row_files is not None:
            return self.row_files[row], 1
        return self.path, int(self.lines[row])

    def subset(self, rows) -> PoseTable:
        """The table of some rows (e.g. the trajectory epochs around the images)."""
        rows = np.asarray(rows, dtype=int)
        return PoseTable(self.path, self.lines[rows], None if self.ids is None else [self.ids[i] for i in rows],
                         None if self.times is None else self.times[rows], self.xyz[rows], self.angles[rows],
                         self.angle_names, None if self.row_files is None else [self.row_files[i] for i in rows])


def _delimiter(header: str) -> str | None:
    """The separator of the header line: comma, semicolon or tab, else None (runs of spaces)."""
    return next((d for d in (",", ";", "\t") if d in header), None)


def read_rows(path) -> tuple[list[str], list[tuple[int, list[str]]]]:
    """(lower-case header, [(line, cells)]) of a delimited text file; blank lines and ``#`` comments skipped."""
    path = Path(path)
    if not path.is_file():
        raise ImportInputError(path, "file does not exist")
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ImportInputError(path, f"not UTF-8 text ({exc})") from None
    lines = [(n, line) for n, line in enumerate(text.splitlines(), start=1)
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise ImportInputError(path, "file is empty, expected a header line", line=1)
    delimiter = _delimiter(lines[0][1])
    rows = []
    for number, line in lines:
        cells = line.split() if delimiter is None else next(csv.reader([line], delimiter=delimiter))
        rows.append((number, [c.strip() for c in cells]))
    header = [h.lower() for h in rows[0][1]]
    return header, rows[1:]


def column(path: Path, header: list[str], key: str, required: bool = True) -> int | None:
    """Index of the column for ``key`` (any of its aliases), None when optional and absent."""
    for alias in ALIASES.get(key, (key,)):
        if alias in header:
            return header.index(alias)
    if required:
        raise ImportInputError(path, f"header lacks a column for {key} (accepted names: "
                               f"{', '.join(ALIASES.get(key, (key,)))}); found {header}", line=1, field=key)
    return None


def _number(path: Path, line: int, name: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ImportInputError(path, f"{text!r} is not a number", line=line, field=name) from None
    if not math.isfinite(value):
        raise ImportInputError(path, f"{text!r} is not a finite number", line=line, field=name)
    return value


def read_pose_table(path, angle_names: tuple[str, str, str], need_ids: bool, need_times: bool,
                    geographic: bool) -> PoseTable:
    """Read a pose CSV; ``geographic``: x/y are longitude/latitude and are range-checked."""
    path = Path(path)
    header, rows = read_rows(path)
    if not rows:
        raise ImportInputError(path, "has a header but no rows", line=2)
    idx = {key: column(path, header, key) for key in ("x", "y", "z", *angle_names)}
    id_col = column(path, header, "id", required=need_ids)
    time_col = column(path, header, "time", required=need_times)
    lines, ids, times, xyz, angles = [], [], [], [], []
    for line, cells in rows:
        if len(cells) != len(header):
            raise ImportInputError(path, f"has {len(cells)} fields, the header has {len(header)}", line=line)
        lines.append(line)
        if id_col is not None:
            ids.append(cells[id_col])
        if time_col is not None:
            times.append(_number(path, line, header[time_col], cells[time_col]))
        xyz.append([_number(path, line, header[idx[k]], cells[idx[k]]) for k in ("x", "y", "z")])
        angles.append([_number(path, line, header[idx[k]], cells[idx[k]]) for k in angle_names])
    table = PoseTable(path, np.array(lines), ids if id_col is not None else None,
                      np.array(times) if time_col is not None else None, np.array(xyz, float),
                      np.array(angles, float), angle_names)
    if geographic:
        _check_geographic(table, header[idx["x"]] in GEOGRAPHIC_X or header[idx["y"]] in ("lat", "latitude"))
    _check_unique_ids(table)
    return table


def _check_geographic(table: PoseTable, named: bool) -> None:
    lon, lat = table.xyz[:, 0], table.xyz[:, 1]
    for values, limit, name in ((lat, 90.0, "latitude"), (lon, 180.0, "longitude")):
        bad = np.flatnonzero(np.abs(values) > limit)
        if bad.size:
            path, line = table.where(int(bad[0]))
            hint = "" if named else "; are the positions projected? then give their projected CRS as the input CRS"
            raise ImportInputError(path, f"{values[bad[0]]:g} is not a {name} (the input CRS is geographic){hint}",
                                   line=line, field=name)


def _check_unique_ids(table: PoseTable) -> None:
    if table.ids is None:
        return
    seen: dict[str, int] = {}
    for i, pair_id in enumerate(table.ids):
        path, line = table.where(i)
        if not pair_id:
            raise ImportInputError(path, "image id is empty", line=line, field="id")
        if pair_id in seen:
            raise ImportInputError(path, f"image {pair_id!r} repeats line {seen[pair_id]}", line=line, field="id")
        seen[pair_id] = line


def read_image_times(path) -> dict[str, tuple[float, int]]:
    """``id,time`` rows: image id -> (seconds, line)."""
    path = Path(path)
    header, rows = read_rows(path)
    id_col, time_col = column(path, header, "id"), column(path, header, "time")
    times: dict[str, tuple[float, int]] = {}
    for line, cells in rows:
        if len(cells) != len(header):
            raise ImportInputError(path, f"has {len(cells)} fields, the header has {len(header)}", line=line)
        pair_id = cells[id_col]
        if pair_id in times:
            raise ImportInputError(path, f"image {pair_id!r} repeats line {times[pair_id][1]}", line=line, field="id")
        times[pair_id] = (_number(path, line, header[time_col], cells[time_col]), line)
    if not times:
        raise ImportInputError(path, "has a header but no rows", line=2)
    return times
