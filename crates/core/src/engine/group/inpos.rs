//! The in-position check (user manual §2.7.2): its settings, the check in progress after
//! a motion command, and its tick against the machine's position errors.

use super::GroupState;
use super::TIME_EPS;
use crate::config::AXES;
use crate::engine::command::AxisMech;
use crate::engine::note::Note;
use crate::planner::Axes;
use crate::vendor::consts as c;

/// The in-position check: its settings, the axes queued markers enabled, the wait of the
/// command running and what `MCC_GetInPosStatus` reads.
#[derive(Debug)]
pub(super) struct InPosition {
    /// In-position settings (`MCC_SetInPos*`).
    pub(super) settings: InPosSettings,
    /// In-position check axes enabled by queued markers.
    pub(super) mask: u32,
    /// In-position check of the last command, while it runs.
    pub(super) wait: Option<InPosWait>,
    /// `MCC_GetInPosStatus`: 0xFF per axis once in position, until the next command.
    pub(super) status: [u8; AXES],
}

impl InPosition {
    /// No check enabled; the settings' defaults for `axes`.
    pub(super) fn for_axes(axes: &[AxisMech; AXES]) -> InPosition {
        InPosition {
            settings: InPosSettings::for_axes(axes),
            mask: 0,
            wait: None,
            // The vendor's library reads 255 for every axis right after init.
            status: [0xFF; AXES],
        }
    }
}

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

impl InPosSettings {
    /// The settings right after init: the tolerance of a mapped axis is the most pulses a
    /// count holds (2^31 − 1) in units, 0 for an unmapped one, as the vendor's library
    /// reads them.
    pub fn for_axes(axes: &[super::AxisMech; AXES]) -> InPosSettings {
        InPosSettings {
            tolerance: std::array::from_fn(|i| match (axes[i].channel, axes[i].factor) {
                (Some(_), f) if f != 0.0 => f64::from(i32::MAX) / f.abs(),
                _ => 0.0,
            }),
            ..InPosSettings::default()
        }
    }
}

/// A tolerance `t` UU of an axis with `factor` pulses per UU as the vendor's library keeps
/// it (measured): a whole number of pulses, `t x factor` truncated to a 32-bit integer
/// (anything out of its range and NaN becoming -2^31, as the x86 conversion gives), and
/// its magnitude (so -1 UU reads 1, and 1e6 UU on a 10,000-pulse axis 2^31 pulses).
fn tolerance_as_vendor_keeps(t: f64, factor: f64) -> f64 {
    let f = factor.abs();
    if f == 0.0 {
        return 0.0;
    }
    let x = t * f;
    let pulses = if x.is_nan() || x <= -2_147_483_649.0 || x >= 2_147_483_648.0 {
        i32::MIN
    } else {
        x as i32
    };
    f64::from(pulses.unsigned_abs()) / f
}

/// Maximum check time before it is set (ms; the examples manual uses 1000).
pub const DEFAULT_INPOS_CHECK_MS: f64 = 1000.0;

impl InPosSettings {
    /// The longest time the check waits after a command's last pulse, ms.
    pub fn set_max_check_ms(&mut self, ms: u16) {
        self.max_check_s = f64::from(ms) / 1000.0;
    }

    /// How long the axes must stay within tolerance in the `IPM_SETTLE_*` modes, ms.
    pub fn set_settle_ms(&mut self, ms: u16) {
        self.settle_s = f64::from(ms) / 1000.0;
    }

    /// The settle time, whole ms.
    pub fn settle_ms(&self) -> i32 {
        (self.settle_s * 1000.0).round() as i32
    }
}

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
        self.limits.track_mask != 0 || self.in_pos.wait.is_some()
    }

    /// Whether an in-position check is running (the engine feeds it the machine).
    pub fn inpos_waiting(&self) -> bool {
        self.in_pos.wait.is_some()
    }

    /// The in-position mask of the check running.
    pub fn inpos_mask_waiting(&self) -> u32 {
        self.in_pos.wait.map_or(0, |w| w.mask)
    }

    /// `MCC_GetInPosStatus`.
    pub fn inpos_status(&self) -> [u8; AXES] {
        self.in_pos.status
    }

    /// One tick of the in-position check (user manual §2.7.2): `errs[i]` is the position
    /// error of axis `i` (UU, motor against command) for the axes in the check. In
    /// position: every axis within its tolerance (and, in the settle modes, for the
    /// settle time): status 0xFF, the next command may run. Not in position within the
    /// maximum check time: the `BLOCK` modes record 0xF501 and drop the rest of the queue;
    /// the `UNBLOCK` modes let the queue go on without a record.
    pub fn check_inpos(&mut self, errs: &[Option<f64>; AXES], dt: f64) {
        let Some(mut w) = self.in_pos.wait else {
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
                    self.in_pos.status[i] = 0xFF;
                }
            }
            self.note(Note::InPosDone(w.mask));
            self.in_pos.wait = None;
        } else if w.elapsed >= w.settings.max_check_s - TIME_EPS {
            self.note(Note::InPosFail {
                mask: w.mask,
                error: w.fails_with_error(),
            });
            self.in_pos.wait = None;
            if w.fails_with_error() {
                self.stop_here();
                self.set_error(ERR_IN_POSITION);
            }
        } else {
            self.in_pos.wait = Some(w);
        }
        self.update_status();
    }
}

