//! Pump or engine: which definition of the mechanical efficiency, need and output a machine's
//! losses are reported by.

/// What the machine does with its gas: which definition of the mechanical efficiency, need
/// and output applies (one per machine, whatever the sign of a run's works).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MachineKind {
    /// A pump or compressor: the crank drives the gas.
    Pump,
    /// An engine: the gas drives the crank.
    Engine,
}

impl MachineKind {
    /// The mechanical efficiency of a run of `gas` work and drive work `work` (J, ∫ T dθ of
    /// gas and inertia) with `lost` J of friction, by the machine's kind whatever the works'
    /// signs: a pump gas / (work + lost) (Karhula 2008 A9.1.72-73), an engine
    /// (−work − lost) / −work (A9.1.74-75); `None` where its denominator, the work the drive
    /// gives (pump) or takes (engine), is not positive (Karhula's definitions are of a steady
    /// cycle). The cylinder's (`stages.rs`) and the machine's (`machine_stage.rs`).
    pub fn efficiency(self, gas: f64, work: f64, lost: f64) -> Option<f64> {
        let need = work + lost;
        match self {
            MachineKind::Pump => (need > 0.0).then(|| gas / need),
            MachineKind::Engine => (work < 0.0).then(|| -need / -work),
        }
    }
}
