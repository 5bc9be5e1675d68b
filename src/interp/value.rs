//! Run-time values and GNAT-exact text forms of scalars.

use crate::check::ir::{ExcId, FloatOp};
use crate::diag::Span;
use std::cell::{Cell, RefCell};
use std::rc::Rc;

/// A record's shared storage: a reference count without a weak count
/// (records are never weakly referenced), so that a record of two
/// components (a list node) takes 40 bytes, a 48-byte block of the
/// allocator, not 48 bytes and a 64-byte block (`tests/value_memory.rs`).
/// Its count is 32 bits: more than four thousand million copies of one
/// record (64 GiB of values holding it) panic rather than wrap.
pub type Shared<T> = rclite::Rc<T>;

/// A value. Discrete values (integers, enumerations, characters, Booleans)
/// are `Int`; composites are reference-counted and copied on write, which
/// gives Ada's value semantics without copying on every read.
///
/// A record is one allocation holding its reference count and its
/// components inline: `Rec1` .. `Rec8` by the number of components (a
/// list node, a 3D point, a frame), `RecN` for none or more than eight
/// (its components in a second allocation). Code reads a record through
/// [`Value::fields`] and writes one through [`Value::fields_mut`] (copy on
/// write) and builds one with [`Value::record`]; it never names the
/// variants. The count is in the variant, not in a field, so `Value` stays
/// 16 bytes and a match on it stays a plain jump on its tag (an enum of
/// records nested in `Value` costs every match an offset computation).
#[derive(Debug, Default)]
pub enum Value {
    #[default]
    Undef,
    Int(i64),
    Real(f64),
    Arr(Array),
    Ptr(Option<Obj>),
    Occ(Rc<Occurrence>),
    Rec1(Shared<[Value; 1]>),
    Rec2(Shared<[Value; 2]>),
    Rec3(Shared<[Value; 3]>),
    Rec4(Shared<[Value; 4]>),
    Rec5(Shared<[Value; 5]>),
    Rec6(Shared<[Value; 6]>),
    Rec7(Shared<[Value; 7]>),
    Rec8(Shared<[Value; 8]>),
    RecN(Shared<Vec<Value>>),
}

/// `$body` for each record variant of `$v`, its `Rc` bound to `$r`;
/// `$other` for any other value.
macro_rules! each_record {
    ($v:expr, $r:ident => $body:expr, _ => $other:expr) => {
        match $v {
            Value::Rec1($r) => $body,
            Value::Rec2($r) => $body,
            Value::Rec3($r) => $body,
            Value::Rec4($r) => $body,
            Value::Rec5($r) => $body,
            Value::Rec6($r) => $body,
            Value::Rec7($r) => $body,
            Value::Rec8($r) => $body,
            Value::RecN($r) => $body,
            _ => $other,
        }
    };
}

impl Clone for Value {
    /// Scalars, arrays and access values inline; a record's clone (one
    /// reference count, whichever its variant) out of line, so that the
    /// engine's every copy of a value stays small.
    #[inline]
    fn clone(&self) -> Value {
        match self {
            Value::Undef => Value::Undef,
            Value::Int(i) => Value::Int(*i),
            Value::Real(x) => Value::Real(*x),
            Value::Arr(a) => Value::Arr(a.clone()),
            Value::Ptr(p) => Value::Ptr(p.clone()),
            _ => self.clone_other(),
        }
    }
}

impl Value {
    #[inline(never)]
    fn clone_other(&self) -> Value {
        match self {
            Value::Occ(o) => Value::Occ(o.clone()),
            Value::Rec1(r) => Value::Rec1(r.clone()),
            Value::Rec2(r) => Value::Rec2(r.clone()),
            Value::Rec3(r) => Value::Rec3(r.clone()),
            Value::Rec4(r) => Value::Rec4(r.clone()),
            Value::Rec5(r) => Value::Rec5(r.clone()),
            Value::Rec6(r) => Value::Rec6(r.clone()),
            Value::Rec7(r) => Value::Rec7(r.clone()),
            Value::Rec8(r) => Value::Rec8(r.clone()),
            Value::RecN(r) => Value::RecN(r.clone()),
            Value::Undef | Value::Int(_) | Value::Real(_) | Value::Arr(_) | Value::Ptr(_) => {
                unreachable!("cloned inline")
            }
        }
    }

