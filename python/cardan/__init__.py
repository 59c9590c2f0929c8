"""cardan: kinematics, loads and efficiency of reciprocating mechanisms (the slider-crank, the
cardan gear and their relatives) from Python.

A case is what ``cardan run`` reads: a path to a case file, its TOML text, or a dict in the same
schema (``docs/configuration.md``; the dict read by the same typed reader, so its errors are the
file's). Everything runs in memory, in the Rust core, with the GIL released.

- ``run(case)`` -> ``Result``: ``summary`` ({train: {metric: value}}, SI), ``units``,
  ``steps(train)`` (per-step columns as numpy arrays), ``to_pandas()``.
- ``sweep(case, {"motion.initial_speed": [...], ...})`` -> the sweep table (a pandas DataFrame
  when pandas is installed, else a dict of numpy arrays).
- ``gear(pair)`` -> the gear-pair rating of ``cardan gear`` (its ``gear.json`` as a dict).

Bad input raises ``CaseError`` naming the field; a run that fails raises ``RunError``.
"""

from ._cardan import CaseError, RunError
from . import _cardan

__all__ = ["run", "sweep", "gear", "Result", "CaseError", "RunError", "COLUMNS"]

#: The per-step column templates and their meanings (the per-step files' columns).
COLUMNS = dict(_cardan.columns())


class Result:
    """One case run in memory.

    ``summary_json`` is the case's ``summary.json`` as the command line writes it (the same
    numbers, bit for bit); ``summary`` and ``units`` are its metrics and their units by crank
    train (``result.summary["cardan_gear"]["mechanical_efficiency"]``).
    """

    def __init__(self, summary_json, trains):
        self.summary_json = summary_json
        mechanisms = summary_json["mechanisms"]
        #: {train label: {metric: value}} (SI; see ``units``).
        self.summary = {k: v["metrics"] for k, v in mechanisms.items()}
        #: {train label: {metric: unit}}.
        self.units = {k: v["units"] for k, v in mechanisms.items()}
        #: What the case should know about its results (a grid too coarse for its peaks).
        self.warnings = list(summary_json.get("warnings", []))
        self._steps = dict(trains)

    @property
    def labels(self):
        """The crank trains, in the summary's order."""
        return list(self.summary)

    def steps(self, label):
        """The per-step columns of the train ``label`` as {column name: numpy array} (every
        ``output.decimation``-th step and the last, as the per-step files hold them)."""
        if label not in self.summary:
            raise KeyError(f"no crank train {label!r}: the case has {self.labels}")
        if label not in self._steps:
            raise ValueError("the case was run with steps=False: no per-step columns kept")
        return dict(self._steps[label])

    def to_pandas(self, label=None):
        """Without ``label``: the summary as a DataFrame (a row per metric, a column per train,
        and ``unit``). With ``label``: that train's per-step columns as a DataFrame."""
        import pandas as pd

        if label is not None:
            return pd.DataFrame(self.steps(label))
        frame = pd.DataFrame(self.summary)
        units = {}
        for per_train in self.units.values():
            for metric, unit in per_train.items():
                units.setdefault(metric, unit)
        frame["unit"] = pd.Series(units)
        return frame

    def __repr__(self):
        return f"<cardan.Result {self.summary_json.get('case')!r}: {', '.join(self.labels)}>"


def run(case, steps=True):
    """Runs ``case`` (a path, TOML text or a dict in the case-file schema) in memory and
    returns its ``Result``; ``steps=False`` keeps no per-step columns (the run then shares its
    steps among the threads, and its memory does not grow with them)."""
    summary_json, trains = _cardan.run(case, steps)
    return Result(summary_json, trains)


def _pandas_or_none():
    try:
        import pandas
    except ImportError:
        return None
    return pandas


def sweep(case, fields=None, mode="grid", as_pandas=None, errors="raise"):
    """Runs ``case`` at every point of ``fields`` ({dotted path: list of values, or {"from",
    "to", "points", "scale"}}, as a case file's ``[sweep]``; values may carry units, "120 mm")
    in ``mode`` "grid" (every combination) or "zip", the points in parallel; without
    ``fields``, the case's own ``[sweep]``.

    Returns the table of ``sweep.csv``: ``case`` (each point's name), each swept field (the
    values as numbers where they were given as numbers, else as written), then
    ``<train>.<metric>`` for every metric. A DataFrame when ``as_pandas`` (default: when pandas
    is installed), else a dict of numpy arrays. A point that fails raises ``RunError`` naming
    it (``errors="raise"``) or, with ``errors="nan"``, has NaN metrics and its message in an
    ``error`` column.
    """
    import numpy as np

    names, swept, metrics, failures = _cardan.sweep(case, fields, mode)
    failed = [f for f in failures if f is not None]
    if failed and errors == "raise":
        raise RunError(f"{len(failed)} of {len(names)} points failed:\n  " + "\n  ".join(failed))
    table = {"case": np.array(names, dtype=object)}
    for path, values in swept.items():
        try:
            table[path] = np.array([float(v) for v in values])
        except ValueError:
            table[path] = np.array(values, dtype=object)
    table.update(metrics)
    if failed:
        table["error"] = np.array([f or "" for f in failures], dtype=object)
    pandas = _pandas_or_none() if as_pandas is None else None
    if as_pandas or (as_pandas is None and pandas is not None):
        import pandas as pd

        return pd.DataFrame(table)
    return table


def gear(pair):
    """Rates a spur gear pair given as ``cardan gear``'s gear file (a path, TOML text or a dict;
    docs/gear-calculator.md): its ``gear.json`` as a dict, with ``failures`` (why the pair
    cannot work; empty if it works) and ``warnings``."""
    return _cardan.gear(pair)
