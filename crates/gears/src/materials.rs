//! A table of common gear materials: elastic constants, AGMA 2001-D04 allowable stress
//! numbers by grade and hardness, ISO 6336-5 endurance limits by quality grade and hardness.
//!
//! A user names a material instead of typing `Z_E` (`Cp`) and the allowables. Sources, line
//! by line, in each function's doc comment:
//!
//! * AGMA 2001-D04 Figs. 3, 4, 5 (bending `s_at`), Fig. 8 and Tables 3, 4, 5 (contact `s_ac`)
//!   as reproduced in Budynas & Nisbett, *Shigley's MED* 9th ed., Figs. 14-2 to 14-5 and
//!   Tables 14-3 to 14-7 (US-unit lines, converted with the exact [`crate::units::PSI`]);
//! * ISO 6336-5:2016 §5 and Table 2 (`σ_lim = A x + B`, `x` the surface hardness HBW or HV,
//!   within the stated hardness range), for the quality grades ML, MQ, ME (§5.2);
//! * elastic moduli of Shigley Table 14-8 (AGMA) for the irons and bronzes; 206 GPa and
//!   ν = 0.3 for steel, the values behind ISO 6336-2:2019 §7's `Z_E = 189.8 √(N/mm²)` for a
//!   steel/steel pair.
//!
//! ISO 6336-5 gives no line for bronze (worm-wheel bronzes are ISO/TS 14521's): asking for
//! its ISO limits is an error naming the fields to give instead.

use crate::agma::factors::{
    bending_allowable_through_hardened, contact_allowable_through_hardened, Grade,
};
use crate::error::{require, GearError};
use crate::units::PSI;

/// Heat treatment / material group; fixes which lines of the standards apply. The ISO 6336
/// abbreviations (ISO 6336-5:2016 Table 1) are given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MaterialGroup {
    /// Through-hardened (quenched and tempered) wrought alloy steel, ISO "V".
    ThroughHardened,
    /// Case-carburized and hardened wrought steel, ISO "Eh".
    CaseCarburized,
    /// Through-hardened steel, gas nitrided, ISO "NV (nitr.)".
    NitridedThroughHardened,
    /// Nitriding steel (Nitralloy 135M type), gas nitrided, ISO "NT (nitr.)".
    NitridingSteel,
    /// Grey cast iron (ASTM A48), ISO "GG".
    GreyCastIron,
    /// Bronze (not covered by ISO 6336-5).
    Bronze,
}

/// ISO 6336-5 material quality grade (ISO 6336-5:2016 §5.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IsoQuality {
    /// ML: modest demands on material quality and heat treatment.
    Ml,
    /// MQ: requirements met by experienced manufacturers at moderate cost (the usual choice).
    Mq,
    /// ME: requirements to be met when a high degree of operating reliability is required.
    Me,
}

/// A named gear material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Name as written in a gear file.
    pub name: &'static str,
    /// Description (standard designation).
    pub description: &'static str,
    /// Material group.
    pub group: MaterialGroup,
    /// Young's modulus `E` \[Pa\].
    pub youngs_modulus: f64,
    /// Poisson's ratio `ν` \[-\].
    pub poisson_ratio: f64,
    /// Whether the Brinell hardness (core hardness for nitrided steels) is needed for the
    /// AGMA allowables.
    pub needs_hardness: bool,
    /// Largest AGMA grade tabulated for this material (1, 2 or 3).
    pub max_grade: u8,
}

/// Steel: `E` = 206 GPa, ν = 0.3 (ISO 6336-2:2019 §7, the steel/steel `Z_E` = 189.8 √MPa).
const E_STEEL: f64 = 206e9;

