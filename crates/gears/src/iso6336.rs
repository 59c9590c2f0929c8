//! ISO 6336 method B rating of a spur pair ([`GearPair`], external or internal), side by
//! side with the AGMA 2001 rating of [`crate::agma`]: the contact safety factor `S_H` by
//! ISO 6336-2:2019 ([`crate::iso6336_pitting`]) and the root safety factor `S_F` by
//! ISO 6336-3:2019 ([`crate::iso6336_bending`]), the load factors by ISO 6336-1:2019
//! ([`crate::iso6336_load`]).
//!
//! Taken as 1, and why: `K_γ` (one mesh); `Z_W` (both members of like hardness; ISO 6336-2
//! §12 raises it only for a soft wheel run against a hardened, ground pinion); `Z_L Z_v Z_R`
//! unless the oil viscosity and flank roughness are given ([`Lubrication`]); `Y_δrelT` and
//! `Y_RrelT` unless given (ISO 6336-3 §11, §12: close to 1 for the standard fillet,
//! `q_s` ≈ 2.5, and root roughness `R_z` ≈ 10 µm of the test gears); `Y_β`, `Z_β` (spur);
//! `C_a` = the running-in tip relief `C_ay` (no designed tip relief). `K_Hβ` is the user's,
//! or AGMA 2001-D04's empirical `Km` for the same face width (the gear file states which):
//! ISO 6336-1 methods B and C need shaft and bearing data a gear pair file does not hold.

use crate::error::{positive, GearError};
use crate::geometry::GearPair;
use crate::iso6336_bending as bend;
use crate::iso6336_load::{
    dynamic_factor_b, face_load_factor_root, iso1328_deviations, mesh_stiffness, resonance_ratio,
    running_in_allowance, running_in_tip_relief, transverse_load_factors, DynamicInputs, RunningIn,
};
use crate::iso6336_pitting as pit;
use crate::materials::LifeCurve;

/// Steel density for `m_red` when none is given, 7830 kg/m³ (ISO 6336-1:2019 §6.5.9).
pub const STEEL_DENSITY: f64 = 7830.0;

/// How `K_v` is obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IsoDynamic {
    /// Given.
    Given(f64),
    /// ISO 6336-1 method B from the accuracy grade of [`IsoInputs::accuracy_grade`] and the
    /// blanks' density \[kg/m³\] (solid blanks).
    MethodB {
        /// Density \[kg/m³\].
        density: f64,
    },
}

/// Oil and surface data for `Z_L`, `Z_v`, `Z_R` (ISO 6336-2 §11, method B).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubrication {
    /// Kinematic viscosity at 40 °C \[mm²/s\].
    pub viscosity_40: f64,
    /// Mean peak-to-valley flank roughness `R_z` of the pair \[m\].
    pub flank_roughness: f64,
}

/// One member's ISO inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoMember {
    /// Allowable stress number (contact) `σ_Hlim` \[Pa\].
    pub sigma_hlim: f64,
    /// Nominal stress number (bending) `σ_Flim` \[Pa\].
    pub sigma_flim: f64,
    /// Life factor curves, size factors and running-in class.
    pub life_curve: LifeCurve,
    /// Tooth form factor `Y_F` (method B, load at the outer point of single tooth contact).
    pub form_factor: f64,
    /// Stress correction factor `Y_S`.
    pub stress_correction_factor: f64,
    /// Rim thickness factor `Y_B` (1 for a solid rim).
    pub rim_factor: f64,
    /// Relative notch sensitivity factor `Y_δrelT`.
    pub notch_sensitivity: f64,
    /// Relative surface factor `Y_RrelT`.
    pub surface_factor: f64,
    /// Load cycles `N_L`.
    pub cycles: f64,
}

