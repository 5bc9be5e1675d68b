//! Renaming declarations (RM 8.5), lowered here so that the engines never
//! see one:
//! - an object renaming is an [`Entity::Alias`] of the renamed object's
//!   name, with the parts of that name that can change (index values,
//!   access values, a function's result) evaluated once, at the renaming's
//!   elaboration, into hidden constants (RM 8.5.1(6));
//! - a subprogram renaming is a subprogram of its own (its parameter names
//!   and defaults are the renaming's), and a call of it is a call of the
//!   renamed subprogram (`Tables::renames`); a renaming of what has no
//!   subprogram of its own (a predefined operator, an attribute, an
//!   enumeration literal, an entry or a protected operation) gets the body
//!   that calls it, as a renaming-as-body does (RM 8.5.4(7.1));
//! - an exception or package renaming is another name for the same
//!   exception or package.

use super::*;
use crate::check::index::DefKind;
use crate::syntax::ast::{ExprKind as K, Renamed};

/// What a subprogram renaming renames.
enum Target {
    /// A subprogram with an id of its own.
    Func(FuncId),
    /// Something a body written here calls (an operator: its symbol).
    Call(Option<String>),
    /// Not a subprogram (reported).
    Error,
}

impl Checker {
    pub(super) fn renaming(&mut self, r: &ast::Renaming, out: &mut Vec<Stmt>) {
        match &r.what {
            Renamed::Object { name, ty } => self.object_renaming(name, ty, &r.renamed, out),
            Renamed::Exception(name) => {
                let es = self.renamed_entity(&r.renamed);
                match es.first() {
                    Some(e @ Entity::Exc(_)) => {
                        let e = e.clone();
                        self.declare_renaming(name, e, &r.renamed);
                    }
                    Some(_) => {
                        let text = crate::syntax::parser::expr_text(&r.renamed);
                        self.err(diagnostics::not_an_exception(r.renamed.span, &text));
                    }
                    None => {}
                }
            }
            Renamed::Package(name) => {
                let es = self.renamed_entity(&r.renamed);
                match es.first() {
                    Some(e @ Entity::Package(_)) => {
                        let e = e.clone();
                        self.declare_renaming(name, e, &r.renamed);
                    }
                    Some(_) => {
                        let text = crate::syntax::parser::expr_text(&r.renamed);
                        self.err(diagnostics::not_a_package(r.renamed.span, &text));
                    }
                    None => {}
                }
            }
            Renamed::Subprogram(spec) => self.subprogram_renaming(spec, &r.renamed, out),
        }
    }

    /// What the name after `renames` denotes (reported when nothing).
    fn renamed_entity(&mut self, renamed: &ast::Expr) -> Vec<Entity> {
        match &renamed.kind {
            K::Name(_) | K::Select(..) => self.denote(renamed, true),
            K::Error => Vec::new(),
            _ => vec![Entity::Number(Static::Int(0))],
        }
    }

    /// Declares `name` as another name of the entity `e` (an exception, a
    /// package), told apart from the renamed one in the index.
    fn declare_renaming(&mut self, name: &ast::Ident, e: Entity, renamed: &ast::Expr) {
        self.index_renaming(&name.name, name.span, &e, None, renamed.span);
        self.declare_checked_unindexed(name, e);
    }

    // ---- objects ----

    fn object_renaming(
        &mut self,
        name: &ast::Ident,
        mark: &ast::Expr,
        renamed: &ast::Expr,
        out: &mut Vec<Stmt>,
    ) {
        let t = self.type_mark(mark);
        let view = self
            .renamed_object(renamed, t, out)
            .unwrap_or_else(|| self.err_ex(renamed.span));
        let kind = if self.constant_view(&view) {
            DefKind::Constant
        } else {
            DefKind::Variable
        };
        let e = Entity::Alias(Box::new(view));
        self.index_renaming(&name.name, name.span, &e, Some(kind), renamed.span);
        self.declare_checked_unindexed(name, e);
    }

