//! The rating of a block a mesh at a time over its lanes, the AGMA stresses of every lane at
//! once (a block kernel, [`agma_lanes`]): the same arithmetic, in the same order, as a lane
//! rated alone ([`RatedMesh::rate`]), so the same bits (`tests/gear_rating.rs` holds the two
//! side by side). The checks a lane rated alone makes are made here as tests of the block (a
//! load, speed or factor out of its range anywhere sends the whole block to the lanes rated
//! one by one, which say where and why), so that no lane carries a `Result`.

use cardan_gears::mesh_loss::PreparedMeshLoss;
use cardan_gears::{CheckedRating, SaturatedLoad};
use cardan_mechanism::{Column, ZERO};

use super::{MeshRating, RatedMesh};
use crate::mesh::{mesh_speeds, tangential, ToothLoad};
use crate::stage::Block;

impl RatedMesh {
    /// The mesh's loss (W) at the first [`Block::len`] lanes of `block` into `loss`, every
    /// lane at once ([`mesh_loss_lanes`]), as its bound model takes it lane by lane (the
    /// tangential load shared by the sets, each set losing its own: `cardan_losses`'s `Mesh`),
    /// with the same bits: `false` where it has no model over lanes or a lane fails a check
    /// (the bound model, lane by lane, then says why).
    pub(super) fn loss_lanes(&mut self, block: &Block, loss: &mut Column) -> bool {
        let Some(model) = &mut self.loss_lanes else {
            return false;
        };
        let n = block.len;
        let (forces, motions) = (
            &block.total.joints[self.joint],
            &block.states.joints[self.joint],
        );
        let pinion = &block.states.bodies[self.body].angular_velocity;
        let (mut ft, mut carrier) = (ZERO, ZERO);
        for i in 0..n {
            let motion = motions.at(i);
            ft[i] = tangential(forces.at(i).force, &motion) / self.sets;
            carrier[i] = mesh_speeds(pinion[i], motion.relative_speed, self.pitch_radius).carrier;
        }
        if !mesh_loss_lanes(model, &pinion[..n], &carrier[..n], &ft[..n], &mut loss[..n]) {
            return false;
        }
        for l in &mut loss[..n] {
            *l *= self.sets;
        }
        true
    }

    /// The mesh's rating at the first [`Block::len`] lanes of `block`, its mesh loss `loss`
    /// (W) at each, into `out` (its [values](MeshRating::values), a column each, the first
    /// `out.len()`): `false` where a lane fails a check of [`RatedMesh::rate`] (the lanes are
    /// then to be rated one by one: `out` holds nothing to be taken).
    pub(super) fn rate_lanes(&mut self, block: &Block, loss: &Column, out: &mut [Column]) -> bool {
        let Some(rating) = self.rating.checked() else {
            return false;
        };
        let n = block.len;
        let (mut load, mut dynamic, mut kv) = (ZERO, ZERO, ZERO);
        if !self.loads_and_factors(block, &mut load, &mut dynamic, &mut kv) {
            return false;
        }
        let [tooth_load, dynamic_load, contact, contact_safety, bending, bending_safety, lost, iso @ ..] =
            out
        else {
            unreachable!(
                "a mesh's rating has at least {} values",
                MeshRating::AGMA_WIDTH
            )
        };
        let agma = [contact, contact_safety, bending, bending_safety];
        if !agma_lanes(&rating, &load, &kv, n, agma) {
            return false;
        }
        if !self.bending {
            bending[..n].fill(f64::NAN);
            bending_safety[..n].fill(f64::NAN);
        }
        tooth_load[..n].copy_from_slice(&load[..n]);
        dynamic_load[..n].copy_from_slice(&dynamic[..n]);
        lost[..n].copy_from_slice(&loss[..n]);
        let speed = &block.states.joints[self.joint].relative_speed;
        let iso_lanes = if iso.is_empty() { 0 } else { n };
        for i in 0..iso_lanes {
            let Ok(values) = self.iso_at(load[i], speed[i]) else {
                return false;
            };
            for (c, v) in iso.iter_mut().zip(values) {
                c[i] = v;
            }
        }
        true
    }

