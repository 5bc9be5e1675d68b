//! Declarations: types, subtypes, objects, numbers, exceptions, subprograms
//! and packages.

use super::tasks::BodyKind;
use super::*;
use crate::syntax::ast::{DeclKind, TypeDef};

impl Checker {
    pub(super) fn decls(&mut self, decls: &[ast::Decl], out: &mut Vec<Stmt>) {
        for d in decls {
            self.decl(d, out);
        }
    }

    /// [`Self::decls`] for a declarative part that must complete what it
    /// declares (a body's, a block's, a package body's): a subprogram
    /// declared in it without a body there is an error, as in GNAT
    /// ("missing body"), not a `Program_Error` when it is called.
    pub(super) fn decls_completed(&mut self, decls: &[ast::Decl], out: &mut Vec<Stmt>) {
        let before = self.funcs.len();
        self.decls(decls, out);
        for d in decls {
            let DeclKind::SubprogramDecl { spec, import: None } = &d.kind else {
                continue;
            };
            let declared = self
                .funcs
                .iter()
                .skip(before)
                .position(|f| f.span == spec.span)
                .map(|i| before + i);
            if let Some(f) = declared
                && self.funcs[f].body.is_none()
                && self.imports[f].is_none()
            {
                let name = spec.name.display();
                self.err(diagnostics::no_body(spec.span, &name));
            }
        }
        // A package whose spec declares a subprogram needs a body in the
        // same declarative part (GNAT: missing body for "P"): without it, a
        // call would stop the program half-way with Program_Error.
        // A declaration that did not parse, or a refused one (`package body
        // P is separate;`), may be the body: no second error for it.
        if decls.iter().any(|d| {
            matches!(
                d.kind,
                DeclKind::Unsupported(_) | DeclKind::UnsupportedNamed(..)
            )
        }) {
            return;
        }
        for d in decls {
            let DeclKind::PackageSpec(p) = &d.kind else {
                continue;
            };
            // What the check of the spec left without a body (a function
            // completed by an expression function in the private part has
            // one).
            let needs_body = match self.denote(&p.name, false).first() {
                Some(Entity::Package(i)) => self.packages[*i].names.values().flatten().any(|e| {
                    matches!(e, Entity::Func(f)
                            if self.funcs[*f as usize].body.is_none()
                                && self.imports[*f as usize].is_none())
                }),
                _ => false,
            };
            let name = crate::syntax::parser::expr_text(&p.name);
            let has_body = decls.iter().any(|b| {
                matches!(&b.kind, DeclKind::PackageBody(b)
                    if crate::syntax::parser::expr_text(&b.name).eq_ignore_ascii_case(&name))
            });
            if needs_body && !has_body {
                self.err(diagnostics::package_without_body(p.name.span, &name));
            }
        }
    }

    pub(super) fn decl(&mut self, d: &ast::Decl, out: &mut Vec<Stmt>) {
        let outer = self.cur_decl.replace(d.span);
        self.decl_inner(d, out);
        self.cur_decl = outer;
    }