    /// A record value of `n` components, the `k`th `next(k)`, in order
    /// (one allocation for up to eight; nothing built on the way).
    #[inline]
    pub fn record_of(n: usize, mut next: impl FnMut(usize) -> Value) -> Value {
        use std::array::from_fn;
        match n {
            1 => Value::Rec1(Shared::new(from_fn(&mut next))),
            2 => Value::Rec2(Shared::new(from_fn(&mut next))),
            3 => Value::Rec3(Shared::new(from_fn(&mut next))),
            4 => Value::Rec4(Shared::new(from_fn(&mut next))),
            5 => Value::Rec5(Shared::new(from_fn(&mut next))),
            6 => Value::Rec6(Shared::new(from_fn(&mut next))),
            7 => Value::Rec7(Shared::new(from_fn(&mut next))),
            8 => Value::Rec8(Shared::new(from_fn(&mut next))),
            _ => Value::RecN(Shared::new((0..n).map(next).collect())),
        }
    }
    /// A record value of these components (one allocation for up to
    /// eight).
    pub fn record(mut v: Fields) -> Value {
        let n = v.len();
        let mut parts = v.drain(..);
        Value::record_of(n, |_| parts.next().unwrap_or_default())
    }
    /// A record's components, `None` for any other value.
    #[inline]
    pub fn fields(&self) -> Option<&[Value]> {
        each_record!(self, r => Some(&r[..]), _ => None)
    }
    /// A record's components to write, copied first when the record is
    /// shared (`Rc::make_mut`); `None` for any other value.
    #[inline]
    pub fn fields_mut(&mut self) -> Option<&mut [Value]> {
        each_record!(self, r => Some(&mut Shared::make_mut(r)[..]), _ => None)
    }
    /// Whether this is a record value.
    #[inline]
    pub fn is_record(&self) -> bool {
        self.fields().is_some()
    }
}

/// `*slot = v` without a call of the drop glue when the old value owns
/// nothing (an `Undef`, `Int` or `Real`): the compiler calls the glue even
/// after a match has shown the variant, and the engine writes slots in
/// every instruction.
#[inline(always)]
pub fn overwrite(slot: &mut Value, v: Value) {
    if matches!(slot, Value::Undef | Value::Int(_) | Value::Real(_)) {
        // Forgetting a scalar leaks nothing.
        std::mem::forget(std::mem::replace(slot, v));
    } else {
        *slot = v;
    }
}

/// A record's components while it is built (on the native stack for up
/// to eight), made a value by [`Value::record`].
pub type Fields = smallvec::SmallVec<[Value; 8]>;

pub use crate::check::types::Variant;

/// Whether a record value's discriminants choose a variant (RM 3.8.1):
/// each condition (discriminant index, its values) holds. A component of a
/// variant not chosen does not exist: reading or writing it is
/// `Constraint_Error` ("discriminant check failed").
pub fn variant_holds(fields: &[Value], conds: &[crate::check::types::Governs]) -> bool {
    conds.iter().all(|(d, ranges)| {
        let x = fields.get(*d as usize).map_or(i64::MIN, Value::int);
        ranges.iter().any(|(l, h)| *l <= x && x <= *h)
    })
}

