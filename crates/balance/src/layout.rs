//! Multi-cylinder machines: each cylinder runs the same mechanism on one crankshaft; the
//! machine's shaking force is the sum of theirs, and their axial spread makes free moments.
//!
//! # Frames
//!
//! The machine frame: the crank axis is z (the crankshaft's, pointing so that the crank turns
//! counter-clockwise seen from +z), x and y across it; the machine's crank angle θ is that of a
//! reference throw from +x, as in one mechanism (Karhula 2008 ch. 4). Cylinder i:
//!
//! - its **throw** φ_i (rad): its crank throw's angle ahead of the reference throw, in the
//!   direction of rotation (the crankshaft's geometry, the same in every plane);
//! - its **axis angle** β_i (rad): its plane frame turned by β_i about the crank axis, so its
//!   cylinder lies along e^{iβ_i}·i (β = 0: along +y, as one mechanism's);
//! - its **axial position** z_i (m) along the crank axis.
//!
//! In its own frame the throw is at ψ_i = θ + φ_i − β_i: the cylinder's mechanism is evaluated
//! at ψ_i ([`Layout::cylinder_crank`]) and its force turned back by e^{iβ_i}. For an in-line
//! machine (β = 0) that is θ + φ_i. A **radial** engine has every cylinder's rod on the one
//! crank pin (φ_i = 0, β_i = 2π·i/n, z_i = 0): each cylinder is a whole mechanism of its own on
//! that pin (no master and articulated rods). A vee shares each pin between its banks
//! (β = ±half the bank angle).
//!
//! # Free moments
//!
//! A force F_i (planar, N) acting in the plane z_i has about the point of the crank axis at z₀
//! the moment (z_i − z₀)·ẑ × F_i = (z_i − z₀)·(−F_y, F_x): as a complex number
//! i·(z_i − z₀)·F_i. Its x part (about the horizontal axis across the crank: the **pitch**) and
//! y part (about the vertical: the **yaw**) are the free moments; the moment about the crank
//! axis (roll) is the reaction of the torque and not part of them. z₀ is midway between the
//! outermost cylinders (issue 24): the free moment of a machine whose forces cancel does not
//! depend on it (`docs/validation/balance.md`, free moments).

use crate::counterweight::Rotor;
use crate::harmonics::{orders_of, revolution_states, zero_orders, Order};
use crate::shaking::{shaking, shaking_lane, Shaking};
use cardan_mechanism::{CrankState, Mechanism, StateBlock, C, LANES};
use std::f64::consts::TAU;

/// One cylinder's place on the crankshaft (module note).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    /// φ: its throw's angle ahead of the reference throw, rad.
    pub throw: f64,
    /// β: its plane frame's turn about the crank axis, rad (its axis along e^{iβ}·i).
    pub axis_angle: f64,
    /// z: its plane's position along the crank axis, m.
    pub axial_position: f64,
}

/// The cylinders of a machine, cylinder 1 first.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    pub cylinders: Vec<Cylinder>,
}

/// The machine's shaking at one step, in the machine frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MachineShaking {
    /// Σ of the cylinders' and rotors' shaking forces, N (x, y as re, im).
    pub force: C,
    /// Free moment about the crank axis's point midway between the outermost cylinders, N·m:
    /// pitch (about x) as re, yaw (about y) as im.
    pub moment: C,
}

impl MachineShaking {
    /// Moment about the horizontal axis across the crank axis, N·m.
    pub fn pitch(&self) -> f64 {
        self.moment.re
    }

    /// Moment about the vertical axis, N·m.
    pub fn yaw(&self) -> f64 {
        self.moment.im
    }
}

impl Layout {
    /// One cylinder, as every case is today.
    pub fn single() -> Self {
        Self::in_line(&[0.0], 0.0)
    }

    /// An in-line machine: throws `throws` (rad), cylinder i at i·`spacing` (m).
    pub fn in_line(throws: &[f64], spacing: f64) -> Self {
        Self {
            cylinders: throws
                .iter()
                .enumerate()
                .map(|(i, &throw)| Cylinder {
                    throw,
                    axis_angle: 0.0,
                    axial_position: i as f64 * spacing,
                })
                .collect(),
        }
    }

    /// A radial engine of `n` cylinders at 2π/n, every rod on the one crank pin (module note).
    pub fn radial(n: usize) -> Self {
        Self {
            cylinders: (0..n)
                .map(|i| Cylinder {
                    throw: 0.0,
                    axis_angle: TAU * i as f64 / n as f64,
                    axial_position: 0.0,
                })
                .collect(),
        }
    }

