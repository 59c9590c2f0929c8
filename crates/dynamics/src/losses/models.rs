//! The loss models bound to a mechanism: one type per model, each its power loss at a step
//! ([`Loss`]) from the joint's total load and relative speed, the pistons' speeds or the
//! crank's; [`crate::LossBudget`] binds them by joint kind.

use super::{At, Loss};
use crate::engine_losses::{
    accessories_power, pumping_power, EngineLosses, ValveTrainLoss, AMBIENT_PRESSURE,
};
use crate::mesh::mesh_speeds;
use crate::mesh::tangential;
use cardan_friction::{
    coulomb_sliding, petroff, short_bearing, viscous_skirt, JournalBearing, RingFilm, RingLoad,
    RollingModel, ViscousSkirt,
};
use cardan_gears::mesh_loss::{mesh_loss, Lubricant, MeshGeometry, Reading};

/// Karhula's ring pack on every piston: a constant force μ·F_cont (A9.1.2-4) at the piston's
/// speed, P = F·|v| (A9.1.8).
#[derive(Debug, Clone)]
pub struct RingPack {
    /// μ_ring·F_cont, N.
    pub force: f64,
}

impl Loss for RingPack {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let force = self.force;
        Ok(at
            .state
            .pistons
            .iter()
            .map(|p| force * p.velocity.abs())
            .sum())
    }
}

/// Every ring of every piston on its oil film ([`RingFilm`]): the minimum film of each ring of
/// each piston (`None` before the first step) carried from step to step by the squeeze term.
#[derive(Debug, Clone)]
pub struct RingFilms {
    /// Each ring of a piston: its film model, elastic pressure (Pa), whether it is the top ring
    /// (which the cylinder pressure above atmospheric loads).
    pub rings: Vec<(RingFilm, f64, bool)>,
    /// The minimum film of each ring of each piston, m.
    pub films: Vec<Option<f64>>,
    /// The time of the previous step, s.
    pub time: Option<f64>,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for RingFilms {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let now = at.state.crank.time;
        let dt = self.time.map(|t0| now - t0).filter(|dt| *dt > 0.0);
        self.time = Some(now);
        let gauge = at.pressure.map_or(0.0, |p| (p - AMBIENT_PRESSURE).max(0.0));
        let mut power = 0.0;
        let per_piston = self.rings.len();
        for (k, p) in at.state.pistons.iter().enumerate() {
            for (r, (film, elastic, top)) in self.rings.iter().enumerate() {
                let load = RingLoad {
                    elastic_pressure: *elastic,
                    gas_pressure_behind: if *top { gauge } else { 0.0 },
                };
                let h = &mut self.films[k * per_piston + r];
                let s = match (*h, dt) {
                    (Some(h0), Some(dt)) => film.step(h0, dt, self.viscosity, p.velocity, load),
                    _ => film.quasi_steady(self.viscosity, p.velocity, load),
                };
                *h = Some(s.min_film_thickness);
                power += s.loss.power;
            }
        }
        Ok(power)
    }

    fn carries_history(&self) -> bool {
        true
    }
}

/// Coulomb friction on a slide's normal force (Karhula A9.1.5 for a skirt; any other slide).
#[derive(Debug, Clone)]
pub struct Coulomb {
    pub joint: usize,
    pub friction_coefficient: f64,
}

/// [`Coulomb`] friction of `friction_coefficient` on prismatic joint `joint`.
pub fn coulomb(joint: usize, friction_coefficient: f64) -> Box<dyn Loss> {
    Box::new(Coulomb {
        joint,
        friction_coefficient,
    })
}

impl Loss for Coulomb {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let (load, state) = (&at.total.joints[self.joint], &at.state.joints[self.joint]);
        let loss = coulomb_sliding(
            self.friction_coefficient,
            load.force.norm(),
            state.relative_speed,
        );
        Ok(loss.power)
    }
}

