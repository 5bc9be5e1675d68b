//! Expressions: overload resolution by the possible types of each operand
//! (bottom-up), then checking against the expected type (top-down).

use super::*;
use crate::syntax::ast::{BinOp, Choice, ExprKind, UnOp};

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
        match self.types.kind(t) {
            TypeKind::UnivInt => "universal integer (a literal)".into(),
            TypeKind::UnivReal => "universal real (a literal)".into(),
            TypeKind::AnyComposite => "an aggregate".into(),
            TypeKind::Null => "null".into(),
            _ => self.types.name(t).to_string(),
        }
    }

    /// Converts a checked expression to the type `t`: reports a mismatch, fixes
    /// the type of universal operands and adds the run-time checks Ada requires
    /// (range of a constrained scalar subtype, length of a constrained array).
    /// Converts an operand to the base type of `t` (unconstrained, as Ada's
    /// `T'Base`): compatibility and universal types, but no range check.
    pub(super) fn coerce_base(&mut self, ex: Ex, t: TypeId) -> Ex {
        let base = self.types.base(t);
        let saved = self.types.list[base as usize].range.take();
        let r = self.coerce(ex, base);
        self.types.list[base as usize].range = saved;
        r
    }

    pub(super) fn coerce(&mut self, mut ex: Ex, t: TypeId) -> Ex {
        if ex.ty == ERROR || t == ERROR {
            return ex;
        }
        if !self.types.compatible(ex.ty, t) {
            let mut d = diagnostics::type_mismatch(
                ex.span,
                &self.tname(t),
                &self.found_desc(ex.ty),
                &self.tname(ex.ty),
            );
            let (tf, ti) = (self.types.is_float(t), self.types.is_integer(t));
            if tf && self.types.is_integer(ex.ty) {
                d = match &ex.kind {
                    ExKind::Int(v) => d.with_hint(format!("write the literal as a real: `{v}.0`")),
                    _ => d.with_hint(format!(
                        "convert it: `{} ({})`",
                        self.types.name(t),
                        self.snippet(ex.span)
                    )),
                };
            } else if ti && self.types.is_float(ex.ty) {
                d = d.with_hint(format!(
                    "convert it: `{} ({})` (rounds to nearest, ties away from zero)",
                    self.types.name(t),
                    self.snippet(ex.span)
                ));
            } else if t == types::STRING
                && matches!(
                    self.types.kind(self.types.base(ex.ty)),
                    TypeKind::Integer
                        | TypeKind::Float
                        | TypeKind::Enum(_)
                        | TypeKind::UnivInt
                        | TypeKind::UnivReal
                )
            {
                // `Put_Line (Count)`: text is made with 'Image.
                let tn = match self.types.kind(ex.ty) {
                    TypeKind::UnivInt => "Integer".to_string(),
                    TypeKind::UnivReal => "Float".to_string(),
                    _ => self.types.name(ex.ty).to_string(),
                };
                d = d.with_hint(format!(
                    "make it text: `{tn}'Image ({})`",
                    self.snippet(ex.span)
                ));
            } else if self.types.base(t) == types::CHARACTER
                && matches!(
                    self.types.kind(self.types.base(ex.ty)),
                    TypeKind::Integer | TypeKind::Float | TypeKind::UnivInt | TypeKind::UnivReal
                )
            {
                // `"Z is " & Z`: `&` joins characters and strings only.
                let tn = match self.types.kind(ex.ty) {
                    TypeKind::UnivInt => "Integer".to_string(),
                    TypeKind::UnivReal => "Float".to_string(),
                    _ => self.types.name(ex.ty).to_string(),
                };
                d = d.with_hint(format!(
                    "`&` joins text, not numbers: make it text with `{tn}'Image ({})`",
                    self.snippet(ex.span)
                ));
            } else if self.types.base(ex.ty) == types::STRING
                && (ti || tf || matches!(self.types.kind(self.types.base(t)), TypeKind::Enum(_)))
            {
                // Text where a number or an enumeration value is wanted.
                let text = self.snippet(ex.span);
                let lit = text.strip_prefix('"').and_then(|t| t.strip_suffix('"'));
                let lits = self
                    .types
                    .enum_lits(t)
                    .map(|l| l.to_vec())
                    .unwrap_or_default();
                let same = lit.and_then(|l| lits.iter().find(|x| x.eq_ignore_ascii_case(l)));
                let hint = match (same, lit) {
                    (Some(name), _) => format!(
                        "write `{}` without quotes",
                        self.spelled(&name.to_lowercase())
                    ),
                    (None, Some(l)) if (ti || tf) && !l.is_empty() => format!(
                        "convert the text: `{}'Value ({text})`, or write the number `{l}`",
                        self.types.name(t)
                    ),
                    _ => format!("convert the text: `{}'Value ({text})`", self.types.name(t)),
                };
                d = d.with_hint(hint);
            } else if let ExKind::Int(v) = ex.kind
                && self.types.is_universal(ex.ty)
            {
                // An integer literal where a Boolean or an enumeration
                // value is wanted.
                if self.types.base(t) == types::BOOLEAN {
                    d = d.with_hint(format!(
                        "write `{}` (Ada's Boolean is not a number)",
                        if v == 0 { "False" } else { "True" }
                    ));
                } else if let Some(lits) = self.types.enum_lits(t).map(|l| l.to_vec())
                    && self.types.base(t) != types::CHARACTER
                {
                    let names: Vec<String> = lits
                        .iter()
                        .take(6)
                        .map(|l| format!("`{}`", self.spelled(&l.to_lowercase())))
                        .collect();
                    let more = if lits.len() > 6 { ", ..." } else { "" };
                    d = d.with_hint(format!(
                        "write one of {}{more} (or `{}'Val ({v})`)",
                        names.join(", "),
                        self.types.name(t)
                    ));
                }
            }
            self.err(d);
            ex.ty = ERROR;
            return ex;
        }
        if let ExKind::Int(v) = ex.kind
            && self.types.is_integer(t)
            && !self.types.is_universal(t)
            && i32::try_from(v).is_err()
        {
            self.err(diagnostics::static_outside_integer(
                ex.span,
                v,
                &self.tname(t),
            ));
            ex.ty = ERROR;
            return ex;
        }
        // RM 4.9(35): a static real expected of a floating point type lies
        // in that type's base range (a literal beyond it, `1.0E309` or
        // `1.0E39` for `Float`, is illegal, not infinity).
        if self.types.is_float(t)
            && !self.types.is_universal(t)
            && let Some((lo, hi)) = self.float_base_range(t)
            && (matches!(ex.kind, ExKind::Real(v) if !v.is_finite())
                || matches!(self.static_value(&ex), Some(Static::Real(v))
                    if exact::overflows(&v) || !(lo..=hi).contains(&exact::to_f64(&v))))
        {
            let e = |x: f64| {
                let t = format!("{x:.5e}");
                match t.split_once('e') {
                    Some((m, p)) if p.starts_with('-') => format!("{m}E{p}"),
                    Some((m, p)) => format!("{m}E+{p}"),
                    None => t,
                }
            };
            let shown = match self.snippet(ex.span) {
                s if s.len() <= 40 => s,
                _ => "the static value".to_string(),
            };
            self.err(diagnostics::static_outside_float(
                ex.span,
                &shown,
                &self.tname(self.types.base(t)),
                &e(lo),
                &e(hi),
            ));
            ex.ty = ERROR;
            return ex;
        }
        let from = ex.ty;
        if self.types.is_universal(ex.ty)
            || matches!(
                self.types.kind(ex.ty),
                TypeKind::Null | TypeKind::AnyComposite
            )
        {
            ex.ty = t;
        }
        let info = self.types.get(t);
        // Operations yield values of the base type, which may lie outside
        // the subtype even when their type is the subtype itself.
        let computed = matches!(
            ex.kind,
            ExKind::IntBin(..)
                | ExKind::FloatBin(..)
                | ExKind::IntNeg(_)
                | ExKind::FloatNeg(_)
                | ExKind::IntAbs(_)
                | ExKind::FloatAbs(_)
                | ExKind::IntToFloat(_)
                | ExKind::FloatToInt(_)
        );
        if self.types.is_scalar(t)
            && info.range.is_some()
            && (from != t || computed)
            && t != INTEGER
        {
            // Statically known to be in range: no check needed.
            let inside = match (
                self.static_value(&ex),
                info.static_range,
                info.static_frange,
            ) {
                (Some(Static::Int(v)), Some((l, h)), _) => l <= v && v <= h,
                (Some(Static::Real(v)), _, Some((l, h))) => {
                    let v = exact::to_f64(&v);
                    l <= v && v <= h
                }
                _ => false,
            };
            let same_range = !computed
                && from != ERROR
                && self.types.get(from).static_range.is_some()
                && self.types.get(from).static_range == info.static_range;
            if !inside && !same_range {
                // A static value outside a static range: it will raise.
                let outside = match (
                    self.static_value(&ex),
                    info.static_range,
                    info.static_frange,
                ) {
                    (Some(Static::Int(v)), Some((l, h)), _) => {
                        Some((v.to_string(), l.to_string(), h.to_string()))
                    }
                    (Some(Static::Real(v)), _, Some((l, h))) => Some((
                        format!("{:?}", exact::to_f64(&v)),
                        format!("{l:?}"),
                        format!("{h:?}"),
                    )),
                    _ => None,
                };
                if let Some((v, l, h)) = outside {
                    let tn = self.tname(t);
                    self.err(diagnostics::will_raise_constraint_error(
                        ex.span, &v, &tn, &l, &h,
                    ));
                }
                let span = ex.span;
                return self.mk(ExKind::RangeCheck(bx(ex), t), t, span);
            }
            ex.ty = t;
            return ex;
        }
        if let Some((_, _, Some(_))) = self.types.array(t)
            && ex.ty != t
        {
            let span = ex.span;
            return self.mk(ExKind::ArrayConvert(bx(ex), t), t, span);
        }
        ex
    }

    fn found_desc(&self, t: TypeId) -> String {
        match self.types.kind(t) {
            TypeKind::UnivInt => "an integer literal".into(),
            TypeKind::UnivReal => "a real literal".into(),
            TypeKind::AnyComposite => "an aggregate".into(),
            TypeKind::Null => "`null`".into(),
            _ => format!("`{}`", self.types.name(t)),
        }
    }

    /// Chooses one type for several expressions that must share one.
    pub(super) fn common_type(&mut self, es: &[&ast::Expr], default: TypeId) -> TypeId {
        let mut univ = None;
        for e in es {
            for t in self.interps(e) {
                if !self.types.is_universal(t)
                    && !matches!(
                        self.types.kind(t),
                        TypeKind::Null | TypeKind::AnyComposite | TypeKind::Error
                    )
                {
                    if es.iter().all(|x| self.fits(x, t)) {
                        return t;
                    }
                } else if univ.is_none() {
                    univ = Some(t);
                }
            }
        }
        match univ {
            Some(UNIV_REAL) => FLOAT,
            Some(UNIV_INT) => default,
            _ => default,
        }
    }

    /// Can `e` have type `t`?
    pub(super) fn fits(&mut self, e: &ast::Expr, t: TypeId) -> bool {
        if t == ERROR {
            return true;
        }
        match &e.kind {
            ExprKind::Str(_) => self
                .types
                .array(t)
                .is_some_and(|(i, el, _)| i.len() == 1 && self.types.base(el) == CHARACTER),
            ExprKind::Aggregate(_) => matches!(
                self.types.kind(t),
                TypeKind::Array { .. } | TypeKind::Record(_)
            ),
            ExprKind::Allocator(..) | ExprKind::Null => self.types.is_access(t),
            ExprKind::Paren(x) => self.fits(x, t),
            ExprKind::If { arms, .. } => arms.first().is_none_or(|a| self.fits(&a.1, t)),
            _ => {
                let is = self.interps(e);
                is.is_empty()
                    || is
                        .iter()
                        .any(|u| *u == ERROR || self.types.compatible(*u, t))
            }
        }
    }

    /// The types an expression could have (without reporting anything).
    /// Memoised per node while an outermost expression is checked (see
    /// `Checker::memo`), which keeps overload resolution linear.
    pub(super) fn interps(&mut self, e: &ast::Expr) -> Vec<TypeId> {
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
                    let t = self.types.designated(t).unwrap_or(t);
                    if let Some(f) = self
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
                .filter_map(|t| self.types.designated(t))
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
                            let Some(r) = self.funcs[f as usize].ret else {
                                continue;
                            };
                            if self.args_fit(f, args) {
                                out.push(r);
                            } else if self.funcs[f as usize].params.is_empty()
                                && let Some((idx, el, _)) = self.types.array(r)
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
                            let t = self.types.designated(t).unwrap_or(t);
                            if let Some((idx, el, _)) = self.types.array(t) {
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
                        Some(t) => match self.types.array(self.types.designated(t).unwrap_or(t)) {
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
                    for t in self.interps(a).into_iter().chain(self.interps(b)) {
                        if self.types.is_bool_array(t) && !v.contains(&t) {
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
                        if self.types.is_array(t) && !v.contains(&t) {
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
                            if !self.types.is_numeric(x)
                                || !(self.types.is_numeric(y) || y == ERROR)
                            {
                                continue;
                            }
                            if *op == BinOp::Pow {
                                if self.types.is_integer(y) {
                                    out.push(x);
                                }
                            } else if self.types.compatible(x, y) || self.types.compatible(y, x) {
                                out.push(if self.types.is_universal(x) { y } else { x });
                            } else if (self.types.base(x) == DURATION
                                && self.types.is_integer(y)
                                && matches!(op, BinOp::Mul | BinOp::Div))
                                || (self.types.base(y) == DURATION
                                    && self.types.is_integer(x)
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
                v.extend(
                    self.interps(a)
                        .into_iter()
                        .filter(|t| self.types.is_bool_array(*t)),
                );
                v
            }
            ExprKind::Unary(op, a) => {
                let mut out: Vec<TypeId> = self
                    .interps(a)
                    .into_iter()
                    .filter(|t| self.types.is_numeric(*t))
                    .collect();
                if out.is_empty() {
                    out = self.user_op_types(op.symbol(), &[a]);
                }
                out
            }
            ExprKind::Membership { .. } => vec![BOOLEAN],
            ExprKind::If { arms, .. } => {
                arms.first().map(|a| self.interps(&a.1)).unwrap_or_default()
            }
            ExprKind::Case { arms, .. } => arms
                .first()
                .map(|a| self.interps(&a.body))
                .unwrap_or_default(),
        }
    }

    /// Is `p` the prefix of an expanded name (a package, or an enclosing
    /// subprogram or named block), rather than a record value?
    pub(super) fn expanded_prefix(&mut self, p: &ast::Expr) -> bool {
        match &p.kind {
            ExprKind::Name(id)
                if self
                    .scopes
                    .iter()
                    .any(|s| s.name.as_deref() == Some(id.key.as_ref())) =>
            {
                true
            }
            // Each prefix of an expanded name is a distinct package or
            // enclosing scope, so a longer chain is a component selection:
            // answering that without walking it keeps a dotted name of
            // n parts linear (each level asks this of its prefix).
            ExprKind::Select(..)
                if select_depth_exceeds(p, self.packages.len() + self.scopes.len()) =>
            {
                false
            }
            ExprKind::Name(_) | ExprKind::Select(..) => {
                matches!(self.denote(p, false).first(), Some(Entity::Package(_)))
            }
            _ => false,
        }
    }

    fn denote_quiet_type(&mut self, p: &ast::Expr) -> Option<TypeId> {
        match &p.kind {
            ExprKind::Name(_) | ExprKind::Select(..) => match self.denote(p, false).first() {
                Some(Entity::Type(t)) => Some(*t),
                _ => None,
            },
            _ => None,
        }
    }

    fn user_op_types(&mut self, sym: &str, args: &[&ast::Expr]) -> Vec<TypeId> {
        let cands = self.op_funcs(sym, args.len());
        let mut out = Vec::new();
        for f in cands {
            let ps: Vec<TypeId> = self.funcs[f as usize].params.iter().map(|p| p.ty).collect();
            if args.iter().zip(&ps).all(|(a, t)| self.fits(a, *t))
                && let Some(r) = self.funcs[f as usize].ret
            {
                out.push(r);
            }
        }
        out
    }

    fn op_funcs(&self, sym: &str, arity: usize) -> Vec<FuncId> {
        self.lookup(&format!("\"{sym}\""))
            .into_iter()
            .filter_map(|e| {
                if let Entity::Func(f) = e {
                    Some(f)
                } else {
                    None
                }
            })
            .filter(|f| self.funcs[*f as usize].params.len() == arity)
            .collect()
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
                    let s = &self.funcs[*f as usize];
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

    /// Maps actual arguments to the formals of `f`: one entry per formal,
    /// `None` where the default applies. `Err` says why they do not match.
    fn match_args<'a>(
        &self,
        f: FuncId,
        args: &'a [ast::Arg],
    ) -> Result<Vec<Option<&'a ast::Arg>>, diagnostics::ArgsMismatch> {
        use diagnostics::ArgsMismatch as Why;
        let sub = &self.funcs[f as usize];
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

    fn args_fit(&mut self, f: FuncId, args: &[ast::Arg]) -> bool {
        let Ok(slots) = self.match_args(f, args) else {
            return false;
        };
        let tys: Vec<TypeId> = self.funcs[f as usize].params.iter().map(|p| p.ty).collect();
        slots
            .iter()
            .zip(tys)
            .all(|(s, t)| s.is_none_or(|a| self.fits(&a.value, t)))
    }

    /// Resolves a call among candidate subprograms and checks its arguments.
    pub(super) fn call(
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
            .filter(|f| self.funcs[*f as usize].ret.is_none() == procedure)
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
                    self.funcs[*f as usize]
                        .ret
                        .is_some_and(|r| self.types.compatible(r, w))
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
                let (a, b) = (&self.funcs[f as usize], &self.funcs[*g as usize]);
                a.params.len() == b.params.len()
                    && a.params
                        .iter()
                        .zip(&b.params)
                        .all(|(x, y)| self.types.base(x.ty) == self.types.base(y.ty))
                    && a.ret.map(|t| self.types.base(t)) == b.ret.map(|t| self.types.base(t))
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
        let params = self.funcs[f as usize].params.clone();
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
                        if !self.types.compatible(actual_ty, p.ty)
                            || self.types.is_universal(actual_ty)
                        {
                            // Only for its diagnostic: the actual stays a variable.
                            let _ = self.coerce(ex.clone(), p.ty);
                        }
                        let back_check = (self.types.is_scalar(actual_ty)
                            && actual_ty != p.ty
                            && self.types.get(actual_ty).range.is_some()
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
        Some(self.internal_prot_call(f, out, span))
    }

    pub fn signature(&self, f: FuncId) -> String {
        let s = &self.funcs[f as usize];
        let ps: Vec<String> = s
            .params
            .iter()
            .map(|p| {
                let mode = mode_text(p.mode);
                format!(
                    "{} : {mode}{}{}",
                    p.name,
                    self.types.name(p.ty),
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
            Some(r) => format!("function {}{params} return {}", s.name, self.types.name(r)),
            None => format!("procedure {}{params}", s.name),
        }
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
                ExKind::Index(p, _) | ExKind::Field(p, _) | ExKind::Slice(p, _) => e = p,
                // A component of the object of a protected function.
                ExKind::Deref(p) if matches!(p.kind, ExKind::Var(v) if Some(v) == self.prot_function_obj) =>
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
        self.var_names.get(&v).cloned()
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
                    && self.types.base(w) != CHARACTER
                {
                    for ent in self.lookup(&char_lit_key(*c)) {
                        if let Entity::EnumLit(t, pos) = ent
                            && self.types.compatible(t, w)
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
                let ty = if self.types.array(ty).is_some_and(|a| a.2.is_some()) {
                    self.types.base(ty)
                } else {
                    ty
                };
                let ty = if self.types.array(ty).is_some() {
                    self.unconstrained_of(ty)
                } else {
                    STRING
                };
                // Its lower bound is its index subtype's first (RM 4.2(11)):
                // 1 for String; otherwise an aggregate of its characters.
                let first = match self.types.array(ty) {
                    Some((index, elem, None)) if index.len() == 1 => {
                        self.types.get(index[0]).static_range.map(|r| (r.0, elem))
                    }
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
                match self.types.designated(pe.ty) {
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
                            self.types.is_universal(first)
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
                                if rt != ERROR && !self.types.compatible(rt, s.ty) {
                                    self.err(diagnostics::range_of_other_type(
                                        x.span,
                                        self.types.name(rt),
                                        &self.tname(s.ty),
                                    ));
                                }
                                ranges.push((l, h));
                            } else if let Some(tt) = self.denote_quiet_type(x) {
                                if !self.types.compatible(tt, s.ty) {
                                    self.err(diagnostics::not_a_subtype_of(
                                        x.span,
                                        self.types.name(tt),
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
                Some(t) if t != ERROR && !self.types.is_universal(t) => {
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
                        if self.types.base(t) != BOOLEAN {
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
                let s = self.expr(subject, None);
                let st = if self.types.is_universal(s.ty) {
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
                let Some(w) = want.filter(|w| self.types.is_access(*w)) else {
                    if want != Some(ERROR) {
                        self.err(diagnostics::allocator_without_access_type(sp));
                    }
                    return self.err_ex(sp);
                };
                let d = self.types.designated(w).unwrap_or(ERROR);
                let t = self.type_mark(tm);
                if !self.types.compatible(t, d) {
                    self.err(diagnostics::designates_other_type(
                        tm.span,
                        self.types.name(w),
                        self.types.name(d),
                        self.types.name(t),
                    ));
                }
                let init = init.as_ref().map(|x| {
                    let v = self.expr(x, Some(t));
                    bx(self.coerce(v, t))
                });
                self.mk(ExKind::Alloc(init, t), w, sp)
            }
        }
    }

    /// An unconstrained array type with the same index and element types.
    pub(super) fn unconstrained_of(&mut self, t: TypeId) -> TypeId {
        match self.types.array(t) {
            Some((idx, el, Some(_))) => {
                let (idx, el) = (idx.to_vec(), el);
                let name = self.types.name(t).to_string();
                let base = self.types.base(t);
                let n = self.types.add(
                    &name,
                    TypeKind::Array {
                        index: idx,
                        elem: el,
                        bounds: None,
                    },
                );
                self.types.list[n as usize].base = base;
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
                        && want.is_none_or(|w| self.types.compatible(*t, w))
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
                        let r = self.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(f, args.into()), r, sp)
                    }
                    None => self.err_ex(sp),
                }
            }
            Entity::Type(t) => {
                let n = self.types.name(*t).to_string();
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
        if let TypeKind::Protected(k) = self.types.kind(pe.ty).clone() {
            return self.prot_function(k, pe, id, &[], sp);
        }
        if let Some(d) = self.types.designated(pe.ty) {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
        }
        if pe.ty == ERROR {
            return self.err_ex(sp);
        }
        match self.types.fields(pe.ty).map(|f| f.to_vec()) {
            Some(fields) => match fields.iter().position(|f| *f.key == *id.key) {
                Some(i) => {
                    let t = fields[i].ty;
                    self.index_field_ref(id.span, pe.ty, i as u32);
                    self.mk(ExKind::Field(bx(pe), i as u32), t, sp)
                }
                None => {
                    let names: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
                    self.err(diagnostics::no_component(
                        id.span,
                        self.types.name(pe.ty),
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
                    self.err(diagnostics::conversion_arity(sp, self.types.name(t)));
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
                        let sub = &self.funcs[*f as usize];
                        sub.params.iter().all(|p| p.default.is_some())
                            && sub
                                .ret
                                .and_then(|r| self.types.array(r))
                                .is_some_and(|a| a.0.len() == args.len())
                    })
                {
                    if let Some(id) = super::stmt::last_ident(p) {
                        self.index_ref(id.span, &id.key, &Entity::Func(f));
                    }
                    let r = self.funcs[f as usize].ret.unwrap_or(ERROR);
                    let defaults: Vec<Arg> = self.funcs[f as usize]
                        .params
                        .iter()
                        .map(|p| Arg {
                            mode: ast::Mode::In,
                            value: p.default.clone().unwrap_or_else(|| Ex::int(0)),
                            back_check: None,
                        })
                        .collect();
                    let callee = self.mk(ExKind::Call(f, defaults.into()), r, p.span);
                    let idx: Vec<TypeId> = self
                        .types
                        .array(r)
                        .map(|a| a.0.to_vec())
                        .unwrap_or_default();
                    let el = self.types.array(r).map(|a| a.1).unwrap_or(ERROR);
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
                        let r = self.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(f, a.into()), r, sp)
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
                if let Some(d) = self.types.designated(pe.ty) {
                    let psp = pe.span;
                    pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
                }
                if pe.ty == ERROR {
                    for a in args {
                        self.expr(&a.value, None);
                    }
                    return self.err_ex(sp);
                }
                let Some((idx, el, _)) = self
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
                        self.types.name(pe.ty),
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
            .find(|u| !self.types.is_universal(*u))
            .or(xi.first().copied())
            .unwrap_or(ERROR);
        let want = if self.types.is_numeric(t) && self.types.is_numeric(src) {
            Some(src)
        } else {
            Some(t)
        };
        let ex = self.expr(x, want);
        if ex.ty == ERROR || t == ERROR {
            return self.err_ex(sp);
        }
        let (tf, ti) = (self.types.is_float(t), self.types.is_integer(t));
        let (sf, si) = (self.types.is_float(ex.ty), self.types.is_integer(ex.ty));
        let inner = if tf && si {
            self.mk(ExKind::IntToFloat(bx(ex)), self.types.base(t), sp)
        } else if ti && sf {
            self.mk(ExKind::FloatToInt(bx(ex)), self.types.base(t), sp)
        } else if (tf && sf) || (ti && si) {
            Ex {
                ty: self.types.base(t),
                ..ex
            }
        } else if self.types.base(ex.ty) == self.types.base(t) {
            ex
        } else if let (Some((i1, e1, _)), Some((i2, e2, _))) =
            (self.types.array(ex.ty), self.types.array(t))
        {
            if i1.len() == i2.len() && self.types.base(e1) == self.types.base(e2) {
                let tt = if self.types.array(t).is_some_and(|a| a.2.is_some()) {
                    t
                } else {
                    self.types.base(t)
                };
                return self.mk(ExKind::ArrayConvert(bx(ex), tt), t, sp);
            }
            self.err(diagnostics::cannot_convert_arrays(
                sp,
                &self.tname(ex.ty),
                self.types.name(t),
            ));
            return self.err_ex(sp);
        } else {
            self.err(diagnostics::cannot_convert(
                sp,
                &self.tname(ex.ty),
                self.types.name(t),
            ));
            return self.err_ex(sp);
        };
        let mut inner = inner;
        inner.span = sp;
        self.coerce(inner, t)
    }

    fn binary(
        &mut self,
        op: BinOp,
        a: &ast::Expr,
        b: &ast::Expr,
        want: Option<TypeId>,
        sp: Span,
    ) -> Ex {
        let lop = match op {
            BinOp::And => Some(LogicOp::And),
            BinOp::Or => Some(LogicOp::Or),
            BinOp::Xor => Some(LogicOp::Xor),
            _ => None,
        };
        if let Some(lop) = lop
            && let Some(t) = self.bool_array_operands(&[a, b], want)
        {
            let x = self.expr(a, Some(t));
            let x = self.coerce(x, t);
            let y = self.expr(b, Some(t));
            let y = self.coerce(y, t);
            return self.mk(ExKind::ArrLogic(lop, bx(x), bx(y)), self.types.base(t), sp);
        }
        match op {
            BinOp::And | BinOp::Or | BinOp::Xor | BinOp::AndThen | BinOp::OrElse => {
                let x = self.expr(a, Some(BOOLEAN));
                let x = self.coerce(x, BOOLEAN);
                let y = self.expr(b, Some(BOOLEAN));
                let y = self.coerce(y, BOOLEAN);
                let lop = match op {
                    BinOp::And => LogicOp::And,
                    BinOp::Or => LogicOp::Or,
                    BinOp::Xor => LogicOp::Xor,
                    BinOp::AndThen => LogicOp::AndThen,
                    _ => LogicOp::OrElse,
                };
                return self.mk(ExKind::Logic(lop, bx(x), bx(y)), BOOLEAN, sp);
            }
            _ => {}
        }
        // User-defined operators (for example "*" on Frame, "-" on Time).
        let user = self.op_funcs(op.symbol(), 2);
        let user_fit: Vec<FuncId> = user
            .into_iter()
            .filter(|f| {
                let ps: Vec<TypeId> = self.funcs[*f as usize]
                    .params
                    .iter()
                    .map(|p| p.ty)
                    .collect();
                self.fits(a, ps[0])
                    && self.fits(b, ps[1])
                    && want.is_none_or(|w| {
                        self.funcs[*f as usize]
                            .ret
                            .is_some_and(|r| self.types.compatible(r, w))
                    })
            })
            .collect();
        let user_call = |this: &mut Self, f: FuncId| {
            let args = [
                ast::Arg {
                    name: None,
                    value: a.clone(),
                    span: a.span,
                },
                ast::Arg {
                    name: None,
                    value: b.clone(),
                    span: b.span,
                },
            ];
            match this.call(&[f], &args, want, false, sp, op.symbol()) {
                Some((f, args)) => {
                    let r = this.funcs[f as usize].ret.unwrap_or(ERROR);
                    this.mk(ExKind::Call(f, args.into()), r, sp)
                }
                None => this.err_ex(sp),
            }
        };
        // `/=` of a type with a user-defined `=` is `not (A = B)`.
        let (user_fit, negate) = if op == BinOp::Ne && user_fit.is_empty() {
            let eq: Vec<FuncId> = self
                .op_funcs("=", 2)
                .into_iter()
                .filter(|f| {
                    let fi = &self.funcs[*f as usize];
                    let (ret, p0, p1) = (fi.ret, fi.params[0].ty, fi.params[1].ty);
                    ret.is_some_and(|r| self.types.base(r) == BOOLEAN)
                        && self.fits(a, p0)
                        && self.fits(b, p1)
                })
                .collect();
            let neg = !eq.is_empty();
            (eq, neg)
        } else {
            (user_fit, false)
        };
        let user_call = |this: &mut Self, f: FuncId| {
            let e = user_call(this, f);
            if negate && e.ty != ERROR {
                let esp = e.span;
                this.mk(ExKind::Not(bx(e)), BOOLEAN, esp)
            } else {
                e
            }
        };
        match op {
            BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge => {
                let (li, ri) = (self.interps(a), self.interps(b));
                let predefined_ok = li.iter().any(|x| {
                    ri.iter()
                        .any(|y| self.types.compatible(*x, *y) || self.types.compatible(*y, *x))
                });
                if let Some(f) = user_fit.first()
                    && (!predefined_ok
                        || !li
                            .iter()
                            .any(|t| self.types.is_scalar(*t) || self.types.is_array(*t)))
                {
                    return user_call(self, *f);
                }
                let t = self.common_type(&[a, b], INTEGER);
                let x = self.expr(a, Some(t));
                let y = self.expr(b, Some(t));
                if x.ty != ERROR
                    && y.ty != ERROR
                    && !self.types.compatible(x.ty, y.ty)
                    && !self.types.compatible(y.ty, x.ty)
                {
                    self.mismatch(op, &x, &y, a, b, sp);
                    return self.mk(ExKind::Error, BOOLEAN, sp);
                }
                let t = if self.types.is_universal(x.ty) {
                    y.ty
                } else {
                    x.ty
                };
                let t = if self.types.is_universal(t) {
                    if self.types.is_float(t) {
                        FLOAT
                    } else {
                        INTEGER
                    }
                } else {
                    t
                };
                let x = self.coerce_base(x, t);
                let y = self.coerce_base(y, t);
                // A comparison of static values is static, and exact (for
                // named numbers, `0.1 + 0.2 = 0.3` is True).
                let order = match (self.shallow_static(&x), self.shallow_static(&y)) {
                    (Some(Static::Int(p)), Some(Static::Int(q))) => Some(p.cmp(&q)),
                    (Some(Static::Real(p)), Some(Static::Real(q))) => Some(p.cmp(&q)),
                    _ => None,
                };
                if let Some(o) = order {
                    use std::cmp::Ordering::*;
                    let r = match op {
                        BinOp::Eq => o == Equal,
                        BinOp::Ne => o != Equal,
                        BinOp::Lt => o == Less,
                        BinOp::Le => o != Greater,
                        BinOp::Gt => o == Greater,
                        _ => o != Less,
                    };
                    return self.mk(ExKind::Int(r as i64), BOOLEAN, sp);
                }
                if matches!(op, BinOp::Eq | BinOp::Ne) {
                    return self.mk(ExKind::Eq(op == BinOp::Ne, bx(x), bx(y)), BOOLEAN, sp);
                }
                let ordered = self.types.is_scalar(t)
                    || self
                        .types
                        .array(t)
                        .is_some_and(|(i, e, _)| i.len() == 1 && self.types.is_discrete(e));
                if !ordered && t != ERROR {
                    self.err(diagnostics::ordering_undefined(
                        sp,
                        op.symbol(),
                        &self.tname(t),
                    ));
                }
                let c = match op {
                    BinOp::Lt => CmpOp::Lt,
                    BinOp::Le => CmpOp::Le,
                    BinOp::Gt => CmpOp::Gt,
                    _ => CmpOp::Ge,
                };
                self.mk(ExKind::Cmp(c, bx(x), bx(y)), BOOLEAN, sp)
            }
            BinOp::Cat => {
                let t = match want {
                    Some(w) if self.types.is_array(w) => self.unconstrained_of(w),
                    _ => {
                        let c: Vec<TypeId> = self
                            .interps(a)
                            .into_iter()
                            .chain(self.interps(b))
                            .filter(|t| self.types.is_array(*t))
                            .collect();
                        c.first()
                            .map(|t| self.unconstrained_of(*t))
                            .unwrap_or(STRING)
                    }
                };
                let el = self.types.array(t).map(|x| x.1).unwrap_or(ERROR);
                let side = |this: &mut Self, e: &ast::Expr| -> (Ex, bool) {
                    if this.fits(e, t) && !matches!(e.kind, ExprKind::Char(_)) {
                        let x = this.expr(e, Some(t));
                        (this.coerce(x, t), false)
                    } else {
                        let x = this.expr(e, Some(el));
                        (this.coerce(x, el), true)
                    }
                };
                let (x, xe) = side(self, a);
                let (y, ye) = side(self, b);
                self.mk(ExKind::Concat(bx(x), bx(y), xe, ye), t, sp)
            }
            _ => {
                // Predefined arithmetic: both operands of one numeric type,
                // except `**` (Integer exponent) and Duration * Integer.
                let arith = self.arith_type(op, a, b, want);
                // A user operator whose result the context wants wins over a
                // predefined one whose result it does not (Ada.Real_Time's
                // `/` of two spans is an Integer).
                let unwanted = |this: &Self, t: TypeId| {
                    let t = if t == DURATION + 1000 { DURATION } else { t };
                    want.is_some_and(|w| {
                        w != ERROR && !this.types.compatible(t, w) && !this.types.compatible(w, t)
                    })
                };
                match arith {
                    Some(t) if unwanted(self, t) && !user_fit.is_empty() => {
                        user_call(self, user_fit[0])
                    }
                    Some(t) => self.arith(op, a, b, t, sp),
                    None => {
                        if let Some(f) = user_fit.first() {
                            return user_call(self, *f);
                        }
                        let x = self.expr(a, None);
                        let y = self.expr(b, None);
                        if x.ty != ERROR && y.ty != ERROR {
                            self.mismatch(op, &x, &y, a, b, sp);
                        }
                        self.err_ex(sp)
                    }
                }
            }
        }
    }

    fn mismatch(&mut self, op: BinOp, x: &Ex, y: &Ex, a: &ast::Expr, b: &ast::Expr, sp: Span) {
        let (xt, yt) = (self.tname(x.ty), self.tname(y.ty));
        let mut d = diagnostics::operands_mixed(sp, op.symbol(), &xt, &yt);
        let (xi, yi) = (self.types.is_integer(x.ty), self.types.is_integer(y.ty));
        let (xf, yf) = (self.types.is_float(x.ty), self.types.is_float(y.ty));
        let fname = |this: &Self, t: TypeId| {
            if this.types.is_universal(t) {
                "Float".to_string()
            } else {
                this.types.name(t).to_string()
            }
        };
        if xi && yf {
            d = d.with_hint(format!(
                "convert the integer: `{} ({}) {} {}`",
                fname(self, y.ty),
                self.snippet(a.span),
                op.symbol(),
                self.snippet(b.span)
            ));
        } else if xf && yi && matches!(y.kind, ExKind::Int(_)) && self.types.is_universal(y.ty) {
            d = d.with_hint(format!(
                "write the literal as a real: `{} {} {}.0`",
                self.snippet(a.span),
                op.symbol(),
                self.snippet(b.span)
            ));
        } else if xf && yi {
            d = d.with_hint(format!(
                "convert the integer: `{} {} {} ({})`",
                self.snippet(a.span),
                op.symbol(),
                fname(self, x.ty),
                self.snippet(b.span)
            ));
        }
        self.err(d);
    }

    fn arith_type(
        &mut self,
        op: BinOp,
        a: &ast::Expr,
        b: &ast::Expr,
        want: Option<TypeId>,
    ) -> Option<TypeId> {
        let (li, ri) = (self.interps(a), self.interps(b));
        if op == BinOp::Pow {
            if !ri.iter().any(|t| self.types.is_integer(*t)) {
                return None;
            }
            if let Some(w) = want
                && self.types.is_numeric(w)
                && self.fits(a, w)
            {
                return Some(w);
            }
            return li
                .iter()
                .copied()
                .find(|t| self.types.is_numeric(*t) && !self.types.is_universal(*t))
                .or(li.iter().copied().find(|t| self.types.is_numeric(*t)));
        }
        let int_only = matches!(op, BinOp::Mod | BinOp::Rem);
        let ok = |this: &Self, t: TypeId| {
            this.types.is_numeric(t) && (!int_only || this.types.is_integer(t))
        };
        if let Some(w) = want
            && ok(self, w)
            && !self.types.is_universal(w)
            && self.fits(a, w)
            && self.fits(b, w)
        {
            return Some(w);
        }
        for &t in li.iter().chain(ri.iter()) {
            if ok(self, t) && !self.types.is_universal(t) && self.fits(a, t) && self.fits(b, t) {
                return Some(t);
            }
        }
        // Duration * Integer, Integer * Duration, Duration / Integer.
        if matches!(op, BinOp::Mul | BinOp::Div) {
            let dl = li.iter().any(|t| self.types.base(*t) == DURATION);
            let dr = ri.iter().any(|t| self.types.base(*t) == DURATION);
            let il = li.iter().any(|t| self.types.is_integer(*t));
            let ir = ri.iter().any(|t| self.types.is_integer(*t));
            if (dl && ir) || (op == BinOp::Mul && il && dr) {
                return Some(DURATION + 1000);
            }
        }
        if li.contains(&UNIV_INT) && ri.contains(&UNIV_INT) {
            return Some(UNIV_INT);
        }
        if li.contains(&UNIV_REAL) && ri.contains(&UNIV_REAL) && !int_only {
            return Some(UNIV_REAL);
        }
        // root_real * root_integer (and / by root_integer) for named numbers.
        if (op == BinOp::Mul
            && ((li.contains(&UNIV_REAL) && ri.contains(&UNIV_INT))
                || (li.contains(&UNIV_INT) && ri.contains(&UNIV_REAL))))
            || (op == BinOp::Div && li.contains(&UNIV_REAL) && ri.contains(&UNIV_INT))
        {
            return Some(UNIV_REAL);
        }
        None
    }

    fn arith(&mut self, op: BinOp, a: &ast::Expr, b: &ast::Expr, t: TypeId, sp: Span) -> Ex {
        if t == DURATION + 1000 {
            // Duration scaled by an integer.
            let (x, y) = if self
                .interps(a)
                .iter()
                .any(|t| self.types.base(*t) == DURATION)
            {
                let x = self.expr(a, Some(DURATION));
                let x = self.coerce(x, DURATION);
                let y = self.expr(b, Some(INTEGER));
                let y = self.coerce(y, INTEGER);
                let ysp = y.span;
                (x, self.mk(ExKind::IntToFloat(bx(y)), DURATION, ysp))
            } else {
                let x = self.expr(a, Some(INTEGER));
                let x = self.coerce(x, INTEGER);
                let y = self.expr(b, Some(DURATION));
                let y = self.coerce(y, DURATION);
                let xsp = x.span;
                (self.mk(ExKind::IntToFloat(bx(x)), DURATION, xsp), y)
            };
            let fop = if op == BinOp::Mul {
                FloatOp::Mul
            } else {
                FloatOp::DurDiv
            };
            return self.mk(ExKind::FloatBin(fop, bx(x), bx(y)), DURATION, sp);
        }
        let base = self.types.base(t);
        if op == BinOp::Pow {
            let x = self.expr(a, Some(t));
            let x = self.coerce_base(x, base);
            let y = self.expr(b, Some(INTEGER));
            let y = self.coerce(
                y,
                if self.types.is_float(t) {
                    INTEGER
                } else {
                    NATURAL
                },
            );
            let e = if self.types.is_float(t) {
                self.mk(ExKind::FloatBin(FloatOp::PowI, bx(x), bx(y)), base, sp)
            } else {
                self.mk(ExKind::IntBin(IntOp::Pow, bx(x), bx(y)), base, sp)
            };
            return self.fold(e);
        }
        let x = self.expr(a, Some(t));
        let y = self.expr(b, Some(t));
        // Both operands static: the result is computed exactly, as Ada's
        // static expressions are (`Integer'Last + 1 - 1` is fine); only the
        // value of the whole static expression must fit its type, which
        // `coerce` checks where it is used.
        let static_operands = self.shallow_static(&x).is_some()
            && self.shallow_static(&y).is_some()
            && self.types.compatible(x.ty, base)
            && self.types.compatible(y.ty, base);
        let (x, y) = if static_operands {
            let (mut x, mut y) = (x, y);
            x.ty = base;
            y.ty = base;
            (x, y)
        } else {
            (self.coerce_base(x, base), self.coerce_base(y, base))
        };
        if self.types.is_float(t) {
            let fop = match op {
                BinOp::Add => FloatOp::Add,
                BinOp::Sub => FloatOp::Sub,
                BinOp::Mul => FloatOp::Mul,
                _ => FloatOp::Div,
            };
            let e = self.mk(ExKind::FloatBin(fop, bx(x), bx(y)), base, sp);
            self.fold(e)
        } else {
            let iop = match op {
                BinOp::Add => IntOp::Add,
                BinOp::Sub => IntOp::Sub,
                BinOp::Mul => IntOp::Mul,
                BinOp::Div => IntOp::Div,
                BinOp::Mod => IntOp::Mod,
                _ => IntOp::Rem,
            };
            let e = self.mk(ExKind::IntBin(iop, bx(x), bx(y)), base, sp);
            self.fold(e)
        }
    }

    /// The value of `e` when it is a static leaf: a literal (every static
    /// operation is folded into one as soon as it is checked) or a scalar
    /// type's bound. Constant time, so folding a chain stays linear.
    pub(super) fn shallow_static(&self, e: &Ex) -> Option<Static> {
        match &e.kind {
            ExKind::Int(_) | ExKind::Real(_) | ExKind::TypeFirst(_) | ExKind::TypeLast(_) => {
                self.static_value(e)
            }
            _ => None,
        }
    }

    /// A real literal node for a static value, remembering its exact value
    /// for the static expressions it is part of.
    pub(super) fn real_lit(&mut self, v: exact::Exact, ty: TypeId, sp: Span) -> Ex {
        let f = exact::to_f64(&v);
        self.exact_reals.insert((sp.start, sp.end, sp.context), v);
        self.mk(ExKind::Real(f), ty, sp)
    }

    /// An operation whose operands are static leaves becomes a literal of
    /// its exact value. An integer value of a type with its own range is
    /// folded only inside that range (the run-time check would raise); an
    /// `Integer` intermediate may leave the 32-bit range, and `coerce`
    /// refuses a final value outside it.
    fn fold(&mut self, e: Ex) -> Ex {
        let leaves = match &e.kind {
            ExKind::IntBin(_, a, b) | ExKind::FloatBin(_, a, b) => {
                self.shallow_static(a).is_some() && self.shallow_static(b).is_some()
            }
            ExKind::IntNeg(a) | ExKind::FloatNeg(a) | ExKind::IntAbs(a) | ExKind::FloatAbs(a) => {
                self.shallow_static(a).is_some()
            }
            _ => false,
        };
        if !leaves {
            return e;
        }
        let base = self.types.base(e.ty);
        match self.static_value(&e) {
            Some(Static::Int(v)) => {
                let info = self.types.get(base);
                let fits = if base == INTEGER || self.types.is_universal(base) {
                    i64::try_from(v).is_ok()
                } else {
                    match (info.range.is_some(), info.static_range) {
                        (false, _) => i64::try_from(v).is_ok(),
                        (true, Some((l, h))) => l <= v && v <= h,
                        (true, None) => false,
                    }
                };
                if fits {
                    self.mk(ExKind::Int(v as i64), e.ty, e.span)
                } else {
                    e
                }
            }
            Some(Static::Real(r)) if !exact::overflows(&r) => self.real_lit(r, e.ty, e.span),
            _ => e,
        }
    }

    /// The Boolean array type of a logical operator's operands: the one
    /// wanted, or one an operand can have; None for Boolean operands.
    fn bool_array_operands(&mut self, ops: &[&ast::Expr], want: Option<TypeId>) -> Option<TypeId> {
        if let Some(w) = want {
            return self.types.is_bool_array(w).then_some(w);
        }
        let cands: Vec<TypeId> = ops.iter().flat_map(|e| self.interps(e)).collect();
        cands.into_iter().find(|t| self.types.is_bool_array(*t))
    }

    fn unary(&mut self, op: UnOp, a: &ast::Expr, want: Option<TypeId>, sp: Span) -> Ex {
        if op == UnOp::Not
            && let Some(t) = self.bool_array_operands(&[a], want)
        {
            let x = self.expr(a, Some(t));
            let x = self.coerce(x, t);
            return self.mk(ExKind::ArrNot(bx(x)), self.types.base(t), sp);
        }
        if op == UnOp::Not {
            let x = self.expr(a, Some(BOOLEAN));
            let x = self.coerce(x, BOOLEAN);
            return self.mk(ExKind::Not(bx(x)), BOOLEAN, sp);
        }
        // A user-defined `"-"`, `"+"` or `"abs"` on a non-numeric type (a
        // record, say).
        if !self.interps(a).iter().any(|t| self.types.is_numeric(*t)) {
            let user: Vec<FuncId> = self
                .op_funcs(op.symbol(), 1)
                .into_iter()
                .filter(|f| {
                    let fi = &self.funcs[*f as usize];
                    let (p, r) = (fi.params[0].ty, fi.ret);
                    self.fits(a, p)
                        && want.is_none_or(|w| r.is_some_and(|r| self.types.compatible(r, w)))
                })
                .collect();
            if !user.is_empty() {
                let args = [ast::Arg {
                    name: None,
                    value: a.clone(),
                    span: a.span,
                }];
                return match self.call(&user, &args, want, false, sp, op.symbol()) {
                    Some((f, args)) => {
                        let r = self.funcs[f as usize].ret.unwrap_or(ERROR);
                        self.mk(ExKind::Call(f, args.into()), r, sp)
                    }
                    None => self.err_ex(sp),
                };
            }
        }
        let t = match want {
            Some(w) if self.types.is_numeric(w) && self.fits(a, w) => w,
            _ => {
                let is = self.interps(a);
                is.iter()
                    .copied()
                    .find(|t| self.types.is_numeric(*t) && !self.types.is_universal(*t))
                    .or(is.first().copied())
                    .unwrap_or(ERROR)
            }
        };
        let x = self.expr(a, Some(t));
        if x.ty == ERROR {
            return x;
        }
        if !self.types.is_numeric(x.ty) {
            self.err(diagnostics::operator_needs_number(
                sp,
                op.symbol(),
                &self.tname(x.ty),
            ));
            return self.err_ex(sp);
        }
        let ty = if self.types.is_universal(x.ty) {
            x.ty
        } else {
            self.types.base(x.ty)
        };
        let x = if self.types.is_universal(x.ty) || self.shallow_static(&x).is_some() {
            // A static operand may be an intermediate outside the type
            // (`-(2 ** 31)`): the folded result is what must fit.
            Ex { ty, ..x }
        } else {
            self.coerce(x, ty)
        };
        let float = self.types.is_float(ty);
        let kind = match (op, float) {
            (UnOp::Plus, _) => return Ex { span: sp, ..x },
            (UnOp::Neg, false) => ExKind::IntNeg(bx(x)),
            (UnOp::Neg, true) => ExKind::FloatNeg(bx(x)),
            (UnOp::Abs, false) => ExKind::IntAbs(bx(x)),
            _ => ExKind::FloatAbs(bx(x)),
        };
        let e = self.mk(kind, ty, sp);
        self.fold(e)
    }

    /// Static choices of a `case`: per arm, the ranges; and the index of the
    /// `others` arm. Reports non-static, duplicate and missing choices.
    pub(super) fn case_choices(
        &mut self,
        t: TypeId,
        arms: &[&[Choice]],
        sp: Span,
    ) -> (Vec<Vec<(i64, i64)>>, Option<usize>) {
        if !self.types.is_discrete(t) && t != ERROR {
            self.err(diagnostics::case_needs_discrete(sp, &self.tname(t)));
        }
        let mut out = Vec::new();
        let mut others = None;
        let mut all: Vec<(i64, i64, Span)> = Vec::new();
        for (i, choices) in arms.iter().enumerate() {
            let mut rs = Vec::new();
            for c in choices.iter() {
                let (lo, hi, csp) = match c {
                    Choice::Others(s) => {
                        if i + 1 != arms.len() || choices.len() != 1 {
                            self.err(diagnostics::others_not_last(*s));
                        }
                        others = Some(i);
                        continue;
                    }
                    Choice::Expr(x) => {
                        if let Some(tt) = self.denote_quiet_type(x) {
                            match self.types.discrete_bounds(tt) {
                                Some((l, h)) => {
                                    (Some(Static::Int(l)), Some(Static::Int(h)), x.span)
                                }
                                None => (None, None, x.span),
                            }
                        } else {
                            let v = self.expr(x, Some(t));
                            let v = self.coerce_base(v, t);
                            let s = self.static_value(&v);
                            (s.clone(), s, x.span)
                        }
                    }
                    Choice::Range(l, h) => {
                        let l = self.expr(l, Some(t));
                        let l = self.coerce_base(l, t);
                        let h = self.expr(h, Some(t));
                        let h = self.coerce_base(h, t);
                        let sp2 = Span {
                            start: l.span.start,
                            end: h.span.end,
                            context: l.span.context,
                        };
                        (self.static_value(&l), self.static_value(&h), sp2)
                    }
                };
                match (lo, hi) {
                    (Some(Static::Int(l)), Some(Static::Int(h))) => {
                        // A choice outside the selector's static subtype
                        // (RM 5.4(7); GNAT: "minimum allowed choice value").
                        if l <= h
                            && t != ERROR
                            && let Some((lo, hi)) = self.types.discrete_bounds(t)
                            && (l < lo || h > hi)
                        {
                            let name = self.types.name(t);
                            let lits = self.types.enum_lits(t).map(|l| l.to_vec());
                            let show = |v: i128| match &lits {
                                Some(ls) if self.types.base(t) != CHARACTER => {
                                    ls.get(v as usize).cloned().unwrap_or_default()
                                }
                                _ => v.to_string(),
                            };
                            self.err(diagnostics::case_choice_outside(
                                csp,
                                name,
                                &show(lo),
                                &show(hi),
                            ));
                        }
                        let (l, h) = (l as i64, h as i64);
                        if l <= h {
                            if let Some(prev) = all.iter().find(|(a, b, _)| l <= *b && *a <= h) {
                                let prev_sp = prev.2;
                                self.err(diagnostics::case_choice_twice(csp, prev_sp));
                            }
                            all.push((l, h, csp));
                        }
                        rs.push((l, h));
                    }
                    _ => {
                        if t != ERROR {
                            self.err(diagnostics::case_choice_not_static(csp));
                        }
                    }
                }
            }
            out.push(rs);
        }
        if others.is_none() && t != ERROR && self.types.is_discrete(t) {
            match self.types.discrete_bounds(t) {
                Some((lo, hi)) => {
                    all.sort_by_key(|x| x.0);
                    let mut missing: Vec<(i128, i128)> = Vec::new();
                    let mut next = lo;
                    for (a, b, _) in &all {
                        if (*a as i128) > next {
                            missing.push((next, (*a as i128 - 1).min(hi)));
                        }
                        next = next.max(*b as i128 + 1);
                    }
                    if next <= hi {
                        missing.push((next, hi));
                    }
                    let missing: Vec<(i128, i128)> =
                        missing.into_iter().filter(|(a, b)| a <= b).collect();
                    if !missing.is_empty() {
                        let lits = self.types.enum_lits(t).map(|l| l.to_vec());
                        let show = |v: i128| match &lits {
                            Some(l) if self.types.base(t) != CHARACTER => {
                                l.get(v as usize).cloned().unwrap_or_default()
                            }
                            _ => v.to_string(),
                        };
                        let text: Vec<String> = missing
                            .iter()
                            .take(8)
                            .map(|(a, b)| {
                                if a == b {
                                    show(*a)
                                } else {
                                    format!("{} .. {}", show(*a), show(*b))
                                }
                            })
                            .collect();
                        self.err(diagnostics::case_missing(sp, self.types.name(t), &text));
                    }
                }
                None => self.err(diagnostics::case_needs_others(sp, self.types.name(t))),
            }
        }
        (out, others)
    }

    fn aggregate(&mut self, items: &[ast::Assoc], t: TypeId, sp: Span) -> Ex {
        if let Some(fields) = self.types.fields(t).map(|f| f.to_vec()) {
            let mut vals: Vec<Option<Ex>> = vec![None; fields.len()];
            let mut pos = 0;
            for it in items {
                if it.choices.is_empty() {
                    if pos >= fields.len() {
                        self.err(diagnostics::aggregate_too_many(
                            it.span,
                            self.types.name(t),
                            fields.len(),
                        ));
                        continue;
                    }
                    let v = self.expr(&it.value, Some(fields[pos].ty));
                    vals[pos] = Some(self.coerce(v, fields[pos].ty));
                    pos += 1;
                    continue;
                }
                for c in &it.choices {
                    let targets: Vec<usize> = match c {
                        Choice::Others(_) => {
                            (0..fields.len()).filter(|i| vals[*i].is_none()).collect()
                        }
                        Choice::Expr(ast::Expr {
                            kind: ExprKind::Name(n),
                            ..
                        }) => match fields.iter().position(|f| *f.key == *n.key) {
                            Some(i) => {
                                self.index_field_ref(n.span, t, i as u32);
                                vec![i]
                            }
                            None => {
                                self.err(diagnostics::aggregate_no_component(
                                    n.span,
                                    self.types.name(t),
                                    &n.name,
                                ));
                                vec![]
                            }
                        },
                        Choice::Expr(x) | Choice::Range(x, _) => {
                            self.err(diagnostics::record_aggregate_unnamed(x.span));
                            vec![]
                        }
                    };
                    for i in targets {
                        if matches!(it.value.kind, ExprKind::Error) {
                            // `Name => <>`: the component's default.
                            let ft = fields[i].ty;
                            vals[i] = Some(fields[i].default.clone().unwrap_or(Ex {
                                kind: ExKind::Default(ft),
                                ty: ft,
                                span: it.span,
                            }));
                            continue;
                        }
                        let v = self.expr(&it.value, Some(fields[i].ty));
                        vals[i] = Some(self.coerce(v, fields[i].ty));
                    }
                }
            }
            let mut out = Vec::new();
            for (i, v) in vals.into_iter().enumerate() {
                match v {
                    Some(v) => out.push(v),
                    None => {
                        self.err(diagnostics::aggregate_lacks(
                            sp,
                            &fields[i].name,
                            self.types.name(t),
                        ));
                        out.push(self.err_ex(sp));
                    }
                }
            }
            return self.mk(ExKind::RecordAgg(out.into()), t, sp);
        }
        let Some((idx, el, bounds)) = self
            .types
            .array(t)
            .map(|(i, e, b)| (i.to_vec(), e, b.cloned()))
        else {
            self.err(diagnostics::aggregate_wrong_type(sp, &self.tname(t)));
            return self.err_ex(sp);
        };
        // For several dimensions, components are rows of the remaining dimensions.
        let comp_ty = if idx.len() > 1 {
            let rest = TypeKind::Array {
                index: idx[1..].to_vec(),
                elem: el,
                bounds: bounds.as_ref().map(|b| b[1..].to_vec()),
            };
            let name = format!("{} row", self.types.name(t));
            self.types.add(&name, rest)
        } else {
            el
        };
        let mut positional = Vec::new();
        let mut named = Vec::new();
        let mut others = None;
        for it in items {
            // `Choice => <>` (parsed as an error value): the component's
            // default (RM 4.3.3(23.1)).
            let v = if matches!(it.value.kind, ExprKind::Error) && !it.choices.is_empty() {
                Ex {
                    kind: ExKind::Default(comp_ty),
                    ty: comp_ty,
                    span: it.span,
                }
            } else {
                let v = self.expr(&it.value, Some(comp_ty));
                self.coerce(v, comp_ty)
            };
            if it.choices.is_empty() {
                positional.push(v);
                continue;
            }
            let mut ranges = Vec::new();
            for c in &it.choices {
                match c {
                    Choice::Others(_) => others = Some(bx(v.clone())),
                    Choice::Expr(x) => {
                        if let Some(tt) = self.denote_quiet_type(x) {
                            ranges.push((
                                self.mk(ExKind::TypeFirst(tt), tt, x.span),
                                self.mk(ExKind::TypeLast(tt), tt, x.span),
                            ));
                        } else {
                            let i = self.expr(x, Some(idx[0]));
                            let i = self.coerce_base(i, idx[0]);
                            ranges.push((i.clone(), i));
                        }
                    }
                    Choice::Range(l, h) => {
                        let l = self.expr(l, Some(idx[0]));
                        let l = self.coerce_base(l, idx[0]);
                        let h = self.expr(h, Some(idx[0]));
                        let h = self.coerce_base(h, idx[0]);
                        ranges.push((l, h));
                    }
                }
            }
            if !ranges.is_empty() {
                named.push((ranges, v));
            }
        }
        if !positional.is_empty() && !named.is_empty() {
            self.err(diagnostics::aggregate_mixed(sp));
        }
        // RM 4.3.3(18): static choices never cover an index twice.
        let mut seen: Vec<(i128, i128, Span)> = Vec::new();
        for (ranges, _) in &named {
            for (l, h) in ranges {
                if let (Some(Static::Int(a)), Some(Static::Int(b))) =
                    (self.static_value(l), self.static_value(h))
                    && a <= b
                {
                    let span = Span {
                        start: l.span.start,
                        end: h.span.end.max(l.span.end),
                        context: l.span.context,
                    };
                    seen.push((a, b, span));
                }
            }
        }
        seen.sort_by_key(|x| (x.0, x.2.start));
        for w in seen.windows(2) {
            let ((_, prev_hi, prev_sp), (lo, _, sp2)) =
                ((w[0].0, w[0].1, w[0].2), (w[1].0, w[1].1, w[1].2));
            if lo <= prev_hi {
                let (first, second) = if prev_sp.start <= sp2.start {
                    (prev_sp, sp2)
                } else {
                    (sp2, prev_sp)
                };
                self.err(diagnostics::aggregate_choice_twice(second, first));
                break;
            }
        }
        if others.is_some() && bounds.is_none() {
            self.err(diagnostics::others_needs_bounds(sp, self.types.name(t)));
        }
        // A static length check for positional aggregates of constrained types.
        if let Some(b) = &bounds
            && others.is_none()
            && named.is_empty()
            && let (Some(Static::Int(l)), Some(Static::Int(h))) =
                (self.static_value(&b[0].0), self.static_value(&b[0].1))
        {
            let len = (h - l + 1).max(0) as usize;
            if positional.len() != len {
                self.err(diagnostics::aggregate_length(
                    sp,
                    self.types.name(t),
                    len,
                    positional.len(),
                ));
            }
        }
        let kind = if named.is_empty() {
            ArrayAggKind::Positional(positional, others)
        } else {
            ArrayAggKind::Named(named, others)
        };
        self.mk(ExKind::ArrayAgg(Box::new(ArrayAgg { ty: t, kind })), t, sp)
    }

    fn attribute(
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
            let base = self.types.base(t);
            let scalar = self.types.is_scalar(t);
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
                    if self.types.array(t).is_some_and(|x| x.2.is_some()) =>
                {
                    let d = dim(self) as usize;
                    let (idx, bounds) = self
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
                    let op = if self.types.is_float(t) {
                        AttrOp::ValueFloat
                    } else if self.types.is_integer(t) {
                        AttrOp::ValueInt
                    } else {
                        AttrOp::ValueEnum(base)
                    };
                    // 'Value yields the base type; only an assignment checks the subtype.
                    return self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                }
                "pos" if self.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(base));
                    return self.mk(ExKind::Attr(AttrOp::Pos, Box::new(vec![x])), UNIV_INT, sp);
                }
                "val" if self.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(UNIV_INT));
                    let x = if self.types.is_universal(x.ty) {
                        Ex { ty: INTEGER, ..x }
                    } else {
                        x
                    };
                    if !self.types.is_integer(x.ty) && x.ty != ERROR {
                        self.err(diagnostics::val_needs_integer(x.span));
                    }
                    // `S'Val` is a function of S's base type (RM 3.5.5): a
                    // position outside a subtype's range is no error.
                    if let (Some(Static::Int(v)), Some((l, h))) =
                        (self.static_value(&x), self.types.discrete_bounds(base))
                        && (v < l || v > h)
                    {
                        self.err(diagnostics::not_a_position(
                            x.span,
                            v,
                            self.types.name(base),
                            l,
                            h,
                        ));
                    }
                    let v = self.mk(ExKind::Attr(AttrOp::Val, Box::new(vec![x])), base, sp);
                    return self.coerce_force_check(v, base);
                }
                "succ" | "pred" if self.types.is_discrete(t) => {
                    let x = arg(self, 0, Some(base));
                    let op = if key == "succ" {
                        AttrOp::Succ
                    } else {
                        AttrOp::Pred
                    };
                    // Past the base type's end with a static argument: a
                    // compile-time error in GNAT too.
                    if let (Some(Static::Int(v)), Some((l, h))) =
                        (self.static_value(&x), self.types.discrete_bounds(base))
                        && ((op == AttrOp::Succ && v >= h) || (op == AttrOp::Pred && v <= l))
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
                            self.types.name(base),
                        ));
                    }
                    let v = self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                    return self.coerce_force_check(v, base);
                }
                "min" | "max" if scalar => {
                    let x = arg(self, 0, Some(base));
                    let y = arg(self, 1, Some(base));
                    let op = match (key, self.types.is_float(t)) {
                        ("min", false) => AttrOp::Min,
                        ("max", false) => AttrOp::Max,
                        ("min", true) => AttrOp::FloatMin,
                        _ => AttrOp::FloatMax,
                    };
                    return self.mk(ExKind::Attr(op, Box::new(vec![x, y])), base, sp);
                }
                "floor" | "ceiling" | "truncation" | "rounding" if self.types.is_float(t) => {
                    let x = arg(self, 0, Some(base));
                    let op = match key {
                        "floor" => AttrOp::Floor,
                        "ceiling" => AttrOp::Ceiling,
                        "truncation" => AttrOp::Truncation,
                        _ => AttrOp::Rounding,
                    };
                    return self.mk(ExKind::Attr(op, Box::new(vec![x])), base, sp);
                }
                "digits" if self.types.is_float(t) => {
                    return self.mk(ExKind::Int(self.types.digits(t) as i64), UNIV_INT, sp);
                }
                "range" => {
                    self.err(diagnostics::range_outside_range_context(sp));
                    return self.err_ex(sp);
                }
                _ => {
                    self.err(diagnostics::attribute_unsupported_for_type(
                        a.span,
                        &a.name,
                        self.types.name(t),
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
        if let Some(d) = self.types.designated(pe.ty)
            && self.types.is_array(d)
        {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), d, psp);
        }
        if let Some((idx, _, _)) = self
            .types
            .array(pe.ty)
            .map(|(i, e, b)| (i.to_vec(), e, b.is_some()))
        {
            let d = dim(self);
            if d as usize > idx.len() {
                self.err(diagnostics::too_few_dimensions(
                    sp,
                    self.types.name(pe.ty),
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
        if key == "image" && self.types.is_scalar(pe.ty) {
            let t = if self.types.is_universal(pe.ty) {
                if self.types.is_float(pe.ty) {
                    FLOAT
                } else {
                    INTEGER
                }
            } else {
                self.types.base(pe.ty)
            };
            return self.image(pe, t, sp);
        }
        let _ = want;
        self.err(diagnostics::attribute_unsupported_here(a.span, &a.name));
        self.err_ex(sp)
    }

    fn coerce_force_check(&mut self, v: Ex, t: TypeId) -> Ex {
        let sp = v.span;
        if self.types.get(t).range.is_some() || self.types.enum_lits(t).is_some() {
            self.mk(ExKind::RangeCheck(bx(v), t), t, sp)
        } else {
            v
        }
    }

    fn image(&mut self, x: Ex, t: TypeId, sp: Span) -> Ex {
        let op = if self.types.base(t) == DURATION {
            AttrOp::ImageDuration
        } else if self.types.is_float(t) {
            AttrOp::ImageFloat(self.types.digits(t) as u8)
        } else if self.types.is_integer(t) {
            AttrOp::ImageInt
        } else if self.types.base(t) == CHARACTER {
            AttrOp::ImageChar
        } else {
            AttrOp::ImageEnum(self.types.base(t))
        };
        self.mk(ExKind::Attr(op, Box::new(vec![x])), STRING, sp)
    }

    /// `X'Range` and `T'Range` as a discrete range.
    pub(super) fn range_attr(
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
            if self.types.is_scalar(t) {
                return (
                    self.mk(ExKind::TypeFirst(t), t, sp),
                    self.mk(ExKind::TypeLast(t), t, sp),
                    t,
                );
            }
            if let Some((idx, _, Some(b))) = self
                .types
                .array(t)
                .map(|(i, e, b)| (i.to_vec(), e, b.cloned()))
                && let Some((l, h)) = b.get(d as usize - 1)
            {
                return (l.clone(), h.clone(), idx[d as usize - 1]);
            }
            self.err(diagnostics::range_needs_scalar_or_array(
                sp,
                self.types.name(t),
            ));
            return (self.err_ex(sp), self.err_ex(sp), ERROR);
        }
        let mut pe = self.expr(p, None);
        if let Some(dt) = self.types.designated(pe.ty) {
            let psp = pe.span;
            pe = self.mk(ExKind::Deref(bx(pe)), dt, psp);
        }
        match self.types.array(pe.ty).map(|(i, _, _)| i.to_vec()) {
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

impl Checker {
    /// The base range of a floating point type (RM 3.5.7): single precision
    /// up to 6 digits, as GNAT; `Duration`'s own.
    fn float_base_range(&self, t: TypeId) -> Option<(f64, f64)> {
        let base = self.types.base(t);
        if base == DURATION {
            return self.types.get(base).static_frange;
        }
        let max = if self.types.digits(t) <= 6 {
            f32::MAX as f64
        } else {
            f64::MAX
        };
        Some((-max, max))
    }

    /// A call of a service that only the simulator has, when the program
    /// is meant for a real arm too (`simulator_only`): it would raise
    /// `CommandNotSupported` there, and in the rehearsal for it.
    fn warn_simulator_only(&mut self, f: FuncId, span: Span) {
        let Some(Some(import)) = self.imports.get(f as usize) else {
            return;
        };
        if !self.simulator_only.contains(&import.as_str()) {
            return;
        }
        let name = self.funcs[f as usize].name.clone();
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
        let name = self.funcs[f as usize].name.to_ascii_lowercase();
        let angles: Vec<&ast::Expr> = if ["rotx", "roty", "rotz"].contains(&name.as_str()) {
            vec![actual]
        } else if self.types.name(formal).eq_ignore_ascii_case("AxesVector") {
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
