"""Rasterise SVG with ``rsvg-convert`` (librsvg): used only to build catalogue masters from official drawings.

Runtime and tests never need it; the build names the missing tool instead of
failing deep inside. librsvg renders deterministically (same version, same
pixels), which keeps the rebuilt masters identical.
"""

from __future__ import annotations

import shutil
import subprocess

import cv2
import numpy as np

RSVG = "rsvg-convert"
INSTALL_HINT = "install it with 'apt-get install librsvg2-bin' (Debian/Ubuntu)"


class RendererMissing(RuntimeError):
    """The SVG renderer needed to build from official drawings is not installed."""


def renderer_available() -> bool:
    return shutil.which(RSVG) is not None


def render_svg(svg: bytes, zoom: float, source: str = "<svg>") -> np.ndarray:
    """BGRA (straight alpha, uint8) rendering of ``svg`` at ``zoom`` (1 = the document's CSS pixel size).

    ``source`` names the drawing in error messages.
    """
    exe = shutil.which(RSVG)
    if exe is None:
        raise RendererMissing(f"{RSVG} not found: building templates from SVG drawings needs it; {INSTALL_HINT}")
    proc = subprocess.run([exe, "--zoom", f"{zoom:.6f}", "--format", "png"], input=svg, capture_output=True)
    if proc.returncode != 0:
        raise ValueError(f"{source}: {RSVG} failed: {proc.stderr.decode(errors='replace').strip()}")
    img = cv2.imdecode(np.frombuffer(proc.stdout, np.uint8), cv2.IMREAD_UNCHANGED)
    if img is None or img.ndim != 3 or img.shape[2] not in (3, 4):
        raise ValueError(f"{source}: {RSVG} returned no colour image")
    if img.shape[2] == 3:  # an opaque rendering may come without alpha
        img = np.dstack([img, np.full(img.shape[:2], 255, np.uint8)])
    return img
