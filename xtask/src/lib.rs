//! The parts of README.md that are made from the code's registries: the metric table, the CSV
//! column table and the mechanism list. `cargo xtask readme` writes them; a test fails when
//! README.md and the registries disagree.

use cardan_mechanism::{JointKind, MachineGeometry, MassInputs, OptionKind, Options, MECHANISMS};

/// (marker name, Markdown) of every generated section.
pub fn sections() -> Vec<(&'static str, String)> {
    vec![
        ("metrics", cardan_dynamics::metrics::markdown_table()),
        ("columns", columns_table()),
        ("mechanisms", mechanisms_table()),
    ]
}

fn columns_table() -> String {
    let mut t = String::from("| column | meaning |\n|---|---|\n");
    for (name, meaning) in cardan_runner::per_step::COLUMNS {
        t.push_str(&format!("| `{name}` | {meaning} |\n"));
    }
    t
}

fn mechanisms_table() -> String {
    // Any valid machine shows the topology: the Karhula thesis machine.
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let mut t = String::from(
        "| `mechanisms` name | what it is | bodies | joints | options |\n|---|---|---|---|---|\n",
    );
    for e in MECHANISMS {
        let m = (e.build)(&geometry, &MassInputs::default(), &Options::new())
            .expect("the thesis machine is valid for every mechanism");
        let top = m.topology();
        let bodies: Vec<String> = top.bodies.iter().map(|b| format!("`{}`", b.name)).collect();
        let joints: Vec<String> = top
            .joints
            .iter()
            .map(|j| {
                let kind = match j.kind {
                    JointKind::Revolute(_) => "pin",
                    JointKind::Prismatic => "slide",
                    JointKind::GearMesh { .. } => "gear mesh",
                };
                format!("`{}` ({kind})", j.name)
            })
            .collect();
        let options: Vec<String> = e
            .options
            .iter()
            .map(|o| {
                let kind = match o.kind {
                    OptionKind::Angle => "angle".to_string(),
                    OptionKind::Length => "length".to_string(),
                    OptionKind::Number => "number".to_string(),
                    OptionKind::Choice(w) => w.join(" / "),
                };
                format!("`{}` ({kind}): {}", o.name, o.meaning)
            })
            .collect();
        t.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            e.name,
            e.summary,
            bodies.join(", "),
            joints.join(", "),
            if options.is_empty() {
                "none".to_string()
            } else {
                options.join("; ")
            }
        ));
    }
    t
}

/// `readme` with every generated section replaced by the registries' current text; an error
/// names a missing marker.
pub fn regenerate(readme: &str) -> Result<String, String> {
    let mut text = readme.to_string();
    for (name, body) in sections() {
        let (begin, end) = (
            format!("<!-- generated:{name} -->\n"),
            format!("<!-- end:{name} -->"),
        );
        let start = text
            .find(&begin)
            .ok_or_else(|| format!("README.md has no {begin:?} marker"))?
            + begin.len();
        let stop = text[start..]
            .find(&end)
            .ok_or_else(|| format!("README.md has no {end:?} marker"))?
            + start;
        text.replace_range(start..stop, &body);
    }
    Ok(text)
}
