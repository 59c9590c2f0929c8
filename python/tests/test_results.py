"""``Result``'s notebook side: ``machine``, ``cylinders``, ``main_bearings``, ``plot()`` (with
matplotlib's Agg backend) and ``_repr_html_``. Cross-checks that need no command line: a machine
of one cylinder has the cylinder's own figures (docs/results.md, "The whole machine"), a
machine of N throws has N + 1 main journals, the charts draw the run's own columns."""

import io
import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np
import pytest

import cardan

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CONFIGS = os.path.join(ROOT, "configs")
NO_GAS = os.path.join(CONFIGS, "karhula-r60-l140-a0-w200pi.toml")
PUMP = os.path.join(CONFIGS, "karhula-pump-r60-l140-a0-w30pi.toml")
INLINE3 = os.path.join(CONFIGS, "karhula-pump-inline3-motor-dynamic.toml")


@pytest.fixture(scope="module")
def pump():
    return cardan.run(PUMP)


@pytest.fixture(scope="module")
def inline3():
    return cardan.run(INLINE3)


def test_machine_holds_the_whole_machine_metrics(pump):
    for label, metrics in pump.machine.items():
        expected = {k: v for k, v in pump.summary[label].items() if k.startswith("machine_")}
        assert metrics == expected and "machine_torque_mean" in metrics
    assert pump.layout["cylinders"] == 1


def test_one_cylinder_is_its_own_machine(pump):
    # docs/results.md: a machine of one cylinder has the cylinder's figures bit for bit.
    for label in pump.labels:
        steps = pump.steps(label)
        (k, cylinder), = pump.cylinders[label].items()
        assert k == 1
        np.testing.assert_array_equal(cylinder["gas_force_n"], steps["gas_force_n"])
        assert set(cylinder) == {"crank_pin_force_x_n", "crank_pin_force_y_n", "gas_force_n"}
        assert list(pump.main_bearings[label]) == [1]


def test_cylinders_and_journals_of_an_inline_three(inline3):
    assert inline3.layout["cylinders"] == 3
    for label in inline3.labels:
        steps = inline3.steps(label)
        cylinders = inline3.cylinders[label]
        assert list(cylinders) == [1, 2, 3]
        for k, columns in cylinders.items():
            for quantity, values in columns.items():
                assert values is steps[f"cylinder_{k}_{quantity}"] or np.array_equal(
                    values, steps[f"cylinder_{k}_{quantity}"]
                )
        # Three throws in three planes: a journal each side of every throw.
        assert list(inline3.main_bearings[label]) == [1, 2, 3, 4]
        assert set(inline3.main_bearings[label][4]) == {"force_x_n", "force_y_n"}


def test_no_steps_no_cylinders():
    result = cardan.run(NO_GAS, steps=False)
    with pytest.raises(ValueError, match="steps=False"):
        result.cylinders
    with pytest.raises(ValueError, match="steps=False"):
        result.plot()
    assert result.machine  # the summary's, no steps needed


def lines(fig):
    """The figure's data lines (not the zero line, whose label matplotlib starts with "_")."""
    return [l for ax in fig.axes for l in ax.get_lines() if not l.get_label().startswith("_")]


def test_plots_draw_the_runs_columns(pump):
    pytest.importorskip("matplotlib")
    figures = pump.plot()
    assert set(figures) == {"torque", "pv", "main_bearing"}  # a gas model, constant speed
    torque = lines(figures["torque"])
    assert len(torque) == len(pump.labels)
    for line, label in zip(torque, pump.labels):
        steps = pump.steps(label)
        np.testing.assert_array_equal(line.get_xdata(), steps["crank_angle_deg"])
        np.testing.assert_array_equal(line.get_ydata(), steps["total_torque_nm"])
    # The pv chart: pressure in bar over travel from top dead centre, 0 ... stroke.
    pv = lines(figures["pv"])
    assert len(pv) == len(pump.labels)
    for line, label in zip(pv, pump.labels):
        travel = np.asarray(line.get_xdata())
        stroke = pump.summary[label]["piston_stroke"] * 1e3
        assert travel.min() == 0.0 and travel.max() == pytest.approx(stroke, rel=1e-9)
        np.testing.assert_array_equal(
            line.get_ydata(), pump.steps(label)["cylinder_pressure_pa"] / 1e5
        )
    # The polar load: angle and magnitude of the journal's load.
    for ax, label in zip(figures["main_bearing"].axes, pump.labels):
        (line,) = ax.get_lines()
        force = pump.main_bearings[label][1]
        magnitude = np.hypot(force["force_x_n"], force["force_y_n"]) / 1e3
        np.testing.assert_array_equal(line.get_ydata(), magnitude)
    for fig in figures.values():
        fig.savefig(io.BytesIO(), format="png")


def test_plots_of_a_dynamic_machine(inline3):
    pytest.importorskip("matplotlib")
    figures = inline3.plot()
    assert {"torque", "pv", "main_bearing", "crank_speed"} <= set(figures)
    # The whole machine's torque beside each train's, for several cylinders.
    torque = lines(figures["torque"])
    assert len(torque) == 2 * len(inline3.labels)
    np.testing.assert_array_equal(
        torque[-1].get_ydata(), inline3.steps(inline3.labels[-1])["machine_torque_nm"]
    )
    speed = lines(figures["crank_speed"])
    for line, label in zip(speed, inline3.labels):
        rpm = inline3.steps(label)["crank_speed_rad_s"] * 30.0 / np.pi
        np.testing.assert_allclose(line.get_ydata(), rpm, rtol=1e-15)
    assert len(lines(figures["main_bearing"])) == 4 * len(inline3.labels)


def test_no_gas_no_pv():
    pytest.importorskip("matplotlib")
    figures = cardan.run(NO_GAS).plot()
    assert "pv" not in figures and "crank_speed" not in figures
    (line, *_) = lines(figures["torque"])
    assert line.get_label().endswith("(inertial_torque_nm)")


def test_the_notebook_shows_the_summary_table(pump):
    page = pump._repr_html_()
    assert page.count("<tr>") == 1 + len({m for s in pump.summary.values() for m in s})
    label = pump.labels[0]
    value = pump.summary[label]["piston_stroke"]
    assert f"<th>piston_stroke</th><td>{value:.6g}</td>" in page
    for label in pump.labels:
        assert f"<th>{label}</th>" in page


@pytest.mark.parametrize("case", [PUMP, os.path.join(CONFIGS, "balance-inline3.toml"), INLINE3])
def test_the_machine_peaks_are_the_peaks_of_the_cylinders_and_journals(case):
    # docs/results.md: machine_crank_pin_force_max is the largest load over the run on any
    # crank pin (one rod to a pin in these inline machines), machine_main_bearing_force_max
    # the largest on any main journal: the peaks of the per-step columns, every step being a
    # row here (no decimation). 1e-12 relative: numpy's hypot against Rust's, a few ulps.
    result = cardan.run(case)
    for label in result.labels:
        pins = max(
            np.hypot(c["crank_pin_force_x_n"], c["crank_pin_force_y_n"]).max()
            for c in result.cylinders[label].values()
        )
        journals = max(
            np.hypot(j["force_x_n"], j["force_y_n"]).max()
            for j in result.main_bearings[label].values()
        )
        machine = result.machine[label]
        assert pins == pytest.approx(machine["machine_crank_pin_force_max"], rel=1e-12)
        assert journals == pytest.approx(machine["machine_main_bearing_force_max"], rel=1e-12)