/// Inputs of [`rate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoInputs {
    /// Pinion torque \[N·m\].
    pub pinion_torque: f64,
    /// Pinion speed relative to the gear's frame \[rad/s\].
    pub pinion_speed: f64,
    /// Face width `b` \[m\].
    pub face_width: f64,
    /// Application factor `K_A`.
    pub application_factor: f64,
    /// `K_v` rule.
    pub dynamic: IsoDynamic,
    /// ISO 1328-1 accuracy grade of both gears (for `K_v` and `K_Hα` by method B).
    pub accuracy_grade: Option<f64>,
    /// Face load factor `K_Hβ`.
    pub face_load_factor: f64,
    /// Given transverse load factor `K_Hα` = `K_Fα`, else method B.
    pub transverse_load_factor: Option<f64>,
    /// Elasticity factor `Z_E` \[√Pa\].
    pub elasticity_factor: f64,
    /// Oil and roughness, else `Z_L Z_v Z_R` = 1.
    pub lubrication: Option<Lubrication>,
    /// `[pinion, gear]`.
    pub members: [IsoMember; 2],
}

/// The ISO rating; arrays are `[pinion, gear]`, stresses in Pa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoRating {
    /// Nominal tangential load at the reference circle `F_t = 2 T1/d1` \[N\].
    pub tangential_load: f64,
    /// Pitch-line velocity at the reference circle \[m/s\].
    pub velocity: f64,
    /// Resonance ratio `N` (method B `K_v` only).
    pub resonance_ratio: Option<f64>,
    /// `K_A`, `K_v`, `K_Hβ`, `K_Hα`, `K_Fβ`, `K_Fα`.
    pub k_a: f64,
    /// Dynamic factor.
    pub k_v: f64,
    /// Face load factor (contact).
    pub k_hbeta: f64,
    /// Transverse load factor (contact).
    pub k_halpha: f64,
    /// Face load factor (root).
    pub k_fbeta: f64,
    /// Transverse load factor (root).
    pub k_falpha: f64,
    /// Zone factor.
    pub z_h: f64,
    /// Elasticity factor \[√Pa\].
    pub z_e: f64,
    /// Contact ratio factor.
    pub z_eps: f64,
    /// Helix angle factor (contact).
    pub z_beta: f64,
    /// Single pair tooth contact factors `[Z_B, Z_D]`.
    pub z_bd: [f64; 2],
    /// Life factors (contact).
    pub z_nt: [f64; 2],
    /// `[Z_L, Z_v, Z_R]`.
    pub z_lvr: [f64; 3],
    /// Work hardening factor.
    pub z_w: f64,
    /// Size factors (contact).
    pub z_x: [f64; 2],
    /// Nominal contact stress.
    pub sigma_h0: f64,
    /// Contact stresses.
    pub sigma_h: [f64; 2],
    /// Pitting stress limits `σ_HG` (= `σ_HP` at `S_Hmin` = 1).
    pub sigma_hg: [f64; 2],
    /// Contact safety factors `S_H`.
    pub s_h: [f64; 2],
    /// Helix angle factor (root).
    pub y_beta: f64,
    /// Deep tooth factor.
    pub y_dt: f64,
    /// Tooth form factors `Y_F` and stress correction factors `Y_S` taken (given, or computed
    /// from the tooth form by the caller).
    pub y_f: [f64; 2],
    pub y_s: [f64; 2],
    /// Life factors (root).
    pub y_nt: [f64; 2],
    /// Size factors (root).
    pub y_x: [f64; 2],
    /// Nominal root stresses.
    pub sigma_f0: [f64; 2],
    /// Root stresses.
    pub sigma_f: [f64; 2],
    /// Root stress limits `σ_FG` (= `σ_FP` at `S_Fmin` = 1).
    pub sigma_fg: [f64; 2],
    /// Root safety factors `S_F`.
    pub s_f: [f64; 2],
}

