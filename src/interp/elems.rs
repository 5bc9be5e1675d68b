//! The components of an array value, stored compactly.
//!
//! An array keeps its components in the narrowest form that holds them
//! all: bytes when every one is a discrete value in `0 ..= 255` (a
//! `String`'s characters, Booleans, small enumerations), integers when
//! every one is a discrete value, reals when every one is a real, and
//! general [`Value`]s otherwise (composites, access values, a mix). Which
//! form an array has is a matter of storage only: every reader sees the
//! same values either way, and storing a component the form cannot hold
//! widens that array value first (once): bytes to integers, anything else
//! to general values.

use super::value::Value;

/// An array's components, in row-major order.
#[derive(Clone, Debug)]
pub enum Elems {
    /// General values.
    Vals(Vec<Value>),
    /// Discrete values in `0 ..= 255`, one byte each (up to 16 held in
    /// the array value itself).
    Bytes(ByteVec),
    /// Discrete values.
    Ints(Vec<i64>),
    /// Reals (`Float`, `Duration`, times).
    Reals(Vec<f64>),
}

/// The bytes of a byte array: a short one (a tag, a label, a number's
/// image) needs no allocation of its own.
pub type ByteVec = smallvec::SmallVec<[u8; 16]>;

impl Default for Elems {
    fn default() -> Self {
        Elems::Bytes(ByteVec::new())
    }
}

/// The byte a value is stored as in a byte array, if it is one.
#[inline(always)]
fn byte(v: &Value) -> Option<u8> {
    match v {
        Value::Int(i) => u8::try_from(*i).ok(),
        _ => None,
    }
}

impl Elems {
    /// Components from general values, in the narrowest form that holds
    /// them.
    pub fn from_vals(vals: Vec<Value>) -> Elems {
        if vals.iter().all(|v| byte(v).is_some()) {
            Elems::Bytes(vals.iter().map(|v| v.int() as u8).collect())
        } else if vals.iter().all(|v| matches!(v, Value::Int(_))) {
            Elems::Ints(vals.iter().map(Value::int).collect())
        } else if vals.iter().all(|v| matches!(v, Value::Real(_))) {
            Elems::Reals(vals.iter().map(Value::real).collect())
        } else {
            Elems::Vals(vals)
        }
    }

    /// `n` copies of `v`.
    pub fn repeat(v: Value, n: usize) -> Elems {
        match v {
            Value::Int(i) => match u8::try_from(i) {
                Ok(b) => Elems::Bytes(smallvec::smallvec![b; n]),
                Err(_) => Elems::Ints(vec![i; n]),
            },
            Value::Real(x) => Elems::Reals(vec![x; n]),
            v => Elems::Vals(vec![v; n]),
        }
    }

    /// An empty list with room for `n` components, in `like`'s form.
    pub fn with_capacity_like(like: &Elems, n: usize) -> Elems {
        match like {
            Elems::Bytes(_) => Elems::Bytes(ByteVec::with_capacity(n)),
            Elems::Ints(_) => Elems::Ints(Vec::with_capacity(n)),
            Elems::Reals(_) => Elems::Reals(Vec::with_capacity(n)),
            Elems::Vals(_) => Elems::Vals(Vec::with_capacity(n)),
        }
    }

    #[inline]
    pub fn len(&self) -> usize {
        match self {
            Elems::Vals(v) => v.len(),
            Elems::Bytes(b) => b.len(),
            Elems::Ints(v) => v.len(),
            Elems::Reals(v) => v.len(),
        }
    }

    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn capacity(&self) -> usize {
        match self {
            Elems::Vals(v) => v.capacity(),
            Elems::Bytes(b) => b.capacity(),
            Elems::Ints(v) => v.capacity(),
            Elems::Reals(v) => v.capacity(),
        }
    }

