"""report.html of a 3-D run (RunFolder3d): one self-contained page with the outcome per body
(overturned, peak tilt about any horizontal axis and its azimuth, slip vector, twist), zoomable
time histories, the energy ledger, the figures (the bodies drawn from the VTK frames), the
scenario and the run's files. The 2-D page (report.py) is left as it is; the helpers that do not
depend on the dimension are shared."""
import base64
import html
import math

import numpy as np

from .animation_3d import write_animation_3d
from .figures_3d import MAX_CURVES, make_run_figures_3d
from .report import HERE, _json_script, _script, dygraphs_assets, energy_section, warnings_section
from .report_data import MAX_PLOT_ROWS, _round, _stride
from .run_folder_3d import azimuth_deg

MAX_ROWS = 30  # bodies in the outcome table: the largest peak tilts; every body is in summary.json


def _cell(key, text, cls="num"):
    """A table cell tagged with the summary.json quantity it shows (the tests read it back)."""
    return f"<td class='{cls}' data-key='{key}'>{text}</td>"


def _g(value, digits=4):
    return "–" if value is None or not math.isfinite(value) else f"{value:.{digits}g}"


def _angle_cell(key, rad):
    return _cell(key, f"{_g(rad)} rad ({_g(math.degrees(rad), 3)}°)")


def lean_direction(axis):
    """The horizontal direction the body's top moved towards when it turned about `axis` by a
    positive angle: axis x e_z (right-handed)."""
    return (axis[1], -axis[0], 0.0)


def _body_row(run, b):
    name = b["name"]
    axis = b.get("peak_tilt_axis", [0.0, 0.0, 0.0])
    tilted = b.get("peak_tilt_rad", 0.0) > 0.0
    axis_az, lean_az = (azimuth_deg(axis), azimuth_deg(lean_direction(axis))) if tilted else (None, None)
    slip = b.get("slip_m", [0.0, 0.0])
    over = b.get("overturned", False)
    final_tilt = float(run.series(name, "tilt_rad")[-1]) if run.has_series(name) else None
    twist = float(run.twist_rad(name)[-1]) if run.has_series(name) else None
    overturned = (f"<td class='{'yes' if over else 'no'}' data-key='overturned'>{'yes' if over else 'no'}"
                  f" (limit {_g(b.get('overturning_angle_rad'))} rad)</td>")
    word = b.get("outcome", "")
    when = b.get("outcome_time_s")
    outcome = (f"<td class='{'yes' if b.get('failed') else 'no'}' data-key='outcome'>{html.escape(word.replace('_', ' '))}"
               f"{f' at {_g(when)} s' if isinstance(when, (int, float)) else ''}</td>")
    return (f"<tr data-body='{html.escape(name)}'><td>{html.escape(name)}</td>{outcome}{overturned}"
            f"{_angle_cell('peak_tilt_rad', b.get('peak_tilt_rad', 0.0))}{_cell('peak_tilt_time_s', _g(b.get('peak_tilt_time_s')))}"
            f"{_cell('peak_tilt_axis_azimuth_deg', _g(axis_az))}{_cell('lean_azimuth_deg', _g(lean_az))}"
            f"{_cell('final_tilt_rad', _g(final_tilt))}{_cell('slip_x_m', _g(slip[0]))}{_cell('slip_y_m', _g(slip[1]))}"
            f"{_cell('slip_length_m', _g(math.hypot(*slip)))}{_cell('peak_slip_m', _g(b.get('peak_slip_m')))}"
            f"{_cell('final_twist_rad', _g(twist))}</tr>")


