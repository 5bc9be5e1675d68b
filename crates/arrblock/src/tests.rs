//! Tests of every public function and every storage form, meant to run
//! under Miri too (`cargo +nightly miri test`): a component that owns heap
//! memory (a `Box`) counts its live values, so a double drop, a leak or a
//! use after free shows up.

use super::*;
use std::cell::Cell;
use std::panic::{AssertUnwindSafe, catch_unwind};

thread_local! {
    /// Owned values alive (made minus dropped).
    static LIVE: Cell<isize> = const { Cell::new(0) };
    /// Clones of an owned value to go before one panics (0: never).
    static PANIC_IN: Cell<usize> = const { Cell::new(0) };
}

fn live() -> isize {
    LIVE.with(|l| l.get())
}

/// Panics at the `n`th clone of an owned value from now.
fn panic_in(n: usize) {
    PANIC_IN.with(|p| p.set(n));
}

#[derive(Debug, PartialEq)]
struct Owned(u64);

impl Owned {
    fn new(n: u64) -> Box<Owned> {
        LIVE.with(|l| l.set(l.get() + 1));
        Box::new(Owned(n))
    }
}

impl Drop for Owned {
    fn drop(&mut self) {
        LIVE.with(|l| l.set(l.get() - 1));
    }
}

/// A component: 16 bytes, one variant owning heap memory.
#[derive(Debug, PartialEq)]
enum T {
    I(i64),
    R(f64),
    S(Box<Owned>),
}

impl Clone for T {
    fn clone(&self) -> T {
        match self {
            T::I(i) => T::I(*i),
            T::R(x) => T::R(*x),
            T::S(b) => {
                PANIC_IN.with(|p| match p.get() {
                    0 => {}
                    1 => {
                        p.set(0);
                        panic!("clone panics (on purpose)");
                    }
                    n => p.set(n - 1),
                });
                T::S(Owned::new(b.0))
            }
        }
    }
}

fn s(n: u64) -> T {
    T::S(Owned::new(n))
}

impl Component for T {
    fn from_int(i: i64) -> T {
        T::I(i)
    }
    fn from_real(x: f64) -> T {
        T::R(x)
    }
    fn scalar(&self) -> Scalar {
        match self {
            T::I(i) => Scalar::Int(*i),
            T::R(x) => Scalar::Real(*x),
            T::S(_) => Scalar::Other,
        }
    }
    fn as_int(&self) -> i64 {
        match self {
            T::I(i) => *i,
            T::R(x) => *x as i64,
            T::S(_) => 0,
        }
    }
    fn as_real(&self) -> f64 {
        match self {
            T::I(i) => *i as f64,
            T::R(x) => *x,
            T::S(_) => 0.0,
        }
    }
}

type A = Array<T>;

/// Component `i` of a test's array.
type MakeT = Box<dyn Fn(usize) -> T>;

/// Runs `f` and checks that every owned value it made was dropped once.
fn balanced(f: impl FnOnce()) {
    let before = live();
    f();
    assert_eq!(live(), before, "owned values leaked or dropped twice");
}

fn vals(a: &A) -> Vec<T> {
    a.data().iter().collect()
}

/// One array of each form, from 1 on, of `n` components.
fn each_form(n: usize) -> Vec<A> {
    vec![
        A::from_vals((0..n).map(|i| T::I(i as i64 % 200)).collect()),
        A::from_vals((0..n).map(|i| T::I(1000 + i as i64)).collect()),
        A::from_vals((0..n).map(|i| T::R(i as f64 + 0.5)).collect()),
        A::from_vals((0..n).map(|i| s(i as u64)).collect()),
    ]
}

#[test]
fn layout_sizes_and_alignment() {
    assert_eq!(HEAD, 24);
    assert_eq!(BOUND, 16);
    assert_eq!(std::mem::size_of::<T>(), VAL_SIZE);
    assert_eq!(std::mem::size_of::<A>(), 8);
    for form in [Form::Bytes, Form::Ints, Form::Reals, Form::Vals] {
        for dims in [0, 1, 2, 7, 255] {
            for cap in [0, 1, 3, 8, 17] {
                balanced(|| {
                    let a = A::with_capacity_dims(form, dims, cap);
                    assert_eq!(a.elems_ptr() as usize % 8, 0);
                    assert_eq!(a.bounds_ptr() as usize % 8, 0);
                    assert_eq!(a.form(), form);
                    assert_eq!(a.len_all(), 0);
                    assert_eq!(a.bounds().len(), dims);
                    assert!(a.bounds().iter().all(|&b| b == (1, 0)));
                    assert!(a.block_size() >= HEAD + dims * BOUND + cap * form.size());
                    assert_eq!(a.block_size() % 8, 0);
                    assert_eq!(a.ref_count(), 1);
                });
            }
        }
    }
}

