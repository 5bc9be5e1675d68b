//! No service call panics or escapes the simulated robot's limits: random
#![allow(clippy::print_stderr)]
//! sequences of service calls with random arguments either work or raise an
//! Ada exception (AdaIR's own, or Constraint_Error from a parameter subtype),
//! and a call that raises leaves the joints exactly where they were.

use adair::kinematics::RobotDescription;
use adair::session::Session;
use proptest::prelude::*;

fn f(x: f64) -> String {
    format!("{x:.3}")
}

fn frame(v: &[f64]) -> String {
    // A random rotation (from three angles) and position, or a raw matrix.
    if v[12] > 0.0 {
        format!(
            "RotZ ({}) * RotY ({}) * RotX ({}) * Identity",
            f(v[0]),
            f(v[1]),
            f(v[2])
        )
        .replace(
            "* Identity",
            &format!(
                "* Trans ({}, {}, {})",
                f(v[3] * 600.0),
                f(v[4] * 600.0),
                f(v[5] * 900.0)
            ),
        )
    } else {
        let n: Vec<String> = v[..12].iter().map(|x| f(x * 400.0)).collect();
        format!(
            "(({}, {}, {}, {}), ({}, {}, {}, {}), ({}, {}, {}, {}))",
            n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7], n[8], n[9], n[10], n[11]
        )
    }
}

fn call(kind: u8, v: &[f64]) -> String {
    let axes = format!(
        "({}, {}, {}, {}, {})",
        f(v[0] * 8.0),
        f(v[1] * 3.0),
        f(v[2] * 3.0),
        f(v[3] * 3.0),
        f(v[4] * 8.0)
    );
    let p = (v[5].abs() * 3.0) as i64 + 1;
    let n = (v[6].abs() * 4.0) as i64 + 1;
    match kind % 17 {
        0 => format!("MoveAxesAbsolute ({axes});"),
        1 => format!("MoveAxesRelative ({axes});"),
        2 => format!("MoveFrameAbsolute ({});", frame(v)),
        3 => format!("MoveFrameRelative ({});", frame(v)),
        4 => format!("SetVelocity ({});", f(v[7].abs() * 120.0)),
        5 => format!(
            "SetMoveMode ({});",
            if v[8] > 0.0 {
                "StraightLine"
            } else {
                "JointInterpolated"
            }
        ),
        6 => format!("SetInterpolation ({});", f(v[9].abs() * 50.0 + 0.05)),
        7 => format!("CreatePath ({p});"),
        8 => format!("InsertPosition ({p}, {n}, {});", frame(v)),
        9 => format!("DeletePosition ({p}, {n});"),
        10 => format!("MovePath ({p});"),
        11 => format!(
            "MoveTool ({}, {});",
            f(v[10].abs() * 80.0),
            f(v[11].abs() * 40.0)
        ),
        12 => format!(
            "declare F : Frame := {}; begin ValidFrame (F); MoveFrameAbsolute (F); end;",
            frame(v)
        ),
        13 => format!("SetBase ({});", frame(v)),
        14 => format!(
            "MoveAxesAbsolute ({axes}, Time => {});",
            f(v[7].abs() * 3.0)
        ),
        15 => format!("DeletePath ({p});"),
        _ => {
            "declare A : AxesVector := ValueAxes; F : Frame := ValueFrameAbsolute; begin null; end;"
                .to_string()
        }
    }
}

fn run(calls: &[(u8, Vec<f64>)], robot: &str) -> Result<(), TestCaseError> {
    let mut src = String::from("InitRobot;\n");
    for (k, v) in calls {
        src.push_str(&format!(
            "declare\n   Before : constant AxesVector := ValueAxes;\nbegin\n   {}\nexception\n   when E : others =>\n      \
             if ValueAxes /= Before then Put_Line (\"MOVED by a refused call\"); end if;\n      \
             Put_Line (Ada.Exceptions.Exception_Name (E));\nend;\n",
            call(*k, v)
        ));
    }
    let buf = adair::golden::SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    s.set_robot(
        RobotDescription::builtin(robot).expect("robot"),
        None,
        false,
    );
    let outcome = s.run_source("props.air", &src);
    let out = buf.take();
    if std::env::var_os("PROPS_SHOW").is_some() {
        eprintln!("{src}\n=> {out}");
    }
    prop_assert_eq!(
        outcome.exit_code(),
        0,
        "script failed: {:?}\n{}\n{}",
        outcome,
        src,
        out
    );
    for line in out.lines() {
        prop_assert!(
            line.starts_with("ADAIR.") || line == "CONSTRAINT_ERROR",
            "unexpected exception {} in\n{}",
            line,
            src
        );
    }
    let state = s.robot_state().expect("robot state");
    let q = state.robot.joints();
    prop_assert!(
        state.kin.description().check_limits(&q).is_ok(),
        "joints out of limits: {:?}",
        q
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn random_services_rv_m1(calls in proptest::collection::vec((any::<u8>(), proptest::collection::vec(-1.0f64..1.0, 13)), 1..24)) {
        run(&calls, "rv-m1")?;
    }

    #[test]
    fn random_services_rm_501(calls in proptest::collection::vec((any::<u8>(), proptest::collection::vec(-1.0f64..1.0, 13)), 1..24)) {
        run(&calls, "rm-501")?;
    }
}
