"""Contact sheet of a drive: a few left images with the truth signs boxed, in one PNG.

``python -m signmapper_core.simulate.contact_sheet DRIVE OUT.png [--tiles 4] [--tile-width 640]``
Boxes are projected from truth.csv with the poses of poses.csv; signs within the
detection range (4-14 m) are boxed green and labelled, others thin orange.
"""

from __future__ import annotations

import argparse
import sys

import cv2
import numpy as np

from ..drive import Drive, TruthSign, open_drive
from ..geometry import world_to_pixel

NEAR_M, FAR_M = 4.0, 14.0


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
        in_range = NEAR_M <= z <= FAR_M
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
    scores = [sum(NEAR_M <= z <= FAR_M for _s, _uv, z in signs_in_view(drive, i)) for i in range(len(drive))]
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
    cols = 2 if len(images) > 1 else 1
    while len(images) % cols:
        images.append(np.zeros_like(images[0]))
    rows = [np.hstack(images[r:r + cols]) for r in range(0, len(images), cols)]
    sheet = np.vstack(rows)
    if not cv2.imwrite(str(out_png), sheet, [cv2.IMWRITE_PNG_COMPRESSION, 9]):
        raise OSError(f"{out_png}: could not write the PNG")
    return sheet


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m signmapper_core.simulate.contact_sheet",
                                description="Draw the truth signs onto a few left images of a drive, as one PNG.")
    p.add_argument("drive", help="drive folder with truth.csv")
    p.add_argument("out", help="output PNG")
    p.add_argument("--tiles", type=int, default=4, help="number of pairs shown (default 4)")
    p.add_argument("--tile-width", type=int, default=640, help="width of each tile in pixels (default 640)")
    args = p.parse_args(argv)
    contact_sheet(args.drive, args.out, args.tiles, args.tile_width)
    print(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
