//! Type and subtype declarations: type definitions, subtype indications,
//! ranges and their elaboration.

use super::*;

impl Checker {
    /// The type an expression of a subtype mark denotes, reporting errors.
    pub(in crate::check) fn type_mark(&mut self, n: &ast::Expr) -> TypeId {
        let es = self.denote(n, true);
        match es.first() {
            Some(Entity::Type(t)) => *t,
            Some(_) => {
                let text = crate::syntax::parser::expr_text(n);
                self.err(diagnostics::not_a_type(n.span, &text));
                ERROR
            }
            None => ERROR,
        }
    }

    pub(in crate::check) fn subtype_ind(&mut self, ind: &ast::SubtypeInd) -> TypeId {
        let t = self.type_mark(&ind.mark);
        match &ind.constraint {
            None => t,
            Some(ast::Constraint::Range(lo, hi)) => {
                if !self.tables.types.is_scalar(t) && t != ERROR {
                    self.err(diagnostics::range_constraint_not_scalar(
                        ind.span,
                        self.tables.types.name(t),
                    ));
                    return t;
                }
                let name = self.tables.types.name(t).to_string();
                self.constrained_scalar(&name, t, lo, hi)
            }
            Some(ast::Constraint::Discriminants(args)) => {
                let items: Vec<(Option<&ast::Ident>, &ast::Expr, Span)> = args
                    .iter()
                    .map(|a| (a.name.as_ref(), &a.value, a.span))
                    .collect();
                self.discriminant_constraint(ind.span, t, &items)
            }
            Some(ast::Constraint::Index(ranges))
                if matches!(
                    self.tables.types.kind(t),
                    TypeKind::Record(_)
                        | TypeKind::Task(_)
                        | TypeKind::Protected(_)
                        | TypeKind::Private
                ) =>
            {
                // `Buffer (80)`, `Gripper (Vacuum)`: positional values.
                let mut items = Vec::new();
                for r in ranges {
                    match r {
                        ast::DiscreteRange::Subtype(ast::SubtypeInd {
                            mark,
                            constraint: None,
                            span,
                        }) => items.push((None, mark, *span)),
                        ast::DiscreteRange::Range(a, _) | ast::DiscreteRange::Attr(a) => {
                            self.err(diagnostics::no_discriminants(
                                a.span,
                                self.tables.types.name(t),
                            ));
                            return ERROR;
                        }
                        ast::DiscreteRange::Subtype(s) => {
                            self.err(diagnostics::no_discriminants(
                                s.span,
                                self.tables.types.name(t),
                            ));
                            return ERROR;
                        }
                    }
                }
                self.discriminant_constraint(ind.span, t, &items)
            }
            Some(ast::Constraint::Index(ranges)) => {
                let Some((index, elem, bounds)) = self
                    .tables
                    .types
                    .array(t)
                    .map(|(i, e, b)| (i.to_vec(), e, b.is_some()))
                else {
                    if t != ERROR {
                        self.err(diagnostics::index_constraint_not_array(
                            ind.span,
                            self.tables.types.name(t),
                        ));
                    }
                    return t;
                };
                if bounds {
                    self.err(diagnostics::already_constrained(
                        ind.span,
                        self.tables.types.name(t),
                    ));
                    return t;
                }
                if ranges.len() != index.len() {
                    self.err(diagnostics::index_constraint_count(
                        ind.span,
                        self.tables.types.name(t),
                        index.len(),
                        ranges.len(),
                    ));
                    return t;
                }
                let mut bs = Vec::new();
                for (r, it) in ranges.iter().zip(&index) {
                    let (lo, hi, _) = self.discrete_range(r, Some(*it));
                    bs.push((self.elaborate_bound(lo), self.elaborate_bound(hi)));
                }
                let name = self.tables.types.name(t).to_string();
                let st = self.tables.types.add_subtype(&name, t);
                self.tables.types.list[st as usize].kind = TypeKind::Array {
                    index,
                    elem,
                    bounds: Some(bs),
                };
                st
            }
        }
    }