/// The viscous skirt (Thai thesis 2.5.c.1-3) on a piston's slide.
#[derive(Debug, Clone)]
pub struct ViscousSkirtLoss {
    pub joint: usize,
    pub skirt: ViscousSkirt,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for ViscousSkirtLoss {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let speed = at.state.joints[self.joint].relative_speed;
        Ok(viscous_skirt(&self.skirt, self.viscosity, speed).power)
    }
}

/// A revolute joint's rolling bearings in a reading of
/// [`cardan_friction::rolling_bearing_loss`]; each of `count` carries an equal share
/// (A9.1.23-25).
#[derive(Debug, Clone)]
pub struct Rolling {
    pub joint: usize,
    /// The bearing in its reading.
    pub model: RollingModel,
    pub count: f64,
    /// Kinematic viscosity, m²/s (the rolling readings' input).
    pub viscosity: f64,
}

impl Loss for Rolling {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let share = at.total.joints[self.joint].force.norm() / self.count;
        let w = at.state.joints[self.joint].relative_speed;
        Ok(self.count * self.model.loss(share, w, self.viscosity).power)
    }
}

/// A revolute joint's plain journal bearings: Petroff's concentric journal, or Ocvirk's short
/// bearing with the eccentricity from the instantaneous load.
#[derive(Debug, Clone)]
pub struct Journal {
    pub joint: usize,
    pub bearing: JournalBearing,
    pub count: f64,
    /// Ocvirk's short bearing; `false`: Petroff.
    pub short: bool,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for Journal {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let share = at.total.joints[self.joint].force.norm() / self.count;
        let w = at.state.joints[self.joint].relative_speed;
        let one = if self.short {
            short_bearing(&self.bearing, self.viscosity, share, w, w)
                .loss
                .power
        } else {
            petroff(&self.bearing, self.viscosity, w, share).0.power
        };
        Ok(self.count * one)
    }
}

/// Anderson & Loewenthal's mesh loss (Karhula A9.1.36-55) on a gear-mesh joint, charged on the
/// tangential load shared by the gear sets; a mesh a gear rating has rated takes the rating's
/// loss (the same model on the same pair), computed once.
#[derive(Debug, Clone)]
pub struct Mesh {
    pub joint: usize,
    /// The body carrying the pinion.
    pub body: usize,
    pub geometry: MeshGeometry,
    pub lubricant: Lubricant,
    pub reading: Reading,
    pub pitch_radius: f64,
    /// Gear sets sharing the load (2 for a twin set): each carries its share and loses its
    /// own, as in the gear rating.
    pub sets: f64,
}

impl Loss for Mesh {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        if let Some(&(_, loss)) = at.rated_meshes.iter().find(|(j, _)| *j == self.joint) {
            return Ok(loss);
        }
        let (state, joint) = (at.state, self.joint);
        let ft = tangential(at.total.joints[joint].force, &state.joints[joint]);
        let speeds = mesh_speeds(state, joint, self.body, self.pitch_radius);
        let sets = self.sets;
        let loss = mesh_loss(
            &self.geometry,
            &self.lubricant,
            &speeds,
            ft / sets,
            self.reading,
        )
        .map_err(|e| format!("gear mesh loss: {e}"))?;
        Ok(sets * loss.total_power)
    }
}

/// The cylinder's valve train at the step's crank angle, speed and acceleration.
impl Loss for ValveTrainLoss {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        let c = &at.state.crank;
        Ok(ValveTrainLoss::power(
            self,
            c.angle,
            c.speed,
            c.acceleration,
        ))
    }
}

/// Bishop's accessories on the swept volume.
#[derive(Debug, Clone)]
pub struct Accessories {
    /// Swept volume, m³.
    pub displacement: f64,
}

impl Loss for Accessories {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        Ok(accessories_power(self.displacement, at.state.crank.speed))
    }
}

/// Bishop's throttling loss on the swept volume.
#[derive(Debug, Clone)]
pub struct Pumping {
    /// Swept volume, m³.
    pub displacement: f64,
    pub engine: EngineLosses,
}

impl Loss for Pumping {
    fn power(&mut self, at: &At) -> Result<f64, String> {
        Ok(pumping_power(
            &self.engine,
            self.displacement,
            at.state.crank.speed,
        ))
    }
}
