"""Sign Mapper QGIS plugin entry point.

Kept free of QGIS imports at module level so the package (and its core) can be
imported by plain Python tools; QGIS calls :func:`classFactory`.
"""


def classFactory(iface):  # noqa: N802 - name fixed by QGIS
    """Construct the plugin; QGIS (and ``qgis_process`` with ``iface`` None) calls this."""
    from .dependencies import add_install_locations  # QGIS imports: only once QGIS loads the plugin

    add_install_locations()  # OpenCV where the README installs it, without PYTHONPATH
    from .plugin import SignMapperPlugin  # after the install locations: it may import OpenCV

    return SignMapperPlugin(iface)
