//! Per-step rows: one row per step (every `decimation`-th step and the last), defined once
//! ([`Row`]: the header and how a step fills it), written as CSV text (`<label>.csv`) and/or
//! as a binary columnar array (`<label>.npy`, NPY format 1.0, `<f8`, Fortran order: each
//! column contiguous, with its names in `<label>.columns.json`), and/or thinned for the
//! report's charts ([`ChartRecorder`]: a few hundred points per charted column, whatever the
//! number of steps). The one sink fills each row once for all of them.
//!
//! The run's thread only copies each row's numbers into a block; a thread of the sink's own
//! formats and writes the blocks, so a large case keeps two cores busy (float formatting is
//! most of a case's time when it writes text). Memory is a few blocks, whatever the number of
//! steps: the NPY file's size is known in advance (rows × columns), so every block's column
//! pieces are written in place.

use crate::report::{ChartData, ChartRecorder, ChartRows, MAX_POINTS};
use anyhow::{bail, Context};
use cardan_case::case::OutputOptions;
use cardan_dynamics::{radial, tangential, Sink, StageColumn, Step, StepBlock, StepScratch};
use cardan_mechanism::{JointKind, Mechanism, PolarComponents};
use std::fs::File;
use std::io::{BufWriter, Seek, SeekFrom, Write};
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::sync::Arc;
use std::thread::JoinHandle;

/// The per-step CSV columns: a name template (units in the name; `{piston}`, `{body}`,
/// `{joint}`, `{extra}`, `{family}` stand for names of the mechanism's topology and the run's
/// load families), and its meaning. The column table of docs/results.md is made from this list.
pub const COLUMNS: &[(&str, &str)] = &[
    ("crank_angle_deg", "crank angle θ from the +x axis (90° is top dead centre of an in-line machine)"),
    ("time_s", "time since the start of the run"),
    ("crank_speed_rad_s", "crank angular velocity ω"),
    ("crank_acceleration_rad_s2", "crank angular acceleration α"),
    ("{piston}_position_m", "piston-pin distance along the cylinder axis from the main bearing axis"),
    ("{piston}_velocity_m_s", "piston velocity along the cylinder, positive away from the crankshaft"),
    ("{piston}_acceleration_m_s2", "piston acceleration along the cylinder"),
    ("{piston}_dx_dtheta_m_rad", "dx/dθ: dV/dθ = −bore area × this"),
    ("{body}_angle_deg", "orientation of the body"),
    ("{body}_angular_velocity_rad_s", "angular velocity of the body"),
    ("{body}_angular_acceleration_rad_s2", "angular acceleration of the body"),
    ("{body}_cg_x_m", "centre of gravity, x"),
    ("{body}_cg_y_m", "centre of gravity, y (along the cylinder)"),
    ("{body}_cg_velocity_m_s", "speed of the centre of gravity"),
    ("{body}_cg_acceleration_m_s2", "acceleration magnitude of the centre of gravity"),
    ("{body}_cg_radial_acceleration_m_s2", "its radial part about the main axis (Karhula 4.1.3)"),
    ("{body}_cg_coriolis_acceleration_m_s2", "its Coriolis part 2·v_r·ω"),
    ("{body}_cg_tangential_acceleration_m_s2", "its tangential part |Z|·α"),
    ("{body}_cg_normal_acceleration_m_s2", "its normal part −|Z|·ω²"),
    ("{joint}_speed_rad_s", "pins: angular velocity of the joint's first body relative to its second"),
    ("{joint}_speed_m_s", "slides: sliding velocity of the first body relative to the second along the slide; meshes: pitch-line velocity relative to the gear carrier"),
    ("{extra}", "a quantity of one mechanism (see its section)"),
    ("cylinder_pressure_pa", "absolute cylinder pressure (empty without a gas model)"),
    ("gas_force_n", "gas force on the piston, towards the crankshaft (empty without a gas model)"),
    ("{family}_{joint}_force_x_n", "force on the joint's first body from its second, x"),
    ("{family}_{joint}_force_y_n", "the same, y"),
    ("{family}_{joint}_force_magnitude_n", "its magnitude"),
    ("{family}_{joint}_moment_nm", "couple a slide carries"),
    ("{family}_{joint}_tangential_n", "gear meshes: the force along the pitch-circle tangent (the tooth load that transmits torque, Karhula A8.1.10)"),
    ("{family}_{joint}_radial_n", "gear meshes: the force towards the first gear's centre"),
    ("{family}_torque_nm", "drive torque on the crankshaft, positive in the direction of rotation"),
    ("{family}_torque_{body}_nm", "the body's share of it by the power balance (Karhula's T_1i10, T_2i10, T_3i10); empty while the crank stands still"),
    ("{joint}_dynamic_tooth_load_n", "with [gear]: Buckingham's dynamic tooth load of the mesh (Karhula A8.1.14), per gear set"),
    ("{joint}_contact_stress_pa", "with [gear]: AGMA contact stress of the mesh"),
    ("{joint}_bending_stress_pa", "with [gear] and known J: AGMA bending stress, the larger member's"),
    ("friction_torque_nm", "with [friction]: the drive torque that covers the losses, Σ P / ω"),
    ("power_loss_{component}_w", "with [friction]: one loss component's power (rings, skirt, a slide, a revolute joint's bearings by joint name, a gear mesh by joint name)"),
];

