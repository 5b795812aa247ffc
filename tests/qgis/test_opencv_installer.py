"""The one-click installer: asks first, runs the command it showed, logs what it printed; never runs pip here."""

import sys
import time

from qgis.PyQt.QtWidgets import QApplication


def wait_done(installer, timeout_s=30.0):
    deadline = time.monotonic() + timeout_s
    while installer.process is not None and time.monotonic() < deadline:
        QApplication.processEvents()
        time.sleep(0.01)
    assert installer.process is None


def test_declining_runs_nothing_and_confirming_runs_and_logs_the_command(sign_mapper, qgis_iface, monkeypatch,
                                                                         tmp_path):
    from sign_mapper import opencv_installer

    monkeypatch.setattr(opencv_installer, "log_file", lambda: tmp_path / "pip.log")
    fake_pip = [sys.executable, "-c", "print('Collecting opencv-python-headless'); print('Successfully installed')"]
    monkeypatch.setattr(opencv_installer, "pip_install_command", lambda missing: fake_pip)
    asked = []
    installer = opencv_installer.ModuleInstaller(qgis_iface, confirm=lambda command: asked.append(command) or False)
    assert not installer.install(["cv2"])
    assert asked == [fake_pip] and installer.process is None
    assert "Installation declined" in (tmp_path / "pip.log").read_text()

    monkeypatch.setattr(opencv_installer, "missing_modules", lambda: [])  # as after a successful install
    installer.confirm = lambda command: True
    assert installer.install(["cv2"])
    wait_done(installer)
    log = (tmp_path / "pip.log").read_text()
    assert "Running: " + " ".join(fake_pip) in log
    assert "Collecting opencv-python-headless" in log and "Successfully installed" in log
    assert "Installed. Restart QGIS" in log


def test_a_failing_pip_is_reported(sign_mapper, qgis_iface, monkeypatch, tmp_path):
    from sign_mapper import opencv_installer

    monkeypatch.setattr(opencv_installer, "log_file", lambda: tmp_path / "pip.log")
    monkeypatch.setattr(opencv_installer, "pip_install_command",
                        lambda missing: [sys.executable, "-c", "import sys; print('No matching distribution'); "
                                                               "sys.exit(1)"])
    installer = opencv_installer.ModuleInstaller(qgis_iface, confirm=lambda command: True)
    installer.install(["cv2"])
    wait_done(installer)
    log = (tmp_path / "pip.log").read_text()
    assert "No matching distribution" in log and "pip failed (exit 1)" in log


class BarIface:
    """QGIS's message bar (pytest-qgis's stub has no createMessage)."""

    def __init__(self):
        from qgis.gui import QgsMessageBar

        self.bar = QgsMessageBar()

    def messageBar(self):  # noqa: N802
        return self.bar


def test_the_offer_is_a_message_with_an_install_button(sign_mapper):
    from qgis.PyQt.QtWidgets import QPushButton
    from sign_mapper import opencv_installer

    iface = BarIface()
    opencv_installer.ModuleInstaller(iface, confirm=lambda command: False).offer(["cv2"])
    items = iface.bar.items()
    assert len(items) == 1
    item = items[-1]
    assert "OpenCV (cv2)" in item.text()
    assert any(b.text() == "Install…" for b in item.findChildren(QPushButton))