/// An object made by an allocator (`new`), which access values designate.
///
/// Its value sits in a `Cell` behind a reference count without a weak
/// count ([`Shared`]): 24 bytes, a 32-byte block of the allocator (std's
/// `Rc<RefCell<Value>>` took 40 bytes, a 48-byte block), so a list node
/// and its record take 64 bytes, 80 of the allocator's blocks, where they
/// took 88 in 112 (`tests/value_memory.rs`).
/// Code reads the value with [`Obj::get`] or [`Obj::with`] and writes it
/// with [`Obj::set`] or [`Obj::update`]; while `with`'s or `update`'s
/// function runs, the object holds `Undef`, so that function must not
/// reach the same object again (none does: they read or write a
/// component of the value handed to them).
///
/// When the last access value to an object goes, the object's value is
/// dropped without recursion: the objects it reaches are queued and dropped
/// one after the other, so that a long linked list is freed in constant
/// native stack (a recursive drop of a few million nodes overflowed it).
#[derive(Clone)]
pub struct Obj(Shared<Cell<Value>>);

impl Obj {
    pub fn new(v: Value) -> Obj {
        Obj(Shared::new(Cell::new(v)))
    }
    /// A copy of the object's value (a reference count for a composite).
    #[inline]
    pub fn get(&self) -> Value {
        self.with(Value::clone)
    }
    /// `f` of the object's value (see the type's note: `f` must not reach
    /// this object). Should `f` panic (an interpreter bug), the object is
    /// left `Undef`.
    #[inline]
    pub fn with<R>(&self, f: impl FnOnce(&Value) -> R) -> R {
        let v = self.0.take();
        let r = f(&v);
        self.put_back(v);
        r
    }
    /// `f` of the object's value to change in place (see [`Obj::with`]).
    #[inline]
    pub fn update<R>(&self, f: impl FnOnce(&mut Value) -> R) -> R {
        let mut v = self.0.take();
        let r = f(&mut v);
        self.put_back(v);
        r
    }
    /// Puts a taken value back. The object held `Undef` meanwhile: nothing
    /// to drop, and no call of the drop glue (which the engine's reads
    /// would pay for; a guard that put the value back on unwinding cost
    /// one such call per read).
    #[inline]
    fn put_back(&self, v: Value) {
        let held = self.0.replace(v);
        if matches!(held, Value::Undef) {
            std::mem::forget(held);
        } else {
            drop(held);
        }
    }
    /// Makes `v` the object's value.
    #[inline]
    pub fn set(&self, v: Value) {
        drop(self.0.replace(v));
    }
    /// Whether two access values designate the same object.
    #[inline]
    pub fn same(&self, other: &Obj) -> bool {
        Shared::ptr_eq(&self.0, &other.0)
    }
    /// The object's address, which names it while it lives.
    #[inline]
    pub fn addr(&self) -> *const () {
        Shared::as_ptr(&self.0).cast()
    }
}

impl std::fmt::Debug for Obj {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.with(|v| f.debug_tuple("Obj").field(v).finish())
    }
}

thread_local! {
    /// While an object's value is being dropped: the values of the objects
    /// whose last access it held, to drop after it.
    static DROPPING: RefCell<Option<Vec<Value>>> = const { RefCell::new(None) };
}

impl Drop for Obj {
    fn drop(&mut self) {
        if Shared::strong_count(&self.0) != 1 {
            return;
        }
        let v = self.0.take();
        if matches!(v, Value::Undef | Value::Int(_) | Value::Real(_)) {
            // Owns nothing.
            std::mem::forget(v);
            return;
        }
        // Queued when a drop is under way (this object was reached from the
        // value being dropped); otherwise this drop drains the queue.
        let mine = DROPPING.try_with(|d| {
            let mut q = d.borrow_mut();
            match q.as_mut() {
                Some(queue) => {
                    queue.push(v);
                    None
                }
                None => {
                    *q = Some(Vec::new());
                    Some(v)
                }
            }
        });
        let Ok(Some(v)) = mine else {
            // Queued, or the thread is ending: `v` drops here.
            return;
        };
        drop(v);
        while let Some(next) = DROPPING.with(|d| d.borrow_mut().as_mut().and_then(Vec::pop)) {
            drop(next);
        }
        DROPPING.with(|d| *d.borrow_mut() = None);
    }
}