/// The table. Names are kebab-case words for the gear file's `material` field.
pub const MATERIALS: &[Material] = &[
    Material {
        name: "steel-through-hardened",
        description: "through-hardened (quenched and tempered) alloy steel, e.g. 42CrMo4, AISI 4140",
        group: MaterialGroup::ThroughHardened,
        youngs_modulus: E_STEEL,
        poisson_ratio: 0.3,
        needs_hardness: true,
        max_grade: 2,
    },
    Material {
        name: "steel-case-carburized",
        description: "case-carburized and hardened steel, e.g. 18CrNiMo7-6, AISI 8620 (58-64 HRC case)",
        group: MaterialGroup::CaseCarburized,
        youngs_modulus: E_STEEL,
        poisson_ratio: 0.3,
        needs_hardness: false,
        max_grade: 3,
    },
    Material {
        name: "steel-nitrided",
        description: "through-hardened steel, gas nitrided (83.5 HR15N), e.g. 42CrMo4 nitrided; hardness = core HB",
        group: MaterialGroup::NitridedThroughHardened,
        youngs_modulus: E_STEEL,
        poisson_ratio: 0.3,
        needs_hardness: true,
        max_grade: 2,
    },
    Material {
        name: "nitriding-steel",
        description: "nitriding steel, gas nitrided (87.5 HR15N), e.g. Nitralloy 135M, 31CrMoV9; hardness = core HB",
        group: MaterialGroup::NitridingSteel,
        youngs_modulus: E_STEEL,
        poisson_ratio: 0.3,
        needs_hardness: true,
        max_grade: 2,
    },
    Material {
        name: "grey-cast-iron",
        description: "grey cast iron ASTM A48 class 30 (174 HB) or class 40 (201 HB): grade = class/10 - 2 (1 = class 30, 2 = class 40)",
        group: MaterialGroup::GreyCastIron,
        youngs_modulus: 22e6 * PSI,
        poisson_ratio: 0.3,
        needs_hardness: false,
        max_grade: 2,
    },
    Material {
        name: "tin-bronze",
        description: "tin bronze AGMA 2C (10-12 % Sn), sand cast, tensile strength 40 ksi",
        group: MaterialGroup::Bronze,
        youngs_modulus: 16e6 * PSI,
        poisson_ratio: 0.3,
        needs_hardness: false,
        max_grade: 1,
    },
    Material {
        name: "aluminium-bronze",
        description: "aluminium bronze ASTM B148 alloy 954, heat treated, tensile strength 90 ksi",
        group: MaterialGroup::Bronze,
        youngs_modulus: 17.5e6 * PSI,
        poisson_ratio: 0.3,
        needs_hardness: false,
        max_grade: 1,
    },
];

/// The material named `name`, if the table has it.
pub fn material(name: &str) -> Option<&'static Material> {
    MATERIALS.iter().find(|m| m.name == name)
}

/// The names of the table, for error messages.
pub fn material_names() -> Vec<&'static str> {
    MATERIALS.iter().map(|m| m.name).collect()
}

/// AGMA 2001-D04 allowable stress numbers \[Pa\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AgmaAllowables {
    /// Allowable bending stress number `s_at` (`St`) \[Pa\].
    pub bending: f64,
    /// Allowable contact stress number `s_ac` (`Sc`) \[Pa\].
    pub contact: f64,
}

/// ISO 6336-5 endurance limits \[Pa\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoLimits {
    /// Allowable stress number (contact) `σ_Hlim` \[Pa\].
    pub contact: f64,
    /// Nominal stress number (bending) `σ_Flim` \[Pa\] (`σ_FE = σ_Flim Y_ST`, `Y_ST` = 2).
    pub bending: f64,
}

/// Vickers hardness of a steel from its Brinell hardness, `HV = HB / 0.95` (the usual
/// approximation of the ISO 18265 steel conversion table below 450 HV; ISO 6336-5 Table 2
/// reads the through-hardened lines in HV).
pub fn vickers_from_brinell(hb: f64) -> f64 {
    hb / 0.95
}

fn grade_of(grade: u8) -> Grade {
    if grade >= 2 {
        Grade::Two
    } else {
        Grade::One
    }
}

fn hardness(hb: Option<f64>) -> Result<f64, GearError> {
    let h = hb.ok_or(GearError::InvalidInput {
        field: "hardness",
        rule: "this material's allowables depend on its Brinell hardness (core hardness of a nitrided steel): give it",
        value: f64::NAN,
    })?;
    require(
        h.is_finite() && h > 0.0,
        "hardness",
        "must be a positive Brinell hardness",
        h,
    )?;
    Ok(h)
}

impl Material {
    fn check_grade(&self, grade: u8) -> Result<(), GearError> {
        require(
            (1..=self.max_grade).contains(&grade),
            "grade",
            match self.max_grade {
                1 => "this material has one AGMA grade: give grade 1 or leave it out",
                2 => "this material has AGMA grades 1 and 2",
                _ => "this material has AGMA grades 1, 2 and 3",
            },
            grade as f64,
        )
    }

