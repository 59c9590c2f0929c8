"""The Python package against the command line: every shipped case's summary equals the
``summary.json`` that ``cardan run`` wrote, bit for bit; the per-step columns equal the CSV's;
a sweep's table equals ``sweep.csv``; bad input raises ``CaseError`` naming the field.

The command line's outputs: ``$CARDAN_CLI_OUT`` where it is set (.ci/run sets it to the folder of
``cargo xtask run configs``; a case missing there fails the test), else the tests make them
with the ``cardan`` binary (``$CARDAN_BIN``, else ``target/release/cardan`` or
``target/debug/cardan`` of this checkout, else ``cardan`` on the PATH; it must be built from this
checkout), running each case they compare into a temporary folder; without either they skip,
saying so. The package's own behaviour is tested with no command line at all.
"""

import csv
import glob
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import cardan

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CONFIGS = os.path.join(ROOT, "configs")
CASE = os.path.join(CONFIGS, "karhula-r60-l140-a0-w200pi.toml")

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    tomllib = None


def cardan_binary():
    """The command line to compare with: $CARDAN_BIN, this checkout's built binary, or PATH's."""
    given = os.environ.get("CARDAN_BIN")
    if given:
        return given
    target = os.environ.get("CARGO_TARGET_DIR") or os.path.join(ROOT, "target")
    for profile in ("release", "debug"):
        path = os.path.join(target, profile, "cardan")
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return shutil.which("cardan")


@pytest.fixture(scope="session")
def cli_out(tmp_path_factory):
    """``cli_out(case_file)``: the output folder holding the command line's results of
    ``case_file`` (``<folder>/<case name>/``)."""
    out = os.environ.get("CARDAN_CLI_OUT")
    if out:
        assert os.path.isdir(out), (
            f"CARDAN_CLI_OUT={out!r} must name the output folder of `cargo xtask run configs`"
        )
        return lambda path: out
    binary = cardan_binary()
    if binary is None:
        pytest.skip(
            "no command-line outputs to compare with: set CARDAN_CLI_OUT to the output folder of "
            "`cargo xtask run configs`, or build the command line (`cargo build --release -p "
            "cardan`, or set CARDAN_BIN)"
        )
    folder = tmp_path_factory.mktemp("cli-out")
    made = set()

    def make(path):
        if path not in made:
            run = subprocess.run(
                [binary, "run", path, "--out", str(folder), "--quiet", "--no-report"],
                capture_output=True,
                text=True,
            )
            assert run.returncode == 0, f"{binary} run {path}: {run.stderr}"
            made.add(path)
        return str(folder)

    return make


def shipped_cases():
    # An optimisation (`[optimize]`: configs/optimize-thesis-pump.toml) writes no summary.json
    # of its own: its folder is `cardan.optimize`'s (docs/optimisation.md).
    return sorted(
        p
        for p in glob.glob(os.path.join(CONFIGS, "*.toml"))
        if "\n[optimize]" not in open(p, encoding="utf-8").read()
    )


def shipped_sweeps():
    return sorted(glob.glob(os.path.join(CONFIGS, "sweeps", "*.toml")))