    /// The renamed object, as a name whose changing parts have been
    /// evaluated into hidden constants (the statements that do it and the
    /// checks of the name go to `out`); `None` after an error.
    fn renamed_object(
        &mut self,
        renamed: &ast::Expr,
        t: TypeId,
        out: &mut Vec<Stmt>,
    ) -> Option<Ex> {
        let what = match &renamed.kind {
            K::Int(_) | K::Real(_) | K::Char(_) | K::Str(_) | K::Null => Some("a literal"),
            K::Binary(..) | K::Unary(..) | K::Membership { .. } => Some("an expression"),
            K::If { .. } | K::Case { .. } => Some("a conditional expression"),
            K::Paren(_) => Some("an expression in parentheses"),
            K::Aggregate(_) => Some("an aggregate"),
            K::Allocator(..) => Some("an allocator"),
            K::Attr(_, _, args) if args.is_empty() => Some("the value of an attribute"),
            K::Apply(p, _) if matches!(self.denote(p, false).first(), Some(Entity::Type(_))) => {
                Some("a type conversion")
            }
            K::Name(_) | K::Select(..) => match self.denote(renamed, false).first() {
                Some(Entity::Number(_)) => Some("a named number"),
                _ => None,
            },
            _ => None,
        };
        if let Some(what) = what {
            let text = self.snippet(renamed.span);
            self.err(diagnostics::renames_a_value(renamed.span, &text, what));
            return None;
        }
        let ex = self.expr(renamed, Some(t));
        if ex.ty == ERROR || t == ERROR {
            return None;
        }
        if self.tables.types.is_universal(ex.ty) {
            let text = self.snippet(renamed.span);
            self.err(diagnostics::renames_a_value(
                renamed.span,
                &text,
                "a number",
            ));
            return None;
        }
        if !self.tables.types.compatible(ex.ty, t) {
            // For its diagnostic (expected T, found ...).
            let _ = self.coerce(ex, t);
            return None;
        }
        let mut checked = false;
        let frozen = self.freeze(ex, &mut checked, out);
        // The name's checks (index, access, qualification) are made now,
        // once (a probe reads one scalar of the object and copies nothing).
        if checked && let Some(probe) = self.probe(frozen.clone()) {
            let var = self.new_slot();
            let span = probe.span;
            out.push(Stmt {
                kind: StmtKind::Init(var, probe),
                span,
            });
        }
        Some(strip_checks(frozen))
    }

    /// `e` with each part that can change evaluated into a hidden constant;
    /// `checked` is set when the name has checks of its own.
    fn freeze(&mut self, e: Ex, checked: &mut bool, out: &mut Vec<Stmt>) -> Ex {
        let Ex { kind, ty, span } = e;
        let kind = match kind {
            ExKind::Var(_)
            | ExKind::Register(_)
            | ExKind::Int(_)
            | ExKind::Real(_)
            | ExKind::Str(_)
            | ExKind::Null
            | ExKind::Error => kind,
            ExKind::Field(p, i) => ExKind::Field(Box::new(self.freeze(*p, checked, out)), i),
            ExKind::Index(p, ixs) => {
                *checked = true;
                let p = self.freeze(*p, checked, out);
                let ixs = ixs.into_iter().map(|x| self.hold(x, out)).collect();
                ExKind::Index(Box::new(p), Box::new(ixs))
            }
            ExKind::Slice(p, lh) => {
                *checked = true;
                let p = self.freeze(*p, checked, out);
                let [l, h] = *lh;
                let lh = [self.hold(l, out), self.hold(h, out)];
                ExKind::Slice(Box::new(p), Box::new(lh))
            }
            ExKind::Deref(p) => {
                *checked = true;
                ExKind::Deref(Box::new(self.hold(*p, out)))
            }
            // A qualified name (`T'(X)`) is a view of X, checked once.
            ExKind::RangeCheck(p, r) => {
                *checked = true;
                ExKind::RangeCheck(Box::new(self.freeze(*p, checked, out)), r)
            }
            kind => return self.hold(Ex { kind, ty, span }, out),
        };
        Ex { kind, ty, span }
    }

