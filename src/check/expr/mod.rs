//! Expressions: the entry `expr` and the interpretation of names, selections
//! and applications.
//! Overload resolution takes the possible types of each operand bottom-up
//! (`interps`), then checks against the expected type top-down (`expr` +
//! `coerce`); calls, operators and folding, aggregates, attributes and case
//! choices each have their own file.

use super::*;
use crate::syntax::ast::{BinOp, Choice, ExprKind, UnOp};

mod aggregates;
mod attributes;
mod calls;
mod choices;
mod coerce;
mod interps;
mod operators;

fn bx(e: Ex) -> Box<Ex> {
    Box::new(e)
}

impl Checker {
    pub(super) fn mk(&self, kind: ExKind, ty: TypeId, span: Span) -> Ex {
        Ex { kind, ty, span }
    }

    pub(super) fn err_ex(&self, span: Span) -> Ex {
        Ex {
            kind: ExKind::Error,
            ty: ERROR,
            span,
        }
    }

    pub(super) fn tname(&self, t: TypeId) -> String {
        match self.tables.types.kind(t) {
            TypeKind::UnivInt => "universal integer (a literal)".into(),
            TypeKind::UnivReal => "universal real (a literal)".into(),
            TypeKind::AnyComposite => "an aggregate".into(),
            TypeKind::Null => "null".into(),
            _ => self.tables.types.name(t).to_string(),
        }
    }

    /// The name of component `i` of record type `t` when it is a
    /// discriminant (of the partial view, where a private type's full
    /// view is hidden).
    fn discriminant_of(&self, t: TypeId, i: u32) -> Option<String> {
        let types = &self.tables.types;
        let f = match types.fields(t) {
            Some(fs) => fs.get(i as usize)?,
            None => types.discriminants(t).get(i as usize)?,
        };
        f.discriminant.then(|| f.name.clone())
    }

    /// Reports an error unless `ex` is a variable that may be assigned.
    pub(super) fn check_variable(&mut self, ex: &Ex, span: Span, what: &str) {
        let mut e = ex;
        loop {
            match &e.kind {
                ExKind::Var(v) => {
                    if let Some((_, constant)) = self.var_info(*v)
                        && constant
                    {
                        let name = self.snippet(e.span);
                        self.err(diagnostics::assigned_constant_or_in(span, &name, what));
                    }
                    return;
                }
                ExKind::Field(p, i) if self.discriminant_of(p.ty, *i).is_some() => {
                    let name = self.discriminant_of(p.ty, *i).unwrap_or_default();
                    self.err(diagnostics::assigned_discriminant(span, &name));
                    return;
                }
                ExKind::Index(p, _)
                | ExKind::Field(p, _)
                | ExKind::Variant(p, _)
                | ExKind::Slice(p, _) => e = p,
                // A component of the object of a protected function.
                ExKind::Deref(p) if matches!(p.kind, ExKind::Var(v) if Some(v) == self.tasking.prot_function_obj) =>
                {
                    let name = self.snippet(span);
                    self.err(diagnostics::protected_function_changes(span, &name, what));
                    return;
                }
                ExKind::Deref(_) | ExKind::Error => return,
                ExKind::Register(a) => {
                    if let Some((d, role)) = self.devices.lookup(*a)
                        && !role.is_writable()
                    {
                        let name = self.snippet(e.span);
                        let dev = self.devices.devices()[d].name.clone();
                        self.err(diagnostics::device_input_assigned(
                            span,
                            &name,
                            role.describe(),
                            &dev,
                            what,
                        ));
                    }
                    return;
                }
                // A constant with a static value stands in the IR as its value.
                ExKind::Int(_) | ExKind::Real(_)
                    if self
                        .snippet(e.span)
                        .starts_with(|c: char| c.is_ascii_alphabetic()) =>
                {
                    let name = self.snippet(e.span);
                    self.err(diagnostics::assigned_constant(span, &name, what));
                    return;
                }
                _ if ex.ty == ERROR => return,
                _ => {
                    self.err(diagnostics::not_a_variable(span, what));
                    return;
                }
            }
        }
    }

    fn var_info(&self, v: Var) -> Option<(String, bool)> {
        crate::work::tick();
        self.scopes.var(v)
    }

    /// Checks an expression; `want` is the type the context expects, if known.
    /// Checks an expression against the type it should have (if known).
    pub(super) fn expr(&mut self, e: &ast::Expr, want: Option<TypeId>) -> Ex {
        crate::work::tick();
        if self.memo.is_some() {
            return self.expr_inner(e, want);
        }
        self.memo = Some(HashMap::new());
        let r = self.expr_inner(e, want);
        self.memo = None;
        r
    }