    fn decl_inner(&mut self, d: &ast::Decl, out: &mut Vec<Stmt>) {
        match &d.kind {
            DeclKind::Object {
                names,
                constant,
                ty,
                init,
                anon,
            } => {
                if let Some(def) = anon
                    && let ast::ExprKind::Name(tn) = &ty.mark.kind
                {
                    let t = self.type_def(tn, def, d.span);
                    self.declare(&tn.name, Entity::Type(t));
                }
                let t = self.elaborating(out, |c| c.subtype_ind(ty));
                self.object(names, *constant, t, init.as_ref(), d.span, out);
            }
            DeclKind::Number { names, value } => {
                let ex = self.expr(value, None);
                let v = match self.static_value(&ex) {
                    Some(v) => v,
                    None => {
                        self.err(diagnostics::named_number_not_static(value.span));
                        Static::Int(0)
                    }
                };
                for n in names {
                    self.declare_checked(n, Entity::Number(v.clone()));
                }
            }
            DeclKind::Type { name, def } => {
                // Completing an incomplete type keeps its id.
                let prev = self
                    .scopes
                    .last()
                    .and_then(|s| s.names.get(&*name.key))
                    .and_then(|es| es.last().cloned());
                if let Some(Entity::Type(old)) = prev
                    && matches!(self.types.kind(old), TypeKind::Incomplete)
                {
                    let t = self.elaborating(out, |c| c.type_def(name, def, d.span));
                    let mut info = self.types.get(t).clone();
                    info.base = old;
                    self.types.list[old as usize] = info;
                    self.retarget_enum_lits(t, old);
                    // Access types declared before the completion that now
                    // designate tasks get their master here (same region).
                    let before: Vec<TypeId> = (0..self.types.list.len() as TypeId)
                        .filter(|&a| {
                            matches!(self.types.kind(a), TypeKind::Access(d) if self.types.base(*d) == old)
                        })
                        .collect();
                    for a in before {
                        self.collection_master(a, d.span, out);
                    }
                    return;
                }
                if matches!(def, TypeDef::Incomplete) {
                    let t = self.types.add(&name.name, TypeKind::Incomplete);
                    self.declare_checked(name, Entity::Type(t));
                    return;
                }
                // Its bounds (an array's, its components') are evaluated
                // once, here.
                let t = self.elaborating(out, |c| c.type_def(name, def, d.span));
                self.declare_checked(name, Entity::Type(t));
                self.collection_master(t, d.span, out);
            }
            DeclKind::Subtype { name, ind } => {
                let of = self.elaborating(out, |c| c.subtype_ind(ind));
                let t = self.types.add_subtype(&name.name, of);
                self.declare_checked(name, Entity::Type(t));
            }
            DeclKind::Exception { names } => {
                for n in names {
                    let id = self.excs.len() as ExcId;
                    self.excs.push(Exception {
                        name: self.exc_name(&n.name),
                    });
                    self.declare_checked(n, Entity::Exc(id));
                }
            }
            DeclKind::SubprogramDecl { spec, import } => {
                let f = self.subprogram_decl(spec, true);
                if let (Some(f), None) = (f, import) {
                    self.elab_flag(f, false, d.span, out);
                }
                if let (Some(f), Some(name)) = (f, import) {
                    if !self.known_builtin(name) {
                        self.err(diagnostics::no_builtin(spec.span, name));
                    } else if let Some(want) = self.import_mismatch(f, name) {
                        let declared = self.signature(f);
                        self.err(diagnostics::import_profile_mismatch(
                            spec.span, name, &declared, &want.text,
                        ));
                    }
                    self.imports[f as usize] = Some(name.clone());
                }
            }
            DeclKind::SubprogramBody(b) => {
                if let Some(f) = self.subprogram_body(b) {
                    self.elab_flag(f, true, d.span, out);
                }
            }
            DeclKind::PackageSpec(p) => self.package_spec(p, out),
            DeclKind::PackageBody(p) => self.package_body(p, out),
            DeclKind::Use(names) => self.use_clause(names),
            DeclKind::Unsupported(what) => {
                if *what == "<error>" || *what == "pragma" {
                    return;
                }
                self.err(diagnostics::unsupported_declaration(d.span, what));
            }
            DeclKind::UnsupportedNamed(what, names) => {
                self.err(diagnostics::unsupported(d.span, what));
                for n in names {
                    self.unsupported_names.insert(n.key.to_string());
                }
            }
            DeclKind::TaskSpec(t) => self.task_spec(t, d.span, out),
            DeclKind::TaskBody(b) => self.task_body(b, d.span),
            DeclKind::ProtectedSpec(p) => self.protected_spec(p, out),
            DeclKind::ProtectedBody(b) => self.protected_body(b),
            DeclKind::EntryBody(b) => self.entry_body(b),
            DeclKind::InterruptUse { entry, address } => {
                self.address_clause(entry, address, d.span)
            }
            DeclKind::Pragma { name, .. } => self.pragma(name, d.span),
        }
    }

    /// The literals of a completed incomplete type (declared just now, in
    /// the current scope) become the literals of the type first declared.
    fn retarget_enum_lits(&mut self, from: TypeId, to: TypeId) {
        let Some(s) = self.scopes.last_mut() else {
            return;
        };
        let is_lit = |e: &Entity| matches!(e, Entity::EnumLit(t, _) if *t == from);
        let keys: Vec<String> = s
            .names
            .iter()
            .filter(|(_, es)| es.iter().any(is_lit))
            .map(|(k, _)| k.clone())
            .collect();
        for k in keys {
            if let Some(es) = s.names.get_mut(&k) {
                for e in es.iter_mut() {
                    if let Entity::EnumLit(t, _) = e
                        && *t == from
                    {
                        *t = to;
                    }
                }
            }
        }
    }

