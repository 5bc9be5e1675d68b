//! The engine's inner loop: a run of instructions over the running frame's
//! scalars (and arrays of scalars), in a small function that borrows the
//! stack once, so that the frame's base, the program counter and the
//! stack's bounds stay in registers (in the big loop of `exec.rs` they live
//! in memory, reloaded by every instruction).
//!
//! The rule that keeps it right: [`run`] executes an instruction only when
//! it can do all of it here; otherwise it stops *before* it, with nothing
//! of it done, and the big loop executes it (a call, a return, an operand of
//! an enclosing frame, a value of an unexpected form, any check that fails:
//! the big loop raises, as it always did). So each instruction here does
//! exactly what its arm in `exec.rs` does when that arm goes on with the
//! next instruction, and no exception is raised here.

use super::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// `x op y` for integers when it needs no check that can fail: the values
/// of `Run::int_op` for results in Integer's range (anything else: None,
/// for the big loop to check).
#[inline(always)]
pub(super) fn int_quick(o: IntOp, x: i64, y: i64) -> Option<i64> {
    let v = match o {
        IntOp::Add => x.checked_add(y),
        IntOp::Sub => x.checked_sub(y),
        IntOp::Mul => x.checked_mul(y),
        IntOp::Mod if y > 0 => Some(x.rem_euclid(y)),
        IntOp::Rem if y > 0 => Some(x % y),
        _ => None,
    }?;
    (i32::MIN as i64..=i32::MAX as i64)
        .contains(&v)
        .then_some(v)
}

/// An element read from an array of scalars.
enum Elem {
    Real(f64),
    Int(i64),
}

/// Element `o` of a compact array of scalars (None: general values).
#[inline(always)]
fn elem(data: &value::Elems, o: usize) -> Option<Elem> {
    match data {
        value::Elems::Reals(r) => r.get(o).map(|x| Elem::Real(*x)),
        value::Elems::Ints(v) => v.get(o).map(|x| Elem::Int(*x)),
        value::Elems::Bytes(b) => b.get(o).map(|x| Elem::Int(*x as i64)),
        value::Elems::Vals(_) => None,
    }
}

