"""Training of the learned sign classifier (``make train-classifier``); not part of the plugin.

Only synthetic faces rendered from the catalogue's master images (the official
drawings) go into training, with strong randomisation of everything a camera on
a vehicle adds. Real photographs are for measuring only and never enter here.
Needs the packages of ``requirements-train.txt`` (PyTorch, onnx, scikit-image).
"""