    pub(super) fn object(
        &mut self,
        names: &[ast::Ident],
        constant: bool,
        t: TypeId,
        init: Option<&ast::Expr>,
        span: Span,
        out: &mut Vec<Stmt>,
    ) {
        let unconstrained_array = self.types.array(t).is_some_and(|a| a.2.is_none());
        let init_ex = init.map(|e| {
            let ex = self.expr(e, Some(t));
            self.coerce(ex, t)
        });
        if init_ex.is_none() && unconstrained_array {
            self.err(diagnostics::unconstrained_object(span, self.types.name(t)));
        }
        if constant && init_ex.is_none() {
            self.err(diagnostics::constant_without_value(span));
        }
        let static_v = if constant {
            init_ex
                .as_ref()
                .and_then(|e| self.static_value(e))
                .filter(|_| self.types.is_scalar(t))
        } else {
            None
        };
        let creates_task = self.types.has_task(t);
        if creates_task && let Some(m) = self.masters.last_mut() {
            *m = true;
        }
        // An unconstrained array object takes the bounds of its initial value.
        for n in names {
            let var = self.new_slot();
            let value = match &init_ex {
                Some(e) => e.clone(),
                None => Ex {
                    kind: ExKind::Default(t),
                    ty: t,
                    span,
                },
            };
            out.push(Stmt {
                kind: StmtKind::Init(var, value),
                span,
            });
            // A task or protected object works without being read.
            if !constant
                && !self.types.is_unique(t)
                && self.level > 0
                && let Some(frame) = self.unread.get_mut(self.level as usize - 1)
            {
                frame.insert(var, (n.name.to_string(), n.span, false));
            }
            self.declare_checked(
                n,
                Entity::Var {
                    var,
                    ty: t,
                    constant,
                    value: static_v.clone(),
                },
            );
        }
        // A library-level (or script) task is activated with the others
        // before the next statement (see `activate_library_tasks`).
        if creates_task && self.masters.is_empty() {
            self.library_tasks = true;
        }
    }

