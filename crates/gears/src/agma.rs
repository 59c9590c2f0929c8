//! AGMA 2001-D04 bending and pitting (contact) rating of spur gears, SI inside.
//!
//! Stresses (AGMA 2001-D04 eqs. 1 and 15 in their metric form; Shigley eqs. 14-15, 14-16):
//!
//! * bending `σ = Wt Ko Kv Ks (1/(b m)) (Km KB / J)`,
//! * contact `σc = Cp √(Wt Ko Kv Ks Km Cf / (d b I))`, `d` the **pinion** operating pitch
//!   diameter for both members,
//!
//! and safety factors (Shigley eqs. 14-41, 14-42) `SF = St YN / (KT KR) / σ`,
//! `SH = Sc ZN CH / (KT KR) / σc` (SH is a stress ratio; compare `SH²` with `SF`).
//! Factors: [`factors`]; geometry factors I and J: [`geometry_factors`]; face-width sizing:
//! [`GearSetRating::required_face_width`]; Nunes 2017's reading: [`nunes`].
//!
//! For an internal (cardan) pair the correct reading differs from Nunes's in three places:
//! `I` from the internal AGMA 908 form (`I ≈ 0.305` for 26/52, 25°, instead of the external
//! table's 0.117), the pinion operating pitch diameter in the contact stress of both members
//! (Nunes: each member's own diameter), and `Km` from the actual face width and the pinion
//! diameter (Nunes: from the maximum allowed face width and each member's own diameter).

pub mod factors;
pub mod geometry_factors;
pub mod nunes;

use crate::error::{non_negative, positive, require, GearError};

/// Per-member data of one gear of the set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemberData {
    /// Bending geometry factor `J` \[-\].
    pub j: f64,
    /// Rim thickness factor `KB` \[-\].
    pub rim: f64,
    /// Allowable bending stress number `St` \[Pa\].
    pub bending_allowable: f64,
    /// Allowable contact stress number `Sc` \[Pa\].
    pub contact_allowable: f64,
    /// Bending stress-cycle factor `YN` \[-\].
    pub yn: f64,
    /// Pitting stress-cycle factor `ZN` \[-\].
    pub zn: f64,
    /// Hardness-ratio factor `CH` \[-\] (1 for the pinion).
    pub ch: f64,
}

/// How the size factor `Ks` is obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SizeFactor {
    /// Given values `[pinion, gear]` \[-\] (AGMA: 1 unless known otherwise).
    Given([f64; 2]),
    /// Shigley eq. 14-10 from the Lewis form factors `[Y pinion, Y gear]` (depends on `b`).
    Shigley {
        /// Lewis form factors `[pinion, gear]` \[-\].
        lewis_y: [f64; 2],
    },
}

/// Everything of an AGMA rating except the load, the speed-dependent `Kv` and the face width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearSetRating {
    /// Transverse module `m` \[m\].
    pub module: f64,
    /// Pinion operating pitch diameter `d` \[m\].
    pub pinion_diameter: f64,
    /// Overload factor `Ko` \[-\].
    pub overload: f64,
    /// Load distribution inputs (`Km` is recomputed for each face width).
    pub load_distribution: factors::LoadDistribution,
    /// Size factor rule.
    pub size: SizeFactor,
    /// Surface condition factor `Cf` \[-\] (1 for normal finishes).
    pub surface_condition: f64,
    /// Pitting geometry factor `I` \[-\].
    pub geometry_i: f64,
    /// Elastic coefficient `Cp` \[√Pa\].
    pub elastic_coefficient: f64,
    /// Temperature factor `KT` \[-\].
    pub temperature: f64,
    /// Reliability factor `KR` \[-\].
    pub reliability: f64,
    /// Pinion data.
    pub pinion: MemberData,
    /// Gear data.
    pub gear: MemberData,
}

/// Result of a rating; arrays are `[pinion, gear]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rating {
    /// Load distribution factor used `Km` \[-\].
    pub km: f64,
    /// Size factors used `Ks` \[-\].
    pub ks: [f64; 2],
    /// Bending stresses `σ` \[Pa\].
    pub bending_stress: [f64; 2],
    /// Contact stresses `σc` \[Pa\] (differ only through `Ks`).
    pub contact_stress: [f64; 2],
    /// Bending safety factors `SF` \[-\].
    pub bending_safety: [f64; 2],
    /// Pitting safety factors `SH` \[-\] (stress ratio).
    pub contact_safety: [f64; 2],
}

/// [`GearSetRating::rate`] at one face width, rated step after step: what depends on neither
/// the load nor the speed (the checks of the set's data, `Km`, `Ks`) taken once. The same
/// arithmetic as [`GearSetRating::rate`], so the same bits, and the same errors (data that
/// fails a check is rated through [`GearSetRating::rate`], which says which).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedRating {
    rating: GearSetRating,
    /// Face width `b` \[m\].
    face_width: f64,
    /// `Km` and `Ks` at this face width, if the data pass their checks.
    factors: Option<(f64, [f64; 2])>,
}

