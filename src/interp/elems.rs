//! The components of an array value, stored compactly.
//!
//! An array whose components are all discrete values in `0 ..= 255` (a
//! `String`'s characters, Booleans, small enumerations) keeps them as bytes,
//! one byte each; any other array keeps general [`Value`]s. Which form an
//! array has is a matter of storage only: every reader sees `Value::Int`s
//! either way, and storing a component that is not a byte turns a byte
//! array into general values first (once, for that array value).

use super::value::Value;

/// An array's components, in row-major order.
#[derive(Clone, Debug)]
pub enum Elems {
    /// General values.
    Vals(Vec<Value>),
    /// Discrete values in `0 ..= 255`, one byte each (up to 16 held in
    /// the array value itself).
    Bytes(ByteVec),
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
    /// Components from general values: bytes when every one is a byte.
    pub fn from_vals(vals: Vec<Value>) -> Elems {
        if vals.iter().all(|v| byte(v).is_some()) {
            Elems::Bytes(vals.iter().map(|v| v.int() as u8).collect())
        } else {
            Elems::Vals(vals)
        }
    }

    /// `n` copies of `v`.
    pub fn repeat(v: Value, n: usize) -> Elems {
        match byte(&v) {
            Some(b) => Elems::Bytes(smallvec::smallvec![b; n]),
            None => Elems::Vals(vec![v; n]),
        }
    }

    /// An empty list with room for `n` components like `like`.
    pub fn with_capacity_like(like: &Elems, n: usize) -> Elems {
        match like {
            Elems::Bytes(_) => Elems::Bytes(ByteVec::with_capacity(n)),
            Elems::Vals(_) => Elems::Vals(Vec::with_capacity(n)),
        }
    }

    #[inline]
    pub fn len(&self) -> usize {
        match self {
            Elems::Vals(v) => v.len(),
            Elems::Bytes(b) => b.len(),
        }
    }

    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Component `i` (which must exist).
    #[inline(always)]
    pub fn get(&self, i: usize) -> Value {
        match self {
            Elems::Vals(v) => v[i].clone(),
            Elems::Bytes(b) => Value::Int(b[i] as i64),
        }
    }

    /// Component `i` as an integer, without building a value.
    #[inline(always)]
    pub fn int(&self, i: usize) -> i64 {
        match self {
            Elems::Vals(v) => v[i].int(),
            Elems::Bytes(b) => b[i] as i64,
        }
    }

    /// Component `i` as a real.
    #[inline(always)]
    pub fn real(&self, i: usize) -> f64 {
        match self {
            Elems::Vals(v) => v[i].real(),
            Elems::Bytes(b) => b[i] as f64,
        }
    }

    /// Component `i` as a general value, if it is stored as one (a
    /// composite component always is).
    #[inline(always)]
    pub fn val(&self, i: usize) -> Option<&Value> {
        match self {
            Elems::Vals(v) => Some(&v[i]),
            Elems::Bytes(_) => None,
        }
    }

    /// The general values, a byte array turned into them first.
    #[inline]
    pub fn vals_mut(&mut self) -> &mut Vec<Value> {
        if let Elems::Bytes(b) = self {
            *self = Elems::Vals(b.iter().map(|&x| Value::Int(x as i64)).collect());
        }
        match self {
            Elems::Vals(v) => v,
            Elems::Bytes(_) => unreachable!("turned into values above"),
        }
    }

    /// Component `i` to change in place (a byte array becomes general
    /// values: for a composite component's parts, which bytes never have).
    #[inline]
    pub fn get_mut(&mut self, i: usize) -> &mut Value {
        &mut self.vals_mut()[i]
    }