fn running_in_class(c: LifeCurve) -> RunningIn {
    match c {
        LifeCurve::ThroughHardened => RunningIn::ThroughHardened,
        LifeCurve::CaseHardened | LifeCurve::Nitrided => RunningIn::Hardened,
        LifeCurve::GreyIron => RunningIn::GreyIron,
    }
}

/// Rates `pair` by ISO 6336-1/-2/-3 method B (spur: `β` = 0). Errors name the input.
pub fn rate(pair: &GearPair, inp: &IsoInputs) -> Result<IsoRating, GearError> {
    validate(inp)?;
    let prepared = PreparedIso::new(pair, inp)?;
    prepared.rate(
        2.0 * inp.pinion_torque / pair.pinion.reference,
        inp.pinion_speed,
    )
}

/// [`rate`] prepared once for many loads and speeds of one pair (a run rates a mesh at every
/// step): the factors that depend on neither the load nor the speed (`Z_H`, `Z_ε`, `Z_β`,
/// `Z_B`/`Z_D`, the ISO 1328-1 deviations, `K_Fβ`, `Y_DT`, the life and size factors, `σ_FG`)
/// are taken here, by the same functions in the same order as [`rate`] takes them, which is
/// [`PreparedIso::new`] then [`PreparedIso::rate`]: one computation, the same bits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedIso {
    inp: IsoInputs,
    /// Teeth `z1`, `z2` (negative: internal), module \[m\], reference pressure angle \[rad\],
    /// face width \[m\], pinion reference diameter \[m\].
    z: [f64; 2],
    module: f64,
    alpha: f64,
    face_width: f64,
    d1: f64,
    internal: bool,
    /// Profile shifts and dedendum coefficients, for the mesh stiffness.
    shift: [f64; 2],
    dedendum: [f64; 2],
    alpha_wt: f64,
    eps: f64,
    z_h: f64,
    z_eps: f64,
    z_beta: f64,
    z_bd: [f64; 2],
    /// `(f_pb, f_fα)` of the accuracy grade \[m\], if given.
    deviations: Option<(f64, f64)>,
    /// The pinion's mean of tip and root diameters and base diameter \[m\].
    dm1: f64,
    db1: f64,
    /// Running-in tip relief `C_a` \[m\].
    tip_relief: f64,
    k_fb: f64,
    y_dt: f64,
    y_beta: f64,
    /// `ρ_red` at the pitch point \[m\], for `Z_L Z_v Z_R`.
    rho_red: f64,
    z_nt: [f64; 2],
    z_x: [f64; 2],
    y_nt: [f64; 2],
    y_x: [f64; 2],
    sigma_fg: [f64; 2],
}

