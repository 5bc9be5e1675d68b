//! Array values (`arrblock`, a crate of this repository: its reference
//! count, bounds and components in one allocation behind a thin pointer,
//! the unsafe code adair forbids in its own), for this interpreter's
//! [`Value`].
//!
//! An array keeps its components in the narrowest form that holds them
//! all: bytes when every one is a discrete value in `0 ..= 255` (a
//! `String`'s characters, Booleans, small enumerations), integers when
//! every one is a discrete value, reals when every one is a real, and
//! general [`Value`]s otherwise (composites, access values, a mix). Which
//! form an array has is a matter of storage only: every reader sees the
//! same values either way, and storing a component the form cannot hold
//! widens that array value first (once): bytes to integers, anything else
//! to general values. Copying an array value is one more reference; the
//! first write to a shared one copies its one block (a `String (1 .. 4)`
//! is 48 bytes: a 24-byte head, its bounds and its 4 characters).

use super::value::Value;
pub use arrblock::{Bound, Form, Scalar};

/// An array value: a pointer to its one block (8 bytes).
pub type Array = arrblock::Array<Value>;
/// An array's components, as a slice of their form.
pub type Elems<'a> = arrblock::Elems<'a, Value>;
/// An array's components to change in place.
pub type ElemsMut<'a> = arrblock::ElemsMut<'a, Value>;

/// The bytes of a byte string built before it becomes an array (a
/// number's image): on the native stack up to 16.
pub type ByteVec = smallvec::SmallVec<[u8; 16]>;

