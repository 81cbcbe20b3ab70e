//! Numbers as a user types them, exact to the bit (issue 51 item 2's `y` line; the explorer's
//! inputs): the `y` line and a session must run what the screen shows, so each number is an
//! `f64` the command line reads back to the same bits; and they are read by people, so each
//! is the shortest decimal that does, never float noise (`--pressure 55158.058345346886` for
//! 8 psi, `--v0 3.3000000000000003` after three steps of 0.1).
//!
//! Two sides. Where a value is made — typed in a screen unit (g, mm, kPa), stepped by a
//! decimal step — it is made the `f64` nearest the decimal meant ([`shifted`], [`tidy`]), so
//! its shortest text is that decimal. Where a line is written, a number is the shortest text
//! the command line reads back to what it held ([`shortest_accepted`]; a pressure in whichever
//! unit `--pressure` takes is shortest, [`pressure_text`]: `8psi`).

use crate::conditions::pressure::{self, PSI};
use crate::text::number;

/// The f64 nearest `x` rounded to `digits` (1 … 17) significant decimal digits.
pub fn round_sig(x: f64, digits: usize) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    format!("{:.*e}", digits.clamp(1, 17) - 1, x)
        .parse()
        .unwrap_or(x)
}

/// A stepped value without the float noise of its steps: the f64 nearest `x` to 12
/// significant digits (3.3000000000000003 → 3.3, 0.11000000000000001 → 0.11), so that a
/// value reached by steps is the one its decimal names and a line writes it as typed.
pub fn tidy(x: f64) -> f64 {
    round_sig(x, 12)
}

/// The shortest rounding of `x` (1, 2, … significant digits) that `same` accepts — the one
/// whose effect is `x`'s to the bit; `x` itself when none shorter is. Every rounding to 17
/// digits reads back to `x`, so `x` is the answer at worst.
pub fn shortest_accepted(x: f64, same: impl Fn(f64) -> bool) -> f64 {
    (1..17)
        .map(|d| round_sig(x, d))
        .find(|&y| y == x || same(y))
        .unwrap_or(x)
}

/// `x × 10^pow` as the decimal shifted: the f64 nearest x's shortest decimal with its point
/// moved (45.93 g → 0.04593 kg exactly as typed; 45.93 / 1000 can land an ulp beside it).
pub fn shifted(x: f64, pow: i32) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x * 10f64.powi(pow);
    }
    let s = format!("{x:e}");
    let Some((mantissa, exp)) = s.split_once('e') else {
        return x * 10f64.powi(pow);
    };
    let exp: i32 = exp.parse().unwrap_or(0);
    format!("{mantissa}e{}", exp + pow)
        .parse()
        .unwrap_or(x * 10f64.powi(pow))
}

/// A value typed in a screen unit `k` times the SI one (g: 1e3, mm: 1e3, kPa: 1e-3), in SI:
/// [`shifted`] for a power of ten, else divided.
pub fn from_screen(typed: f64, k: f64) -> f64 {
    let pow = k.log10().round() as i32;
    if 10f64.powi(pow) == k {
        shifted(typed, -pow)
    } else {
        typed / k
    }
}

/// The units a pressure is written in, as `--pressure` reads them (src/conditions/pressure.rs),
/// pascals first: the one chosen where two are as short.
const PRESSURE_UNITS: [(&str, f64); 4] = [("", 1.0), ("kPa", 1e3), ("bar", 1e5), ("psi", PSI)];

/// The gauge pressure `p` (Pa) as the shortest text `--pressure` reads back to exactly `p`:
/// "80000" for 0.8 bar, "8psi" for 8 psi (55 158.058 345 346 886 Pa), "55.5kPa".
pub fn pressure_text(p: f64) -> String {
    let reads = |text: &str| pressure::parse("pressure", text).ok() == Some(p);
    let mut best = number(p);
    for (unit, scale) in PRESSURE_UNITS {
        let x = p / scale;
        for d in 1..=17 {
            let text = format!("{}{unit}", number(round_sig(x, d)));
            if text.len() >= best.len() {
                break;
            }
            if reads(&text) {
                best = text;
                break;
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_typed_value_in_a_screen_unit_is_the_decimal_typed() {
        for (typed, k, si) in [
            (45.93, 1e3, "0.04593"),
            (57.0, 1e3, "0.057"),
            (33.5, 1e3, "0.0335"),
            (55.158, 1e-3, "55158"),
            (2.5, 1.0, "2.5"),
        ] {
            assert_eq!(number(from_screen(typed, k)), si);
        }
        // 0.1 steps to 3.3 are 3.3, not 3.3000000000000003
        assert_eq!(number(3.2 + 0.1), "3.3000000000000003");
        assert_eq!(tidy(3.2 + 0.1), 3.3);
        assert_eq!(tidy(0.1 * 1.1), 0.11);
    }

    #[test]
    fn a_pressure_is_written_in_its_shortest_exact_unit() {
        let psi8 = pressure::parse("p", "8psi").unwrap();
        assert_eq!(number(psi8), "55158.058345346886");
        assert_eq!(pressure_text(psi8), "8psi");
        assert_eq!(pressure_text(80_000.0), "80000");
        assert_eq!(pressure_text(55_500.0), "55500");
        let odd = pressure::parse("p", "0.83bar").unwrap();
        assert_eq!(pressure::parse("p", &pressure_text(odd)).unwrap(), odd);
        // a pressure no unit writes shorter stays the shortest text of its pascals
        assert_eq!(pressure_text(55_158.1), "55158.1");
    }

    #[test]
    fn the_shortest_accepted_is_exact_or_the_value() {
        let x = 0.1 + 0.2;
        assert_eq!(shortest_accepted(x, |_| false), x);
        assert_eq!(shortest_accepted(x, |y| (y - x).abs() < 1e-9), 0.3);
    }
}
