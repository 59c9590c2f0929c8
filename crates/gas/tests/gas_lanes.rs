//! The gas over a block's lanes (`PreparedGas::lanes`) against the gas a step at a time
//! (`PreparedGas::at`): the Karhula pump's block path takes the chamber volume from the piston
//! positions the mechanism filled and its powers all at once, and must give, lane by lane, the
//! bits of the single step at the same position; the models and chambers it does not fit say
//! so. No paper needed: the two paths are the one formula (A6.1.1.11, A6.2.1.1).

use cardan_gas::{Cylinder, GasModel, KarhulaEngine, KarhulaPump, Polytropic};
use cardan_mechanism::{
    CrankMotion, CrankState, MachineGeometry, MassInputs, Mechanism, Options, StateBlock, LANES,
    MECHANISMS,
};
use std::f64::consts::PI;

/// Every registered mechanism whose piston moves in a cylinder, for two geometries (the
/// thesis's, and a short rod with a pin offset).
fn machines() -> Vec<Box<dyn Mechanism>> {
    let mut all = Vec::new();
    for (crank, rod, offset) in [(0.06, 0.14, 0.0), (0.026, 0.09, -0.01)] {
        let g = MachineGeometry {
            crank_length: crank,
            rod_length: rod,
            bore: 0.12,
            pin_offset: offset,
        };
        for e in MECHANISMS {
            let m = (e.build)(&g, &MassInputs::default(), &Options::new()).unwrap();
            if m.has_cylinder() {
                all.push(m);
            }
        }
    }
    assert!(
        all.len() >= 4,
        "the slider-crank and the cardan gear at least"
    );
    all
}

fn pump(exponent: f64) -> KarhulaPump {
    KarhulaPump {
        gas: Polytropic::new(exponent, 1.07, 101_325.0).unwrap(),
    }
}

/// The cylinder of bore 120 mm and compression ratio `ratio` that `m`'s pistons sweep.
fn cylinder(m: &dyn Mechanism, ratio: f64, pistons: u32) -> Cylinder {
    let swept = f64::from(pistons) * PI / 4.0 * 0.12 * 0.12 * m.stroke();
    Cylinder::with_compression_ratio(0.12, swept, ratio)
        .unwrap()
        .with_pistons(pistons)
        .unwrap()
}