impl arrblock::Component for Value {
    #[inline(always)]
    fn from_int(i: i64) -> Value {
        Value::Int(i)
    }
    #[inline(always)]
    fn from_real(x: f64) -> Value {
        Value::Real(x)
    }
    #[inline(always)]
    fn scalar(&self) -> Scalar {
        match self {
            Value::Int(i) => Scalar::Int(*i),
            Value::Real(x) => Scalar::Real(*x),
            _ => Scalar::Other,
        }
    }
    #[inline(always)]
    fn as_int(&self) -> i64 {
        self.int()
    }
    #[inline(always)]
    fn as_real(&self) -> f64 {
        self.real()
    }
    #[inline(always)]
    fn overwrite(slot: &mut Value, v: Value) {
        super::value::overwrite(slot, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn form(a: &Array) -> &'static str {
        match a.form() {
            Form::Vals => "vals",
            Form::Bytes => "bytes",
            Form::Ints => "ints",
            Form::Reals => "reals",
        }
    }

    /// An array value is a pointer, and a `String (1 .. 4)` one block of
    /// 48 bytes: head, bounds and characters (`tests/value_memory.rs`
    /// counts what a copy allocates).
    #[test]
    fn an_array_is_one_pointer_to_one_block() {
        assert_eq!(std::mem::size_of::<Array>(), 8);
        assert_eq!(std::mem::size_of::<Value>(), 16);
        assert_eq!(Array::string("ABCD").block_size(), 48);
        let s = Array::string("P 123: 45");
        assert_eq!(s.bounds(), &[(1, 9)]);
        assert_eq!(s.data().bytes(), Some(&b"P 123: 45"[..]));
    }

    #[test]
    fn a_write_copies_a_shared_array_only() {
        let a = Array::from_vals(vec![Value::Int(1), Value::Int(2)]);
        let mut b = a.clone();
        b.set(0, Value::Int(7));
        assert_eq!(a.data().int(0), 1);
        assert_eq!(b.data().int(0), 7);
        let p = b.clone();
        b.set(1, Value::Int(8));
        assert!(!b.same_block(&p), "a shared block is copied");
        drop(p);
        let p = b.clone();
        drop(p);
        let q = b.clone();
        drop(q);
        let before = b.clone();
        drop(before);
        assert_eq!(b.ref_count(), 1);
        b.set(0, Value::Int(9));
        assert_eq!((b.data().int(0), b.data().int(1)), (9, 8));
        let mut m = Array::repeat(Value::Real(0.5), 6).with_bounds(&[(1, 2), (0, 2)]);
        assert_eq!(m.offset(&[2, 2]), Some(5));
        m.set(5, Value::Real(2.0));
        assert_eq!(m.data().real(5), 2.0);
        m.set_bounds(&[(1, 6)]);
        assert_eq!(m.data().real(5), 2.0);
        assert_eq!(m.bounds(), &[(1, 6)]);
        let strs = Array::repeat(Value::str("ab"), 3);
        let mut c = strs.clone();
        *c.get_mut(1) = Value::str("cd");
        assert_eq!(strs.data().get(1), Value::str("ab"));
        assert_eq!(c.data().get(1), Value::str("cd"));
        assert_eq!(c.clone().into_vals().len(), 3);
        assert_eq!(c.into_vals()[1], Value::str("cd"));
    }

    #[test]
    fn each_form_widens_only_when_a_value_does_not_fit() {
        let mut e = Array::from_vals(vec![Value::Int(65), Value::Int(66)]);
        assert_eq!(form(&e), "bytes");
        e.set(0, Value::Int(255));
        assert_eq!(e.data().bytes(), Some(&[255u8, 66][..]));
        e.set(1, Value::Int(256));
        assert_eq!(form(&e), "ints");
        assert_eq!((e.data().int(0), e.data().int(1)), (255, 256));
        e.set(0, Value::Int(-3));
        assert_eq!(form(&e), "ints");
        e.push(Value::Real(0.5));
        assert_eq!(form(&e), "vals");
        assert_eq!(e.len_all(), 3);
        assert!(matches!(e.data().get(2), Value::Real(x) if x == 0.5));

        let mut r = Array::repeat(Value::Real(0.0), 3);
        assert_eq!(form(&r), "reals");
        r.set(1, Value::Real(2.5));
        assert_eq!(r.data().real(1), 2.5);
        r.set(2, Value::Int(1));
        assert_eq!(form(&r), "vals");
        assert!(matches!(r.data().get(1), Value::Real(x) if x == 2.5));
        assert!(matches!(r.data().get(2), Value::Int(1)));

        let n = Array::from_vals(vec![Value::Int(-1)]);
        assert_eq!(form(&n), "ints");
        assert_eq!(form(&Array::from_vals(vec![Value::Undef])), "vals");
    }

    #[test]
    fn all_forms_compare_and_join_alike() {
        let b = Array::from_vals(vec![Value::Int(1), Value::Int(2)]);
        let mut v = Array::with_capacity(Form::Vals, 2);
        v.push(Value::Int(1));
        v.push(Value::Int(2));
        assert_eq!(form(&v), "vals");
        let i = Array::from_elems(1, Elems::Ints(&[1, 2]));
        assert_eq!(b.data(), v.data());
        assert_eq!(i.data(), b.data());
        let mixed = [Value::Int(1), Value::Real(2.0)];
        assert_ne!(b.data(), Elems::Vals(&mixed));
        let mut j = b.clone();
        j.extend_from(Elems::Reals(&[0.5]));
        assert_eq!(j.len_all(), 3);
        assert!(matches!(j.data().get(2), Value::Real(x) if x == 0.5));
        assert_eq!(b.len_all(), 2, "the shared original is not changed");
        let mut k = Array::default();
        k.extend_from(Elems::Reals(&[0.5, 1.5]));
        assert_eq!(form(&k), "reals");
        let mut c = Array::repeat(Value::Int(0), 4);
        c.copy_from(1, v.data());
        assert_eq!(c.data().bytes(), Some(&[0u8, 1, 2, 0][..]));
        c.copy_from(2, Elems::Ints(&[1000]));
        assert_eq!(c.data().int(2), 1000);
        assert_eq!(c.data().slice(0..2), Elems::Ints(&[0, 1]));
        let mut p = Array::default();
        p.push(Value::Real(1.0));
        assert_eq!(form(&p), "reals");
        let mut s = Array::string("ab");
        for _ in 0..100 {
            s.push(Value::Int(b'c' as i64));
        }
        let s = Array::vector(1, s);
        assert_eq!(s.bounds(), &[(1, 102)]);
        assert_eq!(s.to_string_lossy().len(), 102);
    }
}
