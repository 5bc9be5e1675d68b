//! The device file and the device world. The two example files are the
//! ones of tasks.md, byte for byte (`examples/devices/`).

mod file;
mod props;
mod world;

use super::*;

const PARALLEL: &str = include_str!("../../../examples/devices/parallel.toml");
const CELL: &str = include_str!("../../../examples/devices/cell.toml");

fn parse(text: &str) -> Devices {
    Devices::from_toml(text, "test.toml").unwrap_or_else(|e| panic!("{e}"))
}

fn world(text: &str) -> World {
    World::new(parse(text))
}

/// The cell of tasks.md with the belt's motor switched on at time 0.
fn running_cell() -> World {
    let mut w = world(CELL);
    w.write(0o350, 1).unwrap();
    w
}

fn position(w: &World, name: &str) -> Place {
    w.objects()
        .into_iter()
        .find(|o| o.name == name)
        .unwrap_or_else(|| panic!("no object {name}"))
        .place
}

fn on_belt(w: &World, name: &str) -> (f64, bool) {
    match position(w, name) {
        Place::OnBelt {
            position, at_end, ..
        } => (position, at_end),
        other => panic!("{name} is not on a belt: {other:?}"),
    }
}

const PARALLEL_ONLY: &str = r#"
[[device]]
name = "parallel"
kind = "parallel"
interrupt = 0o340
input = 0o342
output = 0o344
control = 0o346
"#;

const TWO_BOXES: &str = r#"
[[event]]
at = 1.0
device = "belt"
object = { name = "box2", width = 20.0 }

[[event]]
at = 1.0
device = "belt"
object = { name = "box3", width = 10.0 }
"#;
