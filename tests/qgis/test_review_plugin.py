"""The review dock's wiring into QGIS: toolbar and menu action, lazy dock, clean unload."""

import pytest
from plugin_iface import RecordingIface
from qgis.core import QgsApplication, QgsProject, QgsVectorLayer
from qgis.PyQt.QtWidgets import QApplication


@pytest.fixture
def iface(qgis_iface):
    window = qgis_iface.mainWindow()
    window.show()  # as in QGIS: a dock only becomes visible inside a shown main window
    yield RecordingIface(qgis_iface)
    window.hide()


def test_init_gui_after_init_processing_adds_one_action_and_unload_removes_everything(sign_mapper, qgis_processing,
                                                                                         iface):
    plugin = sign_mapper.classFactory(iface)
    plugin.initProcessing()
    plugin.initGui()
    plugin.initGui()  # a second call adds nothing
    assert QgsApplication.processingRegistry().providerById("signmapper") is not None
    action, viewer = plugin.review_ui.action, plugin.viewer_ui.action
    assert iface.added == [("toolbar", action), ("menu", "&Sign Mapper", action),
                           ("toolbar", viewer), ("menu", "&Sign Mapper", viewer)]
    assert action.text() == "Review signs" and action.isCheckable()
    assert viewer.text() == "Drive viewer" and not viewer.icon().isNull()
    assert plugin.review_ui.dock is None and plugin.viewer_ui.dock is None  # built on first use
    viewer.setChecked(True)
    QApplication.processEvents()
    viewer_dock = plugin.viewer_ui.dock
    assert viewer_dock is not None and viewer_dock.isVisible() and plugin.viewer_ui.controller._active

    action.setChecked(True)
    QApplication.processEvents()
    dock = plugin.review_ui.dock
    assert dock is not None and dock.isVisible() and ("dock", dock) in iface.added
    assert plugin.review_ui.controller._active
    dock.close()  # the dock's own close button unchecks the action and stops following layers
    QApplication.processEvents()
    assert not action.isChecked() and not plugin.review_ui.controller._active
    action.setChecked(True)
    QApplication.processEvents()
    assert dock.isVisible()

    plugin.unload()
    assert ("toolbar", action) in iface.removed and ("menu", "&Sign Mapper", action) in iface.removed
    assert ("dock", dock) in iface.removed and ("dock", viewer_dock) in iface.removed
    assert ("toolbar", viewer) in iface.removed
    assert plugin.review_ui is None and plugin.viewer_ui is None
    assert QgsApplication.processingRegistry().providerById("signmapper") is None


def test_visible_dock_follows_the_current_layer_and_unload_disconnects(sign_mapper, qgis_processing, iface):
    plugin = sign_mapper.classFactory(iface)
    plugin.initGui()
    plugin.review_ui.action.setChecked(True)
    QApplication.processEvents()
    controller = plugin.review_ui.controller
    layer = QgsVectorLayer("Point?crs=EPSG:2056&field=name:string", "other", "memory")
    QgsProject.instance().addMapLayer(layer)
    controller.set_layer(layer)  # what iface.currentLayerChanged calls
    assert controller.layer is None and "Sign Mapper" in plugin.review_ui.dock.title.text()
    plugin.unload()
    assert not controller._active and not controller.busy()
    QgsProject.instance().removeAllMapLayers()


def test_add_missed_sign_from_the_viewer_opens_the_review_on_the_viewers_layer(sign_mapper, qgis_processing, iface):
    plugin = sign_mapper.classFactory(iface)
    plugin.initGui()
    layer = QgsVectorLayer("Point?crs=EPSG:2056&field=name:string", "other", "memory")
    QgsProject.instance().addMapLayer(layer)
    calls = []
    plugin.review_ui.action.setChecked(True)
    QApplication.processEvents()
    review = plugin.review_ui.controller
    review.decisions.add_sign = lambda pair_id, u, v: calls.append((review.session.layer, pair_id, u, v))
    plugin.review_ui.action.setChecked(False)
    QApplication.processEvents()
    plugin.viewer_ui._add_sign(layer, "000004", 120.0, 80.0)
    QApplication.processEvents()
    assert plugin.review_ui.action.isChecked() and plugin.review_ui.dock.isVisible()
    assert calls == [(None, "000004", 120.0, 80.0)]  # a plain memory layer is no Sign Mapper layer: no session
    plugin.unload()
    QgsProject.instance().removeAllMapLayers()


def test_the_review_dock_claims_700_px_beside_another_dock(sign_mapper, qgis_processing):
    """Qt splits a dock area evenly: beside QGIS's Layers panel on a 1000 px screen the review got 284 px."""
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtWidgets import QDockWidget, QLabel, QMainWindow, QTreeView

    window = QMainWindow()
    window.setCentralWidget(QLabel("map canvas"))
    window.setGeometry(0, 0, 1600, 1000)
    layers = QDockWidget("Layers")
    layers.setWidget(QTreeView())
    window.addDockWidget(Qt.RightDockWidgetArea, layers)
    window.show()
    QApplication.processEvents()

    class Iface:
        def __init__(self):
            self.added = []

        def mainWindow(self):  # noqa: N802
            return window

        def addDockWidget(self, area, dock):  # noqa: N802
            window.addDockWidget(area, dock)

        def __getattr__(self, name):  # toolbar and menu: not what this test looks at
            return lambda *args: None

    from sign_mapper.review.plugin_ui import ReviewUi

    ui = ReviewUi(Iface())
    ui.build = lambda: (QDockWidget("Sign Mapper review"), type("Controller", (), {
        "activate": lambda self: None, "deactivate": lambda self: None})())
    ui.action.setChecked(True)
    QApplication.processEvents()
    assert ui.dock.isVisible() and layers.isVisible()
    assert ui.dock.height() >= 700 - 10  # a title bar's rounding
    window.close()