    /// The value of `e` as of now: `e` itself when it cannot change,
    /// else a hidden constant initialised with it.
    fn hold(&mut self, e: Ex, out: &mut Vec<Stmt>) -> Ex {
        match &e.kind {
            ExKind::Int(_)
            | ExKind::Real(_)
            | ExKind::Str(_)
            | ExKind::Null
            | ExKind::Error
            | ExKind::TypeFirst(_)
            | ExKind::TypeLast(_) => return e,
            ExKind::Var(v) if self.scopes.var(*v).is_some_and(|(_, constant)| constant) => {
                return e;
            }
            _ => {}
        }
        let (ty, span) = (e.ty, e.span);
        let var = self.new_slot();
        self.scopes.declare_hidden(var, ty);
        out.push(Stmt {
            kind: StmtKind::Init(var, e),
            span,
        });
        self.mk(ExKind::Var(var), ty, span)
    }

    /// A scalar read out of the object `x` whose evaluation makes the
    /// checks of `x`'s name: `x` itself, its length, or its first
    /// component's probe. `None` for a task or protected object.
    fn probe(&self, x: Ex) -> Option<Ex> {
        let t = x.ty;
        let types = &self.tables.types;
        if types.is_scalar(t) || types.is_access(t) {
            return Some(x);
        }
        if types.is_unique(t) {
            return None;
        }
        if types.array(t).is_some() {
            let span = x.span;
            return Some(self.mk(
                ExKind::Attr(AttrOp::ArrLength(1), Box::new(vec![x])),
                INTEGER,
                span,
            ));
        }
        let first = types.fields(t)?.first()?.ty;
        let span = x.span;
        self.probe(self.mk(ExKind::Field(Box::new(x), 0), first, span))
    }

    /// Whether a renamed object is a constant (its name's root is a
    /// constant, an `in` parameter, or a value held here).
    fn constant_view(&self, x: &Ex) -> bool {
        match &x.kind {
            ExKind::Var(v) => self.scopes.var(*v).is_some_and(|(_, c)| c),
            ExKind::Index(p, _) | ExKind::Slice(p, _) | ExKind::Field(p, _) => {
                self.constant_view(p)
            }
            ExKind::Deref(_) | ExKind::Register(_) | ExKind::Error => false,
            _ => true,
        }
    }

    // ---- subprograms ----

