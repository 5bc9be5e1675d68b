//! Operators: binary and unary operators, their operand types, and static
//! folding.

use super::*;

impl Checker {
    pub(super) fn binary(
        &mut self,
        op: BinOp,
        a: &ast::Expr,
        b: &ast::Expr,
        want: Option<TypeId>,
        sp: Span,
    ) -> Ex {
        let lop = match op {
            BinOp::And => Some(LogicOp::And),
            BinOp::Or => Some(LogicOp::Or),
            BinOp::Xor => Some(LogicOp::Xor),
            _ => None,
        };
        if let Some(lop) = lop
            && let Some(t) = self.bool_array_operands(&[a, b], want)
        {
            let x = self.expr(a, Some(t));
            let x = self.coerce(x, t);
            let y = self.expr(b, Some(t));
            let y = self.coerce(y, t);
            return self.mk(
                ExKind::ArrLogic(lop, bx(x), bx(y)),
                self.tables.types.base(t),
                sp,
            );
        }
        if let Some(lop) = lop
            && let Some(t) = self.modular_operands(&[a, b], want)
        {
            let mop = match lop {
                LogicOp::And => ModOp::And,
                LogicOp::Or => ModOp::Or,
                _ => ModOp::Xor,
            };
            return self.modular_op(mop, a, b, t, sp);
        }
        match op {
            BinOp::And | BinOp::Or | BinOp::Xor | BinOp::AndThen | BinOp::OrElse => {
                let x = self.expr(a, Some(BOOLEAN));
                let x = self.coerce(x, BOOLEAN);
                let y = self.expr(b, Some(BOOLEAN));
                let y = self.coerce(y, BOOLEAN);
                let lop = match op {
                    BinOp::And => LogicOp::And,
                    BinOp::Or => LogicOp::Or,
                    BinOp::Xor => LogicOp::Xor,
                    BinOp::AndThen => LogicOp::AndThen,
                    _ => LogicOp::OrElse,
                };
                return self.mk(ExKind::Logic(lop, bx(x), bx(y)), BOOLEAN, sp);
            }
            _ => {}
        }
        // User-defined operators (for example "*" on Frame, "-" on Time).
        let user = self.op_funcs(op.symbol(), 2);
        let user_fit: Vec<FuncId> = user
            .into_iter()
            .filter(|f| {
                let ps: Vec<TypeId> = self.tables.funcs[*f as usize]
                    .params
                    .iter()
                    .map(|p| p.ty)
                    .collect();
                self.fits(a, ps[0])
                    && self.fits(b, ps[1])
                    && want.is_none_or(|w| {
                        self.tables.funcs[*f as usize]
                            .ret
                            .is_some_and(|r| self.tables.types.compatible(r, w))
                    })
            })
            .collect();
        let user_call = |this: &mut Self, f: FuncId| {
            let args = [
                ast::Arg {
                    name: None,
                    value: a.clone(),
                    span: a.span,
                },
                ast::Arg {
                    name: None,
                    value: b.clone(),
                    span: b.span,
                },
            ];
            match this.call(&[f], &args, want, false, sp, op.symbol()) {
                Some((f, args)) => {
                    let r = this.tables.funcs[f as usize].ret.unwrap_or(ERROR);
                    this.mk(ExKind::Call(this.tables.callee(f), args.into()), r, sp)
                }
                None => this.err_ex(sp),
            }
        };
        // `/=` of a type with a user-defined `=` is `not (A = B)`.
        let (user_fit, negate) = if op == BinOp::Ne && user_fit.is_empty() {
            let eq: Vec<FuncId> = self
                .op_funcs("=", 2)
                .into_iter()
                .filter(|f| {
                    let fi = &self.tables.funcs[*f as usize];
                    let (ret, p0, p1) = (fi.ret, fi.params[0].ty, fi.params[1].ty);
                    ret.is_some_and(|r| self.tables.types.base(r) == BOOLEAN)
                        && self.fits(a, p0)
                        && self.fits(b, p1)
                })
                .collect();
            let neg = !eq.is_empty();
            (eq, neg)
        } else {
            (user_fit, false)
        };
        let user_call = |this: &mut Self, f: FuncId| {
            let e = user_call(this, f);
            if negate && e.ty != ERROR {
                let esp = e.span;
                this.mk(ExKind::Not(bx(e)), BOOLEAN, esp)
            } else {
                e
            }
        };
        match op {
            BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => {
                let (li, ri) = (self.interps(a), self.interps(b));
                let predefined_ok = li.iter().any(|x| {
                    ri.iter().any(|y| {
                        self.tables.types.compatible(*x, *y) || self.tables.types.compatible(*y, *x)
                    })
                });
                if let Some(f) = user_fit.first()
                    && (!predefined_ok
                        || !li.iter().any(|t| {
                            self.tables.types.is_scalar(*t) || self.tables.types.is_array(*t)
                        }))
                {
                    return user_call(self, *f);
                }
                let t = self.common_type(&[a, b], INTEGER);
                let x = self.expr(a, Some(t));
                let y = self.expr(b, Some(t));
                if x.ty != ERROR
                    && y.ty != ERROR
                    && !self.tables.types.compatible(x.ty, y.ty)
                    && !self.tables.types.compatible(y.ty, x.ty)
                {
                    self.mismatch(op, &x, &y, a, b, sp);
                    return self.mk(ExKind::Error, BOOLEAN, sp);
                }
                let t = if self.tables.types.is_universal(x.ty) {
                    y.ty
                } else {
                    x.ty
                };
                let t = if self.tables.types.is_universal(t) {
                    if self.tables.types.is_float(t) {
                        FLOAT
                    } else {
                        INTEGER
                    }
                } else {
                    t
                };
                let x = self.coerce_base(x, t);
                let y = self.coerce_base(y, t);
                // A comparison of static values is static, and exact (for
                // named numbers, `0.1 + 0.2 = 0.3` is True).
                let order = match (self.shallow_static(&x), self.shallow_static(&y)) {
                    (Some(Static::Int(p)), Some(Static::Int(q))) => Some(p.cmp(&q)),
                    (Some(Static::Real(p)), Some(Static::Real(q))) => Some(p.cmp(&q)),
                    _ => None,
                };
                if let Some(o) = order {
                    use std::cmp::Ordering::*;
                    let r = match op {
                        BinOp::Eq => o == Equal,
                        BinOp::Ne => o != Equal,
                        BinOp::Lt => o == Less,
                        BinOp::Le => o != Greater,
                        BinOp::Gt => o == Greater,
                        _ => o != Less,
                    };
                    return self.mk(ExKind::Int(r as i64), BOOLEAN, sp);
                }
                if matches!(op, BinOp::Eq | BinOp::Ne) {
                    if self.limited_equality(t, op.symbol(), sp) {
                        return self.mk(ExKind::Error, BOOLEAN, sp);
                    }
                    return self.mk(ExKind::Eq(op == BinOp::Ne, bx(x), bx(y)), BOOLEAN, sp);
                }
                let ordered =
                    self.tables.types.is_scalar(t)
                        || self.tables.types.array(t).is_some_and(|(i, e, _)| {
                            i.len() == 1 && self.tables.types.is_discrete(e)
                        });
                if !ordered && t != ERROR {
                    self.err(diagnostics::ordering_undefined(
                        sp,
                        op.symbol(),
                        &self.tname(t),
                    ));
                }
                let c = match op {
                    BinOp::Lt => CmpOp::Lt,
                    BinOp::Le => CmpOp::Le,
                    BinOp::Gt => CmpOp::Gt,
                    _ => CmpOp::Ge,
                };
                self.mk(ExKind::Cmp(c, bx(x), bx(y)), BOOLEAN, sp)
            }
            BinOp::Cat => {
                let t = match want {
                    Some(w) if self.tables.types.is_array(w) => self.unconstrained_of(w),
                    _ => {
                        let c: Vec<TypeId> = self
                            .interps(a)
                            .into_iter()
                            .chain(self.interps(b))
                            .filter(|t| self.tables.types.is_array(*t))
                            .collect();
                        c.first()
                            .map(|t| self.unconstrained_of(*t))
                            .unwrap_or(STRING)
                    }
                };
                let el = self.tables.types.array(t).map(|x| x.1).unwrap_or(ERROR);
                let side = |this: &mut Self, e: &ast::Expr| -> (Ex, bool) {
                    if this.fits(e, t) && !matches!(e.kind, ExprKind::Char(_)) {
                        let x = this.expr(e, Some(t));
                        (this.coerce(x, t), false)
                    } else {
                        let x = this.expr(e, Some(el));
                        (this.coerce(x, el), true)
                    }
                };
                let (x, xe) = side(self, a);
                let (y, ye) = side(self, b);
                self.mk(ExKind::Concat(bx(x), bx(y), xe, ye), t, sp)
            }
            _ => {
                // Predefined arithmetic: both operands of one numeric type,
                // except `**` (Integer exponent) and Duration * Integer.
                let arith = self.arith_type(op, a, b, want);
                // A user operator whose result the context wants wins over a
                // predefined one whose result it does not (Ada.Real_Time's
                // `/` of two spans is an Integer).
                let unwanted = |this: &Self, t: TypeId| {
                    let t = if t == DURATION + 1000 { DURATION } else { t };
                    want.is_some_and(|w| {
                        w != ERROR
                            && !this.tables.types.compatible(t, w)
                            && !this.tables.types.compatible(w, t)
                    })
                };
                match arith {
                    Some(t) if unwanted(self, t) && !user_fit.is_empty() => {
                        user_call(self, user_fit[0])
                    }
                    Some(t) => self.arith(op, a, b, t, sp),
                    None => {
                        if let Some(f) = user_fit.first() {
                            return user_call(self, *f);
                        }
                        let x = self.expr(a, None);
                        let y = self.expr(b, None);
                        if x.ty != ERROR && y.ty != ERROR {
                            self.mismatch(op, &x, &y, a, b, sp);
                        }
                        self.err_ex(sp)
                    }
                }
            }
        }
    }

