# Sign Mapper — set-up, tests, demo and packaging on Debian 12.
#
# QGIS and qgis_process.bin run the system Python (/usr/bin/python3), not the
# venv, so every target puts the venv's site-packages on PYTHONPATH: that is
# how OpenCV (pip) becomes importable next to Debian's QGIS, numpy and GDAL.

SHELL := /bin/bash
SYSTEM_PYTHON := /usr/bin/python3
VENV := .venv
PY := $(VENV)/bin/python
PY_VERSION := $(shell $(SYSTEM_PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null || echo 3.11)
SITE_PACKAGES := $(CURDIR)/$(VENV)/lib/python$(PY_VERSION)/site-packages
QGIS_PROCESS := qgis_process.bin
SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)
APT_PACKAGES := qgis python3-qgis qgis-providers python3-venv python3-pip python3-numpy python3-scipy \
                python3-pyproj python3-shapely python3-pil python3-gdal git \
                postgresql postgresql-15-postgis-3 python3-psycopg2 \
                tesseract-ocr tesseract-ocr-deu tesseract-ocr-fra tesseract-ocr-ita fonts-dejavu-core
# tesseract-ocr*: reading plate texts (optional for the plugin, needed by the tests);
# fonts-dejavu-core: the font synthetic drives set plate texts in
# rsvg-convert: for make catalogue (rendering the official drawings) and the tests of that build
BUILD_APT_PACKAGES := librsvg2-bin

export PYTHONPATH := $(SITE_PACKAGES)$(if $(PYTHONPATH),:$(PYTHONPATH))
export QT_QPA_PLATFORM := offscreen

DEMO_DIR := demo-output
DEMO_DRIVE := $(DEMO_DIR)/sample-drive
DEMO_PAIRS := 20
REAL_DATA ?= /work/data/real
PLUGIN_NAME := sign_mapper
QGIS_PROFILE_PLUGINS := $(HOME)/.local/share/QGIS/QGIS3/profiles/default/python/plugins

TRAIN_VENV := .venv-train
TRAIN_PY := $(TRAIN_VENV)/bin/python

.PHONY: setup apt build-apt venv test test-core demo screenshots desktop-check lint zip deploy catalogue catalogue-sheet import-model train-classifier calibrate-classifier open-set kitti-drive clean help

help:
	@echo "make setup     Debian packages (QGIS), venv with pinned requirements"
	@echo "make test      all tests (core, QGIS, qgis_process.bin)"
	@echo "make test-core core tests only, without QGIS"
	@echo "make demo      generate a sample drive and run Sign Mapper on it with qgis_process.bin"
	@echo "make desktop-check QGIS desktop under Xvfb: map the demo drive from the dialog, open viewer and review"
	@echo "make screenshots the same, keeping its screenshots in docs/"
	@echo "make lint      ruff"
	@echo "make zip       dist/sign_mapper.zip, installable in QGIS"
	@echo "make deploy    link this checkout into the default QGIS profile"
	@echo "make catalogue SVG=DIR  rebuild templates/ch from the official drawings in DIR (deterministic)"
	@echo "make train-classifier  retrain templates/ch/classifier (own venv with PyTorch; ~2.5 h on 2 cores)"
	@echo "make calibrate-classifier REAL_DATA=DIR [CALIBRATE_ARGS=--source gtsdb]  fit its indicator on the tune half of real photographs"
	@echo "make open-set [OPEN_SET_SEED=4401] how signs of ids the network never saw come out (~3 h; REAL_DATA=DIR)"
	@echo "make import-model rebuild models/import_and_map_signs.model3 from the registered algorithms"
	@echo "make kitti-drive KITTI_REPO=GIT_DIR  KITTI drive 0001 into the cache tests/core/test_kitti_drive.py maps"

setup: apt venv

apt:
	@if ! dpkg -s $(APT_PACKAGES) >/dev/null 2>&1; then \
		echo "Installing Debian packages: $(APT_PACKAGES)"; \
		$(SUDO) apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(APT_PACKAGES); \
	fi

venv: $(VENV)/.installed