/// Runs the instructions of `ops` from `pc` while it can (see the module's
/// comment); returns where it stopped: the first instruction it did not
/// execute. `lvl` and `fp` are the running frame's level and first slot,
/// `stack` the live slots, `stop` the user's stop request (a loop's step
/// that would poll it stops here instead when it is set).
#[inline(never)]
pub(super) fn run(
    ops: &[Op],
    mut pc: usize,
    lvl: u16,
    fp: usize,
    stack: &mut [Value],
    stop: Option<&AtomicBool>,
) -> usize {
    loop {
        let here = pc;
        let Some(op) = ops.get(pc) else {
            return here;
        };
        pc += 1;
        // The slot of a local operand (another frame's: stop).
        macro_rules! at {
            ($v:expr) => {{
                let v: Var = $v;
                if v.level != lvl {
                    return here;
                }
                fp + v.slot as usize
            }};
        }
        macro_rules! int {
            ($v:expr) => {
                match stack.get(at!($v)) {
                    Some(Value::Int(x)) => *x,
                    _ => return here,
                }
            };
        }
        macro_rules! real {
            ($v:expr) => {
                match stack.get(at!($v)) {
                    Some(Value::Real(x)) => *x,
                    Some(Value::Int(x)) => *x as f64,
                    _ => return here,
                }
            };
        }
        // The destination's slot, checked before anything is written.
        macro_rules! dst {
            ($v:expr) => {{
                let i = at!($v);
                if i >= stack.len() {
                    return here;
                }
                i
            }};
        }
        macro_rules! put_int {
            ($i:expr, $x:expr) => {{
                let x: i64 = $x;
                super::exec::put_int_in(&mut stack[$i], x)
            }};
        }
        macro_rules! put_real {
            ($i:expr, $x:expr) => {{
                let x: f64 = $x;
                super::exec::put_real_in(&mut stack[$i], x)
            }};
        }
        macro_rules! stopped {
            () => {
                stop.is_some_and(|f| f.load(Ordering::Relaxed))
            };
        }
        match op {
            Op::Int(d, v) => {
                let i = dst!(*d);
                put_int!(i, *v);
            }
            Op::Real(d, v) => {
                let i = dst!(*d);
                put_real!(i, *v);
            }
            Op::Move(d, s) => {
                let v = match stack.get(at!(*s)) {
                    Some(v) => v.clone(),
                    None => return here,
                };
                let i = dst!(*d);
                exec::set(&mut stack[i], v);
            }
            Op::IntBin(o, d, a, b, _) => {
                let (x, y) = (int!(*a), int!(*b));
                let Some(v) = int_quick(*o, x, y) else {
                    return here;
                };
                let i = dst!(*d);
                put_int!(i, v);
            }
            Op::IntBinK(o, d, a, y, _) => {
                let x = int!(*a);
                let Some(v) = int_quick(*o, x, *y) else {
                    return here;
                };
                let i = dst!(*d);
                put_int!(i, v);
            }
            Op::CmpK(o, d, a, k) => {
                let r = exec::holds(*o, int!(*a).cmp(k));
                let i = dst!(*d);
                put_int!(i, r as i64);
            }
            Op::Cmp(o, d, a, b) => {
                let ord = match (stack.get(at!(*a)), stack.get(at!(*b))) {
                    (Some(Value::Int(x)), Some(Value::Int(y))) => x.cmp(y),
                    (Some(Value::Real(x)), Some(Value::Real(y))) => {
                        x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal)
                    }
                    _ => return here,
                };
                let r = exec::holds(*o, ord);
                let i = dst!(*d);
                put_int!(i, r as i64);
            }
            Op::Eq(ne, d, a, b) => {
                let same = match (stack.get(at!(*a)), stack.get(at!(*b))) {
                    (Some(Value::Int(x)), Some(Value::Int(y))) => x == y,
                    (Some(x @ (Value::Real(_) | Value::Ptr(_))), Some(y)) => x == y,
                    _ => return here,
                };
                let i = dst!(*d);
                put_int!(i, (same != *ne) as i64);
            }
            Op::Logic(o, d, a, b) => {
                let (x, y) = (int!(*a) != 0, int!(*b) != 0);
                let r = match o {
                    LogicOp::And | LogicOp::AndThen => x && y,
                    LogicOp::Or | LogicOp::OrElse => x || y,
                    LogicOp::Xor => x ^ y,
                };
                let i = dst!(*d);
                put_int!(i, r as i64);
            }
            Op::Not(d, a) => {
                let x = int!(*a) == 0;
                let i = dst!(*d);
                put_int!(i, x as i64);
            }
            Op::RealAdd(d, a, b) => {
                let v = real!(*a) + real!(*b);
                let i = dst!(*d);
                put_real!(i, v);
            }
            Op::RealSub(d, a, b) => {
                let v = real!(*a) - real!(*b);
                let i = dst!(*d);
                put_real!(i, v);
            }
            Op::RealMul(d, a, b) => {
                let v = real!(*a) * real!(*b);
                let i = dst!(*d);
                put_real!(i, v);
            }
            Op::RealDiv(d, a, b) => {
                let v = real!(*a) / real!(*b);
                let i = dst!(*d);
                put_real!(i, v);
            }
            Op::ToReal(d, a) => {
                let v = real!(*a);
                let i = dst!(*d);
                put_real!(i, v);
            }
            Op::Index1(d, arr, x, _) | Op::Index2(d, arr, [x, _], _) => {
                let idx = match op {
                    Op::Index2(_, _, [_, y], _) => [int!(*x), int!(*y)],
                    _ => [int!(*x), 0],
                };
                let n = if matches!(op, Op::Index2(..)) { 2 } else { 1 };
                let got = match stack.get(at!(*arr)) {
                    Some(Value::Arr(a)) => match a.offset(&idx[..n]) {
                        Some(o) => elem(&a.data, o),
                        None => None,
                    },
                    _ => None,
                };
                let i = dst!(*d);
                match got {
                    Some(Elem::Real(x)) => put_real!(i, x),
                    Some(Elem::Int(x)) => put_int!(i, x),
                    None => return here,
                }
            }
            Op::StoreIndex1(arr, x, src, _) | Op::StoreIndex2(arr, [x, _], src, _) => {
                let idx = match op {
                    Op::StoreIndex2(_, [_, y], _, _) => [int!(*x), int!(*y)],
                    _ => [int!(*x), 0],
                };
                let n = if matches!(op, Op::StoreIndex2(..)) {
                    2
                } else {
                    1
                };
                let val = match stack.get(at!(*src)) {
                    Some(Value::Real(x)) => Elem::Real(*x),
                    Some(Value::Int(x)) => Elem::Int(*x),
                    _ => return here,
                };
                let Some(Value::Arr(a)) = stack.get_mut(at!(*arr)) else {
                    return here;
                };
                // The element's place and form first: nothing is written
                // (nor the array copied) unless all of it can be done here.
                let Some(o) = a.offset(&idx[..n]) else {
                    return here;
                };
                let fits = match (&val, &a.data) {
                    (Elem::Real(_), value::Elems::Reals(r)) => o < r.len(),
                    (Elem::Int(_), value::Elems::Ints(v)) => o < v.len(),
                    (Elem::Int(x), value::Elems::Bytes(b)) => (0..=255).contains(x) && o < b.len(),
                    _ => false,
                };
                if !fits {
                    return here;
                }
                match (val, &mut Rc::make_mut(a).data) {
                    (Elem::Real(x), value::Elems::Reals(r)) => r[o] = x,
                    (Elem::Int(x), value::Elems::Ints(v)) => v[o] = x,
                    (Elem::Int(x), value::Elems::Bytes(b)) => b[o] = x as u8,
                    // (Excluded by `fits`: a copy keeps its form.)
                    _ => {}
                }
            }
            Op::DerefField(d, a, f, ..) => {
                let got = match stack.get(at!(*a)) {
                    Some(Value::Ptr(Some(o))) => match o.try_borrow() {
                        Ok(r) => r.fields().and_then(|r| r.get(*f as usize).cloned()),
                        Err(_) => None,
                    },
                    _ => None,
                };
                let Some(v) = got else {
                    return here;
                };
                let i = dst!(*d);
                exec::set(&mut stack[i], v);
            }
            Op::Null(d) => {
                let i = dst!(*d);
                exec::set(&mut stack[i], Value::Ptr(None));
            }
            Op::Jump(t) => pc = *t as usize,
            Op::JumpIfNot(c, t) => {
                if int!(*c) == 0 {
                    pc = *t as usize;
                }
            }
            Op::JumpIf(c, t) => {
                if int!(*c) != 0 {
                    pc = *t as usize;
                }
            }
            Op::CmpKJumpNot(o, a, k, t) => {
                if !exec::holds(*o, int!(*a).cmp(k)) {
                    pc = *t as usize;
                }
            }
            Op::CmpJumpNot(o, a, b, t) => {
                let ord = match (stack.get(at!(*a)), stack.get(at!(*b))) {
                    (Some(Value::Int(x)), Some(Value::Int(y))) => x.cmp(y),
                    (Some(Value::Real(x)), Some(Value::Real(y))) => {
                        x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal)
                    }
                    _ => return here,
                };
                if !exec::holds(*o, ord) {
                    pc = *t as usize;
                }
            }
            Op::ForStart(v, l, h, rev, exit) => {
                let (lo, hi) = (int!(*l), int!(*h));
                let i = dst!(*v);
                if lo > hi {
                    pc = *exit as usize;
                } else {
                    put_int!(i, if *rev { hi } else { lo });
                }
            }
            Op::ForNext(v, l, h, rev, body, _) => {
                let i = int!(*v);
                let last = if *rev { int!(*l) } else { int!(*h) };
                if i != last {
                    // The loop's step polls the user's stop: when it is
                    // set, the big loop's step raises.
                    if stopped!() {
                        return here;
                    }
                    let s = dst!(*v);
                    put_int!(s, if *rev { i - 1 } else { i + 1 });
                    pc = *body as usize;
                }
            }
            Op::Poll(_) => {
                if stopped!() {
                    return here;
                }
            }
            _ => return here,
        }
    }
}