    fn expr_inner(&mut self, e: &ast::Expr, want: Option<TypeId>) -> Ex {
        let r = self.expr_kind(e, want);
        if r.ty != ERROR && self.index.uses {
            self.index.types.push((e.span, r.ty));
        }
        r
    }

    fn expr_kind(&mut self, e: &ast::Expr, want: Option<TypeId>) -> Ex {
        let sp = e.span;
        match &e.kind {
            ExprKind::Int(v) => match i64::try_from(v.get()) {
                Ok(v) => self.mk(ExKind::Int(v), UNIV_INT, sp),
                Err(_) => {
                    self.err(diagnostics::integer_literal_too_large(sp));
                    self.err_ex(sp)
                }
            },
            ExprKind::Real(v) => self.mk(ExKind::Real(*v), UNIV_REAL, sp),
            ExprKind::Char(c) => {
                if let Some(w) = want
                    && self.tables.types.base(w) != CHARACTER
                {
                    for ent in self.lookup(&char_lit_key(*c)) {
                        if let Entity::EnumLit(t, pos) = ent
                            && self.tables.types.compatible(t, w)
                        {
                            return self.mk(ExKind::Int(pos), t, sp);
                        }
                    }
                }
                self.mk(ExKind::Int(*c as i64), CHARACTER, sp)
            }
            ExprKind::Str(s) => {
                let ty = match want {
                    Some(w) if self.fits(e, w) => w,
                    _ => STRING,
                };
                let ty = if self.tables.types.array(ty).is_some_and(|a| a.2.is_some()) {
                    self.tables.types.base(ty)
                } else {
                    ty
                };
                let ty = if self.tables.types.array(ty).is_some() {
                    self.unconstrained_of(ty)
                } else {
                    STRING
                };
                // Its lower bound is its index subtype's first (RM 4.2(11)):
                // 1 for String; otherwise an aggregate of its characters.
                let first = match self.tables.types.array(ty) {
                    Some((index, elem, None)) if index.len() == 1 => self
                        .tables
                        .types
                        .get(index[0])
                        .static_range
                        .map(|r| (r.0, elem)),
                    _ => None,
                };
                if let Some((f, elem)) = first
                    && f != 1
                {
                    let items: Vec<Ex> = s
                        .chars()
                        .map(|c| self.mk(ExKind::Int(c as i64), elem, sp))
                        .collect();
                    let agg = ArrayAgg {
                        ty,
                        kind: ArrayAggKind::Positional(items, None),
                    };
                    return self.mk(ExKind::ArrayAgg(Box::new(agg)), ty, sp);
                }
                self.mk(ExKind::Str(Rc::from(s.as_str())), ty, sp)
            }
            ExprKind::Null => self.mk(ExKind::Null, NULL_T, sp),
            ExprKind::Error => self.err_ex(sp),
            ExprKind::Paren(x) => self.expr(x, want),
            ExprKind::Name(id) => {
                let es = self.denote(e, true);
                self.entity_value(&es, want, sp, &crate::syntax::parser::expr_text(e), id)
            }
            ExprKind::Select(p, id) => {
                if self.expanded_prefix(p) {
                    let es = self.denote(e, true);
                    return self.entity_value(
                        &es,
                        want,
                        sp,
                        &crate::syntax::parser::expr_text(e),
                        id,
                    );
                }
                let pe = self.expr(p, None);
                self.component(pe, id, sp)
            }
            ExprKind::Deref(p) => {
                let pe = self.expr(p, None);
                match self.tables.types.designated(pe.ty) {
                    Some(d) => self.mk(ExKind::Deref(bx(pe)), d, sp),
                    None => {
                        if pe.ty != ERROR {
                            self.err(diagnostics::all_needs_access(sp, &self.tname(pe.ty)));
                        }
                        self.err_ex(sp)
                    }
                }
            }
            ExprKind::Apply(p, args) => self.apply(p, args, want, sp),
            ExprKind::Attr(p, a, args) => self.attribute(p, a, args, want, sp),
            ExprKind::Qualified(t, x) => {
                let t = self.type_mark(t);
                let ex = self.expr(x, Some(t));
                self.coerce(ex, t)
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, want, sp),
            ExprKind::Unary(op, a) => self.unary(*op, a, want, sp),
            ExprKind::Membership {
                negated,
                subject,
                choices,
            } => {
                let t = {
                    let mut refs: Vec<&ast::Expr> = vec![subject];
                    for c in choices {
                        match c {
                            Choice::Range(l, h) => {
                                refs.push(l);
                                refs.push(h);
                            }
                            Choice::Expr(x)
                                if !is_range_attr(x) && self.denote_quiet_type(x).is_none() =>
                            {
                                refs.push(x)
                            }
                            _ => {}
                        }
                    }
                    let ct = self.common_type(&refs, INTEGER);
                    if let Some(Choice::Expr(x)) = choices.first()
                        && let Some(tt) = self.denote_quiet_type(x)
                        && {
                            let first = self.interps(subject).first().copied().unwrap_or(ERROR);
                            self.tables.types.is_universal(first)
                        }
                    {
                        tt
                    } else {
                        ct
                    }
                };
                let s = self.expr(subject, Some(t));
                let s = self.coerce_base(s, t);
                let mut ranges = Vec::new();
                for c in choices {
                    match c {
                        Choice::Range(l, h) => {
                            let l = self.expr(l, Some(t));
                            let l = self.coerce_base(l, t);
                            let h = self.expr(h, Some(t));
                            let h = self.coerce_base(h, t);
                            ranges.push((l, h));
                        }
                        Choice::Expr(x) => {
                            if let ExprKind::Attr(prefix, _, args) = &x.kind
                                && is_range_attr(x)
                            {
                                // `X in A'Range`, `X in A'Range (N)`
                                let (l, h, rt) = self.range_attr(prefix, args, x.span);
                                if rt != ERROR && !self.tables.types.compatible(rt, s.ty) {
                                    self.err(diagnostics::range_of_other_type(
                                        x.span,
                                        self.tables.types.name(rt),
                                        &self.tname(s.ty),
                                    ));
                                }
                                ranges.push((l, h));
                            } else if let Some(tt) = self.denote_quiet_type(x) {
                                if !self.tables.types.compatible(tt, s.ty) {
                                    self.err(diagnostics::not_a_subtype_of(
                                        x.span,
                                        self.tables.types.name(tt),
                                        &self.tname(s.ty),
                                    ));
                                }
                                ranges.push((
                                    self.mk(ExKind::TypeFirst(tt), tt, x.span),
                                    self.mk(ExKind::TypeLast(tt), tt, x.span),
                                ));
                            } else {
                                let v = self.expr(x, Some(t));
                                let v = self.coerce_base(v, t);
                                ranges.push((v.clone(), v));
                            }
                        }
                        Choice::Others(os) => self.err(diagnostics::others_in_membership(*os)),
                    }
                }
                self.mk(
                    ExKind::InRanges(bx(s), Box::new(ranges), *negated),
                    BOOLEAN,
                    sp,
                )
            }
            ExprKind::Aggregate(items) => match want {
                Some(t) if self.tables.types.is_hidden(t) => {
                    let pkg = self.private_package(t);
                    self.err(diagnostics::private_aggregate(sp, &self.tname(t), &pkg));
                    self.err_ex(sp)
                }
                Some(t) if t != ERROR && !self.tables.types.is_universal(t) => {
                    self.aggregate(items, t, sp)
                }
                Some(_) => self.err_ex(sp),
                None => {
                    self.err(diagnostics::aggregate_type_unknown(sp));
                    self.err_ex(sp)
                }
            },
            ExprKind::If { arms, els } => {
                let t = match want {
                    Some(w) if w != ERROR => w,
                    _ => {
                        let mut refs: Vec<&ast::Expr> = arms.iter().map(|a| &a.1).collect();
                        if let Some(e) = els {
                            refs.push(e);
                        }
                        self.common_type(&refs, INTEGER)
                    }
                };
                let t = self.dependent_type(t);
                let mut out = Vec::new();
                for (c, v) in arms {
                    let c = self.expr(c, Some(BOOLEAN));
                    let c = self.coerce(c, BOOLEAN);
                    let v = self.expr(v, Some(t));
                    out.push((c, self.coerce(v, t)));
                }
                let els = match els {
                    Some(x) => {
                        let v = self.expr(x, Some(t));
                        self.coerce(v, t)
                    }
                    None => {
                        if self.tables.types.base(t) != BOOLEAN {
                            self.err(diagnostics::if_expression_without_else(sp));
                        }
                        self.mk(ExKind::Int(1), BOOLEAN, sp)
                    }
                };
                self.mk(ExKind::If(Box::new(out), bx(els)), t, sp)
            }
            ExprKind::Case { subject, arms } => {
                let t = match want {
                    Some(w) if w != ERROR => w,
                    _ => {
                        let refs: Vec<&ast::Expr> = arms.iter().map(|a| &a.body).collect();
                        self.common_type(&refs, INTEGER)
                    }
                };
                let t = self.dependent_type(t);
                let s = self.expr(subject, None);
                let st = if self.tables.types.is_universal(s.ty) {
                    INTEGER
                } else {
                    s.ty
                };
                let s = self.coerce(s, st);
                let choice_lists: Vec<&[Choice]> =
                    arms.iter().map(|a| a.choices.as_slice()).collect();
                let (ranges, others_at) = self.case_choices(st, &choice_lists, sp);
                let mut out = Vec::new();
                let mut others = None;
                for (i, a) in arms.iter().enumerate() {
                    let v = self.expr(&a.body, Some(t));
                    let v = self.coerce(v, t);
                    if Some(i) == others_at {
                        others = Some(v);
                    } else {
                        out.push((ranges[i].clone(), v));
                    }
                }
                self.mk(ExKind::Case(Box::new((s, out, others))), t, sp)
            }
            ExprKind::Allocator(tm, init) => {
                let Some(w) = want.filter(|w| self.tables.types.is_access(*w)) else {
                    if want != Some(ERROR) {
                        self.err(diagnostics::allocator_without_access_type(sp));
                    }
                    return self.err_ex(sp);
                };
                let d = self.tables.types.designated(w).unwrap_or(ERROR);
                let t = self.allocated_subtype(tm);
                if !self.tables.types.compatible(t, d) {
                    self.err(diagnostics::designates_other_type(
                        tm.span,
                        self.tables.types.name(w),
                        self.tables.types.name(d),
                        self.tables.types.name(t),
                    ));
                }
                let init = init.as_ref().map(|x| {
                    let v = self.expr(x, Some(t));
                    bx(self.coerce(v, t))
                });
                if init.is_none() && self.tables.types.unknown_discriminants(t) {
                    self.err(diagnostics::unknown_discriminants_unconstrained(
                        tm.span,
                        &self.tname(t),
                        "an allocator",
                    ));
                } else if init.is_none() && self.needs_discriminants(t) {
                    self.err(diagnostics::allocator_unconstrained(
                        tm.span,
                        self.tables.types.name(t),
                    ));
                }
                self.mk(ExKind::Alloc(init, t), w, sp)
            }
        }
    }