    fn mismatch(&mut self, op: BinOp, x: &Ex, y: &Ex, a: &ast::Expr, b: &ast::Expr, sp: Span) {
        let (xt, yt) = (self.tname(x.ty), self.tname(y.ty));
        let mut d = diagnostics::operands_mixed(sp, op.symbol(), &xt, &yt);
        let (xi, yi) = (
            self.tables.types.is_integer(x.ty),
            self.tables.types.is_integer(y.ty),
        );
        let (xf, yf) = (
            self.tables.types.is_float(x.ty),
            self.tables.types.is_float(y.ty),
        );
        let fname = |this: &Self, t: TypeId| {
            if this.tables.types.is_universal(t) {
                "Float".to_string()
            } else {
                this.tables.types.name(t).to_string()
            }
        };
        if xi && yf {
            d = d.with_hint(format!(
                "convert the integer: `{} ({}) {} {}`",
                fname(self, y.ty),
                self.snippet(a.span),
                op.symbol(),
                self.snippet(b.span)
            ));
        } else if xf
            && yi
            && matches!(y.kind, ExKind::Int(_))
            && self.tables.types.is_universal(y.ty)
        {
            d = d.with_hint(format!(
                "write the literal as a real: `{} {} {}.0`",
                self.snippet(a.span),
                op.symbol(),
                self.snippet(b.span)
            ));
        } else if xf && yi {
            d = d.with_hint(format!(
                "convert the integer: `{} {} {} ({})`",
                self.snippet(a.span),
                op.symbol(),
                fname(self, x.ty),
                self.snippet(b.span)
            ));
        } else if let Some(t) = [x.ty, y.ty]
            .into_iter()
            .find(|t| self.tables.types.is_hidden(*t))
        {
            let pkg = self.private_package(t);
            d = d.with_hint(format!(
                "`{}` is a private type: outside `{pkg}` only the operators `{pkg}` declares apply",
                self.tname(t)
            ));
        }
        self.err(d);
    }

