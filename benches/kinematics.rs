//! Kinematics benchmarks: FK, IK (all branches), a 1 m straight line at
//! 0.1 mm spacing. Run with `cargo bench --bench kinematics`.

use std::hint::black_box;

use adair::kinematics::{Kinematics, Pose, RobotDescription, joints_from_deg};
use criterion::{Criterion, criterion_group, criterion_main};

fn benches(c: &mut Criterion) {
    let k = Kinematics::new(RobotDescription::builtin("rv-m1").unwrap());
    let tool = k.standard_tool();
    let q = joints_from_deg([20.0, 30.0, 60.0, 20.0, 45.0]);
    let goal = k.fk_tcp(&q, &tool);

    c.bench_function("fk_tcp", |b| {
        b.iter(|| k.fk_tcp(black_box(&q), black_box(&tool)))
    });
    c.bench_function("ik_all", |b| {
        b.iter(|| k.ik_all(black_box(&goal), black_box(&tool), black_box(&q)))
    });

    // A 1 m line across the workspace (found by a seeded random search),
    // turning 166 deg on the way.
    let from = [
        -1.8147111035561387,
        0.9988806455274518,
        0.16790116455599968,
        0.15130968965554703,
        0.3753630771170644,
    ];
    let end = Pose::from_rows([
        [
            -0.10053765179716685,
            0.3616196803662003,
            0.9268890911770185,
            521.2680882314384,
        ],
        [
            0.4708465191294069,
            -0.8033906527155815,
            0.36450927910404884,
            204.99438052497214,
        ],
        [
            0.8764677609557772,
            0.47306940917911755,
            -0.08949635804929636,
            298.13232182040827,
        ],
    ]);
    let length = (end.translation - k.fk_tcp(&from, &tool).translation).norm();
    assert!((length - 1000.0).abs() < 1e-6);
    let points = k.straight_line(&from, &end, &tool, 0.1).unwrap();
    assert_eq!(points.len(), 10_000);
    c.bench_function("straight_line_1m_0.1mm", |b| {
        b.iter(|| k.straight_line(black_box(&from), black_box(&end), black_box(&tool), 0.1))
    });
}

criterion_group!(kinematics, benches);
criterion_main!(kinematics);
