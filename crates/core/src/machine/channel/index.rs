//! A channel's encoder index pulses: [`IndexPulses`], the pulses the motor passes in a
//! step, through the cached index interval that lets most steps skip the division.

use crate::machine::index_pulses::{floor_i64, IndexCell};
use crate::machine::Channel;

/// The index pulses of a channel's last step, the grid they lie on and the index
/// interval of the last position looked up.
///
/// Positions here are motor positions in pulses of the machine frame; what a latch
/// captures is in the frame of the command counter, which starts `base` pulses up it
/// (the caller's).
///
/// `repr(C)`: what every step reads first (the count, the move, the cached interval),
/// then the grid and the last pulse's count, read only when the motor leaves the
/// interval.
#[derive(Debug, Clone)]
#[repr(C)]
pub(super) struct IndexPulses {
    /// Index pulses passed in the last step.
    events: u32,
    /// Motor positions at the start and end of the last step.
    last_move: (f64, f64),
    /// The index interval of the last position looked up ([`IndexPulses::interval`]),
    /// or [`IndexCell::NONE`]; always one of `grid`.
    cell: IndexCell,
    /// The index grid (spacing, phase) in x4 counts, which the channel sets from its
    /// spec and `dwPPR` ([`Channel::refresh_grid`]).
    grid: (i64, i64),
    /// The last index pulse passed, in the frame of the command counter.
    last_count: Option<i64>,
}

impl IndexPulses {
    /// No pulse passed, one index pulse a count at phase 0 (the channel sets its grid).
    pub(super) const NONE: IndexPulses = IndexPulses {
        events: 0,
        last_move: (0.0, 0.0),
        cell: IndexCell::NONE,
        grid: (1, 0),
        last_count: None,
    };

    /// Index pulses passed in the last step.
    #[inline(always)]
    pub(super) fn events(&self) -> u32 {
        self.events
    }

    /// The last index pulse passed, in the frame of the command counter.
    #[inline]
    pub(super) fn last_count(&self) -> Option<i64> {
        self.last_count
    }

    /// Whether the motor stood still in the last step.
    #[inline(always)]
    pub(super) fn stood_still(&self) -> bool {
        self.last_move.0 == self.last_move.1
    }

    /// Forgets the pulses of the last step (steps deferred from now on have none until
    /// they are brought up to date).
    #[inline]
    pub(super) fn clear_events(&mut self) {
        self.events = 0;
    }

    /// Tests: forgets the last pulse's count (kept only for the step that passed it).
    #[cfg(test)]
    pub(super) fn forget_last_count(&mut self) {
        self.last_count = None;
    }

    /// Index grid `(spacing, phase)`; a new one drops the cached index interval. Returns
    /// whether the grid changed.
    pub(super) fn set_grid(&mut self, grid: (i64, i64)) -> bool {
        if grid == self.grid {
            return false;
        }
        self.grid = grid;
        self.cell = IndexCell::NONE;
        true
    }

    /// The interval of the last position looked up, as [`IndexPulses::interval`] left
    /// it.
    #[inline]
    pub(super) fn cell(&self) -> IndexCell {
        self.cell
    }

    /// The `n`th (from 0) index pulse the motor passed in the last step, in pulses of
    /// the machine frame, or `None` when it passed fewer than `n + 1`. Pulses are passed
    /// in the order of the motion.
    #[inline]
    pub(super) fn passed(&self, n: u32) -> Option<i64> {
        let (spacing, phase) = self.grid;
        let k = |x: f64| (x.floor() as i64 - phase).div_euclid(spacing);
        let (from, to) = self.last_move;
        let (a, b) = (k(from), k(to));
        let n = i64::from(n);
        let idx = if b > a {
            // Moving up: pulses a+1 ..= b.
            (a + 1 + n <= b).then_some(a + 1 + n)
        } else {
            // Moving down: pulses a, a-1, ..., b+1.
            (a - n > b).then_some(a - n)
        }?;
        Some(idx * spacing + phase)
    }

    /// `(floor(x) - phase).div_euclid(spacing)` on the grid: the index interval of motor
    /// position `x`.
    /// A motor that stays within the interval of the last lookup (nearly every step: index
    /// pulses are a motor turn apart) gets it by two comparisons: with integer bounds
    /// `lo <= x < hi` means `lo <= floor(x) <= hi - 1`.
    pub(super) fn interval(&mut self, x: f64) -> i64 {
        let (spacing, phase) = self.grid;
        if self.cell.holds(x) {
            return self.cell.k;
        }
        let k = (floor_i64(x) - phase).div_euclid(spacing);
        self.cell = IndexCell::new(spacing, phase, k).unwrap_or(IndexCell::NONE);
        k
    }

    /// Counts the index pulses of a step of the motor from `from` to `to`, with the
    /// command counter starting at `base`.
    #[inline]
    pub(super) fn count(&mut self, from: f64, to: f64, base: f64) {
        self.events = 0;
        self.last_move = (from, to);
        // Whole-pulse positions (the ideal plant) use integer arithmetic; a lagging motor
        // between pulses rounds down to the pulse it has passed.
        if self.cell.holds(from) && self.cell.holds(to) {
            // Both ends in one interval (a motor that stood still too, nearly always: the
            // interval is the one its last move ended in): no index pulse passed.
            return;
        }
        self.count_across(from, to, base);
    }

    /// [`IndexPulses::count`] of a move that leaves the last index interval looked up.
    #[inline(never)]
    fn count_across(&mut self, from: f64, to: f64, base: f64) {
        // Index pulses in x4 counts of the motor position: one count per pulse.
        let (spacing, phase) = self.grid;
        let (a, b) = (self.interval(from), self.interval(to));
        if a != b {
            self.events = u32::try_from((a - b).unsigned_abs()).unwrap_or(u32::MAX);
            // Moving up the last index passed is the highest, moving down the lowest.
            let last = if b > a { b } else { b + 1 };
            self.last_count = Some(last * spacing + phase - base as i64);
        }
    }
}

impl Channel {
    /// Recomputes the index grid after `spec` or `mac` changed; a new grid drops the
    /// cached index interval.
    pub(in crate::machine) fn refresh_grid(&mut self) {
        let spacing = i64::from(self.spec.index_spacing.unwrap_or(self.mac.dwPPR).max(1));
        self.set_grid((spacing, i64::from(self.spec.index_phase)));
    }

    /// Index grid `(spacing, phase)`; a new one drops the cached index interval.
    pub(in crate::machine) fn set_grid(&mut self, grid: (i64, i64)) {
        if self.index.set_grid(grid) {
            self.step.wake();
        }
    }

    /// The `n`th (from 0) index pulse the motor passed in the last step, in the pulse
    /// frame of the command counter (what a latch captures), or `None` when it passed
    /// fewer than `n + 1`. Pulses are passed in the order of the motion.
    pub fn index_passed(&self, n: u32) -> Option<i64> {
        // (The frame's start only where there is a pulse: most calls find none.)
        let at = self.index.passed(n)?;
        Some(at - self.step.base() as i64)
    }

    /// Tests: the index interval of motor position `x` (pulses, machine frame).
    #[cfg(test)]
    pub(in crate::machine) fn index_interval(&mut self, x: f64) -> i64 {
        self.index.interval(x)
    }

    /// Index pulses passed in the last step.
    #[inline]
    pub fn index_events(&self) -> u32 {
        self.index.events()
    }

    /// The last index pulse passed, as a count of the command counter (what a latch
    /// captures at it).
    #[inline]
    pub(in crate::machine) fn last_index_count(&self) -> Option<i64> {
        self.index.last_count()
    }
}