    fn arith_type(
        &mut self,
        op: BinOp,
        a: &ast::Expr,
        b: &ast::Expr,
        want: Option<TypeId>,
    ) -> Option<TypeId> {
        let (li, ri) = (self.interps(a), self.interps(b));
        if op == BinOp::Pow {
            if !ri.iter().any(|t| self.tables.types.is_integer(*t)) {
                return None;
            }
            if let Some(w) = want
                && self.tables.types.is_numeric(w)
                && self.fits(a, w)
            {
                return Some(w);
            }
            return li
                .iter()
                .copied()
                .find(|t| self.tables.types.is_numeric(*t) && !self.tables.types.is_universal(*t))
                .or(li
                    .iter()
                    .copied()
                    .find(|t| self.tables.types.is_numeric(*t)));
        }
        let int_only = matches!(op, BinOp::Mod | BinOp::Rem);
        let ok = |this: &Self, t: TypeId| {
            this.tables.types.is_numeric(t) && (!int_only || this.tables.types.is_integer(t))
        };
        if let Some(w) = want
            && ok(self, w)
            && !self.tables.types.is_universal(w)
            && self.fits(a, w)
            && self.fits(b, w)
        {
            return Some(w);
        }
        for &t in li.iter().chain(ri.iter()) {
            if ok(self, t)
                && !self.tables.types.is_universal(t)
                && self.fits(a, t)
                && self.fits(b, t)
            {
                return Some(t);
            }
        }
        // Duration * Integer, Integer * Duration, Duration / Integer.
        if matches!(op, BinOp::Mul | BinOp::Div) {
            let dl = li.iter().any(|t| self.tables.types.base(*t) == DURATION);
            let dr = ri.iter().any(|t| self.tables.types.base(*t) == DURATION);
            let il = li.iter().any(|t| self.tables.types.is_integer(*t));
            let ir = ri.iter().any(|t| self.tables.types.is_integer(*t));
            if (dl && ir) || (op == BinOp::Mul && il && dr) {
                return Some(DURATION + 1000);
            }
        }
        if li.contains(&UNIV_INT) && ri.contains(&UNIV_INT) {
            return Some(UNIV_INT);
        }
        if li.contains(&UNIV_REAL) && ri.contains(&UNIV_REAL) && !int_only {
            return Some(UNIV_REAL);
        }
        // root_real * root_integer (and / by root_integer) for named numbers.
        if (op == BinOp::Mul
            && ((li.contains(&UNIV_REAL) && ri.contains(&UNIV_INT))
                || (li.contains(&UNIV_INT) && ri.contains(&UNIV_REAL))))
            || (op == BinOp::Div && li.contains(&UNIV_REAL) && ri.contains(&UNIV_INT))
        {
            return Some(UNIV_REAL);
        }
        None
    }