#[test]
fn creation_of_each_form() {
    balanced(|| {
        let e = A::from_vals(vec![]);
        assert_eq!(
            (e.form(), e.len_all(), e.bounds()),
            (Form::Bytes, 0, &[(1, 0)][..])
        );
        assert_eq!(e.len(0), 0);
        let d = A::default();
        assert_eq!((d.form(), d.len_all()), (Form::Bytes, 0));
        assert_eq!(d, e);
        let [b, i, r, v] = <[A; 4]>::try_from(each_form(5)).unwrap();
        assert_eq!(b.form(), Form::Bytes);
        assert_eq!(i.form(), Form::Ints);
        assert_eq!(r.form(), Form::Reals);
        assert_eq!(v.form(), Form::Vals);
        for a in [&b, &i, &r, &v] {
            assert_eq!(a.bounds(), &[(1, 5)]);
            assert_eq!(a.len(0), 5);
            assert_eq!(a.len_all(), 5);
        }
        assert_eq!(vals(&i)[4], T::I(1004));
        assert_eq!(vals(&r)[2], T::R(2.5));
        assert_eq!(vals(&v)[3], s(3));
        assert_eq!(b.data().bytes(), Some(&[0u8, 1, 2, 3, 4][..]));
        // A mix of integers and reals is general values.
        let m = A::from_vals(vec![T::I(1), T::R(2.0)]);
        assert_eq!(m.form(), Form::Vals);
        let one = A::from_vals(vec![s(9)]);
        assert_eq!((one.form(), one.len_all()), (Form::Vals, 1));
        // FromIterator.
        let c: A = (0..3).map(T::I).collect();
        assert_eq!(c.data().bytes(), Some(&[0u8, 1, 2][..]));
    });
}

#[test]
fn from_elems_string_repeat_vector() {
    balanced(|| {
        for a in each_form(4) {
            let c = A::from_elems(-2, a.data());
            assert_eq!(c.bounds(), &[(-2, 1)]);
            assert_eq!(c.form(), a.form());
            assert_eq!(c.data(), a.data());
            assert!(!c.same_block(&a));
            let e = A::from_elems(7, a.data().slice(1..1));
            assert_eq!((e.len_all(), e.bounds()), (0, &[(7, 6)][..]));
            let part = A::from_elems(1, a.data().slice(1..3));
            assert_eq!(vals(&part), vals(&a)[1..3].to_vec());
        }
        let st = A::string("Hello");
        assert_eq!(st.form(), Form::Bytes);
        assert_eq!(st.to_string_lossy(), "Hello");
        let u = A::string("h€llo");
        assert_eq!(u.form(), Form::Ints);
        assert_eq!(u.to_string_lossy(), "h€llo");
        assert_eq!(A::string("").len_all(), 0);
        assert_eq!(A::from_vals(vec![s(1)]).to_string_lossy(), "?");

        for (v, form) in [
            (T::I(7), Form::Bytes),
            (T::I(-7), Form::Ints),
            (T::R(1.5), Form::Reals),
            (s(3), Form::Vals),
        ] {
            for n in [0, 1, 5] {
                let r = A::repeat(v.clone(), n);
                assert_eq!(
                    (r.form(), r.len_all(), r.bounds()),
                    (form, n, &[(1, n as i64)][..])
                );
                assert!(r.data().iter().all(|x| x == v));
            }
            let r = A::repeat_in(v.clone(), 6, &[(0, 1), (5, 7)]);
            assert_eq!(r.bounds(), &[(0, 1), (5, 7)]);
            assert_eq!(r.len_all(), 6);
            let r0 = A::repeat_in(v.clone(), 1, &[]);
            assert_eq!((r0.bounds().len(), r0.len_all()), (0, 1));
        }

        for a in each_form(3) {
            let blk = a.clone();
            let v = A::vector(10, a);
            assert_eq!(v.bounds(), &[(10, 12)]);
            // `a` was shared: the vector is a copy, the other unchanged.
            assert_eq!(blk.bounds(), &[(1, 3)]);
            assert!(!v.same_block(&blk));
        }
        let v = A::vector(
            0,
            A::from_vals(vec![s(1), s(2)]).with_bounds(&[(1, 1), (1, 2)]),
        );
        assert_eq!(v.bounds(), &[(0, 1)]);
        assert_eq!(vals(&v), vec![s(1), s(2)]);
    });
}

