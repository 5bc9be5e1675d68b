//! Attributes of types and objects (`'Image`, `'First`, `'Range`, ...).

use super::*;

impl Checker {
    pub(super) fn attribute(
        &mut self,
        p: &ast::Expr,
        a: &ast::Ident,
        args: &[ast::Expr],
        want: Option<TypeId>,
        sp: Span,
    ) -> Ex {
        let key = a.key.as_ref();
        if matches!(key, "count" | "callable" | "terminated")
            && let Some(x) = self.task_attribute(p, key, sp)
        {
            return x;
        }
        let type_prefix = self.denote_quiet_type(p);
        // Of a private type where its full view is hidden: none.
        let prefix_type = match type_prefix {
            Some(t) => Some(t),
            None => self.interps(p).first().copied(),
        };
        // `B'Constrained` of an object is the partial view's (RM 3.7.2).
        if let Some(t) = prefix_type
            && self.tables.types.is_hidden(t)
            && !(key == "constrained" && type_prefix.is_none())
        {
            let pkg = self.private_package(t);
            let what = format!("its attribute `'{}`", a.name);
            self.err(diagnostics::private_full_view(
                sp,
                &what,
                &self.tname(t),
                &pkg,
            ));
            return self.err_ex(sp);
        }
        let arg = |this: &mut Self, i: usize, t: Option<TypeId>| -> Ex {
            match args.get(i) {
                Some(x) => {
                    let v = this.expr(x, t);
                    match t {
                        Some(t) => this.coerce(v, t),
                        None => v,
                    }
                }
                None => {
                    this.err(diagnostics::attribute_needs_argument(sp, &a.name));
                    this.err_ex(sp)
                }
            }
        };
        let dim = |this: &mut Self| -> u8 {
            match args.first() {
                None => 1,
                Some(x) => {
                    let v = this.expr(x, Some(UNIV_INT));
                    match this.static_value(&v) {
                        Some(Static::Int(n)) if n >= 1 => n as u8,
                        _ => {
                            this.err(diagnostics::dimension_not_static(x.span));
                            1
                        }
                    }
                }
            }
        };
        if let Some(t) = type_prefix {
            let base = self.tables.types.base(t);
            let scalar = self.tables.types.is_scalar(t);
            match key {
                "first" | "last" if scalar => {
                    let k = if key == "first" {
                        ExKind::TypeFirst(t)
                    } else {
                        ExKind::TypeLast(t)
                    };
                    return self.mk(k, t, sp);
                }
                "first" | "last" | "length"
                    if self.tables.types.array(t).is_some_and(|x| x.2.is_some()) =>
                {
                    let d = dim(self) as usize;
                    let (idx, bounds) = self
                        .tables
                        .types
                        .array(t)
                        .map(|(i, _, b)| (i.to_vec(), b.cloned().unwrap_or_default()))
                        .unwrap_or_default();
                    let Some((lo, hi)) = bounds.get(d - 1).cloned() else {
                        self.err(diagnostics::no_such_dimension(sp));
                        return self.err_ex(sp);
                    };
                    let it = idx[d - 1];
                    return match key {
                        "first" => Ex {
                            ty: it,
                            span: sp,
                            ..lo
                        },
                        "last" => Ex {
                            ty: it,
                            span: sp,
                            ..hi
                        },
                        _ => {
                            let len = self.mk(
                                ExKind::IntBin(
                                    IntOp::Add,
                                    bx(self.mk(
                                        ExKind::IntBin(IntOp::Sub, bx(hi), bx(lo)),
                                        UNIV_INT,
                                        sp,
                                    )),
                                    bx(Ex::int(1)),
                                ),
                                UNIV_INT,
                                sp,
                            );
                            self.mk(
                                ExKind::Attr(AttrOp::Max, Box::new(vec![len, Ex::int(0)])),
                                UNIV_INT,
                                sp,
                            )
                        }
                    };
                }
                "image" if scalar => {
                    let x = arg(self, 0, Some(base));
                    return self.image(x, base, sp);
                }
                "value" if scalar => {
                    let x = arg(self, 0, Some(STRING));
                    let op = if self.tables.types.is_float(t) {
                        AttrOp::ValueFloat
                    } else if self.tables.types.is_integer(t) {
                        AttrOp::ValueInt
                    } else {
                        AttrOp::ValueEnum(base)
                    };
                    // 'Value yields the base type; only an assignment checks the subtype.
                    return self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                }
                "pos" if self.tables.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(base));
                    return self.mk(ExKind::Attr(AttrOp::Pos, Box::new(vec![x])), UNIV_INT, sp);
                }
                "val" if self.tables.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(UNIV_INT));
                    let x = if self.tables.types.is_universal(x.ty) {
                        Ex { ty: INTEGER, ..x }
                    } else {
                        x
                    };
                    if !self.tables.types.is_integer(x.ty) && x.ty != ERROR {
                        self.err(diagnostics::val_needs_integer(x.span));
                    }
                    // `S'Val` is a function of S's base type (RM 3.5.5): a
                    // position outside a subtype's range is no error.
                    if let (Some(Static::Int(v)), Some((l, h))) = (
                        self.static_value(&x),
                        self.tables.types.discrete_bounds(base),
                    ) && (v < l || v > h)
                    {
                        self.err(diagnostics::not_a_position(
                            x.span,
                            v,
                            self.tables.types.name(base),
                            l,
                            h,
                        ));
                    }
                    let v = self.mk(ExKind::Attr(AttrOp::Val, Box::new(vec![x])), base, sp);
                    return self.coerce_force_check(v, base);
                }
                "modulus" if self.tables.types.modulus(t).is_some() => {
                    let n = self.tables.types.modulus(t).unwrap_or(1);
                    return self.mk(ExKind::Int(n), UNIV_INT, sp);
                }
                // A modular type's successor of its last value is its
                // first: `S'Succ (X)` is `X + 1`, wrapping (RM 3.5(22)).
                "succ" | "pred" if self.tables.types.modulus(t).is_some() => {
                    let x = arg(self, 0, Some(base));
                    if x.ty == ERROR {
                        return self.err_ex(sp);
                    }
                    let op = if key == "succ" {
                        ModOp::Add
                    } else {
                        ModOp::Sub
                    };
                    let one = self.mk(ExKind::Int(1), base, sp);
                    let e = self.mk(ExKind::ModBin(op, bx(x), bx(one)), base, sp);
                    return self.fold(e);
                }
                "succ" | "pred" if self.tables.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(base));
                    let op = if key == "succ" {
                        AttrOp::Succ
                    } else {
                        AttrOp::Pred
                    };
                    // Past the base type's end with a static argument: a
                    // compile-time error in GNAT too.
                    if let (Some(Static::Int(v)), Some((l, h))) = (
                        self.static_value(&x),
                        self.tables.types.discrete_bounds(base),
                    ) && ((op == AttrOp::Succ && v >= h) || (op == AttrOp::Pred && v <= l))
                    {
                        let (end, which) = if op == AttrOp::Succ {
                            ("last", "Succ")
                        } else {
                            ("first", "Pred")
                        };
                        self.err(diagnostics::no_successor(
                            x.span,
                            which,
                            end,
                            self.tables.types.name(base),
                        ));
                    }
                    let v = self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                    return self.coerce_force_check(v, base);
                }
                "min" | "max" if scalar => {
                    let x = arg(self, 0, Some(base));
                    let y = arg(self, 1, Some(base));
                    let op = match (key, self.tables.types.is_float(t)) {
                        ("min", false) => AttrOp::Min,
                        ("max", false) => AttrOp::Max,
                        ("min", true) => AttrOp::FloatMin,
                        _ => AttrOp::FloatMax,
                    };
                    return self.mk(ExKind::Attr(op, Box::new(vec![x, y])), base, sp);
                }
                "floor" | "ceiling" | "truncation" | "rounding"
                    if self.tables.types.is_float(t) =>
                {
                    let x = arg(self, 0, Some(base));
                    let op = match key {
                        "floor" => AttrOp::Floor,
                        "ceiling" => AttrOp::Ceiling,
                        "truncation" => AttrOp::Truncation,
                        _ => AttrOp::Rounding,
                    };
                    return self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                }
                "digits" if self.tables.types.is_float(t) => {
                    return self.mk(
                        ExKind::Int(self.tables.types.digits(t) as i64),
                        UNIV_INT,
                        sp,
                    );
                }
                "range" => {
                    self.err(diagnostics::range_outside_range_context(sp));
                    return self.err_ex(sp);
                }
                _ => {
                    self.err(diagnostics::attribute_unsupported_for_type(
                        a.span,
                        &a.name,
                        self.tables.types.name(t),
                    ));
                    return self.err_ex(sp);
                }
            }
        }
        // Attributes of objects.
        let mut pe = self.expr(p, None);
        if pe.ty == ERROR {
            return self.err_ex(sp);
        }
        if let Some(d) = self.tables.types.designated(pe.ty)
            && self.tables.types.is_array(d)
        {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
        }
        if let Some((idx, _, _)) = self
            .tables
            .types
            .array(pe.ty)
            .map(|(i, e, b)| (i.to_vec(), e, b.is_some()))
        {
            let d = dim(self);
            if d as usize > idx.len() {
                self.err(diagnostics::too_few_dimensions(
                    sp,
                    self.tables.types.name(pe.ty),
                    idx.len(),
                ));
                return self.err_ex(sp);
            }
            let it = idx[d as usize - 1];
            return match key {
                "first" => self.mk(
                    ExKind::Attr(AttrOp::ArrFirst(d), Box::new(vec![pe])),
                    it,
                    sp,
                ),
                "last" => self.mk(ExKind::Attr(AttrOp::ArrLast(d), Box::new(vec![pe])), it, sp),
                "length" => self.mk(
                    ExKind::Attr(AttrOp::ArrLength(d), Box::new(vec![pe])),
                    UNIV_INT,
                    sp,
                ),
                "range" => {
                    self.err(diagnostics::range_outside_range_context(sp));
                    self.err_ex(sp)
                }
                _ => {
                    self.err(diagnostics::attribute_unsupported_on_arrays(
                        a.span, &a.name,
                    ));
                    self.err_ex(sp)
                }
            };
        }
        if key == "constrained" {
            if self.tables.types.discriminants(pe.ty).is_empty() {
                if pe.ty != ERROR {
                    let ty = self.tables.types.name(pe.ty).to_string();
                    self.err(diagnostics::constrained_without_discriminants(pe.span, &ty));
                }
                return self.err_ex(sp);
            }
            // RM 3.7.2: whether the object's discriminants can change.
            return self
                .constrained_ex(&pe)
                .unwrap_or_else(|| self.mk(ExKind::Int(1), BOOLEAN, sp));
        }
        if key == "image" && self.tables.types.is_scalar(pe.ty) {
            let t = if self.tables.types.is_universal(pe.ty) {
                if self.tables.types.is_float(pe.ty) {
                    FLOAT
                } else {
                    INTEGER
                }
            } else {
                self.tables.types.base(pe.ty)
            };
            return self.image(pe, t, sp);
        }
        let _ = want;
        self.err(diagnostics::attribute_unsupported_here(a.span, &a.name));
        self.err_ex(sp)
    }

    fn coerce_force_check(&mut self, v: Ex, t: TypeId) -> Ex {
        let sp = v.span;
        if self.tables.types.get(t).range.is_some() || self.tables.types.enum_lits(t).is_some() {
            self.mk(ExKind::RangeCheck(bx(v), t), t, sp)
        } else {
            v
        }
    }

    fn image(&mut self, x: Ex, t: TypeId, sp: Span) -> Ex {
        let op = if self.tables.types.base(t) == DURATION {
            AttrOp::ImageDuration
        } else if self.tables.types.is_float(t) {
            AttrOp::ImageFloat(self.tables.types.digits(t) as u8)
        } else if self.tables.types.is_integer(t) {
            AttrOp::ImageInt
        } else if self.tables.types.base(t) == CHARACTER {
            AttrOp::ImageChar
        } else {
            AttrOp::ImageEnum(self.tables.types.base(t))
        };
        self.mk(ExKind::Attr(op, Box::new(vec![x])), STRING, sp)
    }

    /// `X'Range` and `T'Range` as a discrete range.
    pub(in crate::check) fn range_attr(
        &mut self,
        p: &ast::Expr,
        args: &[ast::Expr],
        sp: Span,
    ) -> (Ex, Ex, TypeId) {
        let d = match args.first() {
            None => 1u8,
            Some(x) => {
                let v = self.expr(x, Some(UNIV_INT));
                match self.static_value(&v) {
                    Some(Static::Int(n)) if n >= 1 => n as u8,
                    _ => 1,
                }
            }
        };
        if let Some(t) = self.denote_quiet_type(p) {
            if self.tables.types.is_scalar(t) {
                return (
                    self.mk(ExKind::TypeFirst(t), t, sp),
                    self.mk(ExKind::TypeLast(t), t, sp),
                    t,
                );
            }
            if let Some((idx, _, Some(b))) = self
                .tables
                .types
                .array(t)
                .map(|(i, e, b)| (i.to_vec(), e, b.cloned()))
                && let Some((l, h)) = b.get(d as usize - 1)
            {
                return (l.clone(), h.clone(), idx[d as usize - 1]);
            }
            self.err(diagnostics::range_needs_scalar_or_array(
                sp,
                self.tables.types.name(t),
            ));
            return (self.err_ex(sp), self.err_ex(sp), ERROR);
        }
        let mut pe = self.expr(p, None);
        if let Some(dt) = self.tables.types.designated(pe.ty) {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), dt, psp);
        }
        match self.tables.types.array(pe.ty).map(|(i, _, _)| i.to_vec()) {
            Some(idx) if (d as usize) <= idx.len() => {
                let it = idx[d as usize - 1];
                (
                    self.mk(
                        ExKind::Attr(AttrOp::ArrFirst(d), Box::new(vec![pe.clone()])),
                        it,
                        sp,
                    ),
                    self.mk(ExKind::Attr(AttrOp::ArrLast(d), Box::new(vec![pe])), it, sp),
                    it,
                )
            }
            _ => {
                if pe.ty != ERROR {
                    self.err(diagnostics::range_needs_array(sp, &self.tname(pe.ty)));
                }
                (self.err_ex(sp), self.err_ex(sp), ERROR)
            }
        }
    }
}
