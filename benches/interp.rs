//! The interpreter on the benchmark programs of `bench/programs`
//! (recursive fib (27), 200,000 4x4 matrix products, a 100,000-node list,
//! a 100,000-record list with 4-character tags, 200,000 labels made and
//! read back as strings,
//! 10,000 joint moves on the simulator, 10,000 rendezvous between two tasks,
//! 1,000 tasks created and finished).
//! `bench/compare.sh` runs the same programs in CPython, Lua and GNAT.

use criterion::{Criterion, criterion_group, criterion_main};

fn run(path: &str) {
    let text = std::fs::read_to_string(path).expect("bench program");
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    // `adair run`'s default robot (moves.air drives it).
    let rv_m1 = adair::kinematics::RobotDescription::builtin("rv-m1").expect("the RV-M1");
    s.set_robot(rv_m1, None, false);
    let outcome = s.run_source(path, &text);
    assert_eq!(outcome.exit_code(), 0, "{path}: {outcome:?}");
}

fn programs(c: &mut Criterion) {
    let mut g = c.benchmark_group("interp");
    g.sample_size(10);
    for p in [
        "fib.adb",
        "matrix.adb",
        "list.adb",
        "records.adb",
        "strings.adb",
        "moves.air",
        "rendezvous.adb",
        "tasks1000.adb",
    ] {
        let path = format!("{}/bench/programs/{p}", env!("CARGO_MANIFEST_DIR"));
        g.bench_function(p, |b| b.iter(|| run(&path)));
    }
    g.finish();
}

criterion_group!(benches, programs);
criterion_main!(benches);