    /// AGMA 2001-D04 allowable stress numbers for grade `grade` and Brinell hardness `hb`
    /// (needed where [`Material::needs_hardness`]):
    ///
    /// * through-hardened: Fig. 3 `s_at` = 77.3 HB + 12 800 psi (grade 1, in SI 0.533 HB +
    ///   88.3 MPa), 102 HB + 16 400 psi (grade 2); Fig. 8 `s_ac` = 322 HB + 29 100 psi (grade 1,
    ///   2.22 HB + 200 MPa), 349 HB + 34 300 psi (grade 2); 140-400 HB (Shigley Figs. 14-2,
    ///   14-5);
    /// * case-carburized (58-64 HRC): Table 3 `s_at` 55 / 65 / 75 ksi, Table 4 `s_ac` 180 / 225
    ///   / 275 ksi for grades 1 / 2 / 3 (Shigley Tables 14-3, 14-6; grade 2 bending the lower,
    ///   65 ksi, of the two core-hardness values);
    /// * nitrided through-hardened: Fig. 4 `s_at` = 82.3 HB + 12 150 psi (grade 1), 108.6 HB +
    ///   15 890 psi (grade 2), core hardness 250-325 HB; Table 4 `s_ac` at 83.5 HR15N 150 / 163
    ///   ksi (Shigley Fig. 14-3, Table 14-6);
    /// * nitriding steel (Nitralloy 135M): Fig. 5 `s_at` = 86.2 HB + 12 730 psi (grade 1),
    ///   113.8 HB + 16 650 psi (grade 2), core 250-325 HB; Table 4 `s_ac` at 87.5 HR15N 170 /
    ///   183 ksi (Shigley Fig. 14-4, Table 14-6);
    /// * grey cast iron ASTM A48: Table 5, class 30 (grade 1) `s_at` 8.5 ksi, `s_ac` 65 ksi;
    ///   class 40 (grade 2) 13 ksi, 75 ksi (the lower end of each `s_ac` range; Shigley
    ///   Table 14-7);
    /// * bronzes: Table 5, tin bronze AGMA 2C `s_at` 5.7 ksi, `s_ac` 30 ksi; aluminium bronze
    ///   ASTM B148 954 `s_at` 23.6 ksi, `s_ac` 65 ksi (Shigley Table 14-7).
    pub fn agma_allowables(&self, hb: Option<f64>, grade: u8) -> Result<AgmaAllowables, GearError> {
        self.check_grade(grade)?;
        let g = grade_of(grade);
        let ksi = |b: f64, c: f64| AgmaAllowables {
            bending: b * 1e3 * PSI,
            contact: c * 1e3 * PSI,
        };
        let core = |h: f64| {
            require(
                (250.0..=325.0).contains(&h),
                "hardness",
                "core hardness of a nitrided steel must lie in [250, 325] HB (AGMA 2001-D04 Figs. 4, 5)",
                h,
            )
        };
        Ok(match self.group {
            MaterialGroup::ThroughHardened => {
                let h = hardness(hb)?;
                AgmaAllowables {
                    bending: bending_allowable_through_hardened(h, g)?,
                    contact: contact_allowable_through_hardened(h, g)?,
                }
            }
            MaterialGroup::CaseCarburized => match grade {
                1 => ksi(55.0, 180.0),
                2 => ksi(65.0, 225.0),
                _ => ksi(75.0, 275.0),
            },
            MaterialGroup::NitridedThroughHardened => {
                let h = hardness(hb)?;
                core(h)?;
                let (st, sc) = match g {
                    Grade::One => (82.3 * h + 12_150.0, 150e3),
                    Grade::Two => (108.6 * h + 15_890.0, 163e3),
                };
                AgmaAllowables {
                    bending: st * PSI,
                    contact: sc * PSI,
                }
            }
            MaterialGroup::NitridingSteel => {
                let h = hardness(hb)?;
                core(h)?;
                let (st, sc) = match g {
                    Grade::One => (86.2 * h + 12_730.0, 170e3),
                    Grade::Two => (113.8 * h + 16_650.0, 183e3),
                };
                AgmaAllowables {
                    bending: st * PSI,
                    contact: sc * PSI,
                }
            }
            MaterialGroup::GreyCastIron => match grade {
                1 => ksi(8.5, 65.0),
                _ => ksi(13.0, 75.0),
            },
            MaterialGroup::Bronze => {
                if self.name == "tin-bronze" {
                    ksi(5.7, 30.0)
                } else {
                    ksi(23.6, 65.0)
                }
            }
        })
    }

