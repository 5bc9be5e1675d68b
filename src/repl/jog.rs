//! `:jog`: one quick jog from the REPL (`:jog J1 +10`, `:jog z -5`), through
//! the same service code as the TeachBox's keys (`services::jog`: limits,
//! speed, driver, clock, recording, trace and the live view).

use super::{Repl, Reply};
use crate::kinematics::{deg, rad};

pub(super) const USAGE: &str = ":jog J1..J5 DEG, or :jog x|y|z MM, or :jog pitch|roll DEG (at the TCP): e.g. :jog J1 +10, :jog z -5\n";

/// What a `:jog` names: a joint (0..4) or a Cartesian axis at the TCP
/// (0..2: x, y, z; 3: pitch; 4: roll), and the amount.
#[derive(Debug, PartialEq)]
enum Jog {
    Joint(usize, f64),
    Cartesian(usize, f64),
}

fn parse(args: &str) -> Result<Jog, String> {
    let mut words = args.split_whitespace();
    let (Some(what), Some(amount), None) = (words.next(), words.next(), words.next()) else {
        return Err(USAGE.into());
    };
    let amount: f64 = amount
        .parse()
        .ok()
        .filter(|a: &f64| a.is_finite())
        .ok_or_else(|| format!(":jog {what} {amount}: the amount must be a number\n{USAGE}"))?;
    let w = what.to_ascii_lowercase();
    let axis = ["x", "y", "z", "pitch", "roll"]
        .iter()
        .position(|a| *a == w);
    match (
        w.strip_prefix('j').and_then(|n| n.parse::<usize>().ok()),
        axis,
    ) {
        (Some(n @ 1..=5), _) => Ok(Jog::Joint(n - 1, amount)),
        (_, Some(a)) => Ok(Jog::Cartesian(a, amount)),
        _ => Err(format!(":jog {what}: no such joint or axis\n{USAGE}")),
    }
}

impl Repl {
    /// `:jog ARGS`: the arm's pose afterwards, or why the jog was refused
    /// (the arm then stays where it was).
    pub(super) fn jog_command(&mut self, args: &str) -> Reply {
        let fail = |text: String| Reply {
            text,
            failed: true,
            quit: false,
        };
        let jog = match parse(args) {
            Ok(j) => j,
            Err(e) => return fail(e),
        };
        let session = &mut self.session;
        let Some(st) = session.robot.as_mut() else {
            return fail(":jog: no robot\n".into());
        };
        if !st.initialized {
            return fail(":jog: the robot is not initialized: run `InitRobot;` first\n".into());
        }
        if let Err(e) = crate::services::fresh_pose(st) {
            return fail(format!(":jog: cannot read the arm's pose: {e}\n"));
        }
        let target = match jog {
            Jog::Joint(j, amount) => {
                let mut q = st.robot.joints();
                let now = deg(q[j]);
                q[j] += rad(amount);
                let spec = &st.kin.description().joints()[j];
                if !spec.contains(q[j]) {
                    let (which, limit, left) = super::teach::limit_ahead(amount, now, spec);
                    return fail(format!(
                        ":jog J{} {amount:+}: refused, it would pass the {which} limit {limit:.1} deg ({left:.1} deg left); the arm did not move\n",
                        j + 1
                    ));
                }
                q
            }
            Jog::Cartesian(axis, amount) => {
                match crate::repl::teach::cartesian_target(st, axis, amount) {
                    Ok(q) => q,
                    Err(e) => {
                        return fail(format!(":jog {args}: refused: {e}; the arm did not move\n"));
                    }
                }
            }
        };
        if let Err(e) = crate::services::jog(st, &mut *session.machine.clock, target) {
            return fail(format!(":jog {args}: refused: {e}; the arm did not move\n"));
        }
        Reply {
            text: self.where_text(),
            ..Reply::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Jog, parse};

    #[test]
    fn jogs_are_read_as_joints_or_axes() {
        assert_eq!(parse("J1 +10"), Ok(Jog::Joint(0, 10.0)));
        assert_eq!(parse("j5 -2.5"), Ok(Jog::Joint(4, -2.5)));
        assert_eq!(parse("z -5"), Ok(Jog::Cartesian(2, -5.0)));
        assert_eq!(parse("Roll 15"), Ok(Jog::Cartesian(4, 15.0)));
        for bad in [
            "", "J1", "J6 10", "J0 1", "w 3", "J1 nan", "J1 inf", "J1 10 20", "x ten",
        ] {
            assert!(parse(bad).is_err(), "{bad:?}");
        }
    }
}
