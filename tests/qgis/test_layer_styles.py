"""Layer styles: every way a run's layers reach the map is styled, the review state shows and follows decisions,
the legend groups by sign family, fields carry aliases in the output language."""

from pathlib import Path

import numpy as np
import pytest
from model_chain import synthetic_drive_then_map_signs
from qgis.core import (
    QgsExpressionContext,
    QgsExpressionContextScope,
    QgsExpressionContextUtils,
    QgsFeature,
    QgsGeometry,
    QgsMapRendererParallelJob,
    QgsMapSettings,
    QgsPoint,
    QgsPointXY,
    QgsProject,
    QgsRectangle,
    QgsVectorLayer,
)
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor, QImage

from signmapper_core.catalogue import load_catalogue
from signmapper_core.statuses import STATUS_COLOURS

STATUSES = ("accepted", "review", "rejected", "manual")
SPACING_M = 10.0  # between the test signs on the map
PX_PER_M = 8.0


@pytest.fixture
def styles(sign_mapper):
    from sign_mapper.gpkg import styles

    return styles


@pytest.fixture
def clean_project():
    yield QgsProject.instance()
    QgsProject.instance().removeAllMapLayers()


def memory_signs(statuses, template_id="2.30-50"):
    """A signs-like memory layer: one 2.30-50 per status, SPACING_M apart along x."""
    layer = QgsVectorLayer("Point?crs=EPSG:2056&field=template_id:string&field=status:string&field=azimuth:double",
                           "signs", "memory")
    features = []
    for i, status in enumerate(statuses):
        feature = QgsFeature(layer.fields())
        feature.setAttributes([template_id, status, None])
        feature.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(2600000.0 + SPACING_M * i, 1200000.0)))
        features.append(feature)
    layer.dataProvider().addFeatures(features)
    return layer


def render(layer, n, extent=None, size=None):
    """The layer drawn as RGB: ``n`` test signs SPACING_M apart, or ``extent`` at ``size`` pixels (96 dpi, the
    map's expression context as the canvas sets it)."""
    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(layer.crs())
    width = int(SPACING_M * n * PX_PER_M)
    settings.setOutputSize(size or QSize(width, int(SPACING_M * PX_PER_M)))
    settings.setExtent(extent or QgsRectangle(2600000.0 - SPACING_M / 2, 1200000.0 - SPACING_M / 2,
                                              2600000.0 + SPACING_M * (n - 0.5), 1200000.0 + SPACING_M / 2))
    settings.setBackgroundColor(QColor("white"))
    settings.setOutputDpi(96)
    map_context = QgsExpressionContext()
    map_context.appendScope(QgsExpressionContextUtils.mapSettingsScope(settings))
    settings.setExpressionContext(map_context)
    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage().convertToFormat(QImage.Format_RGB888)
    ptr = image.constBits()
    ptr.setsize(image.bytesPerLine() * image.height())
    rows = np.frombuffer(ptr, np.uint8).reshape(image.height(), image.bytesPerLine())
    return rows[:, : image.width() * 3].reshape(image.height(), image.width(), 3).copy()


def cells(rgb, n):
    w = rgb.shape[1] // n
    return [rgb[:, i * w:(i + 1) * w] for i in range(n)]


def share_near(cell, colour, tolerance=40):
    target = np.array(QColor(colour).getRgb()[:3])
    return float(np.mean(np.abs(cell.astype(int) - target).sum(axis=2) < tolerance))


def strong_red(cell):
    r, g, b = (cell[..., i].astype(int) for i in range(3))
    return float(np.mean((r > 180) & (g < 80) & (b < 80)))


