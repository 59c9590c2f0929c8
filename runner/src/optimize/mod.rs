//! Running an `[optimize]` (issue 40): each mechanism of the case searched on its own
//! (`search.rs`: the case of that mechanism alone at each point the optimiser asks for, run in
//! memory as the batch runs it, its summary read for the objective and the constraints; the
//! metrics checked first against what each mechanism's summary reports, [`check_metrics`]),
//! then the outputs written into the optimisation's folder, replaced whole (`outputs.rs`:
//! `<mechanism>/optimum.json`, `<mechanism>/history.csv`, `<mechanism>/summary.json`,
//! `convergence.svg`, `report.md`, and `at-optima/`: every mechanism at its own optimum in one
//! summary, with the comparison report of a case). A batch runs its optimisations after its
//! cases (`crate::run`'s `optimizations.rs`), each whole, on one shard.

mod outputs;
mod search;

pub use outputs::{optimum_json, report_md, write};
pub use search::{check_metrics, optimize, MechanismOptimum};
