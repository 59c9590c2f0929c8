//! The inputs of a machine a [`crate::MechanismError`] can name: the shared geometry, the
//! masses, the motion's grid and a mechanism's own options. The names a case file gives them
//! are the case's business (it maps each to its field); an option is named by its
//! registry entry ([`crate::Entry::options`]), which owns the option's name.

/// An input of the machine that is physically impossible or ill-posed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// [`crate::MachineGeometry::crank_length`].
    CrankLength,
    /// [`crate::MachineGeometry::rod_length`].
    RodLength,
    /// [`crate::MachineGeometry::pin_offset`].
    PinOffset,
    /// The rod's centre of gravity, [`crate::MassProperties::rod_cg`].
    RodCg,
    /// The number of steps of the run's crank-angle grid.
    Steps,
    /// An option of the mechanism whose registry entry is named `mechanism`: the
    /// [`crate::OptionSpec::name`] of one of its [`crate::Entry::options`].
    Option {
        mechanism: &'static str,
        name: &'static str,
    },
}

impl Input {
    /// Every input but the options: those are listed by the registry ([`crate::MECHANISMS`],
    /// `Input::all` at the crate's root).
    pub const SHARED: [Input; 5] = [
        Input::CrankLength,
        Input::RodLength,
        Input::PinOffset,
        Input::RodCg,
        Input::Steps,
    ];
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every option a mechanism names in its errors is one of its registry entry's options.
    #[test]
    fn named_options_are_the_registrys() {
        let all = Input::all();
        for (mechanism, name) in [
            ("cardan_gear", "pressure_angle"),
            ("hypotrochoid", "angular_modulus"),
            ("hypotrochoid", "piston_link_length"),
            ("hypotrochoid", "planet_radius"),
        ] {
            assert!(
                all.contains(&Input::Option { mechanism, name }),
                "{mechanism}.{name}"
            );
        }
    }
}
