//! The in-position check (user manual §2.7.2): its settings, the check in progress after
//! a motion command, and its tick against the machine's position errors.

use super::GroupState;
use super::TIME_EPS;
use crate::config::AXES;
use crate::engine::trace::Note;
use crate::planner::Axes;
use crate::vendor::consts as c;

/// In-position settings of a group (user manual §2.7.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InPosSettings {
    /// `IPM_*` mode.
    pub mode: u16,
    /// Maximum check time, s.
    pub max_check_s: f64,
    /// Settle time, s (the `IPM_SETTLE_*` modes).
    pub settle_s: f64,
    /// Tolerance per axis, UU.
    pub tolerance: Axes,
}

/// Maximum check time before it is set (ms; the examples manual uses 1000).
pub const DEFAULT_INPOS_CHECK_MS: f64 = 1000.0;

impl Default for InPosSettings {
    fn default() -> Self {
        InPosSettings {
            mode: c::IPM_ONETIME_BLOCK,
            max_check_s: DEFAULT_INPOS_CHECK_MS / 1000.0,
            settle_s: 0.0,
            tolerance: [0.0; AXES],
        }
    }
}

/// An in-position check in progress.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct InPosWait {
    pub(super) mask: u32,
    pub(super) elapsed: f64,
    pub(super) settled: f64,
    pub(super) settings: InPosSettings,
}

impl InPosWait {
    /// Every mode waits for the check; the `BLOCK` modes also stop the queue (with an
    /// error record) when it fails, the `UNBLOCK` modes then go on.
    pub(super) fn blocks(&self) -> bool {
        true
    }

    fn fails_with_error(&self) -> bool {
        matches!(
            self.settings.mode,
            c::IPM_ONETIME_BLOCK | c::IPM_SETTLE_BLOCK
        )
    }
}

/// Error record of a failed in-position check (docs/vendor-interface.md).
pub const ERR_IN_POSITION: i32 = crate::error_record::ErrorRecord::InPosition.code();

impl GroupState {
    /// Whether a check that needs the machine watches this group even when it stands.
    pub fn has_safety_checks(&self) -> bool {
        self.track_mask != 0 || self.inpos_wait.is_some()
    }

    /// Whether an in-position check is running (the engine feeds it the machine).
    pub fn inpos_waiting(&self) -> bool {
        self.inpos_wait.is_some()
    }

    /// The in-position mask of the check running.
    pub fn inpos_mask_waiting(&self) -> u32 {
        self.inpos_wait.map_or(0, |w| w.mask)
    }

    /// `MCC_GetInPosStatus`.
    pub fn inpos_status(&self) -> [u8; AXES] {
        self.inpos_status
    }

    /// One tick of the in-position check (user manual §2.7.2): `errs[i]` is the position
    /// error of axis `i` (UU, motor against command) for the axes in the check. In
    /// position: every axis within its tolerance (and, in the settle modes, for the
    /// settle time): status 0xFF, the next command may run. Not in position within the
    /// maximum check time: the `BLOCK` modes record 0xF501 and drop the rest of the queue;
    /// the `UNBLOCK` modes let the queue go on without a record.
    pub fn check_inpos(&mut self, errs: &[Option<f64>; AXES], dt: f64) {
        let Some(mut w) = self.inpos_wait else {
            return;
        };
        w.elapsed += dt;
        let within = (0..AXES).all(|i| {
            w.mask & (1 << i) == 0 || errs[i].is_none_or(|e| e.abs() <= w.settings.tolerance[i])
        });
        let settle = matches!(w.settings.mode, c::IPM_SETTLE_BLOCK | c::IPM_SETTLE_UNBLOCK);
        if within {
            w.settled += dt;
        } else {
            w.settled = 0.0;
        }
        let done = within && (!settle || w.settled >= w.settings.settle_s - TIME_EPS);
        if done {
            for i in 0..AXES {
                if w.mask & (1 << i) != 0 {
                    self.inpos_status[i] = 0xFF;
                }
            }
            self.note(Note::InPosDone(w.mask));
            self.inpos_wait = None;
        } else if w.elapsed >= w.settings.max_check_s - TIME_EPS {
            self.note(Note::InPosFail {
                mask: w.mask,
                error: w.fails_with_error(),
            });
            self.inpos_wait = None;
            if w.fails_with_error() {
                self.stop_here();
                self.set_error(ERR_IN_POSITION);
            }
        } else {
            self.inpos_wait = Some(w);
        }
        self.update_status();
    }
}
