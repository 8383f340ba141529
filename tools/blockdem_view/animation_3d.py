"""An animation of a 3-D run in the axonometric view: the bodies posed from history.csv at each
frame time (RunFolder3d.bodies_at: the first VTK frame's faces moved by each body's centroid and
turn), MP4 through Debian's ffmpeg when it is installed, else an animated GIF through Pillow."""
import shutil

import numpy as np
from matplotlib import animation

from .animation import DPI, WIDTH_IN, frame_times, save_movie
from .drawing_3d import VIEWS, draw_frame, screen_extent
from .figures import STYLE, plt
MAX_FACE_DRAWS = 3.0e5  # faces drawn over the whole animation: a large wall gets fewer frames
                        # (each frame redraws every face), so that a report stays a matter of seconds


def frame_times_on_rows(run, fps, max_frames):
    """[s] the frames' times (animation.frame_times), each moved to its nearest history row."""
    t = run.t_s
    rows = sorted({int(np.argmin(np.abs(t - x))) for x in frame_times(t, fps, max_frames)})
    return [float(t[r]) for r in rows]


def write_animation_3d(run, folder, fps=25, max_frames=750, fmt=None):
    """Writes folder/animation.mp4 (or .gif); returns its path, or None without VTK frames."""
    if not run.frames:
        return None
    fmt = fmt or ("mp4" if shutil.which("ffmpeg") else "gif")
    first = run.bodies_at(0.0)
    faces = max(1, len(first.offsets))
    times = frame_times_on_rows(run, fps, max(2, min(max_frames, int(MAX_FACE_DRAWS / faces))))
    kinds = run.kinds_by_index()
    camera = VIEWS["axonometric"][0]
    # One view box for the whole run, from a sample of the frames (every body's reach).
    sample = [run.bodies_at(x) for x in times[:: max(1, len(times) // 12)] + [times[-1]]]
    extents = [screen_extent(f, kinds, camera) for f in sample]
    lo = np.min([e[0] for e in extents], axis=0)
    hi = np.max([e[1] for e in extents], axis=0)
    pad = 0.08 * max(hi - lo)
    limits = (lo - pad, hi + pad)
    edge = 0.3 if faces < 5000 else 0.1
    with plt.rc_context({**STYLE, "savefig.bbox": None}):
        # The height follows the scene's shape within 0.3 to 0.75 of the width, rounded to an
        # even number of pixels for H.264.
        ratio = min(0.75, max(0.3, (limits[1][1] - limits[0][1]) / (limits[1][0] - limits[0][0])))
        height = round(WIDTH_IN * ratio * DPI / 2) * 2 / DPI
        fig, ax = plt.subplots(figsize=(WIDTH_IN, height))

        def update(time_s):
            ax.cla()
            frame = run.bodies_at(time_s)
            draw_frame(ax, frame, kinds, camera, limits, edge)
            ax.set_xticks([])
            ax.set_yticks([])
            ax.grid(False)
            ax.set_title(f"{run.title()}   t = {frame.time_s:.2f} s")
            return ()

        movie = animation.FuncAnimation(fig, update, frames=times, blit=False)
        path = folder / f"animation.{fmt}"
        folder.mkdir(parents=True, exist_ok=True)
        save_movie(movie, path, fmt, fps)
        plt.close(fig)
        return path