/// The CSV header of `mechanism` run with the load families `families` (the run's, then
/// `total` when there are several), and where its body columns are; [`Row::fill`] fills a
/// row in this order.
fn header(
    mechanism: &dyn Mechanism,
    families: &[&str],
    gas: bool,
    stages: &[Vec<StageColumn>],
) -> (Vec<String>, Range<usize>) {
    let t = mechanism.topology();
    let mut h: Vec<String> = [
        "crank_angle_deg",
        "time_s",
        "crank_speed_rad_s",
        "crank_acceleration_rad_s2",
    ]
    .map(String::from)
    .to_vec();
    for p in &t.pistons {
        for s in [
            "position_m",
            "velocity_m_s",
            "acceleration_m_s2",
            "dx_dtheta_m_rad",
        ] {
            h.push(format!("{}_{s}", p.name));
        }
    }
    let bodies_start = h.len();
    for b in &t.bodies {
        for s in [
            "angle_deg",
            "angular_velocity_rad_s",
            "angular_acceleration_rad_s2",
            "cg_x_m",
            "cg_y_m",
            "cg_velocity_m_s",
            "cg_acceleration_m_s2",
            "cg_radial_acceleration_m_s2",
            "cg_coriolis_acceleration_m_s2",
            "cg_tangential_acceleration_m_s2",
            "cg_normal_acceleration_m_s2",
        ] {
            h.push(format!("{}_{s}", b.name));
        }
    }
    let bodies = bodies_start..h.len();
    for j in &t.joints {
        let unit = match j.kind {
            JointKind::Revolute(_) => "rad_s",
            JointKind::Prismatic | JointKind::GearMesh { .. } => "m_s",
        };
        h.push(format!("{}_speed_{unit}", j.name));
    }
    h.extend(t.extras.iter().map(|e| e.name.to_string()));
    if gas {
        h.push("cylinder_pressure_pa".into());
        h.push("gas_force_n".into());
    }
    for f in families {
        for j in &t.joints {
            for s in ["force_x_n", "force_y_n", "force_magnitude_n"] {
                h.push(format!("{f}_{}_{s}", j.name));
            }
            match j.kind {
                JointKind::Prismatic => h.push(format!("{f}_{}_moment_nm", j.name)),
                JointKind::GearMesh { .. } => {
                    h.push(format!("{f}_{}_tangential_n", j.name));
                    h.push(format!("{f}_{}_radial_n", j.name));
                }
                JointKind::Revolute(_) => {}
            }
        }
        h.push(format!("{f}_torque_nm"));
        for b in &t.bodies {
            h.push(format!("{f}_torque_{}_nm", b.name));
        }
    }
    h.extend(stages.iter().flatten().map(|c| c.name.clone()));
    (h, bodies)
}

/// What a run's steps hold besides the mechanism's own state: the load families (in the run's
/// order), a gas model, the columns of each of the run's stages (in the run's order).
pub struct RunLayout<'b> {
    pub families: &'b [&'b str],
    pub gas: bool,
    pub stages: &'b [Vec<StageColumn>],
}