    /// The subtype an allocator names: `new Station (Id => 9, Speed => 0)`
    /// with a discriminant constraint (RM 4.8(3)), else a type mark.
    /// The type of the dependent expressions of an `if` or `case`
    /// expression expected of type `t`: for a scalar, its base type. They
    /// have the expression's type, not a subtype (RM 4.5.7), so
    /// `(if B then -K else 0) < 0` is True for a `K` of subtype `1 .. 10`;
    /// where the value goes to a constrained place, that place checks it.
    fn dependent_type(&self, t: TypeId) -> TypeId {
        let types = &self.tables.types;
        if types.is_scalar(t) && !types.is_universal(t) {
            types.base(t)
        } else {
            t
        }
    }

    fn allocated_subtype(&mut self, tm: &ast::Expr) -> TypeId {
        if let ExprKind::Apply(p, args) = &tm.kind
            && let ExprKind::Name(id) = &p.kind
            && let Some(Entity::Type(t)) = self.lookup(&id.key).first().cloned()
            && !self.tables.types.discriminants(t).is_empty()
        {
            let t = self.type_mark(p);
            let items: Vec<(Option<&ast::Ident>, &ast::Expr, Span)> = args
                .iter()
                .map(|a| (a.name.as_ref(), &a.value, a.span))
                .collect();
            return self.discriminant_constraint(tm.span, t, &items);
        }
        self.type_mark(tm)
    }

