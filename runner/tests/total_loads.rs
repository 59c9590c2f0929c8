//! Every shipped case with gas, in both readings of the cardan mesh: the run's total loads at
//! every step equal the general planar solve of the summed inertial and gas loads (the
//! involute mesh's loaded flank is chosen by the total, not per family).

use cardan_case::case;
use cardan_dynamics::{planar, run_summary, GasAt, Solver};
use cardan_mechanism::{Grid, Loads};
use std::path::Path;

#[test]
fn shipped_cases_with_gas_have_the_general_solve_of_their_total() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    let mut checked = 0;
    for file in files {
        let mut text = std::fs::read_to_string(&file).unwrap();
        if text.contains("\n[optimize]") {
            // An optimisation's case, checked as the case the file gives (its `[optimize]` is
            // the search's, not the case's).
            let mut table: toml::Table = text.parse().unwrap();
            table.remove("optimize");
            text = toml::to_string(&table).unwrap();
        }
        if !text.contains("[gas]") {
            continue;
        }
        let mut readings = vec![text.clone()];
        if text.contains("cardan_gear") && !text.contains("[cardan_gear]") {
            readings.push(format!(
                "{text}\n[cardan_gear]\ngear_mesh_model = \"involute\"\n"
            ));
        }
        for text in readings {
            let case = case::parse(&file, &text).unwrap();
            if case.dynamics.is_some() {
                // A solved motion's steps are not a prescribed grid's: its totals are checked
                // on its own motion (crates/dynamics/tests/machine_motion.rs).
                continue;
            }
            let gas = case.gas.as_ref().unwrap();
            for m in &case.mechanisms {
                let t = m.topology();
                let cylinder = gas
                    .cylinder(case.geometry.bore, m.stroke(), case.pistons)
                    .unwrap();
                let steps = cylinder.with_phased_chamber(m.as_ref(), case.crank_phase, |c| {
                    let prepared = gas.model().prepare(*c, case.motion.initial_speed).unwrap();
                    let at = |theta: f64| prepared.at(theta);
                    let at: GasAt = &at;
                    let mut grid = Grid::new(
                        case.motion,
                        case.motion.start_angle,
                        case.end_angle,
                        case.steps,
                    );
                    run_summary(m.as_ref(), &mut grid, Some(at), Solver::ClosedForm, true)
                        .unwrap()
                        .0
                });
                let scale = steps
                    .iter()
                    .flat_map(|s| s.total.joints.iter().map(|j| j.force.norm()))
                    .fold(0.0, f64::max);
                let mut solved = Loads::for_topology(t);
                for s in &steps {
                    planar::loads(t, &s.state, true, &s.piston_forces, &mut solved);
                    for (k, joint) in t.joints.iter().enumerate() {
                        let d = (s.total.joints[k].force - solved.joints[k].force).norm();
                        assert!(
                            d <= 1e-9 * scale,
                            "{}: {}: {} off by {d} N of {scale} N at {}",
                            file.display(),
                            m.name(),
                            joint.name,
                            s.state.crank.angle
                        );
                    }
                    let d = (s.total.crank_torque - solved.crank_torque).abs();
                    assert!(d <= 1e-9 * scale * case.geometry.crank_length);
                }
                checked += 1;
            }
        }
    }
    // 7 shipped cases with gas; the 4 with a cardan gear again in the involute reading.
    assert!(checked >= 16, "only {checked} runs checked");
}