/// Rows per block handed to the writing thread: large enough that the hand-over is rare, small
/// enough that a block (rows × columns × 8 bytes, about 0.5 MB for a cardan gear with every
/// family) stays in the caches.
const BLOCK_ROWS: usize = 512;

/// The number of rows written for steps 0..=`last_step`: every `decimation`-th and the last.
pub fn row_count(last_step: usize, decimation: usize) -> usize {
    last_step / decimation + 1 + usize::from(last_step % decimation != 0)
}

/// The per-step row of one crank train: its column names and how a [`Step`] fills it. The
/// files and the charts both take their rows from here, so that a column's name and its value
/// are defined in one place.
#[derive(Clone)]
pub struct Row<'a> {
    mechanism: &'a dyn Mechanism,
    /// Shared by the copies a shared run makes.
    header: Arc<[String]>,
    /// The body columns (orientation, centre-of-gravity motion and its polar parts).
    bodies: Range<usize>,
    /// Whether to compute them; else they are NaN. Their arc tangents and hypotenuses are
    /// most of a row's cost, and no chart draws them: a row for the charts alone skips them.
    fill_bodies: bool,
    /// Families with a total (the names of the header's force blocks).
    with_total: bool,
    total_shares: Vec<f64>,
    /// Which of each stage's values its columns hold.
    stages: Arc<[Vec<usize>]>,
}

impl<'a> Row<'a> {
    /// The row of `mechanism` run with `run`'s families and stages.
    pub fn new(mechanism: &'a dyn Mechanism, run: &RunLayout) -> Self {
        let mut names: Vec<&str> = run.families.to_vec();
        let with_total = run.families.len() > 1;
        if with_total {
            names.push("total");
        }
        let (header, bodies) = header(mechanism, &names, run.gas, run.stages);
        Self {
            mechanism,
            header: header.into(),
            bodies,
            fill_bodies: true,
            with_total,
            total_shares: vec![0.0; mechanism.topology().bodies.len()],
            stages: run
                .stages
                .iter()
                .map(|s| s.iter().map(|c| c.value).collect())
                .collect(),
        }
    }

    /// The column names.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// Leaves the body columns NaN unless `reads` says one of them is read (by its index).
    pub fn skip_unread_bodies(&mut self, reads: impl Fn(usize) -> bool) {
        self.fill_bodies = self.bodies.clone().any(reads);
    }

    /// Appends the step's row to `r` (NaN for a quantity undefined at the step).
    pub fn fill(&mut self, s: &Step, r: &mut Vec<f64>) {
        let t = self.mechanism.topology();
        let st = s.state;
        let start = r.len();
        r.extend([
            st.crank.angle.to_degrees(),
            st.crank.time,
            st.crank.speed,
            st.crank.acceleration,
        ]);
        for p in &st.pistons {
            r.extend([p.position, p.velocity, p.acceleration, p.dx_dtheta]);
        }
        if self.fill_bodies {
            for b in &st.bodies {
                let polar = PolarComponents::of(&b.cg);
                r.extend([
                    b.orientation.arg().to_degrees(),
                    b.angular_velocity,
                    b.angular_acceleration,
                    b.cg.position.re,
                    b.cg.position.im,
                    b.cg.velocity.norm(),
                    b.cg.acceleration.norm(),
                    polar.radial_acceleration,
                    polar.coriolis_acceleration,
                    polar.tangential_acceleration,
                    polar.normal_acceleration,
                ]);
            }
        } else {
            r.resize(r.len() + self.bodies.len(), f64::NAN);
        }
        r.extend(st.joints.iter().map(|j| j.relative_speed));
        r.extend(&st.extras);
        if let Some(p) = s.pressure {
            r.push(p);
            r.push(s.piston_forces.first().copied().unwrap_or(0.0));
        }
        if self.with_total {
            for (k, total) in self.total_shares.iter_mut().enumerate() {
                *total = s.shares.iter().map(|sh| sh[k]).sum();
            }
        }
        let total = self
            .with_total
            .then_some((s.total, self.total_shares.as_slice()));
        let families = s.families.iter().zip(s.shares.iter().map(Vec::as_slice));
        for (loads, shares) in families.chain(total) {
            for ((j, l), m) in t.joints.iter().zip(&loads.joints).zip(&st.joints) {
                r.extend([l.force.re, l.force.im, l.force.norm()]);
                match j.kind {
                    JointKind::Prismatic => r.push(l.moment),
                    JointKind::GearMesh { .. } => {
                        r.extend([tangential(l.force, m), radial(l.force, m)]);
                    }
                    JointKind::Revolute(_) => {}
                }
            }
            r.push(loads.crank_torque);
            r.extend(shares);
        }
        for (columns, values) in self.stages.iter().zip(s.stages) {
            r.extend(columns.iter().map(|&k| values[k]));
        }
        debug_assert_eq!(
            r.len() - start,
            self.header.len(),
            "a row must match the header"
        );
    }
}