#[test]
fn clone_shares_and_drop_frees_once() {
    balanced(|| {
        let a = A::from_vals(vec![s(1), s(2), s(3)]);
        assert_eq!(live(), 3);
        let b = a.clone();
        let c = b.clone();
        assert_eq!(live(), 3);
        assert_eq!((a.ref_count(), b.ref_count()), (3, 3));
        assert!(a.same_block(&c));
        drop(a);
        assert_eq!(c.ref_count(), 2);
        drop(b);
        assert_eq!(c.ref_count(), 1);
        assert_eq!(vals(&c)[2], s(3));
        drop(c);
        assert_eq!(live(), 0);
    });
    // Nested arrays are not components here, but many copies of one
    // block in a vector are.
    balanced(|| {
        let a = A::from_vals(vec![s(1)]);
        let v: Vec<A> = (0..100).map(|_| a.clone()).collect();
        assert_eq!(a.ref_count(), 101);
        drop(v);
        assert_eq!(a.ref_count(), 1);
    });
}

#[test]
fn copy_on_write_when_shared_in_place_when_own() {
    balanced(|| {
        for a in each_form(4) {
            let mut a = a;
            let before = vals(&a);
            let b = a.clone();
            // Shared: make_mut copies.
            a.make_mut();
            assert!(!a.same_block(&b));
            assert_eq!((a.ref_count(), b.ref_count()), (1, 1));
            assert_eq!(a, b);
            // Own: make_mut does not.
            let p = a.ptr;
            a.make_mut();
            assert_eq!(a.ptr, p);
            // data_mut when shared
            let mut c = a.clone();
            match c.data_mut() {
                ElemsMut::Bytes(x) => x[0] = 99,
                ElemsMut::Ints(x) => x[0] = 99,
                ElemsMut::Reals(x) => x[0] = 99.0,
                ElemsMut::Vals(x) => x[0] = s(99),
            }
            assert_eq!(vals(&a), before);
            assert_ne!(vals(&c), before);
            let p = c.ptr;
            let v0 = c.data().get(0);
            c.set(1, v0.clone());
            assert_eq!(c.ptr, p, "own block written in place");
            assert_eq!(c.data().get(1), v0);
            let _ = c.data_mut();
            assert_eq!(c.ptr, p);
            assert_eq!(vals(&b), before);
        }
    });
}

#[test]
fn set_widens_each_form() {
    balanced(|| {
        let cases: Vec<(Form, T, Form)> = vec![
            (Form::Bytes, T::I(3), Form::Bytes),
            (Form::Bytes, T::I(300), Form::Ints),
            (Form::Bytes, T::I(-1), Form::Ints),
            (Form::Bytes, T::R(0.5), Form::Vals),
            (Form::Bytes, s(1), Form::Vals),
            (Form::Ints, T::I(3), Form::Ints),
            (Form::Ints, T::R(0.5), Form::Vals),
            (Form::Ints, s(1), Form::Vals),
            (Form::Reals, T::R(3.5), Form::Reals),
            (Form::Reals, T::I(3), Form::Vals),
            (Form::Reals, s(1), Form::Vals),
            (Form::Vals, T::I(3), Form::Vals),
            (Form::Vals, T::R(3.5), Form::Vals),
            (Form::Vals, s(8), Form::Vals),
        ];
        for (from, v, to) in cases {
            let mut a = each_form(4).into_iter().find(|a| a.form() == from).unwrap();
            let a2 = a.clone();
            let before = vals(&a);
            a.set(2, v.clone());
            assert_eq!(a.form(), to, "{from:?} set {v:?}");
            let mut want = before.clone();
            want[2] = v.clone();
            assert_eq!(vals(&a), want);
            assert_eq!(vals(&a2), before);
            assert_eq!(a.bounds(), a2.bounds());
            // set on an own array too
            drop(a2);
            a.set(0, v.clone());
            assert_eq!(a.data().get(0), v);
        }
    });
}

