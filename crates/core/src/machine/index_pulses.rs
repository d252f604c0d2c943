//! A channel's encoder index pulses: the grid they lie on, the pulses the motor passes in
//! a step, and the cached index interval that lets most steps skip the division.

/// `x.floor() as i64` without a call to libm's `floor` (x86-64 without SSE4.1 has no
/// rounding instruction): the same result for every `f64`, since `as` truncates toward
/// zero and saturates (NaN gives 0).
pub(super) fn floor_i64(x: f64) -> i64 {
    let t = x as i64;
    if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// Interval bounds below this in magnitude are exact in an `f64` (and nothing computed
/// from them overflows).
pub(super) const CELL_LIMIT: i64 = 1 << 52;

/// The index interval `k` of the last position looked up on the channel's grid
/// (`spacing`, `phase`; a new grid drops the cell), and its bounds as motor positions:
/// every `x` in `lo <= x < hi` has `(floor(x) - phase).div_euclid(spacing) == k`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct IndexCell {
    pub(super) k: i64,
    pub(super) lo: f64,
    pub(super) hi: f64,
}

impl IndexCell {
    /// No interval: holds no position (the bounds are the wrong way round), so the next
    /// lookup computes one.
    pub(super) const NONE: IndexCell = IndexCell {
        k: 0,
        lo: f64::INFINITY,
        hi: f64::NEG_INFINITY,
    };

    /// The cell of interval `k`, when its bounds are exact.
    pub(super) fn new(spacing: i64, phase: i64, k: i64) -> Option<IndexCell> {
        let lo = k.checked_mul(spacing)?.checked_add(phase)?;
        let hi = lo.checked_add(spacing)?;
        (lo > -CELL_LIMIT && hi < CELL_LIMIT).then_some(IndexCell {
            k,
            lo: lo as f64,
            hi: hi as f64,
        })
    }

    /// Whether `x` is inside (false for NaN).
    pub(super) fn holds(&self, x: f64) -> bool {
        x >= self.lo && x < self.hi
    }
}
