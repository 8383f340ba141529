"""Figures, animation and report for a blockdem run folder (docs/outputs-visual.md).

Reads only what `blockdem run` writes (history.csv, energy.csv, bodies.json, summary.json,
scenario.toml); needs Debian's python3-matplotlib and python3-numpy, never the C++ library.
"""
