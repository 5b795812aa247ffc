"""Mapping a drive once for a test module, the plugin registered only for that."""


def map_drive(sign_mapper, drive, out, **params):
    """``out`` mapped from ``drive`` by mapsigns with ``params``, the plugin registered only for it (for
    module-scoped fixtures, which cannot use ``registered_plugin``)."""
    import processing

    plugin = sign_mapper.classFactory(None)
    plugin.initProcessing()
    try:
        processing.run("signmapper:mapsigns", {"DRIVE": str(drive), "OUTPUT": str(out), **params})
    finally:
        plugin.unload()
    return out
