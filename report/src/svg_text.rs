//! The text of the charts written without the formatting machinery, byte for byte as the
//! `format!`s it replaces wrote it (issue 37: the charts' numbers were most of a run's report):
//! coordinates with one decimal ([`c`], [`points_text`]), tick labels' fixed decimals
//! ([`fixed_decimals`]), XML escapes ([`push_esc`]), and the pieces of a line ([`put!`]).

/// Fixed formatting of a coordinate (one decimal: integer arithmetic, fast, and the same on
/// every machine; [`coord_digits`]).
#[inline]
pub(super) fn c(v: f64) -> Coord {
    Coord(v)
}

/// A coordinate written with one decimal ([`coord_digits`]) where it is formatted (`{}`): no
/// string of its own, no integer formatting (most of a report's formatting: issue 37).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Coord(f64);

impl std::fmt::Display for Coord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut digits = [0; 24];
        let start = coord_digits(self.0, &mut digits);
        // Only ASCII digits, the point and the sign were written.
        f.pad(std::str::from_utf8(&digits[start..]).unwrap_or("0"))
    }
}

/// A polyline's `points`: each (x, y) of `xy` as `x,y` ([`c`]), separated by
/// spaces; `n` points expected. Written as bytes and made a string once (issue 37).
pub(super) fn points_text(xy: impl Iterator<Item = (f64, f64)>, n: usize) -> String {
    let mut text = Vec::with_capacity(n * 14);
    let mut digits = [0; 24];
    for (x, y) in xy {
        let start = coord_digits(x, &mut digits);
        text.extend_from_slice(&digits[start..]);
        text.push(b',');
        let start = coord_digits(y, &mut digits);
        text.extend_from_slice(&digits[start..]);
        text.push(b' ');
    }
    text.pop();
    // Only ASCII digits, points, signs, commas and spaces were written.
    String::from_utf8(text).unwrap_or_default()
}

/// `v` with one decimal, written at the end of `digits` from the returned index: the tenths
/// rounded to an integer and its digits with the point before the last; "0" beyond ±1e14 or
/// not finite. By hand rather than `{}` of the integers (the same digits: tested).
fn coord_digits(v: f64, digits: &mut [u8; 24]) -> usize {
    let t = (v * 10.0).round();
    let mut k = digits.len() - 1;
    if !t.is_finite() || t.abs() > 1e15 {
        digits[k] = b'0';
        return k;
    }
    // At most 1e15 tenths: a sign, 15 digits, the point and the tenth.
    let t = t as i64;
    let tenths = t.unsigned_abs();
    digits[k] = b'0' + (tenths % 10) as u8;
    k -= 1;
    digits[k] = b'.';
    let mut n = tenths / 10;
    loop {
        k -= 1;
        digits[k] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    if t < 0 {
        k -= 1;
        digits[k] = b'-';
    }
    k
}

/// A piece of a chart's text that [`put!`] appends: text as it is, a coordinate ([`c`]).
pub(crate) trait Piece {
    fn put(&self, o: &mut String);
}

impl Piece for &str {
    #[inline]
    fn put(&self, o: &mut String) {
        o.push_str(self);
    }
}

impl Piece for String {
    #[inline]
    fn put(&self, o: &mut String) {
        o.push_str(self);
    }
}

impl Piece for Coord {
    #[inline]
    fn put(&self, o: &mut String) {
        let mut digits = [0; 24];
        let start = coord_digits(self.0, &mut digits);
        o.extend(digits[start..].iter().map(|&b| char::from(b)));
    }
}

/// Appends each piece ([`Piece`]) to the string, as `write!` of them one after another
/// would, without the formatting machinery: the lines a chart repeats, its grid and legend
/// (issue 37).
macro_rules! put {
    ($o:expr; $($piece:expr),+ $(,)?) => {{
        let o: &mut String = $o;
        $( $crate::svg_text::Piece::put(&$piece, o); )+
    }};
}
pub(crate) use put;

/// Escapes text for XML.
pub fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    push_esc(&mut o, s);
    o
}

/// Appends `s` escaped for XML: `&`, `<`, `>` and `"` as entities, the runs between them
/// whole (they are ASCII, so every other byte, of any character, is copied as it is).
pub fn push_esc(o: &mut String, s: &str) {
    let mut start = 0;
    for (k, b) in s.bytes().enumerate() {
        let entity = match b {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            _ => continue,
        };
        o.push_str(&s[start..k]);
        o.push_str(entity);
        start = k + 1;
    }
    o.push_str(&s[start..]);
}