    /// A discriminant constraint (RM 3.7.1): each discriminant's value,
    /// by position or by name, elaborated with the declaration.
    pub(in crate::check) fn discriminant_constraint(
        &mut self,
        at: Span,
        t: TypeId,
        items: &[(Option<&ast::Ident>, &ast::Expr, Span)],
    ) -> TypeId {
        let ds = self.tables.types.discriminants(t).to_vec();
        let tn = self.tables.types.name(t).to_string();
        if ds.is_empty() {
            if t != ERROR {
                self.err(diagnostics::no_discriminants(at, &tn));
            }
            return ERROR;
        }
        if self.tables.types.discriminant_constraint(t).is_some() {
            self.err(diagnostics::already_constrained(at, &tn));
            return t;
        }
        let mut vals: Vec<Option<Ex>> = vec![None; ds.len()];
        let mut pos = 0;
        let mut failed = false;
        for (name, value, span) in items {
            let j = match name {
                None => {
                    if pos >= ds.len() {
                        self.err(diagnostics::discriminant_count(*span, &tn, true));
                        return ERROR;
                    }
                    pos += 1;
                    pos - 1
                }
                Some(n) => match ds.iter().position(|d| *d.key == *n.key) {
                    Some(j) => {
                        self.index_field_ref(n.span, t, j as u32);
                        j
                    }
                    None => {
                        let names: Vec<&str> = ds.iter().map(|d| d.name.as_str()).collect();
                        self.err(diagnostics::no_such_discriminant(
                            n.span, &tn, &n.name, &names,
                        ));
                        self.expr(value, None);
                        failed = true;
                        continue;
                    }
                },
            };
            if vals[j].is_some() {
                self.err(diagnostics::discriminant_given_twice(*span, &ds[j].name));
                failed = true;
                continue;
            }
            let v = self.expr(value, Some(ds[j].ty));
            let v = self.coerce(v, ds[j].ty);
            vals[j] = Some(self.elaborate_bound(v));
        }
        if failed {
            return ERROR;
        }
        let Some(vals) = vals.into_iter().collect::<Option<Vec<Ex>>>() else {
            self.err(diagnostics::discriminant_count(at, &tn, false));
            return ERROR;
        };
        let st = self.tables.types.add_subtype(&tn, t);
        self.tables.types.list[st as usize].discr = Some(vals.into());
        st
    }

    fn constrained_scalar(
        &mut self,
        name: &str,
        t: TypeId,
        lo: &ast::Expr,
        hi: &ast::Expr,
    ) -> TypeId {
        let base = self.tables.types.base(t);
        let l = self.expr(lo, Some(base));
        let l = self.coerce_base(l, base);
        let h = self.expr(hi, Some(base));
        let h = self.coerce_base(h, base);
        let st = self.tables.types.add_subtype(name, t);
        self.set_range(st, l, h);
        st
    }

    /// Runs `f` (the check of a subtype indication or type definition of a
    /// declaration) with its non-static bounds elaborated into `out`: they
    /// are evaluated once, when the declaration is (RM 3.2.2), not at each
    /// check against the subtype.
    pub(super) fn elaborating<T>(
        &mut self,
        out: &mut Vec<Stmt>,
        f: impl FnOnce(&mut Self) -> T,
    ) -> T {
        let outer = self.bounds_out.replace(Vec::new());
        let r = f(self);
        let got = std::mem::replace(&mut self.bounds_out, outer);
        out.extend(got.unwrap_or_default());
        r
    }

    /// A bound that is not static, while a declaration is elaborated: a
    /// fresh slot that holds its value from now on.
    pub(in crate::check) fn elaborate_bound(&mut self, e: Ex) -> Ex {
        if self.bounds_out.is_none()
            || self.static_value(&e).is_some()
            || e.ty == ERROR
            || (self.in_discriminated && ir::reads_discriminant(&e))
        {
            return e;
        }
        let v = self.new_slot();
        let (ty, span) = (e.ty, e.span);
        if let Some(out) = &mut self.bounds_out {
            out.push(Stmt {
                kind: StmtKind::Init(v, e),
                span,
            });
        }
        Ex {
            kind: ExKind::Var(v),
            ty,
            span,
        }
    }

