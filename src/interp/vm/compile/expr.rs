//! Compiling expressions.

use super::*;

impl<'r> Compiler<'r> {
    /// A jump (to be patched) taken when the condition `c` is False: a
    /// comparison jumps itself.
    pub(in crate::interp::vm) fn jump_unless(&mut self, c: &Ex) -> usize {
        let op = match &c.kind {
            ExKind::Cmp(op, a, b) => match b.kind {
                ExKind::Int(k) => Op::CmpKJumpNot {
                    op: *op,
                    x: self.expr(a),
                    k,
                    target: 0,
                },
                _ => {
                    let x = self.left(a, b);
                    Op::CmpJumpNot {
                        op: *op,
                        x,
                        y: self.expr(b),
                        target: 0,
                    }
                }
            },
            _ => Op::JumpIfNot(self.expr(c), 0),
        };
        self.ops.push(op);
        self.ops.len() - 1
    }

    /// The operand holding `e`'s value: a variable itself, or a temporary.
    pub(in crate::interp::vm) fn expr(&mut self, e: &Ex) -> Var {
        if let ExKind::Var(v) = e.kind {
            return v;
        }
        let t = self.temp();
        self.expr_into(e, t);
        t
    }

    /// An operand for the left side of a binary operation whose right side
    /// is `right`: copied to a temporary when the right side may change it.
    pub(in crate::interp::vm) fn left(&mut self, e: &Ex, right: &Ex) -> Var {
        self.operand_before(e, [right])
    }

