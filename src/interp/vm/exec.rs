//! The execution loop, and its helpers over frame slots.

use super::*;
use crate::interp::aggregate::{AggBounds, AggPart};

impl<'a, 'c> Run<'a, 'c> {
    /// What a choice of an array aggregate gives, from its slot (emptied).
    fn agg_part_of(&mut self, p: &PartOp) -> AggPart {
        match *p {
            PartOp::One(v) => AggPart::One(self.take_slot(v)),
            PartOp::Each(v) => AggPart::Each(match self.take_slot(v) {
                Value::Arr(a) => a.into_vals(),
                _ => Vec::new(),
            }),
        }
    }

    /// The value of a slot, which is left empty.
    pub(super) fn take_slot(&mut self, v: Var) -> Value {
        let i = self.sl(v);
        std::mem::take(&mut self.m.stack[i])
    }

    /// The value of a record aggregate of a type without discriminants,
    /// its components taken from their slots straight into the record's
    /// one allocation.
    fn record_from_slots(&mut self, vars: &[Var]) -> Value {
        let (stack, display) = (&mut self.m.stack, &self.m.display);
        Value::record_of(vars.len(), |k| {
            let v = vars[k];
            std::mem::take(&mut stack[display[v.level as usize] + v.slot as usize])
        })
    }

    #[inline(always)]
    pub(super) fn sl(&self, v: Var) -> usize {
        self.m.display[v.level as usize] + v.slot as usize
    }

    #[inline(always)]
    pub(super) fn int_at(&self, v: Var) -> i64 {
        self.int_ix(self.sl(v))
    }

    /// How the values in slots `a` and `b` compare (as `Value::compare`,
    /// integers inline).
    #[inline(always)]
    pub(super) fn order_ix(&self, a: usize, b: usize) -> std::cmp::Ordering {
        let (x, y) = (&self.m.stack[a], &self.m.stack[b]);
        match (x, y) {
            (Value::Int(p), Value::Int(q)) => p.cmp(q),
            (Value::Real(p), Value::Real(q)) => {
                p.partial_cmp(q).unwrap_or(std::cmp::Ordering::Equal)
            }
            _ => compare_slow(x, y),
        }
    }

    /// How the value in slot `a` compares with the integer `k`.
    #[inline(always)]
    pub(super) fn order_k(&self, a: usize, k: i64) -> std::cmp::Ordering {
        match &self.m.stack[a] {
            Value::Int(x) => x.cmp(&k),
            other => compare_slow(other, &Value::Int(k)),
        }
    }

    /// The integer in stack slot `i`.
    #[inline(always)]
    pub(super) fn int_ix(&self, i: usize) -> i64 {
        match &self.m.stack[i] {
            Value::Int(i) => *i,
            other => int_slow(other),
        }
    }

    /// The real in stack slot `i` (an integer converted, as
    /// `Value::real`).
    #[inline(always)]
    pub(super) fn real_ix(&self, i: usize) -> f64 {
        match &self.m.stack[i] {
            Value::Real(x) => *x,
            other => real_slow(other),
        }
    }

    /// `dst := x op y` for integers: addition and subtraction inline, the
    /// rest (and every overflow) through `Run::int_op`'s checks.
    #[inline(always)]
    pub(super) fn int_arith(&mut self, o: IntOp, d: usize, x: i64, y: i64, span: Span) -> R<()> {
        self.int_value(o, x, y, span).map(|v| self.put_int_ix(d, v))
    }

    /// `x op y` for integers, as [`Self::int_arith`] computes it.
    #[inline(always)]
    pub(super) fn int_value(&self, o: IntOp, x: i64, y: i64, span: Span) -> R<i64> {
        self.int_value_at(o, x, y, || span)
    }

    /// [`Self::int_value`] whose place is made only when a check fails.
    #[inline(always)]
    pub(super) fn int_value_at(
        &self,
        o: IntOp,
        x: i64,
        y: i64,
        span: impl FnOnce() -> Span,
    ) -> R<i64> {
        // (Anything `int_quick` leaves goes to `int_op` for its checks.)
        match super::fast::int_quick(o, x, y) {
            Some(v) => Ok(v),
            None => self.int_op(o, x, y, span()),
        }
    }

    #[inline(always)]
    pub(super) fn put(&mut self, v: Var, x: Value) {
        self.put_ix(self.sl(v), x);
    }

    #[inline(always)]
    pub(super) fn put_ix(&mut self, i: usize, x: Value) {
        set(&mut self.m.stack[i], x);
    }

    /// `put_ix` of an integer: a slot that holds one already is written in
    /// place (nothing to drop).
    #[inline(always)]
    pub(super) fn put_int_ix(&mut self, i: usize, x: i64) {
        put_int_in(&mut self.m.stack[i], x);
    }

    /// `put_ix` of a real, in place like [`Self::put_int`].
    #[inline(always)]
    pub(super) fn put_real_ix(&mut self, i: usize, x: f64) {
        put_real_in(&mut self.m.stack[i], x);
    }

    /// Runs level-0 code to its end.
    pub(super) fn exec_code(&mut self, code: &'c Code) -> R<()> {
        let need = self.c.globals as usize + code.temps as usize;
        self.m.stack.grow_to(need);
        self.exec_loop(code, false)
    }