    /// An unconstrained array type with the same index and element types.
    pub(super) fn unconstrained_of(&mut self, t: TypeId) -> TypeId {
        match self.tables.types.array(t) {
            Some((idx, el, Some(_))) => {
                let (idx, el) = (idx.to_vec(), el);
                let name = self.tables.types.name(t).to_string();
                let base = self.tables.types.base(t);
                let n = self.tables.types.add(
                    &name,
                    TypeKind::Array {
                        index: idx,
                        elem: el,
                        bounds: None,
                    },
                );
                self.tables.types.list[n as usize].base = base;
                n
            }
            _ => t,
        }
    }

    /// The value a name denotes; `id` is the identifier it ends with (the
    /// resolved overload is recorded there).
    fn entity_value(
        &mut self,
        es: &[Entity],
        want: Option<TypeId>,
        sp: Span,
        text: &str,
        id: &ast::Ident,
    ) -> Ex {
        let Some(first) = es.first() else {
            return self.err_ex(sp);
        };
        match first {
            Entity::Var { var, ty, value, .. } => match value {
                Some(Static::Int(v)) => self.mk(ExKind::Int(*v as i64), *ty, sp),
                Some(Static::Real(v)) => {
                    let v = v.clone();
                    self.real_lit(v, *ty, sp)
                }
                None => {
                    let (v, ty) = (*var, *ty);
                    self.mark_read(v);
                    self.mk(ExKind::Var(v), ty, sp)
                }
            },
            Entity::Alias(x) => {
                let mut x = (**x).clone();
                x.span = sp;
                x
            }
            Entity::Number(Static::Int(v)) => match i64::try_from(*v) {
                Ok(v) => self.mk(ExKind::Int(v), UNIV_INT, sp),
                Err(_) => self.err_ex(sp),
            },
            Entity::Number(Static::Real(v)) => {
                let v = v.clone();
                self.real_lit(v, UNIV_REAL, sp)
            }
            Entity::EnumLit(..) | Entity::Func(_) => {
                // Enumeration literals first, by the expected type; then parameterless functions.
                for e in es {
                    if let Entity::EnumLit(t, pos) = e
                        && want.is_none_or(|w| self.tables.types.compatible(*t, w))
                    {
                        self.index_ref(id.span, &id.key, e);
                        return self.mk(ExKind::Int(*pos), *t, sp);
                    }
                }
                let fs: Vec<FuncId> = funcs_of(es);
                if fs.is_empty() {
                    if let Some(e @ Entity::EnumLit(t, pos)) = es.first() {
                        self.index_ref(id.span, &id.key, e);
                        return self.mk(ExKind::Int(*pos), *t, sp);
                    }
                    return self.err_ex(sp);
                }
                match self.call(&fs, &[], want, false, sp, text) {
                    Some((f, args)) => {
                        self.index_ref(id.span, &id.key, &Entity::Func(f));
                        let r = self.tables.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(self.tables.callee(f), args.into()), r, sp)
                    }
                    None => self.err_ex(sp),
                }
            }
            Entity::Type(t) => {
                let n = self.tables.types.name(*t).to_string();
                self.err(diagnostics::type_is_not_a_value(sp, &n));
                self.err_ex(sp)
            }
            Entity::Exc(_) => {
                self.err(diagnostics::exception_is_not_a_value(sp, text));
                self.err_ex(sp)
            }
            Entity::Package(_) => {
                self.err(diagnostics::package_is_not_a_value(sp, text));
                self.err_ex(sp)
            }
        }
    }

    fn component(&mut self, mut pe: Ex, id: &ast::Ident, sp: Span) -> Ex {
        if let Some(x) = self.conc_discriminant(&pe, id, sp) {
            return x;
        }
        if let TypeKind::Protected(k) = self.tables.types.kind(pe.ty).clone() {
            return self.prot_function(k, pe, id, &[], sp);
        }
        if let Some(d) = self.tables.types.designated(pe.ty) {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
            if let Some(x) = self.conc_discriminant(&pe, id, sp) {
                return x;
            }
            if let TypeKind::Protected(k) = self.tables.types.kind(pe.ty).clone() {
                return self.prot_function(k, pe, id, &[], sp);
            }
        }
        if pe.ty == ERROR {
            return self.err_ex(sp);
        }
        if self.tables.types.is_hidden(pe.ty) {
            let pkg = self.private_package(pe.ty);
            self.err(diagnostics::private_component(
                id.span,
                &id.name,
                &self.tname(pe.ty),
                &pkg,
            ));
            return self.err_ex(sp);
        }
        match self.tables.types.fields(pe.ty).map(|f| f.to_vec()) {
            Some(fields) => match fields.iter().position(|f| *f.key == *id.key) {
                Some(i) => {
                    let t = fields[i].ty;
                    self.index_field_ref(id.span, pe.ty, i as u32);
                    if fields[i].variant.is_some() {
                        // A component of a variant: a discriminant check.
                        let (pt, psp) = (pe.ty, pe.span);
                        pe = self.mk(ExKind::Variant(bx(pe), i as u32), pt, psp);
                    }
                    self.mk(ExKind::Field(bx(pe), i as u32), t, sp)
                }
                None => {
                    let names: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
                    self.err(diagnostics::no_component(
                        id.span,
                        self.tables.types.name(pe.ty),
                        &id.name,
                        &names,
                    ));
                    self.err_ex(sp)
                }
            },
            None => {
                self.err(diagnostics::selection_needs_record(
                    id.span,
                    &id.name,
                    &self.tname(pe.ty),
                ));
                self.err_ex(sp)
            }
        }
    }

    /// `T.Id` of a task `T`, `P.Size` of a protected object `P`: a
    /// discriminant (RM 9.1(12), 9.4(12)); `B.Size` of an object of a
    /// private type whose partial view has discriminants, where its full
    /// view is hidden (RM 7.3(3)): the full view's discriminant.
    fn conc_discriminant(&mut self, pe: &Ex, id: &ast::Ident, sp: Span) -> Option<Ex> {
        let types = &self.tables.types;
        let j = types
            .discriminants(pe.ty)
            .iter()
            .position(|d| *d.key == *id.key)?;
        let t = types.discriminants(pe.ty)[j].ty;
        let private = matches!(types.kind(pe.ty), TypeKind::Private);
        if private
            || matches!(
                types.kind(pe.ty),
                TypeKind::Task(_) | TypeKind::Protected(_)
            )
        {
            self.index_field_ref(id.span, pe.ty, j as u32);
        }
        let types = &self.tables.types;
        if private {
            match types.full_kind(pe.ty) {
                TypeKind::Task(_) | TypeKind::Protected(_) => {}
                kind => {
                    // A record (or, before the full declaration, what
                    // will be one: a task or protected completion then
                    // is refused, see `install_full_view`).
                    if matches!(kind, TypeKind::Private) {
                        self.early_discriminant_reads
                            .insert(types.base(pe.ty), id.span);
                    }
                    return Some(self.mk(ExKind::Field(bx(pe.clone()), j as u32), t, sp));
                }
            }
        }
        match types.full_kind(pe.ty).clone() {
            TypeKind::Task(_) => Some(self.mk(
                ExKind::Attr(
                    AttrOp::TaskDiscriminant(j as u32),
                    Box::new(vec![pe.clone()]),
                ),
                t,
                sp,
            )),
            TypeKind::Protected(k) => {
                let rec = self.tables.prots[k as usize].rec;
                let obj = self.mk(ExKind::Deref(bx(pe.clone())), rec, pe.span);
                Some(self.mk(ExKind::Field(bx(obj), j as u32 + 1), t, sp))
            }
            _ => None,
        }
    }

    fn apply(&mut self, p: &ast::Expr, args: &[ast::Arg], want: Option<TypeId>, sp: Span) -> Ex {
        if let ExprKind::Select(q, id) = &p.kind
            && let Some(k) = self.peek_protected(q)
        {
            let obj = self.expr(q, None);
            return self.prot_function(k, obj, id, args, sp);
        }
        let pes = match &p.kind {
            ExprKind::Name(_) => self.denote(p, true),
            ExprKind::Select(q, _) if self.expanded_prefix(q) => self.denote(p, true),
            _ => Vec::new(),
        };
        if matches!(&p.kind, ExprKind::Name(_)) && pes.is_empty() {
            for a in args {
                self.expr(&a.value, None);
            }
            return self.err_ex(sp);
        }
        match pes.first() {
            Some(Entity::Type(t)) => {
                let t = *t;
                if args.len() != 1 || args[0].name.is_some() {
                    self.err(diagnostics::conversion_arity(sp, self.tables.types.name(t)));
                    return self.err_ex(sp);
                }
                self.conversion(t, &args[0].value, sp)
            }
            Some(Entity::Func(_)) => {
                let fs: Vec<FuncId> = funcs_of(&pes);
                let name = crate::syntax::parser::expr_text(p);
                // `ValueAxes (2)`: a parameterless function whose array result is indexed.
                if !fs.iter().any(|f| self.args_fit(*f, args))
                    && let Some(f) = fs.iter().copied().find(|f| {
                        let sub = &self.tables.funcs[*f as usize];
                        sub.params.iter().all(|p| p.default.is_some())
                            && sub
                                .ret
                                .and_then(|r| self.tables.types.array(r))
                                .is_some_and(|a| a.0.len() == args.len())
                    })
                {
                    if let Some(id) = super::stmt::last_ident(p) {
                        self.index_ref(id.span, &id.key, &Entity::Func(f));
                    }
                    let r = self.tables.funcs[f as usize].ret.unwrap_or(ERROR);
                    let defaults: Vec<Arg> = self.tables.funcs[f as usize]
                        .params
                        .iter()
                        .map(|p| Arg {
                            mode: ast::Mode::In,
                            value: p.default.clone().unwrap_or_else(|| Ex::int(0)),
                            back_check: None,
                        })
                        .collect();
                    let callee = self.mk(
                        ExKind::Call(self.tables.callee(f), defaults.into()),
                        r,
                        p.span,
                    );
                    let idx: Vec<TypeId> = self
                        .tables
                        .types
                        .array(r)
                        .map(|a| a.0.to_vec())
                        .unwrap_or_default();
                    let el = self.tables.types.array(r).map(|a| a.1).unwrap_or(ERROR);
                    let mut ix = Vec::new();
                    for (a, it) in args.iter().zip(&idx) {
                        let v = self.expr(&a.value, Some(*it));
                        ix.push(self.coerce_base(v, *it));
                    }
                    return self.mk(ExKind::Index(bx(callee), Box::new(ix)), el, sp);
                }
                match self.call(&fs, args, want, false, sp, &name) {
                    Some((f, a)) => {
                        if let Some(id) = super::stmt::last_ident(p) {
                            self.index_ref(id.span, &id.key, &Entity::Func(f));
                        }
                        let r = self.tables.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(self.tables.callee(f), a.into()), r, sp)
                    }
                    None => self.err_ex(sp),
                }
            }
            Some(Entity::Exc(_) | Entity::Package(_)) => {
                self.err(diagnostics::cannot_call_or_index(
                    sp,
                    &crate::syntax::parser::expr_text(p),
                ));
                self.err_ex(sp)
            }
            _ => {
                let mut pe = self.expr(p, None);
                if let Some(d) = self.tables.types.designated(pe.ty) {
                    let psp = pe.span;
                    pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
                }
                if pe.ty == ERROR {
                    for a in args {
                        self.expr(&a.value, None);
                    }
                    return self.err_ex(sp);
                }
                if self.tables.types.is_hidden(pe.ty) {
                    let pkg = self.private_package(pe.ty);
                    self.err(diagnostics::private_full_view(
                        sp,
                        "indexing",
                        &self.tname(pe.ty),
                        &pkg,
                    ));
                    return self.err_ex(sp);
                }
                let Some((idx, el, _)) = self
                    .tables
                    .types
                    .array(pe.ty)
                    .map(|(i, e, b)| (i.to_vec(), e, b.is_some()))
                else {
                    self.err(diagnostics::neither_array_nor_subprogram(
                        sp,
                        &self.snippet(p.span),
                        &self.tname(pe.ty),
                    ));
                    return self.err_ex(sp);
                };
                if args.len() == 1 && is_range_arg(&args[0].value) {
                    let ExprKind::Aggregate(items) = &args[0].value.kind else {
                        return self.err_ex(sp);
                    };
                    let Some(Choice::Range(l, h)) = items[0].choices.first() else {
                        return self.err_ex(sp);
                    };
                    let l = self.expr(l, Some(idx[0]));
                    let l = self.coerce_base(l, idx[0]);
                    let h = self.expr(h, Some(idx[0]));
                    let h = self.coerce_base(h, idx[0]);
                    let t = self.unconstrained_of(pe.ty);
                    return self.mk(ExKind::Slice(bx(pe), Box::new([l, h])), t, sp);
                }
                if args.len() != idx.len() {
                    self.err(diagnostics::index_count(
                        sp,
                        self.tables.types.name(pe.ty),
                        idx.len(),
                        args.len(),
                    ));
                    return self.err_ex(sp);
                }
                let mut ix = Vec::new();
                for (a, it) in args.iter().zip(&idx) {
                    if let Some(n) = &a.name {
                        self.err(diagnostics::named_array_index(n.span));
                    }
                    let v = self.expr(&a.value, Some(*it));
                    ix.push(self.coerce_base(v, *it));
                }
                self.mk(ExKind::Index(bx(pe), Box::new(ix)), el, sp)
            }
        }
    }

    fn conversion(&mut self, t: TypeId, x: &ast::Expr, sp: Span) -> Ex {
        let xi = self.interps(x);
        let src = xi
            .iter()
            .copied()
            .find(|u| !self.tables.types.is_universal(*u))
            .or(xi.first().copied())
            .unwrap_or(ERROR);
        let want = if self.tables.types.is_numeric(t) && self.tables.types.is_numeric(src) {
            Some(src)
        } else {
            Some(t)
        };
        let ex = self.expr(x, want);
        if ex.ty == ERROR || t == ERROR {
            return self.err_ex(sp);
        }
        let (tf, ti) = (
            self.tables.types.is_float(t),
            self.tables.types.is_integer(t),
        );
        let (sf, si) = (
            self.tables.types.is_float(ex.ty),
            self.tables.types.is_integer(ex.ty),
        );
        let inner = if tf && si {
            self.mk(ExKind::IntToFloat(bx(ex)), self.tables.types.base(t), sp)
        } else if ti && sf {
            self.mk(ExKind::FloatToInt(bx(ex)), self.tables.types.base(t), sp)
        } else if tf
            && sf
            && self.tables.types.whole_ns(t)
            && !self.tables.types.whole_ns(ex.ty)
            && !self.tables.types.is_universal(ex.ty)
        {
            // To whole nanoseconds, as GNAT's fixed point Duration holds them.
            let one = Ex::real(1.0);
            self.mk(
                ExKind::FloatBin(FloatOp::DurMul, bx(ex), bx(one)),
                self.tables.types.base(t),
                sp,
            )
        } else if ti
            && si
            // A static universal value is judged by `coerce`; any other
            // (`Ring (Character'Pos (C))`) is checked like a typed one.
            && (!self.tables.types.is_universal(ex.ty) || self.shallow_static(&ex).is_none())
            && self.tables.types.base(ex.ty) != self.tables.types.base(t)
        {
            self.int_conversion(ex, t, sp)
        } else if (tf && sf) || (ti && si) {
            Ex {
                ty: self.tables.types.base(t),
                ..ex
            }
        } else if self.tables.types.base(ex.ty) == self.tables.types.base(t) {
            ex
        } else if self.tables.types.fields(t).is_some()
            && self.tables.types.derivation_root(ex.ty) == self.tables.types.derivation_root(t)
            && self.tables.types.discriminants(t).is_empty()
        {
            // Between record types of one derivation (`Pose (T)` of a
            // `Tool_Pose`): the same components, the value as it is.
            Ex {
                ty: self.tables.types.base(t),
                ..ex
            }
        } else if let (Some((i1, e1, _)), Some((i2, e2, _))) =
            (self.tables.types.array(ex.ty), self.tables.types.array(t))
        {
            if i1.len() == i2.len() && self.tables.types.base(e1) == self.tables.types.base(e2) {
                let tt = if self.tables.types.array(t).is_some_and(|a| a.2.is_some()) {
                    t
                } else {
                    self.tables.types.base(t)
                };
                return self.mk(ExKind::ArrayConvert(bx(ex), tt), t, sp);
            }
            self.err(diagnostics::cannot_convert_arrays(
                sp,
                &self.tname(ex.ty),
                self.tables.types.name(t),
            ));
            return self.err_ex(sp);
        } else {
            self.err(diagnostics::cannot_convert(
                sp,
                &self.tname(ex.ty),
                self.tables.types.name(t),
            ));
            return self.err_ex(sp);
        };
        let mut inner = inner;
        inner.span = sp;
        self.coerce(inner, t)
    }
}