/// The crank angles of a run of the thesis's grid (90° to 810° by 1°, whose points fall on
/// the strokes' ends), and an irregular span over several cycles either side of zero.
fn angles() -> Vec<f64> {
    let mut all: Vec<f64> = (90..=810).map(|d| f64::from(d).to_radians()).collect();
    all.extend((0..1500).map(|k| -31.0 + 0.0417 * f64::from(k)));
    all
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Lane by lane, the pump's block path at the positions `piston_position` gives is its single
/// step at the angle, bit for bit, whatever the slices' length (a block of one, a part of a
/// block, several blocks): for every cylinder mechanism, one piston or two in phase, two
/// exponents.
#[test]
fn the_pumps_lanes_are_its_steps_bit_for_bit() {
    let angles = angles();
    for m in machines() {
        for (ratio, pistons, exponent) in [(12.0, 1, 1.4), (7.5, 2, 1.3)] {
            let model = pump(exponent);
            cylinder(m.as_ref(), ratio, pistons).with_chamber(m.as_ref(), |chamber| {
                let gas = model.prepare(*chamber, 50.0).unwrap();
                let (steps, forces): (Vec<f64>, Vec<f64>) =
                    angles.iter().map(|&theta| gas.at(theta)).unzip();
                let positions: Vec<f64> = angles.iter().map(|&t| m.piston_position(t).0).collect();
                for len in [1, 5, LANES, 100, angles.len()] {
                    let (mut p, mut f) = (vec![f64::NAN; angles.len()], vec![0.0; angles.len()]);
                    for (((a, x), p), f) in angles
                        .chunks(len)
                        .zip(positions.chunks(len))
                        .zip(p.chunks_mut(len))
                        .zip(f.chunks_mut(len))
                    {
                        assert!(gas.lanes(a, x, p, f), "{}", m.name());
                    }
                    assert_eq!(bits(&p), bits(&steps), "{} slices of {len}", m.name());
                    assert_eq!(bits(&f), bits(&forces), "{} slices of {len}", m.name());
                }
                // The intake strokes are at ambient pressure and the compression strokes above.
                let ambient = steps.iter().filter(|&&p| p == 101_325.0).count();
                assert!(ambient > angles.len() / 3 && ambient < 2 * angles.len() / 3);
            });
        }
    }
}

/// A block the mechanism filled at crank states whose direction is e^{iθ} holds the positions
/// of `piston_position`, so that its lanes are the steps bit for bit; on the run's grid, whose
/// directions are rotated from one step to the next (within 1.5e-14 of e^{iθ}), the pressures
/// are the steps' within the round-off that carries to the volume, and every lane is on the
/// same stroke (the intake strokes' lanes exact).
#[test]
fn the_pump_at_a_filled_blocks_positions_is_its_steps() {
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 300.0,
        angular_acceleration: 0.0,
    };
    let grid = motion.grid(PI / 2.0, 4.5 * PI, 720).unwrap();
    for m in machines() {
        let model = pump(1.4);
        cylinder(m.as_ref(), 12.0, 1).with_chamber(m.as_ref(), |chamber| {
            let gas = model.prepare(*chamber, 300.0).unwrap();
            let mut block = StateBlock::for_topology(m.topology());
            let exact: Vec<CrankState> = grid
                .iter()
                .map(|c| CrankState::new(c.angle, c.speed, 0.0, c.time))
                .collect();
            for (cranks, exact_bits) in [(&exact, true), (&grid, false)] {
                for chunk in cranks.chunks(LANES) {
                    block.fill(m.as_ref(), chunk);
                    let n = chunk.len();
                    let (mut p, mut f) = ([0.0; LANES], [0.0; LANES]);
                    let position = &block.pistons[0].position[..n];
                    assert!(gas.lanes(&block.crank.angle[..n], position, &mut p, &mut f));
                    for (i, c) in chunk.iter().enumerate() {
                        let (step, force) = gas.at(c.angle);
                        let (p, f) = (p[i], f[i]);
                        if exact_bits || step == 101_325.0 {
                            assert_eq!(
                                (p.to_bits(), f.to_bits()),
                                (step.to_bits(), force.to_bits())
                            );
                        } else {
                            assert!((p - step).abs() <= 1e-12 * step, "{} {p} {step}", m.name());
                            assert!((f - force).abs() <= 1e-12 * force, "{}", m.name());
                        }
                    }
                }
            }
        });
    }
}

/// Where the gas at a step is not a function of the step's volume alone, the block path
/// declines and writes nothing: the engine's combustion pressure needs the volume δ before
/// (A6.1.1.13), and a phased opposed-piston chamber the second piston's position at θ + φ.
#[test]
fn the_lanes_decline_where_they_do_not_fit() {
    let m = &machines()[0];
    let angles = [1.0, 2.0, 3.0];
    let positions = angles.map(|t| m.piston_position(t).0);
    let (mut p, mut f) = ([-1.0; 3], [-1.0; 3]);
    let engine = KarhulaEngine::new(pump(1.35).gas, 12e6, 9.5_f64.to_radians()).unwrap();
    cylinder(m.as_ref(), 12.0, 1).with_chamber(m.as_ref(), |chamber| {
        let gas = engine.prepare(*chamber, 300.0).unwrap();
        assert!(!gas.lanes(&angles, &positions, &mut p, &mut f));
    });
    let model = pump(1.4);
    cylinder(m.as_ref(), 12.0, 2).with_phased_chamber(m.as_ref(), 0.2, |chamber| {
        assert!(chamber.piston.is_none());
        let gas = model.prepare(*chamber, 300.0).unwrap();
        assert!(!gas.lanes(&angles, &positions, &mut p, &mut f));
    });
    assert_eq!((p, f), ([-1.0; 3], [-1.0; 3]));
}
