//! Exact unit conversions used at the edges of the US-unit correlations.
//!
//! Every constant is an exact definition (international yard and pound agreement, 1959;
//! standard gravity 9.806 65 m/s², CGPM 1901), so a formula converted with them reproduces
//! its US-unit original to rounding error.

/// One inch in metres (exact, 1959 agreement).
pub const INCH: f64 = 0.0254;
/// One foot in metres (exact).
pub const FOOT: f64 = 0.3048;
/// One foot per minute in metres per second (exact: 0.3048 / 60).
pub const FT_PER_MIN: f64 = 0.00508;
/// One pound-force in newtons (exact: 0.453 592 37 kg × 9.806 65 m/s²).
pub const LBF: f64 = 4.448_221_615_260_5;
/// One pound-force per square inch in pascals (exact: [`LBF`] / [`INCH`]²).
pub const PSI: f64 = LBF / (INCH * INCH);
/// One mechanical horsepower (550 ft·lbf/s) in watts.
pub const HORSEPOWER: f64 = 550.0 * FOOT * LBF;
/// One centipoise (= 1 mPa·s) in pascal seconds.
pub const CENTIPOISE: f64 = 1.0e-3;
