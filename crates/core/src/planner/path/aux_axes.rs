//! The auxiliary axes U..B of a path: their longest travel (the path of a motion whose
//! X/Y/Z stand still) and their end position.

use super::XYZ;
use crate::planner::{check_all_finite, Axes, PlanError, NUM_AXES};

/// Longest |end - start| over the aux axes U..B.
pub(super) fn aux_travel(start: &Axes, end: &Axes) -> f64 {
    (XYZ..NUM_AXES)
        .map(|i| (end[i] - start[i]).abs())
        .fold(0.0, f64::max)
}

/// End position: `start` with the aux axes replaced by `aux_end` when given.
pub(super) fn with_aux(start: &Axes, aux_end: Option<[f64; 5]>) -> Result<Axes, PlanError> {
    let mut end = *start;
    if let Some(aux) = aux_end {
        check_all_finite(&aux, "aux axis position")?;
        end[XYZ..].copy_from_slice(&aux);
    }
    Ok(end)
}