def test_review_state_shows_in_the_symbol_and_follows_decisions(styles):
    layer = memory_signs(STATUSES)
    styles.apply_style(layer, "signs", load_catalogue(), "de")
    accepted, review, rejected, manual = cells(render(layer, 4), 4)
    assert strong_red(accepted) > 0.01 and share_near(accepted, STATUS_COLOURS["review"]) < 0.002
    assert share_near(review, STATUS_COLOURS["review"], 60) > 0.01  # orange halo
    assert strong_red(rejected) < 0.2 * strong_red(accepted)  # faded
    assert share_near(rejected, "#212121", 60) > 0.002  # crossed
    assert share_near(manual, STATUS_COLOURS["manual"]) > 0.002 and share_near(accepted,
                                                                              STATUS_COLOURS["manual"]) < 0.001
    # a decision changes the picture at the next repaint, without restyling
    layer.startEditing()
    fid = sorted(f.id() for f in layer.getFeatures())[1]
    layer.changeAttributeValue(fid, layer.fields().indexOf("status"), "rejected")
    layer.commitChanges()
    _, decided, _, _ = cells(render(layer, 4), 4)
    assert share_near(decided, STATUS_COLOURS["review"], 60) < 0.002 and share_near(decided, "#212121", 60) > 0.002


def test_legend_has_classes_by_status_then_the_pictograms_by_sign_family(styles):
    catalogue = load_catalogue()
    renderer = styles.signs_renderer(catalogue, "fr")
    status, *groups = renderer.rootRule().children()
    assert status.label() == "Statut"
    assert [(r.label(), r.filterExpression()) for r in status.children()] == [
        ("accepté", "\"status\" = 'accepted'"), ("à contrôler", "\"status\" = 'review'"),
        ("rejeté", "\"status\" = 'rejected'"), ("ajouté à la main", "\"status\" = 'manual'")]
    legend = [item.label() for item in renderer.legendSymbolItems()]
    assert legend[:5] == ["Statut", "accepté", "à contrôler", "rejeté", "ajouté à la main"]
    labels = [g.label() for g in groups]
    assert labels == ["Signaux de danger", "Signaux de priorité", "Interdictions", "Prescriptions",
                      "Signaux d'indication", "Plaque complémentaire", "Signal inconnu", "other"]
    assert sum(len(g.children()) for g in groups[:-3]) == len(catalogue)
    # supplementary plates: one rule, typed or not; the signs no catalogue entry matches: one rule
    assert groups[-3].filterExpression() == "\"plate_of\" IS NOT NULL OR \"template_id\" = 'plate'"
    assert groups[-2].filterExpression() == "\"template_id\" = 'unknown'"
    danger = {r.label().split(" ", 1)[0] for r in groups[0].children()}
    assert "1.01" in danger and "2.30-50" not in danger
    mandatory = {r.label().split(" ", 1)[0] for r in groups[3].children()}
    assert "2.37" in mandatory and all(catalogue[i].colour == "blue" for i in mandatory)
    assert groups[-1].isElse()


