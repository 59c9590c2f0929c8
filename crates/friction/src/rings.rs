//! Piston-ring friction.
//!
//! Two models:
//!
//! * [`KarhulaRingPack`]: Karhula (2008) App. 9.1, A9.1.2–A9.1.4 and A9.1.8: two compression
//!   rings and one oil ring pressed by constant contact pressures over their heights, with a
//!   constant friction coefficient μ_ring = 0.07 (Andersson et al. 2002). The force does not
//!   depend on speed, gas pressure or oil.
//! * [`RingFilm`]: one ring on an oil film, Furuhama (1959) style, as set up in the Thai thesis
//!   §2.5.c (eqs 2.5.c.5–2.5.c.7): the 1-D Reynolds equation with sliding and squeeze terms,
//!   ∂/∂x(h³ ∂p/∂x) = 6μU ∂h/∂x + 12μ ∂h/∂t, on the ring face h(x) = h_min + s(x) (parabolic
//!   barrel, taper or the thesis's parabola + flat), solved in closed form on a grid with the
//!   cumulative integrals F = ∫dx/h², H = ∫x dx/h³, G = ∫dx/h³ of the thesis (eq. 2.5.c.6). Unlike
//!   the thesis (p = 0 at both ends, film fixed) the outlet obeys the Reynolds cavitation
//!   condition p = ∂p/∂x = 0, the film thickness follows from the radial load balance, and a
//!   Greenwood–Tripp asperity pressure (Greenwood & Tripp 1970, with the fit
//!   F_{5/2}(λ) = 4.4086e-5 (4 − λ)^6.804 of Hu et al. 1994) carries what the film cannot, with a
//!   boundary friction coefficient: this gives the mixed-lubrication (Stribeck) transition
//!   continuously as the film thins at low speed.
//!
//! The film model is usable in two ways:
//!
//! * quasi-steady ([`RingFilm::quasi_steady`]): ∂h/∂t = 0, h_min from the instantaneous load and
//!   speed only (no memory). This is the usual simplification away from the dead centres; at the
//!   dead centres it predicts film collapse to the asperities (boundary friction), where the real
//!   squeeze film would still carry part of the load;
//! * dynamic ([`RingFilm::step`]): the caller keeps the film state [`RingFilmState`] and steps it
//!   with backward Euler, ∂h/∂t = (h_new − h_old)/Δt, solving the load balance for h_new each
//!   step (unconditionally stable, so crank-angle steps of a degree are fine).
//!
//! The radial load per unit circumference is (p_elastic + p_gas behind the ring) · b, the face
//! pressure boundary values are ambient (0) on both sides (gas pressure on the face ignored, as
//! in the thesis), and the oil supply is fully flooded.

use crate::{positive, FrictionError, SlidingLoss};
use std::f64::consts::PI;

/// Ring friction coefficient μ_ring of Karhula (2008) App. 9.1 (A9.1.4, from Andersson et al.
/// 2002).
pub const KARHULA_RING_MU: f64 = 0.07;

/// Karhula's (2008) constant-coefficient ring pack.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct KarhulaRingPack {
    /// Piston diameter d_pis, m.
    pub piston_diameter: f64,
    /// Number of compression rings (Karhula: 2).
    pub compression_rings: u32,
    /// Height (axial width) of a compression ring, m (Karhula: 2 mm, A9.1.2).
    pub compression_ring_height: f64,
    /// Contact pressure of a compression ring, Pa (Karhula: 0.19 N/mm², Andersson et al. 2002).
    pub compression_ring_pressure: f64,
    /// Number of oil rings (Karhula: 1).
    pub oil_rings: u32,
    /// Height of an oil ring, m (Karhula: 4 mm, A9.1.2).
    pub oil_ring_height: f64,
    /// Contact pressure of an oil ring, Pa (Karhula: 1 N/mm²).
    pub oil_ring_pressure: f64,
    /// Ring friction coefficient μ_ring (Karhula: 0.07).
    pub friction_coefficient: f64,
}