    fn subprogram_renaming(
        &mut self,
        spec: &ast::SubprogramSpec,
        renamed: &ast::Expr,
        out: &mut Vec<Stmt>,
    ) {
        let params = self.params(&spec.params);
        let ret = spec.ret.as_ref().map(|r| self.type_mark(r));
        let key = spec.name.key();
        let name = spec.name.display();
        if let ast::Designator::Op(op, sp) = &spec.name
            && !OPERATORS.contains(&op.to_ascii_lowercase().as_str())
        {
            self.err(diagnostics::not_an_operator_symbol(*sp, op));
        }
        // The renamed subprogram is found before the renaming is declared:
        // the renaming's own name does not denote it yet (RM 8.3(16)).
        let target = self.renamed_subprogram(&name, &params, ret, renamed);
        let completes = self.declared_before(spec, &params, ret);
        let f = match completes {
            Some(f) => {
                self.conform_as_body(f, spec);
                f
            }
            None => {
                let f = self.tables.funcs.len() as FuncId;
                let mut sub = Subprogram {
                    name: name.clone(),
                    params,
                    ret,
                    level: self.level + 1,
                    nslots: 0,
                    body: None,
                    span: spec.span,
                };
                // The renamed subprogram's subtypes apply (RM 8.5.4(7)):
                // the renaming's parameter names and defaults are its own.
                if let Target::Func(g) = target {
                    let g = &self.tables.funcs[g as usize];
                    for (p, q) in sub.params.iter_mut().zip(&g.params) {
                        p.ty = q.ty;
                    }
                    sub.ret = g.ret;
                }
                self.tables.funcs.push(sub);
                self.tables.imports.push(None);
                let tys: Vec<TypeId> = self.tables.funcs[f as usize]
                    .params
                    .iter()
                    .map(|p| p.ty)
                    .collect();
                let written = spec.params.iter().flat_map(|p| &p.names);
                for (i, (pid, ty)) in written.zip(tys).enumerate() {
                    self.index_param(f, i as u32, pid, ty);
                }
                f
            }
        };
        match target {
            Target::Func(g) if g == f => self.err(diagnostics::renames_itself(renamed.span, &name)),
            Target::Func(g) => {
                let root = self.tables.callee(g);
                if completes.is_none() {
                    self.tables.renames.insert(f, root);
                    self.tables.imports[f as usize] = self.tables.imports[root as usize].clone();
                }
                self.call_body(f, root, spec.span, renamed.span);
            }
            Target::Call(op) => self.written_body(f, spec, renamed, op.as_deref()),
            // An empty body: the program does not run, and no second error
            // says the renaming has none.
            Target::Error => {
                self.tables.funcs[f as usize].body = Some(Rc::new(Body {
                    stmts: Vec::new(),
                    handlers: Vec::new(),
                }));
            }
        }
        if completes.is_some() {
            self.elab_flag(f, true, spec.span, out);
            return;
        }
        let e = Entity::Func(f);
        match &spec.name {
            ast::Designator::Ident(i) => {
                self.index_def(&i.name, i.span, &e, None);
                if let Some(d) = self.index.defs.last_mut() {
                    d.renames = Some(renamed.span);
                }
                self.declare_checked_unindexed(i, e);
            }
            ast::Designator::Op(_, _) => self.declare(&key, e),
        }
    }

    /// The subprogram declared earlier in this declarative region with
    /// this profile, which the renaming completes (a renaming-as-body);
    /// an error when it has a body already.
    fn declared_before(
        &mut self,
        spec: &ast::SubprogramSpec,
        params: &[Param],
        ret: Option<TypeId>,
    ) -> Option<FuncId> {
        let key = spec.name.key();
        let mut existing: Vec<FuncId> = self
            .scopes
            .innermost()
            .and_then(|s| s.names.get(&key))
            .map(|es| super::expr::funcs_of(es))
            .unwrap_or_default();
        if let Some((p, true)) = self.scopes.innermost().and_then(|s| s.package)
            && let Some(es) = self.tables.packages[p].names.get(&key)
        {
            existing.extend(super::expr::funcs_of(es));
        }
        let f = existing
            .into_iter()
            .find(|f| self.same_profile(&self.tables.funcs[*f as usize], params, ret))?;
        if self.tables.funcs[f as usize].body.is_some() || self.tables.imports[f as usize].is_some()
        {
            self.err(diagnostics::declared_with_same_profile(
                spec.span,
                &spec.name.display(),
            ));
            return None;
        }
        Some(f)
    }

    /// A renaming-as-body repeats the parameter names of the declaration
    /// it completes (full conformance, RM 8.5.4(5)).
    fn conform_as_body(&mut self, f: FuncId, spec: &ast::SubprogramSpec) {
        let declared: Vec<String> = self.tables.funcs[f as usize]
            .params
            .iter()
            .map(|p| p.name.clone())
            .collect();
        let written = spec.params.iter().flat_map(|p| &p.names);
        for (id, d) in written.zip(&declared) {
            if !id.name.eq_ignore_ascii_case(d) {
                self.err(diagnostics::renaming_as_body_names(id.span, &id.name, d));
            }
        }
    }

