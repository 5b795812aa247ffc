"""A Processing model chaining syntheticdrive into mapsigns, as a user would build it in the modeler."""

from drive_fixtures import SMALL_SYNTHETIC as SMALL
from qgis.core import (
    QgsProcessingModelAlgorithm,
    QgsProcessingModelChildAlgorithm,
    QgsProcessingModelChildParameterSource,
    QgsProcessingModelOutput,
)


def synthetic_drive_then_map_signs(drive_dir, mapsigns_values=None) -> QgsProcessingModelAlgorithm:
    """Six small pairs with depth written to ``drive_dir``, mapped by mapsigns (its ``mapsigns_values`` as static
    values); the model's output ``map:gpkg`` is mapsigns' GeoPackage."""
    model = QgsProcessingModelAlgorithm("chain", "tests")
    sim = QgsProcessingModelChildAlgorithm("signmapper:syntheticdrive")
    sim.setChildId("sim")
    for name, value in {"PAIRS": 6, "SEED": 12, "WRITE_DEPTH": True, "WIDTH": SMALL["width"],
                        "HEIGHT": SMALL["height"], "FX": SMALL["fx"], "OUTPUT": str(drive_dir)}.items():
        sim.addParameterSources(name, [QgsProcessingModelChildParameterSource.fromStaticValue(value)])
    mapper = QgsProcessingModelChildAlgorithm("signmapper:mapsigns")
    mapper.setChildId("map")
    mapper.addParameterSources("DRIVE", [QgsProcessingModelChildParameterSource.fromChildOutput("sim", "OUTPUT")])
    for name, value in (mapsigns_values or {}).items():
        mapper.addParameterSources(name, [QgsProcessingModelChildParameterSource.fromStaticValue(value)])
    output = QgsProcessingModelOutput("gpkg", "Mapped signs")
    output.setChildId("map")
    output.setChildOutputName("OUTPUT")
    mapper.setModelOutputs({"gpkg": output})
    model.addChildAlgorithm(sim)
    model.addChildAlgorithm(mapper)
    model.updateDestinationParameters()
    return model