impl KarhulaRingPack {
    /// Karhula's pack for a piston of diameter `piston_diameter` (m): 2 compression rings of
    /// 2 mm at 0.19 MPa, 1 oil ring of 4 mm at 1 MPa, μ = 0.07. The ring heights of A9.1.2 are
    /// missing from the seed's text; 2 mm / 4 mm are as quoted in
    /// `docs/validation/engine-friction.md`.
    pub fn karhula(piston_diameter: f64) -> Result<Self, FrictionError> {
        Ok(Self {
            piston_diameter: positive("piston_diameter", piston_diameter)?,
            compression_rings: 2,
            compression_ring_height: 2e-3,
            compression_ring_pressure: 0.19e6,
            oil_rings: 1,
            oil_ring_height: 4e-3,
            oil_ring_pressure: 1e6,
            friction_coefficient: KARHULA_RING_MU,
        })
    }

    /// Total ring contact force, N: F_cont = n_co p_co π d h_co + n_oil p_oil π d h_oil
    /// (A9.1.3 with A_ring = π d_pis h_ring).
    pub fn contact_force(&self) -> f64 {
        let circ = PI * self.piston_diameter;
        f64::from(self.compression_rings)
            * self.compression_ring_pressure
            * circ
            * self.compression_ring_height
            + f64::from(self.oil_rings) * self.oil_ring_pressure * circ * self.oil_ring_height
    }

    /// Ring friction at piston speed `piston_speed` (m/s): F = μ_ring F_cont against the piston
    /// velocity (A9.1.4), P = F |v| (A9.1.8).
    pub fn loss(&self, piston_speed: f64) -> SlidingLoss {
        let f = self.friction_coefficient * self.contact_force();
        SlidingLoss {
            friction_force: f,
            power: f * piston_speed.abs(),
        }
    }
}

/// Running-face profile of a ring: the film thickness is h(x) = h_min + s(x), 0 ≤ x ≤ b, with
/// x = 0 at the edge that leads when the ring slides with positive speed (the model mirrors the
/// profile for negative speed).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum RingProfile {
    /// Symmetric parabolic barrel: s(x) = δ (2x/b − 1)² (Furuhama 1959; the usual compression
    /// ring face).
    Barrel {
        /// Face width b, m.
        width: f64,
        /// Crown height δ (rise of the face at the edges above its lowest point), m.
        crown_height: f64,
    },
    /// Linear taper: s(x) = δ (1 − x/b), thickest at the leading edge (a taper-faced ring
    /// sliding towards its thick edge; also the classic inclined-pad slider).
    Taper {
        /// Face width b, m.
        width: f64,
        /// Rise δ of the leading edge above the trailing edge, m.
        rise: f64,
    },
    /// The Thai thesis's face (eq. 2.5.c.4 and the profile below eq. 2.5.c.8): a parabola
    /// a1 x² + b1 x + δ on 0 ≤ x ≤ r_p b′ reaching the flat h_min at x = r_p b′, then flat to
    /// b = (1 + r_p) b′; δ = b/1000, b1 = −(δ/(r_p b′) + a1 r_p b′).
    Thai {
        /// Width of the flat part b′, m (thesis example 3 mm).
        flat_width: f64,
        /// Ratio r_p of the parabolic to the flat width (0.5 pressure ring, 1 oil ring).
        parabola_ratio: f64,
        /// Parabola coefficient a1, 1/m (thesis: 0.0015 mm⁻¹ = 1.5 m⁻¹ for the pressure ring,
        /// 0.0025 mm⁻¹ = 2.5 m⁻¹ for the oil ring).
        a1: f64,
    },
}

impl RingProfile {
    /// Lubricated face width b, m.
    pub fn width(&self) -> f64 {
        match *self {
            RingProfile::Barrel { width, .. } | RingProfile::Taper { width, .. } => width,
            RingProfile::Thai {
                flat_width,
                parabola_ratio,
                ..
            } => (1.0 + parabola_ratio) * flat_width,
        }
    }