impl PreparedRating {
    /// `rating` at face width `face_width` \[m\].
    pub fn new(rating: &GearSetRating, face_width: f64) -> Self {
        let factors = (|| {
            rating.validate()?;
            positive("face_width", face_width)?;
            let km = rating
                .load_distribution
                .factor(face_width, rating.pinion_diameter)?
                .km;
            Ok::<_, GearError>((km, rating.size_factors(face_width)?))
        })()
        .ok();
        Self {
            rating: *rating,
            face_width,
            factors,
        }
    }

    /// [`GearSetRating::rate`] for tangential load `wt` \[N\] and dynamic factor `kv` \[-\].
    pub fn rate(&self, wt: f64, kv: f64) -> Result<Rating, GearError> {
        let Some((km, ks)) = self.factors else {
            return self.rating.rate(wt, kv, self.face_width);
        };
        non_negative("tangential load", wt)?;
        require(kv.is_finite() && kv >= 1.0, "kv", "must be >= 1", kv)?;
        Ok(self.rating.stresses(wt, kv, self.face_width, km, ks))
    }

    /// The rating with the set's data checked and `Km`, `Ks` taken, for a caller that checks a
    /// block of loads and dynamic factors at once ([`CheckedRating::rate`]); `None` where the
    /// data fail a check ([`PreparedRating::rate`] then says which).
    pub fn checked(&self) -> Option<CheckedRating> {
        self.factors.map(|(km, ks)| CheckedRating {
            rating: self.rating,
            face_width: self.face_width,
            km,
            ks,
        })
    }
}

/// A [`PreparedRating`] whose data passed their checks, `Km` and `Ks` known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CheckedRating {
    rating: GearSetRating,
    face_width: f64,
    km: f64,
    ks: [f64; 2],
}

impl CheckedRating {
    /// Whether [`PreparedRating::rate`] takes the tangential load `wt` \[N\] and the dynamic
    /// factor `kv` \[-\]: its checks of them, as one test.
    #[inline(always)]
    pub fn takes(wt: f64, kv: f64) -> bool {
        wt.is_finite() && wt >= 0.0 && kv.is_finite() && kv >= 1.0
    }

    /// [`PreparedRating::rate`] of a `wt` and `kv` it takes ([`CheckedRating::takes`]): the
    /// same arithmetic, the same bits. Inlined, so that a block kernel's loop over its lanes
    /// compiles it for the kernel's instruction set.
    #[inline(always)]
    pub fn rate(&self, wt: f64, kv: f64) -> Rating {
        self.rating
            .stresses(wt, kv, self.face_width, self.km, self.ks)
    }
}

/// Bending stress `σ = Wt Ko Kv Ks Km KB / (b m J)` \[Pa\] (AGMA 2001-D04 eq. 15, metric form;
/// Shigley eq. 14-15). `wt` \[N\], `b` and `m` \[m\], factors \[-\].
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn bending_stress(
    wt: f64,
    ko: f64,
    kv: f64,
    ks: f64,
    km: f64,
    kb: f64,
    face_width: f64,
    module: f64,
    j: f64,
) -> f64 {
    wt * ko * kv * ks * km * kb / (face_width * module * j)
}

/// Contact stress `σc = Cp √(Wt Ko Kv Ks Km Cf / (d b I))` \[Pa\] (AGMA 2001-D04 eq. 1, metric
/// form; Shigley eq. 14-16). `cp` \[√Pa\], `d` pinion operating pitch diameter \[m\].
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn contact_stress(
    wt: f64,
    ko: f64,
    kv: f64,
    ks: f64,
    km: f64,
    cf: f64,
    pinion_diameter: f64,
    face_width: f64,
    i: f64,
    cp: f64,
) -> f64 {
    cp * (wt * ko * kv * ks * km * cf / (pinion_diameter * face_width * i)).sqrt()
}

impl GearSetRating {
    fn validate(&self) -> Result<(), GearError> {
        positive("module", self.module)?;
        positive("pinion_diameter", self.pinion_diameter)?;
        positive("overload", self.overload)?;
        positive("surface_condition", self.surface_condition)?;
        positive("geometry_i", self.geometry_i)?;
        positive("elastic_coefficient", self.elastic_coefficient)?;
        positive("temperature", self.temperature)?;
        positive("reliability", self.reliability)?;
        for m in [&self.pinion, &self.gear] {
            positive("j", m.j)?;
            positive("rim", m.rim)?;
            positive("bending_allowable", m.bending_allowable)?;
            positive("contact_allowable", m.contact_allowable)?;
            positive("yn", m.yn)?;
            positive("zn", m.zn)?;
            positive("ch", m.ch)?;
        }
        Ok(())
    }