def case_dict(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


@pytest.mark.parametrize("path", shipped_cases(), ids=os.path.basename)
def test_summary_is_the_command_lines_bit_for_bit(path, cli_out):
    name = case_dict(path)["name"]
    with open(os.path.join(cli_out(path), name, "summary.json")) as f:
        expected = json.load(f)
    # Summaries only: the run shared by the threads.
    result = cardan.run(path, steps=False)
    assert result.summary_json == expected
    # Every float equal as bits (== would pass 0.0 against -0.0).
    for label, metrics in expected["mechanisms"].items():
        for metric, value in metrics["metrics"].items():
            got = result.summary[label][metric]
            assert math.copysign(1.0, got) == math.copysign(1.0, value), (label, metric)


def test_a_dict_a_toml_text_and_a_path_give_the_same_run():
    with open(CASE) as f:
        text = f.read()
    by_path = cardan.run(CASE, steps=False).summary_json
    assert cardan.run(text, steps=False).summary_json == by_path
    assert cardan.run(case_dict(CASE), steps=False).summary_json == by_path


def test_steps_are_the_csv_columns_bit_for_bit(cli_out):
    result = cardan.run(CASE)
    name = case_dict(CASE)["name"]
    for label in result.labels:
        steps = result.steps(label)
        with open(os.path.join(cli_out(CASE), name, f"{label}.csv")) as f:
            rows = list(csv.reader(f))
        header, body = rows[0], rows[1:]
        assert list(steps) == header
        for k, column in enumerate(header):
            expected = np.array([float(r[k]) if r[k] else np.nan for r in body])
            np.testing.assert_array_equal(steps[column], expected, err_msg=column)
        assert steps["crank_angle_deg"].dtype == np.float64
        assert len(steps["crank_angle_deg"]) == 7201


def test_the_steps_summary_is_the_shared_runs():
    # Kept steps run on one thread, the summary alone on several: the same bits.
    assert cardan.run(CASE).summary_json == cardan.run(CASE, steps=False).summary_json


def test_units_and_pandas():
    result = cardan.run(CASE)
    assert result.units["cardan_gear"]["piston_velocity_max"] == "m/s"
    pd = pytest.importorskip("pandas")
    frame = result.to_pandas()
    assert frame.loc["piston_velocity_max", "unit"] == "m/s"
    assert frame.loc["piston_stroke", "slider_crank"] == result.summary["slider_crank"]["piston_stroke"]
    steps = result.to_pandas("slider_crank")
    assert isinstance(steps, pd.DataFrame) and len(steps) == 7201


@pytest.mark.parametrize("path", shipped_sweeps(), ids=os.path.basename)
def test_sweep_table_is_sweep_csv(path, cli_out):
    name = case_dict(path)["name"]
    with open(os.path.join(cli_out(path), name, "sweep.csv")) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    table = cardan.sweep(path, as_pandas=False)
    assert list(table) == header
    assert list(table["case"]) == [r[0] for r in body]
    swept = list(case_dict(path)["sweep"])
    for k, column in enumerate(header[1:], start=1):
        written = [r[k] for r in body]
        got = table[column]
        if column in swept:
            # The values as written, and the column in SI (tested in test_sweep.py).
            assert table.written[column] == written, column
            assert got.dtype == np.float64 and column in table.units, column
        elif got.dtype == object:
            assert list(got) == written, column
        else:
            expected = np.array([float(v) if v else np.nan for v in written])
            np.testing.assert_array_equal(got, expected, err_msg=column)


def test_a_sweep_point_is_the_run_of_its_case():
    base = case_dict(CASE)
    base["motion"]["steps"] = 720
    speeds, rods = [30.0, 300.0], [0.12, 0.16, 0.2]
    table = cardan.sweep(
        base, {"motion.initial_speed": speeds, "geometry.rod_length": rods}, as_pandas=False
    )
    assert len(table["case"]) == 6
    for k in range(6):
        point = json.loads(json.dumps(base))
        point["motion"]["initial_speed"] = table["motion.initial_speed"][k]
        point["geometry"]["rod_length"] = table["geometry.rod_length"][k]
        summary = cardan.run(point, steps=False).summary
        for train, metrics in summary.items():
            for metric, value in metrics.items():
                assert table[f"{train}.{metric}"][k] == value, (k, train, metric)
    assert sorted(set(table["geometry.rod_length"])) == rods


def test_a_case_with_a_sweep_is_refused_by_run():
    with pytest.raises(cardan.CaseError, match="cardan.sweep"):
        cardan.run(shipped_sweeps()[0])


def test_gear_is_the_published_example():
    # docs/validation/gears.md §2.1: Shigley's Example 14-4 (bending 6417 / 4854 psi,
    # SF 5.62 / 6.82), as crates/gear-file/tests/gear_file.rs checks the command's gear.json.
    path = os.path.join(ROOT, "configs-gears", "shigley-14-4.toml")
    rating = cardan.gear(path)
    assert rating["failures"] == []
    from_dict = cardan.gear(case_dict(path))
    assert from_dict.pop("file") == "<dict>"
    assert {k: v for k, v in rating.items() if k != "file"} == from_dict
    psi = 6894.757293168361

    def close(value, printed, half_unit):
        # The printed figure's rounding (half its last digit) plus 0.1 % for the example's
        # rounded intermediate factors: crates/gear-file/tests/gear_file.rs's tolerance.
        return abs(value - printed) <= half_unit + 1e-3 * abs(printed)

    for member, bending, sf in [("pinion", 6417.0, 5.62), ("gear", 4854.0, 6.82)]:
        m = rating["rating"][member]
        assert close(m["bending_stress"] / psi, bending, 0.5), member
        assert close(m["bending_safety_factor"], sf, 0.005), member


# Bad input: CaseError naming the field, as the command line says it.


def bad(edit):
    case = case_dict(CASE)
    edit(case)
    with pytest.raises(cardan.CaseError) as e:
        cardan.run(case)
    return str(e.value)


def test_an_unknown_key_names_the_nearest():
    def edit(c):
        c["geometry"]["rod_lenght"] = c["geometry"].pop("rod_length")

    message = bad(edit)
    assert "geometry.rod_lenght" in message and '"rod_length"' in message, message


def test_a_wrong_type_names_the_field():
    def edit(c):
        c["motion"]["steps"] = "many"

    message = bad(edit)
    assert "motion.steps" in message and "whole number" in message, message


def test_nan_names_the_field():
    def edit(c):
        c["geometry"]["rod_length"] = float("nan")

    message = bad(edit)
    assert "geometry.rod_length" in message and "finite" in message, message


def test_nan_in_a_swept_list_names_the_field():
    with pytest.raises(cardan.CaseError, match=r'sweep\."motion.initial_speed"\[1\]'):
        cardan.sweep(CASE, {"motion.initial_speed": [1.0, float("nan")]})


def test_an_object_that_is_no_value_names_the_field():
    def edit(c):
        c["geometry"]["bore"] = object()

    assert "geometry.bore" in bad(edit)


def test_a_missing_file_and_bad_toml():
    with pytest.raises(cardan.CaseError, match="cannot read"):
        cardan.run("no-such-case.toml")
    with pytest.raises(cardan.CaseError, match="line"):
        cardan.run("name = \n")


def test_the_messages_are_the_command_lines():
    # The same reader as files: the text after the file's label is the file's message.
    case = case_dict(CASE)
    case["geometry"]["rod_length"] = -1
    with pytest.raises(cardan.CaseError) as from_dict:
        cardan.run(case)
    with open(CASE) as f:
        text = f.read().replace("rod_length = 0.14", "rod_length = -1")
    with pytest.raises(cardan.CaseError) as from_text:
        cardan.run(text)
    assert str(from_dict.value).split(": ", 1)[1] == str(from_text.value).split(": ", 1)[1]


def test_a_panic_in_a_run_is_a_run_error_and_the_interpreter_goes_on():
    # A real panic inside a crank train's run (a rayon worker): the runner's test hook,
    # compiled only with the package's `test-hooks` feature, which .ci/run's wheel enables
    # (CARDAN_TEST_HOOKS=1 there: the test must not skip).
    from cardan import _cardan

    if not _cardan.TEST_HOOKS:
        assert not os.environ.get("CARDAN_TEST_HOOKS"), "the wheel was built without test-hooks"
        pytest.skip("a wheel built without the feature test-hooks")
    case = case_dict(CASE)
    case["name"] = _cardan.TEST_PANIC_CASE
    with pytest.raises(cardan.RunError, match="internal error .*deliberate panic"):
        cardan.run(case, steps=False)
    # Twice, and the interpreter and the package still work.
    with pytest.raises(cardan.RunError):
        cardan.run(case)
    assert cardan.run(CASE, steps=False).summary_json["case"] == case_dict(CASE)["name"]


def test_the_shipped_optimisation_is_the_command_lines(cli_out):
    # configs/optimize-thesis-pump.toml through cardan.optimize: each mechanism's optimum is the
    # command line's optimum.json, value for value (the same search from the same seed: the
    # starts run in parallel but each is deterministic, docs/optimisation.md).
    path = os.path.join(ROOT, "configs", "optimize-thesis-pump.toml")
    optima, report = cardan.optimize(path)
    folder = os.path.join(cli_out(path), "optimize-thesis-pump")
    assert sorted(optima) == sorted(
        d for d in os.listdir(folder) if os.path.isfile(os.path.join(folder, d, "optimum.json"))
    )
    for mechanism, got in optima.items():
        with open(os.path.join(folder, mechanism, "optimum.json"), encoding="utf-8") as f:
            want = json.load(f)
        assert got == want, mechanism
    assert "cardan_gear" in report and "slider_crank" in report