impl PreparedIso {
    /// `pair` with the inputs `inp` (its `pinion_torque` and `pinion_speed` are not read: they
    /// are [`PreparedIso::rate`]'s). Errors name the input, as [`rate`]'s.
    pub fn new(pair: &GearPair, inp: &IsoInputs) -> Result<Self, GearError> {
        validate_fixed(inp)?;
        let s = &pair.spec;
        let (m, alpha) = (s.module, s.pressure_angle);
        let z1 = s.pinion.teeth as f64;
        let z2 = s.gear.teeth as f64;
        let d1 = pair.pinion.reference;
        let alpha_wt = pair.operating_pressure_angle;
        let eps = pair.contact_ratio;
        let z_h = pit::zone_factor(0.0, alpha_wt, alpha);
        let z_eps = pit::contact_ratio_factor(eps, 0.0);
        let z_beta = pit::helix_angle_factor(0.0);
        let da = [pair.pinion.tip, pair.gear.tip];
        let db = [pair.pinion.base, pair.gear.base];
        let df = [pair.pinion.root, pair.gear.root];
        let (zb, zd) =
            pit::single_pair_factors(z1, z2.abs(), da, db, alpha_wt, eps, 0.0, pair.internal);
        // ISO 6336-1 §9, §8.3.4.
        let deviations = match inp.accuracy_grade {
            Some(q) => {
                let a = iso1328_deviations(m, d1, q)?;
                let g = iso1328_deviations(m, pair.gear.reference, q)?;
                // The larger of the two gears' deviations, f_pb = f_pt cos α.
                Some((a.0.max(g.0) * alpha.cos(), a.1.max(g.1)))
            }
            None => None,
        };
        if let IsoDynamic::MethodB { density } = inp.dynamic {
            positive("density", density)?;
        }
        let method_b = matches!(inp.dynamic, IsoDynamic::MethodB { .. })
            || inp.transverse_load_factor.is_none();
        if method_b && deviations.is_none() {
            return Err(GearError::InvalidInput {
                field: "accuracy_grade",
                rule: "ISO 6336-1 method B K_v and K_Hα need the ISO 1328-1 accuracy grade (or give both factors)",
                value: f64::NAN,
            });
        }
        let tip_relief = 0.5
            * (running_in_tip_relief(inp.members[0].sigma_hlim)
                + running_in_tip_relief(inp.members[1].sigma_hlim));
        let h = [(da[0] - df[0]).abs() / 2.0, (da[1] - df[1]).abs() / 2.0];
        let b = inp.face_width;
        let k_fb = face_load_factor_root(inp.face_load_factor, (b / h[0]).min(b / h[1]));
        // `ρ_red` at the pitch point; internal: the ring's concave flank, ρ1 ρ2/(ρ2 − ρ1).
        let r1 = 0.5 * db[0] * alpha_wt.tan();
        let r2 = 0.5 * db[1] * alpha_wt.tan();
        let rho_red = if pair.internal {
            r1 * r2 / (r2 - r1)
        } else {
            r1 * r2 / (r1 + r2)
        };
        let mut p = Self {
            inp: *inp,
            z: [z1, z2],
            module: m,
            alpha,
            face_width: b,
            d1,
            internal: pair.internal,
            shift: [s.pinion.shift, s.gear.shift],
            dedendum: [s.pinion.dedendum_coefficient, s.gear.dedendum_coefficient],
            alpha_wt,
            eps,
            z_h,
            z_eps,
            z_beta,
            z_bd: [zb, zd],
            deviations,
            dm1: 0.5 * (da[0] + df[0]),
            db1: db[0],
            tip_relief,
            k_fb,
            y_dt: bend::deep_tooth_factor(eps, inp.accuracy_grade),
            y_beta: bend::helix_angle_factor(0.0, 0.0),
            rho_red,
            z_nt: [0.0; 2],
            z_x: [0.0; 2],
            y_nt: [0.0; 2],
            y_x: [0.0; 2],
            sigma_fg: [0.0; 2],
        };
        for k in 0..2 {
            let mb = &inp.members[k];
            p.z_nt[k] = pit::life_factor_contact(mb.life_curve, mb.cycles)?;
            p.z_x[k] = pit::size_factor_contact(mb.life_curve, m);
            p.y_nt[k] = bend::life_factor_root(mb.life_curve, mb.cycles);
            p.y_x[k] = bend::size_factor_root(mb.life_curve, m);
            p.sigma_fg[k] = bend::root_stress_limit(
                mb.sigma_flim,
                p.y_nt[k],
                mb.notch_sensitivity,
                mb.surface_factor,
                p.y_x[k],
            );
        }
        Ok(p)
    }