    /// Height s(x) of the face above its lowest point at x (0 ≤ x ≤ b), m.
    pub fn offset(&self, x: f64) -> f64 {
        match *self {
            RingProfile::Barrel {
                width,
                crown_height,
            } => {
                let t = 2.0 * x / width - 1.0;
                crown_height * t * t
            }
            RingProfile::Taper { width, rise } => rise * (1.0 - x / width),
            RingProfile::Thai {
                flat_width,
                parabola_ratio,
                a1,
            } => {
                let xm = parabola_ratio * flat_width;
                if x >= xm {
                    0.0
                } else {
                    let delta = self.width() / 1000.0;
                    let b1 = -(delta / xm + a1 * xm);
                    (a1 * x * x + b1 * x + delta).max(0.0)
                }
            }
        }
    }
}

/// Greenwood–Tripp rough-surface contact between ring face and liner.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AsperityContact {
    /// Composite RMS roughness σ = √(σ1² + σ2²), m.
    pub composite_roughness: f64,
    /// Pressure coefficient K E′ of p_a = K E′ F_{5/2}(h/σ), Pa, with
    /// K = (8√2/15) π (ηβσ)² √(σ/β) and 1/E′ = (1 − ν1²)/E1 + (1 − ν2²)/E2 (Greenwood & Tripp
    /// 1970).
    pub pressure_coefficient: f64,
    /// Boundary friction coefficient of the asperity contacts μ_b.
    pub boundary_friction: f64,
}

impl AsperityContact {
    /// Typical values for a steel ring on a cast-iron liner: σ = 0.4 µm; ηβσ = 0.04 and
    /// σ/β = 0.001 (Hu et al. 1994), E = 210/120 GPa, ν = 0.3/0.26, so K E′ ≈ 9.9 MPa;
    /// μ_b = 0.1. Engineering defaults, not from the seeds: calibrate for real work.
    pub fn typical() -> Self {
        let k = 8.0 * 2f64.sqrt() / 15.0 * PI * 0.04f64.powi(2) * 0.001f64.sqrt();
        let e_inv = (1.0 - 0.3f64.powi(2)) / 210e9 + (1.0 - 0.26f64.powi(2)) / 120e9;
        Self {
            composite_roughness: 0.4e-6,
            pressure_coefficient: k / e_inv,
            boundary_friction: 0.1,
        }
    }

    /// Asperity contact pressure at local film thickness `h` (m), Pa:
    /// K E′ · 4.4086e-5 (4 − h/σ)^6.804 for h/σ < 4, else 0 (Hu et al. 1994 fit of
    /// Greenwood–Tripp's F_{5/2}).
    pub fn pressure(&self, h: f64) -> f64 {
        let lambda = h / self.composite_roughness;
        if lambda >= 4.0 {
            0.0
        } else {
            self.pressure_coefficient * 4.4086e-5 * (4.0 - lambda.max(0.0)).powf(6.804)
        }
    }
}

/// Radial load on a ring.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct RingLoad {
    /// Elastic (tension) contact pressure of the ring over its face, Pa.
    pub elastic_pressure: f64,
    /// Gas pressure behind the ring (in the groove), gauge, Pa. For the top ring this is about
    /// the cylinder pressure above ambient; for lower rings the inter-ring pressure.
    pub gas_pressure_behind: f64,
}

/// A ring on an oil film: profile, bore and surface contact.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RingFilm {
    /// Running-face profile.
    pub profile: RingProfile,
    /// Bore (liner) diameter, m; the ring's sliding length is π times this.
    pub bore: f64,
    /// Asperity contact model.
    pub asperity: AsperityContact,
}

