"""Where is the cardan gear the more efficient pump? Karhula's (2008) air pump (crank 60 mm, bore
120 mm, the thesis's loss models) over crank speed x rod length: the mechanical efficiency of
both mechanisms and their difference, as a heat map (matplotlib, optional: without it the table
is printed). The case is a dict in the case-file schema (configs/sweeps/karhula-pump-map-speed-rod.toml
is the same case as a file).

    python efficiency_map.py [OUT.png]
"""

import sys

import numpy as np

import cardan

CASE = {
    "name": "karhula-pump-map",
    "machine": "pump",
    "mechanisms": ["slider_crank", "cardan_gear"],
    "geometry": {"crank_length": 0.06, "rod_length": 0.14, "bore": 0.12},
    "motion": {
        "start_angle": 90.0,
        "end_angle": 810.0,
        "initial_speed": 30.0,
        "angular_acceleration": 0.0,
        "steps": 720,
    },
    "gas": {"model": "karhula_pump", "compression_ratio": 12, "polytropic_exponent": 1.4, "filling": 1.07},
    "friction": {},
}


def main(out="efficiency-map.png"):
    speeds = np.geomspace(10.0, 600.0, 8)  # rad/s
    rods = np.linspace(0.14, 0.30, 6)  # m
    table = cardan.sweep(
        CASE,
        {"motion.initial_speed": list(speeds), "geometry.rod_length": list(rods)},
        as_pandas=False,
    )
    # Grid mode: the first field varies fastest.
    shape = (len(rods), len(speeds))
    assert (table["motion.initial_speed"].reshape(shape) == speeds).all()
    cardan_eff = table["cardan_gear.mechanical_efficiency"].reshape(shape).T
    slider_eff = table["slider_crank.mechanical_efficiency"].reshape(shape).T
    advantage = cardan_eff - slider_eff
    print("cardan gear efficiency minus the slider-crank's, percentage points")
    print("speed rad/s | " + " ".join(f"l={r * 1000:5.0f}mm" for r in rods))
    for w, row in zip(speeds, advantage):
        print(f"{w:11.1f} | " + " ".join(f"{100 * a:9.2f}" for a in row))
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no plot")
        return
    fig, axes = plt.subplots(1, 3, figsize=(14, 4), constrained_layout=True)
    for ax, (title, z) in zip(
        axes,
        [
            ("slider-crank efficiency", slider_eff),
            ("cardan gear efficiency", cardan_eff),
            ("cardan minus slider-crank", advantage),
        ],
    ):
        mesh = ax.pcolormesh(rods * 1000, speeds, z, shading="nearest")
        ax.set_yscale("log")
        ax.set_xlabel("rod length, mm")
        ax.set_ylabel("crank speed, rad/s")
        ax.set_title(title)
        fig.colorbar(mesh, ax=ax)
    axes[2].contour(rods * 1000, speeds, advantage, levels=[0.0], colors="k")
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:])
