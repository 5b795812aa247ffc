"""What the deliverable algorithms (Export inventory, Inventory atlas) share: the reviewed signs layer, whether
signs still to review go in, and the language; read as (layer, statuses, language)."""

from __future__ import annotations

from qgis.core import QgsProcessing, QgsProcessingParameterBoolean, QgsProcessingParameterVectorLayer

from ..signmapper_core.output.inventory_export import DELIVERED
from ..signmapper_core.output.schema import run_language
from ..signmapper_core.statuses import REVIEW
from .base import SignMapperAlgorithm
from .signs_input import signs_layer_and_run


class DeliverableAlgorithm(SignMapperAlgorithm):
    """Subclasses call :meth:`add_deliverable_inputs` first, and read them with :meth:`deliverable_inputs`."""

    GROUP_ID = "inventory"
    SIGNS = "SIGNS"
    INCLUDE_REVIEW = "INCLUDE_REVIEW"
    LANGUAGE = "LANGUAGE"
    REVIEW_HELP = ""  # what "Also signs still to review" adds, in the subclass's words
    LANGUAGE_HELP = ""

    def add_deliverable_inputs(self) -> None:
        self.add_parameter(
            QgsProcessingParameterVectorLayer(self.SIGNS, self.tr("Mapped signs"), [QgsProcessing.TypeVectorPoint]),
            "The 'signs' layer written by Map traffic signs, as the review left it.",
        )
        self.add_parameter(
            QgsProcessingParameterBoolean(self.INCLUDE_REVIEW, self.tr("Also signs still to review"), False),
            self.REVIEW_HELP,
        )
        self.add_language_parameter(self.LANGUAGE, "The layer's language", self.LANGUAGE_HELP)

    def deliverable_inputs(self, parameters, context) -> tuple:
        """(signs layer, its run table, the statuses delivered, the language: chosen, else the layer's own)."""

        layer, run = signs_layer_and_run(self.parameterAsVectorLayer(parameters, self.SIGNS, context))
        language = self.chosen_language(parameters, self.LANGUAGE, context) or run_language(run)
        statuses = DELIVERED + ((REVIEW,) if self.parameterAsBoolean(parameters, self.INCLUDE_REVIEW, context)
                                else ())
        return layer, run, statuses, language