pub use super::elems::{Array, Bound, ByteVec, Elems, ElemsMut, Form};

/// An array's bounds while they are computed, one pair per dimension.
pub type Bounds = smallvec::SmallVec<[Bound; 1]>;

/// Whether two access values are equal: both null, or designating the
/// same object (`Value`'s `==`, and the inner loop's `P /= null`).
#[inline(always)]
pub fn same_access(a: &Option<Obj>, b: &Option<Obj>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(x), Some(y)) => x.same(y),
        _ => false,
    }
}

impl PartialEq for Value {
    fn eq(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Int(a), Value::Int(b)) => a == b,
            (Value::Real(a), Value::Real(b)) => a == b,
            (Value::Arr(a), Value::Arr(b)) => {
                // Ada: arrays are equal when lengths and components match (bounds may differ).
                a.len_all() == b.len_all()
                    && (0..a.bounds().len()).all(|d| a.len(d) == b.len(d))
                    && a.data() == b.data()
            }
            (Value::Ptr(a), Value::Ptr(b)) => same_access(a, b),
            (Value::Undef, Value::Undef) => true,
            (a, b) => match (a.fields(), b.fields()) {
                (Some(a), Some(b)) => a == b,
                _ => false,
            },
        }
    }
}

impl Value {
    pub fn str(s: &str) -> Value {
        Value::Arr(Array::string(s))
    }
    /// A `String` value of this text.
    pub fn string(s: String) -> Value {
        Value::str(&s)
    }
    pub fn int(&self) -> i64 {
        match self {
            Value::Int(i) => *i,
            Value::Real(r) => *r as i64,
            _ => 0,
        }
    }
    pub fn real(&self) -> f64 {
        match self {
            Value::Real(r) => *r,
            Value::Int(i) => *i as f64,
            _ => 0.0,
        }
    }
    pub fn text(&self) -> String {
        match self {
            Value::Arr(a) => a.to_string_lossy(),
            _ => String::new(),
        }
    }
    /// Ordering of scalars and of one-dimensional discrete arrays (strings).
    pub fn compare(&self, other: &Value) -> std::cmp::Ordering {
        use std::cmp::Ordering;
        match (self, other) {
            (Value::Int(a), Value::Int(b)) => a.cmp(b),
            (Value::Real(a), Value::Real(b)) => a.partial_cmp(b).unwrap_or(Ordering::Equal),
            (Value::Arr(a), Value::Arr(b)) => {
                if let (Some(x), Some(y)) = (a.data().bytes(), b.data().bytes()) {
                    return x.cmp(y);
                }
                for (x, y) in a.data().iter().zip(b.data().iter()) {
                    let c = x.compare(&y);
                    if c != Ordering::Equal {
                        return c;
                    }
                }
                a.len_all().cmp(&b.len_all())
            }
            _ => Ordering::Equal,
        }
    }
}

/// An exception occurrence: which exception, its message, where it was raised
/// and the call chain (innermost call first).
#[derive(Clone, Debug, PartialEq)]
pub struct Occurrence {
    pub exc: ExcId,
    pub message: String,
    pub span: Span,
    pub chain: Vec<Span>,
    /// Where a handler re-raised it (`raise;`), first first.
    pub reraised: Vec<Span>,
    /// `chain` is whole. An occurrence raised in code the compiled engine
    /// runs holds only the calls of natives in progress until the engine
    /// adds its frames' calls (it keeps them in its frames, not in `Machine::calls`).
    pub chained: bool,
    /// How the run ends if nothing handles it.
    pub ending: Ending,
}

/// What an occurrence that leaves the program is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Ending {
    /// An exception no handler caught.
    #[default]
    Exception,
    /// Every task blocked (the message names each and what it waits for).
    Deadlock,
    /// The user stopped the run (Ctrl-C) while tasks ran.
    Stopped,
}

