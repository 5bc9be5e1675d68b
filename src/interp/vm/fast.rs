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
use crate::interp::stack::Stack;
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

/// The stop request of a run that has none (`Machine::interrupted` is
/// None): the loops test one flag either way.
pub(super) static NEVER: AtomicBool = AtomicBool::new(false);

/// An element read from an array of scalars.
enum Elem {
    Real(f64),
    Int(i64),
}

/// Element `o` of a compact array of scalars (None: general values).
#[inline(always)]
fn elem(data: value::Elems, o: usize) -> Option<Elem> {
    match data {
        value::Elems::Reals(r) => r.get(o).map(|x| Elem::Real(*x)),
        value::Elems::Ints(v) => v.get(o).map(|x| Elem::Int(*x)),
        value::Elems::Bytes(b) => b.get(o).map(|x| Elem::Int(*x as i64)),
        value::Elems::Vals(_) => None,
    }
}

/// What the inner loop needs to enter calls and return from them (see
/// [`run_calls`]): the callers' frames, the display, the call depth and the
/// compiled bodies, the number of current occurrences and whether the
/// stack has holes (other tasks' frames freed below its top); and the
/// running code's registers besides the program counter, in and out.
pub(super) struct Calls<'x, 'c> {
    pub(super) frames: &'x mut Vec<Frame<'c>>,
    pub(super) display: &'x mut Vec<usize>,
    pub(super) depth: &'x mut usize,
    pub(super) codes: &'x [Option<&'c Code>],
    pub(super) current: usize,
    pub(super) holes: bool,
    pub(super) cur: &'c Code,
    pub(super) lvl: u16,
    pub(super) fp: usize,
    pub(super) current_base: usize,
}

/// Whether [`run`] is worth calling at `pc`: its call costs more than it
/// saves unless it can run at least two instructions (a loop whose body
/// begins with an entry call or an `accept` has nothing to run here).
#[inline(always)]
pub(super) fn worth(ops: &[Op], pc: u32) -> bool {
    let pc = pc as usize;
    ops.get(pc).is_some_and(takes) && ops.get(pc + 1).is_some_and(takes)
}

/// Whether [`run`] executes `op` (when its operands are as it needs).
#[inline(always)]
fn takes(op: &Op) -> bool {
    matches!(
        op,
        Op::Int(..)
            | Op::Real(..)
            | Op::Move(..)
            | Op::IntBin { .. }
            | Op::IntBinK { .. }
            | Op::CmpK { .. }
            | Op::Cmp { .. }
            | Op::Eq { .. }
            | Op::Logic { .. }
            | Op::Not(..)
            | Op::RealAdd(..)
            | Op::RealSub(..)
            | Op::RealMul(..)
            | Op::RealDiv(..)
            | Op::ToReal(..)
            | Op::Index1 { .. }
            | Op::Index2 { .. }
            | Op::StoreIndex1 { .. }
            | Op::StoreIndex2 { .. }
            | Op::DerefField { .. }
            | Op::Null(..)
            | Op::Jump(..)
            | Op::JumpIfNot(..)
            | Op::JumpIf(..)
            | Op::CmpKJumpNot { .. }
            | Op::CmpJumpNot { .. }
            | Op::ForStart { .. }
            | Op::ForNext { .. }
            | Op::Poll(..)
            | Op::Call { .. }
            | Op::CallK { .. }
            | Op::Return(..)
            | Op::ReturnIntBin { .. }
    )
}

