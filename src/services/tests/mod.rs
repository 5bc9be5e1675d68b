//! Tests of the services: the service core, gripper and ValidFrame
//! scripts, every float argument refused, random service calls, saves that
//! keep the old file. Unit tests of the library (not integration tests) so
//! that `cargo test --lib` covers `src/services/`, which keeps a mutation run
//! (`scripts/mutants.sh`) to one test binary.

mod bad_floats;
mod file_kinds;
mod gripper;
mod path_memory;
mod props;
mod realtime;
mod record_table;
mod save_keeps_file;
mod scripts;
mod service_core;
mod teachbox;

/// A session driving the simulated RV-M1.
fn rv_m1_session() -> crate::session::Session {
    let mut s = crate::session::Session::new(Box::new(std::io::sink()));
    s.set_robot(
        crate::kinematics::RobotDescription::builtin("rv-m1").unwrap(),
        None,
        false,
    );
    s
}