/// `Integer'Image`: a leading blank for non-negative values.
pub fn image_int(v: i64) -> String {
    image_int_bytes(v).into_iter().map(char::from).collect()
}

/// `Integer'Image (v)` as bytes: a sign or a space, then the digits.
pub fn image_int_bytes(v: i64) -> ByteVec {
    let mut digits = [0u8; 20];
    let mut n = v.unsigned_abs();
    let mut i = digits.len();
    loop {
        i -= 1;
        digits[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    let mut out = ByteVec::new();
    out.push(if v < 0 { b'-' } else { b' ' });
    out.extend_from_slice(&digits[i..]);
    out
}

/// Decimal digits of |x| rounded half away from zero at `frac` digits after
/// the point when `sci` is false, or with `frac` digits after the first
/// significant digit when `sci` is true. Returns (digits, exponent of the
/// first digit). Rust's own formatting rounds ties to even, so the rounding is
/// done here on an exact-enough expansion.
fn round_digits(x: f64, frac: usize, sci: bool) -> (Vec<u8>, i32) {
    let x = x.abs();
    if x == 0.0 {
        return (vec![0; frac + 1], 0);
    }
    let s = format!("{x:.70e}");
    let (mant, exp) = s.split_once('e').unwrap_or((&s, "0"));
    let mut exp: i32 = exp.parse().unwrap_or(0);
    let mut digits: Vec<u8> = mant
        .bytes()
        .filter(u8::is_ascii_digit)
        .map(|b| b - b'0')
        .collect();
    // Number of digits to keep.
    let keep: i64 = if sci {
        frac as i64 + 1
    } else {
        exp as i64 + 1 + frac as i64
    };
    if keep < 0 {
        return (vec![0; frac + 1], 0);
    }
    let keep = keep as usize;
    let round_up = digits.get(keep).is_some_and(|d| *d >= 5);
    digits.truncate(keep);
    while digits.len() < keep {
        digits.push(0);
    }
    if round_up {
        let mut i = digits.len();
        loop {
            if i == 0 {
                digits.insert(0, 1);
                exp += 1;
                if sci {
                    digits.pop();
                }
                break;
            }
            i -= 1;
            if digits[i] == 9 {
                digits[i] = 0;
            } else {
                digits[i] += 1;
                break;
            }
        }
    }
    if keep == 0 && !round_up {
        return (vec![0; frac + 1], 0);
    }
    (digits, exp)
}

/// `Ada.Float_Text_IO.Put (Item, Fore, Aft, Exp)` as GNAT prints it.
pub fn put_float(x: f64, fore: usize, aft: usize, exp: usize) -> String {
    let aft = aft.max(1);
    let neg = x.is_sign_negative() && !x.is_nan();
    // GNAT: the text at the left of the whole field, the rest `*`.
    if !x.is_finite() {
        let s = match (x.is_nan(), neg) {
            (true, _) => "NaN",
            (false, true) => "-Inf",
            (false, false) => "+Inf",
        };
        let width = fore + aft + 1 + if exp > 0 { exp + 1 } else { 0 };
        return format!("{s:*<width$}");
    }
    let mut body = String::new();
    if exp > 0 {
        let (digits, e) = round_digits(x, aft, true);
        let e = if x == 0.0 { 0 } else { e };
        body.push((b'0' + digits[0]) as char);
        body.push('.');
        for d in &digits[1..] {
            body.push((b'0' + d) as char);
        }
        let ed = format!("{}", e.abs());
        let width = exp.saturating_sub(1).max(1);
        body.push('E');
        body.push(if e < 0 { '-' } else { '+' });
        for _ in ed.len()..width {
            body.push('0');
        }
        body.push_str(&ed);
        let int = if neg {
            format!("-{}", &body[..1])
        } else {
            body[..1].to_string()
        };
        format!("{}{}", pad_left(&int, fore), &body[1..])
    } else {
        let (mut digits, e) = round_digits(x, aft, false);
        while digits.len() < aft + 1 {
            digits.insert(0, 0);
        }
        // digits hold the integer part (e + 1 digits, or a leading 0) and `aft` fraction digits.
        let int_len = digits.len() - aft;
        let (ip, fp) = digits.split_at(int_len);
        let mut int: String = ip.iter().map(|d| (b'0' + d) as char).collect();
        if int.is_empty() {
            int.push('0');
        }
        let _ = e;
        let int = if neg { format!("-{int}") } else { int };
        let frac: String = fp.iter().map(|d| (b'0' + d) as char).collect();
        format!("{}.{}", pad_left(&int, fore), frac)
    }
}

/// `Float'Image` (GNAT, Float'Digits = 6): `" 8.30600E+02"`.
pub fn image_float(x: f64) -> String {
    image_float_digits(x, 6)
}

/// `T'Image` of a floating point type of `digits` decimal digits: that
/// many significant digits (`digits 3`: `" 3.14E+00"`).
pub fn image_float_digits(x: f64, digits: u32) -> String {
    let s = put_float(x, 1, digits.max(1) as usize - 1, 3);
    // GNAT: `+Inf*******`, `NaN********` without the blank of a sign.
    if s.starts_with('-') || !x.is_finite() {
        s
    } else {
        format!(" {s}")
    }
}

/// `Duration'Image`: GNAT's Duration is a 64-bit count of nanoseconds
/// (`Duration'Small` = 1 ns), so the value is rounded to whole nanoseconds
/// within that range: `" 11.000000000"`, `" 9223372036.854775807"`.
pub fn image_duration(x: f64) -> String {
    // `as` saturates at i64's bounds (and takes NaN to 0).
    let ns = (x * 1e9).round() as i64;
    let sign = if ns < 0 { '-' } else { ' ' };
    let a = ns.unsigned_abs();
    format!("{sign}{}.{:09}", a / 1_000_000_000, a % 1_000_000_000)
}

pub fn pad_left(s: &str, width: usize) -> String {
    let n = s.chars().count();
    if n >= width {
        s.to_string()
    } else {
        format!("{}{}", " ".repeat(width - n), s)
    }
}

/// `Integer'Value`: blanks around, an optional sign, Ada literal syntax
/// (underscores, based literals, exponents).
pub fn value_int(s: &str) -> Option<i64> {
    let t = s.trim_matches(|c: char| c == ' ' || c == '\t');
    let (neg, body) = match t.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, t.strip_prefix('+').unwrap_or(t)),
    };
    match crate::syntax::lexer::numeric_literal(body)? {
        crate::syntax::token::Token::Int(v) => {
            let v = if neg { -v.get() } else { v.get() };
            i64::try_from(v).ok()
        }
        _ => None,
    }
}

