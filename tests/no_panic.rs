//! The lexer, parser and checker never panic, whatever the input.

use proptest::prelude::*;

fn check(src: &str) {
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let _ = s.check_source("fuzz.air", src, false);
}

/// Fragments of AdaIR, so that random programs get past the lexer often.
const WORDS: &[&str] = &[
    "procedure",
    "P",
    "is",
    "begin",
    "end",
    ";",
    "X",
    ":",
    "Integer",
    ":=",
    "1",
    "2.0",
    "+",
    "-",
    "*",
    "(",
    ")",
    ",",
    "if",
    "then",
    "else",
    "loop",
    "for",
    "in",
    "..",
    "'",
    "First",
    "type",
    "T",
    "record",
    "array",
    "of",
    "case",
    "when",
    "=>",
    "others",
    "\"s\"",
    "'c'",
    "function",
    "return",
    "declare",
    "exception",
    "raise",
    "null",
    "new",
    "access",
    "all",
    ".",
    "package",
    "body",
    "with",
    "use",
    "Put_Line",
    "16#FF#",
    "&",
    "and",
    "or",
    "not",
    "mod",
    "**",
    "|",
    "<>",
    "range",
    "subtype",
    "Float",
    "exit",
    "while",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text(s in "\\PC{0,200}") {
        check(&s);
    }

    #[test]
    fn token_soup(words in proptest::collection::vec(0..WORDS.len(), 0..80)) {
        let src: Vec<&str> = words.iter().map(|i| WORDS[*i]).collect();
        check(&src.join(" "));
    }

    #[test]
    fn mutated_programs(cut in 0usize..400, insert in 0..WORDS.len()) {
        let base = "with Ada.Text_IO; use Ada.Text_IO;\nprocedure Demo is\n   type V is array (1 .. 3) of Float;\n   A : V := (1.0, 2.0, 3.0);\n   function F (X : Integer) return Integer is\n   begin\n      return X * 2;\n   end F;\nbegin\n   for I in A'Range loop\n      Put_Line (Float'Image (A (I)) & Integer'Image (F (I)));\n   end loop;\nend Demo;\n";
        let cut = cut.min(base.len());
        let cut = (0..=cut).rev().find(|i| base.is_char_boundary(*i)).unwrap_or(0);
        let src = format!("{} {} {}", &base[..cut], WORDS[insert], &base[cut..]);
        check(&src);
    }
}
