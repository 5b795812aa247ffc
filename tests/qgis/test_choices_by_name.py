"""Every choice (enum) parameter of the plugin takes its option's number or its name, in any case (algorithms/base.py).

QGIS 3.22's enum parameters accept numbers only; ``qgis_process.bin`` passes what
the user typed as text. test_qgis_process_cli.py runs the KITTI preset by name
through ``qgis_process.bin``; here every algorithm's choices are read by name.
"""

import pytest
from qgis.core import QgsApplication, QgsProcessingContext, QgsProcessingParameterEnum


def algorithm(alg_id):
    return QgsApplication.processingRegistry().createAlgorithmById(alg_id)


def test_every_choice_of_every_algorithm_is_read_by_each_of_its_names(registered_plugin):
    from sign_mapper.algorithms.base import enum_names

    context, seen = QgsProcessingContext(), 0
    for alg in QgsApplication.processingRegistry().providerById("signmapper").algorithms():
        alg = algorithm(alg.id())
        for param in alg.parameterDefinitions():
            if not isinstance(param, QgsProcessingParameterEnum):
                continue
            names = enum_names(param)
            assert len(names) == len(param.options()) and len(set(names)) == len(names), (alg.id(), param.name())
            assert all(" " not in name for name in names), (alg.id(), param.name(), names)  # typed on a command line
            for number, name in enumerate(names):
                assert alg.parameterAsEnum({param.name(): name.upper()}, param.name(), context) == number
                assert alg.parameterAsEnum({param.name(): str(number)}, param.name(), context) == number
                seen += 1
    assert seen >= 30


def test_several_choices_by_name_and_the_names_the_plugin_reads(registered_plugin):
    maps, context = algorithm("signmapper:mapsigns"), QgsProcessingContext()
    assert maps.parameterAsEnums({"COLOURS": "red, Yellow"}, "COLOURS", context) == [0, 2]
    assert maps.parameterAsEnums({"COLOURS": ["blue", 0]}, "COLOURS", context) == [1, 0]
    assert maps.chosen_name({"CLASSIFIER": "NCC"}, "CLASSIFIER", context) == "ncc"
    assert maps.chosen_language({"LANGUAGE": "fr"}, "LANGUAGE", context) == "fr"
    assert maps.chosen_language({"LANGUAGE": "Auto"}, "LANGUAGE", context) is None
    imports = algorithm("signmapper:importdrive")
    # the option's text as the dialog shows it counts as a name too
    assert imports.chosen_name({"PRESET": "KITTI raw drive folder"}, "PRESET", context) == "kitti"


@pytest.mark.parametrize("value, message", [
    ("red,purple", "COLOURS (Sign colours to detect): 'purple' is not one of its options; give one of red, blue, "
                   "yellow, green, brown, orange, or the option's number 0 to 5"),
    ("7", "Incorrect parameter value for COLOURS"),   # numbers are QGIS's to check
])
def test_a_choice_it_does_not_have_is_refused_before_the_run(registered_plugin, small_drive, tmp_path, value,
                                                             message):
    ok, text = algorithm("signmapper:mapsigns").checkParameterValues(
        {"DRIVE": str(small_drive), "OUTPUT": str(tmp_path / "signs.gpkg"), "COLOURS": value}, QgsProcessingContext())
    assert not ok and message in text
