"""report.html: one self-contained page (no server, no network) with the scenario, the derived
parameters, the outcome, the animation, zoomable plots and the figures of a run folder."""
import base64
import html
import json
import math
import subprocess
from pathlib import Path

from .convergence_section import convergence_section
from .figures import dynamic_bodies
from .make_figures import make_run_figures
from .report_data import animation_data, plot_data

HERE = Path(__file__).resolve().parent
DYGRAPHS = Path("/usr/share/javascript/dygraphs")  # Debian's libjs-dygraphs


def _json_script(payload):
    """JSON safe inside <script>: '<\\/' is a valid JSON escape of '</', which could end the element."""
    return json.dumps(payload, separators=(",", ":")).replace("</", "<\\/")


def _script(code):
    """JavaScript safe inside <script>: it must not contain '</script' (checked, not rewritten,
    since rewriting could change a regular expression)."""
    if "</script" in code.lower():
        raise ValueError("a script to inline contains '</script'")
    return code


def dygraphs_assets():
    """(javascript, css) of Debian's dygraphs, or ('', '') when it is not installed."""
    js, css = DYGRAPHS / "dygraph.min.js", DYGRAPHS / "dygraph.min.css"
    if not js.is_file():
        return "", ""
    # The source-map comment would point at a file the page does not carry.
    code = "\n".join(l for l in js.read_text(encoding="utf-8").splitlines() if not l.startswith("//# sourceMappingURL"))
    style = "\n".join(l for l in css.read_text(encoding="utf-8").splitlines() if "sourceMappingURL" not in l)
    return code, style


def derived_parameters(run, blockdem):
    """The output of `blockdem check` on the scenario as run, or None when it cannot be had
    (no binary given, or the scenario names files relative to its original folder)."""
    if not blockdem:
        return None
    try:
        done = subprocess.run([str(Path(blockdem).resolve()), "check", "scenario.toml"], cwd=run.path, capture_output=True,
                              text=True, timeout=60)
    except OSError:
        return None
    return done.stdout if done.returncode == 0 else None


def _yes_no(flag, detail=""):
    cls = "yes" if flag else "no"
    return f"<td class='{cls}'>{'yes' if flag else 'no'}{html.escape(detail)}</td>"


def _num(value, unit="", digits=4):
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "<td class='num'>–</td>"
    return f"<td class='num'>{value:.{digits}g}{(' ' + unit) if unit else ''}</td>"


def outcome_section(run):
    s = run.summary
    parts = ["<h2 id='outcome'>Outcome</h2>"]
    if s.get("status") == "interrupted":
        parts.append(f"<p class='failed'>The run was interrupted (SIGINT or SIGTERM) at t = {s.get('time_s', 0):.4g} s; "
                     "the results below are those up to that time.</p>")
    elif s.get("status") != "completed":
        parts.append(f"<p class='failed'>The run stopped: {html.escape(str(s.get('error', s.get('status'))))}</p>")
    parts.append(f"<p>Simulated {s.get('time_s', 0):.4g} s in {s.get('steps', 0)} steps of dt = {s.get('dt_s', 0):.4g} s "
                 f"(stable limit {s.get('critical_dt_s', 0):.4g} s); wall time {run.run_info.get('wall_time_s', s.get('wall_time_s', 0)):.3g} s. "
                 f"Displacements are relative to {html.escape(str(s.get('displacements_relative_to', 'ground')))}.</p>")
    rows = ["<tr><th>body</th><th>outcome</th><th>slid?</th><th>rocked?</th><th>overturned?</th><th>peak |rotation|</th>"
            "<th>at t</th><th>peak |u| relative</th><th>final u_x relative</th></tr>"]
    for b in s.get("bodies", []):
        if b.get("kind") != "dynamic":
            continue
        slid = f" ({b['sliding_time_s']:.3g} s sliding)" if b.get("slid") else ""
        over = f" at t = {b['overturning_time_s']:.3f} s" if b.get("overturned") else ""
        rot = b.get("peak_abs_rotation_rad", 0.0)
        final = (b.get("final_relative_displacement_m") or [None])[0]
        rows.append(f"<tr><td>{html.escape(b['name'])}</td>{_outcome_cell(b)}{_yes_no(b.get('slid'), slid)}{_yes_no(b.get('rocked'))}"
                    f"{_yes_no(b.get('overturned'), over)}<td class='num'>{rot:.4g} rad ({math.degrees(rot):.3g}°)</td>"
                    f"{_num(b.get('time_of_peak_rotation_s'), 's')}{_num(b.get('peak_abs_relative_displacement_m'), 'm')}"
                    f"{_num(final, 'm')}</tr>")
    parts.append("<table>" + "".join(rows) + "</table>")
    parts.extend(_collapse_and_domain(s))
    parts.append("<p class='note'>Outcomes (overturned, fell and left_model are failures), sliding, rocking and "
                 "overturning: docs/outputs.md, \"Outcomes\".</p>")
    notes = run.limitations()
    if notes:
        items = "".join(f"<li>{html.escape(n)}</li>" for n in notes)
        parts.append(f"<h3 id='limits'>What this report cannot show</h3><ul class='limits'>{items}</ul>")
    return "\n".join(parts)