    /// z₀, m: midway between the outermost cylinders.
    pub fn reference(&self) -> f64 {
        let z = self.cylinders.iter().map(|c| c.axial_position);
        let (lo, hi) = z.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
            (lo.min(z), hi.max(z))
        });
        0.5 * (lo + hi)
    }

    /// Cylinder `i`'s own crank state at the machine's `crank`: its angle ψ = θ + φ − β, the
    /// same speed, acceleration and time.
    pub fn cylinder_crank(&self, i: usize, crank: &CrankState) -> CrankState {
        let c = &self.cylinders[i];
        CrankState::new(
            crank.angle + c.throw - c.axis_angle,
            crank.speed,
            crank.acceleration,
            crank.time,
        )
    }

    /// A rotor of cylinder `i`, given in that cylinder's frame at its own angle ψ, in the
    /// machine frame at θ: z = e^{iβ}·u·e^{ik(θ+φ−β)}, so u turns by β + k·(φ − β); at the
    /// cylinder's axial position plus its own.
    pub fn place(&self, i: usize, rotor: &Rotor) -> Rotor {
        let c = &self.cylinders[i];
        let turn = c.axis_angle + rotor.order as f64 * (c.throw - c.axis_angle);
        Rotor {
            mass_radius: rotor.mass_radius * C::from_polar(1.0, turn),
            order: rotor.order,
            axial_position: c.axial_position + rotor.axial_position,
        }
    }

    /// The machine's shaking from each cylinder's own (`per_cylinder[i]` in cylinder i's frame
    /// at its angle ψ_i) and from `rotors` (in the machine frame, [`Layout::place`]) at
    /// `crank` (module note).
    pub fn sum(
        &self,
        per_cylinder: impl ExactSizeIterator<Item = Shaking>,
        rotors: &[Rotor],
        crank: &CrankState,
    ) -> MachineShaking {
        let axis = |i: usize| C::from_polar(1.0, self.cylinders[i].axis_angle);
        self.sum_about(self.reference(), axis, per_cylinder, rotors, crank)
    }

    /// Each cylinder's axis direction e^{iβ}, which [`Layout::sum`] turns its shaking by.
    pub fn axes(&self) -> Vec<C> {
        self.cylinders
            .iter()
            .map(|c| C::from_polar(1.0, c.axis_angle))
            .collect()
    }

    /// [`Layout::sum`] with the cylinders' [`Layout::axes`] made beforehand (the same bits).
    pub fn sum_on(
        &self,
        axes: &[C],
        per_cylinder: impl ExactSizeIterator<Item = Shaking>,
        rotors: &[Rotor],
        crank: &CrankState,
    ) -> MachineShaking {
        self.sum_about(self.reference(), |i| axes[i], per_cylinder, rotors, crank)
    }

    /// [`Layout::sum`], cylinder i's axis direction `axis(i)`, the moments about the plane
    /// `z0` (m; [`Layout::reference`], found once by a caller that sums at every step).
    pub fn sum_about(
        &self,
        z0: f64,
        axis: impl Fn(usize) -> C,
        per_cylinder: impl ExactSizeIterator<Item = Shaking>,
        rotors: &[Rotor],
        crank: &CrankState,
    ) -> MachineShaking {
        assert_eq!(
            per_cylinder.len(),
            self.cylinders.len(),
            "one shaking per cylinder"
        );
        let mut out = MachineShaking::default();
        let mut add = |force: C, z: f64| {
            out.force += force;
            out.moment += C::i() * (z - z0) * force;
        };
        for (i, (c, s)) in self.cylinders.iter().zip(per_cylinder).enumerate() {
            add(axis(i) * s.force, c.axial_position);
        }
        for r in rotors {
            add(r.force(crank), r.axial_position);
        }
        out
    }

    /// Every cylinder's [`Shaking`] in its own frame at the machine's `crank`, each running
    /// `mechanism` at its own angle.
    pub fn cylinders_shaking(&self, mechanism: &dyn Mechanism, crank: &CrankState) -> Vec<Shaking> {
        (0..self.cylinders.len())
            .map(|i| {
                let state = mechanism.state(&self.cylinder_crank(i, crank));
                shaking(mechanism.topology(), &state)
            })
            .collect()
    }

    /// The machine's shaking at `crank`: `mechanism` in every cylinder, plus `rotors` (machine
    /// frame).
    pub fn shaking(
        &self,
        mechanism: &dyn Mechanism,
        rotors: &[Rotor],
        crank: &CrankState,
    ) -> MachineShaking {
        self.sum(
            self.cylinders_shaking(mechanism, crank).into_iter(),
            rotors,
            crank,
        )
    }
}

