"""``cardan.sweep``: a case run at every point of a sweep, as the table of ``sweep.csv``, its
swept fields as numbers in SI and every column's unit at hand."""

import functools

from . import _cardan
from ._cardan import RunError

ERRORS = ("raise", "nan")


class SweepTable(dict):
    """A sweep's table as {column: numpy array} (``as_pandas=False``), in the order of
    ``sweep.csv``'s columns, with ``units`` ({column: SI unit}) and ``written`` ({swept field:
    its values as written}): what a DataFrame's ``attrs`` hold."""

    def __init__(self, *args, units=None, written=None, **columns):
        super().__init__(*args, **columns)
        #: {column: unit}: every swept field of a unit (SI) and every metric.
        self.units = dict(units or {})
        #: {swept field: [value as written]}, as ``sweep.csv`` holds them.
        self.written = dict(written or {})


@functools.lru_cache(maxsize=1)
def _schema():
    return _cardan.case_schema()


def _resolve(node):
    """``node`` with its ``$ref`` (to the schema's ``$defs``) followed."""
    while isinstance(node, dict) and "$ref" in node:
        node = _schema()["$defs"][node["$ref"].rsplit("/", 1)[1]]
    return node


def _members(node):
    """``node`` and, depth first, the members of its ``allOf``, ``anyOf`` and ``oneOf``."""
    node = _resolve(node)
    if not isinstance(node, dict):
        return
    yield node
    for key in ("allOf", "anyOf", "oneOf"):
        for member in node.get(key, []):
            yield from _members(member)


def field_schema(path):
    """The schema of the case-file field at the dotted ``path`` (``"geometry.rod_length"``), or
    None where the schema does not tell (a mechanism's own table, a field that is not there)."""
    node = _schema()
    for part in path.split("."):
        found = None
        for member in _members(node):
            if part in member.get("properties", {}):
                found = member["properties"][part]
                break
        if found is None:
            return None
        node = found
    return node


def field_unit(path):
    """The unit of a bare number of the field at ``path`` (its schema's ``x-unit``): None for a
    field of no unit (a count, a ratio, a word) or one the schema does not tell."""
    node = field_schema(path)
    if node is None:
        return None
    for member in _members(node):
        if "x-unit" in member:
            return member["x-unit"]
    return None


def _number(text):
    try:
        return float(text)
    except ValueError:
        return None


def si_column(path, written):
    """The values ``written`` of the swept field ``path`` as (float64 array in SI, SI unit), or
    None where they are not numbers: a field of a unit takes its values as the case file does
    (``"6 bar"`` is 600000 Pa; a bare number in the field's unit: 30 of an angle is 30°, 0.5236
    rad), a value it would refuse NaN (that point failed); a field of no unit (a count, a ratio,
    a coefficient in the unit its name says), its values if all are numbers, unit None."""
    import numpy as np

    unit = field_unit(path)
    if unit is None:
        numbers = [_number(v) for v in written]
        if any(x is None for x in numbers):
            return None
        return np.array(numbers, dtype=np.float64), None
    values, si_unit = [], None
    for text in written:
        x = _number(text)
        try:
            value, si_unit = _cardan.quantity(text if x is None else x, unit)
        except ValueError:
            value = float("nan")
        values.append(value)
    if si_unit is None:
        return None  # no value converts: not a quantity after all (a list of them)
    return np.array(values, dtype=np.float64), si_unit


def sweep(case, fields=None, mode="grid", as_pandas=None, errors="raise"):
    """Runs ``case`` at every point of ``fields`` ({dotted path: list of values, or {"from",
    "to", "points", "scale"}}, as a case file's ``[sweep]``; values may carry units, "120 mm")
    in ``mode`` "grid" (every combination) or "zip", the points in parallel; without
    ``fields``, the case's own ``[sweep]``.

    Returns the table of ``sweep.csv``: ``case`` (each point's name), each swept field, then
    ``<train>.<metric>`` for every metric (SI). A swept field of numbers is a float64 column in
    SI whatever units its values were written in ("6 bar" -> 600000.0); a field of other values
    (a word, a list) keeps them as written. The units (of every swept field of a unit, in SI,
    and of every metric) are in ``attrs["units"]`` of a DataFrame (``units`` of the dict), the swept values
    as written in ``attrs["written"]`` (``written``). A DataFrame when ``as_pandas`` (default:
    when pandas is installed), else a ``SweepTable`` (a dict of numpy arrays).

    ``errors="raise"``: a point that does not validate raises ``CaseError`` before any point
    runs, a point that fails running raises ``RunError`` naming it. ``errors="nan"``: either
    point has NaN metrics and its message in an ``error`` column; the others run.
    """
    import numpy as np

    if errors not in ERRORS:
        raise ValueError(f"errors={errors!r}: must be one of {ERRORS}")
    names, swept, metrics, units, failures = _cardan.sweep(case, fields, mode, errors == "nan")
    failed = [f for f in failures if f is not None]
    if failed and errors == "raise":
        raise RunError(f"{len(failed)} of {len(names)} points failed:\n  " + "\n  ".join(failed))
    table = SweepTable(case=np.array(names, dtype=object))
    for path, written in swept:
        table.written[path] = list(written)
        column = si_column(path, written)
        if column is None:
            table[path] = np.array(written, dtype=object)
        else:
            table[path], unit = column
            if unit is not None:
                table.units[path] = unit
    table.update(metrics)
    table.units.update(units)
    if failed:
        table["error"] = np.array([f or "" for f in failures], dtype=object)
    if as_pandas is None:
        try:
            import pandas  # noqa: F401
        except ImportError:
            as_pandas = False
        else:
            as_pandas = True
    if not as_pandas:
        return table
    import pandas as pd

    frame = pd.DataFrame(dict(table))
    frame.attrs["units"] = dict(table.units)
    frame.attrs["written"] = dict(table.written)
    return frame