/// The recorder of the report's charts of `mechanism`'s rows `row`, `rows` of them, held in
/// the file `file` names (or none: the crank train's label).
fn chart_recorder(
    row: &Row,
    mechanism: &dyn Mechanism,
    rows: usize,
    file: String,
) -> ChartRecorder {
    let joints: Vec<String> = mechanism
        .topology()
        .joints
        .iter()
        .map(|j| j.name.to_string())
        .collect();
    ChartRecorder::new(row.header(), &joints, rows, MAX_POINTS, file)
}

/// A sink writing the per-step rows of one crank train to its files, and thinning them for the
/// report's charts if asked.
pub struct PerStepSink<'a> {
    row: Row<'a>,
    decimation: usize,
    last_step: usize,
    files: Writer,
    charts: Option<ChartRecorder>,
}

impl<'a> PerStepSink<'a> {
    /// Creates `<label>.csv` and/or `<label>.npy` (with `<label>.columns.json`) in `dir`, as
    /// `options` asks, and records the report's charts if `charts`, for `mechanism` run with
    /// `run`'s families and stages over `last_step + 1` steps; `None` if `options` asks for no
    /// file ([`ChartSink`] records the charts alone). The charts take the rows the files take
    /// (every `options.decimation`-th step and the last), so that a chart draws the very rows
    /// of the file it names.
    pub fn create(
        dir: &Path,
        label: &str,
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        options: OutputOptions,
        last_step: usize,
        charts: bool,
    ) -> anyhow::Result<Option<Self>> {
        if !(options.csv || options.npy) {
            return Ok(None);
        }
        let row = Row::new(mechanism, run);
        let rows = row_count(last_step, options.decimation);
        let charts = charts.then(|| {
            let file = if options.csv {
                format!("{label}.csv")
            } else {
                format!("{label}.npy")
            };
            chart_recorder(&row, mechanism, rows, file)
        });
        let files = Writer::start(dir, label, row.header(), rows, options)?;
        Ok(Some(Self {
            row,
            decimation: options.decimation,
            last_step,
            files,
            charts,
        }))
    }

    /// Writes out the last rows and waits until every file is complete; returns the charts'
    /// series if they were recorded.
    pub fn finish(self) -> anyhow::Result<Option<ChartData>> {
        self.files.finish()?;
        Ok(self.charts.map(ChartRecorder::finish))
    }
}

impl Sink for PerStepSink<'_> {
    /// The files hold the torque shares and the extras.
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        if s.index % self.decimation != 0 && s.index != self.last_step {
            return Ok(());
        }
        let files = &mut self.files;
        let start = files.block.len();
        self.row.fill(s, &mut files.block);
        finite_row(
            self.row.header(),
            &files.block[start..],
            0..self.row.header().len(),
            s,
        )?;
        if let Some(c) = &mut self.charts {
            c.record(&files.block[start..]);
        }
        if files.block.len() >= BLOCK_ROWS * files.columns {
            files.send()?;
        }
        Ok(())
    }
}

/// A sink thinning the per-step rows of a crank train that writes no file for the report's
/// charts: the rows [`PerStepSink`] would write (every `decimation`-th step and the last) that
/// the charts take ([`ChartRows`]), the row's undrawn columns left unfilled. The
/// pieces of a shared run ([`cardan_dynamics::run_parallel`]) keep their rows until they are
/// joined, in the steps' order: the charts are the same as a run by one thread gives.
#[derive(Clone)]
pub struct ChartSink<'a> {
    row: Row<'a>,
    decimation: usize,
    last_step: usize,
    pick: ChartRows,
    /// The next step the charts take (found at the first step this sink takes, then counted on:
    /// no division per step).
    next: Option<usize>,
    /// The recorder; `None` in a piece of a shared run.
    recorder: Option<ChartRecorder>,
    /// The columns the charts read (shared by the pieces).
    read: Arc<[usize]>,
    /// The row being filled, and a row being recorded (NaN where the charts do not read).
    scratch: Vec<f64>,
    whole: Vec<f64>,
    /// The rows taken and not yet recorded, one after the other, each of the `read` columns
    /// only, and the steps of the first and the last one taken.
    rows: Vec<f64>,
    first_taken: Option<usize>,
    last_taken: Option<usize>,
    /// Where a step the charts take is gathered from a block's columns.
    step: StepScratch,
}

