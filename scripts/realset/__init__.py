"""The real-photograph set's tools (see README.md here): ``python -m scripts.realset.build_manifests DATA``,
``python -m scripts.realset.make_subset DATA OUT``, run from the repository root."""