    /// What the name after `renames` denotes, among subprograms of the
    /// renaming's profile (types conform; modes are checked here too).
    fn renamed_subprogram(
        &mut self,
        name: &str,
        params: &[Param],
        ret: Option<TypeId>,
        renamed: &ast::Expr,
    ) -> Target {
        let before = self.diags.len();
        let (es, op) = match &renamed.kind {
            K::Str(s) => (
                self.lookup(&format!("\"{}\"", s.to_ascii_lowercase())),
                Some(s.clone()),
            ),
            K::Name(_) => (self.denote(renamed, true), None),
            K::Select(p, id) => {
                let op = id
                    .name
                    .strip_prefix('"')
                    .and_then(|x| x.strip_suffix('"'))
                    .map(str::to_string);
                // `P."+"` of a predefined operator: no subprogram in P.
                let report = op.is_none()
                    || !matches!(self.denote(p, false).first(), Some(Entity::Package(_)))
                    || !self.denote(renamed, false).is_empty();
                (self.denote(renamed, report), op)
            }
            // `T'Image` and other attributes that are functions.
            K::Attr(p, _, args) if args.is_empty() => {
                let es = self.denote(p, true);
                return match es.first() {
                    Some(Entity::Type(_)) => Target::Call(None),
                    Some(_) => {
                        let text = crate::syntax::parser::expr_text(renamed);
                        self.err(diagnostics::not_a_subprogram(renamed.span, &text));
                        Target::Error
                    }
                    None => Target::Error,
                };
            }
            // A member of an entry family (`Station.Load (3)`): called by a
            // body, whose call evaluates the index each time, as GNAT does.
            K::Apply(p, args)
                if matches!(p.kind, K::Select(..))
                    && matches!(&args[..], [a] if a.name.is_none())
                    && self.denote(p, false).is_empty() =>
            {
                return Target::Call(None);
            }
            K::Error => return Target::Error,
            _ => {
                let text = self.snippet(renamed.span);
                self.err(diagnostics::not_a_subprogram(renamed.span, &text));
                return Target::Error;
            }
        };
        if self.diags.len() > before {
            return Target::Error;
        }
        let text = renamed_text(renamed);
        if es.is_empty() {
            // An operator with no subprogram is a predefined one; an entry
            // or a protected operation (`Buffer.Put`) is called by a body.
            return Target::Call(op);
        }
        let fs = super::expr::funcs_of(&es);
        if fs.is_empty() {
            if es.iter().all(|e| matches!(e, Entity::EnumLit(..))) {
                return Target::Call(None);
            }
            self.err(diagnostics::not_a_subprogram(renamed.span, &text));
            return Target::Error;
        }
        let types = &self.tables.types;
        let conformant = fs.iter().copied().find(|g| {
            let s = &self.tables.funcs[*g as usize];
            s.params.len() == params.len()
                && s.params
                    .iter()
                    .zip(params)
                    .all(|(x, y)| types.base(x.ty) == types.base(y.ty))
                && s.ret.map(|t| types.base(t)) == ret.map(|t| types.base(t))
        });
        let Some(g) = conformant else {
            if op.is_some() {
                return Target::Call(op);
            }
            let sigs: Vec<String> = fs.iter().map(|f| self.signature(*f)).collect();
            self.err(diagnostics::renaming_profile_mismatch(
                renamed.span,
                name,
                &text,
                &sigs,
            ));
            return Target::Error;
        };
        if let Some(id) = super::stmt::last_ident(renamed) {
            self.index_ref(id.span, &id.key, &Entity::Func(g));
        }
        let theirs = self.tables.funcs[g as usize].params.clone();
        for (mine, their) in params.iter().zip(&theirs) {
            if mine.mode != their.mode {
                let sig = self.signature(g);
                self.err(diagnostics::renaming_mode_mismatch(
                    renamed.span,
                    &mine.name,
                    mode_word(mine.mode),
                    mode_word(their.mode),
                    &sig,
                ));
            }
        }
        // A protected operation is called with its object: by a body.
        if self.tables.prot_real.contains_key(&g) {
            return Target::Call(None);
        }
        Target::Func(g)
    }