def warnings_section(run):
    """The run's own warnings (summary.json "warnings": dt above the live stable limit, deep overlaps,
    a balance error above 1%), first, because a result that may be wrong must say so."""
    warnings = run.summary.get("warnings") or []
    if not warnings:
        return ""
    items = "".join(f"<li>{html.escape(str(w))}</li>" for w in warnings)
    return (f"<h2 id='warnings'>Warnings</h2><p class='failed'>This result may be wrong; read these before "
            f"trusting it (docs/outputs.md, \"Checks and warnings\").</p><ul class='limits'>{items}</ul>")


def _outcome_cell(b):
    """The body's outcome word with its event (docs/outputs.md, "Outcomes"); summaries without one say so."""
    outcome = b.get("outcome")
    if outcome is None:
        return "<td>–</td>"
    t = b.get("outcome_time_s")
    detail = f" at t = {t:.3f} s" if t is not None else ""
    if outcome == "fell" and b.get("fell"):
        x, y = b["fell"]["position_m"]
        rest = "came to rest" if b["fell"].get("came_to_rest") else "still moving"
        detail += f", {rest} at ({x:.3f}, {y:.3f}) m"
    if outcome == "left_model" and b.get("left_model"):
        x, y = b["left_model"]["position_m"]
        detail += f", taken out at ({x:.3f}, {y:.3f}) m"
    cls = "yes" if b.get("failed") else "no"
    return f"<td class='{cls}'><b>{html.escape(outcome.replace('_', ' '))}</b>{html.escape(detail)}</td>"


def _collapse_and_domain(s):
    """The collapse of each assembly (more than one block) and the bodies that left the model."""
    parts = []
    rows = []
    collapse = s.get("collapse", [])
    for c in collapse:
        repeats = c["group"] == "all" and len(collapse) == 2 and collapse[0]["blocks"] == c["blocks"]
        if c["blocks"] < 2 or repeats:
            continue
        first = (f"{html.escape(c['first_to_go'])} at t = {c['first_to_go_time_s']:.3f} s"
                 if c.get("first_to_go") else "none")
        rows.append(f"<tr><td>{html.escape(c['group'])}</td><td class='num'>{c['blocks']}</td><td class='num'>{c['fell']}</td>"
                    f"<td class='num'>{c['overturned']}</td><td class='num'>{c['left_model']}</td>"
                    f"<td class='num'>{100 * c['displaced_mass_fraction']:.3g}%</td><td>{first}</td></tr>")
    if rows:
        parts.append("<table><tr><th>assembly</th><th>blocks</th><th>fell</th><th>overturned</th><th>left the model</th>"
                     "<th>mass displaced</th><th>first to go</th></tr>" + "".join(rows) + "</table>")
    left = s.get("domain", {}).get("left", [])
    if left:
        items = "".join(f"<li>{html.escape(l['body'])} at t = {l['time_s']:.3f} s, at ({l['position_m'][0]:.3f}, "
                        f"{l['position_m'][1]:.3f}) m</li>" for l in left)
        parts.append(f"<p>Bodies that left the model (taken out of the run, frozen where they left):</p><ul>{items}</ul>")
    return parts


ENERGY_ROWS = [("kinetic", "kinetic (now)"), ("gravitational_change", "gravitational change since t = 0"),
               ("elastic", "elastic, in contact springs (now)"), ("normal_dashpot_dissipated", "dissipated by normal dashpots"),
               ("shear_dashpot_dissipated", "dissipated by shear dashpots"), ("friction_dissipated", "dissipated by friction"),
               ("table_work", "work done by the table"),
               ("removed_with_bodies_leaving", "taken out with bodies that left the model"),
               ("initial_stored", "stored at t = 0"), ("residual", "residual")]


def energy_section(run, terms=ENERGY_ROWS):
    """The ledger's terms at the end (terms: (summary key, label) pairs; the 3-D ledger has its own)."""
    e = run.summary.get("energy_j", {})
    rows = "".join(f"<tr><td>{label}</td>{_num(e.get(key), 'J')}</tr>" for key, label in terms if key in e)
    error = e.get("balance_error_relative")
    note = (f"<p id='balance-error'>Balance error at the end: {error:.3g} of the largest term.</p>"
            if error is not None else "")
    return f"<h2 id='energy'>Energy balance at the end</h2><table>{rows}</table>{note}"


