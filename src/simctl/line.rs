//! The command-line grammar both units read, written from robots.md alone
//! (it shares nothing with the driver's encoder, so a misreading of the
//! manuals is not made twice).
//!
//! A line is a two-letter command in capitals, then optionally spaces, then
//! comma-separated arguments (spaces around an argument are allowed). The
//! unit is strict about everything else: lower-case commands, empty
//! arguments, signs or points in integer arguments and numbers beyond their
//! field are command errors.

/// One received line split into its command and arguments.
#[derive(Debug, PartialEq)]
pub struct Line<'a> {
    /// The two capital letters.
    pub code: &'a str,
    /// The arguments, trimmed (an empty one stays, and is refused later).
    pub args: Vec<&'a str>,
}

/// Splits a line (without its CR); `None` when it does not start with two
/// capital letters.
pub fn split(line: &str) -> Option<Line<'_>> {
    let line = line.trim_matches([' ', '\t']);
    let code = line.get(..2)?;
    if !code.bytes().all(|b| b.is_ascii_uppercase()) {
        return None;
    }
    let rest = line[2..].trim_start_matches([' ', '\t']);
    let args = if rest.is_empty() {
        Vec::new()
    } else {
        rest.split(',')
            .map(|a| a.trim_matches([' ', '\t']))
            .collect()
    };
    Some(Line { code, args })
}

/// Largest magnitude of a decimal argument: four integer digits (mm or
/// degrees); a longer number is a command error (adair's choice; the
/// manuals give no field width).
pub const DECIMAL_MAX: f64 = 9999.9;

/// A decimal argument (`+12.3`, `-5`, `.5`, `7.`), rounded to the units'
/// least input increment of 0.1 (mm or degrees). The driver sends one
/// decimal; a unit reads more digits and keeps the tenth, as here.
pub fn decimal(s: &str) -> Option<f64> {
    let body = s.strip_prefix(['+', '-']).unwrap_or(s);
    let (int, frac) = match body.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (body, None),
    };
    let digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if !digits(int) || !frac.is_none_or(digits) {
        return None;
    }
    if int.is_empty() && frac.is_none_or(str::is_empty) {
        return None;
    }
    let v: f64 = s.parse().ok()?;
    let tenths = (v * 10.0).round() / 10.0;
    // `-0.04` is 0.0 after rounding, not -0.0.
    let tenths = if tenths == 0.0 { 0.0 } else { tenths };
    (tenths.abs() <= DECIMAL_MAX).then_some(tenths)
}

/// An integer argument: an optional sign and at most six digits, within
/// `min..=max`.
pub fn integer(s: &str, min: i64, max: i64) -> Option<i64> {
    let body = s.strip_prefix(['+', '-']).unwrap_or(s);
    if body.is_empty() || body.len() > 6 || !body.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let v: i64 = s.parse().ok()?;
    (min..=max).contains(&v).then_some(v)
}

/// All of `args` as decimals, if there are exactly `n` and each parses.
pub fn decimals<const N: usize>(args: &[&str]) -> Option<[f64; N]> {
    if args.len() != N {
        return None;
    }
    let mut out = [0.0; N];
    for (o, a) in out.iter_mut().zip(args) {
        *o = decimal(a)?;
    }
    Some(out)
}

/// A 16-bit port value: decimal -32768..32767 (two's complement) or `&H`
/// with one to four hex digits.
pub fn port_value(s: &str) -> Option<u16> {
    if let Some(hex) = s.strip_prefix("&H") {
        if hex.is_empty() || hex.len() > 4 {
            return None;
        }
        return u16::from_str_radix(hex, 16).ok();
    }
    integer(s, -32768, 32767).map(|v| v as i16 as u16)
}

/// A number formatted as the RV-M1 answers it: explicit sign, one decimal,
/// never `-0.0`.
pub fn signed_tenth(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r:+.1}")
}