impl<'a> ChartSink<'a> {
    /// The charts of `mechanism` run with `run`'s families and stages over `last_step + 1`
    /// steps, its rows every `decimation`-th step and the last; `label` names the series.
    pub fn new(
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        decimation: usize,
        last_step: usize,
        label: &str,
    ) -> Self {
        let mut row = Row::new(mechanism, run);
        let rows = row_count(last_step, decimation);
        let recorder = chart_recorder(&row, mechanism, rows, label.to_string());
        row.skip_unread_bodies(|k| recorder.reads(k));
        let width = row.header().len();
        Self {
            row,
            decimation,
            last_step,
            pick: recorder.rows(),
            next: None,
            read: (0..width).filter(|&k| recorder.reads(k)).collect(),
            recorder: Some(recorder),
            scratch: Vec::with_capacity(width),
            whole: vec![f64::NAN; width],
            rows: Vec::new(),
            first_taken: None,
            last_taken: None,
            step: StepScratch::for_topology(mechanism.topology()),
        }
    }

    /// The first step from `step` on whose row the charts take (`usize::MAX` past the last).
    fn taken_from(&self, step: usize) -> usize {
        if step > self.last_step {
            return usize::MAX;
        }
        // The rows taken are every stride-th and the last (whose step is the last step).
        let last_row = row_count(self.last_step, self.decimation) - 1;
        let k = self.pick.next_taken(step.div_ceil(self.decimation));
        if k >= last_row {
            self.last_step
        } else {
            k * self.decimation
        }
    }

    /// Records the rows taken so far (in a sink that has the recorder).
    fn record(&mut self) {
        if let Some(r) = &mut self.recorder {
            for row in self.rows.chunks_exact(self.read.len()) {
                for (&k, &v) in self.read.iter().zip(row) {
                    self.whole[k] = v;
                }
                r.add(&self.whole);
            }
            self.rows.clear();
        }
    }

    /// The thinned series.
    pub fn finish(mut self) -> Option<ChartData> {
        self.record();
        self.recorder.map(ChartRecorder::finish)
    }
}

impl ChartSink<'_> {
    /// Takes the row of `s`, a step the charts take.
    fn take(&mut self, s: &Step) -> Result<(), String> {
        self.scratch.clear();
        self.row.fill(s, &mut self.scratch);
        finite_row(
            self.row.header(),
            &self.scratch,
            self.read.iter().copied(),
            s,
        )?;
        self.rows.extend(self.read.iter().map(|&k| self.scratch[k]));
        self.first_taken.get_or_insert(s.index);
        self.last_taken = Some(s.index);
        // One row at a time, unless this is a piece of a shared run.
        self.record();
        Ok(())
    }
}

/// Fails the step `s` if a number of its row `row` among `columns` is infinite, naming the
/// column (the CSV's name) and the crank angle: the stepper checks what the loads are made of
/// (NaN included), but a derived column (a magnitude, a torque share, a power) can still
/// overflow. A NaN here is a documented empty cell (a torque share while the crank stands
/// still, an extra where it is undefined).
fn finite_row(
    header: &[String],
    row: &[f64],
    columns: impl IntoIterator<Item = usize>,
    s: &Step,
) -> Result<(), String> {
    match columns.into_iter().find(|&k| row[k].is_infinite()) {
        None => Ok(()),
        Some(k) => Err(format!(
            "crank angle {:.4}°: {} is not finite ({})",
            s.state.crank.angle.to_degrees(),
            header[k],
            row[k]
        )),
    }
}

