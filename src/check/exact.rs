//! Exact values of static real expressions (Ada's universal arithmetic,
//! RM 4.9): named numbers and static real expressions are rationals, rounded
//! to the machine's `Float` only where a value leaves the static world.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

pub type Exact = BigRational;

/// The rational a real literal denotes. The lexer keeps literals as `f64`;
/// the shortest decimal that reads back as the same `f64` is the literal as
/// written for every literal of up to 15 significant digits (`0.1` is 1/10).
pub fn of_f64(v: f64) -> Option<Exact> {
    if !v.is_finite() {
        return None;
    }
    let text = format!("{v}");
    let (neg, text) = match text.strip_prefix('-') {
        Some(t) => (true, t),
        None => (false, text.as_str()),
    };
    let (int, frac) = text.split_once('.').unwrap_or((text, ""));
    let digits: BigInt = format!("{int}{frac}").parse().ok()?;
    let den = BigInt::from(10u32).pow(frac.len() as u32);
    let r = BigRational::new(digits, den);
    Some(if neg { -r } else { r })
}

/// The exact value of a machine number: the rational an `f64` is (its
/// binary value, not the shortest decimal that reads back as it).
pub fn of_double(v: f64) -> Option<Exact> {
    BigRational::from_float(v)
}

/// RM 4.9(38): the machine number of a floating point type nearest to `r`
/// (every floating point type of adair is a 64-bit double).
pub fn to_machine(r: &Exact) -> Option<Exact> {
    of_double(to_f64(r))
}

/// RM 4.9(38) for a fixed point type of whole nanoseconds (Duration): `r`
/// truncated toward zero to a multiple of 1 ns, as GNAT does.
pub fn to_whole_ns(r: &Exact) -> Exact {
    let ns = BigRational::from_integer(BigInt::from(1_000_000_000u32));
    (r * &ns).trunc() / ns
}

pub fn of_int(v: i128) -> Exact {
    BigRational::from_integer(BigInt::from(v))
}

/// Rounded to the nearest `f64`.
pub fn to_f64(r: &Exact) -> f64 {
    r.to_f64().unwrap_or(f64::NAN)
}

/// `r ** n` for an integer exponent (a negative one divides); `None` for
/// `0.0 ** -n` and absurd exponents.
pub fn pow(r: &Exact, n: i128) -> Option<Exact> {
    if n.unsigned_abs() > 4096 {
        return None;
    }
    if n < 0 && r.is_zero() {
        return None;
    }
    let mut out = BigRational::one();
    for _ in 0..n.unsigned_abs() {
        out *= r;
    }
    Some(if n < 0 { out.recip() } else { out })
}

/// Whether the exact value is so large that rounding it leaves `f64`.
pub fn overflows(r: &Exact) -> bool {
    !to_f64(&r.abs()).is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_are_their_decimal_value() {
        let a = of_f64(0.1).unwrap();
        let b = of_f64(0.2).unwrap();
        let c = of_f64(0.3).unwrap();
        assert_eq!(a + b, c);
        assert_eq!(
            of_f64(-2.5).unwrap(),
            BigRational::new((-5).into(), 2.into())
        );
        assert_eq!(of_f64(1.0e20).unwrap(), of_int(100_000_000_000_000_000_000));
        assert!(of_f64(f64::NAN).is_none());
    }

    #[test]
    fn a_third_times_three_is_one() {
        let third = of_int(1) / of_int(3);
        assert_eq!(third.clone() * of_int(3), of_int(1));
        assert_eq!(to_f64(&third), 1.0 / 3.0);
        assert_eq!(pow(&of_int(2), -2).unwrap(), of_int(1) / of_int(4));
        assert!(pow(&of_int(0), -1).is_none());
    }

    #[test]
    fn machine_numbers_are_rounded_to_double() {
        let third = of_int(1) / of_int(3);
        let m = to_machine(&third).unwrap();
        assert_ne!(m.clone() * of_int(3), of_int(1));
        assert_eq!(to_f64(&m), 1.0 / 3.0);
        // 0.1 as a double is not 1/10.
        assert_ne!(of_double(0.1).unwrap(), of_f64(0.1).unwrap());
        assert_eq!(to_machine(&of_int(3)).unwrap(), of_int(3));
    }

    #[test]
    fn whole_nanoseconds_truncate_toward_zero() {
        let ns = |n: i128| of_int(n) / of_int(1_000_000_000);
        assert_eq!(to_whole_ns(&(of_int(2) / of_int(3))), ns(666_666_666));
        assert_eq!(to_whole_ns(&(of_int(-2) / of_int(3))), ns(-666_666_666));
        assert_eq!(to_whole_ns(&(of_int(3) / of_int(2_000_000_000))), ns(1));
        assert_eq!(to_whole_ns(&of_int(5)), of_int(5));
    }
}
