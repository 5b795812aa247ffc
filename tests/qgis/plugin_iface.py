"""The QGIS interface the plugin's GUI tests hand it: pytest-qgis's stub plus what it lacks."""


class RecordingIface:
    """The pytest-qgis stub iface plus the removal calls it lacks, recording what the plugin adds and removes."""

    def __init__(self, iface):
        self._iface = iface
        self.added, self.removed = [], []

    def __getattr__(self, name):
        return getattr(self._iface, name)

    def addToolBarIcon(self, action):  # noqa: N802
        self.added.append(("toolbar", action))

    def removeToolBarIcon(self, action):  # noqa: N802
        self.removed.append(("toolbar", action))

    def addPluginToMenu(self, menu, action):  # noqa: N802
        self.added.append(("menu", menu, action))

    def removePluginMenu(self, menu, action):  # noqa: N802
        self.removed.append(("menu", menu, action))

    def addDockWidget(self, area, dock):  # noqa: N802
        self.added.append(("dock", dock))

    def removeDockWidget(self, dock):  # noqa: N802
        self.removed.append(("dock", dock))