/// The in-position tolerances, as the program sets them.
impl GroupState {
    /// Sets the tolerance of every axis, UU (each >= 0, which the caller checks): each must
    /// be a distance of its axis within the position range ("Ranges"); an error changes
    /// nothing.
    pub fn set_inpos_tolerances(&mut self, v: Axes) {
        for (i, (t, a)) in v.iter().zip(&self.mech.axes).enumerate() {
            if a.channel.is_some() {
                self.in_pos.settings.tolerance[i] = tolerance_as_vendor_keeps(*t, a.factor);
            }
        }
    }

    /// Sets the tolerances in pulses (the obsolete form): each becomes UU with its axis's
    /// pulses per UU, 0 for an axis without a factor.
    pub fn set_inpos_tolerances_pulses(&mut self, v: [u16; AXES]) {
        for (i, t) in v.iter().enumerate() {
            let f = self.mech.axes[i].factor.abs();
            self.in_pos.settings.tolerance[i] = if f > 0.0 { f64::from(*t) / f } else { 0.0 };
        }
    }

    /// The tolerances in pulses, rounded, at most `u16::MAX`.
    pub fn inpos_tolerances_pulses(&self) -> [u16; AXES] {
        std::array::from_fn(|i| {
            (self.in_pos.settings.tolerance[i] * self.mech.axes[i].factor.abs())
                .round()
                .min(f64::from(u16::MAX)) as u16
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::GroupDef;
    use crate::engine::command::AxisMech;
    use crate::error::McclError;

    /// A group of eight axes on channels 0..7 of card 0, `factor` pulses per UU each.
    fn group(factor: f64) -> GroupState {
        let def = GroupDef::new([0, 1, 2, 3, 4, 5, 6, 7], 0, 10).unwrap();
        let axes = std::array::from_fn(|i| AxisMech {
            channel: Some((0, i)),
            factor,
            safe_speed: 1.0,
            high: 1e9,
            low: -1e9,
        });
        GroupState::new(0, def, axes, 0.001)
    }

    #[test]
    fn tolerances_in_pulses_go_through_each_axis_factor() {
        // -1000 pulses per UU (reversed direction: the size counts): 10 pulses = 0.01 UU
        // and back; 70 UU = 70000 pulses reads as the WORD maximum 65535.
        let mut g = group(-1000.0);
        g.set_inpos_tolerances_pulses([10; AXES]);
        assert_eq!(g.in_pos.settings.tolerance, [0.01; AXES]);
        assert_eq!(g.inpos_tolerances_pulses(), [10; AXES]);
        g.set_inpos_tolerances([70.0; AXES]);
        assert_eq!(g.inpos_tolerances_pulses(), [65535; AXES]);
    }

    #[test]
    fn tolerances_are_kept_as_the_vendors_library_keeps_them() {
        // Measured (scenario setters_inpos_group, 10,000 pulses per UU): -1 UU reads 1;
        // 1e6 UU (1e10 pulses, beyond 32 bits) and NaN read 2^31 pulses = 214748.3648.
        let mut g = group(10_000.0);
        let mut v = [0.5; AXES];
        v[0] = -1.0;
        v[1] = 1e6;
        v[2] = f64::NAN;
        v[3] = 0.123_456_78;
        g.set_inpos_tolerances(v);
        assert_eq!(g.in_pos.settings.tolerance[0], 1.0);
        assert_eq!(g.in_pos.settings.tolerance[1], 214_748.364_8);
        assert_eq!(g.in_pos.settings.tolerance[2], 214_748.364_8);
        // 1234.5678 pulses: whole pulses, truncated.
        assert_eq!(g.in_pos.settings.tolerance[3], 0.1234);
    }

    #[test]
    fn check_and_settle_times_are_set_in_ms() {
        let mut s = InPosSettings::default();
        s.set_max_check_ms(250);
        s.set_settle_ms(1500);
        assert_eq!(
            (s.max_check_s, s.settle_s, s.settle_ms()),
            (0.25, 1.5, 1500)
        );
    }

    #[test]
    fn tracking_error_limit_and_mask() {
        // Axis 2 at 1000 pulses per UU: 0.3 UU is a valid limit, 2e12 UU is not (2e15
        // pulses) and leaves 0.3.
        let mut g = group(1000.0);
        g.set_track_error_limit(2, 0.3).unwrap();
        assert_eq!(g.set_track_error_limit(2, 2e12), Err(McclError::Parameter));
        assert_eq!(g.limits.track_limit[2], 0.3);
        g.enable_track_error(0b101);
        g.enable_track_error(0b010);
        assert_eq!(g.limits.track_mask, 0b111);
        g.disable_track_error();
        assert_eq!(g.limits.track_mask, 0);
    }
}