def outcome_section(run):
    s = run.summary
    parts = ["<h2 id='outcome'>Outcome</h2>"]
    if s.get("status") == "interrupted":
        parts.append(f"<p class='failed'>The run was interrupted (SIGINT or SIGTERM) at t = {s.get('time_s', 0):.4g} s; "
                     "the results below are those up to that time.</p>")
    elif s.get("status") != "completed":
        parts.append(f"<p class='failed'>The run stopped: {html.escape(str(s.get('error', s.get('status'))))}</p>")
    critical = s.get("critical_dt_s")
    limit = f" (stable limit at the start {critical:.4g} s)" if isinstance(critical, (int, float)) else ""
    parts.append(f"<p>Simulated {s.get('time_s', 0):.4g} s in {s.get('steps', 0)} steps of dt = {s.get('dt_s', 0):.4g} s"
                 f"{limit}; {s.get('contact_points', 0)} contact points at the end. Slips are relative to the table "
                 f"(the prescribed motion), tilts are about any horizontal axis.</p>")
    dynamic = [b for b in s.get("bodies", []) if b.get("kind") == "dynamic"]
    if dynamic:
        over = sum(1 for b in dynamic if b.get("overturned"))
        words = {}
        for b in dynamic:
            words[b.get("outcome", "?")] = words.get(b.get("outcome", "?"), 0) + 1
        counted = ", ".join(f"{n} {w.replace('_', ' ')}" for w, n in sorted(words.items()))
        most = max(dynamic, key=lambda b: b.get("peak_tilt_rad", 0.0))
        far = max(dynamic, key=lambda b: b.get("peak_slip_m", 0.0))
        parts.append(f"<p id='outcome-counts'>{len(dynamic)} dynamic bodies ({html.escape(counted)}), <b>{over} overturned</b>; largest peak tilt "
                     f"{most.get('peak_tilt_rad', 0.0):.4g} rad ({html.escape(most['name'])}), largest peak slip "
                     f"{far.get('peak_slip_m', 0.0):.4g} m ({html.escape(far['name'])}).</p>")
    shown = sorted(dynamic, key=lambda b: -b.get("peak_tilt_rad", 0.0)) if len(dynamic) > MAX_ROWS else dynamic
    rows = ["<tr><th>body</th><th>outcome</th><th>overturned?</th><th>peak tilt</th><th>at t [s]</th><th>tilt axis azimuth [°]</th>"
            "<th>leaned towards [°]</th><th>final tilt [rad]</th><th>slip x [m]</th><th>slip y [m]</th>"
            "<th>|slip| [m]</th><th>peak |slip| [m]</th><th>final twist [rad]</th></tr>"]
    rows += [_body_row(run, b) for b in shown[:MAX_ROWS]]
    parts.append("<table id='outcome-table'>" + "".join(rows) + "</table>")
    if len(dynamic) > MAX_ROWS:
        parts.append(f"<p class='note'>The {MAX_ROWS} largest peak tilts of {len(dynamic)} bodies; every body is in "
                     "summary.json.</p>")
    parts.append("<p class='note'>Tilt: the angle between a body's initially vertical line and the vertical. Peak tilt "
                 "axis: the horizontal axis it turned about at the peak (summary.json <code>peak_tilt_axis</code>); its "
                 "azimuth and the direction the top leaned towards are measured from +x towards +y (counter-clockwise "
                 "seen from above). Outcome: the 2-D words and rule (docs/outputs.md, \"Outcomes\"), from the tilt on the body "
                 "below, the slip of the resting face's lowest corner on it, and the support. Overturned: the tilt at the end exceeds atan(d / h) of the initial base (the limit "
                 "shown). Slip: the centroid's horizontal displacement minus the table's, at the end. Twist: the turn "
                 "about the vertical (twist-swing split of the quaternion in history.csv), counter-clockwise +. "
                 "docs/3d.md, \"Outputs\".</p>")
    notes = run.limitations()
    if notes:
        items = "".join(f"<li>{html.escape(n)}</li>" for n in notes)
        parts.append(f"<h3 id='limits'>What this report cannot show</h3><ul class='limits'>{items}</ul>")
    return "\n".join(parts)


ENERGY_ROWS_3D = [("kinetic", "kinetic (now)"), ("gravitational_change", "gravitational change since t = 0"),
                  ("elastic", "elastic, in contact springs (now)"), ("normal_dashpot", "dissipated by normal dashpots"),
                  ("shear_dashpot", "dissipated by shear dashpots"), ("friction", "dissipated by friction"),
                  ("table_work", "work done by the table"), ("residual", "residual")]


def _plot(t, series, labels, ylabel, title):
    step = _stride(len(t), MAX_PLOT_ROWS)
    rows = np.column_stack([t[::step]] + [s[::step] for s in series])
    return {"title": title, "ylabel": ylabel, "labels": ["t"] + labels, "rows": [_round(r) for r in rows],
            "thinned": step > 1}


def plot_data(run):
    """The zoomable plots: tilt, slips, twist of the bodies that tilted most, the table, the ledger."""
    t = run.t_s
    bodies = run.ranked_dynamic(MAX_CURVES)
    ref = run.table_name() or "the ground"
    plots = []
    if bodies:
        plots.append(_plot(t, [run.series(b, "tilt_rad") for b in bodies], bodies, "tilt [rad]", "Tilt"))
        plots.append(_plot(t, [run.slip_m(b, "x") for b in bodies], bodies, "u_x [m]", f"Slip along x relative to {ref}"))
        plots.append(_plot(t, [run.slip_m(b, "y") for b in bodies], bodies, "u_y [m]", f"Slip along y relative to {ref}"))
        plots.append(_plot(t, [run.twist_rad(b) for b in bodies], bodies, "twist [rad]",
                           "Twist (about the vertical, counter-clockwise +)"))
    if run.table_name():
        plots.append(_plot(t, [run.table_acceleration_m_s2(a) for a in "xyz"], ["a_x", "a_y", "a_z"], "a [m/s²]",
                           f"Table acceleration ({run.table_name()}; from its velocity in history.csv)"))
    e = run.energy
    if e is not None:
        names = [c for c in ["kinetic_J", "gravitational_change_J", "elastic_J", "normal_dashpot_J", "shear_dashpot_J",
                             "friction_J", "table_work_J", "residual_J"] if c in e]
        plots.append(_plot(e["t_s"], [e[c] for c in names], names, "energy [J]", "Energy ledger"))
        if "balance_error" in e:
            plots.append(_plot(e["t_s"], [e["balance_error"]], ["balance_error"], "[-]",
                               "Balance error (|residual| over the largest term; meaningless near t = 0)"))
    return plots