    /// The type an expression of a subtype mark denotes, reporting errors.
    pub(super) fn type_mark(&mut self, n: &ast::Expr) -> TypeId {
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

    pub(super) fn subtype_ind(&mut self, ind: &ast::SubtypeInd) -> TypeId {
        let t = self.type_mark(&ind.mark);
        match &ind.constraint {
            None => t,
            Some(ast::Constraint::Range(lo, hi)) => {
                if !self.types.is_scalar(t) && t != ERROR {
                    self.err(diagnostics::range_constraint_not_scalar(
                        ind.span,
                        self.types.name(t),
                    ));
                    return t;
                }
                let name = self.types.name(t).to_string();
                self.constrained_scalar(&name, t, lo, hi)
            }
            Some(ast::Constraint::Index(ranges)) => {
                let Some((index, elem, bounds)) = self
                    .types
                    .array(t)
                    .map(|(i, e, b)| (i.to_vec(), e, b.is_some()))
                else {
                    if t != ERROR {
                        self.err(diagnostics::index_constraint_not_array(
                            ind.span,
                            self.types.name(t),
                        ));
                    }
                    return t;
                };
                if bounds {
                    self.err(diagnostics::already_constrained(
                        ind.span,
                        self.types.name(t),
                    ));
                    return t;
                }
                if ranges.len() != index.len() {
                    self.err(diagnostics::index_constraint_count(
                        ind.span,
                        self.types.name(t),
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
                let name = self.types.name(t).to_string();
                let st = self.types.add_subtype(&name, t);
                self.types.list[st as usize].kind = TypeKind::Array {
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
        let base = self.types.base(t);
        let l = self.expr(lo, Some(base));
        let l = self.coerce_base(l, base);
        let h = self.expr(hi, Some(base));
        let h = self.coerce_base(h, base);
        let st = self.types.add_subtype(name, t);
        self.set_range(st, l, h);
        st
    }

    /// Runs `f` (the check of a subtype indication or type definition of a
    /// declaration) with its non-static bounds elaborated into `out`: they
    /// are evaluated once, when the declaration is (RM 3.2.2), not at each
    /// check against the subtype.
    fn elaborating<T>(&mut self, out: &mut Vec<Stmt>, f: impl FnOnce(&mut Self) -> T) -> T {
        let outer = self.bounds_out.replace(Vec::new());
        let r = f(self);
        let got = std::mem::replace(&mut self.bounds_out, outer);
        out.extend(got.unwrap_or_default());
        r
    }

    /// A bound that is not static, while a declaration is elaborated: a
    /// fresh slot that holds its value from now on.
    pub(super) fn elaborate_bound(&mut self, e: Ex) -> Ex {
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
        let info = &mut self.types.list[st as usize];
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
    pub(super) fn discrete_range(
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
                if !self.types.is_discrete(t) && t != ERROR {
                    self.err(diagnostics::range_not_discrete(a.span, self.types.name(t)));
                }
                (l, h, t)
            }
            ast::DiscreteRange::Subtype(ind) => {
                let t = self.subtype_ind(ind);
                if !self.types.is_discrete(t) && t != ERROR {
                    self.err(diagnostics::not_a_discrete_type(
                        ind.span,
                        self.types.name(t),
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

    pub(super) fn type_def(&mut self, name: &ast::Ident, def: &TypeDef, span: Span) -> TypeId {
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
                let t = self.types.add(&name.name, TypeKind::Enum(images));
                self.types.list[t as usize].static_range = Some((0, n as i128 - 1));
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
                let t = self.types.add(&name.name, TypeKind::Integer);
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
                let t = self.types.add(&name.name, TypeKind::Float);
                // GNAT: single precision up to 6 digits, else double.
                let n = n.filter(|n| (1..=15).contains(n)).unwrap_or(15);
                self.types.list[t as usize].digits = Some(n);
                let max = if n <= 6 { f32::MAX as f64 } else { f64::MAX };
                self.types.list[t as usize].static_frange = Some((-max, max));
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
                let mut info = self.types.get(parent).clone();
                let id = self.types.list.len() as TypeId;
                info.name = name.name.to_string();
                info.base = id;
                if let TypeKind::Enum(_) = &info.kind {
                    // Derived enumeration types get their own literals.
                    let lits = self
                        .types
                        .enum_lits(parent)
                        .map(|l| l.to_vec())
                        .unwrap_or_default();
                    info.kind = TypeKind::Enum(lits.clone());
                    self.types.list.push(info);
                    for (i, l) in lits.iter().enumerate() {
                        self.declare(l, Entity::EnumLit(id, i as i64));
                    }
                    return id;
                }
                let k = self.types.kind(parent).clone();
                if let TypeKind::Array { bounds: None, .. } = &info.kind {
                } else if matches!(info.kind, TypeKind::Array { .. }) {
                } else {
                    info.kind = k;
                }
                if let Some((l, h)) = &mut info.range {
                    l.ty = id;
                    h.ty = id;
                }
                self.types.list.push(info);
                id
            }
            TypeDef::Array { index, elem } => {
                let et = self.subtype_ind(elem);
                if matches!(self.types.array(et), Some((_, _, None))) {
                    self.err(diagnostics::array_component_unconstrained(elem.span));
                }
                match index {
                    ast::ArrayIndex::Unconstrained(marks) => {
                        let idx: Vec<TypeId> = marks.iter().map(|m| self.type_mark(m)).collect();
                        self.types.add(
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
                            let t = if self.types.is_universal(t) {
                                INTEGER
                            } else {
                                t
                            };
                            idx.push(self.types.base(t));
                            bs.push((self.elaborate_bound(l), self.elaborate_bound(h)));
                        }
                        self.types.add(
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
                    if matches!(self.types.array(t), Some((_, _, None))) {
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
                let t = self.types.add(&name.name, TypeKind::Record(fields));
                for (i, (n, ft)) in names.into_iter().zip(tys).enumerate() {
                    self.index_field(t, i as u32, n, ft);
                }
                t
            }
            TypeDef::Access(ind) => {
                let t = self.subtype_ind(ind);
                self.types.add(&name.name, TypeKind::Access(t))
            }
            TypeDef::Incomplete => self.types.add(&name.name, TypeKind::Incomplete),
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
    fn collection_master(&mut self, t: TypeId, span: Span, out: &mut Vec<Stmt>) {
        let designated = match self.types.kind(t) {
            TypeKind::Access(d) => *d,
            _ => return,
        };
        if !self.types.has_task(designated) || self.types.get(t).master.is_some() {
            return;
        }
        if let Some(m) = self.masters.last_mut() {
            *m = true;
        }
        let v = self.new_slot();
        self.types.list[t as usize].master = Some(v);
        out.push(Stmt {
            kind: StmtKind::NoteMaster(v),
            span,
        });
    }

    // ---- subprograms ----

    pub(super) fn params(&mut self, ps: &[ast::Param]) -> Vec<Param> {
        let mut out = Vec::new();
        for p in ps {
            let t = self.type_mark(&p.ty);
            let default = p.default.as_ref().map(|d| {
                let ex = self.expr(d, Some(t));
                self.coerce(ex, t)
            });
            if default.is_some() && p.mode != ast::Mode::In {
                self.err(diagnostics::default_on_non_in_parameter(p.span));
            }
            for n in &p.names {
                out.push(Param {
                    name: n.name.to_string(),
                    mode: p.mode,
                    ty: t,
                    default: default.clone(),
                });
            }
        }
        out
    }

    pub(super) fn same_profile(
        &self,
        a: &Subprogram,
        params: &[Param],
        ret: Option<TypeId>,
    ) -> bool {
        a.params.len() == params.len()
            && a.params
                .iter()
                .zip(params)
                .all(|(x, y)| self.types.base(x.ty) == self.types.base(y.ty) && x.mode == y.mode)
            && a.ret.map(|t| self.types.base(t)) == ret.map(|t| self.types.base(t))
    }

    /// Declares a subprogram (or finds its earlier declaration) and returns its id.
    fn subprogram_decl(
        &mut self,
        spec: &ast::SubprogramSpec,
        declare_only: bool,
    ) -> Option<FuncId> {
        let params = self.params(&spec.params);
        let ret = spec.ret.as_ref().map(|r| self.type_mark(r));
        let key = spec.name.key();
        if let ast::Designator::Op(op, sp) = &spec.name {
            let ok = [
                "+", "-", "*", "/", "**", "=", "<", "<=", ">", ">=", "&", "abs", "not", "and",
                "or", "xor", "mod", "rem",
            ];
            if !ok.contains(&op.to_ascii_lowercase().as_str()) {
                self.err(diagnostics::not_an_operator_symbol(*sp, op));
            }
        }
        // A body completes an earlier declaration with the same profile.
        let mut existing: Vec<FuncId> = self
            .scopes
            .last()
            .and_then(|s| s.names.get(&key))
            .map(|es| super::expr::funcs_of(es))
            .unwrap_or_default();
        if let Some((p, true)) = self.scopes.last().and_then(|s| s.package)
            && let Some(es) = self.packages[p].names.get(&key)
        {
            existing.extend(super::expr::funcs_of(es));
        }
        for f in existing {
            let sub = &self.funcs[f as usize];
            if self.same_profile(sub, &params, ret) {
                if declare_only || sub.body.is_some() || self.imports[f as usize].is_some() {
                    self.err(diagnostics::declared_with_same_profile(
                        spec.span,
                        &spec.name.display(),
                    ));
                }
                return Some(f);
            }
        }
        let id = self.funcs.len() as FuncId;
        self.funcs.push(Subprogram {
            name: spec.name.display(),
            params,
            ret,
            level: self.level + 1,
            nslots: 0,
            body: None,
            span: spec.span,
        });
        self.imports.push(None);
        let tys: Vec<TypeId> = self.funcs[id as usize]
            .params
            .iter()
            .map(|p| p.ty)
            .collect();
        let written = spec.params.iter().flat_map(|p| &p.names);
        for (i, (pid, ty)) in written.zip(tys).enumerate() {
            self.index_param(id, i as u32, pid, ty);
        }
        match &spec.name {
            ast::Designator::Ident(i) => self.declare_checked(i, Entity::Func(id)),
            ast::Designator::Op(_, _) => self.declare(&key, Entity::Func(id)),
        }
        Some(id)
    }

    /// The elaboration of a subprogram declared apart from its body
    /// (RM 3.11(14)): at the declaration (`body` false) a hidden Boolean
    /// of the region, False; at the body, True. Nothing for a body
    /// without an earlier declaration.
    fn elab_flag(&mut self, f: FuncId, body: bool, span: Span, out: &mut Vec<Stmt>) {
        let var = match self.elab_flags.get(&f) {
            Some(v) => *v,
            None if body => return,
            None => {
                let v = self.new_slot();
                self.elab_flags.insert(f, v);
                v
            }
        };
        let value = self.mk(ExKind::Int(body as i64), BOOLEAN, span);
        out.push(Stmt {
            kind: StmtKind::Init(var, value),
            span,
        });
    }

    /// The first statement of the body of `f` when it has an elaboration
    /// flag: a call before the body was elaborated raises Program_Error
    /// (RM 3.11(14)), before anything of the body runs, at the
    /// declaration `span` (the report's call chain shows the call).
    fn elab_check(&self, f: FuncId, span: Span) -> Option<Stmt> {
        let var = *self.elab_flags.get(&f)?;
        let flag = self.mk(ExKind::Var(var), BOOLEAN, span);
        let name = &self.funcs[f as usize].name;
        let msg = format!(
            "access before elaboration: `{name}` was called before its body was elaborated"
        );
        let msg = self.mk(ExKind::Str(Rc::from(msg.as_str())), STRING, span);
        Some(Stmt {
            kind: StmtKind::If(
                vec![(
                    self.mk(ExKind::Not(Box::new(flag)), BOOLEAN, span),
                    vec![Stmt {
                        kind: StmtKind::Raise(PROGRAM_ERROR, Some(msg)),
                        span,
                    }],
                )],
                Vec::new(),
            ),
            span,
        })
    }

    fn subprogram_body(&mut self, b: &ast::SubprogramBody) -> Option<FuncId> {
        let f = self.subprogram_decl(&b.spec, false)?;
        if let Some((end, sp)) = &b.end_name {
            let name = b.spec.name.display();
            if end.eq_ignore_ascii_case(&name) {
                self.index_ref(*sp, &end.to_lowercase(), &Entity::Func(f));
            } else {
                self.err(diagnostics::end_name_mismatch(*sp, end, &name));
            }
        }
        let written: Vec<&ast::Ident> = b.spec.params.iter().flat_map(|p| p.names.iter()).collect();
        // A statement the parser could not read may have been the return
        // (asked before the check, which may take the statements).
        let unreadable = b
            .body
            .stmts
            .borrow()
            .iter()
            .any(|s| matches!(s.kind, ast::StmtKind::Error));
        let saw_return = self.check_body(
            f,
            &b.spec.name.key(),
            &b.spec.name.display(),
            &written,
            &b.decls,
            &b.body,
            BodyKind::Subprogram,
        );
        let ret = self.funcs[f as usize].ret;
        if ret.is_some() && !saw_return && !unreadable {
            self.err(diagnostics::function_without_return(
                b.spec.span,
                &b.spec.name.display(),
            ));
        }
        Some(f)
    }

    /// Checks the body of subprogram `f` (a subprogram, a task body, a
    /// protected operation or entry): its parameters become its first
    /// slots, then its declarations and statements. A body whose
    /// declarations may create tasks is their master; a task body also
    /// reports its activation. Returns whether a `return` was seen.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn check_body(
        &mut self,
        f: FuncId,
        key: &str,
        display: &str,
        written: &[&ast::Ident],
        decls: &[ast::Decl],
        body: &ast::Block,
        kind: BodyKind,
    ) -> bool {
        let ret = self.funcs[f as usize].ret;
        let params = self.funcs[f as usize].params.clone();
        // Nested bodies are not the main program's.
        let main = std::mem::take(&mut self.main_body);
        self.level += 1;
        self.unread.push(HashMap::new());
        self.ctx.push(FuncCtx {
            func: Some(f),
            ret,
            saw_return: false,
            next_slot: 0,
        });
        self.push_scope();
        self.name_scope(key);
        self.unit_path.push(display.to_string());
        let mut written = written.iter();
        let mut last = None;
        for (i, p) in params.iter().enumerate() {
            let var = self.new_slot();
            last = Some(var);
            let e = Entity::Var {
                var,
                ty: p.ty,
                constant: p.mode == ast::Mode::In,
                value: None,
            };
            match written.next() {
                // As the body writes it (the same name as its declaration's
                // in a legal completion; a duplicate body's own otherwise).
                Some(id) => {
                    self.index_body_param(f, i as u32, id, &e);
                    self.declare(&id.name, e);
                }
                // The hidden object parameter of a protected operation.
                None => self.declare(&p.name, e),
            }
        }
        let outer_function_obj = self.prot_function_obj;
        if let BodyKind::Protected(k) = kind {
            self.prot_ctx.push((k, last));
            self.declare_components(k, last);
            self.prot_function_obj = if self.funcs[f as usize].ret.is_some() {
                last
            } else {
                None
            };
        }
        self.masters.push(false);
        let decl_span = self.funcs[f as usize].span;
        let mut elab: Vec<Stmt> = self.elab_check(f, decl_span).into_iter().collect();
        self.decls_completed(decls, &mut elab);
        self.parts_here = kind == BodyKind::Subprogram && main;
        let inner = self.block(body);
        let creates = self.masters.pop().unwrap_or(false);
        let body_span = body.span;
        let elab = self.master_region(elab, inner, body_span, creates, kind == BodyKind::Task);
        if matches!(kind, BodyKind::Protected(_)) {
            self.prot_ctx.pop();
        }
        self.prot_function_obj = outer_function_obj;
        self.unit_path.pop();
        self.pop_scope();
        let ctx = self.ctx.pop().expect("ctx");
        self.report_unread();
        self.level -= 1;
        let sub = &mut self.funcs[f as usize];
        sub.nslots = ctx.next_slot;
        sub.body = Some(Rc::new(Body {
            stmts: elab,
            handlers: Vec::new(),
        }));
        ctx.saw_return
    }

    /// The last `end ...;` of a region's text (the whole span if there is
    /// none).
    fn end_of(&self, span: Span) -> Span {
        let Some(t) = self.texts.get(&span.context) else {
            return span;
        };
        let Some(text) = t.get(span.lo()..span.hi().min(t.len())) else {
            return span;
        };
        match text.to_ascii_lowercase().rfind("end") {
            Some(i) => Span {
                start: span.start + crate::diag::offset(i),
                end: span.end,
                context: span.context,
            },
            None => span,
        }
    }

    /// The statements of a declarative region: its elaboration `elab`,
    /// then `inner`. When the region may create tasks, they are activated
    /// at its `begin` and the region is their master; a task body always
    /// reports its activation.
    pub(super) fn master_region(
        &mut self,
        mut elab: Vec<Stmt>,
        inner: Body,
        span: Span,
        creates: bool,
        task_body: bool,
    ) -> Vec<Stmt> {
        if creates || task_body {
            elab.push(Stmt {
                kind: StmtKind::Activate,
                span,
            });
        }
        elab.push(Stmt {
            kind: StmtKind::Block(Box::new(inner)),
            span,
        });
        if !creates {
            return elab;
        }
        // The region's `end`, where it waits for its tasks.
        let span = self.end_of(span);
        vec![Stmt {
            kind: StmtKind::Master(Box::new(Body {
                stmts: elab,
                handlers: Vec::new(),
            })),
            span,
        }]
    }

    fn package_spec(&mut self, p: &ast::PackageSpec, out: &mut Vec<Stmt>) {
        let name = crate::syntax::parser::expr_text(&p.name);
        let full = if self.level == 0 && self.unit_path.is_empty() {
            name.clone()
        } else {
            format!("{}.{}", self.unit_path.join("."), name)
        };
        let idx = if self.level == 0 && self.unit_path.is_empty() {
            let idx = self.package(&full);
            if let ast::ExprKind::Select(_, id) | ast::ExprKind::Name(id) = &p.name.kind {
                self.index_def(&id.name, id.span, &Entity::Package(idx), None);
            }
            idx
        } else {
            let idx = self.packages.len();
            self.packages.push(Package {
                name: full.clone(),
                names: PMap::new(),
                private: PMap::new(),
            });
            if let ast::ExprKind::Name(id) = &p.name.kind {
                self.declare_checked(id, Entity::Package(idx));
            }
            idx
        };
        self.push_scope();
        self.set_scope_package(idx, false);
        // Child units see their parents' declarations.
        if let Some((parent, _)) = full.rsplit_once('.')
            && let Some(pi) = self
                .packages
                .iter()
                .position(|x| x.name.eq_ignore_ascii_case(parent))
        {
            self.scopes.last_mut().expect("scope").uses.push(pi);
            self.mark_uses(self.scopes.len() - 1);
        }
        self.unit_path.extend(name.split('.').map(str::to_string));
        self.decls(&p.decls, out);
        self.set_scope_package(idx, true);
        self.decls(&p.private, out);
        for _ in name.split('.') {
            self.unit_path.pop();
        }
        self.pop_scope();
    }

    fn package_body(&mut self, p: &ast::PackageBody, out: &mut Vec<Stmt>) {
        let name = crate::syntax::parser::expr_text(&p.name);
        let idx = match self.denote(&p.name, false).first() {
            Some(Entity::Package(i)) => *i,
            _ => {
                self.err(diagnostics::package_body_without_spec(p.name.span, &name));
                return;
            }
        };
        self.push_scope();
        self.set_scope_package(idx, true);
        self.unit_path.extend(name.split('.').map(str::to_string));
        self.decls_completed(&p.decls, out);
        if let Some(init) = &p.init {
            let b = self.block(init);
            out.push(Stmt {
                kind: StmtKind::Block(Box::new(b)),
                span: init.span,
            });
        }
        for _ in name.split('.') {
            self.unit_path.pop();
        }
        self.pop_scope();
        // Every subprogram declared in the spec needs a body.
        let missing: Vec<String> = self.packages[idx]
            .names
            .values()
            .flatten()
            .filter_map(|e| match e {
                Entity::Func(f)
                    if self.funcs[*f as usize].body.is_none()
                        && self.imports[*f as usize].is_none() =>
                {
                    Some(self.funcs[*f as usize].name.clone())
                }
                _ => None,
            })
            .collect();
        for m in missing {
            self.err(diagnostics::package_body_lacks(p.span, &name, &m));
        }
    }

    /// The value of a static expression, if it is one.
    pub(super) fn static_value(&self, e: &Ex) -> Option<Static> {
        use Static::*;
        Some(match &e.kind {
            ExKind::Int(v) => Int(*v as i128),
            ExKind::Real(v) => Real(
                self.exact_reals
                    .get(&(e.span.start, e.span.end, e.span.context))
                    .cloned()
                    .or_else(|| exact::of_f64(*v))?,
            ),
            ExKind::IntNeg(a) => match self.static_value(a)? {
                Int(v) => Int(-v),
                _ => return None,
            },
            ExKind::IntAbs(a) => match self.static_value(a)? {
                Int(v) => Int(v.abs()),
                _ => return None,
            },
            ExKind::FloatAbs(a) => match self.static_value(a)? {
                Real(v) => Real(num_traits::Signed::abs(&v)),
                _ => return None,
            },
            ExKind::FloatNeg(a) => match self.static_value(a)? {
                Real(v) => Real(-v),
                _ => return None,
            },
            ExKind::IntBin(op, a, b) => {
                let (Int(x), Int(y)) = (self.static_value(a)?, self.static_value(b)?) else {
                    return None;
                };
                Int(match op {
                    IntOp::Add => x.checked_add(y)?,
                    IntOp::Sub => x.checked_sub(y)?,
                    IntOp::Mul => x.checked_mul(y)?,
                    IntOp::Div => x.checked_div(y)?,
                    IntOp::Rem => x.checked_rem(y)?,
                    IntOp::Mod => {
                        if y == 0 {
                            return None;
                        }
                        x.rem_euclid(y) + if y < 0 && x.rem_euclid(y) != 0 { y } else { 0 }
                    }
                    IntOp::Pow => x.checked_pow(u32::try_from(y).ok()?)?,
                })
            }
            ExKind::FloatBin(op, a, b) => {
                let real = |s: Static| match s {
                    Real(v) => v,
                    Int(v) => exact::of_int(v),
                };
                let x = real(self.static_value(a)?);
                if *op == FloatOp::PowI {
                    let Int(n) = self.static_value(b)? else {
                        return None;
                    };
                    return exact::pow(&x, n).map(Real);
                }
                let y = real(self.static_value(b)?);
                Real(match op {
                    FloatOp::Add => x + y,
                    FloatOp::Sub => x - y,
                    FloatOp::Mul => x * y,
                    FloatOp::Div if num_traits::Zero::is_zero(&y) => return None,
                    FloatOp::Div => x / y,
                    FloatOp::PowI | FloatOp::DurDiv => return None,
                })
            }
            ExKind::IntToFloat(a) => match self.static_value(a)? {
                Int(v) => Real(exact::of_int(v)),
                r => r,
            },
            ExKind::RangeCheck(a, _) => self.static_value(a)?,
            ExKind::TypeFirst(t) => Int(self.types.discrete_bounds(*t)?.0),
            ExKind::TypeLast(t) => Int(self.types.discrete_bounds(*t)?.1),
            ExKind::Attr(AttrOp::Pos, a) => self.static_value(a.first()?)?,
            // `T'Val (N)`, `T'Succ (X)`, `T'Pred (X)` of static arguments are
            // static when the result is a value of T.
            ExKind::Attr(op @ (AttrOp::Val | AttrOp::Succ | AttrOp::Pred), a) => {
                let Int(v) = self.static_value(a.first()?)? else {
                    return None;
                };
                let v = match op {
                    AttrOp::Succ => v + 1,
                    AttrOp::Pred => v - 1,
                    _ => v,
                };
                let (l, h) = self.types.discrete_bounds(self.types.base(e.ty))?;
                if v < l || v > h {
                    return None;
                }
                Int(v)
            }
            ExKind::Attr(op @ (AttrOp::Min | AttrOp::Max), a) if a.len() == 2 => {
                let (Int(x), Int(y)) = (self.static_value(&a[0])?, self.static_value(&a[1])?)
                else {
                    return None;
                };
                Int(if *op == AttrOp::Min {
                    x.min(y)
                } else {
                    x.max(y)
                })
            }
            _ => return None,
        })
    }
}