#[test]
fn get_mut_turns_into_vals() {
    balanced(|| {
        for a in each_form(3) {
            let mut a = a;
            let b = a.clone();
            *a.get_mut(1) = s(42);
            assert_eq!(a.form(), Form::Vals);
            assert_eq!(a.data().val(1), Some(&s(42)));
            assert_eq!(vals(&b)[1], b.data().get(1));
            assert_ne!(a, b);
            *a.get_mut(0) = T::I(1);
            assert_eq!(a.data().int(0), 1);
        }
        let mut a = A::from_vals(vec![T::I(1)]);
        let r = catch_unwind(AssertUnwindSafe(|| {
            a.get_mut(5);
        }));
        assert!(r.is_err());
    });
}

#[test]
fn push_grows_across_capacities() {
    balanced(|| {
        let items: Vec<(Form, MakeT)> = vec![
            (Form::Bytes, Box::new(|i| T::I((i % 256) as i64))),
            (Form::Ints, Box::new(|i| T::I(-(i as i64)))),
            (Form::Reals, Box::new(|i| T::R(i as f64))),
            (Form::Vals, Box::new(|i| s(i as u64))),
        ];
        for (form, f) in &items {
            for start_cap in [0, 1, 5] {
                for dims in [0, 1, 3] {
                    let mut a = A::with_capacity_dims(*form, dims, start_cap);
                    let mut caps = vec![];
                    let mut snap = None;
                    for i in 0..300 {
                        a.push(f(i));
                        assert_eq!(a.form(), *form);
                        caps.push(a.head().cap);
                        if i == 150 {
                            // A shared array grows by a copy.
                            snap = Some(a.clone());
                        }
                    }
                    caps.dedup();
                    assert!(caps.len() > 3, "{caps:?}");
                    assert_eq!(a.len_all(), 300);
                    for (i, v) in a.data().iter().enumerate() {
                        assert_eq!(v, f(i));
                    }
                    let snap = snap.unwrap();
                    assert_eq!(snap.len_all(), 151);
                    for (i, v) in snap.data().iter().enumerate() {
                        assert_eq!(v, f(i));
                    }
                    assert_eq!(a.bounds().len(), dims);
                }
            }
        }
        // push that widens
        let mut a = A::from_vals(vec![T::I(1)]);
        a.push(T::I(1000));
        assert_eq!(a.form(), Form::Ints);
        a.push(T::R(1.0));
        assert_eq!(a.form(), Form::Vals);
        a.push(s(5));
        assert_eq!(vals(&a), vec![T::I(1), T::I(1000), T::R(1.0), s(5)]);
        // push to an empty array takes the value's form
        for (v, f) in [
            (T::R(2.0), Form::Reals),
            (s(1), Form::Vals),
            (T::I(-3), Form::Ints),
        ] {
            let mut e = A::default();
            e.push(v.clone());
            assert_eq!((e.form(), vals(&e)), (f, vec![v]));
        }
    });
}

#[test]
fn reserve_and_extend() {
    balanced(|| {
        let mut a = A::default();
        a.reserve(10);
        assert!(a.head().cap >= 10);
        let p = a.ptr;
        for i in 0..10 {
            a.push(T::I(i));
        }
        assert_eq!(a.ptr, p, "reserved room used without moving");
        a.reserve(0);
        // extend of every form pair
        for x in each_form(5) {
            for y in each_form(3) {
                let mut a = x.clone();
                let keep = x.clone();
                a.extend_from(y.data());
                let mut want = vals(&x);
                want.extend(vals(&y));
                assert_eq!(vals(&a), want, "{:?} + {:?}", x.form(), y.form());
                assert_eq!(keep, x);
                // own array, many extends crossing capacities
                let mut b = A::with_capacity(x.form(), 0);
                for _ in 0..40 {
                    b.extend_from(y.data());
                }
                assert_eq!(b.len_all(), 120);
                assert_eq!(b.form(), y.form());
                // extend from itself (a copy of it)
                let mut c = x.clone();
                let c2 = c.clone();
                c.extend_from(c2.data());
                assert_eq!(c.len_all(), 10);
                drop(c2);
                let c3 = c.clone();
                c.extend_from(c3.data());
                assert_eq!(c.len_all(), 20);
                // empty extends change nothing
                let p = c.ptr;
                c.extend_from(y.data().slice(0..0));
                assert_eq!((c.ptr, c.len_all()), (p, 20));
            }
        }
        // an empty array takes the other's form and keeps its own room
        let mut e = A::with_capacity(Form::Bytes, 50);
        let v = A::from_vals(vec![s(1), s(2)]);
        e.extend_from(v.data());
        assert_eq!(e.form(), Form::Vals);
        assert!(e.head().cap >= 50);
        assert_eq!(vals(&e), vals(&v));
    });
}

