//! Tests of the services through whole programs: the service core,
//! gripper and ValidFrame scripts, every float argument refused, random
//! service calls, saves that keep the old file, the exceptions bound, the
//! path memory full; and a robot description read from a file. They build
//! a `Session`, the layer above the services (tests/layering.rs), so they
//! are an integration test (`cargo test --test services`); the services'
//! unit tests (`src/services/tests/`) need none. The first pass of a
//! mutation run over `src/services/` (`scripts/mutants.sh`) runs both.

mod bad_floats;
mod exceptions;
mod file_kinds;
mod gripper;
mod lazy_robot;
mod path_memory;
mod props;
mod realtime;
mod record_table;
mod robot_file;
mod save_keeps_file;
mod scripts;
mod service_core;
mod teachbox;

/// A session driving the simulated RV-M1.
fn rv_m1_session() -> adair::session::Session {
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    s.set_robot(
        adair::kinematics::RobotDescription::builtin("rv-m1").unwrap(),
        None,
        false,
    );
    s
}
