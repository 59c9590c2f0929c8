"""The rod length that maximises the cardan gear's advantage over the slider-crank, in mechanical
efficiency, at a given crank speed: scipy.optimize.minimize_scalar (bounded) over the rod length,
each evaluation a case run in memory (summary only). The case is Karhula's (2008) air pump with
the thesis's loss models (see efficiency_map.py).

    python optimise_rod.py [SPEED_RAD_S]
"""

import copy
import sys

import cardan
from efficiency_map import CASE


def advantage(rod_length, speed):
    """Cardan gear efficiency minus the slider-crank's at `speed` (rad/s), rod `rod_length` (m)."""
    case = copy.deepcopy(CASE)
    case["geometry"]["rod_length"] = float(rod_length)
    case["motion"]["initial_speed"] = float(speed)
    s = cardan.run(case, steps=False).summary
    return s["cardan_gear"]["mechanical_efficiency"] - s["slider_crank"]["mechanical_efficiency"]


def main(speed=600.0):
    speed = float(speed)
    bounds = (0.13, 0.40)  # m: from just over twice the crank to a long rod
    try:
        from scipy.optimize import minimize_scalar
    except ImportError:
        print("scipy is not installed: a grid search instead")
        rods = [bounds[0] + k * (bounds[1] - bounds[0]) / 40 for k in range(41)]
        best = max(rods, key=lambda r: advantage(r, speed))
        print(f"at {speed} rad/s the advantage is largest at l = {best * 1000:.1f} mm")
        return best
    found = minimize_scalar(
        lambda r: -advantage(r, speed), bounds=bounds, method="bounded", options={"xatol": 1e-4}
    )
    print(
        f"at {speed} rad/s the cardan gear's advantage is largest at l = {found.x * 1000:.1f} mm: "
        f"{-100 * found.fun:.3f} percentage points ({found.nfev} runs)"
    )
    return found.x


if __name__ == "__main__":
    main(*sys.argv[1:])