/// The throws of an evenly firing machine from its firing order (cylinder numbers from 1): the
/// cylinder that fires j-th reaches its top dead centre j·`interval` later than the first, so
/// its throw trails by that angle, φ = −j·interval mod 2π (`interval`: 4π/n for a four-stroke,
/// 2π/n for a two-stroke, rad). Returns the throws by cylinder number.
///
/// # Panics
/// If `firing_order` is not a permutation of 1..=n.
pub fn throws_from_firing_order(firing_order: &[usize], interval: f64) -> Vec<f64> {
    let n = firing_order.len();
    let mut throws = vec![f64::NAN; n];
    for (j, &cylinder) in firing_order.iter().enumerate() {
        assert!(
            (1..=n).contains(&cylinder) && throws[cylinder - 1].is_nan(),
            "firing order {firing_order:?} is not a permutation of 1..={n}"
        );
        throws[cylinder - 1] = (-(j as f64) * interval).rem_euclid(TAU);
    }
    throws
}

/// A machine's orders over one revolution at constant speed.
#[derive(Debug, Clone, PartialEq)]
pub struct MachineOrders {
    /// Orders 0..=max of the shaking force, N.
    pub force: Vec<Order>,
    /// Orders 0..=max of the free moment (pitch as re, yaw as im), N·m.
    pub moment: Vec<Order>,
}

impl Layout {
    /// The orders 0..=`max_order` of the machine's shaking force and free moment
    /// ([`Layout::shaking`]) over one revolution from θ = 0 at the constant speed `speed`
    /// (rad/s), on `steps` steps ([`crate::orders`]: `steps` > 2·`max_order`, and high enough
    /// that the orders above N/2 are negligible).
    pub fn orders(
        &self,
        mechanism: &dyn Mechanism,
        rotors: &[Rotor],
        speed: f64,
        steps: usize,
        max_order: usize,
    ) -> MachineOrders {
        let mut scratch = OrdersScratch::default();
        self.orders_in(mechanism, rotors, speed, steps, max_order, &mut scratch)
    }

    /// [`Layout::orders`] in the room `scratch` (kept between calls with the one `mechanism`:
    /// its block is of that mechanism's topology, and every call writes what it reads).
    ///
    /// The same operations as [`Layout::shaking`] at each step and [`crate::orders`] over the
    /// steps, in the same order (the same bits): each cylinder's states filled a block at a
    /// time, its shaking turned by its axis and added into the step's force and moment (every
    /// cylinder in turn, then the rotors: [`Layout::sum_about`]'s order), the cylinder's crank
    /// states the revolution's own where its angle ψ = θ + φ − β is θ to the bit (one cylinder
    /// in its own frame), the factors of the transform the revolution's cos θ and sin θ (the
    /// same angles j·2π/N: [`crate::harmonics::factors`]).
    pub(crate) fn orders_in(
        &self,
        mechanism: &dyn Mechanism,
        rotors: &[Rotor],
        speed: f64,
        steps: usize,
        max_order: usize,
        scratch: &mut OrdersScratch,
    ) -> MachineOrders {
        let t = mechanism.topology();
        let OrdersScratch {
            block,
            cranks,
            own,
            forces,
            moments,
            table,
        } = scratch;
        let block = block.get_or_insert_with(|| Box::new(StateBlock::for_topology(t)));
        cranks.clear();
        cranks.extend(revolution_states(0.0, speed, steps));
        let zero = C::new(0.0, 0.0);
        forces.clear();
        forces.resize(steps, zero);
        moments.clear();
        moments.resize(steps, zero);
        let z0 = self.reference();
        for c in &self.cylinders {
            let axis = C::from_polar(1.0, c.axis_angle);
            let lever = C::i() * (c.axial_position - z0);
            let chunks = cranks
                .chunks(LANES)
                .zip(forces.chunks_mut(LANES).zip(moments.chunks_mut(LANES)));
            for (chunk, (forces, moments)) in chunks {
                // θ ≥ +0 (from θ₀ = 0): (θ + φ) − β is θ for φ = β = ±0.
                let states = if c.throw == 0.0 && c.axis_angle == 0.0 {
                    chunk
                } else {
                    own.clear();
                    own.extend(chunk.iter().map(|crank| {
                        let angle = crank.angle + c.throw - c.axis_angle;
                        match angle.to_bits() == crank.angle.to_bits() {
                            true => *crank,
                            false => {
                                CrankState::new(angle, crank.speed, crank.acceleration, crank.time)
                            }
                        }
                    }));
                    own.as_slice()
                };
                block.fill(mechanism, states);
                for (k, (f, m)) in forces.iter_mut().zip(moments.iter_mut()).enumerate() {
                    let force = axis * shaking_lane(t, block, k).force;
                    *f += force;
                    *m += lever * force;
                }
            }
        }
        for r in rotors {
            let lever = C::i() * (r.axial_position - z0);
            for ((crank, f), m) in cranks.iter().zip(forces.iter_mut()).zip(moments.iter_mut()) {
                let force = r.force(crank);
                *f += force;
                *m += lever * force;
            }
        }
        table.clear();
        table.extend(cranks.iter().map(|c| c.direction));
        // One cylinder in the plane z₀ without rotors elsewhere: a moment of zeros, whose orders
        // are zeros ([`crate::harmonics::zero_orders`]).
        if moments.iter().all(|m| m.re == 0.0 && m.im == 0.0) {
            let [force] = orders_of(forces.iter().map(|&f| [f]), 0.0, max_order, table);
            let moment = zero_orders(forces.len(), max_order);
            return MachineOrders { force, moment };
        }
        let samples = forces.iter().zip(moments.iter()).map(|(&f, &m)| [f, m]);
        let [force, moment] = orders_of(samples, 0.0, max_order, table);
        MachineOrders { force, moment }
    }
}

