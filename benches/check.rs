//! The checker on its two pathological inputs (issue 11): a 10,000-term
//! `1 - 1 - ...` and `F * F * ... * F` (22 factors) with two user `"*"`
//! overloads. Both were quadratic or exponential before the checker
//! memoised what each operand can mean.

use criterion::{Criterion, criterion_group};

fn minus() -> String {
    let terms = vec!["1"; 10_000].join(" - ");
    format!(
        "with Ada.Text_IO; use Ada.Text_IO;\nprocedure Minus is\n   X : constant Integer := {terms};\nbegin\n   Put_Line (Integer'Image (X));\nend Minus;\n"
    )
}

fn star() -> String {
    let factors = vec!["F"; 22].join(" * ");
    format!(
        "procedure Star is
   type V is record A : Integer; end record;
   type W is record B : Integer; end record;
   function \"*\" (L, R : V) return V is begin return (A => L.A + R.A); end \"*\";
   function \"*\" (L, R : W) return W is begin return (B => L.B * R.B); end \"*\";
   F : constant V := (A => 1);
   X : V;
begin
   X := {factors};
end Star;
"
    )
}

fn check(text: &str) {
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    assert!(s.check_source("bench.adb", text, false).is_ok());
}

fn pathological(c: &mut Criterion) {
    let mut g = c.benchmark_group("check");
    g.sample_size(10);
    let (m, s) = (minus(), star());
    g.bench_function("minus_10000", |b| b.iter(|| check(&m)));
    g.bench_function("star_22", |b| b.iter(|| check(&s)));
    g.finish();
}

criterion_group!(benches, pathological);

/// As `adair` does (`main.rs`), the work runs on a thread with a 512 MiB
/// stack: the checker recurses once per operand of the 10,000-term chain,
/// deeper than a main thread's 8 MiB (criterion_main! ran it there and
/// overflowed).
fn main() {
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(|| {
            benches();
            Criterion::default().configure_from_args().final_summary();
        })
        .expect("a thread for the benchmarks")
        .join()
        .expect("the benchmarks");
}
