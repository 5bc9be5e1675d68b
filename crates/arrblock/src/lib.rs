//! An array value: its reference count, its bounds and its components in
//! one allocation, behind a thin pointer (8 bytes).
//!
//! [`Array`] points to one block of the allocator: a 24-byte head (the
//! reference count, the components' form, the number of dimensions, the
//! number of components and the room for them), a pair of bounds per
//! dimension, then the components. Copying an array value is one more
//! reference; the first write to a shared one copies the block, one
//! allocation.
//!
//! An array keeps its components in the narrowest form that holds them
//! all: bytes when every one is a discrete value in `0 ..= 255`, integers
//! when every one is a discrete value, reals when every one is a real, and
//! general values (`V`) otherwise. Which form an array has is a matter of
//! storage only: every reader sees the same values either way
//! ([`Array::data`]), and storing a component the form cannot hold widens
//! that array value first (once): bytes to integers, anything else to
//! general values.
//!
//! Every method that changes an array first makes its block its own (a
//! copy when it is shared, as `Rc::make_mut`), so no write is seen through
//! another copy. Not `Send`: the count is not atomic.

use std::alloc::{self, Layout};
use std::cell::Cell;
use std::marker::PhantomData;
use std::ptr::{self, NonNull};

/// What an array's general component values must tell and do (adair's
/// `Value`).
pub trait Component: Clone + PartialEq {
    /// A discrete value.
    fn from_int(i: i64) -> Self;
    /// A real value.
    fn from_real(x: f64) -> Self;
    /// Which scalar this is, if it is one.
    fn scalar(&self) -> Scalar;
    /// As an integer (a real truncated; anything else 0).
    fn as_int(&self) -> i64;
    /// As a real (an integer converted; anything else 0.0).
    fn as_real(&self) -> f64;
    /// `*slot = v` (a type may skip its drop glue for what owns nothing).
    #[inline(always)]
    fn overwrite(slot: &mut Self, v: Self) {
        *slot = v;
    }
}

/// What a component value is, for the form that can hold it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scalar {
    Int(i64),
    Real(f64),
    Other,
}

/// A dimension's bounds (first, last).
pub type Bound = (i64, i64);

/// How an array's components are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Form {
    /// Discrete values in `0 ..= 255`, one byte each.
    Bytes,
    /// Discrete values.
    Ints,
    /// Reals (`Float`, `Duration`, times).
    Reals,
    /// General values.
    Vals,
}

impl Form {
    /// The bytes one component takes.
    #[inline(always)]
    fn size(self) -> usize {
        match self {
            Form::Bytes => 1,
            Form::Ints | Form::Reals => 8,
            Form::Vals => VAL_SIZE,
        }
    }
    /// The narrowest form that holds `v`.
    fn of<V: Component>(v: &V) -> Form {
        match v.scalar() {
            Scalar::Int(i) if (0..=255).contains(&i) => Form::Bytes,
            Scalar::Int(_) => Form::Ints,
            Scalar::Real(_) => Form::Reals,
            Scalar::Other => Form::Vals,
        }
    }
    /// Whether a component of this form can hold `v`.
    #[inline(always)]
    fn holds<V: Component>(self, v: &V) -> bool {
        match (self, v.scalar()) {
            (Form::Vals, _) | (Form::Ints, Scalar::Int(_)) | (Form::Reals, Scalar::Real(_)) => true,
            (Form::Bytes, Scalar::Int(i)) => (0..=255).contains(&i),
            _ => false,
        }
    }
}

/// The size of a general component: the block's layout is computed
/// without the type (all `V` of one program are one type; adair's is 16).
const VAL_SIZE: usize = 16;

/// The head of an array's block; the bounds and then the components
/// follow it.
#[repr(C)]
struct Head {
    /// The number of [`Array`]s that point to the block. 32 bits: more
    /// than four thousand million copies of one array panic rather than
    /// wrap.
    count: Cell<u32>,
    form: Form,
    /// The number of dimensions, so of bound pairs.
    dims: u8,
    /// The number of components.
    len: usize,
    /// The room for components.
    cap: usize,
}

