"""Benchmarks, run from the repository root as modules: ``.venv/bin/python -m bench.bench_mapping ...`` (README.md
here holds their figures). They import ``signmapper_core``, the shared tools of ``scripts`` and the test helpers
(``tests.drive_fixtures``) by package name, without putting folders on ``sys.path``.
"""
