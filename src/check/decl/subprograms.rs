//! Subprogram and package declarations and bodies: profiles, elaboration
//! checks, masters.

use super::*;

impl Checker {
    pub(in crate::check) fn params(&mut self, ps: &[ast::Param]) -> Vec<Param> {
        let mut out = Vec::new();
        // Two parameters (or discriminants) of one name: GNAT's "conflicts
        // with declaration", reported at the second.
        let mut seen = std::collections::HashSet::new();
        for id in ps.iter().flat_map(|p| &p.names) {
            if !seen.insert(id.key.to_string()) {
                self.err(diagnostics::declared_twice(id.span, &id.name));
            }
        }
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

    pub(in crate::check) fn same_profile(
        &self,
        a: &Subprogram,
        params: &[Param],
        ret: Option<TypeId>,
    ) -> bool {
        a.params.len() == params.len()
            && a.params.iter().zip(params).all(|(x, y)| {
                self.tables.types.base(x.ty) == self.tables.types.base(y.ty) && x.mode == y.mode
            })
            && a.ret.map(|t| self.tables.types.base(t)) == ret.map(|t| self.tables.types.base(t))
    }

    /// Declares a subprogram (or finds its earlier declaration) and returns its id.
    pub(super) fn subprogram_decl(
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
            .innermost()
            .and_then(|s| s.names.get(&key))
            .map(|es| super::expr::funcs_of(es))
            .unwrap_or_default();
        if let Some((p, true)) = self.scopes.innermost().and_then(|s| s.package)
            && let Some(es) = self.tables.packages[p].names.get(&key)
        {
            existing.extend(super::expr::funcs_of(es));
        }
        for f in existing {
            let sub = &self.tables.funcs[f as usize];
            if self.same_profile(sub, &params, ret) {
                if declare_only || sub.body.is_some() || self.tables.imports[f as usize].is_some() {
                    self.err(diagnostics::declared_with_same_profile(
                        spec.span,
                        &spec.name.display(),
                    ));
                }
                return Some(f);
            }
        }
        let id = self.tables.funcs.len() as FuncId;
        self.tables.funcs.push(Subprogram {
            name: spec.name.display(),
            params,
            ret,
            level: self.level + 1,
            nslots: 0,
            body: None,
            span: spec.span,
        });
        self.tables.imports.push(None);
        self.flag_formals(id);
        let tys: Vec<TypeId> = self.tables.funcs[id as usize]
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
    pub(super) fn elab_flag(&mut self, f: FuncId, body: bool, span: Span, out: &mut Vec<Stmt>) {
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
    pub(super) fn elab_check(&self, f: FuncId, span: Span) -> Option<Stmt> {
        let var = *self.elab_flags.get(&f)?;
        let flag = self.mk(ExKind::Var(var), BOOLEAN, span);
        let name = &self.tables.funcs[f as usize].name;
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

    pub(super) fn subprogram_body(&mut self, b: &ast::SubprogramBody) -> Option<FuncId> {
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
        let ret = self.tables.funcs[f as usize].ret;
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
    pub(in crate::check) fn check_body(
        &mut self,
        f: FuncId,
        key: &str,
        display: &str,
        written: &[&ast::Ident],
        decls: &[ast::Decl],
        body: &ast::Block,
        kind: BodyKind,
    ) -> bool {
        let ret = self.tables.funcs[f as usize].ret;
        let params = self.tables.funcs[f as usize].params.clone();
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
        self.scopes.push();
        self.scopes.name(key);
        self.unit_path.push(display.to_string());
        let mut written = written.iter();
        let mut last = None;
        let mut param_vars = Vec::with_capacity(params.len());
        for (i, p) in params.iter().enumerate() {
            let var = self.new_slot();
            param_vars.push(var);
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
        // The hidden flags of `out` and `in out` formals of a mutable
        // record type: the slots after the parameters. A body checked
        // before its flags were decided (an expression function of a
        // visible part) has none.
        self.pending_flags.retain(|&g| g != f);
        let mut flagged = Vec::new();
        if self.flagged_funcs.contains(&f) {
            for j in self.flagged_formals(f) {
                let flag = self.new_slot();
                self.constrained_flags.insert(param_vars[j], Some(flag));
                flagged.push(param_vars[j]);
            }
        } else {
            for (p, v) in params.iter().zip(&param_vars) {
                if self.needs_constrained_flag(p.mode, p.ty) {
                    self.constrained_flags.insert(*v, None);
                    flagged.push(*v);
                }
            }
        }
        let outer_function_obj = self.tasking.prot_function_obj;
        if let BodyKind::Protected(k) = kind {
            self.tasking.prot_ctx.push((k, last));
            self.declare_components(k, last);
            self.tasking.prot_function_obj = if self.tables.funcs[f as usize].ret.is_some() {
                last
            } else {
                None
            };
        }
        self.tasking.masters.push(false);
        let decl_span = self.tables.funcs[f as usize].span;
        let mut elab: Vec<Stmt> = self.elab_check(f, decl_span).into_iter().collect();
        self.decls_completed(decls, &mut elab);
        self.parts_here = kind == BodyKind::Subprogram && main;
        let inner = self.block(body);
        let creates = self.tasking.masters.pop().unwrap_or(false);
        let body_span = body.span;
        let elab = self.master_region(elab, inner, body_span, creates, kind == BodyKind::Task);
        if matches!(kind, BodyKind::Protected(_)) {
            self.tasking.prot_ctx.pop();
        }
        self.tasking.prot_function_obj = outer_function_obj;
        self.unit_path.pop();
        self.scopes.pop();
        for v in flagged {
            self.constrained_flags.remove(&v);
        }
        let ctx = self.ctx.pop().expect("ctx");
        self.report_unread();
        self.level -= 1;
        let sub = &mut self.tables.funcs[f as usize];
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
    /// reports its activation. The activation is the first statement of
    /// the handled sequence, so a `Tasking_Error` for a task that failed to
    /// activate is the region's own handlers' to catch (RM 9.2(5)).
    pub(in crate::check) fn master_region(
        &mut self,
        mut elab: Vec<Stmt>,
        mut inner: Body,
        span: Span,
        creates: bool,
        task_body: bool,
    ) -> Vec<Stmt> {
        if creates || task_body {
            inner.stmts.insert(
                0,
                Stmt {
                    kind: StmtKind::Activate,
                    span,
                },
            );
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

    pub(super) fn package_spec(&mut self, p: &ast::PackageSpec, out: &mut Vec<Stmt>) {
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
            let idx = self.tables.packages.len();
            self.tables.packages.push(Package {
                name: full.clone(),
                names: PMap::new(),
                private: PMap::new(),
                deferred: Vec::new(),
                private_types: Vec::new(),
                full_view_at: Vec::new(),
            });
            if let ast::ExprKind::Name(id) = &p.name.kind {
                self.declare_checked(id, Entity::Package(idx));
            }
            idx
        };
        self.scopes.push();
        self.scopes.set_package(idx, false);
        // Child units see their parents' declarations.
        if let Some((parent, _)) = full.rsplit_once('.')
            && let Some(pi) = self
                .tables
                .packages
                .iter()
                .position(|x| x.name.eq_ignore_ascii_case(parent))
        {
            self.scopes.innermost_mut().expect("scope").uses.push(pi);
            self.scopes.mark_uses(self.scopes.depth() - 1);
        }
        self.unit_path.extend(name.split('.').map(str::to_string));
        self.decls(&p.decls, out);
        self.scopes.set_package(idx, true);
        self.decls(&p.private, out);
        self.end_of_package_spec(idx);
        self.tables.packages[idx].full_view_at.push(p.span);
        for _ in name.split('.') {
            self.unit_path.pop();
        }
        self.scopes.pop();
    }

    pub(super) fn package_body(&mut self, p: &ast::PackageBody, out: &mut Vec<Stmt>) {
        let name = crate::syntax::parser::expr_text(&p.name);
        let idx = match self.denote(&p.name, false).first() {
            Some(Entity::Package(i)) => *i,
            _ => {
                self.err(diagnostics::package_body_without_spec(p.name.span, &name));
                return;
            }
        };
        self.scopes.push();
        self.scopes.set_package(idx, true);
        self.full_views(idx, true);
        self.tables.packages[idx].full_view_at.push(p.span);
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
        self.scopes.pop();
        self.full_views(idx, false);
        // Every subprogram declared in the spec needs a body.
        let missing: Vec<String> = self.tables.packages[idx]
            .names
            .values()
            .flatten()
            .filter_map(|e| match e {
                Entity::Func(f)
                    if self.tables.funcs[*f as usize].body.is_none()
                        && self.tables.imports[*f as usize].is_none() =>
                {
                    Some(self.tables.funcs[*f as usize].name.clone())
                }
                _ => None,
            })
            .collect();
        for m in missing {
            self.err(diagnostics::package_body_lacks(p.span, &name, &m));
        }
    }
}