    fn arith(&mut self, op: BinOp, a: &ast::Expr, b: &ast::Expr, t: TypeId, sp: Span) -> Ex {
        if t == DURATION + 1000 {
            // Duration scaled by an integer.
            let (x, y) = if self
                .interps(a)
                .iter()
                .any(|t| self.tables.types.base(*t) == DURATION)
            {
                let x = self.expr(a, Some(DURATION));
                let x = self.coerce(x, DURATION);
                let y = self.expr(b, Some(INTEGER));
                let y = self.coerce(y, INTEGER);
                let ysp = y.span;
                (x, self.mk(ExKind::IntToFloat(bx(y)), DURATION, ysp))
            } else {
                let x = self.expr(a, Some(INTEGER));
                let x = self.coerce(x, INTEGER);
                let y = self.expr(b, Some(DURATION));
                let y = self.coerce(y, DURATION);
                let xsp = x.span;
                (self.mk(ExKind::IntToFloat(bx(x)), DURATION, xsp), y)
            };
            let fop = if op == BinOp::Mul {
                FloatOp::DurMul
            } else {
                FloatOp::DurDiv
            };
            return self.mk(ExKind::FloatBin(fop, bx(x), bx(y)), DURATION, sp);
        }
        let base = self.tables.types.base(t);
        if self.tables.types.modulus(base).is_some() {
            let mop = match op {
                BinOp::Add => ModOp::Add,
                BinOp::Sub => ModOp::Sub,
                BinOp::Mul => ModOp::Mul,
                BinOp::Div => ModOp::Div,
                BinOp::Mod => ModOp::Mod,
                BinOp::Rem => ModOp::Rem,
                _ => ModOp::Pow,
            };
            return self.modular_op(mop, a, b, t, sp);
        }
        if op == BinOp::Pow {
            let x = self.expr(a, Some(t));
            let x = self.coerce_base(x, base);
            let y = self.expr(b, Some(INTEGER));
            let y = self.coerce(
                y,
                if self.tables.types.is_float(t) {
                    INTEGER
                } else {
                    NATURAL
                },
            );
            let e = if self.tables.types.is_float(t) {
                self.mk(ExKind::FloatBin(FloatOp::PowI, bx(x), bx(y)), base, sp)
            } else {
                self.mk(ExKind::IntBin(IntOp::Pow, bx(x), bx(y)), base, sp)
            };
            return self.fold(e);
        }
        let x = self.expr(a, Some(t));
        let y = self.expr(b, Some(t));
        // Both operands static: the result is computed exactly, as Ada's
        // static expressions are (`Integer'Last + 1 - 1` is fine); only the
        // value of the whole static expression must fit its type, which
        // `coerce` checks where it is used.
        let static_operands = self.shallow_static(&x).is_some()
            && self.shallow_static(&y).is_some()
            && self.tables.types.compatible(x.ty, base)
            && self.tables.types.compatible(y.ty, base);
        let (x, y) = if static_operands {
            let (mut x, mut y) = (x, y);
            x.ty = base;
            y.ty = base;
            (x, y)
        } else {
            (self.coerce_base(x, base), self.coerce_base(y, base))
        };
        if self.tables.types.is_float(t) {
            let fop = match op {
                BinOp::Add => FloatOp::Add,
                BinOp::Sub => FloatOp::Sub,
                BinOp::Mul => FloatOp::Mul,
                _ => FloatOp::Div,
            };
            let fop = if self.tables.types.whole_ns(base) {
                fop.on_duration()
            } else {
                fop
            };
            let e = self.mk(ExKind::FloatBin(fop, bx(x), bx(y)), base, sp);
            self.fold(e)
        } else {
            let iop = match op {
                BinOp::Add => IntOp::Add,
                BinOp::Sub => IntOp::Sub,
                BinOp::Mul => IntOp::Mul,
                BinOp::Div => IntOp::Div,
                BinOp::Mod => IntOp::Mod,
                _ => IntOp::Rem,
            };
            let e = self.mk(ExKind::IntBin(iop, bx(x), bx(y)), base, sp);
            self.fold(e)
        }
    }

