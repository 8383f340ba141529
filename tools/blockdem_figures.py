#!/usr/bin/python3
"""Figures of blockdem run folders (docs/outputs-visual.md). Run with Debian's Python:

  /usr/bin/python3 tools/blockdem_figures.py run OUT_DIR [--formats png,svg] [--times 0,1,2]
  /usr/bin/python3 tools/blockdem_figures.py compare DIR1 DIR2 ... --body block [--labels a,b] --out FIGDIR

`run` writes OUT_DIR/figures/{acceleration,response,energy,snapshots}.<fmt> and the animation;
`compare` writes FIGDIR/acceleration_comparison.<fmt> (the paper's Fig. 5 for several runs).
"""
import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from blockdem_view import figures  # noqa: E402
from blockdem_view.make_figures import make_run_figures  # noqa: E402
from blockdem_view.run_folder import RunFolder, RunFolderError  # noqa: E402


def split(text):
    return [s for s in text.split(",") if s] if text else []


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    one = sub.add_parser("run", help="all figures of one run folder")
    one.add_argument("folder")
    one.add_argument("--formats", default="png,svg", help="comma-separated: png, svg, pdf")
    one.add_argument("--bodies", default="", help="comma-separated dynamic bodies (default: the first 6)")
    one.add_argument("--times", default="", help="comma-separated snapshot times [s]")
    one.add_argument("--no-animation", action="store_true")
    one.add_argument("--out", default=None, help="folder for the figures (default: FOLDER/figures)")
    many = sub.add_parser("compare", help="one body's acceleration in several runs (Fig. 5 style)")
    many.add_argument("folders", nargs="+")
    many.add_argument("--body", required=True)
    many.add_argument("--labels", default="", help="comma-separated, one per folder (default: folder names)")
    many.add_argument("--overlay", action="store_true", help="one panel instead of one per run")
    many.add_argument("--formats", default="png,svg")
    many.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    try:
        if args.command == "run":
            run = RunFolder(args.folder)
            times = [float(t) for t in split(args.times)] or None
            written = make_run_figures(run, split(args.formats), split(args.bodies), times,
                                       not args.no_animation, args.out)
        else:
            runs = [RunFolder(f) for f in args.folders]
            labels = split(args.labels) or [Path(f).name for f in args.folders]
            if len(labels) != len(runs):
                parser.error("--labels needs one label per folder")
            written = {"acceleration_comparison": figures.comparison_figure(
                runs, labels, args.body, Path(args.out), split(args.formats), args.overlay)}
    except (RunFolderError, KeyError) as e:
        print(f"blockdem_figures: {e.args[0] if isinstance(e, KeyError) else e}", file=sys.stderr)
        return 2
    for paths in written.values():
        for p in paths:
            print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