    pub(in crate::check) fn set_range(&mut self, st: TypeId, l: Ex, h: Ex) {
        let (l, h) = (self.elaborate_bound(l), self.elaborate_bound(h));
        let (sl, sh) = (self.static_value(&l), self.static_value(&h));
        let info = &mut self.tables.types.list[st as usize];
        info.static_range = None;
        info.static_frange = None;
        match (sl, sh) {
            (Some(Static::Int(a)), Some(Static::Int(b))) => info.static_range = Some((a, b)),
            (Some(Static::Real(a)), Some(Static::Real(b))) => {
                info.static_frange = Some((exact::to_f64(&a), exact::to_f64(&b)))
            }
            _ => {}
        }
        info.range = Some((l, h));
    }

    /// A discrete range: returns low and high bound expressions and the type.
    pub(in crate::check) fn discrete_range(
        &mut self,
        r: &ast::DiscreteRange,
        want: Option<TypeId>,
    ) -> (Ex, Ex, TypeId) {
        match r {
            ast::DiscreteRange::Range(a, b) => {
                let t = match want {
                    Some(t) => t,
                    None => self.common_type(&[a, b], INTEGER),
                };
                let l = self.expr(a, Some(t));
                let l = self.coerce_base(l, t);
                let h = self.expr(b, Some(t));
                let h = self.coerce_base(h, t);
                if !self.tables.types.is_discrete(t) && t != ERROR {
                    self.err(diagnostics::range_not_discrete(
                        a.span,
                        self.tables.types.name(t),
                    ));
                }
                (l, h, t)
            }
            ast::DiscreteRange::Subtype(ind) => {
                let t = self.subtype_ind(ind);
                if !self.tables.types.is_discrete(t) && t != ERROR {
                    self.err(diagnostics::not_a_discrete_type(
                        ind.span,
                        self.tables.types.name(t),
                    ));
                }
                let sp = ind.span;
                (
                    Ex {
                        kind: ExKind::TypeFirst(t),
                        ty: t,
                        span: sp,
                    },
                    Ex {
                        kind: ExKind::TypeLast(t),
                        ty: t,
                        span: sp,
                    },
                    t,
                )
            }
            ast::DiscreteRange::Attr(e) => {
                let ast::ExprKind::Attr(prefix, _, args) = &e.kind else {
                    return (Ex::int(0), Ex::int(0), ERROR);
                };
                self.range_attr(prefix, args, e.span)
            }
        }
    }