    /// `a op b` of the modular type `t`: each operand a value of the type
    /// (a static one in 0 .. modulus - 1, RM 4.9(35)), the exponent of
    /// `**` a Natural; folded when both are static.
    fn modular_op(&mut self, op: ModOp, a: &ast::Expr, b: &ast::Expr, t: TypeId, sp: Span) -> Ex {
        let base = self.tables.types.base(t);
        let x = self.expr(a, Some(base));
        let x = self.coerce_base(x, base);
        let y = if op == ModOp::Pow {
            let y = self.expr(b, Some(INTEGER));
            self.coerce(y, NATURAL)
        } else {
            let y = self.expr(b, Some(base));
            self.coerce_base(y, base)
        };
        if x.ty == ERROR || y.ty == ERROR {
            return self.err_ex(sp);
        }
        let e = self.mk(ExKind::ModBin(op, bx(x), bx(y)), base, sp);
        self.fold(e)
    }

    /// The modular type of a logical operator's operands (`R and Mask`,
    /// `not R`): the one wanted, or one every operand can have; None for
    /// Boolean operands.
    fn modular_operands(&mut self, ops: &[&ast::Expr], want: Option<TypeId>) -> Option<TypeId> {
        if let Some(w) = want {
            return self.tables.types.modulus(w).is_some().then_some(w);
        }
        let cands: Vec<TypeId> = ops.iter().flat_map(|e| self.interps(e)).collect();
        cands.into_iter().find(|t| {
            self.tables.types.modulus(*t).is_some() && ops.iter().all(|e| self.fits(e, *t))
        })
    }

