"""``signmapper:inventoryatlas``: a PDF with a sheet per delivered sign, and the print layout that makes it."""

from __future__ import annotations

from pathlib import Path

from qgis.core import (
    QgsLayoutExporter,
    QgsProcessingAlgorithm,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFileDestination,
    QgsProject,
)

from ..layout.atlas import atlas_layout
from ..signmapper_core.output.partial_output import write_failure
from .deliverable import DeliverableAlgorithm

LAYOUT_NAME = "Sign Mapper inventory: {layer}"


class InventoryAtlasAlgorithm(DeliverableAlgorithm):
    NAME = "inventoryatlas"
    DISPLAY_NAME = "Inventory atlas (PDF)"
    ICON = "inventory_atlas.svg"
    HELP = (
        "Prints the delivered signs of a 'signs' layer (accepted and added by hand; optionally also those still to "
        "review) as a PDF with one A4 sheet per sign, in sign number order: SSV number and name, sign number, "
        "status and date, the catalogue pictogram, the photo (the image crop Map traffic signs writes beside the "
        "GeoPackage), E/N/H, face azimuth, mounting height, format and size, the sign a plate belongs to, its text, "
        "and a map of its surroundings at 1:250. Titles and words are in the output language. The print layout "
        "can be added to the project (Project ▸ Layouts) to adjust and print it again; its map shows the "
        "project's layers (a background map, the trajectory) when the signs layer is one of them. A failed or "
        "cancelled run leaves an earlier PDF as it was."
    )

    ADD_LAYOUT = "ADD_LAYOUT"
    OUTPUT = "OUTPUT"
    REVIEW_HELP = "Also a sheet for each sign whose status is still 'review' (its status line says so)."
    LANGUAGE_HELP = ("Titles, sign names and words (status, format) on the sheets in this language; by default the "
                     "language the signs were mapped in.")

    def flags(self):
        # a layout is built and its pictures and map drawn on the GUI thread, as QGIS's own atlas export does
        return super().flags() | QgsProcessingAlgorithm.FlagNoThreading

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_deliverable_inputs()
        self.add_parameter(
            QgsProcessingParameterBoolean(self.ADD_LAYOUT, self.tr("Add the print layout to the project"), True),
            "The layout behind the PDF in Project ▸ Layouts, to adjust and print again (replacing an earlier one "
            "of the same name). Only for a signs layer of the project.",
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Atlas PDF"), fileFilter="PDF (*.pdf)"),
            "The PDF to write, one sheet per sign.",
        )
        self.addOutput(QgsProcessingOutputNumber("PAGES", self.tr("Sheets")))

    def check_outputs(self, parameters, context) -> None:
        target = Path(self.output_target(parameters, self.OUTPUT, context))
        if target.suffix.lower() != ".pdf":  # said before any file is locked
            raise QgsProcessingException(f"{self.parameterDefinition(self.OUTPUT).description()}: {target}: give a "
                                         "file ending in .pdf")
        super().check_outputs(parameters, context)

    def process(self, parameters, context, feedback):
        from ..signmapper_core.catalogue import load_catalogue  # delays OpenCV until used

        target = Path(self.output_target(parameters, self.OUTPUT, context))
        layer, run, statuses, language = self.deliverable_inputs(parameters, context)
        folder = run.get("catalogue")
        catalogue = load_catalogue(folder if folder and (Path(folder) / "catalogue.json").is_file() else None)
        project = context.project()  # None in qgis_process without --PROJECT_PATH: the layout needs one
        owner = project if project is not None else QgsProject()
        layout = atlas_layout(owner, layer, catalogue, language, statuses, LAYOUT_NAME.format(layer=layer.name()))
        atlas = layout.atlas()
        if not atlas.updateFeatures():
            raise QgsProcessingException(f"{layer.name()}: no sign with status {', '.join(statuses)}: no atlas "
                                         "to print")
        feedback.pushInfo(f"{atlas.count()} sheets, in {language}")
        partial = self.parameterAsFileOutput(parameters, self.OUTPUT, context)  # moved in when the run succeeds
        result, error = QgsLayoutExporter.exportToPdf(atlas, partial, QgsLayoutExporter.PdfExportSettings(), feedback)
        if feedback.isCanceled():
            raise QgsProcessingException(f"Cancelled; {target} not written.")
        if result != QgsLayoutExporter.Success:
            raise write_failure(target, "the atlas", error or f"QgsLayoutExporter error {result}")
        if self.parameterAsBoolean(parameters, self.ADD_LAYOUT, context):
            self.add_to_project(project, layer, layout, feedback)
        return {self.OUTPUT: str(target), "PAGES": atlas.count()}

    @staticmethod
    def add_to_project(project, layer, layout, feedback) -> None:
        if project is None or project.mapLayer(layer.id()) is None:
            feedback.pushInfo("The print layout is not added: the signs layer is not a layer of the project")
            return
        manager = project.layoutManager()
        earlier = manager.layoutByName(layout.name())
        if earlier is not None:
            manager.removeLayout(earlier)
        manager.addLayout(layout)
        feedback.pushInfo(f"Print layout '{layout.name()}' added to the project (Project ▸ Layouts)")