    /// Each lane's rated tooth load (N), Buckingham's dynamic load (N) and AGMA's dynamic
    /// factor, as [`RatedMesh::rate`] takes them: `false` where a lane fails a check of them.
    fn loads_and_factors(
        &mut self,
        block: &Block,
        load: &mut Column,
        dynamic: &mut Column,
        kv: &mut Column,
    ) -> bool {
        let (forces, motions) = (
            &block.total.joints[self.joint],
            &block.states.joints[self.joint],
        );
        let saturated = match (self.tooth_load, &self.saturated) {
            (ToothLoad::Thesis, Ok(s)) => Some(*s),
            (ToothLoad::Thesis, Err(_)) => return false,
            _ => None,
        };
        let mut takes = true;
        for i in 0..block.len {
            let motion = motions.at(i);
            let force = forces.at(i).force;
            let tangential_load = tangential(force, &motion).abs() / self.sets;
            takes &= self.set.takes_step(tangential_load, motion.relative_speed);
            let Some(factor) = self.kept_kv(motion.relative_speed) else {
                return false;
            };
            kv[i] = factor;
            load[i] = match self.tooth_load {
                ToothLoad::Tangential => tangential_load,
                ToothLoad::RingForce => force.norm() / self.sets,
                ToothLoad::Thesis => self.thesis_load(block, i, force, &motion),
            };
            dynamic[i] = match saturated {
                Some(s) if SaturatedLoad::takes(load[i]) => s.dynamic_load(load[i]),
                Some(_) => return false,
                None => {
                    let v = motion.relative_speed.abs();
                    match self.set.buckingham.dynamic_load(load[i], v) {
                        Ok(d) => d.dynamic_load,
                        Err(_) => return false,
                    }
                }
            };
        }
        takes
    }

    /// AGMA's dynamic factor `Kv` at the pitch-line velocity `v` (m/s) of a step
    /// [`GearSet::takes_step`](cardan_gears::GearSet::takes_step) takes, kept with the speed's
    /// bits as [`RatedMesh::kept_dynamic_factor`] keeps it (the same factor); `None` where it
    /// cannot be taken.
    fn kept_kv(&mut self, v: f64) -> Option<f64> {
        let bits = v.abs().to_bits();
        match self.kv {
            Some((kept, kv)) if kept == bits => Some(kv.kv),
            _ => {
                let kv = cardan_gears::dynamic_factor(self.set.quality, v.abs()).ok()?;
                self.kv = Some((bits, kv));
                Some(kv.kv)
            }
        }
    }
}

cardan_mechanism::vectorised! {
    /// AGMA 2001-D04's stresses and safety factors (eqs. 1 and 15, [`CheckedRating::rate`]) at
    /// each of the first `n` lanes' load `load` (N) and dynamic factor `kv`, the larger
    /// member's stress and the smaller safety factor into `[contact stress, contact safety,
    /// bending stress, bending safety]` (Pa, -): `false` where a lane's load or factor is not
    /// one the rating takes ([`CheckedRating::takes`]).
    fn agma_lanes(
        rating: &CheckedRating,
        load: &Column,
        kv: &Column,
        n: usize,
        out: [&mut Column; 4],
    ) -> bool {
        let [contact, contact_safety, bending, bending_safety] = out;
        let mut takes = true;
        for i in 0..n {
            takes &= CheckedRating::takes(load[i], kv[i]);
            let r = rating.rate(load[i], kv[i]);
            contact[i] = r.contact_stress[0].max(r.contact_stress[1]);
            contact_safety[i] = r.contact_safety[0].min(r.contact_safety[1]);
            bending[i] = r.bending_stress[0].max(r.bending_stress[1]);
            bending_safety[i] = r.bending_safety[0].min(r.bending_safety[1]);
        }
        takes
    }
}

cardan_mechanism::vectorised! {
    /// Anderson & Loewenthal's mesh loss over a block's lanes
    /// ([`PreparedMeshLoss::total_power_lanes`], Karhula A9.1.41-55), compiled for the block
    /// kernels' instruction sets.
    fn mesh_loss_lanes(
        model: &mut PreparedMeshLoss,
        pinion: &[f64],
        carrier: &[f64],
        ft: &[f64],
        out: &mut [f64],
    ) -> bool {
        model.total_power_lanes(pinion, carrier, ft, out)
    }
}
