//! The program's setting of the safety checks: the hardware limit switch check (the
//! checks themselves are the core's `engine::safety`, run by the tick).

use super::Shared;
use std::sync::atomic::Ordering;

impl Shared {
    /// Turns the hardware limit switch check on in `mode` (see
    /// [`crate::engine::safety::limit_check_mode`]) or,
    /// with `None`, off.
    pub fn set_limit_check(&self, mode: Option<i32>) {
        self.outputs
            .limit_check
            .store(mode.unwrap_or(-1), Ordering::Release);
    }

    /// The hardware limit switch check's mode, −1 when off.
    pub(in crate::engine) fn limit_check(&self) -> i32 {
        self.outputs.limit_check.load(Ordering::Relaxed)
    }
}