def test_fields_get_aliases_in_the_output_language(styles, small_drive, registered_plugin, tmp_path):
    import processing

    out = tmp_path / "fr.gpkg"
    processing.run("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out), "LANGUAGE": 3})  # fr
    layer = QgsVectorLayer(f"{out}|layername=signs", "signs", "ogr")  # opens with the embedded default style
    aliases = {f.name(): f.alias() for f in layer.fields()}
    assert aliases["template_id"] == "Type de signal (OSR)" and aliases["elevation"] == "H [m]"
    names = {f["template_id"]: f["name"] for f in layer.getFeatures()}
    catalogue = load_catalogue()
    assert names and all(name == catalogue[tid].name("fr") for tid, name in names.items())
    # coded values read in French where people read them (table, identify, forms, labels); the file keeps codes
    from qgis.core import QgsExpression, QgsExpressionContext, QgsExpressionContextUtils

    context = QgsExpressionContext(QgsExpressionContextUtils.globalProjectLayerScopes(layer))
    shown = QgsExpression("represent_value(\"status\") || ' | ' || represent_value(\"reviewed\") || ' | ' || "
                          "represent_value(\"shape\") || ' | ' || represent_value(\"format\")")
    for feature in layer.getFeatures():
        context.setFeature(feature)
        status = {"accepted": "accepté", "review": "à contrôler"}[feature["status"]]
        shape = {"circle": "cercle", "triangle": "triangle", "rectangle": "rectangle", "square": "carré",
                 "diamond": "losange", "octagon": "octogone"}[feature["shape"]]
        fmt = {"normal": "normal", "large": "grand", "small": "petit", "intermediate": "intermédiaire"}.get(
            feature["format"], feature["format"])
        assert shown.evaluate(context) == f"{status} | non | {shape} | {fmt}"



@pytest.fixture
def qgis_locale():
    """set(locale): QGIS's own locale override, as in Settings ▸ Options ▸ General; restored afterwards."""
    from qgis.core import QgsSettings

    settings = QgsSettings()
    saved = {key: settings.value(key) for key in ("locale/overrideFlag", "locale/userLocale")}

    def set_locale(locale: str) -> None:
        settings.setValue("locale/overrideFlag", True)
        settings.setValue("locale/userLocale", locale)

    yield set_locale
    for key, value in saved.items():
        if value is None:
            settings.remove(key)
        else:
            settings.setValue(key, value)


def test_without_a_language_chosen_the_output_speaks_the_language_qgis_is_set_to(registered_plugin, qgis_locale):
    from qgis.core import QgsApplication, QgsProcessingContext

    algorithm = QgsApplication.processingRegistry().algorithmById("signmapper:mapsigns")
    context = QgsProcessingContext()
    for locale, language in (("fr_CH", "fr"), ("it_CH", "it"), ("de_CH", "de"), ("en_GB", "en"), ("rm_CH", "en")):
        qgis_locale(locale)
        assert algorithm.language({}, context) == language, locale  # LANGUAGE left at its default
    qgis_locale("fr_CH")
    assert algorithm.language({"LANGUAGE": 3}, context) == "fr" and algorithm.language({"LANGUAGE": 1}, context) != "fr"
    choices = algorithm.parameterDefinition("LANGUAGE").options()  # offered by name, in the order of the codes
    assert choices[1:] == ["English", "Deutsch", "Français", "Italiano"]


def _assert_styled(layer, language_alias):
    assert layer.renderer().type() == "RuleRenderer", layer.name()
    assert layer.labelsEnabled()
    assert layer.fields().field("template_id").alias() == language_alias


def test_run_and_load_results_gives_styled_layers(registered_plugin, small_drive, tmp_path, clean_project):
    """The dialog's path: Processing loads the layers without their default style; the post-processor styles."""
    import processing

    out = tmp_path / "loaded.gpkg"
    processing.runAndLoadResults("signmapper:mapsigns", {"DRIVE": str(small_drive), "OUTPUT": str(out),
                                                         "LANGUAGE": 2})  # de
    layers = {Path(layer.source().split("|")[0]).name + "|" + layer.source().split("=")[-1]: layer
              for layer in clean_project.mapLayers().values()}
    signs, detections = layers["loaded.gpkg|signs"], layers["loaded.gpkg|detections"]
    _assert_styled(signs, "Signaltyp (SSV)")
    assert detections.renderer().type() == "categorizedSymbol"
    assert detections.renderer().classAttribute() == "status"


def test_a_model_run_loads_styled_layers(registered_plugin, tmp_path, clean_project):
    import processing

    model = synthetic_drive_then_map_signs(tmp_path / "d", {"LANGUAGE": 1})  # en
    processing.runAndLoadResults(model, {"map:gpkg": str(tmp_path / "chain.gpkg")})
    signs = [layer for layer in clean_project.mapLayers().values() if layer.source().endswith("layername=signs")]
    assert signs, [layer.source() for layer in clean_project.mapLayers().values()]
    for layer in signs:
        _assert_styled(layer, "Sign type (SSV)")


def pole_layer():
    """Three signs on one pole (2.30-50 at the top, 2.37, 3.03 at the bottom, a few cm apart) and one alone."""
    layer = QgsVectorLayer("PointZ?crs=EPSG:2056&field=template_id:string&field=status:string&field=azimuth:double"
                           "&field=elevation:double", "signs", "memory")
    features = []
    for template_id, status, dx, z in (("2.37", "review", 0.04, 401.3), ("2.30-50", "accepted", 0.0, 402.0),
                                       ("3.03", "accepted", 0.02, 400.6), ("2.30-50", "accepted", 20.0, 402.0)):
        feature = QgsFeature(layer.fields())
        feature.setAttributes([template_id, status, 180.0, z])
        feature.setGeometry(QgsGeometry(QgsPoint(2600000.0 + dx, 1200000.0, z)))
        features.append(feature)
    layer.dataProvider().addFeatures(features)
    return layer


def test_every_sign_on_a_pole_is_drawn_and_labelled_apart_highest_on_top(styles, clean_project):
    """Signs on one pole once hid each other (13 signs showed as 8 symbols): stacked by height on the map."""
    from qgis.core import QgsRenderContext

    layer = pole_layer()
    clean_project.addMapLayer(layer)
    styles.apply_style(layer, "signs", load_catalogue(), "de")
    # the offsets QGIS draws with, per sign: its face, its label
    context = QgsRenderContext()
    context.setExpressionContext(layer.createExpressionContext())
    rules = {}
    for group in layer.renderer().rootRule().children():
        for rule in group.children():
            rules[rule.filterExpression()] = rule
    face_y, label_y = {}, {}
    label_settings = layer.labeling().settings()  # a copy: kept while its properties are read
    label_offset = label_settings.dataDefinedProperties().property(styles.QgsPalLayerSettings.OffsetXY)
    for feature in layer.getFeatures():
        context.expressionContext().setFeature(feature)
        face = rules[f"\"template_id\" = '{feature['template_id']}'"].symbol().symbolLayer(0)
        offset, _ = face.dataDefinedProperties().property(styles.QgsSymbolLayer.PropertyOffset).valueAsString(
            context.expressionContext())
        face_y[feature.id()] = float(offset.split(",")[1])
        text, _ = label_offset.valueAsString(context.expressionContext())
        label_y[feature.id()] = float(text.split(",")[1])
    by_height = sorted((f for f in layer.getFeatures() if f.geometry().asPoint().x() < 2600010),
                       key=lambda f: -f["elevation"])
    ys = [face_y[f.id()] for f in by_height]
    step = styles.STACK_STEP_MM
    assert ys == pytest.approx([-step, 0.0, step])  # the highest on top, the stack centred on the pole
    alone = next(f for f in layer.getFeatures() if f.geometry().asPoint().x() > 2600010)
    assert face_y[alone.id()] == 0.0
    assert label_y == face_y  # each label beside its own pictogram
    assert label_settings.displayAll  # none dropped as a collision
    far = QgsExpressionContextScope()
    far.setVariable("map_scale", 2 * styles.STACK_MAX_SCALE)  # zoomed out: poles are not told apart, not stacked
    context.expressionContext().appendScope(far)
    context.expressionContext().setFeature(by_height[0])
    assert label_offset.valueAsString(context.expressionContext())[0].endswith(",0")

    # drawn: the red disc above the blue one above the yellow diamond, each a pictogram's height apart
    rgb = render(layer, 1, QgsRectangle(2599998.0, 1199998.0, 2600002.0, 1200002.0), QSize(200, 200))  # 1:~75
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    rows = {"red": np.nonzero((r > 180) & (g < 80) & (b < 80))[0], "blue": np.nonzero((b > 150) & (r < 60))[0],
            "yellow": np.nonzero((r > 200) & (g > 170) & (b < 60))[0]}
    assert all(len(found) > 20 for found in rows.values()), {k: len(v) for k, v in rows.items()}
    centres = {colour: float(np.median(found)) for colour, found in rows.items()}
    px_per_mm = 96 / 25.4
    assert centres["red"] < centres["blue"] < centres["yellow"]
    assert centres["blue"] - centres["red"] == pytest.approx(step * px_per_mm, abs=4)
    assert centres["yellow"] - centres["blue"] == pytest.approx(step * px_per_mm, abs=4)