    /// Component `i` (which must exist).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Value {
        match self {
            Elems::Vals(v) => v[i].clone(),
            Elems::Bytes(b) => Value::Int(b[i] as i64),
            Elems::Ints(v) => Value::Int(v[i]),
            Elems::Reals(v) => Value::Real(v[i]),
        }
    }

    /// Component `i` as an integer, without building a value.
    #[inline(always)]
    pub fn int(&self, i: usize) -> i64 {
        match self {
            Elems::Vals(v) => v[i].int(),
            Elems::Bytes(b) => b[i] as i64,
            Elems::Ints(v) => v[i],
            Elems::Reals(v) => v[i] as i64,
        }
    }

    /// Component `i` as a real.
    #[inline(always)]
    pub fn real(&self, i: usize) -> f64 {
        match self {
            Elems::Vals(v) => v[i].real(),
            Elems::Bytes(b) => b[i] as f64,
            Elems::Ints(v) => v[i] as f64,
            Elems::Reals(v) => v[i],
        }
    }

    /// Component `i` as a general value, if it is stored as one (a
    /// composite component always is).
    #[inline(always)]
    pub fn val(&self, i: usize) -> Option<&Value> {
        match self {
            Elems::Vals(v) => Some(&v[i]),
            _ => None,
        }
    }

    /// The general values, a compact array turned into them first.
    #[inline]
    pub fn vals_mut(&mut self) -> &mut Vec<Value> {
        if !matches!(self, Elems::Vals(_)) {
            let vals = std::mem::take(self).into_vals();
            *self = Elems::Vals(vals);
        }
        match self {
            Elems::Vals(v) => v,
            _ => unreachable!("turned into values above"),
        }
    }

    /// Component `i` to change in place (a compact array becomes general
    /// values: for a composite component's parts, which compact arrays
    /// never have).
    #[inline]
    pub fn get_mut(&mut self, i: usize) -> &mut Value {
        &mut self.vals_mut()[i]
    }

    /// Makes the form hold `v` (widening it if it cannot).
    #[cold]
    fn widen_for(&mut self, v: &Value) {
        match (&*self, v) {
            (Elems::Bytes(b), Value::Int(_)) => {
                *self = Elems::Ints(b.iter().map(|&x| x as i64).collect());
            }
            _ => {
                self.vals_mut();
            }
        }
    }

    /// Sets component `i` (which must exist).
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Value) {
        match (&mut *self, v) {
            (Elems::Vals(vs), v) => super::value::overwrite(&mut vs[i], v),
            (Elems::Bytes(b), Value::Int(x)) if (0..=255).contains(&x) => b[i] = x as u8,
            (Elems::Ints(vs), Value::Int(x)) => vs[i] = x,
            (Elems::Reals(vs), Value::Real(x)) => vs[i] = x,
            (e, v) => {
                e.widen_for(&v);
                e.set(i, v);
            }
        }
    }

    /// Appends a component.
    pub fn push(&mut self, v: Value) {
        match (&mut *self, v) {
            (Elems::Vals(vs), v) => vs.push(v),
            (Elems::Bytes(b), Value::Int(x)) if (0..=255).contains(&x) => b.push(x as u8),
            (Elems::Ints(vs), Value::Int(x)) => vs.push(x),
            (Elems::Reals(vs), Value::Real(x)) => vs.push(x),
            (e, v) if e.is_empty() => {
                // An empty list takes the form of its first component.
                let n = e.capacity();
                let mut one = Elems::repeat(v, 1);
                one.reserve(n);
                *e = one;
            }
            (e, v) => {
                e.widen_for(&v);
                e.push(v);
            }
        }
    }

    /// Room for `n` more components.
    pub fn reserve(&mut self, n: usize) {
        match self {
            Elems::Vals(v) => v.reserve(n),
            Elems::Bytes(b) => b.reserve(n),
            Elems::Ints(v) => v.reserve(n),
            Elems::Reals(v) => v.reserve(n),
        }
    }

    /// Appends `other`'s components. An empty list takes `other`'s form,
    /// keeping its own capacity.
    pub fn extend_from(&mut self, other: &Elems) {
        match (&mut *self, other) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a.extend_from_slice(b),
            (Elems::Ints(a), Elems::Ints(b)) => a.extend_from_slice(b),
            (Elems::Reals(a), Elems::Reals(b)) => a.extend_from_slice(b),
            (Elems::Vals(a), Elems::Vals(b)) => a.extend(b.iter().cloned()),
            (_, b) if b.is_empty() => {}
            (a, b) if a.is_empty() => {
                let mut n = Elems::with_capacity_like(b, a.capacity().max(b.len()));
                n.extend_from(b);
                *a = n;
            }
            _ => {
                for v in other.iter() {
                    self.push(v);
                }
            }
        }
    }

    /// Components `range`, in the same form.
    pub fn slice(&self, range: std::ops::Range<usize>) -> Elems {
        match self {
            Elems::Vals(v) => Elems::Vals(v[range].to_vec()),
            Elems::Bytes(b) => Elems::Bytes(ByteVec::from_slice(&b[range])),
            Elems::Ints(v) => Elems::Ints(v[range].to_vec()),
            Elems::Reals(v) => Elems::Reals(v[range].to_vec()),
        }
    }

    /// Copies `src`'s components over those from `at` on.
    pub fn copy_from(&mut self, at: usize, src: &Elems) {
        match (&mut *self, src) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a[at..at + b.len()].copy_from_slice(b),
            (Elems::Ints(a), Elems::Ints(b)) => a[at..at + b.len()].copy_from_slice(b),
            (Elems::Reals(a), Elems::Reals(b)) => a[at..at + b.len()].copy_from_slice(b),
            (Elems::Vals(a), Elems::Vals(b)) => a[at..at + b.len()].clone_from_slice(b),
            _ => {
                for (k, v) in src.iter().enumerate() {
                    self.set(at + k, v);
                }
            }
        }
    }

    /// The components as values, in order.
    pub fn iter(&self) -> impl Iterator<Item = Value> + '_ {
        (0..self.len()).map(|i| self.get(i))
    }

    /// The components as general values.
    pub fn into_vals(self) -> Vec<Value> {
        match self {
            Elems::Vals(v) => v,
            Elems::Bytes(b) => b.into_iter().map(|x| Value::Int(x as i64)).collect(),
            Elems::Ints(v) => v.into_iter().map(Value::Int).collect(),
            Elems::Reals(v) => v.into_iter().map(Value::Real).collect(),
        }
    }

    /// The bytes, when the array is stored as bytes.
    pub fn bytes(&self) -> Option<&[u8]> {
        match self {
            Elems::Bytes(b) => Some(b),
            _ => None,
        }
    }
}