/// State and friction of a ring film at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct RingFilmState {
    /// Minimum film thickness h_min, m (the state a dynamic caller keeps).
    pub min_film_thickness: f64,
    /// Squeeze velocity ∂h/∂t, m/s (0 when quasi-steady).
    pub squeeze_velocity: f64,
    /// Load carried by the oil film per unit circumference, N/m.
    pub film_load: f64,
    /// Load carried by asperities per unit circumference, N/m.
    pub asperity_load: f64,
    /// Hydrodynamic (viscous shear) friction per unit circumference, N/m.
    pub hydrodynamic_friction: f64,
    /// Boundary friction μ_b × asperity load, per unit circumference, N/m.
    pub boundary_friction: f64,
    /// Viscous dissipation in the film per unit circumference, W/m (∫ μ(∂u/∂y)² dy dx; equals
    /// hydrodynamic friction × |U| in steady state, an energy check).
    pub viscous_dissipation: f64,
    /// Total friction on the ring and power.
    pub loss: SlidingLoss,
}

/// Grid intervals across the ring face.
const GRID: usize = 400;

/// Film pressure integrals of one evaluation.
#[derive(Debug, Clone, Copy, Default)]
struct Film {
    load: f64,
    friction: f64,
    dissipation: f64,
}

impl RingFilm {
    /// A ring film; `bore` must be positive.
    pub fn new(
        profile: RingProfile,
        bore: f64,
        asperity: AsperityContact,
    ) -> Result<Self, FrictionError> {
        positive("bore", bore)?;
        positive("profile width", profile.width())?;
        Ok(Self {
            profile,
            bore,
            asperity,
        })
    }

    /// Offsets s(x_i) on the grid, mirrored for negative speed.
    fn offsets(&self, speed: f64) -> ([f64; GRID + 1], f64) {
        let b = self.profile.width();
        let dx = b / GRID as f64;
        let mut s = [0.0; GRID + 1];
        for (i, si) in s.iter_mut().enumerate() {
            let x = i as f64 * dx;
            let xm = if speed < 0.0 { b - x } else { x };
            *si = self.profile.offset(xm);
        }
        (s, dx)
    }

