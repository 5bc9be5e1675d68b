//! The controllers' command language (robots.md), without I/O: the lines the
//! serial driver sends and the replies it parses, shared with the virtual
//! controller (`adair sim-controller`) so both read the same grammar.

use crate::kinematics::JOINTS;

/// Which drive unit is on the line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// RV-M1's D/U-M1: answers `WH`, `ER`, `DR`; joint moves as `MJ` degrees.
    RvM1,
    /// RM-501's Movemaster II unit: never answers; joint moves as `MI` counts.
    Rm501,
}

impl Unit {
    /// The unit a robot description names (by its `name`).
    pub fn of_robot(name: &str) -> Unit {
        if name.eq_ignore_ascii_case("RM-501") {
            Unit::Rm501
        } else {
            Unit::RvM1
        }
    }

    /// Port settings: (data bits, stop bits); both units use even parity
    /// and RTS/CTS.
    pub fn framing(self) -> (u8, u8) {
        match self {
            Unit::RvM1 => (7, 2),
            Unit::Rm501 => (8, 1),
        }
    }

    /// Every command the driver may send to this unit: robots.md's command
    /// set. The RM-501 takes nothing else (`GP`, `TL`, `WH`, `MJ` would put
    /// it in error mode, and it never says so); its `ER` is only the probe
    /// at the start ([`PROBE`]), sent before anything else and cleared by
    /// `RS`.
    pub fn commands(self) -> &'static [&'static str] {
        match self {
            Unit::RvM1 => &[
                "NT", "OG", "MJ", "MP", "PD", "MO", "MS", "MC", "DW", "HE", "SP", "TL", "GO", "GC",
                "GP", "TI", "WH", "ER", "RS", "ID", "DR", "OD",
            ],
            Unit::Rm501 => &["MI", "PS", "MO", "NT", "HO", "OG", "SP", "GO", "GC", "RS"],
        }
    }

    /// Whether `line`'s command is in this unit's command set.
    pub fn knows(self, line: &str) -> bool {
        let (code, _) = split(line);
        self.commands().contains(&code.as_str())
    }

    /// Counts per controller degree of each joint (`MI`).
    pub fn counts_per_deg(self) -> [f64; JOINTS] {
        [40.0, 40.0, 40.0, 1.0 / 0.075, 1.0 / 0.075]
    }
}

/// The first line sent to any unit: an RV-M1 answers it, an RM-501 takes it
/// as a command error (cleared by the `RS` that follows).
pub const PROBE: &str = "ER";

/// The speed levels `SP 0..9`: the fraction of each joint's maximum speed
/// the unit moves at, in adair's model of the units (level `L` runs at
/// `max(L, 1) / 9`; the manuals give no table, docs/serial.md says so).
pub fn level_fraction(level: u8) -> f64 {
    f64::from(level.clamp(1, 9)) / 9.0
}

/// The level of a velocity in percent (`SetVelocity`): `velocity / 100 x 9`,
/// rounded.
pub fn level_of_percent(percent: f64) -> u8 {
    (percent / 100.0 * 9.0).round().clamp(0.0, 9.0) as u8
}

/// One decimal, always with `.`, and an explicit sign as the unit writes
/// (`+51.0`, `-0.3`); `-0.0` is written `+0.0`.
pub fn num(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r:+.1}")
}

/// `MJ w,s,e,p,r`: a relative joint move in controller degrees.
pub fn mj(delta: &[f64; JOINTS]) -> String {
    let parts: Vec<String> = delta.iter().map(|d| num(*d)).collect();
    format!("MJ {}", parts.join(","))
}

/// `MI a1,..,a5,0`: a relative joint move in counts.
pub fn mi(counts: &[i64; JOINTS]) -> String {
    let parts: Vec<String> = counts.iter().map(|c| format!("{c:+}")).collect();
    format!("MI {},+0", parts.join(","))
}

/// Splits a command line into its two-letter code and its arguments.
pub fn split(line: &str) -> (String, Vec<&str>) {
    let line = line.trim();
    let code_len = line
        .char_indices()
        .take_while(|(_, c)| c.is_ascii_alphabetic())
        .count()
        .min(2);
    let (code, rest) = line.split_at(code_len);
    let args = rest
        .trim()
        .split(',')
        .map(str::trim)
        .filter(|a| !a.is_empty())
        .collect();
    (code.to_ascii_uppercase(), args)
}

/// Parses decimal arguments (`+51.0`); `None` for anything else.
pub fn numbers(args: &[&str]) -> Option<Vec<f64>> {
    args.iter()
        .map(|a| {
            let ok = !a.is_empty()
                && a.chars()
                    .all(|c| c.is_ascii_digit() || c == '.' || c == '+' || c == '-');
            if ok { a.parse::<f64>().ok() } else { None }
        })
        .collect()
}

/// A `WH` reply: five numbers `x,y,z,p,r`.
pub fn parse_wh(reply: &str) -> Option<[f64; 5]> {
    let parts: Vec<&str> = reply.trim().split(',').map(str::trim).collect();
    if parts.len() != 5 {
        return None;
    }
    let v = numbers(&parts)?;
    let mut out = [0.0; 5];
    out.copy_from_slice(&v);
    out.iter().all(|x| x.is_finite()).then_some(out)
}

/// An `ER` reply: 0 none, 1 error mode I, 2 error mode II.
pub fn parse_er(reply: &str) -> Option<u8> {
    match reply.trim() {
        "0" => Some(0),
        "1" => Some(1),
        "2" => Some(2),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_one_decimal_a_sign_and_a_point() {
        assert_eq!(num(51.04), "+51.0");
        assert_eq!(num(-88.26), "-88.3");
        assert_eq!(num(-0.01), "+0.0");
        assert_eq!(
            mj(&[1.0, -2.5, 0.0, 0.04, 10.0]),
            "MJ +1.0,-2.5,+0.0,+0.0,+10.0"
        );
        assert_eq!(mi(&[40, -80, 0, 13, 0]), "MI +40,-80,+0,+13,+0,+0");
    }

    #[test]
    fn replies_parse_or_are_refused() {
        assert_eq!(
            parse_wh("+51.0,-88.3,+737.1,+10.9,+179.9"),
            Some([51.0, -88.3, 737.1, 10.9, 179.9])
        );
        assert_eq!(parse_wh("+51.0,-88.3,+737.1,+10.9"), None);
        assert_eq!(parse_wh("+51.0,-88.3,+737.1,+10.9,x"), None);
        assert_eq!(parse_er("2"), Some(2));
        assert_eq!(parse_er("3"), None);
        assert_eq!(parse_er("0\r"), Some(0));
        assert_eq!(split("MJ +1.0, -2.0"), ("MJ".into(), vec!["+1.0", "-2.0"]));
        assert_eq!(split("SP 5,H"), ("SP".into(), vec!["5", "H"]));
    }
}