    pub(in crate::check) fn type_def(
        &mut self,
        name: &ast::Ident,
        discriminants: &[ast::Param],
        def: &TypeDef,
        span: Span,
    ) -> TypeId {
        if let Some(p) = discriminants.first()
            && !matches!(def, TypeDef::Record(_) | TypeDef::Unsupported(_))
        {
            self.err(diagnostics::unsupported(
                p.span,
                "a discriminant part on a type that is not a record",
            ));
        }
        match def {
            TypeDef::Enum(lits) => {
                let images: Vec<crate::check::types::Image> = lits
                    .iter()
                    .map(|l| match l {
                        ast::EnumLit::Ident(i) => i.name.to_uppercase().into(),
                        ast::EnumLit::Char(c, _) => format!("'{c}'").into(),
                    })
                    .collect();
                let n = images.len();
                let t = self.tables.types.add(&name.name, TypeKind::Enum(images));
                self.tables.types.list[t as usize].static_range = Some((0, n as i128 - 1));
                for (i, l) in lits.iter().enumerate() {
                    match l {
                        ast::EnumLit::Ident(id) => {
                            self.declare_checked(id, Entity::EnumLit(t, i as i64))
                        }
                        ast::EnumLit::Char(c, _) => {
                            self.declare(&char_lit_key(*c), Entity::EnumLit(t, i as i64))
                        }
                    }
                }
                t
            }
            TypeDef::IntRange(lo, hi) => {
                let l = self.expr(lo, Some(UNIV_INT));
                let h = self.expr(hi, Some(UNIV_INT));
                let t = self.tables.types.add(&name.name, TypeKind::Integer);
                match (self.static_value(&l), self.static_value(&h)) {
                    (Some(Static::Int(a)), Some(Static::Int(b))) => {
                        if a < INT_FIRST || b > INT_LAST {
                            self.err(diagnostics::integer_type_too_wide(
                                span, INT_FIRST, INT_LAST,
                            ));
                        }
                    }
                    _ => self.err(diagnostics::integer_range_not_static(span)),
                }
                let (l, h) = (Ex { ty: t, ..l }, Ex { ty: t, ..h });
                self.set_range(t, l, h);
                t
            }
            TypeDef::Modular(m) => {
                let n = self.expr(m, Some(UNIV_INT));
                let t = self.tables.types.add(&name.name, TypeKind::Integer);
                let n = match self.static_value(&n) {
                    Some(Static::Int(v)) if (1..=1 << 32).contains(&v) => v as i64,
                    Some(Static::Int(v)) => {
                        self.err(diagnostics::modulus_out_of_range(m.span, v));
                        1 << 16
                    }
                    _ => {
                        if n.ty != ERROR {
                            self.err(diagnostics::modulus_not_static(m.span));
                        }
                        1 << 16
                    }
                };
                self.tables.types.list[t as usize].modulus = Some(n);
                let (l, h) = (
                    self.mk(ExKind::Int(0), t, m.span),
                    self.mk(ExKind::Int(n - 1), t, m.span),
                );
                self.set_range(t, l, h);
                t
            }
            TypeDef::Float { digits, range } => {
                let d = self.expr(digits, Some(UNIV_INT));
                let n = match self.static_value(&d) {
                    Some(Static::Int(v)) => u32::try_from(v).ok(),
                    Some(_) => None,
                    None => {
                        self.err(diagnostics::digits_not_static(digits.span));
                        None
                    }
                };
                let t = self.tables.types.add(&name.name, TypeKind::Float);
                // GNAT: single precision up to 6 digits, else double.
                let n = n.filter(|n| (1..=15).contains(n)).unwrap_or(15);
                self.tables.types.list[t as usize].digits = Some(n);
                let max = if n <= 6 { f32::MAX as f64 } else { f64::MAX };
                self.tables.types.list[t as usize].static_frange = Some((-max, max));
                if let Some((lo, hi)) = range {
                    let l = self.expr(lo, Some(UNIV_REAL));
                    let h = self.expr(hi, Some(UNIV_REAL));
                    let (l, h) = (Ex { ty: t, ..l }, Ex { ty: t, ..h });
                    self.set_range(t, l, h);
                }
                t
            }
            TypeDef::Derived(ind) => {
                let parent = self.subtype_ind(ind);
                let mut info = self.tables.types.get(parent).clone();
                let id = self.tables.types.list.len() as TypeId;
                info.name = name.name.to_string();
                info.base = id;
                info.root = Some(self.tables.types.derivation_root(parent));
                if self.tables.types.is_hidden(parent) {
                    // From a private type whose full view is hidden here:
                    // its full view is the parent's, hidden too.
                    info.kind = self.tables.types.full_kind(parent).clone();
                    self.tables.types.list.push(info);
                    self.derived_from_private(parent, id);
                    return id;
                }
                if let TypeKind::Enum(_) = &info.kind {
                    // Derived enumeration types get their own literals.
                    let lits = self
                        .tables
                        .types
                        .enum_lits(parent)
                        .map(|l| l.to_vec())
                        .unwrap_or_default();
                    info.kind = TypeKind::Enum(lits.clone());
                    self.tables.types.list.push(info);
                    for (i, l) in lits.iter().enumerate() {
                        self.declare(l, Entity::EnumLit(id, i as i64));
                    }
                    return id;
                }
                let k = self.tables.types.kind(parent).clone();
                if let TypeKind::Array { bounds: None, .. } = &info.kind {
                } else if matches!(info.kind, TypeKind::Array { .. }) {
                } else {
                    info.kind = k;
                }
                if let Some((l, h)) = &mut info.range {
                    l.ty = id;
                    h.ty = id;
                }
                self.tables.types.list.push(info);
                id
            }
            TypeDef::Array { index, elem } => {
                let et = self.subtype_ind(elem);
                if matches!(self.tables.types.array(et), Some((_, _, None))) {
                    self.err(diagnostics::array_component_unconstrained(elem.span));
                }
                if self.tables.types.unknown_discriminants(et) {
                    self.err(diagnostics::unknown_discriminants_unconstrained(
                        elem.span,
                        &self.tname(et),
                        "an array element",
                    ));
                } else if self.needs_discriminants(et) {
                    self.err(diagnostics::discriminated_component_unconstrained(
                        elem.span,
                        self.tables.types.name(et),
                    ));
                }
                match index {
                    ast::ArrayIndex::Unconstrained(marks) => {
                        let idx: Vec<TypeId> = marks.iter().map(|m| self.type_mark(m)).collect();
                        self.tables.types.add(
                            &name.name,
                            TypeKind::Array {
                                index: idx,
                                elem: et,
                                bounds: None,
                            },
                        )
                    }
                    ast::ArrayIndex::Constrained(ranges) => {
                        let mut idx = Vec::new();
                        let mut bs = Vec::new();
                        for r in ranges {
                            let (l, h, t) = self.discrete_range(r, None);
                            let t = if self.tables.types.is_universal(t) {
                                INTEGER
                            } else {
                                t
                            };
                            idx.push(self.tables.types.base(t));
                            bs.push((self.elaborate_bound(l), self.elaborate_bound(h)));
                        }
                        self.tables.types.add(
                            &name.name,
                            TypeKind::Array {
                                index: idx,
                                elem: et,
                                bounds: Some(bs),
                            },
                        )
                    }
                }
            }
            TypeDef::Record(list) => self.record_def(name, discriminants, list),
            TypeDef::Access(ind) => {
                let t = self.subtype_ind(ind);
                self.tables.types.add(&name.name, TypeKind::Access(t))
            }
            TypeDef::Incomplete => self.tables.types.add(&name.name, TypeKind::Incomplete),
            TypeDef::Private { .. } => {
                self.err(diagnostics::private_type_context(span));
                ERROR
            }
            TypeDef::Unsupported(what) => {
                self.err(diagnostics::unsupported(span, what));
                // The error type itself: what uses the name says nothing more.
                ERROR
            }
        }
    }