/// Room for [`Layout::orders`] kept between calls with one mechanism
/// ([`crate::PreparedBalance::orders`]): a block of the mechanism's topology (some 30 kB of
/// columns to zero, made at its first use) and the revolution's crank states, force, moment
/// and factors, each written whole before it is read.
#[derive(Default)]
pub struct OrdersScratch {
    block: Option<Box<StateBlock>>,
    cranks: Vec<CrankState>,
    own: Vec<CrankState>,
    forces: Vec<C>,
    moments: Vec<C>,
    table: Vec<C>,
}

impl std::fmt::Debug for OrdersScratch {
    /// Its name only: what a room holds depends on the calls made (and a block is some 30 kB).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("OrdersScratch").finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[should_panic(expected = "not a permutation")]
    fn a_firing_order_that_is_not_a_permutation_is_refused() {
        throws_from_firing_order(&[1, 3, 3, 2], std::f64::consts::PI);
    }

    /// One room used for revolutions of 120, 70 (a last block of 6 lanes, the rest of the
    /// block stale) and 120 steps again, at other speeds and orders, gives the bits of a fresh
    /// room each time, for every registered mechanism: nothing of a call is read by the next.
    #[test]
    fn a_kept_room_gives_the_bits_of_a_fresh_one() {
        let geometry = cardan_mechanism::MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let options = cardan_mechanism::Options::new();
        let layout = Layout::in_line(&[0.0, 2.1, 4.2], 0.1);
        let rotors = [layout.place(1, &Rotor::on_crank(C::new(0.01, 0.002), 0.02))];
        let bits = |o: &MachineOrders| -> Vec<[u64; 8]> {
            let parts = |o: &Order| [o.forward.re, o.forward.im, o.backward.re, o.backward.im];
            (o.force.iter().zip(&o.moment))
                .map(|(f, m)| {
                    let [a, b, c, d] = parts(f);
                    let [e, f, g, h] = parts(m);
                    [a, b, c, d, e, f, g, h].map(f64::to_bits)
                })
                .collect()
        };
        for entry in cardan_mechanism::MECHANISMS {
            let m = (entry.build)(&geometry, &Default::default(), &options).unwrap();
            let mut kept = OrdersScratch::default();
            for (steps, speed, max_order) in [(120, 30.0, 4), (70, 300.0, 6), (120, 50.0, 2)] {
                let a = layout.orders_in(m.as_ref(), &rotors, speed, steps, max_order, &mut kept);
                let b = layout.orders(m.as_ref(), &rotors, speed, steps, max_order);
                let what = format!("{}: {steps} steps at {speed} rad/s", entry.name);
                assert_eq!(bits(&a), bits(&b), "{what}");
                assert_eq!(a.force.len(), max_order + 1, "{what}");
            }
        }
    }

    /// A rotor of a cylinder turned by β with its throw at φ: on the crank (k = 1) it turns
    /// with the throw, e^{iφ}; against it (k = −1) by e^{i(2β − φ)}.
    #[test]
    fn a_rotor_is_placed_with_its_cylinder() {
        let layout = Layout {
            cylinders: vec![Cylinder {
                throw: 0.3,
                axis_angle: 1.1,
                axial_position: 0.2,
            }],
        };
        let on_crank = layout.place(0, &Rotor::on_crank(C::new(2.0, 0.0), 0.05));
        assert!((on_crank.mass_radius - C::from_polar(2.0, 0.3)).norm() < 1e-15);
        assert!((on_crank.axial_position - 0.25).abs() < 1e-15);
        let backward = Rotor {
            order: -1,
            ..Rotor::on_crank(C::new(2.0, 0.0), 0.0)
        };
        let placed = layout.place(0, &backward);
        assert!((placed.mass_radius - C::from_polar(2.0, 2.2 - 0.3)).norm() < 1e-15);
    }
}