    /// Hydrodynamic load, friction and dissipation per unit circumference for minimum film
    /// `h_min`, sliding speed magnitude `u` ≥ 0 (profile already mirrored) and squeeze velocity
    /// `hdot`, with the Reynolds (p = ∂p/∂x = 0) outlet condition.
    fn film(s: &[f64; GRID + 1], dx: f64, mu: f64, u: f64, h_min: f64, hdot: f64) -> Film {
        let n = GRID;
        let mut h = [0.0; GRID + 1];
        for i in 0..=n {
            h[i] = h_min + s[i];
        }
        // Cumulative trapezoid integrals F = ∫dx/h², H = ∫x dx/h³, G = ∫dx/h³ (thesis 2.5.c.6).
        let mut f = [0.0; GRID + 1];
        let mut hh = [0.0; GRID + 1];
        let mut g = [0.0; GRID + 1];
        for i in 1..=n {
            let (x0, x1) = ((i - 1) as f64 * dx, i as f64 * dx);
            let (h0, h1) = (h[i - 1], h[i]);
            f[i] = f[i - 1] + 0.5 * dx * (1.0 / (h0 * h0) + 1.0 / (h1 * h1));
            hh[i] = hh[i - 1] + 0.5 * dx * (x0 / h0.powi(3) + x1 / h1.powi(3));
            g[i] = g[i - 1] + 0.5 * dx * (1.0 / h0.powi(3) + 1.0 / h1.powi(3));
        }
        let a = 6.0 * mu * u;
        let q = 12.0 * mu * hdot;
        // R(x_c) = p(x_c) when C is chosen so that ∂p/∂x(x_c) = 0; its first return to zero
        // after being positive is the Reynolds outlet.
        let r = |i: usize| a * f[i] + q * hh[i] - (a * h[i] + q * i as f64 * dx) * g[i];
        let mut seen_positive = false;
        let mut outlet: Option<(usize, f64)> = None; // (last film node, x_c)
        for i in 1..=n {
            let ri = r(i);
            if ri > 0.0 {
                seen_positive = true;
            } else if seen_positive {
                let rp = r(i - 1);
                let t = rp / (rp - ri);
                outlet = Some((i - 1, (i as f64 - 1.0 + t) * dx));
                break;
            }
        }
        // Pressure constant C of h³ ∂p/∂x = 6μU h + 12μ ḣ x + C, the film end and h there.
        let (c, last, xc) = if !seen_positive {
            // No pressure builds up (diverging or separating film): ambient pressure, full film.
            let mut out = Film::default();
            for (i, hi) in h.iter().enumerate() {
                let w = if i == 0 || i == n { 0.5 } else { 1.0 };
                out.friction += w * dx * mu * u / hi;
                out.dissipation += w * dx * mu * u * u / hi;
            }
            return out;
        } else if let Some((k, xc)) = outlet {
            let hc = h_min + lerp_at(s, dx, xc);
            (-(a * hc + q * xc), k, xc)
        } else {
            // Pressure positive to the trailing edge: full film, p(b) = 0.
            (-(a * f[n] + q * hh[n]) / g[n], n, n as f64 * dx)
        };
        let hc = h_min + lerp_at(s, dx, xc);
        let mut out = Film::default();
        let mut p_prev = 0.0;
        let mut prev_tau = 0.0;
        let mut prev_diss = 0.0;
        for i in 0..=n {
            let x = i as f64 * dx;
            let (p, tau, diss) = if i <= last {
                let p = (a * f[i] + q * hh[i] + c * g[i]).max(0.0);
                let dpdx = (a * h[i] + q * x + c) / h[i].powi(3);
                (
                    p,
                    mu * u / h[i] + 0.5 * h[i] * dpdx,
                    mu * u * u / h[i] + h[i].powi(3) * dpdx * dpdx / (12.0 * mu),
                )
            } else {
                // Cavitated: streamers fill the fraction h_c/h of the gap.
                let fill = (hc / h[i]).min(1.0);
                (0.0, fill * mu * u / h[i], fill * mu * u * u / h[i])
            };
            if i > 0 {
                let x0 = x - dx;
                // Split the interval at the outlet so the film/cavitation change is integrated
                // exactly to first order.
                if i == last + 1 && xc > x0 && xc < x {
                    let w1 = xc - x0;
                    let w2 = x - xc;
                    out.load += 0.5 * w1 * p_prev;
                    out.friction += 0.5 * w1 * (prev_tau + prev_tau) + 0.5 * w2 * (tau + tau);
                    out.dissipation +=
                        0.5 * w1 * (prev_diss + prev_diss) + 0.5 * w2 * (diss + diss);
                } else {
                    out.load += 0.5 * dx * (p_prev + p);
                    out.friction += 0.5 * dx * (prev_tau + tau);
                    out.dissipation += 0.5 * dx * (prev_diss + diss);
                }
            }
            p_prev = p;
            prev_tau = tau;
            prev_diss = diss;
        }
        out
    }

    /// Asperity load per unit circumference, N/m.
    fn asperity_load(&self, s: &[f64; GRID + 1], dx: f64, h_min: f64) -> f64 {
        // The offsets are non-negative: no asperity touches once h_min is 4σ.
        if h_min >= 4.0 * self.asperity.composite_roughness {
            return 0.0;
        }
        let mut w = 0.0;
        for (i, si) in s.iter().enumerate() {
            let wt = if i == 0 || i == GRID { 0.5 } else { 1.0 };
            w += wt * dx * self.asperity.pressure(h_min + si);
        }
        w
    }

