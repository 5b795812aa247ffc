"""What the review's and the drive viewer's controllers share: the dock's requests wired to their slots,
and QGIS's current layer followed only while the dock is visible."""

from __future__ import annotations

from qgis.PyQt.QtCore import QObject


class DockController(QObject):
    """A dock's controller. Subclasses give ``set_layer`` (called with each current layer while active),
    ``stop_following`` (the dock was hidden) and ``release`` (plugin unload, after the dock is disconnected)."""

    def __init__(self, iface, dock, parent=None):
        super().__init__(parent)
        self.iface, self.dock = iface, dock
        self._active = False
        self._dock_connections = []

    def connect_dock(self, connections) -> None:
        """Connect (signal, slot) pairs of the dock's requests; ``shutdown`` disconnects them."""
        for signal, slot in connections:
            signal.connect(slot)
        self._dock_connections += list(connections)

    def set_layer(self, layer) -> None:
        raise NotImplementedError

    def activate(self) -> None:
        """Start following the current layer (the dock became visible)."""
        if self._active:
            return
        self._active = True
        self.iface.currentLayerChanged.connect(self.set_layer)
        self.set_layer(self.iface.activeLayer())

    def deactivate(self) -> None:
        """Stop following layers (the dock was hidden)."""
        if not self._active:
            return
        self._active = False
        self.iface.currentLayerChanged.disconnect(self.set_layer)
        self.stop_following()

    def stop_following(self) -> None:
        """What hiding the dock stops besides following layers."""

    def shutdown(self) -> None:
        """Disconnect everything and release what the controller holds (plugin unload)."""
        self.deactivate()
        for signal, slot in self._dock_connections:
            signal.disconnect(slot)
        self._dock_connections = []
        self.release()

    def release(self) -> None:
        """Wait for running jobs and remove what the controller put on the map."""