    /// A record type (RM 3.8), with its discriminant part (RM 3.7) and
    /// variant parts (RM 3.8.1). The discriminants are its first components;
    /// inside the definition they stand for the value being built
    /// (`ExKind::Discriminant`).
    fn record_def(
        &mut self,
        name: &ast::Ident,
        discriminants: &[ast::Param],
        list: &ast::ComponentList,
    ) -> TypeId {
        let (mut fields, mut names) = self.discriminant_part(discriminants);
        self.scopes.push();
        for (i, f) in fields.iter().enumerate() {
            let x = Ex {
                kind: ExKind::Discriminant(i as u32),
                ty: f.ty,
                span: names[i].span,
            };
            self.declare(&f.name, Entity::Alias(Box::new(x)));
        }
        let outer = std::mem::replace(&mut self.in_discriminated, !fields.is_empty());
        self.component_list(list, &mut fields, &mut names, None);
        self.in_discriminated = outer;
        self.scopes.pop();
        let tys: Vec<TypeId> = fields.iter().map(|f| f.ty).collect();
        let t = self.tables.types.add(&name.name, TypeKind::Record(fields));
        for (i, (n, ft)) in names.into_iter().zip(tys).enumerate() {
            self.index_field(t, i as u32, n, ft);
        }
        t
    }