    fn size_factors(&self, face_width: f64) -> Result<[f64; 2], GearError> {
        match self.size {
            SizeFactor::Given(k) => {
                positive("Ks", k[0])?;
                positive("Ks", k[1])?;
                Ok(k)
            }
            SizeFactor::Shigley { lewis_y } => Ok([
                factors::size_factor_shigley(face_width, self.module, lewis_y[0])?,
                factors::size_factor_shigley(face_width, self.module, lewis_y[1])?,
            ]),
        }
    }

    /// Stresses and safety factors for tangential load `wt` \[N\], dynamic factor `kv` \[-\] and
    /// face width `b` \[m\]. A zero load gives zero stresses and infinite safety factors.
    pub fn rate(&self, wt: f64, kv: f64, face_width: f64) -> Result<Rating, GearError> {
        self.validate()?;
        non_negative("tangential load", wt)?;
        require(kv.is_finite() && kv >= 1.0, "kv", "must be >= 1", kv)?;
        positive("face_width", face_width)?;
        let km = self
            .load_distribution
            .factor(face_width, self.pinion_diameter)?
            .km;
        let ks = self.size_factors(face_width)?;
        Ok(self.stresses(wt, kv, face_width, km, ks))
    }

    /// The stresses and safety factors of [`GearSetRating::rate`] once its inputs are checked
    /// and its `Km` and `Ks` known.
    #[inline(always)]
    fn stresses(&self, wt: f64, kv: f64, face_width: f64, km: f64, ks: [f64; 2]) -> Rating {
        let members = [&self.pinion, &self.gear];
        let mut out = Rating {
            km,
            ks,
            bending_stress: [0.0; 2],
            contact_stress: [0.0; 2],
            bending_safety: [0.0; 2],
            contact_safety: [0.0; 2],
        };
        let kt_kr = self.temperature * self.reliability;
        for k in 0..2 {
            let m = members[k];
            let s = bending_stress(
                wt,
                self.overload,
                kv,
                ks[k],
                km,
                m.rim,
                face_width,
                self.module,
                m.j,
            );
            let sc = contact_stress(
                wt,
                self.overload,
                kv,
                ks[k],
                km,
                self.surface_condition,
                self.pinion_diameter,
                face_width,
                self.geometry_i,
                self.elastic_coefficient,
            );
            out.bending_stress[k] = s;
            out.contact_stress[k] = sc;
            out.bending_safety[k] = m.bending_allowable * m.yn / kt_kr / s;
            out.contact_safety[k] = m.contact_allowable * m.zn * m.ch / kt_kr / sc;
        }
        out
    }

    /// Smallest face width \[m\] meeting the required bending (`sf`) and pitting (`sh`, stress
    /// ratio) safety factors for tangential load `wt` \[N\] shared equally by `sets` identical
    /// gear sets (1 = single set, 2 = twin set), with dynamic factor `kv`.
    ///
    /// `Km` (through `Cpf`, `Cma`) and a Shigley `Ks` depend on the face width, so each of the
    /// four criteria is solved by bisection on `b ∈ [1 µm, 40 in]` (the `Cpf` range), where the
    /// safety factor grows monotonically with `b`. Errors when even 40 in is not enough.
    pub fn required_face_width(
        &self,
        wt: f64,
        kv: f64,
        sf: f64,
        sh: f64,
        sets: u32,
    ) -> Result<FaceWidths, GearError> {
        positive("tangential load", wt)?;
        positive("required sf", sf)?;
        positive("required sh", sh)?;
        require(sets >= 1, "sets", "must be >= 1", sets as f64)?;
        let w = wt / sets as f64;
        let (lo0, hi0) = (1e-6, 40.0 * crate::units::INCH);
        let solve = |pick: &dyn Fn(&Rating) -> f64, need: f64| -> Result<f64, GearError> {
            let at = |b: f64| self.rate(w, kv, b).map(|r| pick(&r));
            if at(hi0)? < need {
                return Err(GearError::Unreachable(format!(
                    "safety factor {need} not reached even at face width 40 in"
                )));
            }
            if at(lo0)? >= need {
                return Ok(lo0);
            }
            let (mut lo, mut hi) = (lo0, hi0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if at(mid)? >= need {
                    hi = mid;
                } else {
                    lo = mid;
                }
                if hi - lo < 1e-12 {
                    break;
                }
            }
            Ok(hi)
        };
        let bending = [
            solve(&|r| r.bending_safety[0], sf)?,
            solve(&|r| r.bending_safety[1], sf)?,
        ];
        let contact = [
            solve(&|r| r.contact_safety[0], sh)?,
            solve(&|r| r.contact_safety[1], sh)?,
        ];
        let governing = bending
            .iter()
            .chain(contact.iter())
            .fold(0.0_f64, |a, &b| a.max(b));
        Ok(FaceWidths {
            bending,
            contact,
            governing,
        })
    }
}

/// Required face widths \[m\]; arrays are `[pinion, gear]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceWidths {
    /// Face width for the bending requirement.
    pub bending: [f64; 2],
    /// Face width for the pitting requirement.
    pub contact: [f64; 2],
    /// The largest of the four \[m\].
    pub governing: f64,
}