    /// The value of `e` when it is a static leaf: a literal (every static
    /// operation is folded into one as soon as it is checked) or a scalar
    /// type's bound. Constant time, so folding a chain stays linear.
    pub(in crate::check) fn shallow_static(&self, e: &Ex) -> Option<Static> {
        match &e.kind {
            ExKind::Int(_) | ExKind::Real(_) | ExKind::TypeFirst(_) | ExKind::TypeLast(_) => {
                self.static_value(e)
            }
            _ => None,
        }
    }

    /// A real literal node for a static value, remembering its exact value
    /// for the static expressions it is part of.
    pub(in crate::check) fn real_lit(&mut self, v: exact::Exact, ty: TypeId, sp: Span) -> Ex {
        let f = exact::to_f64(&v);
        self.exact_reals.insert((sp.start, sp.end, sp.context), v);
        self.mk(ExKind::Real(f), ty, sp)
    }

    /// An operation whose operands are static leaves becomes a literal of
    /// its exact value. An integer value of a type with its own range is
    /// folded only inside that range (the run-time check would raise); an
    /// `Integer` intermediate may leave the 32-bit range, and `coerce`
    /// refuses a final value outside it.
    pub(super) fn fold(&mut self, e: Ex) -> Ex {
        let leaves = match &e.kind {
            ExKind::IntBin(_, a, b) | ExKind::ModBin(_, a, b) | ExKind::FloatBin(_, a, b) => {
                self.shallow_static(a).is_some() && self.shallow_static(b).is_some()
            }
            ExKind::IntNeg(a) | ExKind::FloatNeg(a) | ExKind::IntAbs(a) | ExKind::FloatAbs(a) => {
                self.shallow_static(a).is_some()
            }
            _ => false,
        };
        if !leaves {
            return e;
        }
        let base = self.tables.types.base(e.ty);
        match self.static_value(&e) {
            Some(Static::Int(v)) => {
                let info = self.tables.types.get(base);
                let fits = if base == INTEGER || self.tables.types.is_universal(base) {
                    i64::try_from(v).is_ok()
                } else {
                    match (info.range.is_some(), info.static_range) {
                        (false, _) => i64::try_from(v).is_ok(),
                        (true, Some((l, h))) => l <= v && v <= h,
                        (true, None) => false,
                    }
                };
                if fits {
                    self.mk(ExKind::Int(v as i64), e.ty, e.span)
                } else {
                    e
                }
            }
            Some(Static::Real(r)) if !exact::overflows(&r) => self.real_lit(r, e.ty, e.span),
            _ => e,
        }
    }

    /// The Boolean array type of a logical operator's operands: the one
    /// wanted, or one an operand can have; None for Boolean operands.
    fn bool_array_operands(&mut self, ops: &[&ast::Expr], want: Option<TypeId>) -> Option<TypeId> {
        if let Some(w) = want {
            return self.tables.types.is_bool_array(w).then_some(w);
        }
        let cands: Vec<TypeId> = ops.iter().flat_map(|e| self.interps(e)).collect();
        cands
            .into_iter()
            .find(|t| self.tables.types.is_bool_array(*t))
    }