#[test]
fn copy_from_each_pair() {
    balanced(|| {
        for x in each_form(6) {
            for y in each_form(2) {
                let mut a = x.clone();
                a.copy_from(3, y.data());
                let mut want = vals(&x);
                want[3..5].clone_from_slice(&vals(&y));
                assert_eq!(vals(&a), want);
                assert_eq!(x.len_all(), 6);
                // own array, then out of range
                let mut b = A::from_elems(1, x.data());
                b.copy_from(0, y.data());
                let r = catch_unwind(AssertUnwindSafe(|| b.copy_from(5, y.data())));
                assert!(r.is_err());
            }
        }
    });
}

#[test]
fn into_vals_moves_or_copies() {
    balanced(|| {
        for a in each_form(4) {
            let want = vals(&a);
            let b = a.clone();
            assert_eq!(b.into_vals(), want); // shared: copied
            assert_eq!(a.ref_count(), 1);
            assert_eq!(a.into_vals(), want); // own: moved (Vals)
        }
        assert_eq!(A::default().into_vals(), vec![]);
    });
}

#[test]
fn bounds_change_and_offsets() {
    balanced(|| {
        for a in each_form(12) {
            let want = vals(&a);
            let keep = a.clone();
            let mut a = a;
            a.set_bounds(&[(0, 2), (1, 4)]);
            assert_eq!(a.bounds(), &[(0, 2), (1, 4)]);
            assert_eq!(keep.bounds(), &[(1, 12)]);
            assert_eq!(vals(&a), want);
            assert_eq!(a.offset(&[0, 1]), Some(0));
            assert_eq!(a.offset(&[2, 4]), Some(11));
            assert_eq!(a.offset(&[1, 2]), Some(5));
            assert_eq!(a.offset(&[3, 1]), None);
            assert_eq!(a.offset(&[0, 0]), None);
            assert_eq!((a.len(0), a.len(1)), (3, 4));
            // same number: in place
            let p = a.ptr;
            a.set_bounds(&[(1, 3), (1, 4)]);
            assert_eq!(a.ptr, p);
            // three dimensions
            let mut a = a.with_bounds(&[(1, 2), (1, 2), (0, 2)]);
            assert_eq!(a.offset(&[2, 1, 1]), Some(7));
            assert_eq!(a.offset(&[2, 2, 2]), Some(11));
            assert_eq!(a.offset(&[2, 2, 3]), None);
            assert_eq!(a.offset(&[2, 2]), Some(3)); // fewer indices: a prefix
            assert_eq!(a.offset(&[1, 1, 1, 1]), None);
            assert_eq!(vals(&a), want);
            a.push(T::I(1));
            assert_eq!(a.len_all(), 13);
            // zero dimensions, then back to one
            a.set_bounds(&[]);
            assert_eq!(a.bounds(), &[]);
            assert_eq!(a.offset(&[]), Some(0));
            assert_eq!(a.len_all(), 13);
            a.set_bounds(&[(1, 13)]);
            assert_eq!(a.offset(&[13]), Some(12));
            assert_eq!(a.offset(&[14]), None);
            assert_eq!(vals(&a)[..12], want[..]);
            // many dimensions
            let b = a.with_bounds(&[(1, 1); 255]);
            assert_eq!(b.bounds().len(), 255);
            assert_eq!(b.len_all(), 13);
            let r = catch_unwind(AssertUnwindSafe(|| b.clone().with_bounds(&[(1, 1); 256])));
            assert!(r.is_err());
        }
    });
}

