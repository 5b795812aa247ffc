"""Contact sheet of a drive: a few left images with the truth signs boxed, in one PNG.

``python -m signmapper_core.simulate.contact_sheet DRIVE OUT.png [--tiles 4] [--tile-width 640]``
Boxes are projected from truth.csv with the poses of poses.csv; signs within the
mapping's default depth range (``DepthConfig``) are boxed green and labelled,
others thin orange.
``--crops`` instead shows every truth sign cut out of the image where it is seen
from nearest a given distance (``--distance``, default 7 m), to look at faces as
the camera sees them.
"""

from __future__ import annotations

import argparse
import sys

import cv2
import numpy as np

from ..drive.reader import Drive, TruthSign, open_drive
from ..geometry import world_to_pixel
from ..pipeline.config import DepthConfig
from .sheet_grid import write_sheet

SEARCH_NEAR_M, SEARCH_FAR_M = DepthConfig.near_m, DepthConfig.far_m  # the mapping's default search space


def sign_corners(sign: TruthSign) -> np.ndarray:
    """World corners (4, 3) of the sign's bounding box, upright, facing ``sign.facing``."""
    phi = np.radians(sign.facing)
    right = np.array([-np.cos(phi), np.sin(phi), 0.0]) * sign.width_m / 2
    up = np.array([0.0, 0.0, sign.height_m / 2])
    c = sign.position
    return np.array([c - right + up, c + right + up, c + right - up, c - right - up])


def signs_in_view(drive: Drive, index: int) -> list[tuple[TruthSign, np.ndarray, float]]:
    """Truth signs whose face is in front of the camera of pair ``index``: (sign, corners uv, depth)."""
    rec = drive.pairs[index]
    out = []
    for sign in drive.truth or []:
        u, v, z = world_to_pixel(drive.camera, rec.pose, sign_corners(sign))
        facing = np.array([np.sin(np.radians(sign.facing)), np.cos(np.radians(sign.facing)), 0.0])
        towards = float(np.dot(facing, rec.pose.centre - sign.position)) > 0
        if np.all(z > 0.5) and towards:
            uv = np.stack([u, v], axis=1)
            inside = (uv[:, 0].max() > 0 and uv[:, 0].min() < drive.camera.width and uv[:, 1].max() > 0
                      and uv[:, 1].min() < drive.camera.height)
            if inside:
                out.append((sign, uv, float(np.mean(z))))
    return out


