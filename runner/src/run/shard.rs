//! Shards (`--shard K/N`): the cases of a batch (sweeps expanded, each optimisation one whole
//! unit) split into N deterministic parts of near-equal expected cost ([`part`]), and the record a shard leaves in its output
//! folder (`shard.json`, [`Manifest`]) by which `cardan merge` gathers the shards into what one
//! run writes (`merge.rs`) and refuses shards of other inputs or another program.

use super::stamp::{input_hash, optimization_hash, Fnv, PROGRAM};
use super::table::TableSweep;
use anyhow::Context;
use cardan_case::case::Case;
use cardan_case::optimize::Optimization;
use cardan_report::files;
use serde_json::{json, Value};
use std::path::Path;

/// The record's file name in a shard's output folder.
pub const MANIFEST: &str = "shard.json";

/// The expected cost of running `case`, in step-evaluations: its steps, times its crank
/// trains (mechanisms), times one plus its per-step stages (the loss budget, the gear
/// rating), each of which costs about as much as the kinetostatics of a step. Its per-step
/// files count as one stage more.
pub fn cost(case: &Case) -> u128 {
    let stages = 1
        + usize::from(case.friction.is_some())
        + usize::from(case.gear.is_some())
        + usize::from(case.output.csv || case.output.npy);
    (case.steps as u128 + 1) * case.mechanisms.len().max(1) as u128 * stages as u128
}

/// Which of `cases` the K-th (from 1) of `n` shards runs: the cases taken by decreasing
/// [`cost`] (ties in their order), each given to the shard with the least cost so far (ties to
/// the lowest): Graham's longest-processing-time rule (R. L. Graham, "Bounds on
/// multiprocessing timing anomalies", SIAM J. Appl. Math. 17 (1969) 416-429: within 4/3 of the
/// best split). The points of a sweep written as a table (no case folders) are split into
/// contiguous ranges (`assign`). The same cases give the same parts on every machine.
pub fn assignment(cases: &[Case], n: usize) -> Vec<usize> {
    assign(cases, &[], &[], n).0
}

/// The expected cost of an optimisation (`[optimize]`), in step-evaluations: at most its
/// starts times its evaluations a start, each a run of one mechanism's case as the file gives
/// it ([`cost`]), for each of its mechanisms. An upper bound (a start that converges stops
/// early), the same on every machine: an optimisation is one unit of [`assignment`]'s rule, run
/// whole by one shard.
pub fn optimization_cost(o: &Optimization) -> u128 {
    let evaluations = (o.starts * o.max_evaluations) as u128;
    o.mechanisms
        .iter()
        .map(|m| {
            o.case_at(m, &vec![None; o.variables.len()])
                .map_or(1, |case| cost(&case))
                * evaluations
        })
        .sum()
}

/// A table sweep of fewer points goes whole to one shard (one unit of [`assignment`]'s rule):
/// its ranges would be too small to be worth a table each.
pub const SPLIT_FROM: usize = 64;

/// The points `start..end` of a table sweep, run by shard `shard` (from 1).
pub type Range = (usize, usize, usize);

