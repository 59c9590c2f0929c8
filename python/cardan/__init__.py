"""cardan: kinematics, loads and efficiency of reciprocating mechanisms (the slider-crank, the
cardan gear and their relatives) from Python.

A case is what ``cardan run`` reads: a path to a case file, its TOML text, or a dict in the same
schema (``docs/case-file.md``; the dict read by the same typed reader, so its errors are the
file's). Everything runs in memory, in the Rust core, with the GIL released.

- ``run(case)`` -> ``Result``: ``summary`` ({train: {metric: value}}, SI), ``units``,
  ``steps(train)`` (per-step columns as numpy arrays), ``machine`` (the whole machine's
  metrics), ``cylinders`` and ``main_bearings`` (their per-step loads), ``plot()`` (matplotlib
  figures), ``to_pandas()``; shown in a notebook as its summary table.
- ``sweep(case, {"motion.initial_speed": [...], ...})`` -> the sweep table (a pandas DataFrame
  when pandas is installed, else a dict of numpy arrays), swept fields in SI, units in
  ``attrs["units"]`` (``.units`` of the dict).
- ``gear(pair)`` -> the gear-pair rating of ``cardan gear`` (its ``gear.json`` as a dict).

Bad input raises ``CaseError`` naming the field; a run that fails raises ``RunError``.
"""

import html
import re

from ._cardan import CaseError, RunError
from . import _cardan
from ._plots import plot as _plot
from ._sweep import SweepTable, sweep

__all__ = ["run", "sweep", "optimize", "gear", "Result", "SweepTable", "CaseError", "RunError", "COLUMNS"]

#: The package's version (the crate's, python/Cargo.toml).
__version__ = _cardan.__version__

#: The per-step column templates and their meanings (the per-step files' columns).
COLUMNS = dict(_cardan.columns())


_CYLINDER = re.compile(r"cylinder_(\d+)_(.+)")
_MAIN_BEARING = re.compile(r"main_bearing_(\d+)_(.+)")


def _metric_units(units):
    """{metric: unit} over every crank train, in the summary's order."""
    merged = {}
    for per_train in units.values():
        for metric, unit in per_train.items():
            merged.setdefault(metric, unit)
    return merged