    /// An operand read before the operands `later`: copied to a temporary
    /// when one of them may change it.
    pub(in crate::interp::vm) fn operand_before<'e>(
        &mut self,
        e: &Ex,
        later: impl IntoIterator<Item = &'e Ex>,
    ) -> Var {
        let a = self.expr(e);
        if !self.is_temp(a) && later.into_iter().any(effects) {
            self.holds(e.ty);
            let t = self.temp();
            self.ops.push(Op::Move(t, a));
            return t;
        }
        a
    }

    /// Evaluates `e` into `dst`, which is written once, at the end.
    pub(in crate::interp::vm) fn expr_into(&mut self, e: &Ex, dst: Var) {
        self.holds(e.ty);
        let span = e.span;
        match &e.kind {
            ExKind::Int(v) => self.ops.push(Op::Int(dst, *v)),
            ExKind::Real(v) => self.ops.push(Op::Real(dst, *v)),
            ExKind::Var(v) => self.ops.push(Op::Move(dst, *v)),
            ExKind::IntBin(op, a, b) => {
                if let ExKind::Int(k) = b.kind {
                    let x = self.expr(a);
                    self.ops.push(Op::IntBinK {
                        op: *op,
                        dst,
                        x,
                        k,
                        span,
                    });
                    return;
                }
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::IntBin {
                    op: *op,
                    dst,
                    x,
                    y,
                    span,
                });
            }
            ExKind::IntNeg(a) => {
                let x = self.expr(a);
                self.ops.push(Op::IntNeg(dst, x, span));
            }
            ExKind::ModBin(op, a, b) => {
                let last = self.types.modular_last(e.ty).unwrap_or(u32::MAX);
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::ModBin {
                    op: *op,
                    dst,
                    x,
                    y,
                    last,
                    span,
                });
            }
            ExKind::FloatBin(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(match op {
                    FloatOp::Add => Op::RealAdd(dst, x, y),
                    FloatOp::Sub => Op::RealSub(dst, x, y),
                    FloatOp::Mul => Op::RealMul(dst, x, y),
                    FloatOp::Div => Op::RealDiv(dst, x, y),
                    _ => Op::FloatBin { op: *op, dst, x, y },
                });
            }
            ExKind::IntToFloat(a) => {
                let x = self.expr(a);
                self.ops.push(Op::ToReal(dst, x));
            }
            ExKind::Cmp(op, a, b) if matches!(b.kind, ExKind::Int(_)) => {
                let ExKind::Int(k) = b.kind else {
                    unreachable!()
                };
                let x = self.expr(a);
                self.ops.push(Op::CmpK { op: *op, dst, x, k });
            }
            ExKind::Cmp(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Cmp { op: *op, dst, x, y });
            }
            ExKind::Eq(ne, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Eq { ne: *ne, dst, x, y });
            }
            ExKind::Logic(op @ (LogicOp::AndThen | LogicOp::OrElse), a, b) => {
                // The result is built in a temporary: `dst` may be read by `b`.
                let t = self.temp();
                self.expr_into(a, t);
                let j = self.ops.len();
                self.ops.push(if *op == LogicOp::AndThen {
                    Op::JumpIfNot(t, 0)
                } else {
                    Op::JumpIf(t, 0)
                });
                self.expr_into(b, t);
                let end = self.here();
                self.patch(j, end);
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Logic(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Logic { op: *op, dst, x, y });
            }
            ExKind::Not(a) => {
                let x = self.expr(a);
                self.ops.push(Op::Not(dst, x));
            }
            ExKind::KeepDiscriminants(parts) => {
                let [v, target, when] = &**parts;
                let x = self.operand_before(v, [when, target]);
                let w = self.expr(when);
                let j = self.ops.len();
                self.ops.push(Op::JumpIfNot(w, 0));
                let cur = self.expr(target);
                let n = self.types.discriminants(target.ty).len() as u32;
                self.ops.push(Op::SameDiscriminants {
                    x,
                    record: cur,
                    n,
                    span,
                });
                let end = self.here();
                self.patch(j, end);
                self.ops.push(Op::Move(dst, x));
            }
            ExKind::Variant(a, i) => {
                let x = self.expr(a);
                if let Some(conds) = self.variant_of(a.ty, *i) {
                    self.ops.push(Op::Variant(x, conds, span));
                }
                self.ops.push(Op::Move(dst, x));
            }
            ExKind::RangeCheck(a, t) => {
                let x = self.expr(a);
                self.with_discrs(Op::RangeCheck(x, *t, span));
                self.ops.push(Op::Move(dst, x));
            }
            ExKind::Index(p, idx) => {
                // The array is read before the indices.
                let arr = self.operand_before(p, idx.iter());
                let mut ix = Vec::with_capacity(idx.len());
                for (k, x) in idx.iter().enumerate() {
                    let later_effects = idx[k + 1..].iter().any(effects);
                    let mut v = self.expr(x);
                    if later_effects && !self.is_temp(v) {
                        let t = self.temp();
                        self.ops.push(Op::Move(t, v));
                        v = t;
                    }
                    ix.push(v);
                }
                self.ops.push(match ix[..] {
                    [i] => Op::Index1 { dst, arr, i, span },
                    [i, j] => Op::Index2 {
                        dst,
                        arr,
                        ix: [i, j],
                        span,
                    },
                    _ => Op::Index {
                        dst,
                        arr,
                        ix: ix.into(),
                        span,
                    },
                });
            }
            ExKind::Field(p, i) => match &p.kind {
                ExKind::Deref(a) => {
                    let x = self.expr(a);
                    self.ops.push(Op::DerefField {
                        dst,
                        ptr: x,
                        field: *i,
                        at_deref: p.span,
                        at_field: span,
                    });
                }
                _ => {
                    let x = self.expr(p);
                    self.ops.push(Op::Field {
                        dst,
                        record: x,
                        field: *i,
                        span,
                    });
                }
            },
            ExKind::Null => self.ops.push(Op::Null(dst)),
            ExKind::Call(f, args) => self.call(*f, Some(args), Some(dst), span),
            ExKind::If(arms, els) => {
                let t = self.temp();
                let mut ends = Vec::new();
                for (c, v) in arms.iter() {
                    let x = self.expr(c);
                    let j = self.ops.len();
                    self.ops.push(Op::JumpIfNot(x, 0));
                    self.expr_into(v, t);
                    ends.push(self.ops.len());
                    self.ops.push(Op::Jump(0));
                    let next = self.here();
                    self.patch(j, next);
                }
                self.expr_into(els, t);
                let end = self.here();
                for j in ends {
                    self.patch(j, end);
                }
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Alloc(init, t) => self.allocator(e, init.as_deref(), *t, dst),
            ExKind::ArrayAgg(agg) if !self.caching && super::agg::static_agg(self.types, e) => {
                // Made once per run, then one reference count per use.
                let at = self.ops.len();
                self.ops.push(Op::Cached(Box::new(CachedOp {
                    value: std::cell::OnceCell::new(),
                    dst,
                    end: 0,
                })));
                self.caching = true;
                self.array_agg(agg, dst, span);
                self.caching = false;
                self.ops.push(Op::CacheFill(at as u32, dst));
                let end = self.here();
                self.patch(at, end);
            }
            ExKind::ArrayAgg(agg) => self.array_agg(agg, dst, span),
            ExKind::RecordAgg(fields) => self.record_agg(fields, e.ty, dst, span),
            ExKind::Discriminant(i) => match self.discrs.last() {
                Some(d) => self.ops.push(Op::Move(dst, d[*i as usize])),
                None => self.ops.push(Op::Discriminant(dst, *i, span)),
            },
            ExKind::Error => self
                .ops
                .push(Op::ProgramError("erroneous expression", span)),
            ExKind::Case(c) => {
                let (subj, arms, others) = &**c;
                let t = self.temp();
                let x = self.expr(subj);
                self.case(x, span, arms, others.as_ref(), |c, v| c.expr_into(v, t));
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Str(s) => self.ops.push(Op::Str(dst, Value::str(s))),
            ExKind::Slice(p, lh) => {
                let (l, h) = (&lh[0], &lh[1]);
                // The base is read before the bounds.
                let base = self.operand_before(p, [l, h]);
                let lo = self.left(l, h);
                let hi = self.expr(h);
                self.ops.push(Op::Slice {
                    dst,
                    base,
                    bounds: [lo, hi],
                    span,
                });
            }
            ExKind::Concat(a, b, xe, ye) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Concat(Box::new(ConcatOp {
                    dst,
                    x,
                    y,
                    elems: (*xe, *ye),
                    takes: (self.is_temp(x), self.is_temp(y) && x != y),
                    ty: e.ty,
                    span,
                })));
            }
            // `'Pos` and `'Val` are the value itself (a check of `'Val`'s
            // range is a node of its own).
            ExKind::Attr(AttrOp::Pos | AttrOp::Val, args) if args.len() == 1 => {
                self.expr_into(&args[0], dst)
            }
            ExKind::Attr(op, args) => {
                // Each argument before the next is evaluated (a later one
                // with effects must not change an earlier one).
                let mut vars = Vec::with_capacity(args.len());
                for (i, a) in args.iter().enumerate() {
                    vars.push(self.operand_before(a, &args[i + 1..]));
                }
                let temps = vars
                    .iter()
                    .enumerate()
                    .map(|(i, v)| self.is_temp(*v) && !vars[..i].contains(v))
                    .collect();
                self.ops.push(Op::Attr(Box::new(AttrInstr {
                    op: *op,
                    dst,
                    args: vars.into(),
                    temps,
                    ty: e.ty,
                    span,
                })));
            }
            ExKind::FloatNeg(_)
            | ExKind::IntAbs(_)
            | ExKind::FloatAbs(_)
            | ExKind::FloatToInt(_)
            | ExKind::Deref(_)
            | ExKind::ArrNot(_)
            | ExKind::ArrayConvert(..) => {
                let (op, a) = UnOp::of(e).expect("a unary operation");
                let x = self.expr(a);
                if matches!(op, UnOp::ArrayConvert(_)) {
                    self.with_discrs(Op::Un { op, dst, x, span });
                } else {
                    self.ops.push(Op::Un { op, dst, x, span });
                }
            }
            ExKind::ArrLogic(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::ArrLogic {
                    op: *op,
                    dst,
                    x,
                    y,
                    span,
                });
            }
            ExKind::TypeFirst(t) => self.ops.push(Op::TypeBound(dst, *t, false)),
            ExKind::TypeLast(t) => self.ops.push(Op::TypeBound(dst, *t, true)),
            ExKind::Default(t) => self.with_discrs(Op::Default(dst, *t, span)),
            ExKind::Register(a) => self.ops.push(Op::Register {
                dst,
                addr: *a,
                ty: e.ty,
                span,
            }),
            ExKind::InRanges(s, ranges, neg) => {
                // The value, then each range as `X >= Lo and then X <= Hi`
                // in turn until one holds it, as GNAT evaluates it (a bound
                // only when it is needed): a result slot of its own, so
                // that `dst` is written once, at the end.
                let x = self.operand_before(s, ranges.iter().flat_map(|(l, h)| [l, h]));
                let t = self.temp();
                self.ops.push(Op::Int(t, 0));
                let mut ends = Vec::new();
                for (l, h) in ranges.iter() {
                    let lo = self.expr(l);
                    let below = self.ops.len();
                    self.ops.push(Op::CmpJumpNot {
                        op: CmpOp::Ge,
                        x,
                        y: lo,
                        target: 0,
                    });
                    let hi = self.expr(h);
                    self.ops.push(Op::Cmp {
                        op: CmpOp::Le,
                        dst: t,
                        x,
                        y: hi,
                    });
                    ends.push(self.ops.len());
                    self.ops.push(Op::JumpIf(t, 0));
                    let next = self.here();
                    self.patch(below, next);
                }
                let end = self.here();
                for j in ends {
                    self.patch(j, end);
                }
                if *neg {
                    self.ops.push(Op::Not(dst, t));
                } else {
                    self.ops.push(Op::Move(dst, t));
                }
            }
        }
    }
}
