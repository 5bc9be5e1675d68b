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
        if self.bounds_out.is_none() || self.static_value(&e).is_some() || e.ty == ERROR {
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

    fn set_range(&mut self, st: TypeId, l: Ex, h: Ex) {
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
        def: &TypeDef,
        span: Span,
    ) -> TypeId {
        match def {
            TypeDef::Enum(lits) => {
                let images: Vec<String> = lits
                    .iter()
                    .map(|l| match l {
                        ast::EnumLit::Ident(i) => i.name.to_uppercase(),
                        ast::EnumLit::Char(c, _) => format!("'{c}'"),
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
            TypeDef::Record(components) => {
                let mut fields: Vec<Field> = Vec::new();
                for c in components {
                    let t = self.subtype_ind(&c.ty);
                    if matches!(self.tables.types.array(t), Some((_, _, None))) {
                        self.err(diagnostics::record_component_unconstrained(c.ty.span));
                    }
                    let default = c.default.as_ref().map(|d| {
                        let ex = self.expr(d, Some(t));
                        self.coerce(ex, t)
                    });
                    for n in &c.names {
                        if fields.iter().any(|f| *f.key == *n.key) {
                            self.err(diagnostics::component_declared_twice(n.span, &n.name));
                        }
                        fields.push(Field {
                            name: n.name.to_string(),
                            key: n.key.to_string(),
                            ty: t,
                            default: default.clone(),
                        });
                    }
                }
                let names: Vec<&ast::Ident> = components.iter().flat_map(|c| &c.names).collect();
                let tys: Vec<TypeId> = fields.iter().map(|f| f.ty).collect();
                let t = self.tables.types.add(&name.name, TypeKind::Record(fields));
                for (i, (n, ft)) in names.into_iter().zip(tys).enumerate() {
                    self.index_field(t, i as u32, n, ft);
                }
                t
            }
            TypeDef::Access(ind) => {
                let t = self.subtype_ind(ind);
                self.tables.types.add(&name.name, TypeKind::Access(t))
            }
            TypeDef::Incomplete => self.tables.types.add(&name.name, TypeKind::Incomplete),
            TypeDef::Unsupported(what) => {
                self.err(diagnostics::unsupported(span, what));
                // The error type itself: what uses the name says nothing more.
                ERROR
            }
        }
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
