"""``cardan.sweep``: swept fields in SI whatever their units, every column's unit, a point that
does not validate or fails running kept as a row of NaN with ``errors="nan"``. No command line
needed: every expected value is a closed-form unit conversion or the run of the point's own
case."""

import json
import math
import os
import sys

import numpy as np
import pytest

import cardan

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "configs", "karhula-r60-l140-a0-w200pi.toml")

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    tomllib = pytest.importorskip("tomli")


def small_case():
    with open(CASE, "rb") as f:
        case = tomllib.load(f)
    case["motion"]["steps"] = 360
    return case


def run_point(case, **fields):
    point = json.loads(json.dumps(case))
    for path, value in fields.items():
        table, key = path.split(".")
        point[table][key] = value
    return cardan.run(point, steps=False).summary


def test_the_version_is_the_packages():
    from importlib.metadata import version

    assert cardan.__version__ == version("cardan")
    assert cardan.__version__.count(".") >= 2


def test_swept_values_with_units_are_numbers_in_si():
    table = cardan.sweep(
        small_case(),
        {"geometry.rod_length": ["140 mm", "20 cm"], "motion.initial_speed": ["600 rpm", 100.0]},
        as_pandas=False,
    )
    # 1 mm = 1e-3 m, 1 cm = 1e-2 m, 1 rpm = 2π/60 rad/s (bare speeds are rad/s); grid order,
    # the first field fastest. One rounding of the product: 1e-15 relative.
    rod, speed = table["geometry.rod_length"], table["motion.initial_speed"]
    assert rod.dtype == np.float64 and speed.dtype == np.float64
    np.testing.assert_allclose(rod, [0.14, 0.2, 0.14, 0.2], rtol=1e-15)
    np.testing.assert_allclose(speed, [20 * math.pi] * 2 + [100.0] * 2, rtol=1e-15)
    assert table.units["geometry.rod_length"] == "m"
    assert table.units["motion.initial_speed"] == "rad/s"
    assert table.written["geometry.rod_length"] == ["140 mm", "20 cm", "140 mm", "20 cm"]
    assert table.written["motion.initial_speed"] == ["600 rpm", "600 rpm", "100.0", "100.0"]
    # The metrics' units are the summary's.
    assert table.units["cardan_gear.piston_velocity_max"] == "m/s"
    assert table.units["slider_crank.piston_stroke"] == "m"
    # A point is the run of its case written in SI.
    summary = run_point(small_case(), **{"geometry.rod_length": 0.2, "motion.initial_speed": 100.0})
    assert table["slider_crank.piston_velocity_max"][3] == summary["slider_crank"]["piston_velocity_max"]


def test_angles_pressures_and_words():
    case = small_case()
    table = cardan.sweep(
        case,
        {"motion.start_angle": [90.0, "1.5 rad"], "motion.mode": ["prescribed", "prescribed"]},
        mode="zip",
        as_pandas=False,
    )
    # A bare angle is in degrees (the case files' rule): 90° = π/2 rad.
    np.testing.assert_allclose(table["motion.start_angle"], [math.pi / 2, 1.5], rtol=1e-15)
    assert table.units["motion.start_angle"] == "rad"
    # A word stays as written, with no unit.
    assert list(table["motion.mode"]) == ["prescribed"] * 2 and "motion.mode" not in table.units


def test_units_in_the_frames_attributes():
    pytest.importorskip("pandas")
    frame = cardan.sweep(small_case(), {"geometry.rod_length": ["140 mm", "0.2 m"]})
    assert frame.attrs["units"]["geometry.rod_length"] == "m"
    assert frame.attrs["written"]["geometry.rod_length"] == ["140 mm", "0.2 m"]
    assert frame["geometry.rod_length"].dtype == np.float64


INFEASIBLE = {"geometry.rod_length": [0.14, 0.05, 0.2]}  # 50 mm: shorter than the 60 mm crank


def test_a_point_that_does_not_validate_raises_case_error_by_default():
    with pytest.raises(cardan.CaseError, match="geometry.rod_length"):
        cardan.sweep(small_case(), INFEASIBLE, as_pandas=False)


def test_a_point_that_does_not_validate_is_a_row_of_nan_with_errors_nan():
    case = small_case()
    table = cardan.sweep(case, INFEASIBLE, as_pandas=False, errors="nan")
    assert len(table["case"]) == 3
    assert table["error"][0] == "" and table["error"][2] == ""
    assert "geometry.rod_length" in table["error"][1] and "crank" in table["error"][1]
    np.testing.assert_array_equal(table["geometry.rod_length"], [0.14, 0.05, 0.2])
    metrics = [c for c in table if "." in c and c not in INFEASIBLE]
    assert metrics
    for column in metrics:
        assert math.isnan(table[column][1]), column
    # The other points are their own runs, bit for bit.
    for k, rod in [(0, 0.14), (2, 0.2)]:
        summary = run_point(case, **{"geometry.rod_length": rod})
        for train, values in summary.items():
            for metric, value in values.items():
                assert table[f"{train}.{metric}"][k] == value, (k, train, metric)


def test_every_point_failing_is_still_a_table():
    table = cardan.sweep(
        small_case(), {"geometry.rod_length": [0.01, 0.02]}, as_pandas=False, errors="nan"
    )
    assert list(table["error"] != "") == [True, True]
    assert list(table["case"]) == [
        "karhula-r60-l140-a0-w200pi-rod_length-0.01",
        "karhula-r60-l140-a0-w200pi-rod_length-0.02",
    ]


def test_an_unknown_errors_mode_is_refused():
    with pytest.raises(ValueError, match="errors='ignore'"):
        cardan.sweep(small_case(), {"geometry.rod_length": [0.14]}, errors="ignore")
