//! Where a loss model attaches: below the registry ([`crate::loss_models`]) and the setup
//! errors that name an attachment's model.

/// Where a loss model attaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Attachment {
    /// The rings of every piston in a cylinder (`rings`).
    Rings,
    /// A piston's slide on the frame (`skirt`).
    Skirt,
    /// The bearings of a revolute joint (`bearings`, `joints.<name>`).
    Bearing,
    /// A gear mesh (`gear_mesh`).
    GearMesh,
    /// An engine's valve train (`valve_train`).
    ValveTrain,
}

impl Attachment {
    /// Every attachment.
    pub const ALL: [Attachment; 5] = [
        Attachment::Rings,
        Attachment::Skirt,
        Attachment::Bearing,
        Attachment::GearMesh,
        Attachment::ValveTrain,
    ];
}