const HEAD: usize = std::mem::size_of::<Head>();
const BOUND: usize = std::mem::size_of::<Bound>();

/// The block of an array of this form, dimensions and room.
fn layout(form: Form, dims: usize, cap: usize) -> Layout {
    let size = cap
        .checked_mul(form.size())
        .and_then(|n| n.checked_add(HEAD + dims * BOUND))
        .expect("array too large");
    match Layout::from_size_align(size, 8) {
        Ok(l) => l.pad_to_align(),
        Err(_) => panic!("array too large"),
    }
}

/// The room for at least `need` components that fills the allocator's
/// block. `malloc` (glibc's) hands out blocks in steps of 16 bytes, 8 of
/// them its own header: the bytes up to the next step cost nothing, and an
/// array that grows into them (a string made by `&`, one piece after the
/// other) needs no new block.
fn room(form: Form, dims: usize, need: usize) -> usize {
    let size = layout(form, dims, need).size();
    let block = size.saturating_add(8 + 15) & !15;
    need + (block - 8 - size) / form.size()
}

/// An array value (see the module's note): a pointer to its one block.
pub struct Array<V: Component> {
    ptr: NonNull<Head>,
    /// It owns its components.
    _owns: PhantomData<V>,
}

/// An array's components, in row-major order, as a slice of their form.
#[derive(Debug)]
pub enum Elems<'a, V> {
    /// General values.
    Vals(&'a [V]),
    /// Discrete values in `0 ..= 255`.
    Bytes(&'a [u8]),
    /// Discrete values.
    Ints(&'a [i64]),
    /// Reals.
    Reals(&'a [f64]),
}

impl<V> Clone for Elems<'_, V> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<V> Copy for Elems<'_, V> {}

/// An array's components to change in place (they keep their form).
#[derive(Debug)]
pub enum ElemsMut<'a, V> {
    Vals(&'a mut [V]),
    Bytes(&'a mut [u8]),
    Ints(&'a mut [i64]),
    Reals(&'a mut [f64]),
}

impl<V: Component> Array<V> {
    /// The bytes of the block (what one copy of the array allocates).
    pub fn block_size(&self) -> usize {
        let h = self.head();
        layout(h.form, h.dims as usize, h.cap).size()
    }

    /// Whether two arrays share one block.
    pub fn same_block(&self, other: &Array<V>) -> bool {
        self.ptr == other.ptr
    }

    /// A new block, the only reference to it, with no components and
    /// `dims` bounds `(1, 0)`.
    fn alloc(form: Form, dims: usize, cap: usize) -> Array<V> {
        assert_eq!(
            std::mem::size_of::<V>(),
            VAL_SIZE,
            "a general value of 16 bytes"
        );
        assert!(
            std::mem::align_of::<V>() <= 8,
            "a general value aligned to at most 8"
        );
        assert!(dims <= 255, "an array of {dims} dimensions");
        let l = layout(form, dims, cap);
        // SAFETY: the layout's size is at least `HEAD`, never zero.
        let p = unsafe { alloc::alloc(l) }.cast::<Head>();
        let Some(ptr) = NonNull::new(p) else {
            alloc::handle_alloc_error(l)
        };
        // SAFETY: the block is `l`, large enough for the head and the
        // bounds, and aligned to 8.
        unsafe {
            p.write(Head {
                count: Cell::new(1),
                form,
                dims: dims as u8,
                len: 0,
                cap,
            });
            let b = p.cast::<u8>().add(HEAD).cast::<Bound>();
            for d in 0..dims {
                b.add(d).write((1, 0));
            }
        }
        Array {
            ptr,
            _owns: PhantomData,
        }
    }

    #[inline(always)]
    fn head(&self) -> &Head {
        // SAFETY: the block lives while an `Array` points to it.
        unsafe { self.ptr.as_ref() }
    }

    /// The head to change: only when this is the block's one reference.
    #[inline(always)]
    fn head_mut(&mut self) -> &mut Head {
        debug_assert_eq!(self.head().count.get(), 1);
        // SAFETY: no other `Array` points to the block (count 1) and
        // `self` is borrowed exclusively.
        unsafe { self.ptr.as_mut() }
    }

    #[inline(always)]
    fn base(&self) -> *mut u8 {
        self.ptr.as_ptr().cast::<u8>()
    }

    #[inline(always)]
    fn bounds_ptr(&self) -> *mut Bound {
        // SAFETY: the bounds follow the head in the block.
        unsafe { self.base().add(HEAD).cast::<Bound>() }
    }

    #[inline(always)]
    fn elems_ptr(&self) -> *mut u8 {
        // SAFETY: the components follow the bounds in the block.
        unsafe { self.base().add(HEAD + BOUND * self.head().dims as usize) }
    }

    /// How the components are stored.
    #[inline(always)]
    pub fn form(&self) -> Form {
        self.head().form
    }

    /// The bounds, one pair per dimension.
    #[inline(always)]
    pub fn bounds(&self) -> &[Bound] {
        // SAFETY: `dims` initialised pairs follow the head.
        unsafe { std::slice::from_raw_parts(self.bounds_ptr(), self.head().dims as usize) }
    }

    /// The components.
    #[inline(always)]
    pub fn data(&self) -> Elems<'_, V> {
        let h = self.head();
        let (p, n) = (self.elems_ptr(), h.len);
        // SAFETY: `len` initialised components of the block's form follow
        // the bounds, aligned to 8.
        unsafe {
            match h.form {
                Form::Bytes => Elems::Bytes(std::slice::from_raw_parts(p, n)),
                Form::Ints => Elems::Ints(std::slice::from_raw_parts(p.cast(), n)),
                Form::Reals => Elems::Reals(std::slice::from_raw_parts(p.cast(), n)),
                Form::Vals => Elems::Vals(std::slice::from_raw_parts(p.cast(), n)),
            }
        }
    }

    /// The components to change in place (the block made this array's own
    /// first).
    #[inline(always)]
    pub fn data_mut(&mut self) -> ElemsMut<'_, V> {
        self.make_mut();
        let (p, n, form) = (self.elems_ptr(), self.head().len, self.head().form);
        // SAFETY: as `data`, and the block is this array's alone.
        unsafe {
            match form {
                Form::Bytes => ElemsMut::Bytes(std::slice::from_raw_parts_mut(p, n)),
                Form::Ints => ElemsMut::Ints(std::slice::from_raw_parts_mut(p.cast(), n)),
                Form::Reals => ElemsMut::Reals(std::slice::from_raw_parts_mut(p.cast(), n)),
                Form::Vals => ElemsMut::Vals(std::slice::from_raw_parts_mut(p.cast(), n)),
            }
        }
    }

    /// Makes the block this array's own: a copy of it when it is shared.
    #[inline(always)]
    pub fn make_mut(&mut self) -> &mut Array<V> {
        if self.head().count.get() != 1 {
            *self = self.copy_with_room(0);
        }
        self
    }

    /// A new block with this array's bounds and components, and room for
    /// `more` besides.
    #[inline(never)]
    fn copy_with_room(&self, more: usize) -> Array<V> {
        let h = self.head();
        let (form, dims, len) = (h.form, h.dims as usize, h.len);
        let cap = match more {
            0 => len,
            _ => room(form, dims, len.saturating_add(more)),
        };
        let mut n = Array::alloc(form, dims, cap);
        // SAFETY: both blocks have `dims` bounds and room for `len`
        // components of `form`; `n` is new and its own.
        unsafe {
            ptr::copy_nonoverlapping(self.bounds_ptr(), n.bounds_ptr(), dims);
            n.write_from(0, self.data());
        }
        n
    }

    /// Appends `src` (of this array's form, and with room for it) at
    /// component `at` = the current length.
    ///
    /// # Safety
    /// The block is this array's own, its form is `src`'s, and it has room
    /// for `at + src.len()` components; `at` is its length.
    unsafe fn write_from(&mut self, at: usize, src: Elems<'_, V>) {
        // SAFETY: as the caller promised.
        unsafe {
            let p = self.elems_ptr();
            match src {
                Elems::Vals(v) => {
                    let dst = p.cast::<V>().add(at);
                    for (i, x) in v.iter().enumerate() {
                        dst.add(i).write(x.clone());
                        // Counted as it goes: a panicking clone leaks nothing
                        // and drops nothing twice.
                        self.head_mut().len = at + i + 1;
                    }
                }
                Elems::Bytes(b) => ptr::copy_nonoverlapping(b.as_ptr(), p.add(at), b.len()),
                Elems::Ints(v) => {
                    ptr::copy_nonoverlapping(v.as_ptr(), p.cast::<i64>().add(at), v.len())
                }
                Elems::Reals(v) => {
                    ptr::copy_nonoverlapping(v.as_ptr(), p.cast::<f64>().add(at), v.len())
                }
            }
            self.head_mut().len = at + src.len();
        }
    }

    /// Room for at least `need` components in all (the block its own).
    fn grow_to(&mut self, need: usize, amortized: bool) {
        let h = self.head();
        if h.count.get() != 1 {
            // A shared block: its copy is made with the room.
            let more = need.saturating_sub(h.len);
            *self = self.copy_with_room(more);
            return;
        }
        if need <= h.cap {
            return;
        }
        let (form, dims, cap) = (h.form, h.dims as usize, h.cap);
        let new_cap = if amortized {
            need.max(cap.saturating_mul(2)).max(4)
        } else {
            room(form, dims, need)
        };
        let old = layout(form, dims, cap);
        let new = layout(form, dims, new_cap);
        // SAFETY: the block was allocated with `old`; components are moved
        // bitwise, which every form allows.
        let p = unsafe { alloc::realloc(self.base(), old, new.size()) }.cast::<Head>();
        let Some(ptr) = NonNull::new(p) else {
            alloc::handle_alloc_error(new)
        };
        self.ptr = ptr;
        self.head_mut().cap = new_cap;
    }

    /// Room for `n` more components (that much, up to the allocator's
    /// block, when it must grow).
    pub fn reserve(&mut self, n: usize) {
        let need = self.len_all().saturating_add(n);
        self.grow_to(need, false);
    }

    /// The same bounds and components in `to`'s form (which must hold
    /// them all), with the same room.
    #[cold]
    #[inline(never)]
    fn convert(&mut self, to: Form) {
        let h = self.head();
        let (dims, len) = (h.dims as usize, h.len);
        let mut n = Array::alloc(to, dims, h.cap.max(len));
        // SAFETY: `n` is new, with `dims` bounds and room for `len`.
        unsafe {
            ptr::copy_nonoverlapping(self.bounds_ptr(), n.bounds_ptr(), dims);
            let p = n.elems_ptr();
            for (i, v) in self.data().iter().enumerate() {
                match to {
                    Form::Bytes => p.add(i).write(v.as_int() as u8),
                    Form::Ints => p.cast::<i64>().add(i).write(v.as_int()),
                    Form::Reals => p.cast::<f64>().add(i).write(v.as_real()),
                    Form::Vals => p.cast::<V>().add(i).write(v),
                }
                n.head_mut().len = i + 1;
            }
        }
        *self = n;
    }

    /// Makes the form hold `v` (widening it if it cannot).
    #[cold]
    fn widen_for(&mut self, v: &V) {
        let to = match (self.form(), v.scalar()) {
            _ if self.len_all() == 0 => Form::of(v),
            (Form::Bytes, Scalar::Int(_)) => Form::Ints,
            _ => Form::Vals,
        };
        self.convert(to);
    }

    /// The number of array values that share this one's block.
    pub fn ref_count(&self) -> usize {
        self.head().count.get() as usize
    }

    /// The number of components (of all dimensions).
    #[inline(always)]
    pub fn len_all(&self) -> usize {
        self.head().len
    }

    /// The length of dimension `dim`.
    pub fn len(&self, dim: usize) -> i64 {
        let (l, h) = self.bounds()[dim];
        (h - l + 1).max(0)
    }

    /// Offset of an index tuple, or `None` when out of bounds.
    #[inline]
    pub fn offset(&self, idx: &[i64]) -> Option<usize> {
        // The two common shapes first, without the loop.
        match (idx, self.bounds()) {
            (&[i], &[(l, h)]) => {
                return (l <= i && i <= h).then_some((i - l) as usize);
            }
            (&[i, j], &[(l0, h0), (l1, h1)]) => {
                return (l0 <= i && i <= h0 && l1 <= j && j <= h1)
                    .then_some(((i - l0) * (h1 - l1 + 1) + (j - l1)) as usize);
            }
            _ => {}
        }
        let mut off = 0i64;
        for (d, &i) in idx.iter().enumerate() {
            let (l, h) = *self.bounds().get(d)?;
            if i < l || i > h {
                return None;
            }
            off = off * self.len(d) + (i - l);
        }
        Some(off as usize)
    }

    /// Sets the bounds (their number may change; the components stay).
    pub fn set_bounds(&mut self, bounds: &[Bound]) {
        self.make_mut();
        if bounds.len() != self.head().dims as usize {
            let h = self.head();
            let (form, len, cap) = (h.form, h.len, h.cap);
            let mut n = Array::alloc(form, bounds.len(), cap);
            // SAFETY: the components move bitwise to the new block, which
            // has room for them; the old one then holds none, and is freed
            // without dropping them.
            unsafe {
                ptr::copy_nonoverlapping(self.elems_ptr(), n.elems_ptr(), len * form.size());
                n.head_mut().len = len;
                self.head_mut().len = 0;
            }
            *self = n;
        }
        let p = self.bounds_ptr();
        for (d, b) in bounds.iter().enumerate() {
            // SAFETY: the block is this array's own, with room for the
            // pairs.
            unsafe { p.add(d).write(*b) };
        }
    }

    /// This array with these bounds.
    pub fn with_bounds(mut self, bounds: &[Bound]) -> Array<V> {
        self.set_bounds(bounds);
        self
    }

    /// A one-dimensional array of these components, from `first` on.
    pub fn vector(first: i64, mut data: Array<V>) -> Array<V> {
        let last = first + data.len_all() as i64 - 1;
        data.set_bounds(&[(first, last)]);
        data
    }

    /// An empty one-dimensional array of this form, with room for `n`.
    pub fn with_capacity(form: Form, n: usize) -> Array<V> {
        Array::alloc(form, 1, n)
    }

    /// An empty array of this form and number of dimensions, with room
    /// for `n` (its bounds set later, without moving its components).
    pub fn with_capacity_dims(form: Form, dims: usize, n: usize) -> Array<V> {
        Array::alloc(form, dims, n)
    }

    /// A one-dimensional array, from `first` on, of a copy of these
    /// components (in their form).
    pub fn from_elems(first: i64, src: Elems<'_, V>) -> Array<V> {
        let mut a = Array::alloc(src.form(), 1, src.len());
        // SAFETY: `a` is new, of `src`'s form, with room for it.
        unsafe {
            a.write_from(0, src);
            a.bounds_ptr().write((first, first + src.len() as i64 - 1));
        }
        a
    }

    /// Components from general values, in the narrowest form that holds
    /// them, from 1 on.
    pub fn from_vals(vals: Vec<V>) -> Array<V> {
        let form = if vals.iter().all(|v| Form::Bytes.holds(v)) {
            Form::Bytes
        } else if vals.iter().all(|v| matches!(v.scalar(), Scalar::Int(_))) {
            Form::Ints
        } else if vals.iter().all(|v| matches!(v.scalar(), Scalar::Real(_))) {
            Form::Reals
        } else {
            Form::Vals
        };
        let mut a = Array::alloc(form, 1, vals.len());
        let p = a.elems_ptr();
        for (i, v) in vals.into_iter().enumerate() {
            // SAFETY: room for `vals.len()` of `form`, which holds each.
            unsafe {
                match form {
                    Form::Bytes => p.add(i).write(v.as_int() as u8),
                    Form::Ints => p.cast::<i64>().add(i).write(v.as_int()),
                    Form::Reals => p.cast::<f64>().add(i).write(v.as_real()),
                    Form::Vals => p.cast::<V>().add(i).write(v),
                }
            }
            a.head_mut().len = i + 1;
        }
        let n = a.len_all() as i64;
        a.set_bounds(&[(1, n)]);
        a
    }

    /// `n` copies of `v`, from 1 on.
    pub fn repeat(v: V, n: usize) -> Array<V> {
        Array::repeat_in(v, n, &[(1, n as i64)])
    }

    /// `n` copies of `v`, with these bounds (which must hold `n`).
    pub fn repeat_in(v: V, n: usize, bounds: &[Bound]) -> Array<V> {
        let form = Form::of(&v);
        let mut a = Array::alloc(form, bounds.len(), n);
        let p = a.elems_ptr();
        // SAFETY: room for `n` of `form`. The writes follow `form`, not a
        // second answer of `v.scalar()` (a safe trait: two answers may
        // differ, and reals written into bytes would pass the block's end).
        unsafe {
            match form {
                Form::Bytes => ptr::write_bytes(p, v.as_int() as u8, n),
                Form::Ints => {
                    let i = v.as_int();
                    (0..n).for_each(|k| p.cast::<i64>().add(k).write(i))
                }
                Form::Reals => {
                    let x = v.as_real();
                    (0..n).for_each(|k| p.cast::<f64>().add(k).write(x))
                }
                Form::Vals => {
                    for k in 0..n {
                        p.cast::<V>().add(k).write(v.clone());
                        a.head_mut().len = k + 1;
                    }
                }
            }
        }
        a.head_mut().len = n;
        a.set_bounds(bounds);
        a
    }

    /// A `String` of these characters.
    pub fn string(s: &str) -> Array<V> {
        if s.is_ascii() {
            Array::from_elems(1, Elems::Bytes(s.as_bytes()))
        } else {
            s.chars().map(|c| V::from_int(c as i64)).collect()
        }
    }

    pub fn to_string_lossy(&self) -> String {
        match self.data() {
            Elems::Bytes(b) => b.iter().map(|&c| c as char).collect(),
            other => other
                .iter()
                .map(|v| match v.scalar() {
                    Scalar::Int(c) => char::from_u32(c as u32).unwrap_or('?'),
                    _ => '?',
                })
                .collect(),
        }
    }

    /// Component `i` to change in place (a compact array becomes general
    /// values: for a composite component's parts, which compact arrays
    /// never have).
    #[inline]
    pub fn get_mut(&mut self, i: usize) -> &mut V {
        if self.form() != Form::Vals {
            self.convert(Form::Vals);
        }
        match self.data_mut() {
            ElemsMut::Vals(v) => &mut v[i],
            _ => unreachable!("turned into values above"),
        }
    }

    /// Sets component `i` (which must exist).
    #[inline(always)]
    pub fn set(&mut self, i: usize, v: V) {
        if !self.form().holds(&v) {
            self.widen_for(&v);
        }
        match self.data_mut() {
            ElemsMut::Vals(vs) => V::overwrite(&mut vs[i], v),
            ElemsMut::Bytes(b) => b[i] = v.as_int() as u8,
            ElemsMut::Ints(vs) => vs[i] = v.as_int(),
            ElemsMut::Reals(vs) => vs[i] = v.as_real(),
        }
    }

    /// Appends a component.
    pub fn push(&mut self, v: V) {
        if !self.form().holds(&v) {
            self.widen_for(&v);
        }
        let len = self.len_all();
        self.grow_to(len + 1, true);
        let p = self.elems_ptr();
        // SAFETY: the block is this array's own (`grow_to`), with room for
        // one more component, of a form that holds `v`.
        unsafe {
            match self.form() {
                Form::Bytes => p.add(len).write(v.as_int() as u8),
                Form::Ints => p.cast::<i64>().add(len).write(v.as_int()),
                Form::Reals => p.cast::<f64>().add(len).write(v.as_real()),
                Form::Vals => p.cast::<V>().add(len).write(v),
            }
        }
        self.head_mut().len = len + 1;
    }

    /// Appends `other`'s components. An empty array takes `other`'s form,
    /// keeping its own room.
    pub fn extend_from(&mut self, other: Elems<'_, V>) {
        if other.is_empty() {
            return;
        }
        let len = self.len_all();
        if len == 0 && self.form() != other.form() {
            self.make_mut();
            self.convert(other.form());
        }
        if self.form() == other.form() {
            self.grow_to(len + other.len(), false);
            // SAFETY: own block, same form, room for both.
            unsafe { self.write_from(len, other) };
        } else {
            self.reserve(other.len());
            for v in other.iter() {
                self.push(v);
            }
        }
    }

    /// Copies `src`'s components over those from `at` on.
    pub fn copy_from(&mut self, at: usize, src: Elems<'_, V>) {
        match (self.data_mut(), src) {
            (ElemsMut::Bytes(a), Elems::Bytes(b)) => a[at..at + b.len()].copy_from_slice(b),
            (ElemsMut::Ints(a), Elems::Ints(b)) => a[at..at + b.len()].copy_from_slice(b),
            (ElemsMut::Reals(a), Elems::Reals(b)) => a[at..at + b.len()].copy_from_slice(b),
            (ElemsMut::Vals(a), Elems::Vals(b)) => a[at..at + b.len()].clone_from_slice(b),
            _ => {
                for (k, v) in src.iter().enumerate() {
                    self.set(at + k, v);
                }
            }
        }
    }

    /// The components as general values, moved out when no one else
    /// holds them.
    pub fn into_vals(mut self) -> Vec<V> {
        if self.form() != Form::Vals || self.head().count.get() != 1 {
            return self.data().iter().collect();
        }
        let len = self.len_all();
        let p = self.elems_ptr().cast::<V>();
        // SAFETY: the block is this array's alone; its `len` values are
        // read out once, and it then holds none (and is freed without
        // dropping them).
        let out = (0..len).map(|i| unsafe { p.add(i).read() }).collect();
        self.head_mut().len = 0;
        out
    }

    /// Frees the block (the last reference went).
    #[cold]
    #[inline(never)]
    fn drop_slow(&mut self) {
        let h = self.head();
        let (form, dims, len, cap) = (h.form, h.dims as usize, h.len, h.cap);
        // SAFETY: this was the last reference; the block's `len` values
        // are dropped once, and it was allocated with this layout.
        unsafe {
            if form == Form::Vals {
                let p = self.elems_ptr().cast::<V>();
                ptr::drop_in_place(ptr::slice_from_raw_parts_mut(p, len));
            }
            alloc::dealloc(self.base(), layout(form, dims, cap));
        }
    }
}

impl<V: Component> Clone for Array<V> {
    /// One more reference to the same block.
    #[inline(always)]
    fn clone(&self) -> Array<V> {
        let c = &self.head().count;
        let n = c.get().checked_add(1).expect("too many copies of an array");
        c.set(n);
        Array {
            ptr: self.ptr,
            _owns: PhantomData,
        }
    }
}

impl<V: Component> Drop for Array<V> {
    #[inline(always)]
    fn drop(&mut self) {
        let c = self.head().count.get();
        if c == 1 {
            self.drop_slow();
        } else {
            self.head().count.set(c - 1);
        }
    }
}

impl<V: Component> Default for Array<V> {
    /// An empty one-dimensional array of bytes.
    fn default() -> Array<V> {
        Array::with_capacity(Form::Bytes, 0)
    }
}

impl<V: Component + std::fmt::Debug> std::fmt::Debug for Array<V> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Array")
            .field("bounds", &self.bounds())
            .field("data", &self.data())
            .finish()
    }
}

impl<V: Component> PartialEq for Array<V> {
    fn eq(&self, other: &Array<V>) -> bool {
        self.bounds() == other.bounds() && self.data() == other.data()
    }
}

impl<V: Component> FromIterator<V> for Array<V> {
    fn from_iter<I: IntoIterator<Item = V>>(it: I) -> Self {
        Array::from_vals(it.into_iter().collect())
    }
}

impl<'a, V: Component> Elems<'a, V> {
    /// How these components are stored.
    #[inline]
    pub fn form(self) -> Form {
        match self {
            Elems::Vals(_) => Form::Vals,
            Elems::Bytes(_) => Form::Bytes,
            Elems::Ints(_) => Form::Ints,
            Elems::Reals(_) => Form::Reals,
        }
    }

    #[inline]
    pub fn len(self) -> usize {
        match self {
            Elems::Vals(v) => v.len(),
            Elems::Bytes(b) => b.len(),
            Elems::Ints(v) => v.len(),
            Elems::Reals(v) => v.len(),
        }
    }

    #[inline]
    pub fn is_empty(self) -> bool {
        self.len() == 0
    }

    /// Component `i` (which must exist).
    #[inline(always)]
    pub fn get(self, i: usize) -> V {
        match self {
            Elems::Vals(v) => v[i].clone(),
            Elems::Bytes(b) => V::from_int(b[i] as i64),
            Elems::Ints(v) => V::from_int(v[i]),
            Elems::Reals(v) => V::from_real(v[i]),
        }
    }

    /// Component `i` as an integer, without building a value.
    #[inline(always)]
    pub fn int(self, i: usize) -> i64 {
        match self {
            Elems::Vals(v) => v[i].as_int(),
            Elems::Bytes(b) => b[i] as i64,
            Elems::Ints(v) => v[i],
            Elems::Reals(v) => v[i] as i64,
        }
    }

    /// Component `i` as a real.
    #[inline(always)]
    pub fn real(self, i: usize) -> f64 {
        match self {
            Elems::Vals(v) => v[i].as_real(),
            Elems::Bytes(b) => b[i] as f64,
            Elems::Ints(v) => v[i] as f64,
            Elems::Reals(v) => v[i],
        }
    }

    /// Component `i` as a general value, if it is stored as one (a
    /// composite component always is).
    #[inline(always)]
    pub fn val(self, i: usize) -> Option<&'a V> {
        match self {
            Elems::Vals(v) => Some(&v[i]),
            _ => None,
        }
    }

    /// Components `range`, in the same form.
    pub fn slice(self, range: std::ops::Range<usize>) -> Elems<'a, V> {
        match self {
            Elems::Vals(v) => Elems::Vals(&v[range]),
            Elems::Bytes(b) => Elems::Bytes(&b[range]),
            Elems::Ints(v) => Elems::Ints(&v[range]),
            Elems::Reals(v) => Elems::Reals(&v[range]),
        }
    }

    /// The components as values, in order.
    pub fn iter(self) -> impl Iterator<Item = V> + 'a {
        (0..self.len()).map(move |i| self.get(i))
    }

    /// The bytes, when the array is stored as bytes.
    pub fn bytes(self) -> Option<&'a [u8]> {
        match self {
            Elems::Bytes(b) => Some(b),
            _ => None,
        }
    }
}

impl<V: Component> PartialEq for Elems<'_, V> {
    fn eq(&self, other: &Elems<'_, V>) -> bool {
        match (*self, *other) {
            (Elems::Bytes(a), Elems::Bytes(b)) => a == b,
            (Elems::Ints(a), Elems::Ints(b)) => a == b,
            (Elems::Reals(a), Elems::Reals(b)) => a == b,
            (Elems::Vals(a), Elems::Vals(b)) => a == b,
            (a, b) => a.len() == b.len() && a.iter().zip(b.iter()).all(|(x, y)| x == y),
        }
    }
}

#[cfg(test)]
mod tests;