    pub(super) fn unary(&mut self, op: UnOp, a: &ast::Expr, want: Option<TypeId>, sp: Span) -> Ex {
        if op == UnOp::Not
            && let Some(t) = self.bool_array_operands(&[a], want)
        {
            let x = self.expr(a, Some(t));
            let x = self.coerce(x, t);
            return self.mk(ExKind::ArrNot(bx(x)), self.tables.types.base(t), sp);
        }
        if op == UnOp::Not
            && let Some(t) = self.modular_operands(&[a], want)
        {
            // `not X` is `(modulus - 1) - X` (RM 4.5.6(5)).
            let x = self.expr(a, Some(t));
            return self.modular_unary(true, x, t, sp);
        }
        if op == UnOp::Not {
            let x = self.expr(a, Some(BOOLEAN));
            let x = self.coerce(x, BOOLEAN);
            return self.mk(ExKind::Not(bx(x)), BOOLEAN, sp);
        }
        // A user-defined `"-"`, `"+"` or `"abs"` on a non-numeric type (a
        // record, say).
        if !self
            .interps(a)
            .iter()
            .any(|t| self.tables.types.is_numeric(*t))
        {
            let user: Vec<FuncId> = self
                .op_funcs(op.symbol(), 1)
                .into_iter()
                .filter(|f| {
                    let fi = &self.tables.funcs[*f as usize];
                    let (p, r) = (fi.params[0].ty, fi.ret);
                    self.fits(a, p)
                        && want
                            .is_none_or(|w| r.is_some_and(|r| self.tables.types.compatible(r, w)))
                })
                .collect();
            if !user.is_empty() {
                let args = [ast::Arg {
                    name: None,
                    value: a.clone(),
                    span: a.span,
                }];
                return match self.call(&user, &args, want, false, sp, op.symbol()) {
                    Some((f, args)) => {
                        let r = self.tables.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(self.tables.callee(f), args.into()), r, sp)
                    }
                    None => self.err_ex(sp),
                };
            }
        }
        let t = match want {
            Some(w) if self.tables.types.is_numeric(w) && self.fits(a, w) => w,
            _ => {
                let is = self.interps(a);
                is.iter()
                    .copied()
                    .find(|t| {
                        self.tables.types.is_numeric(*t) && !self.tables.types.is_universal(*t)
                    })
                    .or(is.first().copied())
                    .unwrap_or(ERROR)
            }
        };
        let x = self.expr(a, Some(t));
        if x.ty == ERROR {
            return x;
        }
        if let Some(mt) = [t, x.ty]
            .into_iter()
            .find(|m| self.tables.types.modulus(*m).is_some())
        {
            return match op {
                UnOp::Neg => self.modular_unary(false, x, mt, sp),
                // `+X` and `abs X` of a modular value are X.
                _ => {
                    let x = self.coerce_base(x, mt);
                    Ex { span: sp, ..x }
                }
            };
        }
        if !self.tables.types.is_numeric(x.ty) {
            self.err(diagnostics::operator_needs_number(
                sp,
                op.symbol(),
                &self.tname(x.ty),
            ));
            return self.err_ex(sp);
        }
        let ty = if self.tables.types.is_universal(x.ty) {
            x.ty
        } else {
            self.tables.types.base(x.ty)
        };
        let x = if self.tables.types.is_universal(x.ty) || self.shallow_static(&x).is_some() {
            // A static operand may be an intermediate outside the type
            // (`-(2 ** 31)`): the folded result is what must fit.
            Ex { ty, ..x }
        } else {
            self.coerce(x, ty)
        };
        let float = self.tables.types.is_float(ty);
        let kind = match (op, float) {
            (UnOp::Plus, _) => return Ex { span: sp, ..x },
            (UnOp::Neg, false) => ExKind::IntNeg(bx(x)),
            (UnOp::Neg, true) => ExKind::FloatNeg(bx(x)),
            (UnOp::Abs, false) => ExKind::IntAbs(bx(x)),
            _ => ExKind::FloatAbs(bx(x)),
        };
        let e = self.mk(kind, ty, sp);
        self.fold(e)
    }

    /// `-X` (`0 - X`) and, `not`, `not X` (`(N - 1) - X`) of the
    /// checked operand `x` of the modular type `t`.
    fn modular_unary(&mut self, not: bool, x: Ex, t: TypeId, sp: Span) -> Ex {
        let base = self.tables.types.base(t);
        let x = self.coerce_base(x, base);
        if x.ty == ERROR {
            return self.err_ex(sp);
        }
        let from = if not {
            self.tables.types.modulus(base).unwrap_or(1) - 1
        } else {
            0
        };
        let k = self.mk(ExKind::Int(from), base, sp);
        let e = self.mk(ExKind::ModBin(ModOp::Sub, bx(k), bx(x)), base, sp);
        self.fold(e)
    }
}
