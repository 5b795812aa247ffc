"""The words of coded output values: every code the output writes has one in every output language."""

from signmapper_core.catalogue import load_catalogue
from signmapper_core.output.schema import LANGUAGE_NAMES, LANGUAGES
from signmapper_core.output.value_names import VALUE_NAMES, value_map, value_name
from signmapper_core.plates.formats import PLATE_FORMATS
from signmapper_core.statuses import STATUS_COLOURS


def test_every_code_written_has_a_word_in_every_language():
    catalogue = load_catalogue()
    written = {"status": set(STATUS_COLOURS), "reviewed": {0, 1},
               "colour": {e.colour for e in catalogue}, "shape": {e.shape for e in catalogue} | {"rectangle"},
               "format": {f for e in catalogue for f in e.formats} | set(PLATE_FORMATS) | {"measured"}}
    for field, codes in written.items():
        assert codes <= set(VALUE_NAMES[field]), (field, codes - set(VALUE_NAMES[field]))
        for code in codes:
            assert all(VALUE_NAMES[field][code][language] for language in LANGUAGES)
    assert set(LANGUAGE_NAMES) == set(LANGUAGES)


def test_a_french_output_reads_french_words_and_codes_stay_codes():
    assert value_name("status", "review", "fr") == "à contrôler"
    assert value_name("reviewed", 1, "fr") == "oui" and value_name("reviewed", 0, "de") == "nein"
    assert value_name("shape", "circle", "it") == "cerchio" and value_name("format", "normal-2", "de") == \
        "normal, 2 Zeilen"
    assert value_name("status", "something new", "fr") == "something new"  # no word: the code as it is
    assert value_name("template_id", "2.30", "fr") == "2.30"  # not a coded field
    assert value_map("status", "de") == {"akzeptiert": "accepted", "zu prüfen": "review", "verworfen": "rejected",
                                         "von Hand erfasst": "manual"}