def annotate(drive: Drive, index: int) -> np.ndarray:
    img = drive.load_left(drive.pairs[index])
    scale = max(1, img.shape[1] // 640)
    for sign, uv, z in signs_in_view(drive, index):
        in_range = SEARCH_NEAR_M <= z <= SEARCH_FAR_M
        colour = (0, 255, 0) if in_range else (0, 200, 255)
        cv2.polylines(img, [np.round(uv).astype(np.int32)], True, colour, 2 * scale if in_range else scale,
                      cv2.LINE_AA)
        if not in_range:
            continue
        label = f"{sign.template_id} {z:.1f} m"
        org = (int(uv[:, 0].min()), max(12, int(uv[:, 1].min()) - 4))
        cv2.putText(img, label, org, cv2.FONT_HERSHEY_SIMPLEX, 0.45 * scale, (0, 0, 0), 3 * scale, cv2.LINE_AA)
        cv2.putText(img, label, org, cv2.FONT_HERSHEY_SIMPLEX, 0.45 * scale, colour, scale, cv2.LINE_AA)
    return img


def pick_pairs(drive: Drive, count: int) -> list[int]:
    """Pairs with the most truth signs in range, spread over the drive."""
    scores = [sum(SEARCH_NEAR_M <= z <= SEARCH_FAR_M for _s, _uv, z in signs_in_view(drive, i))
              for i in range(len(drive))]
    chosen: list[int] = []
    for i in sorted(range(len(drive)), key=lambda k: (-scores[k], k)):
        if all(abs(i - j) >= 3 for j in chosen):
            chosen.append(i)
        if len(chosen) == count:
            break
    return sorted(chosen)


def contact_sheet(drive_path, out_png, tiles: int = 4, tile_width: int = 640) -> np.ndarray:
    drive = open_drive(drive_path)
    chosen = pick_pairs(drive, tiles)
    images = []
    for i in chosen:
        img = annotate(drive, i)
        h = int(round(img.shape[0] * tile_width / img.shape[1]))
        small = cv2.resize(img, (tile_width, h), interpolation=cv2.INTER_AREA)
        cv2.putText(small, f"pair {drive.pairs[i].id}", (8, h - 10), cv2.FONT_HERSHEY_SIMPLEX, 0.5,
                    (255, 255, 255), 1, cv2.LINE_AA)
        images.append(small)
    return write_sheet(out_png, images, 2 if len(images) > 1 else 1, 0)


def sign_crops(drive_path, out_png, distance_m: float = 7.0, tile: int = 128, columns: int = 8) -> np.ndarray:
    """Each truth sign cut out (with a margin) of the left image that sees it nearest ``distance_m``."""
    drive = open_drive(drive_path)
    best: dict[str, tuple[float, int, np.ndarray]] = {}
    for i in range(len(drive)):
        for sign, uv, z in signs_in_view(drive, i):
            inside = (uv[:, 0].min() >= 0 and uv[:, 1].min() >= 0 and uv[:, 0].max() < drive.camera.width
                      and uv[:, 1].max() < drive.camera.height)
            nearer = abs(z - distance_m) < best.get(sign.sign_id, (np.inf,))[0]
            if inside and SEARCH_NEAR_M <= z <= SEARCH_FAR_M and nearer:
                best[sign.sign_id] = (abs(z - distance_m), i, uv)
    tiles = []
    for sign in drive.truth or []:
        if sign.sign_id not in best:
            continue
        _d, i, uv = best[sign.sign_id]
        img = drive.load_left(drive.pairs[i])
        x0, y0 = uv.min(axis=0)
        x1, y1 = uv.max(axis=0)
        m = 0.2 * max(x1 - x0, y1 - y0)
        x0, y0 = int(max(0, x0 - m)), int(max(0, y0 - m))
        x1, y1 = int(min(img.shape[1], x1 + m)), int(min(img.shape[0], y1 + m))
        crop = img[y0:y1, x0:x1]
        scale = tile / max(crop.shape[:2])
        crop = cv2.resize(crop, (max(1, round(crop.shape[1] * scale)), max(1, round(crop.shape[0] * scale))),
                          interpolation=cv2.INTER_AREA if scale < 1 else cv2.INTER_NEAREST)
        cell = np.full((tile + 16, tile, 3), 40, np.uint8)
        cell[:crop.shape[0], :crop.shape[1]] = crop
        z = float(np.linalg.norm(sign.position - drive.pairs[i].pose.centre))
        cv2.putText(cell, f"{sign.template_id} {z:.0f}m", (2, tile + 12), cv2.FONT_HERSHEY_SIMPLEX, 0.38,
                    (255, 255, 255), 1, cv2.LINE_AA)
        tiles.append(cell)
    if not tiles:
        raise ValueError(f"{drive_path}: no truth sign is fully in view within {SEARCH_NEAR_M:g}-{SEARCH_FAR_M:g} m")
    return write_sheet(out_png, tiles, columns, 40)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m signmapper_core.simulate.contact_sheet",
                                description="Draw the truth signs onto a few left images of a drive, as one PNG.")
    p.add_argument("drive", help="drive folder with truth.csv")
    p.add_argument("out", help="output PNG")
    p.add_argument("--tiles", type=int, default=4, help="number of pairs shown (default %(default)s)")
    p.add_argument("--tile-width", type=int, default=640, help="width of each tile in pixels (default %(default)s)")
    p.add_argument("--crops", action="store_true", help="one crop per truth sign instead of whole images")
    p.add_argument("--distance", type=float, default=7.0, help="with --crops: preferred viewing distance, m")
    args = p.parse_args(argv)
    if args.crops:
        sign_crops(args.drive, args.out, args.distance)
    else:
        contact_sheet(args.drive, args.out, args.tiles, args.tile_width)
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