/// The shard (from 1) of each of `cases`, the ranges of points of each sweep of `tables`
/// (a sweep written as a table), and the shard of each of `optimizations` (each one unit, of
/// [`optimization_cost`]). The cases, and each table of fewer than [`SPLIT_FROM`] points
/// (one unit of its points' cost: the first point's [`cost`] times its points), are dealt by
/// [`assignment`]'s rule; then each larger table, in order, is split into contiguous ranges
/// that fill the shards' costs up to one level ([`fill`]), shard 1 taking the first range,
/// shard 2 the next, and so on (a shard already above the level takes none).
pub(super) fn assign(
    cases: &[Case],
    tables: &[TableSweep],
    optimizations: &[Optimization],
    n: usize,
) -> (Vec<usize>, Vec<Vec<Range>>, Vec<usize>) {
    let n = n.max(1);
    let mut points: std::collections::HashMap<&str, usize> = Default::default();
    for c in cases {
        if let Some((s, _)) = &c.sweep {
            *points.entry(s).or_default() += 1;
        }
    }
    // Each unit: its first case, its cases, its cost.
    let mut units: Vec<(usize, Vec<usize>, u128)> = Vec::new();
    let mut table_unit: std::collections::HashMap<&str, usize> = Default::default();
    for (i, c) in cases.iter().enumerate() {
        let table = c
            .sweep
            .as_ref()
            .filter(|(s, _)| !super::table::case_folders(c, points[s.as_str()]));
        let u = match table {
            Some((s, _)) => *table_unit.entry(s).or_insert_with(|| {
                units.push((i, Vec::new(), 0));
                units.len() - 1
            }),
            None => {
                units.push((i, Vec::new(), 0));
                units.len() - 1
            }
        };
        units[u].1.push(i);
        units[u].2 += cost(c);
    }
    let split = |t: &TableSweep| t.points() >= SPLIT_FROM && n > 1;
    for (t, table) in tables.iter().enumerate().filter(|(_, t)| !split(t)) {
        let i = cases.len() + t;
        units.push((i, vec![i], cost(&table.first) * table.points() as u128));
    }
    for (j, o) in optimizations.iter().enumerate() {
        let i = cases.len() + tables.len() + j;
        units.push((i, vec![i], optimization_cost(o)));
    }
    units.sort_by_key(|(first, _, cost)| (std::cmp::Reverse(*cost), *first));
    let mut load = vec![0u128; n];
    let mut shard_of = vec![0; cases.len() + tables.len() + optimizations.len()];
    for (_, members, cost) in units {
        let k = (0..n).min_by_key(|&k| (load[k], k)).unwrap_or(0);
        load[k] += cost;
        for i in members {
            shard_of[i] = k + 1;
        }
    }
    let optimization_shards = shard_of.split_off(cases.len() + tables.len());
    let whole = shard_of.split_off(cases.len());
    let ranges = tables
        .iter()
        .zip(whole)
        .map(|(t, k)| {
            if !split(t) {
                return vec![(0, t.points(), k)];
            }
            let per_point = cost(&t.first).max(1);
            let amounts = fill(&mut load, per_point * t.points() as u128);
            let (mut sum, mut start) = (0u128, 0usize);
            let mut ranges = Vec::new();
            for (k, a) in amounts.into_iter().enumerate() {
                sum += a;
                // The boundary nearest the cost so far; the last is the points' count.
                let end = ((sum + per_point / 2) / per_point).min(t.points() as u128) as usize;
                if end > start {
                    ranges.push((start, end, k + 1));
                    start = end;
                }
            }
            ranges
        })
        .collect();
    (shard_of, ranges, optimization_shards)
}

/// Water-filling: shares of `total` (each shard's, summing to `total`) that raise the lowest
/// of `load` to one level (the lowest-loaded first; what does not divide evenly one unit more
/// to the lowest-loaded), added to `load`. Integers: the same on every machine.
fn fill(load: &mut [u128], total: u128) -> Vec<u128> {
    let n = load.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&k| (load[k], k));
    // The m lowest are filled: raising them to the next load would take `total` or more.
    let (mut m, mut sum) = (0, 0u128);
    while m < n {
        let next = load[order[m]];
        if m > 0 && m as u128 * next - sum >= total {
            break;
        }
        sum += next;
        m += 1;
    }
    let (level, extra) = ((total + sum) / m as u128, (total + sum) % m as u128);
    let mut amounts = vec![0u128; n];
    for (i, &k) in order[..m].iter().enumerate() {
        amounts[k] = level - load[k] + u128::from((i as u128) < extra);
        load[k] += amounts[k];
    }
    amounts
}

/// Whether each of `cases` is in the K-th of `n` shards ([`assignment`]).
pub fn part(cases: &[Case], k: usize, n: usize) -> Vec<bool> {
    assignment(cases, n).into_iter().map(|s| s == k).collect()
}

/// Keeps in `cases`, `tables` and `optimizations` only the K-th of `n` parts ([`assign`]),
/// and returns the shard's record of the whole batch ([`Manifest::new`]).
pub(super) fn take(
    cases: &mut Vec<Case>,
    tables: &mut Vec<TableSweep>,
    optimizations: &mut Vec<Optimization>,
    (k, n): (usize, usize),
    reports: bool,
    failures: &[String],
) -> Manifest {
    let manifest = Manifest::new(cases, tables, optimizations, (k, n), reports, failures);
    let (mine, ranges, optimization_shards) = assign(cases, tables, optimizations, n);
    let mut index = 0;
    optimizations.retain(|_| {
        index += 1;
        optimization_shards[index - 1] == k
    });
    index = 0;
    cases.retain(|_| {
        index += 1;
        mine[index - 1] == k
    });
    // Each table's range of this shard (at most one: the ranges are dealt in shard order).
    let mut ranges = ranges.into_iter();
    tables.retain_mut(|t| {
        let range = ranges
            .next()
            .and_then(|r| r.into_iter().find(|&(_, _, s)| s == k));
        t.range = range.map(|(start, end, _)| start..end);
        t.range.is_some()
    });
    manifest
}