impl Sink for ChartSink<'_> {
    /// Only the steps the charts take, each gathered from the block's columns (a long run's
    /// charts take one step in many).
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        let end = block.first + block.len();
        let mut next = match self.next {
            Some(n) => n,
            None => self.taken_from(block.first),
        };
        let mut scratch = std::mem::take(&mut self.step);
        while next < end {
            let s = block.step(next - block.first, &mut scratch);
            self.take(&s).map_err(|message| (next, message))?;
            next = self.taken_from(next + 1);
        }
        self.step = scratch;
        self.next = Some(next);
        Ok(())
    }

    fn wants_steps(&self) -> bool {
        false
    }
}

impl cardan_dynamics::Joinable for ChartSink<'_> {
    fn fork(&self) -> Self {
        Self {
            recorder: None,
            ..self.clone()
        }
    }

    fn join(&mut self, later: Self) {
        // The step both pieces took is recorded once.
        let width = self.read.len();
        let skip = usize::from(later.first_taken.is_some() && later.first_taken <= self.last_taken);
        self.rows
            .extend_from_slice(&later.rows[(skip * width).min(later.rows.len())..]);
        if later.last_taken.is_some() {
            self.last_taken = later.last_taken;
        }
        self.record();
    }
}

/// The per-step files of one crank train: the run's thread copies rows into a block, a thread
/// of the writer's own formats and writes the blocks.
struct Writer {
    /// The rows of the block being filled, one after the other.
    block: Vec<f64>,
    columns: usize,
    to_writer: Option<SyncSender<Vec<f64>>>,
    /// Blocks the writer is done with, for reuse.
    spare: Receiver<Vec<f64>>,
    writer: Option<JoinHandle<anyhow::Result<()>>>,
}

impl Writer {
    /// Creates the files `options` asks for in `dir`, named by `label`, for `rows` rows of
    /// `header`, and starts their thread.
    fn start(
        dir: &Path,
        label: &str,
        header: &[String],
        rows: usize,
        options: OutputOptions,
    ) -> anyhow::Result<Self> {
        let csv = if options.csv {
            Some(CsvFile::create(
                &dir.join(format!("{label}.csv")),
                header,
                options.significant_digits,
            )?)
        } else {
            None
        };
        let npy = if options.npy {
            let names = dir.join(format!("{label}.columns.json"));
            let json = serde_json::to_string(header)? + "\n";
            crate::output::write_file(&names, json.as_bytes())?;
            Some(NpyFile::create(
                &dir.join(format!("{label}.npy")),
                rows,
                header.len(),
            )?)
        } else {
            None
        };
        let columns = header.len();
        let (to_writer, blocks) = sync_channel::<Vec<f64>>(2);
        let (give_back, spare) = sync_channel::<Vec<f64>>(3);
        let writer = std::thread::Builder::new()
            .name(format!("{label} writer"))
            .spawn(move || {
                let mut files = Files { csv, npy, columns };
                for block in blocks {
                    files.write(&block)?;
                    // The run may have finished and stopped taking blocks back.
                    let _ = give_back.try_send(block);
                }
                files.finish(rows)
            })
            .context("start the thread writing the per-step files")?;
        Ok(Self {
            block: Vec::with_capacity(BLOCK_ROWS * columns),
            columns,
            to_writer: Some(to_writer),
            spare,
            writer: Some(writer),
        })
    }

    /// Hands the filled rows to the writer.
    fn send(&mut self) -> Result<(), String> {
        let next = self
            .spare
            .try_recv()
            .unwrap_or_else(|_| Vec::with_capacity(BLOCK_ROWS * self.columns));
        let block = std::mem::replace(&mut self.block, next);
        self.block.clear();
        let sent = self.to_writer.as_ref().map(|w| w.send(block));
        match sent {
            Some(Ok(())) => Ok(()),
            // The writer stopped: its error says why.
            _ => Err(self
                .join()
                .err()
                .unwrap_or_else(|| "the writer stopped".into())),
        }
    }

    /// Waits for the writer to write everything it was given.
    fn join(&mut self) -> Result<(), String> {
        self.to_writer = None;
        match self.writer.take().map(JoinHandle::join) {
            Some(Ok(Ok(()))) | None => Ok(()),
            Some(Ok(Err(e))) => Err(format!("{e:#}")),
            Some(Err(_)) => Err("the thread writing the per-step files panicked".into()),
        }
    }

