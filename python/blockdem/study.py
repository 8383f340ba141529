"""blockdem.sweep: a parameter study in memory, the plan, cases and table of `blockdem sweep`.

The cases run in C++ (src/sweep: make_case, run_case, format_row) on threads, with the GIL
released; this file only turns Python arguments into the plan's text values and the table's
rows into numpy columns. See docs/python.md ("Studies") and docs/sweeps.md.
"""
import os

import numpy as np

from blockdem import _core


def _toml_value(value):
    """A value as `--set` reads it: numbers and booleans as TOML, strings as given."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"sweep: {value!r} ({type(value).__name__}) cannot be a scenario value")


def _value_list(values):
    """A level list: "a:b:step" / "v1,v2" text as the CLI takes it, or a sequence of numbers."""
    if values is None or isinstance(values, str):
        return values
    return ",".join(_toml_value(v) for v in np.atleast_1d(values))


def _axes(vary, cases):
    """--cases first, then each --vary in order (the CLI's order of axes)."""
    axes = []
    if cases is not None:
        if isinstance(cases, (str, os.PathLike)):
            raise TypeError("sweep: cases is a list of dicts; a case list file goes to the CLI's --cases")
        cases = list(cases)
        if not cases:
            raise ValueError("sweep: cases is empty")
        keys = list(cases[0])
        for i, c in enumerate(cases):
            if list(c) != keys:
                raise ValueError(f"sweep: case {i} sets {list(c)}, case 0 sets {keys}: every case sets the same keys")
        axes.append((keys, [[_toml_value(c[k]) for k in keys] for c in cases]))
    for key, values in (vary or {}).items():
        if isinstance(values, str):
            points = [[v] for v in _core.parse_value_list(values)]
        else:
            points = [[_toml_value(v)] for v in values]
        if not points:
            raise ValueError(f"sweep: vary[{key!r}] has no values")
        axes.append(([key], points))
    return axes


def _column(name, texts):
    """A column of results.csv as numpy: integers, floats (empty = NaN) or strings."""
    if name == "case_id":
        return np.array([int(t) for t in texts], dtype=np.int64)
    if name in ("status", "error", "record"):
        return np.array(texts, dtype=object)
    if name.endswith((".overturned", ".failed")):
        return np.array([t == "1" for t in texts], dtype=bool)
    try:
        return np.array([float(t) if t != "" else np.nan for t in texts], dtype=np.float64)
    except ValueError:
        return np.array(texts, dtype=object)


def sweep(scenario, vary=None, cases=None, records=None, scale=None, target_pga=None, target_pga_unit=None,
          record_keys=None, solver="dem", stop_when_overturned=True, housner_dt=1.0e-4, housner_restitution=None,
          threads=0):
    """Runs every case of a study and returns its table as {column: numpy array}.

    scenario: a blockdem.Scenario or a scenario file. vary: {key: values} (a sequence, or the
    CLI's "start:stop:step" / "v1,v2" text), one axis each, in order. cases: a list of dicts
    setting several keys together (one axis, first). records: a folder or list file (as
    --records), or a list of record files. scale / target_pga (with target_pga_unit "g",
    "m/s^2" or "gal"): the levels per record. record_keys: {key: value} for every record, e.g.
    {"duration": 15}. solver: "dem" or "housner". threads: cases at once (0: all cores).

    Columns are those of results.csv (docs/sweeps.md): case_id, the varied values, status,
    error, table_pga_m_s2, per body "<body>.overturned" ... "<body>.failed" (bool for 0/1),
    wall_time_s; plus "bodies" (the names). A case that fails has status "failed" or "error"
    and its message; it never raises.
    """
    from blockdem import Scenario  # the package's own class (the extension's)

    if not isinstance(scenario, Scenario):
        scenario = Scenario.from_file(os.fspath(scenario))
    suite, files = None, []
    if isinstance(records, (str, os.PathLike)):
        suite = os.fspath(records)
    elif records is not None:
        files = [os.fspath(r) for r in records]
        if not files:
            raise ValueError("sweep: records is empty")
    table = _core.sweep_table(
        scenario, _axes(vary, cases), suite, files, _value_list(scale), _value_list(target_pga),
        target_pga_unit, [(k, _toml_value(v)) for k, v in (record_keys or {}).items()], solver,
        stop_when_overturned, housner_dt, -1.0 if housner_restitution is None else housner_restitution, int(threads))
    rows = table["rows"]
    result = {name: _column(name, [r[i] for r in rows]) for i, name in enumerate(table["columns"])}
    result["bodies"] = list(table["bodies"])
    return result