build-apt:
	@if ! command -v rsvg-convert >/dev/null; then \
		echo "Installing the SVG renderer for the catalogue build: $(BUILD_APT_PACKAGES)"; \
		$(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $(BUILD_APT_PACKAGES); \
	fi

# a .venv that is a link to another checkout's venv (a git worktree) is used as it is: venv cannot recreate it
# through the link; pip still installs what a changed requirements file adds
$(VENV)/.installed: requirements.txt requirements-dev.txt requirements-dask.txt
	[ -L $(VENV) ] || $(SYSTEM_PYTHON) -m venv --system-site-packages $(VENV)
	$(PY) -m pip install -q -r requirements-dev.txt
	$(PY) -c "import cv2, numpy, qgis.core; print('OpenCV', cv2.__version__, 'numpy', numpy.__version__)"
	touch $@

# build-apt too: the tests of the catalogue build render official drawings and would skip without it
test: setup build-apt
	$(PY) -m pytest

test-core: venv
	$(PY) -m pytest -p no:pytest_qgis tests/core

demo: setup
	@mkdir -p $(DEMO_DIR)/profile
	@[ -f $(DEMO_DRIVE)/poses.csv ] || $(PY) -m signmapper_core.simulate $(DEMO_DRIVE) --pairs $(DEMO_PAIRS) --seed 7
	@rm -rf $(DEMO_DIR)/plugins && mkdir -p $(DEMO_DIR)/plugins && ln -s $(CURDIR) $(DEMO_DIR)/plugins/$(PLUGIN_NAME)
	@export QGIS_PLUGINPATH=$(CURDIR)/$(DEMO_DIR)/plugins QGIS_CUSTOM_CONFIG_PATH=$(CURDIR)/$(DEMO_DIR)/profile; \
	$(QGIS_PROCESS) plugins enable $(PLUGIN_NAME) >/dev/null 2>&1; \
	$(QGIS_PROCESS) run signmapper:mapsigns -- DRIVE=$(CURDIR)/$(DEMO_DRIVE) \
		OUTPUT=$(CURDIR)/$(DEMO_DIR)/signs.gpkg && \
	$(QGIS_PROCESS) run signmapper:drivetrajectory -- DRIVE=$(CURDIR)/$(DEMO_DRIVE) \
		OUTPUT=$(CURDIR)/$(DEMO_DIR)/trajectory.gpkg TRACK=$(CURDIR)/$(DEMO_DIR)/track.gpkg >/dev/null && \
	$(QGIS_PROCESS) run native:createpointslayerfromtable -- INPUT=$(CURDIR)/$(DEMO_DRIVE)/truth.csv \
		XFIELD=easting YFIELD=northing ZFIELD=height TARGET_CRS=EPSG:2056 \
		OUTPUT=$(CURDIR)/$(DEMO_DIR)/truth.gpkg >/dev/null && \
	$(QGIS_PROCESS) run signmapper:evaluate -- "SIGNS=$(CURDIR)/$(DEMO_DIR)/signs.gpkg|layername=signs" \
		REFERENCE=$(CURDIR)/$(DEMO_DIR)/truth.gpkg REFERENCE_ID_FIELD=template_id REFERENCE_FACING_FIELD=facing \
		RADIUS=0.75 REPORT=$(CURDIR)/$(DEMO_DIR)/evaluation.html STATISTICS=$(CURDIR)/$(DEMO_DIR)/statistics.gpkg \
		MATCHES=$(CURDIR)/$(DEMO_DIR)/matches.gpkg 2>/dev/null | sed -n '/^Table 1/,/^  3d/p'
	@echo "Demo output in $(DEMO_DIR)/: signs.gpkg (layers signs, detections), evaluation.html, trajectory.gpkg"

# Real-display check: QGIS desktop under Xvfb with the plugin in a throw-away profile, driven by
# scripts/desktop_check.py (Map traffic signs from its dialog, drive viewer, review dock); screenshots in docs/.
# No PYTHONPATH: the plugin finds OpenCV in this folder's .venv by itself.
SCREEN_DIR := build/desktop
SHOTS_OUT ?= $(CURDIR)/$(SCREEN_DIR)/shots
screenshots:
	$(MAKE) desktop-check SHOTS_OUT=$(CURDIR)/docs

desktop-check: setup
	@command -v xvfb-run >/dev/null || { $(SUDO) apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq xvfb; }
	@[ -f $(DEMO_DRIVE)/poses.csv ] || $(PY) -m signmapper_core.simulate $(DEMO_DRIVE) --pairs $(DEMO_PAIRS) --seed 7
	@rm -rf $(SCREEN_DIR) && mkdir -p $(SCREEN_DIR)/plugins $(SCREEN_DIR)/profiles/profiles/default/QGIS $(SHOTS_OUT)
	@ln -s $(CURDIR) $(SCREEN_DIR)/plugins/$(PLUGIN_NAME)
	@printf '[PythonPlugins]\n$(PLUGIN_NAME)=true\n\n[qgis]\ncheckVersion=false\n' \
		> $(SCREEN_DIR)/profiles/profiles/default/QGIS/QGIS3.ini
	env -u PYTHONPATH QT_QPA_PLATFORM=xcb QGIS_PLUGINPATH=$(CURDIR)/$(SCREEN_DIR)/plugins \
	SIGNMAPPER_CHECK_DRIVE=$(CURDIR)/$(DEMO_DRIVE) SIGNMAPPER_CHECK_OUT=$(SHOTS_OUT) \
	SIGNMAPPER_CHECK_GPKG=$(CURDIR)/$(SCREEN_DIR)/signs.gpkg SIGNMAPPER_CHECK_REPORT=$(CURDIR)/$(SCREEN_DIR)/report.json \
		timeout 1800 xvfb-run -a -s "-screen 0 1600x1000x24" qgis --profiles-path $(CURDIR)/$(SCREEN_DIR)/profiles \
		--nologo --noversioncheck --code $(CURDIR)/scripts/desktop_check.py
	@$(PY) -c "import json, sys; r = json.load(open('$(SCREEN_DIR)/report.json')); \
		print(json.dumps(r, indent=1)); sys.exit(0 if r['ok'] else 1)"

lint: venv
	$(PY) -m ruff check .

catalogue: venv
	@if [ -z "$(SVG)" ]; then \
		echo "usage: make catalogue SVG=<folder of the official drawings> (signalo project/images/official/original," \
		     "see templates/README.md)"; exit 2; fi
	@$(MAKE) --no-print-directory build-apt
	$(PY) -m signmapper_core.catalogue.build --svg "$(SVG)"
	$(PY) -m signmapper_core.catalogue.plate_build --svg "$(SVG)"

$(TRAIN_VENV)/.installed: requirements.txt requirements-train.txt
	$(SYSTEM_PYTHON) -m venv --system-site-packages $(TRAIN_VENV)
	PYTHONPATH= $(TRAIN_PY) -m pip install -q -r requirements-train.txt
	touch $@

# Reproducible: same catalogue and arguments, same model. Generated patches are cached in /tmp.
# the shipped model's recipe (its card's "training" command): faces of the official drawings and, for half of
# them, pictograms redrawn; 4 epochs over 1,500 patches a class and 30,000 of background
TRAIN_ARGS ?= --design-variants --per-class 1500 --background 30000 --epochs 4
TRAIN_CATALOGUE ?= templates/ch
train-classifier: apt $(TRAIN_VENV)/.installed
	PYTHONPATH= $(TRAIN_PY) -m training.train --catalogue $(TRAIN_CATALOGUE) --threads 2 --workers 2 $(TRAIN_ARGS)

# temperature and acceptance threshold fitted on the tune half of the real photographs (scripts/realset);
# CALIBRATE_ARGS="--source gtsdb" fits on the GTSDB tune scenes instead of the GTSRB tune crops
CALIBRATE_ARGS ?=
calibrate-classifier: venv
	$(PY) -m scripts.calibrate_classifier --data $(REAL_DATA) $(CALIBRATE_ARGS)

# the open-set measurement (issue 44, docs/measurements.md): a network trained as the shipped one but without the
# ids OPEN_SET_SEED draws, calibrated as the shipped one, maps drives with a catalogue that lacks those ids; the
# tables say how their signs came out (real photographs of the tune half, perfect box; the drives: unknown,
# accepted as another id, missed). About 3 h on 2 cores.
OPEN_SET_DIR ?= build/open-set
OPEN_SET_SEED ?= 4401
OPEN_SET_DRIVES ?= $(shell seq 8000 8019)
open-set: apt venv $(TRAIN_VENV)/.installed
	$(PY) -m training.left_out $(OPEN_SET_DIR)/catalogue --seed $(OPEN_SET_SEED)
	PYTHONPATH= $(TRAIN_PY) -m training.train --catalogue $(OPEN_SET_DIR)/catalogue --threads 2 --workers 2 \
		--cache $(OPEN_SET_DIR)/train-cache $(TRAIN_ARGS)
	$(PY) -m scripts.calibrate_classifier --data $(REAL_DATA) --model $(OPEN_SET_DIR)/catalogue/classifier \
		$(CALIBRATE_ARGS)
	$(PY) -m scripts.evaluate_real_photos open-set --data $(REAL_DATA) --catalogue $(OPEN_SET_DIR)/catalogue
	$(PY) -m scripts.evaluate_mapping --generate $(OPEN_SET_DRIVES) --pairs 100 --workers 2 \
		--catalogue $(OPEN_SET_DIR)/catalogue --ids @$(OPEN_SET_DIR)/catalogue/left_out.txt

catalogue-sheet: venv
	$(PY) -m signmapper_core.catalogue.sheet docs/catalogue-sheet.png

zip: venv
	$(PY) -m scripts.build_zip dist/$(PLUGIN_NAME).zip

import-model: venv
	$(PY) -m scripts.make_import_model

# KITTI raw drive 2011_09_26_drive_0001 (CC BY-NC-SA, never committed) from a local git copy into the cache of
# tests/core/test_kitti_drive.py ($$SIGNMAPPER_KITTI_CACHE or ~/.cache/sign_mapper/kitti; tests/data/kitti/README.md);
# git and the standard library are all it needs
kitti-drive:
	@if [ -z "$(KITTI_REPO)" ]; then \
		echo "usage: make kitti-drive KITTI_REPO=<git dir holding the drive> (tests/data/kitti/README.md)"; exit 2; fi
	$(SYSTEM_PYTHON) -m scripts.kitti_drive --repo "$(KITTI_REPO)"

deploy:
	mkdir -p $(QGIS_PROFILE_PLUGINS)
	ln -sfn $(CURDIR) $(QGIS_PROFILE_PLUGINS)/$(PLUGIN_NAME)
	@echo "Linked into $(QGIS_PROFILE_PLUGINS)/$(PLUGIN_NAME); the plugin finds OpenCV in $(SITE_PACKAGES) by itself"

clean:
	rm -rf build dist $(DEMO_DIR) .pytest_cache .ruff_cache $(TRAIN_VENV)