    /// Film and asperity response to a prescribed minimum film `min_film_thickness` (m) and
    /// squeeze velocity `squeeze_velocity` (m/s, negative when closing), at sliding speed
    /// `sliding_speed` (m/s) and viscosity `viscosity` (Pa·s). No load balance: this is the
    /// building block of [`quasi_steady`](Self::quasi_steady) and [`step`](Self::step).
    pub fn evaluate(
        &self,
        viscosity: f64,
        sliding_speed: f64,
        min_film_thickness: f64,
        squeeze_velocity: f64,
    ) -> RingFilmState {
        let (s, dx) = self.offsets(sliding_speed);
        let u = sliding_speed.abs();
        let film = Self::film(&s, dx, viscosity, u, min_film_thickness, squeeze_velocity);
        let wa = self.asperity_load(&s, dx, min_film_thickness);
        let (hydro, boundary) = if u == 0.0 {
            (0.0, 0.0)
        } else {
            (film.friction, self.asperity.boundary_friction * wa)
        };
        let circ = PI * self.bore;
        let force = (hydro + boundary) * circ;
        RingFilmState {
            min_film_thickness,
            squeeze_velocity,
            film_load: film.load,
            asperity_load: wa,
            hydrodynamic_friction: hydro,
            boundary_friction: boundary,
            viscous_dissipation: film.dissipation,
            loss: SlidingLoss {
                friction_force: force,
                power: force * u,
            },
        }
    }

    /// Radial load per unit circumference, N/m: (p_elastic + p_gas) · b.
    pub fn load_per_length(&self, load: RingLoad) -> f64 {
        (load.elastic_pressure + load.gas_pressure_behind).max(0.0) * self.profile.width()
    }

    /// Solves the load balance film + asperities = `target` (N/m) for h in [1e-10, 1e-3] m,
    /// with ḣ = `hdot(h)`; the carried load decreases monotonically with h. The root is
    /// bracketed outwards from `guess` (the previous step's film, when stepping) by factors of
    /// 4 and then found by the Illinois variant of regula falsi on ln h to 1e-10 in ln h or
    /// 1e-10 of the load: about a dozen film evaluations instead of the 45 of a bisection.
    fn solve(
        &self,
        target: f64,
        guess: Option<f64>,
        eval: impl Fn(f64) -> RingFilmState,
    ) -> RingFilmState {
        let (floor, ceiling) = (1e-10_f64.ln(), 1e-3_f64.ln());
        // g(x) = carried(e^x) − target, decreasing in x.
        let g = |x: f64| {
            let st = eval(x.exp());
            (st.film_load + st.asperity_load - target, st)
        };
        let start = guess
            .filter(|h| h.is_finite() && *h > 0.0)
            .map_or(0.5 * (floor + ceiling), |h| h.ln().clamp(floor, ceiling));
        let (mut lo, mut hi) = (start, start);
        let (mut g_lo, st) = g(start);
        if g_lo == 0.0 {
            return st;
        }
        let mut g_hi = g_lo;
        let step = 4f64.ln();
        // Expand until g(lo) > 0 > g(hi), or a limit is reached.
        while g_lo < 0.0 {
            if lo <= floor {
                return eval(floor.exp());
            }
            hi = lo;
            g_hi = g_lo;
            lo = (lo - step).max(floor);
            g_lo = g(lo).0;
        }
        while g_hi > 0.0 {
            if hi >= ceiling {
                return eval(ceiling.exp());
            }
            lo = hi;
            g_lo = g_hi;
            hi = (hi + step).min(ceiling);
            g_hi = g(hi).0;
        }
        let mut side = 0;
        let mut best = (lo, g_lo);
        for _ in 0..100 {
            let x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
            let (gx, st) = g(x);
            if gx.abs() <= 1e-10 * target.abs() || hi - lo < 1e-10 {
                return st;
            }
            if gx > 0.0 {
                lo = x;
                g_lo = gx;
                if side == 1 {
                    g_hi *= 0.5;
                }
                side = 1;
            } else {
                hi = x;
                g_hi = gx;
                if side == -1 {
                    g_lo *= 0.5;
                }
                side = -1;
            }
            best = (x, gx);
        }
        eval(best.0.exp())
    }