impl PartialEq for Elems {
    fn eq(&self, other: &Elems) -> bool {
        match (self, other) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a == b,
            (Elems::Ints(a), Elems::Ints(b)) => a == b,
            (Elems::Reals(a), Elems::Reals(b)) => a == b,
            (Elems::Vals(a), Elems::Vals(b)) => a == b,
            _ => self.len() == other.len() && self.iter().zip(other.iter()).all(|(x, y)| x == y),
        }
    }
}

impl FromIterator<Value> for Elems {
    fn from_iter<I: IntoIterator<Item = Value>>(it: I) -> Self {
        Elems::from_vals(it.into_iter().collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn form(e: &Elems) -> &'static str {
        match e {
            Elems::Vals(_) => "vals",
            Elems::Bytes(_) => "bytes",
            Elems::Ints(_) => "ints",
            Elems::Reals(_) => "reals",
        }
    }

    /// A string of up to 16 characters is one allocation: the array value
    /// (bounds and bytes inline) behind its `Rc`.
    #[test]
    fn a_short_string_is_held_inline() {
        assert!(std::mem::size_of::<Elems>() <= 32);
        assert!(std::mem::size_of::<super::super::value::Array>() <= 56);
        let s = super::super::value::Array::string("P 123: 45");
        assert!(matches!(&s.data, Elems::Bytes(b) if !b.spilled()));
        assert!(!s.bounds.spilled());
    }

    #[test]
    fn each_form_widens_only_when_a_value_does_not_fit() {
        let mut e = Elems::from_vals(vec![Value::Int(65), Value::Int(66)]);
        assert_eq!(form(&e), "bytes");
        e.set(0, Value::Int(255));
        assert_eq!(e.bytes(), Some(&[255u8, 66][..]));
        e.set(1, Value::Int(256));
        assert_eq!(form(&e), "ints");
        assert_eq!((e.int(0), e.int(1)), (255, 256));
        e.set(0, Value::Int(-3));
        assert_eq!(form(&e), "ints");
        e.push(Value::Real(0.5));
        assert_eq!(form(&e), "vals");
        assert_eq!(e.len(), 3);
        assert!(matches!(e.get(2), Value::Real(x) if x == 0.5));

        let mut r = Elems::repeat(Value::Real(0.0), 3);
        assert_eq!(form(&r), "reals");
        r.set(1, Value::Real(2.5));
        assert_eq!(r.real(1), 2.5);
        r.set(2, Value::Int(1));
        assert_eq!(form(&r), "vals");
        assert!(matches!(r.get(1), Value::Real(x) if x == 2.5));
        assert!(matches!(r.get(2), Value::Int(1)));

        let n = Elems::from_vals(vec![Value::Int(-1)]);
        assert_eq!(form(&n), "ints");
        assert_eq!(form(&Elems::from_vals(vec![Value::Undef])), "vals");
    }

    #[test]
    fn all_forms_compare_and_join_alike() {
        let b = Elems::from_vals(vec![Value::Int(1), Value::Int(2)]);
        let v = Elems::Vals(vec![Value::Int(1), Value::Int(2)]);
        let i = Elems::Ints(vec![1, 2]);
        assert_eq!(b, v);
        assert_eq!(i, b);
        assert_ne!(b, Elems::Vals(vec![Value::Int(1), Value::Real(2.0)]));
        let mut j = b.clone();
        j.extend_from(&Elems::Reals(vec![0.5]));
        assert_eq!(j.len(), 3);
        assert!(matches!(j.get(2), Value::Real(x) if x == 0.5));
        let mut k = Elems::default();
        k.extend_from(&Elems::Reals(vec![0.5, 1.5]));
        assert_eq!(form(&k), "reals");
        let mut c = Elems::repeat(Value::Int(0), 4);
        c.copy_from(1, &v);
        assert_eq!(c.bytes(), Some(&[0u8, 1, 2, 0][..]));
        c.copy_from(2, &Elems::Ints(vec![1000]));
        assert_eq!(c.int(2), 1000);
        assert_eq!(c.slice(0..2), Elems::Ints(vec![0, 1]));
        let mut p = Elems::default();
        p.push(Value::Real(1.0));
        assert_eq!(form(&p), "reals");
    }
}
