"""The plugin constructs without a GUI, registers its provider once and unloads cleanly."""

import html
import subprocess
import sys
import textwrap

from qgis.core import QgsApplication

PROVIDER_ID = "signmapper"


def test_class_factory_with_iface_none_only_constructs(sign_mapper, qgis_processing):
    plugin = sign_mapper.classFactory(None)
    assert plugin.iface is None
    assert QgsApplication.processingRegistry().providerById(PROVIDER_ID) is None


def test_init_processing_twice_registers_one_provider_and_unload_removes_it(sign_mapper, qgis_processing):
    plugin = sign_mapper.classFactory(None)
    plugin.initProcessing()
    plugin.initProcessing()
    registry = QgsApplication.processingRegistry()
    providers = [p for p in registry.providers() if p.id() == PROVIDER_ID]
    assert len(providers) == 1
    assert providers[0].name() == "Sign Mapper"
    assert registry.algorithmById("signmapper:drivetrajectory") is not None
    plugin.unload()
    assert registry.providerById(PROVIDER_ID) is None
    plugin.unload()  # a second unload is harmless


def test_every_parameter_has_help(registered_plugin):
    provider = QgsApplication.processingRegistry().providerById(PROVIDER_ID)
    algorithms = provider.algorithms()
    assert algorithms
    for alg in algorithms:
        assert alg.shortHelpString()
        for param in alg.parameterDefinitions():
            assert param.help().strip(), f"{alg.id()} parameter {param.name()} has no help"


def test_missing_opencv_gives_install_message_not_traceback(plugin_dir, tmp_path):
    """With cv2 unimportable the provider still loads and the algorithm says how to install OpenCV."""
    script = textwrap.dedent(
        f"""
        import sys
        sys.modules["cv2"] = None  # makes 'import cv2' fail like a missing package
        sys.path.insert(0, {str(plugin_dir)!r})
        from qgis.core import QgsApplication, QgsProcessingContext, QgsProcessingFeedback
        app = QgsApplication([], False); app.initQgis()
        sys.path.append(QgsApplication.pkgDataPath() + "/python/plugins")
        from processing.core.Processing import Processing
        Processing.initialize()
        import sign_mapper
        plugin = sign_mapper.classFactory(None)
        plugin.initProcessing()
        alg = QgsApplication.processingRegistry().createAlgorithmById("signmapper:drivetrajectory")
        print("LOADED", alg is not None)
        try:
            alg.processAlgorithm({{"DRIVE": {str(tmp_path)!r}, "OUTPUT": "memory:"}},
                                 QgsProcessingContext(), QgsProcessingFeedback())
        except Exception as exc:
            print("MESSAGE", type(exc).__name__, exc)
        """
    )
    env = {"QT_QPA_PLATFORM": "offscreen", "PATH": "/usr/bin:/bin", "HOME": str(tmp_path)}
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=120)
    assert "LOADED True" in result.stdout, result.stdout + result.stderr
    assert "MESSAGE QgsProcessingException" in result.stdout
    assert "OpenCV (cv2)" in result.stdout and "pip install" in result.stdout
    assert "Traceback" not in result.stdout


def test_map_signs_help_lists_every_output_field(registered_plugin):
    from sign_mapper.signmapper_core.output import schema as output_schema

    help_text = QgsApplication.processingRegistry().algorithmById("signmapper:mapsigns").shortHelpString()
    for field in output_schema.FIELDS:
        assert f"<b>{field.name}</b>" in help_text and html.escape(field.help, quote=False) in help_text
    assert "'-&lt;value&gt;' for a sign with a number" in help_text  # shown, not swallowed as a tag
    assert "<b>mount_height_m</b> (signs):" in help_text and "<b>u</b> (signs and detections):" in help_text


def test_every_algorithm_has_its_own_icon(registered_plugin):
    from qgis.core import QgsApplication

    provider = QgsApplication.processingRegistry().providerById("signmapper")
    icons = {}
    for alg in provider.algorithms():
        icon = alg.icon()
        assert not icon.isNull() and icon.availableSizes() or not icon.pixmap(32, 32).isNull(), alg.id()
        icons[alg.id()] = icon.pixmap(32, 32).toImage()
    from sign_mapper.algorithms import ALGORITHMS

    assert len(icons) == len(ALGORITHMS)
    images = list(icons.values())
    assert all(images[i] != images[j] for i in range(len(images)) for j in range(i + 1, len(images)))


def test_help_texts_keep_their_angle_brackets_and_name_the_classifier(registered_plugin):
    """The help panel renders HTML: 'depth/<id>.npy' once lost '<id>' as an unknown tag."""
    registry = QgsApplication.processingRegistry()
    synthetic = registry.algorithmById("signmapper:syntheticdrive").shortHelpString()
    assert "depth/&lt;id&gt;.npy" in synthetic and "depth/.npy" not in synthetic
    mapsigns = registry.algorithmById("signmapper:mapsigns").shortHelpString()
    assert "'&lt;output name&gt;_crops'" in mapsigns
    assert "template matching (classification indicator)" not in mapsigns
    assert "learned network or by template matching (classification indicator" in mapsigns
