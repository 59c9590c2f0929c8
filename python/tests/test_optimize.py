"""``cardan.optimize``: the closed-form kinematic optimum of runner/tests/optimize.rs found
from Python, arguments replacing the case's ``[optimize]`` entries, bad input raising
``CaseError`` naming the field."""

import pytest

import cardan

CASE = {
    "name": "kinematic",
    "machine": "pump",
    "mechanisms": ["slider_crank"],
    "geometry": {"crank_length": "50 mm", "rod_length": "200 mm", "bore": "80 mm"},
    "motion": {
        "start_angle": "0 deg",
        "end_angle": "360 deg",
        "initial_speed": "100 rad/s",
        "angular_acceleration": 0,
        "steps": 360,
    },
}


def test_the_closed_form_optimum_is_found():
    # Peak piston acceleration r·ω²·(1 + r/l), minimised with (r/l)·ω >= 20 rad/s: l* = 5r =
    # 250 mm, a* = 600 m/s² (runner/tests/optimize.rs states the derivation and tolerances).
    optima, report = cardan.optimize(
        CASE,
        objective="piston_acceleration_max",
        sense="min",
        variables={"geometry.rod_length": ["150 mm", "400 mm"]},
        constraints=["rod_angular_velocity_max >= 20 rad/s"],
    )
    best = optima["slider_crank"]
    assert best["feasible"]
    assert abs(best["variables"][0]["value"] - 250.0) < 0.1
    assert abs(best["objective"]["value"] - 600.0) < 0.05
    assert best["constraints"][0]["active"]
    assert "slider_crank" in report


def test_bad_input_names_the_field():
    with pytest.raises(cardan.CaseError, match="optimize.variables"):
        cardan.optimize(
            CASE,
            objective="piston_acceleration_max",
            sense="min",
            variables={"geometry.rod_length": ["400 mm", "150 mm"]},
        )
    with pytest.raises(cardan.CaseError, match="no \\[optimize\\]"):
        cardan.optimize(CASE)
