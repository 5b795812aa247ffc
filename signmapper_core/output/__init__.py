"""What a run writes: the output schema and its words, the GeoPackage and its safety, crops and the inventory."""
