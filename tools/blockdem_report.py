#!/usr/bin/python3
"""Writes OUT_DIR/report.html (and the figures in OUT_DIR/figures/) for a blockdem run folder, 2-D or
3-D (summary.json "dimension": 3: report_3d.py, docs/3d.md).
Usually called by `blockdem report OUT_DIR`; run it with Debian's Python:

  /usr/bin/python3 tools/blockdem_report.py OUT_DIR [--blockdem build/blockdem] [--no-animation]
"""
import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from blockdem_view.convergence_section import study_base_folder  # noqa: E402
from blockdem_view.report import write_report  # noqa: E402
from blockdem_view.report_3d import write_report_3d  # noqa: E402
from blockdem_view.run_folder import RunFolder, RunFolderError, run_dimension  # noqa: E402
from blockdem_view.run_folder_3d import RunFolder3d  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder")
    parser.add_argument("--blockdem", default=None, help="the blockdem binary, for the derived parameters")
    parser.add_argument("--formats", default="png,svg", help="figure formats besides the report (png is always made)")
    parser.add_argument("--no-animation", action="store_true", help="skip the MP4/GIF file (the page animates anyway)")
    args = parser.parse_args(argv)
    formats = ["png"] + [f for f in args.formats.split(",") if f and f != "png"]
    try:
        folder = study_base_folder(args.folder)
        # A 3-D run (docs/3d.md): its own page, figures and animation drawn from the VTK frames.
        run = RunFolder3d(folder) if run_dimension(folder) == 3 else RunFolder(folder)
        for note in run.limitations():
            print(f"blockdem report: note: {note}", file=sys.stderr)
        if isinstance(run, RunFolder3d):
            path = write_report_3d(run, formats, not args.no_animation)
        else:
            path = write_report(run, args.blockdem, formats, not args.no_animation)
    except RunFolderError as e:
        print(f"blockdem_report: {e}", file=sys.stderr)
        return 2
    except OSError as e:  # disk full, file too large, permissions: blockdem's exit status 4
        print(f"blockdem_report: could not write: {e.filename or ''}: {e.strerror or e}", file=sys.stderr)
        return 4
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
