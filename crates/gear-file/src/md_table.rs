//! The one shape of `report.md`'s tables, for the geometry, AGMA, ISO and measurement sections
//! alike: a quantity table (`| quantity | value | unit |`) and a per-member table
//! (`| … | pinion | gear | unit |`), each number by [`num`], so that a value that rounds to
//! zero prints "0.0000", never "-0.0000".

use cardan_gears::geometry::checks::fixed;
use std::fmt::Write as _;

/// Text for a Markdown table cell: `|` escaped.
pub(crate) fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

/// `x` with `decimals` decimals, without the sign of a value that rounds to zero.
pub(crate) fn num(x: f64, decimals: usize) -> String {
    fixed(x, decimals)
}

/// Numbers by [`num`] joined by " / " (one row's related values, e.g. `K_Hβ / K_Fβ`).
pub(crate) fn nums(xs: &[f64], decimals: usize) -> String {
    xs.iter()
        .map(|&x| num(x, decimals))
        .collect::<Vec<_>>()
        .join(" / ")
}

/// Numbers by [`num`] as the cells of one row, joined by " | " (a row of more than two
/// numbers, e.g. AGMA's and ISO's safety factors side by side).
pub(crate) fn cells(xs: &[f64], decimals: usize) -> String {
    xs.iter()
        .map(|&x| num(x, decimals))
        .collect::<Vec<_>>()
        .join(" | ")
}

/// A Markdown table being written to `o`.
pub(crate) struct Table<'a> {
    o: &'a mut String,
}

impl<'a> Table<'a> {
    /// A quantity table: `| quantity | value | unit |`.
    pub(crate) fn quantities(o: &'a mut String) -> Self {
        let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
        Self { o }
    }

    /// A per-member table headed `first` (e.g. "per member"): `| first | pinion | gear | unit |`.
    pub(crate) fn members(o: &'a mut String, first: &str) -> Self {
        let _ = writeln!(
            o,
            "| {} | pinion | gear | unit |\n|---|---:|---:|---|",
            cell(first)
        );
        Self { o }
    }

    /// A row of a quantity table with its value already written.
    pub(crate) fn row(&mut self, quantity: &str, value: &str, unit: &str) {
        let _ = writeln!(self.o, "| {} | {value} | {unit} |", cell(quantity));
    }

    /// A row of a quantity table: `x / scale` to `decimals` decimals.
    pub(crate) fn value(
        &mut self,
        quantity: &str,
        x: f64,
        scale: f64,
        decimals: usize,
        unit: &str,
    ) {
        self.row(quantity, &num(x / scale, decimals), unit);
    }

    /// A row of a per-member table with its two cells already written.
    pub(crate) fn pair_text(&mut self, quantity: &str, cells: [&str; 2], unit: &str) {
        let _ = writeln!(
            self.o,
            "| {} | {} | {} | {unit} |",
            cell(quantity),
            cells[0],
            cells[1]
        );
    }

    /// A row of a per-member table: `[pinion, gear] / scale` to `decimals` decimals.
    pub(crate) fn pair(
        &mut self,
        quantity: &str,
        xs: [f64; 2],
        scale: f64,
        decimals: usize,
        unit: &str,
    ) {
        let cells = xs.map(|x| num(x / scale, decimals));
        self.pair_text(quantity, [&cells[0], &cells[1]], unit);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_rounding_to_zero_has_no_sign() {
        // "-0.0000" in a report was a cosmetic defect (issue 39 item 5).
        assert_eq!(num(-1e-9, 4), "0.0000");
        assert_eq!(num(-0.00004, 4), "0.0000");
        assert_eq!(num(-0.00006, 4), "-0.0001");
        assert_eq!(nums(&[-1e-12, 0.5], 3), "0.000 / 0.500");
        let mut o = String::new();
        Table::members(&mut o, "per member").pair("profile shift", [-1e-9, -0.25], 1.0, 4, "-");
        assert!(
            o.ends_with("| profile shift | 0.0000 | -0.2500 | - |\n"),
            "{o}"
        );
    }
}
