//! A channel's encoder index pulses: the pulses the motor passes in a step, through the cached index interval that lets most steps skip the division.

use crate::machine::index_pulses::{floor_i64, IndexCell};
use crate::machine::Channel;

impl Channel {
    fn index_grid(&self) -> (i64, i64) {
        self.grid
    }

    /// Recomputes the index grid after `spec` or `mac` changed; a new grid drops the
    /// cached index interval.
    pub(in crate::machine) fn refresh_grid(&mut self) {
        let spacing = i64::from(self.spec.index_spacing.unwrap_or(self.mac.dwPPR).max(1));
        self.set_grid((spacing, i64::from(self.spec.index_phase)));
    }

    /// Index grid `(spacing, phase)`; a new one drops the cached index interval.
    pub(in crate::machine) fn set_grid(&mut self, grid: (i64, i64)) {
        if grid != self.grid {
            self.grid = grid;
            self.cell = IndexCell::NONE;
            self.resting = false;
        }
    }

    /// The `n`th (from 0) index pulse the motor passed in the last step, in the pulse
    /// frame of the command counter (what a latch captures), or `None` when it passed
    /// fewer than `n + 1`. Pulses are passed in the order of the motion.
    pub fn index_passed(&self, n: u32) -> Option<i64> {
        let (spacing, phase) = self.index_grid();
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
        Some(idx * spacing + phase - self.base as i64)
    }

    /// `(floor(x) - phase).div_euclid(spacing)` on the channel's grid: the index interval
    /// of motor position `x`.
    /// A motor that stays within the interval of the last lookup (nearly every step: index
    /// pulses are a motor turn apart) gets it by two comparisons: with integer bounds
    /// `lo <= x < hi` means `lo <= floor(x) <= hi - 1`.
    pub(in crate::machine) fn index_interval(&mut self, x: f64) -> i64 {
        let (spacing, phase) = self.grid;
        if self.cell.holds(x) {
            return self.cell.k;
        }
        let k = (floor_i64(x) - phase).div_euclid(spacing);
        self.cell = IndexCell::new(spacing, phase, k).unwrap_or(IndexCell::NONE);
        k
    }

    /// The last index pulse passed, as a count of the command counter (what a latch
    /// captures at it).
    #[inline]
    pub(in crate::machine) fn last_index_count(&self) -> Option<i64> {
        self.last_index_count
    }

    #[inline]
    pub(in crate::machine) fn count_index(&mut self, from: f64, to: f64) {
        self.index_events = 0;
        self.last_move = (from, to);
        // Whole-pulse positions (the ideal plant) use integer arithmetic; a lagging motor
        // between pulses rounds down to the pulse it has passed.
        if self.cell.holds(from) && self.cell.holds(to) {
            // Both ends in one interval (a motor that stood still too, nearly always: the
            // interval is the one its last move ended in): no index pulse passed.
            return;
        }
        self.count_index_across(from, to);
    }

    /// [`Channel::count_index`] of a move that leaves the last index interval looked up.
    #[inline(never)]
    fn count_index_across(&mut self, from: f64, to: f64) {
        // Index pulses in x4 counts of the motor position: one count per pulse.
        let (spacing, phase) = self.index_grid();
        let (a, b) = (self.index_interval(from), self.index_interval(to));
        if a != b {
            self.index_events = u32::try_from((a - b).unsigned_abs()).unwrap_or(u32::MAX);
            // Moving up the last index passed is the highest, moving down the lowest.
            let last = if b > a { b } else { b + 1 };
            self.last_index_count = Some(last * spacing + phase - self.base as i64);
        }
    }
}