/// `format!("{v:.decimals$}")` (decimals ≤ 8), by integer arithmetic where `v` is a whole
/// number of the last decimal's units, as a chart's ticks mostly are (issue 37): where
/// `v·10^decimals` rounds to an integer below 2^50 in floating point, the exact product is
/// within 1/8 of it, so the exact decimal rounding that `{:.N}` does gives that integer.
pub(super) fn fixed_decimals(v: f64, decimals: usize) -> String {
    const POWERS: [f64; 9] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8];
    let scaled = POWERS.get(decimals).map_or(f64::NAN, |p| v * p);
    if !(scaled.abs() < (1u64 << 50) as f64 && scaled == scaled.trunc()) {
        return format!("{v:.decimals$}");
    }
    let mut digits = scaled.abs() as u64;
    // The digits from the last, at least one before the point.
    let mut text = Vec::with_capacity(24);
    for k in 0.. {
        if k == decimals && decimals > 0 {
            text.push(b'.');
        }
        text.push(b'0' + (digits % 10) as u8);
        digits /= 10;
        if digits == 0 && k >= decimals {
            break;
        }
    }
    if v.is_sign_negative() {
        text.push(b'-');
    }
    text.reverse();
    // Only ASCII digits, the point and the sign were written.
    String::from_utf8(text).unwrap_or_else(|_| format!("{v:.decimals$}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_are_written_as_the_formatting_machinery_wrote_them() {
        // The format coordinates had, `{}.{}` of the tenths' quotient and remainder.
        let by_format = |v: f64| {
            let t = (v * 10.0).round();
            if !t.is_finite() || t.abs() > 1e15 {
                return "0".to_string();
            }
            let t = t as i64;
            let sign = if t < 0 { "-" } else { "" };
            format!("{sign}{}.{}", t.abs() / 10, t.abs() % 10)
        };
        let mut values = vec![
            0.0,
            -0.0,
            0.04,
            -0.04,
            0.05,
            -0.05,
            0.95,
            -0.95,
            9.95,
            99.95,
            1e14,
            -1e14,
            99_999_999_999_999.9,
            1e15,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN_POSITIVE,
            u64::MAX as f64,
        ];
        // A SplitMix64 stream over many magnitudes, signs and fractions.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        for _ in 0..200_000 {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^= z >> 31;
            let unit = (z >> 11) as f64 / (1u64 << 53) as f64;
            let scale = 10f64.powi((z % 18) as i32 - 2);
            let sign = if z & (1 << 7) == 0 { 1.0 } else { -1.0 };
            values.push(sign * unit * scale);
        }
        for k in 0..=20_000 {
            values.push(k as f64 * 0.05 - 500.0);
        }
        for v in values {
            assert_eq!(c(v).to_string(), by_format(v), "{v:e}");
            assert_eq!(format!("[{:>12}]", c(v)), format!("[{:>12}]", by_format(v)));
        }
    }

    #[test]
    fn fixed_decimals_are_the_formatting_machinery_s() {
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.125,
            1e-9,
            -1e-9,
            0.1,
            0.3,
            1e15,
            -1e15,
            (1u64 << 50) as f64,
            (1u64 << 50) as f64 - 1.0,
            1e300,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        // Ticks as the charts make them, lo + k·step over nice ranges of many magnitudes.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        for _ in 0..20_000 {
            let z = next();
            let scale = 10f64.powi((z % 24) as i32 - 12);
            let a = ((z >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale;
            let b = a + ((next() >> 11) as f64 / (1u64 << 53) as f64) * scale;
            // A 1-2-2.5-5 step of about a fifth of the range, as the charts' (`nice_range`).
            let mag = 10f64.powf(((b - a) / 5.0).log10().floor());
            let step = [1.0, 2.0, 2.5, 5.0][(z % 4) as usize] * mag;
            let lo = (a / step).floor() * step;
            let ticks = ((b - lo) / step).ceil() as usize;
            for k in 0..=ticks {
                values.push(lo + k as f64 * step);
                values.push((lo + k as f64 * step) / 1e3);
            }
            values.push(a);
        }
        // Both ways are taken: by integers, and by `format!`.
        let whole = |v: f64, d: i32| (v * 10f64.powi(d)).fract() == 0.0;
        let by_integers = values.iter().filter(|v| whole(**v, 2)).count();
        assert!(by_integers > 10_000 && by_integers + 10_000 < values.len());
        for v in values {
            for decimals in 0..=8 {
                assert_eq!(
                    fixed_decimals(v, decimals),
                    format!("{v:.decimals$}"),
                    "{v:e} to {decimals} decimals"
                );
            }
        }
    }

    #[test]
    fn escaping_is_by_character() {
        // The escape as it was, a character at a time.
        let by_chars = |s: &str| {
            let mut o = String::new();
            for ch in s.chars() {
                match ch {
                    '&' => o.push_str("&amp;"),
                    '<' => o.push_str("&lt;"),
                    '>' => o.push_str("&gt;"),
                    '"' => o.push_str("&quot;"),
                    _ => o.push(ch),
                }
            }
            o
        };
        for s in [
            "",
            "plain",
            "&",
            "<>\"&",
            "a < b & c > \"d\"",
            "Δ `x` → 10⁵ Pa & ° <µ>",
            "&&&",
            "é&é",
            "end&",
        ] {
            assert_eq!(esc(s), by_chars(s), "{s}");
        }
    }

    #[test]
    fn points_are_coordinates_pairs_by_spaces() {
        let xy = [(1.0, -2.25), (0.04, 1e20), (f64::NAN, -0.04), (123.45, 6.0)];
        let mut by_push = String::new();
        for (x, y) in xy {
            by_push.push_str(&format!("{},{} ", c(x), c(y)));
        }
        by_push.pop();
        assert_eq!(points_text(xy.into_iter(), 4), by_push);
        assert_eq!(by_push, "1.0,-2.3 0.0,0 0,0.0 123.5,6.0");
        assert_eq!(points_text(std::iter::empty(), 0), "");
    }
}
