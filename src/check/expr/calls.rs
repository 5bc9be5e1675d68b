//! Calls: overload resolution among subprograms, matching arguments to a
//! profile, and the warnings a call draws.

use super::*;

impl Checker {
    pub(super) fn user_op_types(&mut self, sym: &str, args: &[&ast::Expr]) -> Vec<TypeId> {
        let cands = self.op_funcs(sym, args.len());
        let mut out = Vec::new();
        for f in cands {
            let ps: Vec<TypeId> = self.tables.funcs[f as usize]
                .params
                .iter()
                .map(|p| p.ty)
                .collect();
            if args.iter().zip(&ps).all(|(a, t)| self.fits(a, *t))
                && let Some(r) = self.tables.funcs[f as usize].ret
            {
                out.push(r);
            }
        }
        out
    }

    pub(super) fn op_funcs(&self, sym: &str, arity: usize) -> Vec<FuncId> {
        self.lookup(&format!("\"{sym}\""))
            .into_iter()
            .filter_map(|e| {
                if let Entity::Func(f) = e {
                    Some(f)
                } else {
                    None
                }
            })
            .filter(|f| self.tables.funcs[*f as usize].params.len() == arity)
            .collect()
    }

    /// Maps actual arguments to the formals of `f`: one entry per formal,
    /// `None` where the default applies. `Err` says why they do not match.
    fn match_args<'a>(
        &self,
        f: FuncId,
        args: &'a [ast::Arg],
    ) -> Result<Vec<Option<&'a ast::Arg>>, diagnostics::ArgsMismatch> {
        use diagnostics::ArgsMismatch as Why;
        let sub = &self.tables.funcs[f as usize];
        let mut slots: Vec<Option<&ast::Arg>> = vec![None; sub.params.len()];
        let mut named = false;
        for (i, a) in args.iter().enumerate() {
            match &a.name {
                None => {
                    if named {
                        return Err(Why::PositionalAfterNamed);
                    }
                    if i >= slots.len() {
                        return Err(Why::TooMany(
                            sub.name.to_string(),
                            sub.params.len(),
                            args.len(),
                        ));
                    }
                    slots[i] = Some(a);
                }
                Some(n) => {
                    named = true;
                    match sub
                        .params
                        .iter()
                        .position(|p| p.name.eq_ignore_ascii_case(&n.name))
                    {
                        Some(j) if slots[j].is_some() => {
                            return Err(Why::GivenTwice(n.name.to_string()));
                        }
                        Some(j) => slots[j] = Some(a),
                        None => {
                            return Err(Why::NoSuchParameter(
                                sub.name.to_string(),
                                n.name.to_string(),
                                sub.params.iter().map(|p| p.name.to_string()).collect(),
                            ));
                        }
                    }
                }
            }
        }
        for (s, p) in slots.iter().zip(&sub.params) {
            if s.is_none() && p.default.is_none() {
                return Err(Why::Missing(p.name.to_string(), sub.name.to_string()));
            }
        }
        Ok(slots)
    }

    pub(super) fn args_fit(&mut self, f: FuncId, args: &[ast::Arg]) -> bool {
        let Ok(slots) = self.match_args(f, args) else {
            return false;
        };
        let tys: Vec<TypeId> = self.tables.funcs[f as usize]
            .params
            .iter()
            .map(|p| p.ty)
            .collect();
        slots
            .iter()
            .zip(tys)
            .all(|(s, t)| s.is_none_or(|a| self.fits(&a.value, t)))
    }

    /// Resolves a call among candidate subprograms and checks its arguments.
    pub(in crate::check) fn call(
        &mut self,
        cands: &[FuncId],
        args: &[ast::Arg],
        want: Option<TypeId>,
        procedure: bool,
        span: Span,
        name: &str,
    ) -> Option<(FuncId, Vec<Arg>)> {
        let kind_ok: Vec<FuncId> = cands
            .iter()
            .copied()
            .filter(|f| self.tables.funcs[*f as usize].ret.is_none() == procedure)
            .collect();
        if kind_ok.is_empty() {
            self.err(if procedure {
                diagnostics::function_result_unused(span, name)
            } else {
                diagnostics::procedure_has_no_value(span, name)
            });
            return None;
        }
        let mut fitting: Vec<FuncId> = kind_ok
            .iter()
            .copied()
            .filter(|f| self.args_fit(*f, args))
            .collect();
        if let Some(w) = want
            && fitting.len() > 1
        {
            let by_ret: Vec<FuncId> = fitting
                .iter()
                .copied()
                .filter(|f| {
                    self.tables.funcs[*f as usize]
                        .ret
                        .is_some_and(|r| self.tables.types.compatible(r, w))
                })
                .collect();
            if !by_ret.is_empty() {
                fitting = by_ret;
            }
        }
        // An inner declaration hides an outer one with the same profile.
        let mut distinct: Vec<FuncId> = Vec::new();
        for f in fitting {
            let same = distinct.iter().any(|g| {
                let (a, b) = (
                    &self.tables.funcs[f as usize],
                    &self.tables.funcs[*g as usize],
                );
                a.params.len() == b.params.len()
                    && a.params
                        .iter()
                        .zip(&b.params)
                        .all(|(x, y)| self.tables.types.base(x.ty) == self.tables.types.base(y.ty))
                    && a.ret.map(|t| self.tables.types.base(t))
                        == b.ret.map(|t| self.tables.types.base(t))
            });
            if !same {
                distinct.push(f);
            }
        }
        let fitting = distinct;
        // After an error in an argument, any candidate will do: no second error.
        let erroneous = args.iter().any(|a| {
            let i = self.interps(&a.value);
            i.is_empty() || i.contains(&ERROR)
        });
        if fitting.len() > 1 && !erroneous {
            let sigs: Vec<String> = fitting.iter().map(|f| self.signature(*f)).collect();
            self.err(diagnostics::ambiguous_call(span, name, &sigs));
            return None;
        }
        let f = match fitting.first() {
            Some(f) => *f,
            None if kind_ok.len() == 1 => kind_ok[0],
            None => {
                let sigs: Vec<String> = kind_ok.iter().map(|f| self.signature(*f)).collect();
                self.err(diagnostics::no_version_accepts(span, name, &sigs));
                for a in args {
                    self.expr(&a.value, None);
                }
                return None;
            }
        };
        let slots = match self.match_args(f, args) {
            Ok(s) => s,
            Err(msg) => {
                let sig = self.signature(f);
                self.err(diagnostics::arguments_rejected(span, &msg, &sig));
                return None;
            }
        };
        for a in args {
            if let Some(n) = &a.name {
                self.index_named_arg(f, n);
            }
        }
        self.warn_simulator_only(f, span);
        let params = self.tables.funcs[f as usize].params.clone();
        let mut out = Vec::new();
        for (slot, p) in slots.into_iter().zip(&params) {
            match slot {
                None => out.push(Arg {
                    mode: ast::Mode::In,
                    value: p.default.clone().unwrap_or_else(|| self.err_ex(span)),
                    back_check: None,
                }),
                Some(a) => {
                    self.warn_degrees(f, p.ty, &a.value);
                    let ex = self.expr(&a.value, Some(p.ty));
                    if p.mode == ast::Mode::In {
                        let ex = self.coerce(ex, p.ty);
                        out.push(Arg {
                            mode: p.mode,
                            value: ex,
                            back_check: None,
                        });
                    } else {
                        self.check_variable(
                            &ex,
                            a.value.span,
                            &format!(
                                "the `{}` parameter `{}`",
                                if p.mode == ast::Mode::Out {
                                    "out"
                                } else {
                                    "in out"
                                },
                                p.name
                            ),
                        );
                        let actual_ty = ex.ty;
                        if !self.tables.types.compatible(actual_ty, p.ty)
                            || self.tables.types.is_universal(actual_ty)
                        {
                            // Only for its diagnostic: the actual stays a variable.
                            let _ = self.coerce(ex.clone(), p.ty);
                        }
                        let back_check = (self.tables.types.is_scalar(actual_ty)
                            && actual_ty != p.ty
                            && self.tables.types.get(actual_ty).range.is_some()
                            && actual_ty != INTEGER)
                            .then_some(actual_ty);
                        out.push(Arg {
                            mode: p.mode,
                            value: ex,
                            back_check,
                        });
                    }
                }
            }
        }
        let (g, mut out) = self.internal_prot_call(f, out, span);
        let flags = self.constrained_flag_args(g, &out);
        out.extend(flags);
        Some((g, out))
    }

    pub fn signature(&self, f: FuncId) -> String {
        let s = &self.tables.funcs[f as usize];
        let ps: Vec<String> = s
            .params
            .iter()
            .map(|p| {
                let mode = mode_text(p.mode);
                format!(
                    "{} : {mode}{}{}",
                    p.name,
                    self.tables.types.name(p.ty),
                    if p.default.is_some() { " := ..." } else { "" }
                )
            })
            .collect();
        let params = if ps.is_empty() {
            String::new()
        } else {
            format!(" ({})", ps.join("; "))
        };
        match s.ret {
            Some(r) => format!(
                "function {}{params} return {}",
                s.name,
                self.tables.types.name(r)
            ),
            None => format!("procedure {}{params}", s.name),
        }
    }

    /// A call of a service that only the simulator has, when the program
    /// is meant for a real arm too (`simulator_only`): it would raise
    /// `CommandNotSupported` there, and in the rehearsal for it.
    fn warn_simulator_only(&mut self, f: FuncId, span: Span) {
        let Some(Some(import)) = self.tables.imports.get(f as usize) else {
            return;
        };
        if !self.options.simulator_only.contains(&import.as_str()) {
            return;
        }
        let name = self.tables.funcs[f as usize].name.clone();
        self.err(diagnostics::simulator_only(span, &name));
    }

    /// A literal over 2 pi where AdaIR expects radians (an angle of `RotX`,
    /// `RotY`, `RotZ`, a component of an `AxesVector`) is almost always
    /// meant in degrees: warn, and suggest `Rad (...)`.
    fn warn_degrees(&mut self, f: FuncId, formal: TypeId, actual: &ast::Expr) {
        fn literal(e: &ast::Expr) -> Option<f64> {
            match &e.kind {
                ExprKind::Real(v) => Some(*v),
                ExprKind::Int(v) => Some(v.get() as f64),
                ExprKind::Unary(_, x) => literal(x).map(|v| -v),
                ExprKind::Paren(x) => literal(x),
                _ => None,
            }
        }
        let name = self.tables.funcs[f as usize].name.to_ascii_lowercase();
        let angles: Vec<&ast::Expr> = if ["rotx", "roty", "rotz"].contains(&name.as_str()) {
            vec![actual]
        } else if self
            .tables
            .types
            .name(formal)
            .eq_ignore_ascii_case("AxesVector")
        {
            match &actual.kind {
                ExprKind::Aggregate(items) => items.iter().map(|i| &i.value).collect(),
                _ => Vec::new(),
            }
        } else {
            Vec::new()
        };
        for e in angles {
            if let Some(v) = literal(e)
                && v.abs() > std::f64::consts::TAU
            {
                let text = self.snippet(e.span);
                self.err(diagnostics::degrees_for_radians(e.span, &text));
            }
        }
    }
}