    /// The body of `f` that calls `g` with `f`'s parameters (a
    /// renaming-as-body; for a renaming, what a call of it would do if it
    /// were not a call of `g` already).
    fn call_body(&mut self, f: FuncId, g: FuncId, decl: Span, span: Span) {
        let level = self.level + 1;
        let mine = self.tables.funcs[f as usize].params.clone();
        let theirs = self.tables.funcs[g as usize].params.clone();
        let mut args = Vec::new();
        for (i, (p, q)) in mine.iter().zip(&theirs).enumerate() {
            let v = self.mk(
                ExKind::Var(Var {
                    level,
                    slot: i as u32,
                }),
                p.ty,
                span,
            );
            let types = &self.tables.types;
            let back_check = (p.mode != ast::Mode::In
                && types.is_scalar(p.ty)
                && p.ty != q.ty
                && types.get(p.ty).range.is_some()
                && p.ty != INTEGER)
                .then_some(p.ty);
            let value = if p.mode == ast::Mode::In {
                self.coerce(v, q.ty)
            } else {
                v
            };
            args.push(Arg {
                mode: p.mode,
                value,
                back_check,
            });
        }
        // The hidden flags of `g`'s mutable formals: `f`'s own (the same
        // formals) when it has them, else True.
        let mine_flagged = self.flagged_formals(f);
        let theirs_flagged = self.flagged_formals(g);
        let nflags = if mine_flagged == theirs_flagged {
            mine_flagged.len()
        } else {
            0
        };
        for (k, _) in theirs_flagged.iter().enumerate() {
            let value = if k < nflags {
                self.mk(
                    ExKind::Var(Var {
                        level,
                        slot: (mine.len() + k) as u32,
                    }),
                    BOOLEAN,
                    span,
                )
            } else {
                self.mk(ExKind::Int(1), BOOLEAN, span)
            };
            args.push(Arg {
                mode: ast::Mode::In,
                value,
                back_check: None,
            });
        }
        let call = match self.tables.funcs[g as usize].ret {
            Some(r) => {
                let ret = self.tables.funcs[f as usize].ret.unwrap_or(r);
                let value = self.mk(ExKind::Call(g, args.into()), r, span);
                StmtKind::Return(Some(self.coerce(value, ret)))
            }
            None => StmtKind::Call(g, args.into()),
        };
        let mut stmts: Vec<Stmt> = self.elab_check(f, decl).into_iter().collect();
        stmts.push(Stmt { kind: call, span });
        let nslots = (mine.len() + mine_flagged.len()) as u32;
        let sub = &mut self.tables.funcs[f as usize];
        sub.nslots = nslots;
        sub.body = Some(Rc::new(Body {
            stmts,
            handlers: Vec::new(),
        }));
    }