FIGURE_CAPTIONS = {
    "snapshots": "The bodies at the start, at the largest peak tilt and at the end (the VTK faces posed from "
                 "history.csv): "
                 "axonometric, plan and two elevations; red dynamic, blue driven (table), grey fixed.",
    "response": f"Tilt, slip along x and y relative to the table, and twist (the {MAX_CURVES} largest peak tilts).",
    "table_motion": "The table's acceleration, x and y horizontal, z vertical.",
    "energy": "The energy ledger, its residual and the balance error.",
}


def figures_section(run, written):
    parts = ["<h2 id='figures'>Figures</h2>"]
    movie = written.get("animation")
    if movie:
        rel = html.escape(str(movie.relative_to(run.path)))
        tag = (f"<video id='animation' controls loop src='{rel}' width='640'></video>" if movie.suffix == ".mp4"
               else f"<img id='animation' alt='animation' src='{rel}' width='640'>")
        parts.append(f"<figure id='figure-animation'>{tag}<figcaption>The run in the axonometric view, the bodies "
                     f"posed from history.csv (<a href='{rel}'>{movie.suffix[1:].upper()}</a>).</figcaption></figure>")
    for stem in ("snapshots", "response", "table_motion", "energy"):
        paths = written.get(stem) or []
        png = next((p for p in paths if p.suffix == ".png"), None)
        if png is None:
            continue
        data = base64.b64encode(png.read_bytes()).decode("ascii")
        links = " ".join(f"<a href='{html.escape(str(p.relative_to(run.path)))}'>{p.suffix[1:].upper()}</a>" for p in paths)
        parts.append(f"<figure id='figure-{stem}'><img alt='{stem}' src='data:image/png;base64,{data}'>"
                     f"<figcaption>{FIGURE_CAPTIONS[stem]} {links}</figcaption></figure>")
    return "\n".join(parts)


def files_section(run):
    names = ["scenario.toml", "history.csv", "energy.csv", "summary.json", "vtk/bodies.pvd"]
    items = "".join(f"<li><a href='{n}'>{n}</a></li>" for n in names if (run.path / n).is_file())
    return (f"<h2 id='files'>Files of this run</h2><ul>{items}</ul><p class='note'>Open vtk/bodies.pvd in ParaView "
            "(colour by tilt_rad or body).</p>")


def build_report_3d(run, written):
    payload = {"plots": plot_data(run)}
    dyg_js, dyg_css = dygraphs_assets()
    title = html.escape(run.title())
    description = html.escape(str(run.scenario.get("description", "")))
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}: blockdem report</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<style>{(HERE / 'report.css').read_text(encoding='utf-8')}
{dyg_css}</style></head>
<body>
<h1>{title}</h1>
<p>{description}</p>
<p class='note'>blockdem report of the 3-D run of <code>{html.escape(str(run.summary.get('scenario', '')))}</code>.
<a href='#outcome'>Outcome</a> · <a href='#figures'>Figures</a> · <a href='#plots'>Time histories</a> ·
<a href='#energy'>Energy</a> · <a href='#scenario'>Scenario</a></p>
{warnings_section(run)}
{outcome_section(run)}
{figures_section(run, written)}
<h2 id='plots'>Time histories</h2>
<p class='note'>Drag to zoom, double-click to reset, use the range selector under each plot for long records.</p>
<div id='plot-area'></div>
{energy_section(run, ENERGY_ROWS_3D)}
<h2 id='scenario'>Scenario as run</h2>
<pre>{html.escape(run.scenario_text)}</pre>
{files_section(run)}
<script type="application/json" id="report-data">{_json_script(payload)}</script>
<script>{_script(dyg_js)}</script>
<script>{_script((HERE / 'report_3d.js').read_text(encoding='utf-8'))}</script>
</body></html>
"""


def write_report_3d(run, formats=("png", "svg"), animation=True):
    """Makes the figures (and the animation file), then writes run.path/report.html; returns its path."""
    written = make_run_figures_3d(run, formats)
    if animation:
        written["animation"] = write_animation_3d(run, run.path / "figures")
    path = run.path / "report.html"
    path.write_text(build_report_3d(run, written), encoding="utf-8")
    return path