/// What a shard records of its run: the program, a hash of the whole batch's inputs, which
/// shard of how many it is, whether reports were written, and every case of the batch (its
/// name, its sweep, its shard) in the batch's order.
#[derive(Debug, Clone, PartialEq)]
pub struct Manifest {
    pub program: String,
    pub inputs_hash: String,
    /// (K, N).
    pub shard: (usize, usize),
    pub reports: bool,
    /// (case name, its sweep, the shard that runs it) of every case of the batch (a sweep
    /// written as a table is in `tables`), then of every optimisation (its folder is copied as
    /// a case's).
    pub cases: Vec<(String, Option<String>, usize)>,
    /// Every sweep written as a table: its name, its points, and the ranges of points each
    /// shard runs (`assign`), in order.
    pub tables: Vec<(String, usize, Vec<Range>)>,
    /// The failures this shard met (the batch's unreadable case files, its failed cases).
    pub failures: Vec<String>,
}

impl Manifest {
    /// The record of shard `k` of `n` of the batch `cases`, `tables` and `optimizations` (as
    /// they run: after the command line's overrides); `failures` so far are the case files
    /// that could not be read, which change the inputs as much as the cases do. A sweep written
    /// as a table is hashed by its definition and its first point, and listed with its ranges;
    /// an optimisation by its input hash ([`optimization_hash`]).
    pub fn new(
        cases: &[Case],
        tables: &[TableSweep],
        optimizations: &[Optimization],
        (k, n): (usize, usize),
        reports: bool,
        failures: &[String],
    ) -> Self {
        let (shards, table_ranges, optimization_shards) = assign(cases, tables, optimizations, n);
        let mut hash = Fnv::default();
        hash.update(format!("{n} shards, reports {reports}").as_bytes());
        for f in failures {
            hash.update(f.as_bytes());
        }
        for case in cases {
            hash.update(case.name.as_bytes())
                .update(input_hash(case, reports && case.sweep.is_none()).as_bytes());
        }
        for t in tables {
            hash.update(t.sweep.name.as_bytes())
                .update(input_hash(&t.first, false).as_bytes())
                .update(t.sweep.definition().as_bytes())
                .update(format!("{} points", t.points()).as_bytes());
        }
        for o in optimizations {
            hash.update(o.name.as_bytes())
                .update(optimization_hash(o, reports).as_bytes());
        }
        let entries: Vec<(String, Option<String>, usize)> = cases
            .iter()
            .zip(shards)
            .map(|(c, s)| (c.name.clone(), c.sweep.as_ref().map(|(s, _)| s.clone()), s))
            .chain(
                optimizations
                    .iter()
                    .zip(optimization_shards)
                    .map(|(o, s)| (o.name.clone(), None, s)),
            )
            .collect();
        let tables = tables
            .iter()
            .zip(table_ranges)
            .map(|(t, r)| (t.sweep.name.clone(), t.points(), r))
            .collect();
        Self {
            program: PROGRAM.to_string(),
            inputs_hash: hash.hex(),
            shard: (k, n),
            reports,
            cases: entries,
            tables,
            failures: Vec::new(),
        }
    }