    /// Quasi-steady ring film (∂h/∂t = 0): h_min such that film + asperity load equals the
    /// radial load at the instantaneous sliding speed `sliding_speed` (m/s), viscosity
    /// `viscosity` (Pa·s) and `load`. Depends on instantaneous inputs only.
    pub fn quasi_steady(
        &self,
        viscosity: f64,
        sliding_speed: f64,
        load: RingLoad,
    ) -> RingFilmState {
        let target = self.load_per_length(load);
        self.solve(target, None, |h| {
            self.evaluate(viscosity, sliding_speed, h, 0.0)
        })
    }

    /// One backward-Euler step of the squeeze-film state: from the previous minimum film
    /// `previous_min_film` (m) over `dt` (s) to the new state that balances `load` with
    /// ∂h/∂t = (h_new − h_old)/Δt. `dt` must be positive.
    pub fn step(
        &self,
        previous_min_film: f64,
        dt: f64,
        viscosity: f64,
        sliding_speed: f64,
        load: RingLoad,
    ) -> RingFilmState {
        let target = self.load_per_length(load);
        self.solve(target, Some(previous_min_film), |h| {
            self.evaluate(viscosity, sliding_speed, h, (h - previous_min_film) / dt)
        })
    }
}

/// Linear interpolation of grid values `s` at x.
fn lerp_at(s: &[f64; GRID + 1], dx: f64, x: f64) -> f64 {
    let t = (x / dx).clamp(0.0, GRID as f64);
    let i = (t.floor() as usize).min(GRID - 1);
    let w = t - i as f64;
    s[i] * (1.0 - w) + s[i + 1] * w
}

/// Friction per unit circumference of the Thai thesis's ring face with a fixed film, as printed
/// (eq. 2.5.c.8), N/m:
/// R′ = μU { 4∫₀^{x_m} dx/h − 3 (∫₀^{x_m} dx/h²)² / ∫₀^{x_m} dx/h³ + (b − x_m)/h_s },
/// with x_m = r_p b′ and h = h_s + s(x) of [`RingProfile::Thai`]. It treats the parabolic part as
/// a full-film pad with p = 0 at both of its ends and the flat as pure Couette shear; the
/// integrals are evaluated with 2000-interval Simpson quadrature. `profile` must be
/// [`RingProfile::Thai`] (returns NaN otherwise).
pub fn thai_ring_friction_per_length(
    profile: &RingProfile,
    viscosity: f64,
    sliding_speed: f64,
    min_film: f64,
) -> f64 {
    let RingProfile::Thai {
        flat_width,
        parabola_ratio,
        ..
    } = *profile
    else {
        return f64::NAN;
    };
    let xm = parabola_ratio * flat_width;
    let b = profile.width();
    let simpson = |k: i32| {
        let n = 2000;
        let dx = xm / n as f64;
        let mut acc = 0.0;
        for i in 0..=n {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            acc += w * (min_film + profile.offset(i as f64 * dx)).powi(-k);
        }
        acc * dx / 3.0
    };
    let (d, f, g) = (simpson(1), simpson(2), simpson(3));
    viscosity * sliding_speed.abs() * (4.0 * d - 3.0 * f * f / g + (b - xm) / min_film)
}

/// Ring-pack power of the Thai thesis (eq. 2.5.c.9): P = π B (R′_pr n_pr + R′_or n_or) U, W,
/// with the friction per unit length of a pressure ring `pressure_ring_friction` and of an oil
/// ring `oil_ring_friction` (N/m), their counts, bore `bore` (m) and speed `speed` (m/s; the
/// thesis uses the mean piston speed).
pub fn thai_ring_power(
    pressure_ring_friction: f64,
    pressure_rings: u32,
    oil_ring_friction: f64,
    oil_rings: u32,
    bore: f64,
    speed: f64,
) -> f64 {
    PI * bore
        * (pressure_ring_friction * f64::from(pressure_rings)
            + oil_ring_friction * f64::from(oil_rings))
        * speed.abs()
}
