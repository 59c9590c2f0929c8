//! The blocks a run fills (`RunRoom`), and the rooms of finished runs a caller that runs
//! many cases keeps for the next ([`RunRooms`]).

use cardan_loads::family::{LoadFamily, Solver};
use cardan_mechanism::{LoadsBlock, Mechanism, StateBlock, Topology};
use std::sync::Mutex;

/// The blocks a run fills, a block at a time: its states, each load family's loads and their
/// total, made for a topology. A run writes every lane of a block it reads (the mechanism its
/// columns, which it writes for every state alike; the families their loads), so that runs
/// (a sweep's points, the pieces of a run shared among threads, [`crate::run_parallel`]) take
/// one room after another ([`RunRooms`]) as a run takes its blocks, instead of making and
/// zeroing their own (some 40 kB a run).
#[derive(Debug, Clone)]
pub(crate) struct RunRoom {
    pub(crate) states: StateBlock,
    pub(crate) loads: Vec<LoadsBlock>,
    pub(crate) total: LoadsBlock,
}

impl RunRoom {
    /// The room of a run of a mechanism of `topology` under `families` load families.
    pub(crate) fn new(topology: &Topology, families: usize) -> Self {
        Self {
            states: StateBlock::for_topology(topology),
            loads: vec![LoadsBlock::for_topology(topology); families],
            total: LoadsBlock::for_topology(topology),
        }
    }
}

/// Rooms of finished runs kept for later runs of the same kind of mechanism under the same
/// kinds of load families (a sweep's points, `cardan_runner`'s tables; a shared run's pieces):
/// such a run takes a kept room instead of making and zeroing its blocks (some 40 kB, 6 % of
/// a sweep point's instructions). Sound because a mechanism writes the same columns of a
/// block at every state whatever its parameters, a family of one kind and solver the same
/// loads columns, and a run reads no lane past a block's length (tested over every kind,
/// reading and added mass in `crates/dynamics/tests/parallel.rs`). Owned by the caller that
/// runs many cases (no global state); at most [`KEPT_ROOMS`] rooms, a failed run's not kept.
#[derive(Debug, Default)]
pub struct RunRooms {
    kept: Mutex<Vec<(RoomKind, RunRoom)>>,
}

/// Rooms a [`RunRooms`] keeps at most (two mechanisms a point on a few threads need a few).
pub const KEPT_ROOMS: usize = 16;

/// What a room fits: the mechanism's name and its topology's sizes, each family's name and
/// solver.
#[derive(Debug, PartialEq)]
pub(crate) struct RoomKind {
    mechanism: &'static str,
    sizes: [usize; 3],
    families: Vec<(&'static str, Solver)>,
}

impl RoomKind {
    fn of(mechanism: &dyn Mechanism, families: &[&dyn LoadFamily]) -> Self {
        let t = mechanism.topology();
        Self {
            mechanism: mechanism.name(),
            sizes: [t.bodies.len(), t.joints.len(), t.pistons.len()],
            families: families.iter().map(|f| (f.name(), f.solver())).collect(),
        }
    }
}

impl RunRooms {
    /// A kept room that fits a run of `mechanism` under `families`, or a new one, with what it
    /// fits (to [`RunRooms::keep`] it by).
    pub(crate) fn take(
        &self,
        mechanism: &dyn Mechanism,
        families: &[&dyn LoadFamily],
    ) -> (RoomKind, RunRoom) {
        let kind = RoomKind::of(mechanism, families);
        let kept = self.kept.lock().ok().and_then(|mut kept| {
            let at = kept.iter().position(|(k, _)| *k == kind)?;
            Some(kept.swap_remove(at).1)
        });
        let room = kept.unwrap_or_else(|| RunRoom::new(mechanism.topology(), families.len()));
        (kind, room)
    }

    /// Keeps `room`, of a run that succeeded, for a later run of its `kind` (unless
    /// [`KEPT_ROOMS`] are kept).
    pub(crate) fn keep(&self, kind: RoomKind, room: RunRoom) {
        if let Ok(mut kept) = self.kept.lock() {
            if kept.len() < KEPT_ROOMS {
                kept.push((kind, room));
            }
        }
    }
}
