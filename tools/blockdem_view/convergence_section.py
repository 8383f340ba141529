"""The report's "Convergence" section: the verdict of `blockdem converge` (docs/convergence.md)
when the run folder is one of a study's runs, i.e. when ../converge.json names it. Also maps a
study folder (converge.json, dt/, dt_2/, ...) to its base run, so that `blockdem report STUDY`
reports the base run with its verdict."""
import html
import json
import math
from pathlib import Path

LABELS = {"peak_rotation_rad": "peak rotation [rad]", "peak_slip_m": "peak slip [m]", "final_slip_m": "final slip [m]",
          "overturning_time_s": "overturned at [s]", "overturned": "overturned", "outcome": "outcome"}
MAX_BODIES = 20  # a large assembly: the least converged first, the rest in converge.csv


def study_base_folder(folder):
    """The base run of a study folder (DIR/converge.json and DIR/<base>/), else the folder itself."""
    folder = Path(folder)
    study = folder / "converge.json"
    if (folder / "summary.json").is_file() or not study.is_file():
        return folder
    try:
        base = json.loads(study.read_text(encoding="utf-8")).get("base_run", "dt")
    except (OSError, ValueError):
        return folder
    return folder / base if (folder / base).is_dir() else folder


def find_study(run_path):
    """(converge.json as a dict, this run's entry in its "runs") when ../converge.json names the
    folder, else (None, None)."""
    path = Path(run_path).resolve()
    study = path.parent / "converge.json"
    if not study.is_file():
        return None, None
    try:
        data = json.loads(study.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None, None
    entry = next((r for r in data.get("runs", []) if r.get("folder") == path.name), None)
    return (data, entry) if entry else (None, None)


def _value(v):
    if v is None:
        return "–"
    if isinstance(v, str):
        return html.escape(v)
    return f"{v:.4g}" if math.isfinite(v) else "–"


def _percent(v):
    return "–" if v is None else f"{100.0 * v:.2f}%"


def _state(judged, ok, bad_word):
    if not judged:
        return "<td class='note'>not judged</td>"
    return "<td class='no'>ok</td>" if ok else f"<td class='yes'>{bad_word}</td>"


def _dt_table(body):
    rows = ["<tr><th>quantity</th><th>dt</th><th>dt/2</th><th>dt/4</th><th>dt → dt/2</th><th>dt/2 → dt/4</th><th></th></tr>"]
    for q in body.get("dt", []):
        values = "".join(f"<td class='num'>{_value(v)}</td>" for v in q.get("values", []))
        changes = q.get("relative_changes") or [None, None]
        rows.append(f"<tr><td>{LABELS.get(q['quantity'], q['quantity'])}</td>{values}"
                    f"<td class='num'>{_percent(changes[0])}</td><td class='num'>{_percent(changes[1])}</td>"
                    f"{_state(q.get('judged'), q.get('converged'), 'not converged')}</tr>")
    return "<table>" + "".join(rows) + "</table>"


def _ensemble_table(body, members):
    rows = [f"<tr><th>ensemble of {members} runs</th><th>mean</th><th>min</th><th>max</th><th>spread</th><th></th></tr>"]
    for s in body.get("ensemble", []):
        if "values_seen" in s:
            cells = f"<td colspan='4'>{html.escape(', '.join(s['values_seen']))}</td>"
        else:
            cells = "".join(f"<td class='num'>{_value(s.get(k))}</td>" for k in ("mean", "min", "max"))
            cells += f"<td class='num'>{_percent(s.get('relative_spread'))}</td>"
        if not s.get("judged", True):
            state = "<td class='note'>not judged</td>"
        elif s.get("chaotic"):
            state = "<td class='yes'>chaotic</td>"
        else:
            state = "<td class='yes'>sensitive</td>" if s.get("sensitive") else "<td class='no'>ok</td>"
        rows.append(f"<tr><td>{LABELS.get(s['quantity'], s['quantity'])}</td>{cells}{state}</tr>")
    fraction = body.get("ensemble_fraction_overturned")
    note = f"<p>Overturned in {100.0 * fraction:.0f}% of the ensemble.</p>" if fraction is not None else ""
    return "<table>" + "".join(rows) + "</table>" + note


def _stiffness_table(body):
    rows = ["<tr><th>contact stiffness (at dt/2)</th><th>× 0.5</th><th>× 1</th><th>× 2</th><th>largest change</th><th></th></tr>"]
    for s in body.get("stiffness", []):
        values = "".join(f"<td class='num'>{_value(v)}</td>" for v in s.get("values", []))
        change = "" if s.get("max_relative_change") is None else _percent(s["max_relative_change"])
        rows.append(f"<tr><td>{LABELS.get(s['quantity'], s['quantity'])}</td>{values}<td class='num'>{change}</td>"
                    f"{_state(s.get('judged', True), not s.get('sensitive'), 'sensitive')}</tr>")
    return "<table>" + "".join(rows) + "</table>"


def _headline(data, entry):
    tol = data.get("tolerance", {})
    floors = tol.get("floors", {})
    counts = data.get("counts", {})
    verdict = data.get("verdict", "?")
    cls = "no" if verdict == "converged" else "yes"
    parts = [f"<p>Verdict of <code>blockdem converge</code>: <span class='{cls}'>{html.escape(verdict)}</span> "
             f"({counts.get('converged', 0)} bodies converged, {counts.get('not_converged', 0)} not converged, "
             f"{counts.get('chaotic', 0)} chaotic). This run is <code>{html.escape(entry['label'])}</code> "
             f"({html.escape(entry.get('description', ''))}) of the study in <code>../</code>.</p>",
             f"<p class='note'>Runs at dt = {data.get('base_dt_s', 0):.4g} s, dt/2 and dt/4. Converged: the relative change "
             f"|b − a| / max(|a|, |b|, floor) from dt/2 to dt/4 is at most {100.0 * tol.get('rtol', 0):g}% for every quantity "
             f"judged, and flags agree; floors {floors.get('peak_rotation_rad', 0):g} rad (rotation), "
             f"{floors.get('peak_slip_m', 0):g} m (slip), {floors.get('overturning_time_s', 0):g} s (overturning time). "
             f"After a body overturns, its peak rotation and slip describe the fall and are not judged.</p>"]
    if data.get("stiffness_sensitive") is not None:
        word = ("<b>depends on</b> the stiffness beyond" if data["stiffness_sensitive"]
                else "does not depend on the stiffness within")
        parts.append(f"<p>Contact stiffness (kn and ks × 0.5 and × 2, at dt/2): the answer {word} the tolerance.</p>")
    for failed in data.get("failed_runs", []):
        parts.append(f"<p class='failed'>Run failed: {html.escape(failed)}</p>")
    return "\n".join(parts)


def convergence_section(run):
    """The section's HTML, or '' when the run is not part of a convergence study."""
    data, entry = find_study(run.path)
    if data is None:
        return ""
    rank = {"chaotic": 0, "not converged": 1, "converged": 2}
    bodies = sorted(data.get("bodies", []), key=lambda b: rank.get(b.get("verdict"), 3))
    members = 1 + data.get("ensemble_study", {}).get("size", 0)
    parts = ["<h2 id='convergence'>Convergence</h2>", _headline(data, entry)]
    for body in bodies[:MAX_BODIES]:
        base_note = "" if body.get("base_within_tolerance", True) else " (the base dt's answer is outside the tolerance)"
        parts.append(f"<h3>{html.escape(body['name'])}: {html.escape(body.get('verdict', '?'))}{base_note}</h3>")
        parts.append(_dt_table(body))
        if body.get("ensemble"):
            parts.append(_ensemble_table(body, members))
        if body.get("stiffness"):
            parts.append(_stiffness_table(body))
        if body.get("reasons"):
            parts.append("<ul>" + "".join(f"<li>{html.escape(r)}</li>" for r in body["reasons"]) + "</ul>")
    if len(bodies) > MAX_BODIES:
        parts.append(f"<p class='note'>… and {len(bodies) - MAX_BODIES} more bodies: ../converge.csv.</p>")
    return "\n".join(parts)
