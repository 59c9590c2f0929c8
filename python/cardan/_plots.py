"""``Result.plot()``: the engineer's charts of a run as matplotlib figures, made with
``matplotlib.figure.Figure`` (no pyplot: no window, no global figure list; any backend, Agg
included, can save them, and a notebook shows them)."""

import math

import numpy as np


def _figure(**kw):
    from matplotlib.figure import Figure

    return Figure(figsize=(7.0, 4.5), layout="constrained", **kw)


def _torque_column(steps):
    """The drive torque: gas and inertia together where there is gas (``total``), else the
    inertia's."""
    for column in ("total_torque_nm", "inertial_torque_nm"):
        if column in steps:
            return column
    return None


def _piston_position(steps):
    """The piston pin's position column (``{piston}_position_m``)."""
    return next((c for c in steps if c.endswith("_position_m")), None)


def torque(result):
    fig = _figure()
    ax = fig.add_subplot()
    for label in result.labels:
        steps = result.steps(label)
        column = _torque_column(steps)
        if column is not None:
            ax.plot(steps["crank_angle_deg"], steps[column], label=f"{label} ({column})")
    if result.layout.get("cylinders", 1) > 1:
        for label in result.labels:
            steps = result.steps(label)
            if "machine_torque_nm" in steps:
                ax.plot(
                    steps["crank_angle_deg"],
                    steps["machine_torque_nm"],
                    linestyle="--",
                    label=f"{label} (whole machine)",
                )
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    ax.set_xlabel("crank angle (deg)")
    ax.set_ylabel("drive torque (N·m)")
    ax.set_title(f"{result.summary_json.get('case')}: drive torque")
    ax.legend(fontsize="small")
    return fig


def pv(result):
    fig = _figure()
    ax = fig.add_subplot()
    drawn = False
    for label in result.labels:
        steps = result.steps(label)
        pressure, position = steps.get("cylinder_pressure_pa"), _piston_position(steps)
        if pressure is None or position is None or not np.isfinite(pressure).any():
            continue
        x = steps[position]
        ax.plot((np.nanmax(x) - x) * 1e3, pressure / 1e5, label=label)
        drawn = True
    if not drawn:
        return None
    ax.set_xlabel("piston travel from top dead centre (mm)")
    ax.set_ylabel("cylinder pressure, absolute (bar)")
    ax.set_title(f"{result.summary_json.get('case')}: p–V (V = V_c + A·travel)")
    ax.legend(fontsize="small")
    return fig


def main_bearing(result):
    bearings = {label: b for label, b in result.main_bearings.items() if b}
    if not bearings:
        return None
    fig = _figure()
    for n, (label, by_k) in enumerate(bearings.items(), start=1):
        ax = fig.add_subplot(1, len(bearings), n, projection="polar")
        for k, force in by_k.items():
            fx, fy = force["force_x_n"], force["force_y_n"]
            ax.plot(np.arctan2(fy, fx), np.hypot(fx, fy) / 1e3, label=f"journal {k}")
        ax.tick_params(axis="y", labelsize="x-small")
        ax.set_title(f"{label}: main bearing load (kN)", fontsize="medium")
        if len(by_k) > 1:
            ax.legend(fontsize="small")
    return fig


def crank_speed(result):
    dynamic = [label for label in result.labels if "speed_mean" in result.summary[label]]
    if not dynamic:
        return None
    fig = _figure()
    ax = fig.add_subplot()
    for label in dynamic:
        steps = result.steps(label)
        ax.plot(steps["crank_angle_deg"], steps["crank_speed_rad_s"] * 30.0 / math.pi, label=label)
    ax.set_xlabel("crank angle (deg)")
    ax.set_ylabel("crank speed (rpm)")
    ax.set_title(f"{result.summary_json.get('case')}: crank speed")
    ax.legend(fontsize="small")
    return fig


def plot(result):
    """{chart name: Figure} of the charts ``result`` holds (see ``Result.plot``)."""
    for label in result.labels:
        result.steps(label)  # raises if the run kept no per-step columns
    charts = {
        "torque": torque,
        "pv": pv,
        "main_bearing": main_bearing,
        "crank_speed": crank_speed,
    }
    figures = {}
    for name, chart in charts.items():
        fig = chart(result)
        if fig is not None:
            figures[name] = fig
    return figures
