"""Checks the layout of a run's figures as matplotlib drew them (tools/blockdem_view/figures.py):
no two texts overlap (tick labels, axis labels, titles, legends: within one panel and between
panels), and no legend covers a plotted point. Also the animation's frame size: at least
MIN_ANIMATION_WIDTH pixels wide.

  /usr/bin/python3 check_figure_layout.py TOOLS_DIR RUN_DIR [RUN_DIR ...]

Each figure is checked when it is saved (the save function is wrapped), so the figures are
checked exactly as written. Exit status 1 on any problem, with one line per problem."""
import subprocess
import sys
import tempfile
from pathlib import Path

MIN_ANIMATION_WIDTH = 1280  # [pixels]

sys.path.insert(0, sys.argv[1])
from blockdem_view import figures  # noqa: E402
from blockdem_view.make_figures import make_run_figures  # noqa: E402
from blockdem_view.run_folder import RunFolder  # noqa: E402
from blockdem_view import animation  # noqa: E402

problems = []


def texts_of(fig):
    """(description, window extent) of every visible, non-empty text outside legends."""
    renderer = fig.canvas.get_renderer()
    out = []
    for k, ax in enumerate(fig.axes):
        for axis, name in ((ax.xaxis, "x"), (ax.yaxis, "y")):
            low, high = sorted(axis.get_view_interval())
            slack = 1e-9 * (high - low)
            for tick, loc in zip(axis.get_major_ticks(), axis.get_majorticklocs()):
                label = tick.label1
                # (matplotlib keeps labels for ticks beyond the view limits but does not draw them)
                if label.get_visible() and label.get_text() and low - slack <= loc <= high + slack:
                    out.append((f"panel {k} {name} tick '{label.get_text()}'", label.get_window_extent(renderer)))
            for text, what in ((axis.label, "label"), (axis.get_offset_text(), "offset")):
                if text.get_visible() and text.get_text():
                    out.append((f"panel {k} {name} {what} '{text.get_text()}'", text.get_window_extent(renderer)))
        title = ax.title
        if title.get_visible() and title.get_text():
            out.append((f"panel {k} title '{title.get_text()}'", title.get_window_extent(renderer)))
        legend = ax.get_legend()
        if legend is not None:
            out.append((f"panel {k} legend", legend.get_window_extent(renderer)))
    for k, legend in enumerate(fig.legends):
        out.append((f"figure legend {k}", legend.get_window_extent(renderer)))
    if fig._suptitle is not None and fig._suptitle.get_text():
        out.append((f"figure title '{fig._suptitle.get_text()}'", fig._suptitle.get_window_extent(renderer)))
    return out


def legends_of(fig, ax):
    """The legends that may cover the lines of ax: its own and the figure's."""
    return ([ax.get_legend()] if ax.get_legend() is not None else []) + list(fig.legends)


def overlap(a, b, tolerance=0.5):
    """True when two boxes (display pixels) overlap by more than tolerance in both directions."""
    return (min(a.x1, b.x1) - max(a.x0, b.x0) > tolerance) and (min(a.y1, b.y1) - max(a.y0, b.y0) > tolerance)


def check_figure(fig, stem):
    fig.canvas.draw()
    texts = texts_of(fig)
    for i in range(len(texts)):
        for j in range(i + 1, len(texts)):
            if overlap(texts[i][1], texts[j][1]):
                problems.append(f"{stem}: {texts[i][0]} overlaps {texts[j][0]}")
    renderer = fig.canvas.get_renderer()
    for k, ax in enumerate(fig.axes):
        for legend in legends_of(fig, ax):
            box = legend.get_window_extent(renderer)
            for line in ax.get_lines():
                points = line.get_transform().transform(line.get_xydata())
                inside = ((points[:, 0] > box.x0) & (points[:, 0] < box.x1) & (points[:, 1] > box.y0)
                          & (points[:, 1] < box.y1))
                if inside.any():
                    problems.append(f"{stem}: a legend covers {int(inside.sum())} points of '{line.get_label()}' "
                                    f"in panel {k}")
                    break


original_save = figures.save


def checked_save(fig, folder, stem, formats):
    check_figure(fig, stem)
    return original_save(fig, folder, stem, formats)


figures.save = checked_save


def animation_width(path):
    """Width in pixels of the first frame (ffprobe for MP4; Pillow for GIF)."""
    if path.suffix == ".gif":
        from PIL import Image
        return Image.open(path).size[0]
    out = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries", "stream=width",
                          "-of", "csv=p=0", str(path)], capture_output=True, text=True, check=True)
    return int(out.stdout.strip())


for folder in sys.argv[2:]:
    run = RunFolder(folder)
    with tempfile.TemporaryDirectory() as out:
        make_run_figures(run, ["png"], animation=False, out=out)
        path = animation.write_animation(run, Path(out), max_frames=3)
        width = animation_width(path)
        if width < MIN_ANIMATION_WIDTH:
            problems.append(f"{folder}: the animation is {width} pixels wide, below {MIN_ANIMATION_WIDTH}")
    print(f"checked {folder}")

# The Fig. 5 comparison overlaid in one panel, with its legend, of the first two runs.
if len(sys.argv) > 3:
    runs = [RunFolder(f) for f in sys.argv[2:4]]
    shared = [b for b in runs[0].recorded("dynamic") if b in runs[1].recorded("dynamic")]
    if shared:
        with tempfile.TemporaryDirectory() as out:
            figures.comparison_figure(runs, ["first", "second"], shared[0], Path(out), ["png"], overlay=True)

for p in problems:
    print("FAIL", p)
sys.exit(1 if problems else 0)