/// `Float'Value`: as [`value_int`], and as GNAT also a point with no
/// digit on one side (`.5`, `5.`, `16#.8#`), never on both.
pub fn value_float(s: &str) -> Option<f64> {
    let t = s.trim_matches(|c: char| c == ' ' || c == '\t');
    let (neg, body) = match t.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, t.strip_prefix('+').unwrap_or(t)),
    };
    // (In a based literal `E` is a digit; elsewhere it starts an exponent.)
    let based = body.contains('#');
    let digit = |c: Option<char>| {
        c.is_some_and(|c| c.is_ascii_digit() || (based && c.is_ascii_alphanumeric()))
    };
    let mut full = String::with_capacity(body.len() + 2);
    let chars: Vec<char> = body.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        let (before, after) = (
            i.checked_sub(1).map(|j| chars[j]),
            chars.get(i + 1).copied(),
        );
        if c == '.' && !digit(before) && digit(after) {
            full.push('0');
        }
        full.push(c);
        if c == '.' && digit(before) && !digit(after) {
            full.push('0');
        }
    }
    match crate::syntax::lexer::numeric_literal(&full)? {
        crate::syntax::token::Token::Real(v) => Some(if neg { -v } else { v }),
        crate::syntax::token::Token::Int(v) => {
            let v = v.get() as f64;
            Some(if neg { -v } else { v })
        }
        _ => None,
    }
}