#[test]
fn elems_methods() {
    balanced(|| {
        let [b, i, r, v] = <[A; 4]>::try_from(each_form(4)).unwrap();
        for (a, form) in [
            (&b, Form::Bytes),
            (&i, Form::Ints),
            (&r, Form::Reals),
            (&v, Form::Vals),
        ] {
            let d = a.data();
            assert_eq!(d.form(), form);
            assert_eq!(d.len(), 4);
            assert!(!d.is_empty());
            assert!(d.slice(2..2).is_empty());
            assert_eq!(d.slice(1..3).len(), 2);
            assert_eq!(d.iter().count(), 4);
            assert_eq!(d.val(0).is_some(), form == Form::Vals);
            assert_eq!(d.bytes().is_some(), form == Form::Bytes);
            let _ = (d.int(3), d.real(3), d.get(3));
            let e = d; // Copy
            assert_eq!(e, d);
            assert!(!format!("{d:?}").is_empty());
            assert!(format!("{a:?}").contains("bounds"));
        }
        assert_eq!(b.data().int(3), 3);
        assert_eq!(i.data().real(1), 1001.0);
        assert_eq!(r.data().int(1), 1);
        assert_eq!(r.data().real(1), 1.5);
        assert_eq!(v.data().int(1), 0);
        // equal values in two forms are equal
        let x = A::from_vals(vec![T::I(1), T::I(2)]);
        let mut y = A::from_vals(vec![T::I(1), T::I(2)]);
        y.get_mut(0);
        assert_eq!(y.form(), Form::Vals);
        assert_eq!(x.data(), y.data());
        assert_eq!(x, y);
        assert_ne!(x.data(), b.data());
    });
}

#[test]
fn clone_panicking_while_a_block_fills() {
    // Every place that clones general values into a new block, with the
    // clone panicking at the first, a middle and the last one.
    for at in [1, 3, 5] {
        balanced(|| {
            let a = A::from_vals((0..5).map(s).collect());
            // make_mut of a shared array (copy_with_room)
            let mut b = a.clone();
            panic_in(at);
            assert!(
                catch_unwind(AssertUnwindSafe(|| {
                    b.make_mut();
                }))
                .is_err()
            );
            assert!(b.same_block(&a));
            // push to a shared array (copy with room)
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| b.push(s(9)))).is_err());
            assert_eq!(b.len_all(), 5);
            // from_elems
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| A::from_elems(1, a.data()))).is_err());
            // extend_from, own array
            let mut c = A::from_vals(vec![s(100)]);
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| c.extend_from(a.data()))).is_err());
            assert_eq!(c.data().val(0), Some(&s(100)));
            assert!(c.len_all() <= 5);
            // repeat
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| A::repeat(s(1), 5))).is_err());
            // copy_from
            let mut d = A::from_vals((0..5).map(s).collect());
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| d.copy_from(0, a.data()))).is_err());
            assert_eq!(d.len_all(), 5);
            // into_vals of a shared array
            panic_in(at);
            assert!(catch_unwind(AssertUnwindSafe(|| a.clone().into_vals())).is_err());
            panic_in(0);
        });
    }
}

#[test]
fn refcount_never_wraps() {
    let a = A::from_vals(vec![s(1)]);
    // As if u32::MAX - 1 copies had been forgotten.
    a.head().count.set(u32::MAX);
    let r = catch_unwind(AssertUnwindSafe(|| a.clone()));
    assert!(r.is_err(), "the u32::MAX + 1st copy must be refused");
    assert_eq!(a.head().count.get(), u32::MAX);
    a.head().count.set(u32::MAX - 1);
    let b = a.clone();
    assert_eq!(b.ref_count(), u32::MAX as usize);
    drop(b);
    a.head().count.set(1);
    drop(a);
    assert_eq!(live(), 0);
}

