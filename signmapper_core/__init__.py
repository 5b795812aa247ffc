"""Sign Mapper detection core.

Pure Python on numpy, OpenCV, pyproj and shapely: no QGIS or Qt import anywhere
in this package, so it runs and is tested without QGIS and can be driven by
other engines. Modules import each other relatively so the package works both
as ``signmapper_core`` and as ``sign_mapper.signmapper_core`` inside the plugin.
"""

__all__ = ["__version__"]
__version__ = "0.1.0"