/// Runs the instructions of `cur` from `pc` while it can (see the
/// module's comment); returns where it stopped: the first instruction it
/// did not execute. `lvl` and `fp` are the running frame's level and first
/// slot, `stop` the user's stop request (a loop's step that would poll it
/// stops here instead when it is set). No call: this is the loops' copy,
/// which keeps its few registers in registers.
#[inline(never)]
pub(super) fn run(
    cur: &Code,
    pc: usize,
    lvl: u16,
    fp: usize,
    st: &mut Stack,
    stop: &AtomicBool,
) -> usize {
    // (Nothing of it is read: this copy enters no call.)
    let (mut frames, mut display, mut depth) = (Vec::new(), Vec::new(), 0);
    let mut cx = Calls {
        frames: &mut frames,
        display: &mut display,
        depth: &mut depth,
        codes: &[],
        current: 0,
        holes: false,
        cur,
        lvl,
        fp,
        current_base: 0,
    };
    steps::<false>(cur, pc, lvl, fp, st, stop, &mut cx)
}

/// [`run`] that also enters calls of compiled subprograms and returns from
/// them (see `enter!` and `ret!`) when they need nothing the big loop does:
/// the callee compiled already, scalar arguments, no Storage_Error, no stop
/// request; a return of a scalar from a frame of scalars on top of the
/// stack, with no `out` parameter and no occurrence to leave. Where it
/// stopped is in the code then running, whose registers it leaves in `cx`.
#[inline(never)]
pub(super) fn run_calls<'c>(
    pc: usize,
    st: &mut Stack,
    stop: &AtomicBool,
    cx: &mut Calls<'_, 'c>,
) -> usize {
    steps::<true>(cx.cur, pc, cx.lvl, cx.fp, st, stop, cx)
}