    /// A discriminant part (RM 3.7) of a record, task or protected type:
    /// its discriminants as components, and their names.
    pub(in crate::check) fn discriminant_part<'a>(
        &mut self,
        discriminants: &'a [ast::Param],
    ) -> (Vec<Field>, Vec<&'a ast::Ident>) {
        let mut fields: Vec<Field> = Vec::new();
        let mut names: Vec<&ast::Ident> = Vec::new();
        let mut defaults = (0, 0);
        for p in discriminants {
            let t = self.type_mark(&p.ty);
            if t != ERROR && !self.tables.types.is_discrete(t) {
                self.err(diagnostics::discriminant_not_discrete(p.ty.span));
            }
            let default = p.default.as_ref().map(|d| {
                let ex = self.expr(d, Some(t));
                self.coerce(ex, t)
            });
            for n in &p.names {
                if default.is_some() {
                    defaults.0 += 1;
                } else {
                    defaults.1 += 1;
                }
                if fields.iter().any(|f| *f.key == *n.key) {
                    self.err(diagnostics::component_declared_twice(n.span, &n.name));
                }
                fields.push(Field {
                    discriminant: true,
                    ..Field::plain(&n.name, &n.key, t, default.clone())
                });
                names.push(n);
            }
        }
        if defaults.0 > 0 && defaults.1 > 0 {
            self.err(diagnostics::discriminant_defaults_incomplete(
                discriminants[0].span,
            ));
        }
        (fields, names)
    }

    /// The components of a component list, in order, then those of its
    /// variant part, each under the conditions of its variant.
    fn component_list<'a>(
        &mut self,
        list: &'a ast::ComponentList,
        fields: &mut Vec<Field>,
        names: &mut Vec<&'a ast::Ident>,
        variant: Option<types::Variant>,
    ) {
        for c in &list.components {
            let t = self.subtype_ind(&c.ty);
            let dependent = self.in_discriminated && self.reads_discriminant(t);
            if dependent {
                self.check_discriminants_alone(t, c.ty.span);
            }
            if !dependent && matches!(self.tables.types.array(t), Some((_, _, None))) {
                self.err(diagnostics::record_component_unconstrained(c.ty.span));
            }
            if !dependent && self.tables.types.unknown_discriminants(t) {
                self.err(diagnostics::unknown_discriminants_unconstrained(
                    c.ty.span,
                    &self.tname(t),
                    "a component",
                ));
            } else if !dependent && self.needs_discriminants(t) {
                self.err(diagnostics::discriminated_component_unconstrained(
                    c.ty.span,
                    self.tables.types.name(t),
                ));
            }
            let default = c.default.as_ref().map(|d| {
                let ex = self.expr(d, Some(t));
                self.coerce(ex, t)
            });
            let ty = if dependent {
                self.tables.types.base(t)
            } else {
                t
            };
            for n in &c.names {
                if fields.iter().any(|f| *f.key == *n.key) {
                    self.err(diagnostics::component_declared_twice(n.span, &n.name));
                }
                fields.push(Field {
                    variant: variant.clone(),
                    dependent: dependent.then_some(t),
                    ..Field::plain(&n.name, &n.key, ty, default.clone())
                });
                names.push(n);
            }
        }
        let Some(vp) = &list.variants else {
            return;
        };
        let Some(d) = fields
            .iter()
            .position(|f| f.discriminant && *f.key == *vp.discriminant.key)
        else {
            if self.lookup(&vp.discriminant.key).is_empty() {
                self.err(diagnostics::not_declared(
                    vp.discriminant.span,
                    &vp.discriminant.name,
                ));
            } else {
                self.err(diagnostics::variant_not_discriminant(
                    vp.discriminant.span,
                    &vp.discriminant.name,
                ));
            }
            for arm in &vp.arms {
                self.component_list(&arm.body, fields, names, variant.clone());
            }
            return;
        };
        let dt = fields[d].ty;
        let choice_lists: Vec<&[ast::Choice]> =
            vp.arms.iter().map(|a| a.choices.as_slice()).collect();
        let (mut ranges, others) = self.case_choices(dt, &choice_lists, vp.span);
        if let Some(o) = others {
            // `when others`: every value no other arm names.
            let (lo, hi) = self
                .tables
                .types
                .discrete_bounds(dt)
                .map(|(l, h)| (l as i64, h as i64))
                .unwrap_or((i64::MIN, i64::MAX));
            let mut taken: Vec<(i64, i64)> = ranges.iter().flatten().copied().collect();
            taken.sort();
            let mut rest = Vec::new();
            let mut next = lo;
            for (a, b) in taken {
                if a > next {
                    rest.push((next, a - 1));
                }
                next = next.max(b.saturating_add(1));
            }
            if next <= hi {
                rest.push((next, hi));
            }
            ranges[o] = rest;
        }
        for (arm, rs) in vp.arms.iter().zip(ranges) {
            let mut conds: Vec<types::Governs> =
                variant.as_deref().map(|v| v.to_vec()).unwrap_or_default();
            conds.push((d as u32, rs.into()));
            self.component_list(&arm.body, fields, names, Some(conds.into()));
        }
    }

    /// Whether a component's subtype reads the discriminants of the record
    /// being defined (its bounds or discriminant values do).
    pub(in crate::check) fn reads_discriminant(&self, t: TypeId) -> bool {
        self.constraint_parts(t)
            .into_iter()
            .any(ir::reads_discriminant)
    }

    /// A component's subtype that reads the discriminants reads each alone
    /// (RM 3.8(12)): `String (1 .. Size)`, not `String (1 .. Size + 1)`.
    pub(in crate::check) fn check_discriminants_alone(&mut self, t: TypeId, span: Span) {
        fn alone(e: &Ex) -> bool {
            match &e.kind {
                ExKind::Discriminant(_) => true,
                ExKind::RangeCheck(x, _) => alone(x),
                _ => false,
            }
        }
        if self
            .constraint_parts(t)
            .into_iter()
            .any(|e| ir::reads_discriminant(e) && !alone(e))
        {
            self.err(diagnostics::discriminant_not_alone(span));
        }
    }

    /// The expressions of a subtype's constraint: its range, its bounds,
    /// its discriminants' values.
    fn constraint_parts(&self, t: TypeId) -> Vec<&Ex> {
        let info = self.tables.types.get(t);
        let range = info.range.iter().flat_map(|(l, h)| [l, h]);
        let bounds = match &info.kind {
            TypeKind::Array {
                bounds: Some(bs), ..
            } => bs.iter().flat_map(|(l, h)| [l, h]).collect(),
            _ => Vec::new(),
        };
        let discr = info.discr.iter().flat_map(|d| d.iter());
        range.chain(bounds).chain(discr).collect()
    }

    /// An access type to a type holding tasks makes its declarative region
    /// a master: the tasks its allocators create belong to that region,
    /// which waits for them at its end, wherever the allocator runs.
    pub(super) fn collection_master(&mut self, t: TypeId, span: Span, out: &mut Vec<Stmt>) {
        let designated = match self.tables.types.kind(t) {
            TypeKind::Access(d) => *d,
            _ => return,
        };
        if !self.tables.types.has_task(designated) || self.tables.types.get(t).master.is_some() {
            return;
        }
        if let Some(m) = self.tasking.masters.last_mut() {
            *m = true;
        }
        let v = self.new_slot();
        self.tables.types.list[t as usize].master = Some(v);
        out.push(Stmt {
            kind: StmtKind::NoteMaster(v),
            span,
        });
    }
}
