"""All figures of one run folder, written to DIR/figures/."""
from pathlib import Path

from . import figures
from .animation import write_animation
from .sensors_figure import sensors_figure


def make_run_figures(run, formats=("png", "svg"), bodies=None, times=None, animation=True, out=None):
    """Writes acceleration, response, energy and snapshot figures (and the animation) of a run.
    Returns {stem: [paths]}."""
    folder = Path(out) if out else run.path / "figures"
    chosen = figures.dynamic_bodies(run, bodies)
    written = {
        "acceleration": figures.acceleration_figure(run, chosen, folder, formats),
        "energy": figures.energy_figure(run, folder, formats),
        "snapshots": figures.snapshot_figure(run, times or run.snapshot_times(), folder, formats),
    }
    if chosen:
        written["response"] = figures.response_figure(run, chosen, folder, formats)
    sensors = sensors_figure(run, folder, formats)  # sensors.csv beside the table motion, when written
    if sensors:
        written["sensors"] = sensors
    if animation and run.drawable():
        written["animation"] = [write_animation(run, folder)]
    return written