    /// Writes the record, with the shard's `failures`, into the shard's output folder `out`.
    pub fn write(mut self, out: &Path, failures: &[String]) -> anyhow::Result<()> {
        self.failures = failures.to_vec();
        let record = json!({
            "program": self.program,
            "inputs_hash": self.inputs_hash,
            "shard": [self.shard.0, self.shard.1],
            "reports": self.reports,
            "cases": self.cases.iter().map(|(c, s, k)| json!([c, s, k])).collect::<Vec<_>>(),
            "tables": self.tables.iter().map(|(sweep, points, ranges)| json!({
                "sweep": sweep,
                "points": points,
                "ranges": ranges.iter().map(|(a, b, k)| json!([a, b, k])).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
            "failures": self.failures,
        });
        let mut text = serde_json::to_string_pretty(&record)?;
        text.push('\n');
        std::fs::create_dir_all(out).with_context(|| format!("create {}", out.display()))?;
        cardan_report::files::write_file_replacing(&out.join(MANIFEST), text.as_bytes())
    }

    /// Reads the record of the shard output folder `dir`.
    pub fn read(dir: &Path) -> anyhow::Result<Self> {
        let path = dir.join(MANIFEST);
        let text = files::read_text(&path, files::RESULT_RECORD).with_context(|| {
            format!(
                "read {}: not the output folder of a `cardan run --shard K/N`",
                path.display()
            )
        })?;
        let v: Value =
            serde_json::from_str(&text).with_context(|| format!("read {}", path.display()))?;
        let bad = || anyhow::anyhow!("{}: not a shard record of cardan", path.display());
        let string = |v: &Value| v.as_str().map(String::from).ok_or_else(bad);
        let number = |v: &Value| v.as_u64().map(|n| n as usize).ok_or_else(bad);
        let cases = v["cases"]
            .as_array()
            .ok_or_else(bad)?
            .iter()
            .map(|c| {
                let sweep = match &c[1] {
                    Value::Null => None,
                    s => Some(string(s)?),
                };
                Ok((string(&c[0])?, sweep, number(&c[2])?))
            })
            .collect::<anyhow::Result<_>>()?;
        let tables = v["tables"]
            .as_array()
            .ok_or_else(bad)?
            .iter()
            .map(|t| {
                let ranges = t["ranges"]
                    .as_array()
                    .ok_or_else(bad)?
                    .iter()
                    .map(|r| Ok((number(&r[0])?, number(&r[1])?, number(&r[2])?)))
                    .collect::<anyhow::Result<_>>()?;
                Ok((string(&t["sweep"])?, number(&t["points"])?, ranges))
            })
            .collect::<anyhow::Result<_>>()?;
        Ok(Self {
            program: string(&v["program"])?,
            inputs_hash: string(&v["inputs_hash"])?,
            shard: (number(&v["shard"][0])?, number(&v["shard"][1])?),
            reports: v["reports"].as_bool().ok_or_else(bad)?,
            cases,
            tables,
            failures: v["failures"]
                .as_array()
                .ok_or_else(bad)?
                .iter()
                .map(string)
                .collect::<anyhow::Result<_>>()?,
        })
    }
}

/// Parses `K/N` (1 <= K <= N).
pub fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let err = || format!("--shard {text}: expected K/N with 1 <= K <= N, e.g. 2/3");
    let (k, n) = text.split_once('/').ok_or_else(err)?;
    let (k, n): (usize, usize) = (
        k.trim().parse().map_err(|_| err())?,
        n.trim().parse().map_err(|_| err())?,
    );
    if k == 0 || k > n {
        return Err(err());
    }
    Ok((k, n))
}

/// Removes the record of an earlier run of the shard from its output folder `out`, before
/// anything is written: a run killed now leaves a shard that `cardan merge` refuses as
/// unfinished, not one whose old record vouches for folders of other inputs.
pub fn remove_record(out: &Path) -> Result<(), String> {
    let old = out.join(MANIFEST);
    match std::fs::remove_file(&old) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(format!("remove {}: {e}: nothing was run", old.display()))
        }
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::{fill, parse_shard};

    /// Water-filling: the lowest loads raised to one level, the shares summing to the total,
    /// a shard above the level given nothing.
    #[test]
    fn fill_raises_the_lowest_loads_to_one_level() {
        let mut load = vec![10, 0, 5];
        assert_eq!(fill(&mut load, 20), vec![1, 12, 7]);
        assert_eq!(load, vec![11, 12, 12]);
        let mut load = vec![100, 0, 0];
        assert_eq!(fill(&mut load, 10), vec![0, 5, 5]);
        let mut load = vec![0; 4];
        assert_eq!(fill(&mut load, 7), vec![2, 2, 2, 1]);
        for total in [0, 1, 99, 1_000_001] {
            let mut load = vec![3, 1_000, 7, 7, 0];
            let before = load.clone();
            let shares = fill(&mut load, total);
            assert_eq!(shares.iter().sum::<u128>(), total);
            let level = (0..5).filter(|&k| shares[k] > 0).map(|k| load[k]);
            let (lo, hi) = (level.clone().min(), level.max());
            assert!(hi.zip(lo).is_none_or(|(h, l)| h - l <= 1), "{load:?}");
            for k in 0..5 {
                if shares[k] == 0 {
                    assert!(before[k] >= load.iter().copied().min().unwrap());
                }
            }
        }
    }

    #[test]
    fn shards_are_read_as_k_of_n() {
        assert_eq!(parse_shard("2/3"), Ok((2, 3)));
        assert_eq!(parse_shard("1/1"), Ok((1, 1)));
        for bad in ["0/3", "4/3", "3", "a/b", "1/0", "-1/2"] {
            assert!(parse_shard(bad).is_err(), "{bad}");
        }
    }
}
