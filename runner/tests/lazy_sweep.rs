//! A sweep is made a point at a time from its definition (issue 26, million-point sweeps):
//! point k made lazily is the point k of the sweep made all at once (its name, swept values,
//! case table and validated case), in a grid (first field fastest) and zipped; and a sweep
//! written as a table runs in memory bounded by a chunk of points, not by its number of
//! points: a table sweep of four times the points peaks no higher, measured by this test
//! binary's own allocator (every allocation of the process counted, its peak kept).

use cardan_case::case::{cases_of_table, point_case};
use cardan_case::sweep::{expand, Sweep};
use cardan_runner::{run_paths, RunOptions};
use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the bytes live and their peak.
struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is passed on to the system allocator unchanged; only counters are added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let live = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(live, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// A tiny case: one mechanism, no gas, 8 steps; `sweep` is its `[sweep]` table's body.
fn tiny(name: &str, sweep: &str) -> String {
    format!(
        r#"
name = "{name}"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = "90 deg"
end_angle = "450 deg"
initial_speed = "30 rad/s"
angular_acceleration = 0.0
steps = 8
[output]
case_folders = false
[sweep]
{sweep}
"#
    )
}

#[test]
fn a_point_made_lazily_is_the_point_made_all_at_once() {
    let file = Path::new("lazy.toml");
    for sweep in [
        // A grid of 4 × 3 × 5 points (the first field fastest), a list, a range, a log range.
        "\"motion.initial_speed\" = [\"3 rad/s\", \"30 rad/s\", 45.0, \"600 rpm\"]\n\"geometry.rod_length\" = { from = \"140 mm\", to = \"200 mm\", points = 3 }\n\"motion.angular_acceleration\" = { from = 1, to = 1000, points = 5, scale = \"log\" }",
        // Zipped.
        "mode = \"zip\"\n\"motion.initial_speed\" = [3.0, 30.0, 300.0]\n\"geometry.rod_length\" = [\"150 mm\", \"170 mm\", \"190 mm\"]",
    ] {
        let table: toml::Table = toml::from_str(&tiny("lazy", sweep)).unwrap();
        let (name, eager) = expand(file, table.clone()).unwrap().unwrap();
        let lazy = Sweep::define(file, table.clone()).unwrap().unwrap();
        assert_eq!(lazy.name, name);
        assert_eq!(lazy.len(), eager.len());
        let cases = cases_of_table(file, table).unwrap();
        for (k, point) in eager.iter().enumerate() {
            let made = lazy.point(k).unwrap();
            assert_eq!(made.name, point.name, "point {k}");
            assert_eq!(made.values, point.values, "point {k}");
            assert_eq!(made.table, point.table, "point {k}");
            assert_eq!(lazy.point_name(k), point.name);
            assert_eq!(lazy.values(k), point.values);
            let case = point_case(&lazy, k).unwrap();
            assert_eq!(format!("{case:?}"), format!("{:?}", cases[k]), "point {k}");
        }
    }
    // The grid's order: the first field fastest.
    let table: toml::Table = toml::from_str(&tiny(
        "lazy",
        "\"motion.initial_speed\" = [1.0, 2.0]\n\"geometry.rod_length\" = [\"150 mm\", \"170 mm\", \"190 mm\"]",
    ))
    .unwrap();
    let lazy = Sweep::define(file, table).unwrap().unwrap();
    let speeds: Vec<String> = (0..6).map(|k| lazy.values(k)[0].1.clone()).collect();
    let rods: Vec<String> = (0..6).map(|k| lazy.values(k)[1].1.clone()).collect();
    assert_eq!(speeds, ["1.0", "2.0", "1.0", "2.0", "1.0", "2.0"]);
    assert_eq!(
        rods,
        ["150 mm", "150 mm", "170 mm", "170 mm", "190 mm", "190 mm"]
    );
}

/// 40 000 points written as a table: the live heap's peak stays under 64 MB above what it
/// was before the run (the points made all at once held some 7.7 kB each, 387 MB for 50 000 of
/// the shipped pump, docs/performance.md: 300 MB here; a test build runs 40 000 points in about
/// a minute, so CI keeps it), and the table has every row.
/// The live heap's peak above its start, bytes, while a table sweep of `speeds` × 32 points
/// runs (its folder in `dir`), and its number of points.
fn sweep_peak(dir: &Path, speeds: usize) -> (usize, usize) {
    let name = format!("big{speeds}");
    let file = dir.join(format!("{name}.toml"));
    let points = speeds * 32;
    let sweep = format!(
        "\"motion.initial_speed\" = {{ from = \"1 rad/s\", to = \"100 rad/s\", points = {speeds} }}\n\"geometry.rod_length\" = {{ from = \"140 mm\", to = \"300 mm\", points = 32 }}"
    );
    std::fs::write(&file, tiny(&name, &sweep)).unwrap();
    let out = dir.join(format!("out{speeds}"));
    let before = LIVE.load(Ordering::Relaxed);
    PEAK.store(before, Ordering::Relaxed);
    let report = run_paths(&[file], &out, RunOptions::default());
    let peak = PEAK.load(Ordering::Relaxed) - before;
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    assert_eq!(report.sweeps.len(), 1);
    assert_eq!(report.sweeps[0].2, points);
    let header: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join(format!("{name}/sweep.json"))).unwrap(),
    )
    .unwrap();
    assert_eq!(header["rows"], points);
    (peak, points)
}

/// A table sweep's memory does not grow with its number of points: a sweep of four times the
/// points (16 384 against 4 096, so that both hold whole validation chunks of 4 096 points and
/// several run chunks of 1 024) peaks at most 1 MB higher, where keeping anything of each
/// point (a summary row is some 100 values, 800 bytes) would add 10 MB; and the larger one
/// stays under 64 MB.
#[test]
fn a_large_table_sweep_runs_in_bounded_memory() {
    let dir = tempfile::tempdir().unwrap();
    let (small, n_small) = sweep_peak(dir.path(), 128);
    let (large, n_large) = sweep_peak(dir.path(), 512);
    eprintln!(
        "table sweeps: live heap peak {:.1} MB ({n_small} points), {:.1} MB ({n_large} points)",
        small as f64 / 1e6,
        large as f64 / 1e6
    );
    assert!(
        large < small + (1 << 20),
        "the live heap's peak grew with the points: {} kB for {n_small}, {} kB for {n_large}",
        small >> 10,
        large >> 10
    );
    let bound = 64 << 20;
    assert!(
        large < bound,
        "the run's live heap peaked at {} MB above its start (bound {} MB)",
        large >> 20,
        bound >> 20
    );
}
