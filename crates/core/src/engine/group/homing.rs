//! A group while `MCC_Home` drives its axes on the simulated machine: taken over, moved
//! by the homing, zeroed at the working home, given back.

use super::GroupState;
use crate::config::AXES;
use crate::error::{McclError, McclResult};

impl GroupState {
    /// Axes being homed, one bit each.
    pub fn homing(&self) -> u32 {
        self.homing
    }

    /// `MCC_Home` on the simulated machine starts on the channels of axes `mask`: the
    /// group must be idle. A group on an MC3B homes on the device (`begin_external_home`).
    pub fn begin_homing(&mut self, mask: u32) -> McclResult<()> {
        if self.features.external.is_some() {
            return Err(McclError::NotAccepted);
        }
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        self.homing = mask;
        self.update_status();
        Ok(())
    }

    /// Homing moved axis `i` to reference position `x` (UU) at speed `v` (UU/s).
    pub fn set_homing_axis(&mut self, i: usize, x: f64, v: f64) {
        let p = x - self.exec.offset[i];
        self.exec.pos[i] = p;
        self.exec.base[i] = p;
        self.queued.end[i] = p;
        self.exec.vel[i] = v;
    }

    /// Axis `i` reached its working home: its position, reference and pulses read 0.
    pub fn home_zero_axis(&mut self, i: usize) {
        self.exec.offset[i] = 0.0;
        self.info_touched();
        self.set_homing_axis(i, 0.0, 0.0);
    }

    /// The homing ended (done, aborted or failed): the group is its own again.
    pub fn end_homing(&mut self) {
        self.homing = 0;
        self.exec.vel = [0.0; AXES];
        self.update_status();
    }
}
