//! Masses and mass moments of inertia of the moving links, with the estimation rules of
//! Karhula (2008), chapter 10, as defaults. The thesis prints no masses: its rules give
//! magnitudes, and every value here can be overridden from the case file.

use std::f64::consts::PI;

/// Materials of the moving links, with the densities of Karhula (2008), chapter 10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Material {
    /// 7850 kg/m³.
    #[default]
    Steel,
    /// Titanium alloy, 4820 kg/m³: the light rod the cardan gear allows.
    Titanium,
    /// 2700 kg/m³, for pistons.
    Aluminium,
}

impl Material {
    /// Density, kg/m³.
    pub fn density(self) -> f64 {
        match self {
            Material::Steel => 7850.0,
            Material::Titanium => 4820.0,
            Material::Aluminium => 2700.0,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Material::Steel => "steel",
            Material::Titanium => "titanium",
            Material::Aluminium => "aluminium",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        [Material::Steel, Material::Titanium, Material::Aluminium]
            .into_iter()
            .find(|m| m.name() == name)
    }
}

/// The mass fields of a case file, each `None` where the case leaves it to the estimation rules.
/// A mechanism resolves them into [`MassProperties`] with its own rules.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MassInputs {
    /// Crankshaft assembly about the main axis, kg·m².
    pub crankshaft_inertia: Option<f64>,
    /// Cardan wheel about its own axis, kg·m².
    pub wheel_inertia: Option<f64>,
    /// Rod (cardan gear, Scotch yoke: the rod or yoke that reciprocates with the piston), kg.
    pub rod_mass: Option<f64>,
    /// Rod about its centre of gravity, kg·m².
    pub rod_inertia: Option<f64>,
    /// Rod centre of gravity from its lower pin (or the yoke slot), along the rod, m.
    pub rod_cg: Option<f64>,
    /// Piston with pin and rings, kg.
    pub piston_mass: Option<f64>,
    /// Rod material, for the rod estimate (default steel).
    pub rod_material: Option<Material>,
}

/// Mass properties of one mechanism's moving links, resolved: the case's values where it gives
/// them, the estimation rules elsewhere. Fields a mechanism has no use for are 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Crankshaft assembly moment of inertia about the main bearing axis, kg·m². Its centre of
    /// gravity is on that axis (the thesis treats the crankshaft as balanced). In the cardan
    /// gear the assembly carries the cardan wheel's mass (Karhula ch. 11.2).
    pub crankshaft_inertia: f64,
    /// Cardan wheel moment of inertia about its own axis, kg·m².
    pub wheel_inertia: f64,
    /// Connecting rod (or yoke) mass, kg.
    pub rod_mass: f64,
    /// Connecting rod moment of inertia about its centre of gravity, kg·m².
    pub rod_inertia: f64,
    /// Distance of the rod's centre of gravity from its lower pin along the rod, m.
    pub rod_cg: f64,
    /// Piston with pin and rings, kg.
    pub piston_mass: f64,
    pub rod_material: Material,
}

/// Extra radius of the crankshaft's flywheel web beyond the crank length, m. Karhula ch. 10:
/// "the maximum diameter of the crankshaft flywheel is approximately 2·crank length + 10...60 mm";
/// the upper end (60 mm on the diameter) reproduces the thesis's mean inertial torque of the
/// cardan gear, which depends on the crankshaft alone, to within 1 % (see the reference tests).
pub const FLYWHEEL_RADIAL_MARGIN: f64 = 0.030;