impl Checker {
    /// `T (X)` of a value of another integer type: checked against the
    /// base range of T (RM 4.6(28)), never wrapped, whether T is a modular
    /// type or a range type (`Word (-1)` raises Constraint_Error); a static
    /// value is left for `coerce` to judge (an error for a modular type).
    /// No check where every value of X's subtype is one of T's.
    fn int_conversion(&mut self, ex: Ex, t: TypeId, sp: Span) -> Ex {
        let b = self.tables.types.base(t);
        let to = self.tables.types.discrete_bounds(b);
        let fits = match (
            self.shallow_static(&ex),
            self.tables.types.discrete_bounds(ex.ty),
        ) {
            (Some(_), _) if self.tables.types.modulus(b).is_some() => true,
            (Some(Static::Int(v)), _) => to.is_some_and(|(l, h)| l <= v && v <= h),
            (_, Some((fl, fh))) => to.is_none_or(|(l, h)| l <= fl && fh <= h),
            _ => to.is_none(),
        };
        if fits {
            Ex { ty: b, ..ex }
        } else {
            self.mk(ExKind::RangeCheck(bx(ex), b), b, sp)
        }
    }
}

/// The slice form `A (L .. H)`, as the parser encodes it.
fn is_range_arg(e: &ast::Expr) -> bool {
    matches!(&e.kind, ExprKind::Aggregate(items) if items.len() == 1 && matches!(items[0].choices.as_slice(), [Choice::Range(..)]) && matches!(items[0].value.kind, ExprKind::Error))
}

/// The subprograms among the entities a name denotes.
pub(super) fn funcs_of(es: &[Entity]) -> Vec<FuncId> {
    es.iter()
        .filter_map(|e| {
            if let Entity::Func(f) = e {
                Some(*f)
            } else {
                None
            }
        })
        .collect()
}

/// `P'Range` or `P'Range (N)`: a range, not a value.
fn is_range_attr(x: &ast::Expr) -> bool {
    matches!(&x.kind, ExprKind::Attr(_, a, _) if &*a.key == "range")
}

/// A parameter mode as a profile writes it (`in` left out).
pub(super) fn mode_text(m: ast::Mode) -> &'static str {
    match m {
        ast::Mode::In => "",
        ast::Mode::Out => "out ",
        ast::Mode::InOut => "in out ",
    }
}

/// Whether `e` is a chain of more than `limit` selections, walking at most
/// `limit + 1` of them.
fn select_depth_exceeds(mut e: &ast::Expr, limit: usize) -> bool {
    for _ in 0..=limit {
        match &e.kind {
            ExprKind::Select(p, _) => e = p,
            _ => return false,
        }
    }
    true
}
