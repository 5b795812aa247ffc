"""Sign Mapper's GeoPackages on the QGIS side: fields and features from ``signmapper_core.output.schema``,
atomic writing and the run table (``output``), the embedded default styles (``styles``).

Used by the ``mapsigns`` and ``evaluate`` algorithms and by the review.
"""
