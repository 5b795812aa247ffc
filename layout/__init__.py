"""Print layouts of Sign Mapper's layers (QGIS side): the inventory atlas, a sheet per sign."""
