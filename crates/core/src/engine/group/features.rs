//! What a program attaches to a group beyond plain motion, each `None` (or empty) until
//! it is used, so that a plain group carries none of it.

use super::{custom, kinematics, post, ExternalExecutor};

/// An external executor, the after-interpolation filters, kinematics, custom motion.
#[derive(Debug, Default)]
pub(super) struct Features {
    /// Set when the group's commands run outside the card (an MC3B: `external.rs`).
    pub(super) external: Option<Box<dyn ExternalExecutor>>,
    /// After-interpolation filters and reverse interpolation (`post.rs`); `None` until
    /// the program uses one.
    pub(super) post: Option<Box<post::Post>>,
    /// Robot kinematics (`MCC_SetKinematicTrans`, `kinematics.rs`): the channels carry
    /// joints, the commands and positions are Cartesian.
    pub(super) kin: Option<Box<kinematics::Kinematics>>,
    /// Custom commands started and not cleaned up yet (`custom.rs`).
    pub(super) custom: custom::CustomSide,
}
