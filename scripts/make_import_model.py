"""Write ``models/import_and_map_signs.model3``: raw survey in, mapped signs out, as a Processing model.

    make import-model        (or: .venv/bin/python -m scripts.make_import_model [OUT.model3])

The model chains ``signmapper:importdrive`` (generic preset: image folders, calibration, pose or trajectory
CSV) into ``signmapper:mapsigns`` and ``signmapper:drivetrajectory`` (pose preview) on the imported drive. Its
inputs are copies of the import's own parameters (same names, help and defaults), so a surveyor fills in one
dialog; the mapping runs with its defaults (open the model in the Model Designer to expose more). Built from the
registered algorithms rather than written by hand, so the file cannot name a parameter the plugin lacks.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

from scripts.qgis_plugin import load_plugin

ROOT = Path(__file__).resolve().parents[1]
MODEL_PATH = ROOT / "models" / "import_and_map_signs.model3"
MODEL_NAME = "Import a raw survey and map its signs"
GROUP = "Sign Mapper"

# the import's parameters a surveyor sets for raw images + calibration + poses (the generic preset)
IMPORT_INPUTS = ("LEFT", "RIGHT", "LEFT_PATTERN", "RIGHT_PATTERN", "CALIBRATION", "POSES", "POSES_KIND",
                 "IMAGE_TIMES", "ANGLES", "ANGLE_UNIT", "NORTH", "INPUT_CRS", "OUTPUT_CRS", "LEVER_X", "LEVER_Y",
                 "LEVER_Z", "BORESIGHT_HEADING", "BORESIGHT_PITCH", "BORESIGHT_ROLL")
OUTPUTS = (("import", "OUTPUT", "Drive folder"), ("import", "CHECK_IMAGE", "Epipolar check image"),
           ("trajectory", "OUTPUT", "Trajectory"), ("map", "OUTPUT", "Signs GeoPackage"))


def build_model(registry):
    """The model, from the algorithms registered in ``registry`` (the plugin's provider must be loaded)."""
    from qgis.core import (
        QgsProcessingModelAlgorithm,
        QgsProcessingModelChildAlgorithm,
        QgsProcessingModelChildParameterSource,
        QgsProcessingModelOutput,
        QgsProcessingModelParameter,
    )
    from qgis.PyQt.QtCore import QPointF

    importer = registry.algorithmById("signmapper:importdrive")
    if importer is None:
        raise RuntimeError("signmapper:importdrive is not registered: load the Sign Mapper provider first")
    model = QgsProcessingModelAlgorithm(MODEL_NAME, GROUP, "signmapper")
    model.setHelpContent({"ALG_DESC": (
        "Raw (or rectified) stereo images, their calibration and the vehicle's poses or trajectory in; a drive "
        "folder (rectified normal images, poses of the left camera), a trajectory preview and the mapped signs "
        "out. Inputs are those of Import drive (generic); the mapping uses Map traffic signs' defaults.")})
    source = QgsProcessingModelChildParameterSource
    for row, name in enumerate(IMPORT_INPUTS):
        definition = importer.parameterDefinition(name).clone()
        component = QgsProcessingModelParameter(name)
        component.setPosition(QPointF(120, 60 + 45 * row))
        model.addModelParameter(definition, component)

    imp = QgsProcessingModelChildAlgorithm("signmapper:importdrive")
    imp.setChildId("import")
    imp.setDescription("Import drive")
    imp.setPosition(QPointF(480, 420))
    imp.addParameterSources("PRESET", [source.fromStaticValue(0)])
    for name in IMPORT_INPUTS:
        imp.addParameterSources(name, [source.fromModelParameter(name)])
    trajectory = QgsProcessingModelChildAlgorithm("signmapper:drivetrajectory")
    trajectory.setChildId("trajectory")
    trajectory.setDescription("Drive trajectory (pose preview)")
    trajectory.setPosition(QPointF(820, 300))
    mapper = QgsProcessingModelChildAlgorithm("signmapper:mapsigns")
    mapper.setChildId("map")
    mapper.setDescription("Map traffic signs")
    mapper.setPosition(QPointF(820, 540))
    for child in (trajectory, mapper):
        child.addParameterSources("DRIVE", [source.fromChildOutput("import", "OUTPUT")])
    children = {"import": imp, "trajectory": trajectory, "map": mapper}
    for child_id, output, title in OUTPUTS:
        model_output = QgsProcessingModelOutput(title)
        model_output.setChildId(child_id)
        model_output.setChildOutputName(output)
        model_output.setMandatory(output != "CHECK_IMAGE")
        outputs = children[child_id].modelOutputs()
        outputs[title] = model_output
        children[child_id].setModelOutputs(outputs)
    for child in children.values():
        _defaults_for_the_rest(registry.algorithmById(child.algorithmId()), child)
        model.addChildAlgorithm(child)
    model.updateDestinationParameters()
    return model


def _defaults_for_the_rest(algorithm, child) -> None:
    """Every parameter of ``child`` not fed by the model gets the algorithm's default, as the Model Designer
    does when an algorithm is added: the model then validates, and the defaults are visible in the designer."""
    from qgis.core import QgsProcessingModelChildParameterSource

    sources = child.parameterSources()
    for definition in algorithm.parameterDefinitions():
        name = definition.name()
        if name in sources or definition.isDestination() or definition.defaultValue() is None:
            continue
        child.addParameterSources(name, [QgsProcessingModelChildParameterSource.fromStaticValue(
            definition.defaultValue())])


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else MODEL_PATH
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication

    app = QgsApplication([], False)
    app.initQgis()
    with tempfile.TemporaryDirectory() as plugins:
        plugin = load_plugin(Path(plugins))
        model = build_model(QgsApplication.processingRegistry())
        out.parent.mkdir(parents=True, exist_ok=True)
        if not model.toFile(str(out)):
            raise SystemExit(f"{out}: could not be written")
        plugin.unload()
    print(f"{out}: {len(model.parameterDefinitions())} parameters, children "
          f"{', '.join(model.childAlgorithms())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