    /// Sets component `i` (which must exist).
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: Value) {
        match self {
            Elems::Vals(vs) => super::value::overwrite(&mut vs[i], v),
            Elems::Bytes(b) => match byte(&v) {
                Some(x) => b[i] = x,
                None => self.vals_mut()[i] = v,
            },
        }
    }

    /// Appends a component.
    pub fn push(&mut self, v: Value) {
        match self {
            Elems::Vals(vs) => vs.push(v),
            Elems::Bytes(b) => match byte(&v) {
                Some(x) => b.push(x),
                None => self.vals_mut().push(v),
            },
        }
    }

    /// Appends `other`'s components.
    /// An empty list takes `other`'s form, keeping its own capacity.
    pub fn extend_from(&mut self, other: &Elems) {
        match (&mut *self, other) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a.extend_from_slice(b),
            (Elems::Vals(a), Elems::Vals(b)) => a.extend(b.iter().cloned()),
            (Elems::Vals(a), Elems::Bytes(b)) if a.is_empty() => {
                let mut n = ByteVec::with_capacity(a.capacity().max(b.len()));
                n.extend_from_slice(b);
                *self = Elems::Bytes(n);
            }
            (Elems::Vals(a), Elems::Bytes(b)) => a.extend(b.iter().map(|&x| Value::Int(x as i64))),
            (Elems::Bytes(a), Elems::Vals(b)) if a.is_empty() => {
                let mut n = Vec::with_capacity(a.capacity().max(b.len()));
                n.extend(b.iter().cloned());
                *self = Elems::Vals(n);
            }
            (Elems::Bytes(_), Elems::Vals(b)) => {
                if !b.is_empty() {
                    self.vals_mut().extend(b.iter().cloned());
                }
            }
        }
    }

    /// Components `range`, in the same form.
    pub fn slice(&self, range: std::ops::Range<usize>) -> Elems {
        match self {
            Elems::Vals(v) => Elems::Vals(v[range].to_vec()),
            Elems::Bytes(b) => Elems::Bytes(ByteVec::from_slice(&b[range])),
        }
    }

    /// Copies `src`'s components over those from `at` on.
    pub fn copy_from(&mut self, at: usize, src: &Elems) {
        match (&mut *self, src) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a[at..at + b.len()].copy_from_slice(b),
            (Elems::Vals(a), Elems::Vals(b)) => a[at..at + b.len()].clone_from_slice(b),
            (Elems::Vals(a), Elems::Bytes(b)) => {
                for (k, &x) in b.iter().enumerate() {
                    a[at + k] = Value::Int(x as i64);
                }
            }
            (Elems::Bytes(_), Elems::Vals(b)) => {
                for (k, v) in b.iter().enumerate() {
                    self.set(at + k, v.clone());
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
        }
    }

    /// The bytes, when the array is stored as bytes.
    pub fn bytes(&self) -> Option<&[u8]> {
        match self {
            Elems::Bytes(b) => Some(b),
            Elems::Vals(_) => None,
        }
    }
}

impl PartialEq for Elems {
    fn eq(&self, other: &Elems) -> bool {
        match (self, other) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a == b,
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
    fn bytes_stay_bytes_until_a_value_is_not_one() {
        let mut e = Elems::from_vals(vec![Value::Int(65), Value::Int(66)]);
        assert!(e.bytes().is_some());
        e.set(0, Value::Int(255));
        assert_eq!(e.bytes(), Some(&[255u8, 66][..]));
        e.set(1, Value::Int(256));
        assert!(e.bytes().is_none());
        assert_eq!(e.int(0), 255);
        assert_eq!(e.int(1), 256);
        let mut n = Elems::from_vals(vec![Value::Int(-1)]);
        assert!(n.bytes().is_none());
        n.push(Value::Int(3));
        assert_eq!(n.len(), 2);
    }

    #[test]
    fn both_forms_compare_and_join_alike() {
        let b = Elems::from_vals(vec![Value::Int(1), Value::Int(2)]);
        let v = Elems::Vals(vec![Value::Int(1), Value::Int(2)]);
        assert_eq!(b, v);
        assert_ne!(b, Elems::Vals(vec![Value::Int(1), Value::Real(2.0)]));
        let mut j = b.clone();
        j.extend_from(&Elems::Vals(vec![Value::Real(0.5)]));
        assert_eq!(j.len(), 3);
        assert!(matches!(j.get(2), Value::Real(x) if x == 0.5));
        let mut c = Elems::repeat(Value::Int(0), 4);
        c.copy_from(1, &v);
        assert_eq!(c.bytes(), Some(&[0u8, 1, 2, 0][..]));
        assert_eq!(c.slice(1..3), v);
    }
}