#[inline(always)]
fn steps<'c, const CALLS: bool>(
    mut cur: &'c Code,
    mut pc: usize,
    mut lvl: u16,
    mut fp: usize,
    st: &mut Stack,
    stop: &AtomicBool,
    cx: &mut Calls<'_, 'c>,
) -> usize {
    let mut ops: &'c [Op] = &cur.ops;
    let mut stack = st.as_mut_slice();
    // The calls' registers, as locals (the depth too, written back).
    let (frames, display, codes) = (&mut *cx.frames, &mut *cx.display, cx.codes);
    let current = cx.current;
    // A quick return needs a frame entered with the current occurrences
    // it leaves (none of its own) and a stack without holes: one test,
    // `entered > current_base` (holes: never quick).
    let entered = if cx.holes { usize::MAX } else { current };
    let mut depth = *cx.depth;
    let mut current_base = cx.current_base;
    // Where it stopped: the registers go back to the big loop.
    macro_rules! stop_at {
        ($pc:expr) => {{
            if CALLS {
                *cx.depth = depth;
                cx.cur = cur;
                cx.lvl = lvl;
                cx.fp = fp;
                cx.current_base = current_base;
            }
            return $pc;
        }};
    }
    loop {
        let here = pc;
        let Some(op) = ops.get(pc) else {
            stop_at!(here);
        };
        pc += 1;
        // The slot of a local operand (another frame's: stop).
        macro_rules! at {
            ($v:expr) => {{
                let v: Var = $v;
                if v.level != lvl {
                    stop_at!(here);
                }
                fp + v.slot as usize
            }};
        }
        macro_rules! int {
            ($v:expr) => {
                match stack.get(at!($v)) {
                    Some(Value::Int(x)) => *x,
                    _ => stop_at!(here),
                }
            };
        }
        macro_rules! real {
            ($v:expr) => {
                match stack.get(at!($v)) {
                    Some(Value::Real(x)) => *x,
                    Some(Value::Int(x)) => *x as f64,
                    _ => stop_at!(here),
                }
            };
        }
        // The destination's slot, checked before anything is written.
        // The order of two integers or two reals in slots (`Cmp`,
        // `CmpJumpNot`); any other form stops before the instruction.
        macro_rules! scalar_cmp {
            ($a:expr, $b:expr) => {
                match (stack.get(at!($a)), stack.get(at!($b))) {
                    (Some(Value::Int(x)), Some(Value::Int(y))) => x.cmp(y),
                    (Some(Value::Real(x)), Some(Value::Real(y))) => {
                        x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal)
                    }
                    _ => stop_at!(here),
                }
            };
        }
        macro_rules! dst {
            ($v:expr) => {{
                let i = at!($v);
                if i >= stack.len() {
                    stop_at!(here);
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
                stop.load(Ordering::Relaxed)
            };
        }
        // A call's callee, when this loop can enter it: compiled already
        // (else the big loop compiles it), its level in the display, and
        // neither Storage_Error nor the user's stop at the call (the big
        // loop raises them at the same instruction).
        macro_rules! callee {
            ($f:expr) => {
                match codes.get($f as usize) {
                    Some(Some(code))
                        if depth < MAX_DEPTH
                            && (code.level as usize) < display.len()
                            && !stopped!() =>
                    {
                        *code
                    }
                    _ => stop_at!(here),
                }
            };
        }
        // Enters `code`, whose frame has been opened at `base`: what
        // `push_call` and the big loop's `enter!` do.
        macro_rules! enter {
            ($code:expr, $base:expr, $dst:expr) => {{
                let (code, base): (&'c Code, usize) = ($code, $base);
                let saved = std::mem::replace(&mut display[code.level as usize], base);
                depth += 1;
                frames.push(Frame {
                    code: cur,
                    pc: pc as u32,
                    current: current_base,
                    saved,
                    fp,
                    dst: $dst,
                });
                current_base = current;
                cur = code;
                ops = &code.ops;
                pc = 0;
                lvl = code.level;
                fp = base;
                stack = st.as_mut_slice();
            }};
        }
        // A return of the integer `$n` (None: of no value): what the big
        // loop's `ret!` and `pop_frame` do for a frame of scalars on top of
        // the stack, with nothing to copy back and no occurrence to leave.
        macro_rules! ret {
            ($n:expr) => {{
                let n: Option<i64> = $n;
                // (The running frame begins at `fp`.)
                if !cur.quick || fp + (cur.frame as usize) < st.len() || entered > current_base {
                    stop_at!(here);
                }
                let Some(f) = frames.pop() else {
                    // The end of a nested run or of a task's body.
                    stop_at!(here);
                };
                if n.is_none() && f.dst != NO_DST {
                    frames.push(f);
                    stop_at!(here);
                }
                st.truncate_scalars(fp);
                display[cur.level as usize] = f.saved;
                depth -= 1;
                cur = f.code;
                ops = &cur.ops;
                pc = f.pc as usize;
                current_base = f.current;
                lvl = cur.level;
                fp = f.fp;
                debug_assert_eq!(fp, display.get(lvl as usize).copied().unwrap_or(0));
                stack = st.as_mut_slice();
                if let Some(n) = n
                    && f.dst != NO_DST
                {
                    put_int!(f.dst, n);
                }
            }};
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
                    None => stop_at!(here),
                };
                let i = dst!(*d);
                exec::set(&mut stack[i], v);
            }
            Op::IntBin { op, dst, x, y, .. } => {
                let (x, y) = (int!(*x), int!(*y));
                let Some(v) = int_quick(*op, x, y) else {
                    stop_at!(here);
                };
                let i = dst!(*dst);
                put_int!(i, v);
            }
            Op::IntBinK { op, dst, x, k, .. } => {
                let x = int!(*x);
                let Some(v) = int_quick(*op, x, *k) else {
                    stop_at!(here);
                };
                let i = dst!(*dst);
                put_int!(i, v);
            }
            Op::CmpK { op, dst, x, k } => {
                let r = exec::holds(*op, int!(*x).cmp(k));
                let i = dst!(*dst);
                put_int!(i, r as i64);
            }
            Op::Cmp { op, dst, x, y } => {
                let ord = scalar_cmp!(*x, *y);
                let r = exec::holds(*op, ord);
                let i = dst!(*dst);
                put_int!(i, r as i64);
            }
            Op::Eq { ne, dst, x, y } => {
                let same = match (stack.get(at!(*x)), stack.get(at!(*y))) {
                    (Some(Value::Int(x)), Some(Value::Int(y))) => x == y,
                    // (Access values here, without a call: `P /= null`.)
                    (Some(Value::Ptr(x)), Some(Value::Ptr(y))) => value::same_access(x, y),
                    (Some(x @ Value::Real(_)), Some(y)) => x == y,
                    _ => stop_at!(here),
                };
                let i = dst!(*dst);
                put_int!(i, (same != *ne) as i64);
            }
            Op::Logic { op, dst, x, y } => {
                let (x, y) = (int!(*x) != 0, int!(*y) != 0);
                let r = match op {
                    LogicOp::And | LogicOp::AndThen => x && y,
                    LogicOp::Or | LogicOp::OrElse => x || y,
                    LogicOp::Xor => x ^ y,
                };
                let i = dst!(*dst);
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
            Op::Index1 { dst, arr, i: x, .. }
            | Op::Index2 {
                dst,
                arr,
                ix: [x, _],
                ..
            } => {
                let idx = match op {
                    Op::Index2 { ix: [_, y], .. } => [int!(*x), int!(*y)],
                    _ => [int!(*x), 0],
                };
                let n = if matches!(op, Op::Index2 { .. }) {
                    2
                } else {
                    1
                };
                let got = match stack.get(at!(*arr)) {
                    Some(Value::Arr(a)) => match a.offset(&idx[..n]) {
                        Some(o) => elem(a.data(), o),
                        None => None,
                    },
                    _ => None,
                };
                let i = dst!(*dst);
                match got {
                    Some(Elem::Real(x)) => put_real!(i, x),
                    Some(Elem::Int(x)) => put_int!(i, x),
                    None => stop_at!(here),
                }
            }
            Op::StoreIndex1 { arr, i: x, src, .. }
            | Op::StoreIndex2 {
                arr,
                ix: [x, _],
                src,
                ..
            } => {
                let idx = match op {
                    Op::StoreIndex2 { ix: [_, y], .. } => [int!(*x), int!(*y)],
                    _ => [int!(*x), 0],
                };
                let n = if matches!(op, Op::StoreIndex2 { .. }) {
                    2
                } else {
                    1
                };
                let val = match stack.get(at!(*src)) {
                    Some(Value::Real(x)) => Elem::Real(*x),
                    Some(Value::Int(x)) => Elem::Int(*x),
                    _ => stop_at!(here),
                };
                let Some(Value::Arr(a)) = stack.get_mut(at!(*arr)) else {
                    stop_at!(here);
                };
                // The element's place and form first: nothing is written
                // (nor the array copied) unless all of it can be done here.
                let Some(o) = a.offset(&idx[..n]) else {
                    stop_at!(here);
                };
                let fits = match (&val, a.data()) {
                    (Elem::Real(_), value::Elems::Reals(r)) => o < r.len(),
                    (Elem::Int(_), value::Elems::Ints(v)) => o < v.len(),
                    (Elem::Int(x), value::Elems::Bytes(b)) => (0..=255).contains(x) && o < b.len(),
                    _ => false,
                };
                if !fits {
                    stop_at!(here);
                }
                match (val, a.data_mut()) {
                    (Elem::Real(x), value::ElemsMut::Reals(r)) => r[o] = x,
                    (Elem::Int(x), value::ElemsMut::Ints(v)) => v[o] = x,
                    (Elem::Int(x), value::ElemsMut::Bytes(b)) => b[o] = x as u8,
                    // (Excluded by `fits`: a copy keeps its form.)
                    _ => {}
                }
            }
            Op::DerefField {
                dst, ptr, field, ..
            } => {
                let got = match stack.get(at!(*ptr)) {
                    Some(Value::Ptr(Some(o))) => {
                        o.with(|v| v.fields().and_then(|r| r.get(*field as usize).cloned()))
                    }
                    _ => None,
                };
                let Some(v) = got else {
                    stop_at!(here);
                };
                let i = dst!(*dst);
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
            Op::CmpKJumpNot { op, x, k, target } => {
                if !exec::holds(*op, int!(*x).cmp(k)) {
                    pc = *target as usize;
                }
            }
            Op::CmpJumpNot { op, x, y, target } => {
                let ord = scalar_cmp!(*x, *y);
                if !exec::holds(*op, ord) {
                    pc = *target as usize;
                }
            }
            Op::ForStart {
                var,
                low,
                high,
                reverse,
                exit,
            } => {
                let (lo, hi) = (int!(*low), int!(*high));
                let i = dst!(*var);
                if lo > hi {
                    pc = *exit as usize;
                } else {
                    put_int!(i, if *reverse { hi } else { lo });
                }
            }
            Op::ForNext {
                var,
                low,
                high,
                reverse,
                body,
                ..
            } => {
                let i = int!(*var);
                let last = if *reverse { int!(*low) } else { int!(*high) };
                if i != last {
                    // The loop's step polls the user's stop: when it is
                    // set, the big loop's step raises.
                    if stopped!() {
                        stop_at!(here);
                    }
                    let s = dst!(*var);
                    put_int!(s, if *reverse { i - 1 } else { i + 1 });
                    pc = *body as usize;
                }
            }
            Op::CallK { f, x, add, dst, .. } => {
                if !CALLS {
                    stop_at!(here);
                }
                // (Out of Integer's range: the big loop raises.)
                let n = int!(*x) + *add as i64;
                if n != n as i32 as i64 {
                    stop_at!(here);
                }
                let dst = if dst.level == NO_VAR.level {
                    NO_DST
                } else {
                    dst!(*dst)
                };
                let code = callee!(*f);
                let base = st.len();
                st.open_frame_int(n, (code.frame - code.temps) as usize, code.frame as usize);
                enter!(code, base, dst);
            }
            Op::Call {
                function,
                f,
                ops: args,
                ..
            } => {
                if !CALLS {
                    stop_at!(here);
                }
                let (args, dst) = match (*function, args.split_last()) {
                    (true, Some((d, args))) => (args, Some(*d)),
                    _ => (&args[..], None),
                };
                // (The result's slot in the caller: a local one only.)
                let dst = match dst {
                    Some(d) => dst!(d),
                    None => NO_DST,
                };
                let code = callee!(*f);
                let base = st.len();
                // The arguments straight into the new frame, scalars only
                // (anything else: the frame goes again, for the big loop).
                for v in args {
                    let i = if v.level == lvl {
                        fp + v.slot as usize
                    } else {
                        match display.get(v.level as usize) {
                            Some(b) => b + v.slot as usize,
                            None => usize::MAX,
                        }
                    };
                    match st.get(i) {
                        Some(Value::Int(n)) => {
                            let n = *n;
                            st.push_int(n)
                        }
                        Some(Value::Real(x)) => {
                            let x = *x;
                            st.push(Value::Real(x))
                        }
                        _ => {
                            st.truncate_scalars(base);
                            stop_at!(here);
                        }
                    }
                }
                let own = (code.frame - code.temps) as usize;
                st.grow_to_clearing(base + own, base + code.frame as usize);
                enter!(code, base, dst);
            }
            Op::Return(x) => {
                if !CALLS {
                    stop_at!(here);
                }
                let n = match x {
                    Some(x) => Some(int!(*x)),
                    None => None,
                };
                ret!(n);
            }
            Op::ReturnIntBin { op, x, y, .. } => {
                if !CALLS {
                    stop_at!(here);
                }
                let (x, y) = (int!(*x), int!(*y));
                let Some(n) = int_quick(*op, x, y) else {
                    stop_at!(here);
                };
                ret!(Some(n));
            }
            Op::Poll(_) => {
                if stopped!() {
                    stop_at!(here);
                }
            }
            _ => stop_at!(here),
        }
    }
}