def animation_section():
    return """<h2 id='animation'>Animation</h2>
<div id='player'>
<div class='controls'><button id='anim-play'>Play</button>
<input id='anim-slider' type='range' min='0' value='0' step='1' aria-label='frame'>
<span id='anim-time'>t = 0 s</span>
<label>speed <select id='anim-speed'><option value='0.1'>0.1×</option><option value='0.25'>0.25×</option>
<option value='0.5'>0.5×</option><option value='1' selected>1× (real time)</option><option value='2'>2×</option>
<option value='5'>5×</option></select></label>
<label>view <select id='anim-view'><option value='view'>moving bodies</option><option value='scene'>whole scene</option></select></label></div>
<canvas id='anim-canvas' width='900' height='420'></canvas>
<p class='note'><span class='legend-swatch' style='background:#c0504d'></span> dynamic
<span class='legend-swatch' style='background:#4f81bd'></span> driven (table)
<span class='legend-swatch' style='background:#9a9a9a'></span> fixed.
Click a plot below to jump to that time.</p></div>"""


def figures_section(run, written):
    parts = ["<h2 id='figures'>Figures</h2>"]
    for stem in ("acceleration", "response", "sensors", "energy", "snapshots"):
        paths = written.get(stem) or []
        png = next((p for p in paths if p.suffix == ".png"), None)
        if png is None:
            continue
        data = base64.b64encode(png.read_bytes()).decode("ascii")
        others = " ".join(f"<a href='{html.escape(str(p.relative_to(run.path)))}'>{p.suffix[1:].upper()}</a>"
                          for p in paths if p.suffix != ".png")
        parts.append(f"<figure><img alt='{stem}' src='data:image/png;base64,{data}'>"
                     f"<figcaption>{stem} {others}</figcaption></figure>")
    for p in written.get("animation", []):
        parts.append(f"<p>Animation file: <a href='{html.escape(str(p.relative_to(run.path)))}'>{p.name}</a></p>")
    return "\n".join(parts)


def files_section(run):
    names = ["scenario.toml", "history.csv", "energy.csv", "summary.json", "bodies.json", "sensors.csv", "interfaces.csv", "vtk/bodies.pvd", "vtk/contacts.pvd"]
    items = "".join(f"<li><a href='{n}'>{n}</a></li>" for n in names if (run.path / n).is_file())
    return f"<h2 id='files'>Files of this run</h2><ul>{items}</ul><p class='note'>Open vtk/*.pvd in ParaView.</p>"


def build_report(run, blockdem=None, written=None):
    """The HTML text of the report of a run whose figures are `written` (see make_run_figures)."""
    bodies = dynamic_bodies(run)
    payload = {"animation": animation_data(run), "plots": plot_data(run, bodies)}
    dyg_js, dyg_css = dygraphs_assets()
    derived = derived_parameters(run, blockdem)
    derived_html = (f"<pre>{html.escape(derived)}</pre>" if derived else
                    "<p class='note'>Not available: run <code>blockdem check</code> on the original scenario.</p>")
    description = html.escape(str(run.scenario.get("description", "")))
    title = html.escape(run.title())
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}: blockdem report</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<style>{(HERE / 'report.css').read_text(encoding='utf-8')}
{dyg_css}</style></head>
<body>
<h1>{title}</h1>
<p>{description}</p>
<p class='note'>blockdem report of <code>{html.escape(str(run.summary.get('scenario', '')))}</code>.
<a href='#outcome'>Outcome</a> · <a href='#animation'>Animation</a> · <a href='#plots'>Plots</a> ·
<a href='#figures'>Figures</a> · <a href='#derived'>Derived parameters</a> · <a href='#scenario'>Scenario</a></p>
{warnings_section(run)}
{outcome_section(run)}
{convergence_section(run)}
{animation_section()}
<h2 id='plots'>Time histories</h2>
<p class='note'>Drag to zoom, double-click to reset, use the range selector under each plot for long records.</p>
<div id='plot-area'></div>
{energy_section(run)}
{figures_section(run, written or {})}
<h2 id='derived'>Derived parameters (blockdem check)</h2>
{derived_html}
<h2 id='scenario'>Scenario as run</h2>
<pre>{html.escape(run.scenario_text)}</pre>
{files_section(run)}
<script type="application/json" id="report-data">{_json_script(payload)}</script>
<script>{_script(dyg_js)}</script>
<script>{_script((HERE / 'report.js').read_text(encoding='utf-8'))}</script>
</body></html>
"""


def write_report(run, blockdem=None, formats=("png", "svg"), animation=True):
    """Makes the figures, then writes run.path/report.html; returns its path."""
    written = make_run_figures(run, formats, animation=animation)
    path = run.path / "report.html"
    path.write_text(build_report(run, blockdem, written), encoding="utf-8")
    return path
