"""A plain PyQGIS script maps a drive with worker processes, written the way most QGIS scripts are (issue 46, 4).

The script runs in its own ``/usr/bin/python3`` as a user runs it: QgsApplication, Processing, the plugin, then
``processing.run("signmapper:mapsigns", …)`` with two worker processes, with and without a main guard.
"""

import subprocess
import sysconfig
import textwrap

import pytest
from qgis.core import QgsVectorLayer

SCRIPT = """\
import sys

from qgis.core import QgsApplication, QgsProcessingFeedback


class Printed(QgsProcessingFeedback):
    def pushWarning(self, warning):
        print("WARNING", warning, flush=True)


app = QgsApplication([], False)
app.initQgis()
sys.path[:0] = [{plugins!r}, "/usr/share/qgis/python/plugins"]
import processing
from processing.core.Processing import Processing

Processing.initialize()
import sign_mapper

plugin = sign_mapper.classFactory(None)
plugin.initProcessing()
{call}
"""
RUN = 'result = processing.run("signmapper:mapsigns", {{"DRIVE": {drive!r}, "OUTPUT": {out!r}, "WORKERS": 2}}, ' \
      'feedback=Printed())\n' \
      'print("RESULT", result["OUTPUT"])'


@pytest.mark.parametrize("guarded", [False, True], ids=["no main guard", "main guard"])
def test_script_maps_a_drive_with_worker_processes(plugin_dir, small_drive, tmp_path, guarded):
    out = tmp_path / "signs.gpkg"
    call = RUN.format(drive=str(small_drive), out=str(out))
    if guarded:
        call = "if __name__ == '__main__':\n" + textwrap.indent(call, "    ")
    script = tmp_path / "map_drive.py"
    script.write_text(SCRIPT.format(plugins=str(plugin_dir), call=call))
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "QT_QPA_PLATFORM": "offscreen",
           "PYTHONPATH": sysconfig.get_paths()["purelib"]}  # OpenCV, as the README has it
    done = subprocess.run(["/usr/bin/python3", str(script)], capture_output=True, text=True, env=env,
                          cwd=str(tmp_path), timeout=600)
    log = done.stdout + done.stderr
    assert done.returncode == 0, log
    assert f"RESULT {out}" in done.stdout
    # the workers mapped: no worker ran the script again (it would fail, and the run fall back to one process)
    assert "WARNING" not in done.stdout and "Traceback" not in log, log
    assert "bootstrapping phase" not in log and "ended abruptly" not in log and "could not start" not in log
    assert QgsVectorLayer(f"{out}|layername=signs", "signs", "ogr").featureCount() >= 2