    /// Writes out the last rows and waits until every file is complete.
    fn finish(mut self) -> anyhow::Result<()> {
        if !self.block.is_empty() {
            self.send().map_err(anyhow::Error::msg)?;
        }
        self.join().map_err(anyhow::Error::msg)
    }
}

impl Drop for Writer {
    /// A run that stopped early (an error) still stops its writer; the files are left
    /// incomplete in the case's temporary folder, which is then removed.
    fn drop(&mut self) {
        let _ = self.join();
    }
}

/// The files the writing thread fills.
struct Files {
    csv: Option<CsvFile>,
    npy: Option<NpyFile>,
    columns: usize,
}

impl Files {
    fn write(&mut self, block: &[f64]) -> anyhow::Result<()> {
        if let Some(c) = &mut self.csv {
            c.write(block, self.columns)?;
        }
        if let Some(n) = &mut self.npy {
            n.write(block)?;
        }
        Ok(())
    }

    fn finish(self, rows: usize) -> anyhow::Result<()> {
        if let Some(c) = self.csv {
            c.finish()?;
        }
        if let Some(n) = self.npy {
            n.finish(rows)?;
        }
        Ok(())
    }
}

/// CSV text: numbers only, no quoting; a NaN (a quantity undefined at the step) is an empty
/// cell; each number the shortest text that reads back to it (zmij), or rounded to
/// `significant_digits`.
struct CsvFile {
    path: PathBuf,
    out: BufWriter<File>,
    significant_digits: Option<usize>,
    line: Vec<u8>,
}

impl CsvFile {
    fn create(
        path: &Path,
        header: &[String],
        significant_digits: Option<usize>,
    ) -> anyhow::Result<Self> {
        let file = File::create(path).with_context(|| format!("create {}", path.display()))?;
        let mut out = BufWriter::with_capacity(1 << 18, file);
        writeln!(out, "{}", header.join(","))?;
        Ok(Self {
            path: path.to_path_buf(),
            out,
            significant_digits,
            line: Vec::new(),
        })
    }

    fn write(&mut self, block: &[f64], columns: usize) -> anyhow::Result<()> {
        let mut buffer = zmij::Buffer::new();
        for row in block.chunks_exact(columns) {
            self.line.clear();
            for (k, &v) in row.iter().enumerate() {
                if k > 0 {
                    self.line.push(b',');
                }
                if v.is_nan() {
                    continue;
                }
                match self.significant_digits {
                    Some(d) => write!(self.line, "{:.*e}", d - 1, v)?,
                    None => self.line.extend_from_slice(buffer.format(v).as_bytes()),
                }
            }
            self.line.push(b'\n');
            self.out
                .write_all(&self.line)
                .with_context(|| format!("write {}", self.path.display()))?;
        }
        Ok(())
    }

    fn finish(mut self) -> anyhow::Result<()> {
        self.out
            .flush()
            .with_context(|| format!("write {}", self.path.display()))
    }
}

/// An NPY 1.0 file of a rows × columns array of little-endian f64 in Fortran order (column
/// after column), written block by block in place: column `c`'s rows `r0..` start at byte
/// `header + 8·(c·rows + r0)`.
struct NpyFile {
    path: PathBuf,
    file: File,
    rows: usize,
    columns: usize,
    header: u64,
    /// Rows written so far.
    written: usize,
    bytes: Vec<u8>,
}

/// The NPY 1.0 preamble for a `rows` × `columns` f64 array in Fortran order: magic, version,
/// header length, the header dictionary padded with spaces to a multiple of 64 bytes and ended
/// by a newline (NumPy's `numpy.lib.format`).
pub fn npy_header(rows: usize, columns: usize) -> Vec<u8> {
    let dict = format!("{{'descr': '<f8', 'fortran_order': True, 'shape': ({rows}, {columns}), }}");
    let unpadded = 10 + dict.len() + 1;
    let len = unpadded.div_ceil(64) * 64;
    let mut h = b"\x93NUMPY\x01\x00".to_vec();
    h.extend_from_slice(&((len - 10) as u16).to_le_bytes());
    h.extend_from_slice(dict.as_bytes());
    h.resize(len - 1, b' ');
    h.push(b'\n');
    h
}

