"""Checks figure files: each PNG is a PNG of a reasonable size, each SVG parses as XML with an
<svg> root, each animation is non-empty. Usage: check_figures.py FILE..."""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

failures = 0
for name in sys.argv[1:]:
    path = Path(name)
    problem = None
    if not path.is_file() or path.stat().st_size == 0:
        problem = "missing or empty"
    elif path.suffix == ".png":
        head = path.read_bytes()[:24]
        width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
        if head[:8] != b"\x89PNG\r\n\x1a\n" or width < 400 or height < 150:
            problem = f"not a PNG of a usable size ({width} x {height})"
    elif path.suffix == ".svg":
        if not ET.parse(path).getroot().tag.endswith("svg"):
            problem = "not an SVG"
    elif path.suffix in (".mp4", ".gif") and path.stat().st_size < 10_000:
        problem = "animation too small to hold frames"
    print(f"{'FAIL' if problem else 'ok  '} {path.name}{': ' + problem if problem else ''}")
    failures += problem is not None
sys.exit(1 if failures else 0)
