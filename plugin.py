"""The plugin object QGIS holds: registers the provider and the review dock."""

from __future__ import annotations

from qgis.core import Qgis, QgsApplication, QgsMessageLog

from .dependencies import install_hint, missing_modules

LOG_TAG = "Sign Mapper"


class SignMapperPlugin:
    """``classFactory`` only constructs; ``initProcessing``/``initGui`` do the work."""

    def __init__(self, iface):
        self.iface = iface
        self.provider = None
        self.review_ui = None
        self.viewer_ui = None
        self.installer = None

    def initProcessing(self):  # noqa: N802 - called by QGIS and qgis_process
        """Register the Processing provider once; a second call does nothing."""
        if self.provider is not None:
            return
        missing = missing_modules()
        if missing:
            QgsMessageLog.logMessage(install_hint(missing), LOG_TAG, Qgis.Warning)
        from .provider.provider import SignMapperProvider  # after the check: the algorithms may import OpenCV

        self.provider = SignMapperProvider()
        QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # noqa: N802
        self.initProcessing()
        missing = missing_modules()
        if missing and self.iface is not None and self.installer is None:
            from .opencv_installer import ModuleInstaller  # Qt widgets: only with a GUI and something missing

            self.installer = ModuleInstaller(self.iface)
            self.installer.offer(missing)  # the hint and an Install… button
        if self.iface is not None and self.review_ui is None:
            # the docks' Qt widgets and OpenCV: only with a GUI (qgis_process never calls initGui)
            from .review.plugin_ui import ReviewUi
            from .viewer.plugin_ui import ViewerUi

            self.review_ui = ReviewUi(self.iface)
            self.viewer_ui = ViewerUi(self.iface, self.review_ui)

    def open_viewer_at(self, layer_id: str, fid: int) -> None:
        """The layer action "Open in the drive viewer" (gpkg/feature_actions): the viewer at the feature's pair."""
        from qgis.core import QgsProject

        layer = QgsProject.instance().mapLayer(layer_id)
        if layer is not None and self.viewer_ui is not None:
            self.viewer_ui.open_at_feature(layer, int(fid))

    def unload(self):
        if self.viewer_ui is not None:
            self.viewer_ui.unload()
            self.viewer_ui = None
        if self.review_ui is not None:
            self.review_ui.unload()
            self.review_ui = None
        self.viewer_ui = None
        self.installer = None
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