    /// The rating at the nominal tangential load `ft` at the reference circle \[N\], positive,
    /// and the pinion speed relative to the gear's frame `pinion_speed` \[rad/s\], not negative
    /// (at rest the resonance ratio is 0 and method B's `K_v` is 1).
    pub fn rate(&self, ft: f64, pinion_speed: f64) -> Result<IsoRating, GearError> {
        positive("tangential load F_t", ft)?;
        crate::error::non_negative("pinion speed", pinion_speed)?;
        let inp = &self.inp;
        let [z1, z2] = self.z;
        let u = z2 / z1;
        let (b, d1, eps) = (self.face_width, self.d1, self.eps);
        let v = pinion_speed * d1 / 2.0;
        let k_a = inp.application_factor;
        let line_load = k_a * ft / b;
        let (c1, c_ga) = mesh_stiffness(
            z1,
            z2,
            self.shift[0],
            self.shift[1],
            self.dedendum,
            self.alpha,
            eps,
            line_load,
        );
        // `new` refused method B without the deviations.
        let f_pb = self.deviations.map_or(0.0, |(f_pb, _)| f_pb);
        let (k_v, resonance) = self.dynamic_factor(pinion_speed, line_load, c1, c_ga)?;
        let k_hb = inp.face_load_factor;
        let (k_ha, k_fa) = match inp.transverse_load_factor {
            Some(k) => (k, k),
            None => {
                let f_th_b = ft * k_a * k_v * k_hb / b;
                transverse_load_factors(
                    eps,
                    self.z_eps,
                    c_ga,
                    f_pb - self.running_in(f_pb, v),
                    f_th_b,
                )
            }
        };
        // Contact (ISO 6336-2).
        let z_e = inp.elasticity_factor;
        let sigma_h0 =
            pit::nominal_contact_stress(ft, d1, b, u, self.z_h, z_e, self.z_eps, self.z_beta);
        let z_lvr = match inp.lubrication {
            None => [1.0; 3],
            Some(l) => {
                let s_lim = inp.members[0].sigma_hlim.min(inp.members[1].sigma_hlim);
                pit::lubrication_factors(s_lim, l.viscosity_40, v, l.flank_roughness, self.rho_red)
            }
        };
        let mut out = IsoRating {
            tangential_load: ft,
            velocity: v,
            resonance_ratio: resonance,
            k_a,
            k_v,
            k_hbeta: k_hb,
            k_halpha: k_ha,
            k_fbeta: self.k_fb,
            k_falpha: k_fa,
            z_h: self.z_h,
            z_e,
            z_eps: self.z_eps,
            z_beta: self.z_beta,
            z_bd: self.z_bd,
            z_nt: self.z_nt,
            z_lvr,
            z_w: 1.0,
            z_x: self.z_x,
            sigma_h0,
            sigma_h: [0.0; 2],
            sigma_hg: [0.0; 2],
            s_h: [0.0; 2],
            y_beta: self.y_beta,
            y_dt: self.y_dt,
            y_f: inp.members.map(|m| m.form_factor),
            y_s: inp.members.map(|m| m.stress_correction_factor),
            y_nt: self.y_nt,
            y_x: self.y_x,
            sigma_f0: [0.0; 2],
            sigma_f: [0.0; 2],
            sigma_fg: self.sigma_fg,
            s_f: [0.0; 2],
        };
        self.rate_members(&mut out, ft);
        Ok(out)
    }

    /// The dynamic factor `K_v`, given or by method B (ISO 6336-1:2019 §6.5.4 to §6.5.8) with
    /// the resonance ratio it was taken at, at the pinion speed `pinion_speed` \[rad/s\], the
    /// line load `line_load` and the mesh stiffnesses `c1`, `c_ga` of [`mesh_stiffness`].
    fn dynamic_factor(
        &self,
        pinion_speed: f64,
        line_load: f64,
        c1: f64,
        c_ga: f64,
    ) -> Result<(f64, Option<f64>), GearError> {
        let [z1, z2] = self.z;
        let eps = self.eps;
        let v = pinion_speed * self.d1 / 2.0;
        // `new` refused method B without the deviations.
        let (f_pb, f_fa) = self.deviations.unwrap_or((0.0, 0.0));
        Ok(match self.inp.dynamic {
            IsoDynamic::Given(k) => (k, None),
            IsoDynamic::MethodB { density } => {
                let n = resonance_ratio(
                    pinion_speed,
                    z1,
                    z2 / z1,
                    self.internal,
                    self.dm1,
                    self.db1,
                    density,
                    c_ga,
                );
                let k = dynamic_factor_b(&DynamicInputs {
                    resonance_ratio: n,
                    line_load,
                    single_stiffness: c1,
                    f_pb_eff: f_pb - self.running_in(f_pb, v),
                    f_fa_eff: f_fa - self.running_in(f_fa, v),
                    tip_relief: self.tip_relief,
                    total_contact_ratio: eps,
                })?;
                (k, Some(n))
            }
        })
    }

