#[cfg(test)]
mod size_tests {
    /// A long program's main body is one compiled code (issue 14): an
    /// instruction of 48 bytes, not 64 (a call keeps its result slot among
    /// its operands).
    #[test]
    fn instructions_stay_small() {
        let op = std::mem::size_of::<super::super::Op>();
        assert!(op <= 48, "{op}");
    }
}

#[cfg(test)]
mod fused_tests {
    use super::super::{Compiler, Op};

    /// The instructions of the body of `name` in `src` (checked by a bare
    /// checker, without the stdlib, and read as the engine reads a
    /// program: not run). The tests of whole runs are in tests/engine.rs.
    fn ops_of(src: &str, name: &str) -> Vec<String> {
        let checked = crate::check::checked_for_tests(src);
        let prog = checked.program();
        let f = prog
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
            .expect("the function");
        let body = f.body.as_deref().expect("its body");
        let walker_calls = |_| false;
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &walker_calls, prog.types);
        c.body(body);
        let code = c.finish(None, true, true);
        code.ops
            .iter()
            .map(|op| match op {
                Op::CallK { .. } => "CallK".to_string(),
                Op::ReturnIntBin(..) => "ReturnIntBin".to_string(),
                Op::Call(..) => "Call".to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    /// `F (N - 1)` and `return X + Y` are one instruction each; an
    /// argument of a constrained subtype (a range check) or a literal
    /// argument is not fused.
    #[test]
    fn a_call_of_x_op_k_and_a_return_of_x_op_y_are_one_instruction() {
        let src = "procedure P is\n\
               function F (N : Integer) return Integer is\n\
               begin\n   if N < 2 then return N; end if;\n   return F (N - 1) + F (N - 2);\nend F;\n\
               function G (N : Natural) return Integer is\n\
               begin\n   if N = 0 then return 0; end if;\n   return G (N - 1) * 2 + F (3);\nend G;\n\
            begin\n   null;\nend P;\n";
        let f = ops_of(src, "F");
        assert_eq!(f.iter().filter(|o| *o == "CallK").count(), 2, "{f:?}");
        assert_eq!(
            f.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{f:?}"
        );
        assert!(
            !f.iter().any(|o| o == "Call" || o.starts_with("IntBin")),
            "{f:?}"
        );
        // `G (N - 1)` converts to Natural (a range check): a plain call;
        // `... * 2 + F (3)` returns `IntBin` of a temporary and a call.
        let g = ops_of(src, "G");
        assert!(!g.iter().any(|o| o == "CallK"), "{g:?}");
        assert_eq!(g.iter().filter(|o| *o == "Call").count(), 2, "{g:?}");
        assert_eq!(
            g.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{g:?}"
        );
    }
}
