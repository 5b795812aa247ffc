"""The grid and the PNG of the simulator's contact sheets (a drive's images, its signs' crops, faces, artwork)."""

from __future__ import annotations

from typing import Sequence

import cv2
import numpy as np


def tile_grid(tiles: Sequence[np.ndarray], columns: int, fill: int) -> np.ndarray:
    """Tiles of one size in rows of ``columns``, the last row made up with blank tiles of grey value ``fill``."""
    tiles = list(tiles)
    while len(tiles) % columns:
        tiles.append(np.full_like(tiles[0], fill))
    return np.vstack([np.hstack(tiles[r:r + columns]) for r in range(0, len(tiles), columns)])


def write_sheet(path, tiles: Sequence[np.ndarray], columns: int, fill: int) -> np.ndarray:
    """The sheet of ``tiles`` (:func:`tile_grid`), written as a compressed PNG at ``path``; OSError where it cannot
    be written (cv2 only returns False)."""
    sheet = tile_grid(tiles, columns, fill)
    if not cv2.imwrite(str(path), sheet, [cv2.IMWRITE_PNG_COMPRESSION, 9]):
        raise OSError(f"{path}: could not write the PNG")
    return sheet
