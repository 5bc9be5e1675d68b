//! The possible types of an expression, bottom-up and without reporting
//! anything: the first pass of overload resolution.

use super::*;

impl Checker {
    /// The types an expression could have (without reporting anything).
    /// Memoised per node while an outermost expression is checked (see
    /// `Checker::memo`), which keeps overload resolution linear.
    pub(in crate::check) fn interps(&mut self, e: &ast::Expr) -> Vec<TypeId> {
        crate::work::tick();
        let outer = self.memo.is_none();
        if outer {
            self.memo = Some(HashMap::new());
        }
        let key = (
            e.span.start,
            e.span.end,
            e.span.context,
            std::mem::discriminant(&e.kind),
        );
        let found = self.memo.as_ref().and_then(|m| m.get(&key).cloned());
        let r = match found {
            Some(r) => r,
            None => {
                let r = self.interps_uncached(e);
                if let Some(m) = self.memo.as_mut() {
                    m.insert(key, r.clone());
                }
                r
            }
        };
        if outer {
            self.memo = None;
        }
        r
    }

    fn interps_uncached(&mut self, e: &ast::Expr) -> Vec<TypeId> {
        match &e.kind {
            ExprKind::Int(_) => vec![UNIV_INT],
            ExprKind::Real(_) => vec![UNIV_REAL],
            ExprKind::Char(c) => {
                let mut v = vec![CHARACTER];
                for ent in self.lookup(&char_lit_key(*c)) {
                    if let Entity::EnumLit(t, _) = ent {
                        v.push(t);
                    }
                }
                v
            }
            ExprKind::Str(_) => vec![STRING],
            ExprKind::Null => vec![NULL_T],
            ExprKind::Aggregate(_) | ExprKind::Allocator(..) => vec![ANY_COMPOSITE],
            ExprKind::Error => vec![ERROR],
            ExprKind::Paren(x) => self.interps(x),
            ExprKind::Name(_) => {
                let es = self.denote(e, false);
                self.entity_types(&es)
            }
            ExprKind::Select(p, id) => {
                if self.expanded_prefix(p) {
                    let es = self.denote(e, false);
                    return self.entity_types(&es);
                }
                let mut out = Vec::new();
                for t in self.interps(p) {
                    let t = self.tables.types.designated(t).unwrap_or(t);
                    if let Some(f) = self
                        .tables
                        .types
                        .fields(t)
                        .and_then(|fs| fs.iter().find(|f| *f.key == *id.key))
                    {
                        out.push(f.ty);
                    }
                }
                out
            }
            ExprKind::Deref(p) => self
                .interps(p)
                .into_iter()
                .filter_map(|t| self.tables.types.designated(t))
                .collect(),
            ExprKind::Apply(p, args) => {
                let pes = match &p.kind {
                    ExprKind::Name(_) | ExprKind::Select(..) => self.denote(p, false),
                    _ => Vec::new(),
                };
                match pes.first() {
                    Some(Entity::Type(t)) => vec![*t],
                    Some(Entity::Func(_)) => {
                        let fs: Vec<FuncId> = funcs_of(&pes);
                        let mut out = Vec::new();
                        for f in fs {
                            let Some(r) = self.tables.funcs[f as usize].ret else {
                                continue;
                            };
                            if self.args_fit(f, args) {
                                out.push(r);
                            } else if self.tables.funcs[f as usize].params.is_empty()
                                && let Some((idx, el, _)) = self.tables.types.array(r)
                            {
                                // `ValueAxes (1)`: a component of the result of
                                // a call without parameters.
                                let slice = args.len() == 1 && is_range_arg(&args[0].value);
                                out.push(if slice || idx.len() != args.len() {
                                    r
                                } else {
                                    el
                                });
                            }
                        }
                        out
                    }
                    _ => {
                        let mut out = Vec::new();
                        for t in self.interps(p) {
                            let t = self.tables.types.designated(t).unwrap_or(t);
                            if let Some((idx, el, _)) = self.tables.types.array(t) {
                                let slice = args.len() == 1 && is_range_arg(&args[0].value);
                                out.push(if slice || idx.len() != args.len() {
                                    t
                                } else {
                                    el
                                });
                            }
                        }
                        out
                    }
                }
            }
            ExprKind::Attr(p, a, _) => {
                let pt = match self.denote_quiet_type(p) {
                    Some(t) => Some(t),
                    None => self.interps(p).first().copied(),
                };
                match a.key.as_ref() {
                    "image" => vec![STRING],
                    "pos" | "length" | "digits" => vec![UNIV_INT],
                    "first" | "last" => match pt {
                        Some(t) => match self
                            .tables
                            .types
                            .array(self.tables.types.designated(t).unwrap_or(t))
                        {
                            Some((idx, _, _)) => vec![idx[0]],
                            None => vec![t],
                        },
                        None => vec![],
                    },
                    _ => pt.into_iter().collect(),
                }
            }
            ExprKind::Qualified(t, _) => match self.denote(t, false).first() {
                Some(Entity::Type(t)) => vec![*t],
                _ => vec![],
            },
            ExprKind::Binary(op, a, b) => match op {
                BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => {
                    vec![BOOLEAN]
                }
                BinOp::And | BinOp::Or | BinOp::Xor => {
                    let mut v = vec![BOOLEAN];
                    // `5 and 3` may be a value of any modular type.
                    if self.interps(a).contains(&UNIV_INT) && self.interps(b).contains(&UNIV_INT) {
                        v.push(UNIV_INT);
                    }
                    for t in self.interps(a).into_iter().chain(self.interps(b)) {
                        if (self.tables.types.is_bool_array(t)
                            || self.tables.types.modulus(t).is_some())
                            && !v.contains(&t)
                        {
                            v.push(t);
                        }
                    }
                    v
                }
                BinOp::AndThen | BinOp::OrElse => vec![BOOLEAN],
                BinOp::Cat => {
                    // Each type once: a chain `S & S & ...` has as many
                    // meanings as its first operand, not one per `&` (the
                    // list grew with the chain: quadratic memory).
                    let mut v: Vec<TypeId> = Vec::new();
                    for t in self.interps(a).into_iter().chain(self.interps(b)) {
                        if self.tables.types.is_array(t) && !v.contains(&t) {
                            v.push(t);
                        }
                    }
                    if v.is_empty() {
                        v.push(STRING);
                    }
                    v
                }
                _ => {
                    let mut out = self.user_op_types(op.symbol(), &[a, b]);
                    let (l, r) = (self.interps(a), self.interps(b));
                    for &x in &l {
                        for &y in &r {
                            if !self.tables.types.is_numeric(x)
                                || !(self.tables.types.is_numeric(y) || y == ERROR)
                            {
                                continue;
                            }
                            if *op == BinOp::Pow {
                                if self.tables.types.is_integer(y) {
                                    out.push(x);
                                }
                            } else if self.tables.types.compatible(x, y)
                                || self.tables.types.compatible(y, x)
                            {
                                out.push(if self.tables.types.is_universal(x) {
                                    y
                                } else {
                                    x
                                });
                            } else if (self.tables.types.base(x) == DURATION
                                && self.tables.types.is_integer(y)
                                && matches!(op, BinOp::Mul | BinOp::Div))
                                || (self.tables.types.base(y) == DURATION
                                    && self.tables.types.is_integer(x)
                                    && *op == BinOp::Mul)
                            {
                                out.push(DURATION);
                            }
                        }
                    }
                    out
                }
            },
            ExprKind::Unary(UnOp::Not, a) => {
                let mut v = vec![BOOLEAN];
                // `not 5` may be a value of any modular type.
                v.extend(self.interps(a).into_iter().filter(|t| {
                    *t == UNIV_INT
                        || self.tables.types.is_bool_array(*t)
                        || self.tables.types.modulus(*t).is_some()
                }));
                v
            }
            ExprKind::Unary(op, a) => {
                let mut out: Vec<TypeId> = self
                    .interps(a)
                    .into_iter()
                    .filter(|t| self.tables.types.is_numeric(*t))
                    .collect();
                if out.is_empty() {
                    out = self.user_op_types(op.symbol(), &[a]);
                }
                out
            }
            ExprKind::Membership { .. } => vec![BOOLEAN],
            ExprKind::If { arms, els } => {
                let mut branches: Vec<&ast::Expr> = arms.iter().map(|a| &a.1).collect();
                branches.extend(els.as_deref());
                self.branch_interps(&branches)
            }
            ExprKind::Case { arms, .. } => {
                let branches: Vec<&ast::Expr> = arms.iter().map(|a| &a.body).collect();
                self.branch_interps(&branches)
            }
        }
    }

