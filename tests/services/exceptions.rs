//! The exceptions the services raise, bound to the stdlib's declarations.

use adair::services::{Exc, ExcIds};
use adair::session::Session;

#[test]
fn every_exception_is_bound_to_its_own_identity() {
    let mut s = Session::new(Box::new(std::io::sink()));
    assert!(s.need_package("AdaIR"));
    let ids = ExcIds::bind(&s.front.checker).expect("stdlib declares them all");
    for (i, a) in Exc::ALL.iter().enumerate() {
        assert_eq!(
            s.front.checker.tables.excs[ids.id(*a) as usize].name,
            a.full_name()
        );
        for b in &Exc::ALL[i + 1..] {
            assert_ne!(ids.id(*a), ids.id(*b));
        }
    }
}