    /// The running-in allowance of a deviation `f` \[m\] at the pitch-line velocity `v`
    /// \[m/s\]: the mean of the two members' [`running_in_allowance`] (ISO 6336-1:2019 §8.3.4).
    fn running_in(&self, f: f64, v: f64) -> f64 {
        let [p, g] = self.inp.members;
        0.5 * (running_in_allowance(running_in_class(p.life_curve), f, p.sigma_hlim, v)
            + running_in_allowance(running_in_class(g.life_curve), f, g.sigma_hlim, v))
    }

    /// The per-member stresses, limits and safety factors, once the pair's factors are in
    /// `out`.
    fn rate_members(&self, out: &mut IsoRating, ft: f64) {
        let (k_a, k_v, k_hb, k_ha) = (out.k_a, out.k_v, out.k_hbeta, out.k_halpha);
        let (k_fb, k_fa, z_lvr, z_w) = (out.k_fbeta, out.k_falpha, out.z_lvr, out.z_w);
        let (sigma_h0, y_dt) = (out.sigma_h0, out.y_dt);
        for k in 0..2 {
            let mb = &self.inp.members[k];
            let sh = pit::contact_stress(out.z_bd[k], sigma_h0, k_a, k_v, k_hb, k_ha);
            let shg = pit::pitting_stress_limit(
                mb.sigma_hlim,
                [out.z_nt[k], z_lvr[0], z_lvr[1], z_lvr[2], z_w, out.z_x[k]],
            );
            let sf0 = bend::nominal_root_stress(
                ft,
                self.face_width,
                self.module,
                mb.form_factor,
                mb.stress_correction_factor,
                out.y_beta,
                mb.rim_factor,
                y_dt,
            );
            let sf = bend::root_stress(sf0, k_a, k_v, k_fb, k_fa);
            out.sigma_h[k] = sh;
            out.sigma_hg[k] = shg;
            out.s_h[k] = shg / sh;
            out.sigma_f0[k] = sf0;
            out.sigma_f[k] = sf;
            out.s_f[k] = out.sigma_fg[k] / sf;
        }
    }
}

/// Checks the inputs of [`rate`].
fn validate(inp: &IsoInputs) -> Result<(), GearError> {
    positive("pinion torque", inp.pinion_torque)?;
    positive("pinion speed", inp.pinion_speed)?;
    validate_fixed(inp)
}

/// Checks the inputs of [`PreparedIso::new`]: all but the load and the speed.
fn validate_fixed(inp: &IsoInputs) -> Result<(), GearError> {
    positive("face width", inp.face_width)?;
    positive("application factor K_A", inp.application_factor)?;
    positive("face load factor K_Hβ", inp.face_load_factor)?;
    positive("elasticity factor Z_E", inp.elasticity_factor)?;
    for m in &inp.members {
        positive("sigma_hlim", m.sigma_hlim)?;
        positive("sigma_flim", m.sigma_flim)?;
        positive("form factor Y_F", m.form_factor)?;
        positive("stress correction factor Y_S", m.stress_correction_factor)?;
        positive("rim factor Y_B", m.rim_factor)?;
        positive("notch sensitivity Y_δrelT", m.notch_sensitivity)?;
        positive("surface factor Y_RrelT", m.surface_factor)?;
        positive("load cycles", m.cycles)?;
    }
    Ok(())
}