    /// ISO 6336-5:2016 Table 2 endurance limits `σ = A x + B` \[N/mm²\] for quality `q`,
    /// `x` the surface hardness in the table's scale (HV from HB by [`vickers_from_brinell`]
    /// for the through-hardened line), within the table's hardness range:
    ///
    /// * through-hardened wrought alloy steel (V), 200-360 HV: `σ_Hlim` ML 1.313 HV + 188,
    ///   MQ 1.313 HV + 373, ME 2.213 HV + 260; `σ_Flim` ML 0.423 HV + 104, MQ 0.425 HV + 187,
    ///   ME 0.358 HV + 231;
    /// * case-carburized wrought steel (Eh), 600-800 HV (taken as met): `σ_Hlim` ML 1300, MQ
    ///   1500, ME 1650; `σ_Flim` ML 312, MQ 425, ME 500;
    /// * nitrided through-hardened steel (NV nitr.), 450-650 HV: `σ_Hlim` ML 788, MQ 998,
    ///   ME 1217; `σ_Flim` ML 258, MQ 363, ME 432;
    /// * nitriding steel (NT nitr.), 650-900 HV: `σ_Hlim` ML 1125, MQ 1250, ME 1450; `σ_Flim`
    ///   ML 270, MQ 420, ME 468;
    /// * grey cast iron (GG), 150-240 HBW (class 30: 174 HB, class 40: 201 HB): `σ_Hlim`
    ///   ML/MQ 1.033 HB + 132, ME 1.465 HB + 122; `σ_Flim` ML/MQ 0.256 HB + 0.6, ME 0.200 HB +
    ///   33.
    ///
    /// Bronze has no ISO 6336-5 line: an error.
    pub fn iso_limits(&self, hb: Option<f64>, q: IsoQuality) -> Result<IsoLimits, GearError> {
        let pick = |ml: (f64, f64), mq: (f64, f64), me: (f64, f64)| match q {
            IsoQuality::Ml => ml,
            IsoQuality::Mq => mq,
            IsoQuality::Me => me,
        };
        let mpa = |h: (f64, f64), f: (f64, f64), x: f64| IsoLimits {
            contact: (h.0 * x + h.1) * 1e6,
            bending: (f.0 * x + f.1) * 1e6,
        };
        let constant = |h: (f64, f64, f64), f: (f64, f64, f64)| {
            let h = pick((0.0, h.0), (0.0, h.1), (0.0, h.2));
            let f = pick((0.0, f.0), (0.0, f.1), (0.0, f.2));
            mpa(h, f, 0.0)
        };
        Ok(match self.group {
            MaterialGroup::ThroughHardened => {
                let hv = vickers_from_brinell(hardness(hb)?);
                require(
                    (200.0..=360.0).contains(&hv),
                    "hardness",
                    "ISO 6336-5 Table 2 (through-hardened alloy steel) covers 200-360 HV, i.e. 190-342 HB",
                    hv * 0.95,
                )?;
                mpa(
                    pick((1.313, 188.0), (1.313, 373.0), (2.213, 260.0)),
                    pick((0.423, 104.0), (0.425, 187.0), (0.358, 231.0)),
                    hv,
                )
            }
            MaterialGroup::CaseCarburized => {
                constant((1300.0, 1500.0, 1650.0), (312.0, 425.0, 500.0))
            }
            MaterialGroup::NitridedThroughHardened => {
                constant((788.0, 998.0, 1217.0), (258.0, 363.0, 432.0))
            }
            MaterialGroup::NitridingSteel => {
                constant((1125.0, 1250.0, 1450.0), (270.0, 420.0, 468.0))
            }
            MaterialGroup::GreyCastIron => {
                let h = hb.unwrap_or(174.0);
                require(
                    (150.0..=240.0).contains(&h),
                    "hardness",
                    "ISO 6336-5 Table 2 (grey cast iron) covers 150-240 HBW",
                    h,
                )?;
                mpa(
                    pick((1.033, 132.0), (1.033, 132.0), (1.465, 122.0)),
                    pick((0.256, 0.6), (0.256, 0.6), (0.200, 33.0)),
                    h,
                )
            }
            MaterialGroup::Bronze => return Err(GearError::InvalidInput {
                field: "material",
                rule:
                    "ISO 6336-5 has no endurance limits for bronze: give sigma_hlim and sigma_flim",
                value: f64::NAN,
            }),
        })
    }

    /// The ISO 6336-2 Table 2 / ISO 6336-3 Table 3 life-factor curve of the material.
    pub fn life_curve(&self) -> LifeCurve {
        match self.group {
            MaterialGroup::ThroughHardened => LifeCurve::ThroughHardened,
            MaterialGroup::CaseCarburized => LifeCurve::CaseHardened,
            MaterialGroup::NitridedThroughHardened | MaterialGroup::NitridingSteel => {
                LifeCurve::Nitrided
            }
            MaterialGroup::GreyCastIron | MaterialGroup::Bronze => LifeCurve::GreyIron,
        }
    }
}

/// Which curve of the ISO life factors `Z_NT` (ISO 6336-2:2019 Table 2) and `Y_NT`
/// (ISO 6336-3:2019 Table 3) applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LifeCurve {
    /// V, GGG (perl., bai.), GTS (perl.): through-hardened steels.
    ThroughHardened,
    /// Eh, IF: case-hardened (and surface-hardened) steels.
    CaseHardened,
    /// NT, NV (nitr.): nitrided steels.
    Nitrided,
    /// GG, GGG (ferr.): grey and ferritic irons (also used here for bronze, which ISO does
    /// not cover).
    GreyIron,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_is_found_and_unique() {
        for m in MATERIALS {
            assert_eq!(material(m.name).unwrap().name, m.name);
        }
        let mut names = material_names();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), MATERIALS.len());
    }
}