/// A real operation of the engines (both call this one). Always inlined:
/// in the engine's loop a call per Float operation cost more than the
/// operation (`#[inline]` alone was not taken).
#[inline(always)]
pub fn float_op(op: FloatOp, x: f64, y: &Value) -> f64 {
    match op {
        FloatOp::Add => x + y.real(),
        FloatOp::Sub => x - y.real(),
        FloatOp::Mul => x * y.real(),
        // IEEE as in GNAT (Float'Machine_Overflows is False).
        FloatOp::Div => x / y.real(),
        FloatOp::PowI => x.powi(y.int() as i32),
        FloatOp::DurDiv => duration_div(x, y.real()),
        FloatOp::DurAdd => whole_ns(x + y.real()),
        FloatOp::DurSub => whole_ns(x - y.real()),
        FloatOp::DurMul => whole_ns(x * y.real()),
        FloatOp::DurQuo => whole_ns(x / y.real()),
    }
}

/// `x` seconds as GNAT's Duration holds them: a whole number of
/// nanoseconds (the nearest). Every Duration, `Time_Span` and `Time` value
/// the engines make goes through here, so equal nanosecond counts are
/// equal reals and compare as GNAT's do (`0.03 - 0.02 = 0.01`). Below
/// 2**50 ns (13 days) each count has its own real and rounding finds it
/// again, so sums, differences and comparisons are exact; beyond, a value
/// is exact to the real's precision only. Non-finite values stay as they
/// are, for the Duration check to refuse.
#[inline]
pub fn whole_ns(x: f64) -> f64 {
    if x.is_finite() {
        (x * 1e9).round() / 1e9
    } else {
        x
    }
}

/// The first whole number of nanoseconds (as [`whole_ns`] holds it) not
/// before `x`.
pub fn ceil_ns(x: f64) -> f64 {
    let c = whole_ns(x);
    if c < x { whole_ns(c + 1e-9) } else { c }
}