    /// The types an `if` or `case` expression may have: its first
    /// branch's, unless that is a literal and another branch has a type
    /// (`(if B then 70000 else J)` is an Integer, so `Word (...)` of it
    /// checks the value).
    fn branch_interps(&mut self, branches: &[&ast::Expr]) -> Vec<TypeId> {
        let Some((first, rest)) = branches.split_first() else {
            return Vec::new();
        };
        let first = self.interps(first);
        if first.iter().all(|t| self.tables.types.is_universal(*t)) {
            for b in rest {
                let i = self.interps(b);
                if i.iter().any(|t| !self.tables.types.is_universal(*t)) {
                    return i;
                }
            }
        }
        first
    }

    /// Is `p` the prefix of an expanded name (a package, or an enclosing
    /// subprogram or named block), rather than a record value?
    pub(in crate::check) fn expanded_prefix(&mut self, p: &ast::Expr) -> bool {
        match &p.kind {
            ExprKind::Name(id) if self.scopes.enclosing(&id.key).is_some() => true,
            // Each prefix of an expanded name is a distinct package or
            // enclosing scope, so a longer chain is a component selection:
            // answering that without walking it keeps a dotted name of
            // n parts linear (each level asks this of its prefix).
            ExprKind::Select(..)
                if select_depth_exceeds(p, self.tables.packages.len() + self.scopes.depth()) =>
            {
                false
            }
            ExprKind::Name(_) | ExprKind::Select(..) => {
                matches!(self.denote(p, false).first(), Some(Entity::Package(_)))
            }
            _ => false,
        }
    }

    pub(super) fn denote_quiet_type(&mut self, p: &ast::Expr) -> Option<TypeId> {
        match &p.kind {
            ExprKind::Name(_) | ExprKind::Select(..) => match self.denote(p, false).first() {
                Some(Entity::Type(t)) => Some(*t),
                _ => None,
            },
            _ => None,
        }
    }

    fn entity_types(&self, es: &[Entity]) -> Vec<TypeId> {
        es.iter()
            .filter_map(|e| match e {
                Entity::Var { ty, .. } => Some(*ty),
                Entity::Alias(x) => Some(x.ty),
                Entity::Number(Static::Int(_)) => Some(UNIV_INT),
                Entity::Number(Static::Real(_)) => Some(UNIV_REAL),
                Entity::EnumLit(t, _) => Some(*t),
                Entity::Func(f) => {
                    let s = &self.tables.funcs[*f as usize];
                    if s.params.iter().all(|p| p.default.is_some()) {
                        s.ret
                    } else {
                        None
                    }
                }
                _ => None,
            })
            .collect()
    }
}