/// The estimation rules of Karhula (2008) chapter 10, for a machine of half-stroke `crank`
/// (the slider-crank crank), rod `rod` and bore `bore` (m):
///
/// - Crankshaft (every mechanism, "treated equal", ch. 11.2): steel of volume π·r²·2r
///   (ch. 10), as a disc of radius r + [`FLYWHEEL_RADIAL_MARGIN`]: J = ½·m·R².
/// - Rod: a bar of overall length ℓ = rod + crank (centre distance plus the two eyes) and
///   cross-section ℓ/10 × ℓ/5 (ch. 10, "length/10 · length/5"), so m = ρ·ℓ³/50; J = m·ℓ²/12;
///   centre of gravity at mid centre distance. Reading ℓ as the overall length reproduces the
///   thesis's steel-versus-titanium difference of the cardan crank-pin force (60740 N vs
///   37960 N) to 1 %; the mid-length centre of gravity reproduces its rod kinematics (−3 %
///   velocity, −18 % acceleration).
/// - Piston with pin: the thesis gives no rule. This project estimates an aluminium disc of
///   the bore and a sixth of its height (0.61 kg for a 120 mm bore), the order of mass of
///   light-alloy pistons with their pins. Override it for a real piston.
///
/// The cardan wheel's rule is [`cardan_wheel_inertia`]; `wheel_inertia` here is 0.
pub fn estimate(crank: f64, rod: f64, bore: f64, rod_material: Material) -> MassProperties {
    let steel = Material::Steel.density();
    let crankshaft_mass = steel * PI * crank * crank * 2.0 * crank;
    let flywheel_radius = crank + FLYWHEEL_RADIAL_MARGIN;
    let overall = rod + crank;
    let rod_mass = rod_material.density() * overall.powi(3) / 50.0;
    MassProperties {
        crankshaft_inertia: 0.5 * crankshaft_mass * flywheel_radius * flywheel_radius,
        wheel_inertia: 0.0,
        rod_mass,
        rod_inertia: rod_mass * overall * overall / 12.0,
        rod_cg: rod / 2.0,
        piston_mass: Material::Aluminium.density() * PI / 4.0 * bore * bore * bore / 6.0,
        rod_material,
    }
}

/// The cardan wheel of pitch diameter d (= the slider-crank crank length, A8.1.4) as a steel
/// disc of face width d/3 (A8.1.9): J = ρ·b·π·d⁴/32 (A8.1.5), kg·m².
pub fn cardan_wheel_inertia(pitch_diameter: f64) -> f64 {
    let d = pitch_diameter;
    Material::Steel.density() * (d / 3.0) * PI * d.powi(4) / 32.0
}

impl MassProperties {
    /// `estimate` overridden by every field `inputs` gives.
    pub fn resolve(estimate: MassProperties, inputs: &MassInputs) -> Self {
        let pick = |given: Option<f64>, default: f64| given.unwrap_or(default);
        MassProperties {
            crankshaft_inertia: pick(inputs.crankshaft_inertia, estimate.crankshaft_inertia),
            wheel_inertia: pick(inputs.wheel_inertia, estimate.wheel_inertia),
            rod_mass: pick(inputs.rod_mass, estimate.rod_mass),
            rod_inertia: pick(inputs.rod_inertia, estimate.rod_inertia),
            rod_cg: pick(inputs.rod_cg, estimate.rod_cg),
            piston_mass: pick(inputs.piston_mass, estimate.piston_mass),
            rod_material: estimate.rod_material,
        }
    }

    /// The fields as (name, value, unit), in case-file names.
    pub fn fields(&self) -> [(&'static str, f64, &'static str); 6] {
        [
            ("crankshaft_inertia", self.crankshaft_inertia, "kg*m^2"),
            ("wheel_inertia", self.wheel_inertia, "kg*m^2"),
            ("rod_mass", self.rod_mass, "kg"),
            ("rod_inertia", self.rod_inertia, "kg*m^2"),
            ("rod_cg", self.rod_cg, "m"),
            ("piston_mass", self.piston_mass, "kg"),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The rules evaluated by hand for the thesis geometry (r = 0.06 m, l = 0.14 m, d = 0.12 m).
    #[test]
    fn thesis_geometry_by_hand() {
        let m = estimate(0.06, 0.14, 0.12, Material::Steel);
        // π·0.06²·0.12·7850 = 10.65377 kg; ½·10.65377·0.09² = 0.0431478
        assert_relative_eq!(
            m.crankshaft_inertia,
            0.5 * 10.653_77 * 0.0081,
            max_relative = 1e-5
        );
        // 7850·0.02·π·0.06⁴/32 = 1.99758e-4
        assert_relative_eq!(cardan_wheel_inertia(0.06), 1.997_58e-4, max_relative = 1e-5);
        // 7850·0.2³/50 = 1.256 kg
        assert_relative_eq!(m.rod_mass, 1.256, max_relative = 1e-12);
        let ti = estimate(0.06, 0.14, 0.12, Material::Titanium);
        assert_relative_eq!(
            m.rod_mass - ti.rod_mass,
            1.6e-4 * (7850.0 - 4820.0),
            max_relative = 1e-12
        );
        // 2700·π/4·0.12³/6 = 0.61073 kg
        assert_relative_eq!(m.piston_mass, 0.610_73, max_relative = 1e-5);
    }
}
