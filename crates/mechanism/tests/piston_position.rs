//! The piston-only path (used for cylinder volumes) agrees with the full state of every
//! mechanism, offsets included: the same formulas, so to round-off.

use cardan_mechanism::{CardanGear, CrankState, Mechanism, SliderCrank};

#[test]
fn piston_position_is_the_state_s() {
    let machines: [Box<dyn Mechanism>; 4] = [
        Box::new(SliderCrank::new(0.06, 0.14, 0.0, 0.07).unwrap()),
        Box::new(SliderCrank::new(0.06, 0.14, 0.015, 0.07).unwrap()),
        Box::new(SliderCrank::new(0.026, 0.09, -0.01, 0.0).unwrap()),
        Box::new(CardanGear::equivalent_to_slider_crank(0.06, 0.14, 0.07).unwrap()),
    ];
    for m in &machines {
        for k in 0..=1000 {
            let theta = -7.0 + 0.0173 * k as f64;
            let p = m.state(CrankState::new(theta, 1.0, 0.0, 0.0)).piston;
            let (x, dx) = m.piston_position(theta);
            assert!(
                (x - p.position).abs() <= 1e-15 * p.position.abs(),
                "θ = {theta}: x {x} vs {}",
                p.position
            );
            assert!(
                (dx - p.dx_dtheta).abs() <= 1e-15,
                "θ = {theta}: dx/dθ {dx} vs {}",
                p.dx_dtheta
            );
        }
    }
}
