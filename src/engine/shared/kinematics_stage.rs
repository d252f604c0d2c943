//! The kinematics stage after each tick, on the shared state, and the registrations applied to a starting engine.

use super::Shared;
use crate::engine::kinematics::*;
use crate::error::{McclError, McclResult};
use crate::vendor::DWORD;
use std::sync::atomic::Ordering;
use std::sync::Arc;

impl Shared {
    /// The kinematics stage after a tick (see the module's documentation): runs on the
    /// engine thread with no lock held, and holds a group's lock only to read what the
    /// callbacks need and to store what they returned.
    pub(in crate::engine) fn kinematics_stage(&self) {
        if !self.routines.kinematics_on.load(Ordering::Acquire) {
            return;
        }
        for n in 0..self.group_count() {
            let job = self.nth_group(n).and_then(|mut g| g.kinematics_job());
            let Some(job) = job else { continue };
            let done = job.call();
            if let Some(mut g) = self.nth_group(n) {
                g.kinematics_done(done);
                self.publish(&mut g);
            }
        }
    }
}

impl Shared {
    /// Applies `regs` to the groups of a system being started (before any other thread can
    /// reach it; call with no lock held: the program's initialisers and forward kinematics
    /// run here, marked as callbacks so that they cannot start or close a system). A
    /// registration for a group that does not run is passed over. Each extension is
    /// allocated zeroed and initialised once; the group keeps its joints (its channels'
    /// positions) and its Cartesian position is the forward kinematics of them. A group on
    /// an MC3B, or a forward kinematics failing there, is `COMMAND_NOTACCEPTED_ERR`.
    pub fn apply_kinematics(&self, regs: &[(usize, Registration)]) -> McclResult<()> {
        for &(g, r) in regs {
            let Ok(index) = u16::try_from(g) else {
                continue;
            };
            let joints = match self.group(index) {
                Ok(grp) => grp.current_joints(),
                Err(_) => continue,
            };
            let ext = Arc::new(Extension::new(r.ext_size)?);
            crate::engine::custom::as_callback(g, || init_extension(r.init, &ext));
            let fns = KinFns {
                fwd: r.fwd,
                inv: r.inv,
                ext,
            };
            let mut posture: DWORD = 0;
            let cart =
                crate::engine::custom::as_callback(g, || fns.forward(g, &joints, &mut posture))
                    .ok_or(McclError::NotAccepted)?;
            let mut grp = self.group(index)?;
            grp.set_kinematics(
                fns,
                super::super::kinematics::next_generation(),
                joints,
                cart,
                posture,
            )?;
            self.routines.kinematics_on.store(true, Ordering::Release);
            self.publish(&mut grp);
        }
        Ok(())
    }
}