    /// The execution loop: runs `code` to its end (`nested`: the code of
    /// a nested run (`nested.rs`), whose frame is set up, and whose return
    /// ends the loop with `Flow::Return`).
    pub(super) fn exec_loop(&mut self, code: &'c Code, nested: bool) -> R<()> {
        let mut frames: Vec<Frame<'c>> = Vec::new();
        let level0 = code;
        let mut cur = code;
        let mut pc: u32 = 0;
        let mut current_base = self.m.current.len();
        let mut pending: Option<Box<Occurrence>> = None;
        let mut enter: Option<Entered<'c>> = None;
        // A task's own frame (None: the main program's code).
        let mut root: Option<(usize, usize)> = None;
        // The running code's level and where its frame begins: an operand
        // of the code's own frame is found without the display.
        let mut lvl = cur.level;
        let mut fp = self.m.display.get(lvl as usize).copied().unwrap_or(0);
        macro_rules! ix {
            ($v:expr) => {{
                let v: Var = $v;
                if v.level == lvl {
                    fp + v.slot as usize
                } else {
                    self.sl(v)
                }
            }};
        }
        // Enters a called frame: the running code is saved with its resume
        // point, and the callee's code starts.
        macro_rules! push_frame {
            ($entered:expr, $dst:expr) => {
                let (code, _, saved) = $entered;
                frames.push(Frame {
                    code: std::mem::replace(&mut cur, code),
                    pc,
                    current: current_base,
                    saved,
                    fp,
                    dst: $dst,
                });
                current_base = self.m.current.len();
                pc = 0;
            };
        }
        // A call's quick way in: the callee's frame is the running one.
        macro_rules! enter {
            ($entered:expr, $dst:expr) => {{
                let entered = $entered;
                let base = entered.1;
                push_frame!(entered, $dst);
                lvl = cur.level;
                fp = base;
                fast!(true);
                continue;
            }};
        }
        // After a loop's step (a `for` loop's start and step, a jump) and
        // a call: the inner loop runs what it can from `pc` on, often the
        // whole loop or the whole call (and the calls it makes); the
        // instruction it stops at is this loop's (see `fast.rs`). Only
        // there, and only where it can run two instructions at least: for
        // one instruction alone, the call would cost more than it saves.
        macro_rules! fast {
            (false) => {{
                if fast::worth(&cur.ops, pc) {
                    let stop = self.m.interrupted.as_deref().unwrap_or(&fast::NEVER);
                    pc = fast::run(cur, pc as usize, lvl, fp, &mut self.m.stack, stop) as u32;
                }
            }};
            (true) => {{
                if fast::worth(&cur.ops, pc) {
                    let mut cx = fast::Calls {
                        frames: &mut frames,
                        display: &mut self.m.display,
                        depth: &mut self.m.depth,
                        codes: &self.codes.by_func,
                        current: self.m.current.len(),
                        holes: !self.m.sched.holes.is_empty(),
                        cur,
                        lvl,
                        fp,
                        current_base,
                    };
                    let stop = self.m.interrupted.as_deref().unwrap_or(&fast::NEVER);
                    pc = fast::run_calls(pc as usize, &mut self.m.stack, stop, &mut cx) as u32;
                    (cur, lvl, fp, current_base) = (cx.cur, cx.lvl, cx.fp, cx.current_base);
                }
            }};
        }
        macro_rules! reload {
            () => {
                lvl = cur.level;
                fp = self.m.display.get(lvl as usize).copied().unwrap_or(0);
            };
        }
        // `dst := arr (idx)` and `arr (idx) := src` for the first `n`
        // indices (the instructions with one, two and more indices).
        macro_rules! load_index {
            ($d:ident, $arr:ident, $idx:ident, $n:expr, $span:ident) => {{
                // Scalars are copied out as such: a `Value` moved through
                // the native stack costs a drop call and a store stall.
                // The compact forms are tested one by one (a `match` on
                // the form was a jump table: an indirect branch).
                let got = match &self.m.stack[ix!(*$arr)] {
                    Value::Arr(a) => match a.offset(&$idx[..$n]) {
                        Some(o) => {
                            let data = a.data();
                            if let value::Elems::Reals(r) = data {
                                Got::Real(r[o])
                            } else if let value::Elems::Ints(v) = data {
                                Got::Int(v[o])
                            } else if let value::Elems::Bytes(b) = data {
                                Got::Int(b[o] as i64)
                            } else {
                                elem_slow(data, o)
                            }
                        }
                        None => Got::Fail("index check failed"),
                    },
                    _ => Got::Fail("access check failed"),
                };
                match got {
                    Got::Real(x) => {
                        self.put_real_ix(ix!(*$d), x);
                        continue;
                    }
                    Got::Int(x) => {
                        self.put_int_ix(ix!(*$d), x);
                        continue;
                    }
                    Got::Val(v) => {
                        self.put_ix(ix!(*$d), v);
                        continue;
                    }
                    Got::Fail(what) => Err(self.check_failed(what, *$span)),
                }
            }};
        }
        macro_rules! store_index {
            ($arr:ident, $idx:ident, $n:expr, $src:ident, $span:ident) => {{
                let i = ix!(*$src);
                // A scalar goes as such (see `Index`), anything else is
                // taken from its temporary.
                let val = match &mut self.m.stack[i] {
                    Value::Real(x) => Got::Real(*x),
                    Value::Int(x) => Got::Int(*x),
                    v => Got::Val(std::mem::take(v)),
                };
                let slot = ix!(*$arr);
                let r = match &mut self.m.stack[slot] {
                    Value::Arr(a) => {
                        match a.offset(&$idx[..$n]) {
                            Some(o) => {
                                // The compact forms one by one (see
                                // `load_index`).
                                match (val, a.data_mut()) {
                                    (Got::Real(x), value::ElemsMut::Reals(r)) => r[o] = x,
                                    (Got::Int(x), value::ElemsMut::Ints(v)) => v[o] = x,
                                    (Got::Int(x), value::ElemsMut::Bytes(b))
                                        if (0..=255).contains(&x) =>
                                    {
                                        b[o] = x as u8
                                    }
                                    (val, _) => store_slow(a, o, val),
                                }
                                Ok(())
                            }
                            None => Err("index check failed"),
                        }
                    }
                    _ => Err("access check failed"),
                };
                match r {
                    Ok(()) => continue,
                    Err(what) => Err(self.check_failed(what, *$span)),
                }
            }};
        }
        // A return of `$value` (an integer, or any value, or none): from a
        // call without `out` parameters the frame goes and the value lands
        // here; everything else takes the long way after the match.
        macro_rules! ret {
            ($value:expr) => {{
                let value: Result<i64, Option<Value>> = $value;
                let frame = if cur.all_in { frames.pop() } else { None };
                if let Some(frame) = frame {
                    self.pop_frame(&frame, cur, current_base);
                    cur = frame.code;
                    pc = frame.pc;
                    current_base = frame.current;
                    lvl = cur.level;
                    fp = frame.fp;
                    debug_assert_eq!(fp, self.m.display.get(lvl as usize).copied().unwrap_or(0));
                    if frame.dst != NO_DST {
                        match value {
                            Ok(n) => self.put_int_ix(frame.dst, n),
                            Err(v) => self.put_ix(frame.dst, v.unwrap_or_default()),
                        }
                    }
                    continue;
                }
                Err(Flow::Return(match value {
                    Ok(n) => Some(Value::Int(n)),
                    Err(v) => v,
                }))
            }};
        }
        loop {
            let op = &cur.ops[pc as usize];
            pc += 1;
            let r: R<()> = match op {
                // The instructions that cannot block, call or return go on
                // with the next one straight away (`continue`) when they
                // succeed; only the others pass the checks after the match.
                Op::Int(d, v) => {
                    self.put_int_ix(ix!(*d), *v);
                    continue;
                }
                Op::Real(d, v) => {
                    self.put_real_ix(ix!(*d), *v);
                    continue;
                }
                Op::Move(d, s) => {
                    let v = self.m.stack[ix!(*s)].clone();
                    self.put_ix(ix!(*d), v);
                    continue;
                }
                Op::IntBin {
                    op,
                    dst,
                    x,
                    y,
                    span,
                } => {
                    let (x, y) = (self.int_ix(ix!(*x)), self.int_ix(ix!(*y)));
                    match self.int_arith(*op, ix!(*dst), x, y, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::IntBinK {
                    op,
                    dst,
                    x,
                    k,
                    span,
                } => {
                    let x = self.int_ix(ix!(*x));
                    match self.int_arith(*op, ix!(*dst), x, *k, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::CmpK { op, dst, x, k } => {
                    let ord = self.order_k(ix!(*x), *k);
                    let r = holds(*op, ord);
                    self.put_int_ix(ix!(*dst), r as i64);
                    continue;
                }
                Op::IntNeg(d, a, span) => {
                    let x = self.int_ix(ix!(*a));
                    self.int_op(IntOp::Sub, 0, x, *span)
                        .map(|v| self.put_ix(ix!(*d), Value::Int(v)))
                }
                Op::ModBin {
                    op,
                    dst,
                    x,
                    y,
                    last,
                    span,
                } => {
                    let (x, y) = (self.int_ix(ix!(*x)), self.int_ix(ix!(*y)));
                    match crate::check::ir::modular(*op, x, y, *last) {
                        Some(v) => {
                            self.put_int_ix(ix!(*dst), v);
                            continue;
                        }
                        None => Err(self.check_failed("divide by zero", *span)),
                    }
                }
                Op::FloatBin { op, dst, x, y } => {
                    let x = self.m.stack[ix!(*x)].real();
                    let yv = &self.m.stack[ix!(*y)];
                    let v = value::float_op(*op, x, yv);
                    self.put_real_ix(ix!(*dst), v);
                    continue;
                }
                // `FloatBin` of the four plain operations, one instruction
                // each (no second dispatch on the operator).
                Op::RealAdd(d, a, b) => {
                    let v = self.real_ix(ix!(*a)) + self.real_ix(ix!(*b));
                    self.put_real_ix(ix!(*d), v);
                    continue;
                }
                Op::RealSub(d, a, b) => {
                    let v = self.real_ix(ix!(*a)) - self.real_ix(ix!(*b));
                    self.put_real_ix(ix!(*d), v);
                    continue;
                }
                Op::RealMul(d, a, b) => {
                    let v = self.real_ix(ix!(*a)) * self.real_ix(ix!(*b));
                    self.put_real_ix(ix!(*d), v);
                    continue;
                }
                Op::RealDiv(d, a, b) => {
                    let v = self.real_ix(ix!(*a)) / self.real_ix(ix!(*b));
                    self.put_real_ix(ix!(*d), v);
                    continue;
                }
                Op::ToReal(d, a) => {
                    let x = self.m.stack[ix!(*a)].real();
                    self.put_real_ix(ix!(*d), x);
                    continue;
                }
                Op::Cmp { op, dst, x, y } => {
                    let ord = self.order_ix(ix!(*x), ix!(*y));
                    let r = holds(*op, ord);
                    self.put_int_ix(ix!(*dst), r as i64);
                    continue;
                }
                Op::Eq { ne, dst, x, y } => {
                    let same = self.m.stack[ix!(*x)] == self.m.stack[ix!(*y)];
                    self.put_int_ix(ix!(*dst), (same != *ne) as i64);
                    continue;
                }
                Op::Logic { op, dst, x, y } => {
                    let (x, y) = (self.int_ix(ix!(*x)) != 0, self.int_ix(ix!(*y)) != 0);
                    let r = match op {
                        LogicOp::And | LogicOp::AndThen => x && y,
                        LogicOp::Or | LogicOp::OrElse => x || y,
                        LogicOp::Xor => x ^ y,
                    };
                    self.put_int_ix(ix!(*dst), r as i64);
                    continue;
                }
                Op::Not(d, a) => {
                    let x = self.int_ix(ix!(*a)) == 0;
                    self.put_int_ix(ix!(*d), x as i64);
                    continue;
                }
                Op::SameDiscriminants { x, record, n, span } => {
                    let (x, y) = (&self.m.stack[ix!(*x)], &self.m.stack[ix!(*record)]);
                    match self.same_discriminants(x, y, *n as usize, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::Variant(a, conds, span) => {
                    match self.variant_check(&self.m.stack[ix!(*a)], conds, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::RangeCheck(a, t, span) => {
                    let v = self.m.stack[ix!(*a)].clone();
                    match self.range_check(&v, *t, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::Index { dst, arr, ix, span } => {
                    let mut idx = [0i64; 4];
                    for (k, v) in ix.iter().enumerate() {
                        idx[k] = self.int_ix(ix!(*v));
                    }
                    load_index!(dst, arr, idx, ix.len(), span)
                }
                Op::Index1 { dst, arr, i, span } => {
                    let idx = [self.int_ix(ix!(*i))];
                    load_index!(dst, arr, idx, 1, span)
                }
                Op::Index2 {
                    dst,
                    arr,
                    ix: [i, j],
                    span,
                } => {
                    let idx = [self.int_ix(ix!(*i)), self.int_ix(ix!(*j))];
                    load_index!(dst, arr, idx, 2, span)
                }
                Op::StoreIndex { arr, ix, src, span } => {
                    let mut idx = [0i64; 4];
                    for (k, v) in ix.iter().enumerate() {
                        idx[k] = self.int_ix(ix!(*v));
                    }
                    store_index!(arr, idx, ix.len(), src, span)
                }
                Op::StoreIndex1 { arr, i, src, span } => {
                    let idx = [self.int_ix(ix!(*i))];
                    store_index!(arr, idx, 1, src, span)
                }
                Op::StoreIndex2 {
                    arr,
                    ix: [i, j],
                    src,
                    span,
                } => {
                    let idx = [self.int_ix(ix!(*i)), self.int_ix(ix!(*j))];
                    store_index!(arr, idx, 2, src, span)
                }
                Op::Field {
                    dst,
                    record,
                    field,
                    span,
                } => {
                    let got = self.m.stack[ix!(*record)]
                        .fields()
                        .map(|r| r[*field as usize].clone());
                    match got {
                        Some(v) => {
                            self.put_ix(ix!(*dst), v);
                            continue;
                        }
                        None => Err(self.check_failed("discriminant check failed", *span)),
                    }
                }
                Op::DerefField {
                    dst,
                    ptr,
                    field,
                    at_deref,
                    at_field,
                } => {
                    let got = match &self.m.stack[ix!(*ptr)] {
                        Value::Ptr(Some(o)) => o.with(|v| match v.fields() {
                            Some(r) => Ok(r[*field as usize].clone()),
                            None => Err(("discriminant check failed", *at_field)),
                        }),
                        _ => Err(("access check failed", *at_deref)),
                    };
                    match got {
                        Ok(v) => {
                            self.put_ix(ix!(*dst), v);
                            continue;
                        }
                        Err((what, span)) => Err(self.check_failed(what, span)),
                    }
                }
                Op::Null(d) => {
                    self.put_ix(ix!(*d), Value::Ptr(None));
                    continue;
                }
                Op::Slice {
                    dst,
                    base,
                    bounds: [l, h],
                    span,
                } => {
                    let (l, h) = (self.int_ix(ix!(*l)), self.int_ix(ix!(*h)));
                    let bi = ix!(*base);
                    let base = std::mem::take(&mut self.m.stack[bi]);
                    let r = self.slice_of(&base, l, h, *span);
                    self.m.stack[bi] = base;
                    r.map(|v| self.put_ix(ix!(*dst), v))
                }
                Op::Str(d, v) => {
                    self.put_ix(ix!(*d), v.clone());
                    continue;
                }
                Op::Cached(c) => {
                    if let Some(v) = c.value.get() {
                        self.put_ix(ix!(c.dst), v.clone());
                        pc = c.end;
                    }
                    continue;
                }
                Op::CacheFill(at, d) => {
                    if let Some(Op::Cached(c)) = cur.ops.get(*at as usize) {
                        let v = self.m.stack[ix!(*d)].clone();
                        // Set once: a second fill (none can happen) keeps
                        // the first value.
                        let _ = c.value.set(v);
                    }
                    continue;
                }
                Op::Concat(c) => {
                    let (xi, yi) = (ix!(c.x), ix!(c.y));
                    let x = if c.takes.0 {
                        std::mem::take(&mut self.m.stack[xi])
                    } else {
                        self.m.stack[xi].clone()
                    };
                    let y = if c.takes.1 {
                        std::mem::take(&mut self.m.stack[yi])
                    } else {
                        self.m.stack[yi].clone()
                    };
                    let (xe, ye) = c.elems;
                    self.concat(x, y, xe, ye, c.ty, c.span)
                        .map(|v| self.put_ix(ix!(c.dst), v))
                }
                Op::Attr(a) => {
                    let mut vals = [Value::Undef, Value::Undef];
                    for ((v, take), val) in a.args.iter().zip(a.temps.iter()).zip(&mut vals) {
                        let i = ix!(*v);
                        *val = if *take {
                            std::mem::take(&mut self.m.stack[i])
                        } else {
                            self.m.stack[i].clone()
                        };
                    }
                    let [a0, a1] = vals;
                    self.attr_of(a.op, a0, a1, a.ty, a.span)
                        .map(|v| self.put_ix(ix!(a.dst), v))
                }
                Op::Un { op, dst, x, span } => {
                    let v = self.m.stack[ix!(*x)].clone();
                    self.unary_of(*op, v, *span)
                        .map(|v| self.put_ix(ix!(*dst), v))
                }
                Op::ArrLogic {
                    op,
                    dst,
                    x,
                    y,
                    span,
                } => {
                    let (xi, yi) = (ix!(*x), ix!(*y));
                    self.arr_logic(*op, &self.m.stack[xi], &self.m.stack[yi], *span)
                        .map(|v| self.put_ix(ix!(*dst), v))
                }
                Op::TypeBound(d, t, last) => self.type_bounds(*t).map(|(l, h)| {
                    self.put_ix(ix!(*d), if *last { h } else { l });
                }),
                Op::Default(d, t, span) => self
                    .default_value(*t, *span)
                    .map(|v| self.put_ix(ix!(*d), v)),
                Op::Register {
                    dst,
                    addr,
                    ty,
                    span,
                } => self
                    .read_register(*addr, *ty, *span)
                    .map(|v| self.put_ix(ix!(*dst), v)),
                Op::Store(st) => {
                    let si = ix!(st.src);
                    let val = std::mem::take(&mut self.m.stack[si]);
                    let steps: Vec<Step> = st
                        .steps
                        .iter()
                        .map(|s| match s {
                            StoreStep::Index(ix, sp) => {
                                Step::Index(ix.iter().map(|v| self.int_ix(ix!(*v))).collect(), *sp)
                            }
                            StoreStep::Field(i) => Step::Field(*i),
                            StoreStep::Variant(conds, sp) => Step::Variant(conds.clone(), *sp),
                            StoreStep::Slice(l, h, sp) => {
                                Step::Slice(self.int_ix(ix!(*l)), self.int_ix(ix!(*h)), *sp)
                            }
                        })
                        .collect();
                    let root = match &st.root {
                        StoreRoot::Var(v) => Root::Slot(ix!(*v)),
                        StoreRoot::Deref(p, sp) => Root::Ptr(self.m.stack[ix!(*p)].clone(), *sp),
                        StoreRoot::Register(a, t, sp) => Root::Register(*a, *t, *sp),
                        StoreRoot::NotVariable(sp) => Root::NotVariable(*sp),
                    };
                    self.store(root, &steps, val, st.span)
                }
                Op::Raise(e, msg, span) => {
                    let m = msg.map(|m| self.m.stack[ix!(m)].clone());
                    Err(self.raise_stmt(*e, m, *span))
                }
                Op::Reraise(span) => Err(self.reraise(*span)),
                Op::Jump(t) => {
                    pc = *t;
                    fast!(false);
                    continue;
                }
                Op::JumpIfNot(c, t) => {
                    if self.int_ix(ix!(*c)) == 0 {
                        pc = *t;
                    }
                    continue;
                }
                Op::CmpKJumpNot { op, x, k, target } => {
                    let ord = self.order_k(ix!(*x), *k);
                    if !holds(*op, ord) {
                        pc = *target;
                    }
                    continue;
                }
                Op::CmpJumpNot { op, x, y, target } => {
                    let ord = self.order_ix(ix!(*x), ix!(*y));
                    if !holds(*op, ord) {
                        pc = *target;
                    }
                    continue;
                }
                Op::JumpIf(c, t) => {
                    if self.int_ix(ix!(*c)) != 0 {
                        pc = *t;
                    }
                    continue;
                }
                Op::Case {
                    x,
                    table,
                    others,
                    span,
                } => {
                    let v = self.int_ix(ix!(*x));
                    match table.iter().find(|(l, h, _)| *l <= v && v <= *h) {
                        Some((_, _, t)) => {
                            pc = *t;
                            Ok(())
                        }
                        None => match others {
                            Some(t) => {
                                pc = *t;
                                Ok(())
                            }
                            None => Err(self.check_failed("case choice not covered", *span)),
                        },
                    }
                }
                Op::ForStart {
                    var,
                    low,
                    high,
                    reverse,
                    exit,
                } => {
                    let (lo, hi) = (self.int_ix(ix!(*low)), self.int_ix(ix!(*high)));
                    if lo > hi {
                        pc = *exit;
                    } else {
                        self.put_int_ix(ix!(*var), if *reverse { hi } else { lo });
                    }
                    fast!(false);
                    continue;
                }
                Op::ForNext {
                    var,
                    low,
                    high,
                    reverse,
                    body,
                    span,
                } => {
                    let i = self.int_ix(ix!(*var));
                    let last = if *reverse {
                        self.int_ix(ix!(*low))
                    } else {
                        self.int_ix(ix!(*high))
                    };
                    if i == last {
                        continue;
                    }
                    self.put_int_ix(ix!(*var), if *reverse { i - 1 } else { i + 1 });
                    pc = *body;
                    match self.poll(*span) {
                        Ok(()) => {
                            fast!(false);
                            continue;
                        }
                        r => r,
                    }
                }
                Op::Poll(span) => self.poll(*span),
                // A motion service while another task's motion runs waits
                // for it (the services are a monitor).
                Op::CallNative(n)
                    if self.m.sched.active()
                        && self.is_service(n.f)
                        && self.m.clock.now() < self.robot_free_at(n.f) =>
                {
                    let until = self.robot_free_at(n.f);
                    self.m
                        .sched
                        .block(tasking::Wait::Delay(until), true, n.span);
                    Ok(())
                }
                Op::CallNative(n) => {
                    self.rerun();
                    let mut vals: Vec<Value> = n
                        .ops
                        .iter()
                        .map(|v| self.m.stack[self.sl(*v)].clone())
                        .collect();
                    self.call_native(n.f, &mut vals, n.span).map(|v| {
                        for &(i, slot) in n.outs.iter() {
                            let x = std::mem::take(&mut vals[i as usize]);
                            self.put(slot, x);
                        }
                        if let Some(d) = n.dst {
                            self.put(d, v.unwrap_or_default());
                        }
                    })
                }
                Op::Call {
                    function,
                    f,
                    ops,
                    span,
                    ..
                } => {
                    // (The result slot before the call: it changes the display.)
                    let (args, dst) = match (*function, ops.split_last()) {
                        (true, Some((d, args))) => (args, ix!(*d)),
                        _ => (&ops[..], NO_DST),
                    };
                    match self.push_call(*f, Args::Slots(args), (lvl, fp), *span) {
                        Ok(entered) => enter!(entered, dst),
                        Err(e) => Err(e),
                    }
                }
                Op::CallK {
                    f,
                    x: a,
                    add,
                    dst: d,
                    span,
                    arg_at: [start, end],
                } => {
                    let x = self.int_ix(ix!(*a));
                    // (Before the call: it changes the display.)
                    let dst = if d.level == NO_VAR.level {
                        NO_DST
                    } else {
                        ix!(*d)
                    };
                    let at = || Span {
                        start: *start,
                        end: *end,
                        context: span.context,
                    };
                    let entered = self
                        .int_value_at(IntOp::Add, x, *add as i64, at)
                        .and_then(|n| self.push_call(*f, Args::Int(n), (lvl, fp), *span));
                    match entered {
                        Ok(entered) => enter!(entered, dst),
                        Err(e) => Err(e),
                    }
                }
                Op::Return(x) => {
                    // Cloned, not taken: the value may be a variable of an
                    // enclosing frame. An integer goes as such (see `Index`).
                    let value = match x {
                        Some(x) => match &self.m.stack[ix!(*x)] {
                            Value::Int(n) => Ok(*n),
                            v => Err(Some(v.clone())),
                        },
                        None => Err(None),
                    };
                    ret!(value)
                }
                Op::ReturnIntBin { op, x, y, span } => {
                    let (x, y) = (self.int_ix(ix!(*x)), self.int_ix(ix!(*y)));
                    match self.int_value(*op, x, y, *span) {
                        Ok(n) => ret!(Ok(n)),
                        Err(e) => Err(e),
                    }
                }
                Op::FallOff => Err(Flow::Exit(FALL_OFF)),
                Op::Dispatch(catches, depth) => {
                    let occ = pending.take().expect("an occurrence to dispatch");
                    self.m.current.truncate(current_base + *depth as usize);
                    match catches.iter().find(|h| match &h.choices {
                        None => true,
                        Some(list) => list.contains(&occ.exc),
                    }) {
                        Some(h) => {
                            let occ: Rc<Occurrence> = Rc::from(occ);
                            if let Some(v) = h.occurrence {
                                self.put(v, Value::Occ(occ.clone()));
                            }
                            self.m.current.push(occ);
                            pc = h.target;
                            Ok(())
                        }
                        None => Err(Flow::Raise(occ)),
                    }
                }
                Op::PopCurrent => {
                    self.m.current.pop();
                    Ok(())
                }
                Op::TruncCurrent(n) => {
                    self.m.current.truncate(current_base + *n as usize);
                    Ok(())
                }
                Op::Delay(x, until, span) => self.op_delay(*x, *until, *span),
                Op::Activate(span) => self.op_activate(*span),
                Op::MasterEnter => {
                    self.tasking_on();
                    self.m.sched.me().masters.push(Vec::new());
                    Ok(())
                }
                Op::MasterLeave(span) => {
                    if self.dependents_done(false, *span) {
                        self.m.sched.me().masters.pop();
                    }
                    Ok(())
                }
                Op::MasterUnwind(span) => {
                    if self.dependents_done(false, *span) {
                        self.m.sched.me().masters.pop();
                        Err(Flow::Raise(pending.take().expect("an occurrence")))
                    } else {
                        Ok(())
                    }
                }
                Op::Settle => {
                    self.rerun();
                    if !self.m.sched.ready.is_empty() {
                        let me = self.m.sched.cur;
                        self.m.sched.make_ready(me);
                        self.m.sched.threads[me].reexec = true;
                        self.m.sched.switch = true;
                    }
                    Ok(())
                }
                Op::AwaitAll(span) => {
                    self.dependents_done(true, *span);
                    Ok(())
                }
                Op::Accept(a) => self.op_accept(a),
                Op::AcceptEnd(params) => {
                    self.end_rendezvous(params, None);
                    Ok(())
                }
                Op::AcceptFail => {
                    let occ = pending.take().expect("an occurrence");
                    self.end_rendezvous(&[], Some(occ.clone()));
                    Err(Flow::Raise(occ))
                }
                Op::EntryCall(ec) => self.op_entry_call(ec),
                Op::EntryDone(d) => match self.entry_done(d) {
                    Ok(None) => Ok(()),
                    Ok(Some(t)) => {
                        pc = t;
                        Ok(())
                    }
                    Err(e) => Err(e),
                },
                Op::ProtEntry(ec) => match self.op_prot_entry(ec) {
                    Ok(ProtStep::Body) => {
                        let sub = &self.c.prots[ec.kind as usize].entries[ec.entry as usize];
                        let body = sub.body.expect("an entry body");
                        match self.push_call(body, Args::Slots(&ec.ops), (lvl, fp), ec.span) {
                            Ok(e) => {
                                enter = Some(e);
                                Ok(())
                            }
                            Err(e) => Err(e),
                        }
                    }
                    Ok(ProtStep::Other) => {
                        // Skip the ProtDone after it.
                        pc = ec.other;
                        Ok(())
                    }
                    Ok(ProtStep::Wait) => Ok(()),
                    Err(e) => Err(e),
                },
                Op::ProtDone(obj, span) => self.serve(*obj, *span),
                Op::Requeue(r) => self.op_requeue(r),
                Op::Requeued(r) => match self.op_requeued(r) {
                    Ok(RequeueStep::Jump(t)) => {
                        pc = t;
                        Ok(())
                    }
                    Ok(RequeueStep::Body(f, slots)) => {
                        match self.push_call(f, Args::Slots(&slots), (lvl, fp), r.span) {
                            Ok(e) => {
                                // The body returns to this instruction.
                                pc -= 1;
                                enter = Some(e);
                                Ok(())
                            }
                            Err(e) => Err(e),
                        }
                    }
                    Ok(RequeueStep::Wait) => Ok(()),
                    Err(e) => Err(e),
                },
                Op::RequeueArgs(..) => Ok(()),
                Op::Select(sel) => match self.op_select(sel) {
                    Ok(Some(t)) => {
                        pc = t;
                        Ok(())
                    }
                    Ok(None) => Ok(()),
                    Err(e) => Err(e),
                },
                Op::AllocTask {
                    dst,
                    access,
                    ty,
                    span,
                }
                | Op::AllocDefault {
                    dst,
                    access,
                    ty,
                    span,
                } => self
                    .allocated_default(*access, *ty, *span)
                    .and_then(|v| self.allocate(v, *span))
                    .map(|v| self.put_ix(ix!(*dst), v)),
                Op::Alloc(d, x, span) => {
                    let v = self.take_slot(*x);
                    self.allocate(v, *span).map(|v| self.put_ix(ix!(*d), v))
                }
                Op::AggBounds(a) => {
                    let ranges: Option<Vec<(i64, i64)>> = a.ranges.as_ref().map(|rs| {
                        rs.iter()
                            .map(|[l, h]| (self.int_ix(ix!(*l)), self.int_ix(ix!(*h))))
                            .collect()
                    });
                    self.agg_bounds(
                        a.ty,
                        a.items as usize,
                        ranges.as_deref(),
                        a.has_others,
                        a.span,
                    )
                    .map(|b| {
                        let [lo, hi, n] = a.out;
                        self.put_ix(ix!(lo), Value::Int(b.lo));
                        self.put_ix(ix!(hi), Value::Int(b.hi));
                        self.put_ix(ix!(n), Value::Int(b.others));
                    })
                }
                Op::ArrayAgg(a) => {
                    let [lo, hi, n] = a.bounds;
                    let b = AggBounds {
                        lo: self.int_ix(ix!(lo)),
                        hi: self.int_ix(ix!(hi)),
                        others: self.int_ix(ix!(n)),
                    };
                    let others = a.others.as_ref().map(|p| self.agg_part_of(p));
                    let r = match &a.choices {
                        None => {
                            let items = a.items.iter().map(|v| self.take_slot(*v)).collect();
                            self.positional_agg(a.ty, &b, items, others, a.span)
                        }
                        Some(cs) => {
                            let choices = cs
                                .iter()
                                .map(|(rs, p)| {
                                    let rs = rs
                                        .iter()
                                        .map(|[l, h]| (self.int_ix(ix!(*l)), self.int_ix(ix!(*h))))
                                        .collect();
                                    (rs, self.agg_part_of(p))
                                })
                                .collect();
                            self.named_agg(a.ty, &b, choices, others, a.span)
                        }
                    };
                    r.map(|v| self.put_ix(ix!(a.dst), v))
                }
                Op::Record(r) => {
                    if r.plain {
                        // No discriminants: nothing to check or shape (as
                        // `record_agg` finds, without the type's lookup).
                        let v = self.record_from_slots(&r.fields);
                        self.put_ix(ix!(r.dst), v);
                        continue;
                    }
                    let fields = r.fields.iter().map(|v| self.take_slot(*v)).collect();
                    self.record_agg(r.ty, fields, r.span)
                        .map(|v| self.put_ix(ix!(r.dst), v))
                }
                Op::ListNew(d) => {
                    let empty = Value::Arr(Array::with_capacity(value::Form::Vals, 0));
                    self.put_ix(ix!(*d), empty);
                    Ok(())
                }
                Op::ListPush(l, x) => {
                    let v = self.take_slot(*x);
                    let li = ix!(*l);
                    if let Value::Arr(a) = &mut self.m.stack[li] {
                        a.push(v);
                    }
                    Ok(())
                }
                Op::Discriminant(d, i, span) => self
                    .discriminant(*i, *span)
                    .map(|v| self.put_ix(ix!(*d), v)),
                Op::PushDiscrs(vs) => {
                    let d = vs.iter().map(|v| self.m.stack[ix!(*v)].clone()).collect();
                    self.m.discrs.push(d);
                    Ok(())
                }
                Op::PopDiscrs => {
                    self.m.discrs.pop();
                    Ok(())
                }
                Op::ProgramError(msg, span) => Err(self.raise(check::PROGRAM_ERROR, *msg, *span)),
                Op::NoteMaster(v) => {
                    let code = self.master_code();
                    self.put_ix(ix!(*v), Value::Int(code));
                    Ok(())
                }
                Op::Abort(ts) => {
                    for t in ts.iter() {
                        let t = self.int_ix(ix!(*t)) as usize;
                        self.abort_task(t);
                    }
                    Ok(())
                }
            };
            // The slow way: a thread switch, a frame to enter, a return,
            // an exit or an exception. Then the running code may differ.
            'slow: {
                if self.m.sched.switch {
                    if nested {
                        // A nested call (a barrier) cannot wait: no thread is
                        // switched in the middle of the instruction that made it.
                        self.m.sched.switch = false;
                        let th = &mut self.m.sched.threads[self.m.sched.cur];
                        th.reexec = false;
                        return Err(self.raise(
                            check::PROGRAM_ERROR,
                            "potentially blocking operation in a barrier",
                            crate::diag::span(0, 0, 0),
                        ));
                    }
                    // The running thread blocked (or ended): save it, run the
                    // next ready one.
                    self.m.sched.switch = false;
                    let th = &mut self.m.sched.threads[self.m.sched.cur];
                    if std::mem::take(&mut th.reexec) {
                        pc -= 1;
                        th.rerun = true;
                    }
                    let me = self.m.sched.cur;
                    let regs =
                        self.save_regs(&mut frames, cur, pc, current_base, pending.take(), root);
                    if matches!(self.m.sched.threads[me].wait, tasking::Wait::Terminated) && me != 0
                    {
                        for (b, t) in regs.regions() {
                            self.free_frame(b, t);
                        }
                        self.end_thread(me, false);
                    } else {
                        self.m.sched.threads[me].regs = Some(regs);
                    }
                    self.swap_registers(me);
                    let next = loop {
                        if let Some(n) = self.m.sched.pick() {
                            break n;
                        }
                        if !self.idle() {
                            return Err(self.deadlock());
                        }
                    };
                    Live {
                        frames,
                        cur,
                        pc,
                        current_base,
                        pending,
                        root,
                    } = self.resume(level0, next)?;
                    break 'slow;
                }
                if let Some(entered) = enter.take() {
                    push_frame!(entered, NO_DST);
                    break 'slow;
                }
                let Err(flow) = r else { break 'slow };
                // Something other than the next instruction: a return, the
                // user's stop, or an exception.
                let mut flow = flow;
                loop {
                    match flow {
                        Flow::Exit(id) if id != FALL_OFF => {
                            // The user's stop (a service's `STOP_LABEL`): leave
                            // every frame.
                            while let Some(f) = frames.pop() {
                                self.pop_frame(&f, cur, current_base);
                                current_base = f.current;
                                cur = f.code;
                            }
                            return Err(Flow::Exit(id));
                        }
                        Flow::Exit(_) | Flow::Return(_) => {
                            let (value, fell_off) = match flow {
                                Flow::Return(v) => (v, false),
                                _ => (None, true),
                            };
                            let Some(frame) = frames.pop() else {
                                self.m.current.truncate(current_base);
                                if nested && !fell_off {
                                    return Err(Flow::Return(value));
                                }
                                if root.is_none() {
                                    // The end of the level-0 code (or a
                                    // nested call that fell off its end).
                                    return Ok(());
                                }
                                // The end of a task body.
                                self.task_ends(root, false);
                                Live {
                                    frames,
                                    cur,
                                    pc,
                                    current_base,
                                    pending,
                                    root,
                                } = self.next_thread(level0)?;
                                break;
                            };
                            let (back, dst) = call_site(frame.code, frame.pc);
                            // Copy-out values live in the frame.
                            let base = self.frame_base(cur);
                            let slots: Vec<(Var, Value)> = back
                                .iter()
                                .map(|&(i, v)| {
                                    (v, std::mem::take(&mut self.m.stack[base + i as usize]))
                                })
                                .collect();
                            let f = cur.func.expect("a called frame");
                            self.pop_frame(&frame, cur, current_base);
                            cur = frame.code;
                            pc = frame.pc;
                            current_base = frame.current;
                            let sub = &self.c.funcs[f as usize];
                            let r = if fell_off && sub.ret.is_some() {
                                Err(self.raise(
                                    check::PROGRAM_ERROR,
                                    format!("{} missing return", self.m.location(sub.span)),
                                    sub.span,
                                ))
                            } else {
                                for (slot, v) in slots {
                                    self.put(slot, v);
                                }
                                if let Some(d) = dst {
                                    self.put(d, value.unwrap_or_default());
                                }
                                Ok(())
                            };
                            match r {
                                Ok(()) => break,
                                Err(e) => flow = e,
                            }
                        }
                        Flow::Raise(mut occ) => {
                            // The calls of the compiled frames, innermost
                            // first, after a native's (see `Occurrence::chained`).
                            if !occ.chained {
                                occ.chain
                                    .extend(frames.iter().rev().map(|f| call_span(f.code, f.pc)));
                                occ.chained = true;
                            }
                            let at = pc - 1;
                            if let Some(r) =
                                cur.regions.iter().find(|r| r.start <= at && at < r.end)
                            {
                                pc = r.dispatch;
                                pending = Some(occ);
                                break;
                            }
                            let Some(frame) = frames.pop() else {
                                self.m.current.truncate(current_base);
                                if root.is_none() {
                                    return Err(Flow::Raise(occ));
                                }
                                // An exception ends a task silently.
                                self.task_ends(root, true);
                                Live {
                                    frames,
                                    cur,
                                    pc,
                                    current_base,
                                    pending,
                                    root,
                                } = self.next_thread(level0)?;
                                break;
                            };
                            self.pop_frame(&frame, cur, current_base);
                            cur = frame.code;
                            pc = frame.pc;
                            current_base = frame.current;
                            flow = Flow::Raise(occ);
                        }
                    }
                }
            }
            reload!();
        }
    }
}

/// `*slot = Int(x)`: a slot that holds an integer already is written in
/// place (nothing to drop).
#[inline(always)]
pub(super) fn put_int_in(slot: &mut Value, x: i64) {
    match slot {
        Value::Int(y) => *y = x,
        s => value::overwrite(s, Value::Int(x)),
    }
}

/// `*slot = Real(x)`, in place like [`put_int_in`].
#[inline(always)]
pub(super) fn put_real_in(slot: &mut Value, x: f64) {
    match slot {
        Value::Real(y) => *y = x,
        s => value::overwrite(s, Value::Real(x)),
    }
}

/// `*slot = v`, a scalar over a scalar written in place (no drop call).
#[inline(always)]
pub(super) fn set(slot: &mut Value, v: Value) {
    match (slot, v) {
        (Value::Int(y), Value::Int(x)) => *y = x,
        (Value::Real(y), Value::Real(x)) => *y = x,
        (s, v) => value::overwrite(s, v),
    }
}

/// An element read by an indexing instruction.
enum Got {
    Real(f64),
    Int(i64),
    Val(Value),
    Fail(&'static str),
}

/// Element `o` of an array held as general values.
#[inline(never)]
fn elem_slow(data: value::Elems, o: usize) -> Got {
    match data {
        value::Elems::Reals(r) => Got::Real(r[o]),
        value::Elems::Ints(v) => Got::Int(v[o]),
        value::Elems::Bytes(b) => Got::Int(b[o] as i64),
        value::Elems::Vals(vs) => match &vs[o] {
            Value::Real(x) => Got::Real(*x),
            Value::Int(x) => Got::Int(*x),
            v => Got::Val(v.clone()),
        },
    }
}

/// Element `o` of an array := `val` (a scalar or a value taken from its
/// temporary), for the forms `store_index` does not write inline: a
/// compact array of another form widens if it must.
#[inline(never)]
fn store_slow(d: &mut Array, o: usize, val: Got) {
    let v = match val {
        Got::Real(x) => Value::Real(x),
        Got::Int(x) => Value::Int(x),
        Got::Val(v) => v,
        Got::Fail(_) => return,
    };
    match d.data_mut() {
        value::ElemsMut::Vals(vs) => set(&mut vs[o], v),
        _ => d.set(o, v),
    }
}

/// Whether a comparison holds for operands ordered `ord`: a bit of the
/// comparison's mask (bit 0 Less, 1 Equal, 2 Greater), without the jump
/// table a `match` on the operator became (an indirect branch per test).
#[inline(always)]
pub(super) fn holds(o: CmpOp, ord: std::cmp::Ordering) -> bool {
    const MASKS: [u8; 6] = [
        0b010, // Eq
        0b101, // Ne
        0b001, // Lt
        0b011, // Le
        0b100, // Gt
        0b110, // Ge
    ];
    let i = match o {
        CmpOp::Eq => 0,
        CmpOp::Ne => 1,
        CmpOp::Lt => 2,
        CmpOp::Le => 3,
        CmpOp::Gt => 4,
        CmpOp::Ge => 5,
    };
    (MASKS[i] >> (ord as i8 + 1)) & 1 != 0
}

/// `Value::int` of a slot that holds no `Int` (rare: kept out of line so
/// that an integer operand is one tag test).
#[cold]
#[inline(never)]
fn int_slow(v: &Value) -> i64 {
    v.int()
}

/// `Value::real` of a slot that holds no `Real`.
#[cold]
#[inline(never)]
fn real_slow(v: &Value) -> f64 {
    v.real()
}

/// `Value::compare` of operands that are not both integers.
#[cold]
#[inline(never)]
fn compare_slow(x: &Value, y: &Value) -> std::cmp::Ordering {
    x.compare(y)
}
