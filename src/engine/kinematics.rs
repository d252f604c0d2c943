//! The kinematics registrations waiting for the next init (`MCC_SetKinematicTrans`
//! registers them before the card starts; the init applies them). What a kinematic group
//! does with them, and how, is the core's [`mccl_core::engine::kinematics`] (re-exported
//! here) and [`crate::engine::group::kinematics`].

pub use mccl_core::engine::kinematics::*;

use crate::config::GROUPS;
use crate::error::{McclError, McclResult};
use parking_lot::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};

/// The registrations made since the last init, per group index.
static REGISTERED: Mutex<[Option<Registration>; GROUPS]> = Mutex::new([None; GROUPS]);

/// Registers kinematics for group `group` (replacing an earlier registration of it);
/// they take effect at the next init. `PARAMETER_ERR` for NULL callbacks or an extension
/// over [`MAX_EXTENSION_BYTES`], `GROUP_PARAMETER_ERR` for a group index out of range.
pub fn register(group: usize, r: Registration) -> McclResult<()> {
    if r.fwd.is_none() || r.inv.is_none() || r.ext_size > MAX_EXTENSION_BYTES {
        return Err(McclError::Parameter);
    }
    let mut all = REGISTERED.lock();
    let slot = all.get_mut(group).ok_or(McclError::Group)?;
    *slot = Some(r);
    Ok(())
}

/// The registrations waiting for the next init, `(group, registration)`.
pub fn registered() -> Vec<(usize, Registration)> {
    let all = REGISTERED.lock();
    all.iter()
        .enumerate()
        .filter_map(|(g, r)| r.map(|r| (g, r)))
        .collect()
}

/// An init applied the registrations: they are used up (the next init runs without
/// kinematics unless the program registers them again, as its groups are made again).
pub fn clear_registered() {
    *REGISTERED.lock() = [None; GROUPS];
}

/// Tells the registrations applied apart, process-wide, so that a kinematics result
/// computed for a replaced registration is dropped.
static GENERATION: AtomicU64 = AtomicU64::new(1);

/// A generation no registration applied before had
/// ([`crate::engine::group::GroupState::set_kinematics`]).
pub fn next_generation() -> u64 {
    GENERATION.fetch_add(1, Ordering::Relaxed)
}