#[test]
fn too_large_is_refused_before_allocating() {
    // Lengths whose block would pass `isize::MAX` bytes (the largest a
    // `Layout` takes) or overflow `usize`: refused with a panic. (Lengths
    // just below are valid layouts the allocator fails on: an abort, by
    // `handle_alloc_error`, not tested.)
    let big_for = |form: Form| {
        let max = isize::MAX as usize;
        [
            usize::MAX,
            usize::MAX / 2,
            max / form.size() + 1,
            (max - 47) / form.size() + 1,
        ]
    };
    let big = big_for(Form::Vals);
    for form in [Form::Bytes, Form::Ints, Form::Reals, Form::Vals] {
        for n in big_for(form) {
            let r = catch_unwind(|| A::with_capacity(form, n));
            assert!(r.is_err(), "{form:?} {n}");
            let r = catch_unwind(|| A::with_capacity_dims(form, 255, n));
            assert!(r.is_err(), "{form:?} {n}");
        }
    }
    for n in big_for(Form::Bytes) {
        assert!(catch_unwind(|| A::repeat(T::I(1), n)).is_err());
        let mut a = A::from_vals(vec![T::I(1)]);
        assert!(catch_unwind(AssertUnwindSafe(|| a.reserve(n))).is_err());
    }
    for n in big_for(Form::Ints) {
        assert!(catch_unwind(|| A::repeat(T::R(1.0), n)).is_err());
    }
    balanced(|| {
        for a in each_form(3) {
            for n in big_for(a.form()) {
                let mut a = a.clone();
                // shared: the copy with room is refused
                assert!(catch_unwind(AssertUnwindSafe(|| a.reserve(n))).is_err());
                assert_eq!(a.ref_count(), 2);
                a.make_mut();
                // own: the realloc is refused
                assert!(catch_unwind(AssertUnwindSafe(|| a.reserve(n))).is_err());
                assert_eq!(a.len_all(), 3);
                let b = a.clone();
                assert_eq!(b, a);
            }
        }
    });
    balanced(|| {
        for &n in &big {
            assert!(catch_unwind(|| A::repeat(s(1), n)).is_err());
        }
    });
}

#[test]
fn neither_send_nor_sync() {
    // Compiles only when `Array<T>` is not `Send` (and likewise `Sync`):
    // two impls would otherwise fit and the call be ambiguous.
    trait AmbiguousIfSend<X> {
        fn f() {}
    }
    impl<X: ?Sized> AmbiguousIfSend<()> for X {}
    impl<X: ?Sized + Send> AmbiguousIfSend<u8> for X {}
    <A as AmbiguousIfSend<_>>::f();
    trait AmbiguousIfSync<X> {
        fn f() {}
    }
    impl<X: ?Sized> AmbiguousIfSync<()> for X {}
    impl<X: ?Sized + Sync> AmbiguousIfSync<u8> for X {}
    <A as AmbiguousIfSync<_>>::f();
}

thread_local! {
    /// How many times a `Flaky` was asked what scalar it is.
    static ASKED: Cell<u32> = const { Cell::new(0) };
}

/// A component whose `scalar` answers an integer, then a real, then an
/// integer... A poor but safe implementation of the trait: the unsafe code
/// must not trust two answers to agree.
#[derive(Clone, Debug, PartialEq)]
struct Flaky(i64, i64);

impl Component for Flaky {
    fn from_int(i: i64) -> Flaky {
        Flaky(i, 0)
    }
    fn from_real(x: f64) -> Flaky {
        Flaky(x as i64, 0)
    }
    fn scalar(&self) -> Scalar {
        let n = ASKED.with(|a| a.replace(a.get() + 1));
        if n.is_multiple_of(2) {
            Scalar::Int(self.0)
        } else {
            Scalar::Real(self.0 as f64)
        }
    }
    fn as_int(&self) -> i64 {
        self.0
    }
    fn as_real(&self) -> f64 {
        self.0 as f64
    }
}

/// `repeat_in` chose the form by one call of `scalar` and wrote the
/// components by another: with answers that differ, 8-byte reals were
/// written into a block of bytes (past its end for more than one
/// component: Miri reports an out-of-bounds write; the plain test sees
/// wrong components).
#[test]
fn repeat_trusts_one_answer_of_scalar() {
    ASKED.with(|a| a.set(0));
    let a = Array::repeat(Flaky(5, 0), 1);
    assert_eq!(a.form(), Form::Bytes);
    assert_eq!(a.data().int(0), 5);
}

/// The same, past the block's end: undefined behaviour (Miri: "out-of-
/// bounds pointer arithmetic" or a write past the allocation).
#[test]
fn repeat_never_writes_past_its_block() {
    for n in [2, 16, 100] {
        ASKED.with(|a| a.set(0));
        let a = Array::repeat(Flaky(7, 0), n);
        assert_eq!(a.form(), Form::Bytes);
        assert!(a.data().iter().all(|v| v.0 == 7));
    }
}
