//! The machine motion (Petrescu 2015, docs/validation/machine-motion.md): the reduced inertia
//! of every registered mechanism against the kinetic energy, a finite difference and the
//! inertial drive torque.

mod common;
use cardan_dynamics::{kinetic_energy, ReducedInertiaOf};
use cardan_mechanism::{CrankState, Loads};
use common::*;

/// T = ½·J*·ω² at any speed and acceleration (the kinetic energy of the state's bodies);
/// dJ*/dθ is the central difference of J* to its truncation error; the pistons' lever is
/// Σ dx/dθ; and the inertial drive torque of the closed forms is J*·α + ½·dJ*/dθ·ω²
/// (Petrescu eq. 5), for every registered mechanism and reading.
#[test]
fn reduced_inertia_is_the_kinetic_energy_and_the_inertial_torque() {
    for (name, m) in every_machine() {
        let t = m.topology();
        let mut j = ReducedInertiaOf::new(m.as_ref());
        let mut largest = 0.0_f64;
        for k in 0..97 {
            let theta = 0.3 + k as f64 * 0.0654;
            let r = j.at(theta);
            assert!(r.inertia > 0.0, "{name}: J* = {}", r.inertia);
            largest = largest.max(r.inertia);
            for (w, a) in [(10.0, 0.0), (157.0, -300.0), (0.5, 4000.0)] {
                let s = m.state(&CrankState::new(theta, w, a, 0.0));
                let ke = kinetic_energy(t, &s);
                let expected = 0.5 * r.inertia * w * w;
                assert!(
                    (ke - expected).abs() <= 1e-12 * expected,
                    "{name} at {theta}: T = {ke}, ½J*ω² = {expected}"
                );
                let lever: f64 = s.pistons.iter().map(|p| p.dx_dtheta).sum();
                assert!((lever - r.piston_lever).abs() <= 1e-12 * lever.abs().max(1e-3));
                let mut loads = Loads::for_topology(t);
                if !m.closed_form_loads(&s, true, &[], &mut loads) {
                    cardan_dynamics::planar::loads(t, &s, true, &[], &mut loads);
                }
                let torque = r.inertia * a + 0.5 * r.derivative * w * w;
                let scale = r.inertia * a.abs() + r.derivative.abs() * w * w + 1e-9;
                assert!(
                    (loads.crank_torque - torque).abs() <= 1e-9 * scale,
                    "{name} at {theta}, ω {w}, α {a}: inertial torque {} against J*α + ½J*'ω² {torque}",
                    loads.crank_torque
                );
            }
            // Central difference, error h²/6·J*''' : below 1e-6 of J* at h = 1e-4.
            let h = 1e-4;
            let fd = (j.at(theta + h).inertia - j.at(theta - h).inertia) / (2.0 * h);
            assert!(
                (fd - r.derivative).abs() <= 1e-6 * r.inertia,
                "{name} at {theta}: dJ*/dθ {} against the difference {fd}",
                r.derivative
            );
        }
        assert!(largest > 0.0);
    }
}
