//! Declarations: the walk of a declarative part, objects, numbers,
//! exceptions, renamings, and static values. Type and subtype declarations
//! are in `types.rs`, subprograms and packages in `subprograms.rs`.

use super::tasks::BodyKind;
use super::*;
use crate::syntax::ast::{DeclKind, TypeDef};

mod private;
mod renaming;
mod subprograms;
mod types;

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
        let before = self.tables.funcs.len();
        self.decls(decls, out);
        for d in decls {
            let DeclKind::SubprogramDecl { spec, import: None } = &d.kind else {
                continue;
            };
            let declared = self
                .tables
                .funcs
                .iter()
                .skip(before)
                .position(|f| f.span == spec.span)
                .map(|i| before + i);
            if let Some(f) = declared
                && self.tables.funcs[f].body.is_none()
                && self.tables.imports[f].is_none()
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
                Some(Entity::Package(i)) => {
                    self.tables.packages[*i].names.values().flatten().any(|e| {
                        matches!(e, Entity::Func(f)
                            if self.tables.funcs[*f as usize].body.is_none()
                                && self.tables.imports[*f as usize].is_none())
                    })
                }
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
                    let t = self.type_def(tn, &[], def, d.span);
                    self.declare(&tn.name, Entity::Type(t));
                }
                let t = self.elaborating(out, |c| c.subtype_ind(ty));
                // Deferred constants: declared in a package's visible part,
                // completed in its private part.
                if *constant && anon.is_none() {
                    match init {
                        None if self.deferred_constant(names, t) => return,
                        Some(v) if self.complete_deferred(names, t, v, d.span, out) => return,
                        _ => {}
                    }
                }
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
            DeclKind::Type {
                name,
                discriminants,
                unknown_discriminants,
                def,
            } => {
                let private = matches!(def, TypeDef::Private { .. });
                if let Some(box_span) = *unknown_discriminants
                    && !private
                {
                    if matches!(def, TypeDef::Incomplete) {
                        self.err(diagnostics::unsupported(
                            box_span,
                            "unknown discriminants on an incomplete type",
                        ));
                    } else {
                        self.err(diagnostics::unknown_discriminants_on_full_type(box_span));
                    }
                }
                // Completing an incomplete type keeps its id.
                let prev = self
                    .scopes
                    .innermost()
                    .and_then(|s| s.names.get(&*name.key))
                    .and_then(|es| es.last().cloned());
                if let Some(old) = self
                    .completes_private(prev.as_ref())
                    .filter(|_| !matches!(def, TypeDef::Private { .. } | TypeDef::Incomplete))
                {
                    self.complete_private(old, name, discriminants, def, d.span, out);
                    return;
                }
                if let TypeDef::Private { limited } = def {
                    self.private_type(
                        name,
                        *limited,
                        discriminants,
                        unknown_discriminants.is_some(),
                        d.span,
                    );
                    return;
                }
                if let Some(Entity::Type(old)) = prev
                    && matches!(self.tables.types.kind(old), TypeKind::Incomplete)
                {
                    let t = self.elaborating(out, |c| c.type_def(name, discriminants, def, d.span));
                    let mut info = self.tables.types.get(t).clone();
                    info.base = old;
                    self.tables.types.list[old as usize] = info;
                    self.retarget_enum_lits(t, old);
                    // Access types declared before the completion that now
                    // designate tasks get their master here (same region).
                    let before: Vec<TypeId> = (0..self.tables.types.list.len() as TypeId)
                        .filter(|&a| {
                            matches!(self.tables.types.kind(a), TypeKind::Access(d) if self.tables.types.base(*d) == old)
                        })
                        .collect();
                    for a in before {
                        self.collection_master(a, d.span, out);
                    }
                    return;
                }
                if matches!(def, TypeDef::Incomplete) {
                    let t = self.tables.types.add(&name.name, TypeKind::Incomplete);
                    self.declare_checked(name, Entity::Type(t));
                    return;
                }
                // Its bounds (an array's, its components') are evaluated
                // once, here.
                let t = self.elaborating(out, |c| c.type_def(name, discriminants, def, d.span));
                self.declare_checked(name, Entity::Type(t));
                self.collection_master(t, d.span, out);
            }
            DeclKind::Subtype { name, ind } => {
                let of = self.elaborating(out, |c| c.subtype_ind(ind));
                let t = self.tables.types.add_subtype(&name.name, of);
                self.declare_checked(name, Entity::Type(t));
            }
            DeclKind::Exception { names } => {
                for n in names {
                    let id = self.tables.excs.len() as ExcId;
                    self.tables.excs.push(Exception {
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
                    self.tables.imports[f as usize] = Some(name.clone());
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
            DeclKind::Renaming(r) => self.renaming(r, out),
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
        let Some(s) = self.scopes.innermost_mut() else {
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
        let unconstrained_array = self.tables.types.array(t).is_some_and(|a| a.2.is_none());
        let init_ex = init.map(|e| {
            let ex = self.expr(e, Some(t));
            self.coerce(ex, t)
        });
        if init_ex.is_none() && unconstrained_array {
            self.err(diagnostics::unconstrained_object(
                span,
                self.tables.types.name(t),
            ));
        }
        if init_ex.is_none() && self.tables.types.unknown_discriminants(t) {
            self.err(diagnostics::unknown_discriminants_unconstrained(
                span,
                &self.tname(t),
                "an object",
            ));
        } else if init_ex.is_none() && self.needs_discriminants(t) {
            self.err(diagnostics::discriminated_object_unconstrained(
                span,
                self.tables.types.name(t),
            ));
        }
        if constant && init_ex.is_none() {
            self.err(diagnostics::constant_without_value(span));
        }
        if !self.tables.types.completed(t) && self.tables.types.private_view(t).is_some() {
            let tn = self.tname(t);
            self.err(diagnostics::premature_private_object(span, &tn));
        }
        if let Some(e) = &init_ex {
            self.limited_init(e, t);
        }
        let static_v = if constant {
            init_ex
                .as_ref()
                .and_then(|e| self.static_value(e))
                .filter(|_| self.tables.types.is_scalar(t))
                .map(|v| self.machine_value(v, t))
        } else {
            None
        };
        let creates_task = self.tables.types.has_task(t);
        if creates_task && let Some(m) = self.tasking.masters.last_mut() {
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
                && !self.tables.types.is_unique(t)
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
        if creates_task && self.tasking.masters.is_empty() {
            self.tasking.library_tasks = true;
        }
    }

    /// RM 4.9(38): the value of a static real expression given to a
    /// constant of a real type is a value of that type (named numbers stay
    /// exact): the nearest double for a floating point type (adair's
    /// floating point types are all doubles), whole nanoseconds for Duration
    /// (truncated, as GNAT does; `coerce` made it so already).
    fn machine_value(&self, v: Static, t: TypeId) -> Static {
        match v {
            Static::Real(r) if self.tables.types.whole_ns(t) => {
                Static::Real(exact::to_whole_ns(&r))
            }
            Static::Real(r)
                if self.tables.types.is_float(t) && !self.tables.types.is_universal(t) =>
            {
                Static::Real(exact::to_machine(&r).unwrap_or(r))
            }
            v => v,
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
            ExKind::ModBin(op, a, b) => {
                let (Int(x), Int(y)) = (self.static_value(a)?, self.static_value(b)?) else {
                    return None;
                };
                let last = self.tables.types.modular_last(e.ty)?;
                Int(ir::modular(*op, i64::try_from(x).ok()?, i64::try_from(y).ok()?, last)?.into())
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
                    FloatOp::Add | FloatOp::DurAdd => x + y,
                    FloatOp::Sub | FloatOp::DurSub => x - y,
                    FloatOp::Mul | FloatOp::DurMul => x * y,
                    FloatOp::Div | FloatOp::DurQuo if num_traits::Zero::is_zero(&y) => return None,
                    FloatOp::Div | FloatOp::DurQuo => x / y,
                    FloatOp::PowI | FloatOp::DurDiv => return None,
                })
            }
            ExKind::IntToFloat(a) => match self.static_value(a)? {
                Int(v) => Real(exact::of_int(v)),
                r => r,
            },
            ExKind::RangeCheck(a, _) => self.static_value(a)?,
            ExKind::TypeFirst(t) => Int(self.tables.types.discrete_bounds(*t)?.0),
            ExKind::TypeLast(t) => Int(self.tables.types.discrete_bounds(*t)?.1),
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
                let (l, h) = self
                    .tables
                    .types
                    .discrete_bounds(self.tables.types.base(e.ty))?;
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