/// `Duration / Integer` as GNAT computes it: Duration is fixed point with a
/// small of one nanosecond, and the quotient is truncated toward zero to
/// whole nanoseconds (10 ns / 4 = 2 ns). A zero divisor gives the infinity
/// that the Duration check then refuses.
pub fn duration_div(x: f64, y: f64) -> f64 {
    if y == 0.0 || !x.is_finite() || !y.is_finite() {
        return x / y;
    }
    let ns = (x * 1e9).round() as i128;
    (ns / y as i128) as f64 / 1e9
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Integer'Image` (written without `format!`).
    #[test]
    fn integer_image_is_gnats() {
        for (v, s) in [
            (0, " 0"),
            (7, " 7"),
            (-7, "-7"),
            (1_000_000, " 1000000"),
            (i64::MIN, "-9223372036854775808"),
            (i64::MAX, " 9223372036854775807"),
        ] {
            assert_eq!(image_int(v), s);
        }
    }

    /// Duration values are whole nanoseconds: differences of canonical
    /// values compare as GNAT's counts do, and a moment between two
    /// nanoseconds goes to the next one (a wake-up at the previous one
    /// would come back for ever).
    #[test]
    fn durations_are_whole_nanoseconds() {
        let d = |op, x: f64, y: f64| float_op(op, x, &Value::Real(y));
        // (The plain difference of the doubles is 0.009999999999999998.)
        assert_eq!(d(FloatOp::DurSub, 0.03, 0.02), 0.01);
        assert!(d(FloatOp::Sub, 0.03, 0.02) < 0.01);
        assert_eq!(d(FloatOp::DurMul, 0.1, 3.0), 0.3);
        assert_eq!(whole_ns(1.0000000004), 1.0);
        let x = 7.1934471234567;
        let c = ceil_ns(x);
        assert!(c >= x && whole_ns(c) == c && c - x < 1e-9, "{c}");
        assert_eq!(ceil_ns(0.5), 0.5);
        assert!(whole_ns(f64::INFINITY).is_infinite());
    }

    #[test]
    fn gnat_float_formats() {
        assert_eq!(image_float(830.6), " 8.30600E+02");
        assert_eq!(image_float(1234.125), " 1.23413E+03");
        assert_eq!(image_float(0.0), " 0.00000E+00");
        assert_eq!(image_float(-0.0), "-0.00000E+00");
        assert_eq!(put_float(7.25, 1, 1, 0), "7.3");
        assert_eq!(put_float(-0.00001, 1, 4, 0), "-0.0000");
        assert_eq!(put_float(3.14158, 1, 3, 2), "3.142E+0");
        assert_eq!(put_float(1.0e-10, 1, 2, 4), "1.00E-010");
        assert_eq!(put_float(2.5, 1, 0, 3), "2.5E+00");
        assert_eq!(put_float(0.95, 1, 0, 0), "0.9");
        assert_eq!(put_float(9.96, 2, 1, 0), "10.0");
        assert_eq!(put_float(-12.5, 5, 2, 0), "  -12.50");
        assert_eq!(image_float(9.999999), " 1.00000E+01");
    }

    #[test]
    fn values() {
        // GNAT's Float'Value takes a point with digits on one side only.
        assert_eq!(value_float(".5"), Some(0.5));
        assert_eq!(value_float("5."), Some(5.0));
        assert_eq!(value_float("-.5"), Some(-0.5));
        assert_eq!(value_float("5.e2"), Some(500.0));
        assert_eq!(value_float("16#.8#"), Some(0.5));
        assert_eq!(value_float("16#E.#"), Some(14.0));
        assert_eq!(value_float("."), None);
        assert_eq!(value_float(".e5"), None);
        assert_eq!(value_float("1..5"), None);
        assert_eq!(value_int(" +1_000 "), Some(1000));
        assert_eq!(value_int("16#FF#"), Some(255));
        assert_eq!(value_int("3e2"), Some(300));
        assert_eq!(value_int("- 5"), None);
        assert_eq!(value_int("1__0"), None);
    }
}

#[cfg(test)]
mod drop_tests {
    use super::{Obj, Value};

    /// A list of many nodes (`type Node is record V : Integer; Next : Ptr;
    /// end record`) is freed in constant native stack: on a thread with
    /// 256 KiB of stack, where a recursive drop overflows (and aborts).
    #[test]
    fn a_long_linked_list_drops_without_recursion() {
        let t = std::thread::Builder::new()
            .stack_size(256 * 1024)
            .spawn(|| {
                let mut head = Value::Ptr(None);
                for i in 0..300_000 {
                    head = Value::Ptr(Some(Obj::new(Value::record(smallvec::smallvec![
                        Value::Int(i),
                        head,
                    ]))));
                }
                // A second access to the fifth node keeps it and its tail.
                let Value::Ptr(Some(first)) = &head else {
                    panic!()
                };
                let mut p = first.clone();
                for _ in 0..4 {
                    let next = match p.get().fields() {
                        Some(r) => r[1].clone(),
                        _ => panic!(),
                    };
                    let Value::Ptr(Some(n)) = next else { panic!() };
                    p = n;
                }
                drop(head);
                let v = match p.get().fields() {
                    Some(r) => r[0].int(),
                    _ => panic!("the kept node lost its value"),
                };
                assert_eq!(v, 299_995);
                drop(p);
            })
            .unwrap();
        t.join().expect("the drop overflowed the stack");
    }
}