def _number(value):
    return "" if value is None else html.escape(f"{value:.6g}")


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
        frame["unit"] = pd.Series(_metric_units(self.units))
        return frame

    @property
    def machine(self):
        """The whole machine's metrics (docs/results.md, "The whole machine": the names starting
        with ``machine_``: its drive torque, power, losses, efficiency, main-journal and
        crank-pin peaks over every cylinder of ``[layout]``) by crank train: {train: {metric:
        value}}, SI (units in ``units``). ``layout`` names the machine they are of."""
        return {
            label: {k: v for k, v in metrics.items() if k.startswith("machine_")}
            for label, metrics in self.summary.items()
        }

    @property
    def layout(self):
        """The machine the whole-machine and balance metrics are of (``summary.json``'s
        ``layout``: kind, cylinders, counterweight, balance shafts)."""
        return dict(self.summary_json.get("layout") or {})

    def _numbered(self, pattern):
        """{train: {k: {quantity: array}}} of the per-step columns ``pattern`` matches (its
        groups: the number k, the quantity), k from 1 as in the column names."""
        found = {}
        for label in self.labels:
            by_k = {}
            for column, values in self.steps(label).items():
                match = pattern.fullmatch(column)
                if match:
                    by_k.setdefault(int(match.group(1)), {})[match.group(2)] = values
            found[label] = dict(sorted(by_k.items()))
        return found

    @property
    def cylinders(self):
        """Each cylinder's per-step loads, by crank train: {train: {k: {quantity: array}}}, k
        from 1 as in ``[layout]``, the quantities those of the columns
        ``cylinder_<k>_<quantity>`` (``crank_pin_force_x_n``, ``crank_pin_force_y_n``: its rod's
        load on its crank pin in the machine frame; ``gas_force_n`` with a gas model: the gas
        force on its piston at its own firing phase), rows as ``steps(train)``'s."""
        return self._numbered(_CYLINDER)

    @property
    def main_bearings(self):
        """Each main journal's per-step load on the crankshaft from the frame, by crank train:
        {train: {k: {"force_x_n": array, "force_y_n": array}}}, k from 1 along the crank axis
        (the columns ``main_bearing_<k>_force_x_n``/``_y_n``, machine frame)."""
        return self._numbered(_MAIN_BEARING)

    def plot(self):
        """The engineer's charts of what the run holds, as matplotlib figures by name (not
        shown; ``fig.savefig(...)`` or a notebook shows them): ``"torque"`` (each crank train's
        drive torque over crank angle, and the whole machine's where it has several cylinders),
        ``"pv"`` with a gas model (cylinder pressure over piston travel from top dead centre,
        the pv diagram's shape: V = V_c + A·travel), ``"main_bearing"`` (the polar load diagram
        of each main journal), ``"crank_speed"`` for a solved (dynamic) motion. Needs the
        per-step columns (``run(case, steps=True)``) and matplotlib."""
        return _plot(self)

    def _repr_html_(self):
        """The summary table: a row per metric, a column per crank train, and the unit."""
        rows = []
        for metric, unit in _metric_units(self.units).items():
            cells = "".join(
                f"<td>{_number(self.summary[label].get(metric))}</td>" for label in self.labels
            )
            rows.append(
                f"<tr><th>{html.escape(metric)}</th>{cells}<td>{html.escape(unit)}</td></tr>"
            )
        head = "".join(f"<th>{html.escape(label)}</th>" for label in self.labels)
        warnings = "".join(f"<li>{html.escape(w)}</li>" for w in self.warnings)
        return (
            f"<div><b>{html.escape(str(self.summary_json.get('case')))}</b>"
            + (f"<ul>{warnings}</ul>" if warnings else "")
            + f"<table><thead><tr><th>metric</th>{head}<th>unit</th></tr></thead>"
            + f"<tbody>{''.join(rows)}</tbody></table></div>"
        )

    def __repr__(self):
        return f"<cardan.Result {self.summary_json.get('case')!r}: {', '.join(self.labels)}>"


def run(case, steps=True):
    """Runs ``case`` (a path, TOML text or a dict in the case-file schema) in memory and
    returns its ``Result``; ``steps=False`` keeps no per-step columns (the run then shares its
    steps among the threads, and its memory does not grow with them)."""
    summary_json, trains = _cardan.run(case, steps)
    return Result(summary_json, trains)


def optimize(case, **spec):
    """Optimises each mechanism of ``case`` (a path, TOML text or a dict) on its own: the
    case's ``[optimize]`` table, its entries replaced by ``spec`` (``objective``, ``sense``,
    ``variables``, ``constraints``, ``starts``, ``seed``, ``max_evaluations``, ``tolerance``;
    docs/optimisation.md). Returns ``(optima, report)``: each mechanism's ``optimum.json`` as a
    dict (variables, objective, constraints with their margins, evaluations, stopping reason),
    and the report comparing the mechanisms at their optima (Markdown)::

        optima, report = cardan.optimize("pump.toml", objective="machine_mechanical_efficiency",
            sense="max", variables={"geometry.rod_length": ["100 mm", "300 mm"]})
        optima["cardan_gear"]["objective"]["value"]
    """
    return _cardan.optimize(case, spec or None)


def gear(pair):
    """Rates a spur gear pair given as ``cardan gear``'s gear file (a path, TOML text or a dict;
    docs/gear-calculator.md): its ``gear.json`` as a dict, with ``failures`` (why the pair
    cannot work; empty if it works) and ``warnings``."""
    return _cardan.gear(pair)
