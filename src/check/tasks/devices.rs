//! Address clauses (a name becomes a device register) and pragmas.

use super::*;

impl Checker {
    /// `for X use at Addr;` outside a task spec: `X` becomes a device
    /// register.
    pub(in crate::check) fn address_clause(
        &mut self,
        name: &ast::Ident,
        address: &ast::Expr,
        span: Span,
    ) {
        let Some(addr) = self.static_int(address, "an address") else {
            return;
        };
        let here = crate::devices::ada_address(addr as u32);
        let Some((dev, role)) = u32::try_from(addr)
            .ok()
            .and_then(|a| self.devices.lookup(a))
        else {
            self.err(self.no_device(address.span, addr));
            return;
        };
        let dname = self.devices.devices()[dev].name.clone();
        if role == crate::devices::Role::Interrupt {
            self.err(diagnostics::object_at_interrupt(
                address.span,
                &here,
                &dname,
            ));
            return;
        }
        let Some(Entity::Var { ty, var, .. }) = self
            .scopes
            .innermost()
            .and_then(|s| s.names.get(&*name.key))
            .and_then(|es| es.last().cloned())
        else {
            self.err(diagnostics::address_clause_not_object(
                name.span, &name.name,
            ));
            return;
        };
        // Bits 0 .. 15 of the register, as the handbook's `t_16_bit`.
        let bits = self.tables.types.array(ty).is_some_and(|(ix, elem, bounds)| {
            let b = bounds.and_then(|b| b.first()).cloned();
            ix.len() == 1 && self.tables.types.base(elem) == BOOLEAN && b.is_some_and(|(lo, hi)| {
                matches!(
                    (self.static_value(&lo), self.static_value(&hi)),
                    (Some(Static::Int(l)), Some(Static::Int(h))) if l == 0.into() && h == 15.into()
                )
            })
        });
        if !self.tables.types.is_integer(ty) && !bits {
            self.err(diagnostics::register_type(span, &name.name));
            return;
        }
        // The device reads and writes it: no "never read" warning.
        for frame in &mut self.unread {
            frame.remove(&var);
        }
        let reg = Entity::Alias(Box::new(Ex {
            kind: ExKind::Register(addr as u32),
            ty,
            span: name.span,
        }));
        self.redeclare(&name.key, reg);
    }

    /// "no device at ADDR" naming the device file and its addresses.
    pub(super) fn no_device(&self, sp: Span, addr: i64) -> Diagnostic {
        // Written whole (an address beyond 32 bits is not cut).
        let here = if addr >= 0 {
            format!("8#{addr:o}#")
        } else {
            addr.to_string()
        };
        let known: Vec<String> = self
            .devices
            .addresses()
            .map(|(a, d, r)| {
                format!(
                    "{} ({} of `{}`)",
                    crate::devices::ada_address(a),
                    r.describe(),
                    self.devices.devices()[d].name
                )
            })
            .collect();
        let mut d = diagnostics::no_device_at(sp, &here, self.devices.source());
        let default = *self.devices == crate::devices::Devices::default_set();
        d = if known.is_empty() {
            d.with_hint("the device file declares no devices: give one with `--devices FILE.toml`")
        } else if default {
            d.with_hint(format!(
                "the addresses there: {}; a program for other devices runs with their file: `adair run --devices FILE.toml ...`",
                known.join(", ")
            ))
        } else {
            d.with_hint(format!("the addresses there: {}", known.join(", ")))
        };
        d
    }

    pub(in crate::check) fn pragma(&mut self, _name: &ast::Ident, _span: Span) {}
}