impl NpyFile {
    fn create(path: &Path, rows: usize, columns: usize) -> anyhow::Result<Self> {
        let mut file = File::create(path).with_context(|| format!("create {}", path.display()))?;
        let header = npy_header(rows, columns);
        file.write_all(&header)?;
        let size = header.len() as u64 + 8 * (rows as u64) * (columns as u64);
        file.set_len(size)
            .with_context(|| format!("size {} to {size} bytes", path.display()))?;
        Ok(Self {
            path: path.to_path_buf(),
            file,
            rows,
            columns,
            header: header.len() as u64,
            written: 0,
            bytes: Vec::new(),
        })
    }

    fn write(&mut self, block: &[f64]) -> anyhow::Result<()> {
        let n = block.len() / self.columns;
        if self.written + n > self.rows {
            bail!(
                "{}: more rows than the {} announced",
                self.path.display(),
                self.rows
            );
        }
        for c in 0..self.columns {
            self.bytes.clear();
            for row in block.chunks_exact(self.columns) {
                self.bytes.extend_from_slice(&row[c].to_le_bytes());
            }
            let at = self.header + 8 * (c * self.rows + self.written) as u64;
            self.file.seek(SeekFrom::Start(at))?;
            self.file
                .write_all(&self.bytes)
                .with_context(|| format!("write {}", self.path.display()))?;
        }
        self.written += n;
        Ok(())
    }

    fn finish(self, rows: usize) -> anyhow::Result<()> {
        if self.written != rows {
            bail!(
                "{}: {} rows written of the {rows} announced",
                self.path.display(),
                self.written
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chart sink finds the next step the charts take by arithmetic: the steps the files
    /// would write (every `decimation`-th and the last) whose rows the charts take.
    #[test]
    fn chart_sink_takes_the_rows_the_recorder_takes() {
        // Any mechanism: the rows' layout does not matter here.
        let m = (cardan_mechanism::MECHANISMS[0].build)(
            &cardan_mechanism::MachineGeometry {
                crank_length: 0.06,
                rod_length: 0.14,
                bore: 0.12,
                pin_offset: 0.0,
            },
            &cardan_mechanism::MassInputs::default(),
            &cardan_mechanism::Options::new(),
        )
        .unwrap();
        let layout = RunLayout {
            families: &["inertial"],
            gas: false,
            stages: &[],
        };
        for (last_step, decimation) in [(10, 1), (100_000, 1), (100_000, 3), (700_001, 7)] {
            let sink = ChartSink::new(m.as_ref(), &layout, decimation, last_step, "c");
            let rows = row_count(last_step, decimation);
            let taken = |i: usize| {
                let row = if i % decimation == 0 {
                    i / decimation
                } else if i == last_step {
                    rows - 1
                } else {
                    return false;
                };
                sink.pick.takes(row)
            };
            let mut next = usize::MAX;
            for i in (0..=last_step).rev() {
                if taken(i) {
                    next = i;
                }
                assert_eq!(
                    sink.taken_from(i),
                    next,
                    "step {i} of {last_step}, every {decimation}"
                );
            }
            assert_eq!(sink.taken_from(last_step + 1), usize::MAX);
        }
    }

    #[test]
    fn row_count_is_every_nth_step_and_the_last() {
        for (last, d) in [(0, 1), (10, 1), (10, 3), (9, 3), (7200, 7), (5, 10)] {
            let expected = (0..=last).filter(|i| i % d == 0 || *i == last).count();
            assert_eq!(row_count(last, d), expected, "last {last}, every {d}");
        }
    }

    #[test]
    fn npy_header_is_aligned_and_names_the_shape() {
        for (r, c) in [(1, 1), (7201, 143), (10_000_001, 999)] {
            let h = npy_header(r, c);
            assert_eq!(h.len() % 64, 0);
            assert_eq!(&h[..8], b"\x93NUMPY\x01\x00");
            assert_eq!(u16::from_le_bytes([h[8], h[9]]) as usize, h.len() - 10);
            assert_eq!(*h.last().unwrap(), b'\n');
            let text = std::str::from_utf8(&h[10..]).unwrap();
            assert!(text.contains(&format!("'shape': ({r}, {c})")), "{text}");
            assert!(text.contains("'fortran_order': True"));
        }
    }
}
