"""An animation of a whole run: MP4 through Debian's ffmpeg when it is installed, else an
animated GIF through Pillow (both drive matplotlib's writers)."""
import shutil

import numpy as np
from matplotlib import animation

from .figures import STYLE, draw_bodies, plt

WIDTH_IN = 6.4  # [in] frame width: at DPI, 1280 pixels (HD), with the figures' 9-point text
DPI = 200  # [pixels per inch] of the animation frames


def frame_times(t, fps, max_frames):
    """[s] the frames' times over the history times t: one per 1/fps of simulated time, thinned
    to max_frames (a long record then plays faster than real time rather than making a huge
    file). Both dimensions."""
    count = int(min(max_frames, np.floor((t[-1] - t[0]) * fps) + 1))
    return np.linspace(t[0], t[-1], max(count, 2))


def frame_rows(run, fps, max_frames):
    """History rows of the frames (frame_times, each on its nearest row)."""
    return sorted({run.row_at(x) for x in frame_times(run.t_s, fps, max_frames)})


def save_movie(movie, path, fmt, fps):
    """Writes a matplotlib animation to path as MP4 (H.264 through ffmpeg) or GIF (Pillow)."""
    if fmt == "mp4":
        # H.264 in yuv420p (what every player plays) needs even pixel sizes: pad by one if odd.
        writer = animation.FFMpegWriter(fps=fps, codec="libx264", extra_args=[
            "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"])
    else:
        writer = animation.PillowWriter(fps=fps)
    movie.save(path, writer=writer, dpi=DPI)


def write_animation(run, folder, fps=25, max_frames=750, fmt=None):
    """Writes folder/animation.mp4 (or .gif); returns its path."""
    fmt = fmt or ("mp4" if shutil.which("ffmpeg") else "gif")
    rows = frame_rows(run, fps, max_frames)
    box = run.view_box()
    # Every frame the same size (a video cannot change it), so no tight bounding box here.
    with plt.rc_context({**STYLE, "savefig.bbox": None}):
        # The height follows the scene's shape (a tall tombstone, a wide wall), within 0.3 to
        # 0.75 of the width, rounded to an even number of pixels for H.264.
        ratio = min(0.75, max(0.3, (box[3] - box[2]) / (box[1] - box[0]) + 0.1))
        height = round(WIDTH_IN * ratio * DPI / 2) * 2 / DPI
        fig, ax = plt.subplots(figsize=(WIDTH_IN, height))
        collection, origin = draw_bodies(ax, run, rows[0], box)
        bodies = run.drawable()
        label = ax.set_title("")

        def update(row):
            collection.set_verts([run.outline_at(b, row) - origin for b in bodies])
            label.set_text(f"{run.title()}   t = {run.t_s[row]:.2f} s")
            return collection, label

        movie = animation.FuncAnimation(fig, update, frames=rows, blit=False)
        path = folder / f"animation.{fmt}"
        folder.mkdir(parents=True, exist_ok=True)
        save_movie(movie, path, fmt, fps)
        plt.close(fig)
        return path