    /// The body of `f` that calls what `renamed` names (an operator
    /// `op`, an attribute, an enumeration literal, an entry), checked as
    /// if written there: `return L + R;`, `Buffer.Put (X);`. When it does
    /// not check, the renaming's profile is what does not fit.
    fn written_body(
        &mut self,
        f: FuncId,
        spec: &ast::SubprogramSpec,
        renamed: &ast::Expr,
        op: Option<&str>,
    ) {
        let span = renamed.span;
        let written: Vec<&ast::Ident> = spec.params.iter().flat_map(|p| &p.names).collect();
        let arg = |i: &ast::Ident| ast::Expr {
            kind: K::Name(i.clone()),
            span: i.span,
        };
        let call = match (op, &written[..]) {
            (Some(op), [l, r]) => binary_op(op).map(|o| K::Binary(o, bx(arg(l)), bx(arg(r)))),
            (Some(op), [x]) => unary_op(op).map(|o| K::Unary(o, bx(arg(x)))),
            (Some(_), _) => None,
            (None, []) => Some(renamed.kind.clone()),
            (None, args) => Some(match &renamed.kind {
                K::Attr(p, a, _) => {
                    K::Attr(p.clone(), a.clone(), args.iter().map(|i| arg(i)).collect())
                }
                _ => K::Apply(
                    bx(renamed.clone()),
                    args.iter()
                        .map(|i| ast::Arg {
                            name: None,
                            value: arg(i),
                            span: i.span,
                        })
                        .collect(),
                ),
            }),
        };
        let name = spec.name.display();
        let text = match renamed.kind {
            K::Apply(..) => self.snippet(span),
            _ => renamed_text(renamed),
        };
        let Some(call) = call else {
            self.err(diagnostics::renaming_profile_mismatch(
                span,
                &name,
                &text,
                &[] as &[&str],
            ));
            return;
        };
        let call = ast::Expr { kind: call, span };
        let stmt = ast::Stmt {
            kind: if spec.ret.is_some() {
                ast::StmtKind::Return(Some(bx(call)))
            } else {
                ast::StmtKind::Call(bx(call))
            },
            span,
        };
        let block = ast::Block {
            stmts: vec![stmt].into(),
            handlers: Vec::new(),
            span,
            lazy: None,
        };
        let before = self.diags.len();
        self.check_body(
            f,
            &spec.name.key(),
            &name,
            &written,
            &[],
            &block,
            BodyKind::Subprogram,
        );
        if self.diags[before..].iter().any(|d| !d.is_warning()) {
            self.diags.truncate(before);
            self.err(diagnostics::renaming_profile_mismatch(
                span,
                &name,
                &text,
                &[] as &[&str],
            ));
        }
    }
}

/// The operator symbols a function may be named by.
pub(super) const OPERATORS: &[&str] = &[
    "+", "-", "*", "/", "**", "=", "<", "<=", ">", ">=", "&", "abs", "not", "and", "or", "xor",
    "mod", "rem",
];

fn mode_word(m: ast::Mode) -> &'static str {
    match m {
        ast::Mode::In => "in",
        ast::Mode::Out => "out",
        ast::Mode::InOut => "in out",
    }
}

/// The renamed name as written (an operator symbol in quotes).
fn renamed_text(e: &ast::Expr) -> String {
    match &e.kind {
        K::Str(s) => format!("\"{s}\""),
        _ => crate::syntax::parser::expr_text(e),
    }
}

fn bx(e: ast::Expr) -> Box<ast::Expr> {
    Box::new(e)
}

fn binary_op(op: &str) -> Option<ast::BinOp> {
    use ast::BinOp::*;
    Some(match op.to_ascii_lowercase().as_str() {
        "and" => And,
        "or" => Or,
        "xor" => Xor,
        "=" => Eq,
        "/=" => Ne,
        "<" => Lt,
        "<=" => Le,
        ">" => Gt,
        ">=" => Ge,
        "+" => Add,
        "-" => Sub,
        "&" => Cat,
        "*" => Mul,
        "/" => Div,
        "mod" => Mod,
        "rem" => Rem,
        "**" => Pow,
        _ => return None,
    })
}

fn unary_op(op: &str) -> Option<ast::UnOp> {
    use ast::UnOp::*;
    Some(match op.to_ascii_lowercase().as_str() {
        "-" => Neg,
        "+" => Plus,
        "not" => Not,
        "abs" => Abs,
        _ => return None,
    })
}

/// The object a renaming denotes: its frozen name without the checks of
/// its qualification (made once, at the renaming).
fn strip_checks(e: Ex) -> Ex {
    match e.kind {
        ExKind::RangeCheck(p, _) => strip_checks(*p),
        _ => e,
    }
}
