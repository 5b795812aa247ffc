"""Validation on imagery the project did not draw: real photographs of signs, mapped to SSV ids.

Public API::

    load_manifest(path, root=None) -> list[RealSign]      # crops.csv / scenes.csv
    load_scene_list(path, root=None) -> list[SceneImage]  # scenes_images.csv
    RealSign.load_image() -> BGR ndarray
"""

from .realset import (
    GROUPS,
    IMAGE_LIST_COLUMNS,
    MANIFEST_COLUMNS,
    SCENE_COLUMN,
    SPLITS,
    ManifestError,
    RealSign,
    SceneImage,
    load_manifest,
    load_scene_list,
    read_bgr,
)

__all__ = [
    "GROUPS",
    "IMAGE_LIST_COLUMNS",
    "MANIFEST_COLUMNS",
    "SCENE_COLUMN",
    "SPLITS",
    "ManifestError",
    "RealSign",
    "SceneImage",
    "load_manifest",
    "load_scene_list",
    "read_bgr",
]
