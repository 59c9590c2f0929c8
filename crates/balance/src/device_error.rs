//! A balancing device that cannot be formed with a mechanism: the device at fault and why.
//! The device is named by its kind ([`Device`]); the case maps it to its field.

/// A balancing device of [`crate::MachineBalance`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Device {
    /// The crank counterweight, [`crate::MachineBalance::counterweight`].
    Counterweight,
    /// The cardan pair's counterweights, [`crate::MachineBalance::cardan_counterweights`].
    CardanCounterweights,
}

impl Device {
    /// Every device.
    pub const ALL: [Device; 2] = [Device::Counterweight, Device::CardanCounterweights];
}

/// A device that cannot be formed with a mechanism, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct DeviceError {
    pub device: Device,
    pub rule: String,
}

impl std::fmt::Display for DeviceError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{:?}: {}", self.device, self.rule)
    }
}

impl std::error::Error for DeviceError {}
