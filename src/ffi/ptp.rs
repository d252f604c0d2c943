//! Point-to-point acc/dec settings per axis (user manual §2.6.2 II; vendor header
//! "Point-to-Point Motion").

use super::{shape, shape_code, with_group};

/// A shape as a `char` output: 0 'T', 1 'S'.
fn shape_byte(s: crate::planner::Shape) -> c_char {
    shape_code(s) as c_char
}
use crate::engine::command::Settings;
use crate::error::{McclError, McclResult};
use crate::vendor::WORD;
use std::os::raw::c_char;
use std::os::raw::c_int;

fn shapes(v: [c_char; 8]) -> Result<[crate::planner::Shape; 8], McclError> {
    let mut out = [crate::planner::Shape::T; 8];
    for (o, c) in out.iter_mut().zip(v) {
        *o = shape(c)?;
    }
    Ok(out)
}

fn times(v: [f64; 8]) -> Result<[f64; 8], McclError> {
    v.iter()
        .try_for_each(|&t| crate::config::range::time_ms(t).map(|_| ()))?;
    Ok(v)
}

/// Stores the per-axis values `v` (an error if the check refused them) in the PtP setting
/// `field` of group `g`.
fn set_ptp<T>(
    g: WORD,
    v: McclResult<[T; 8]>,
    field: impl FnOnce(&mut Settings) -> &mut [T; 8],
) -> McclResult<c_int> {
    let v = v?;
    super::update_group(g, |grp| *field(&mut grp.settings) = v)
}

per_axis_setters! {
    /// PtP acceleration shape per axis ('T' or 'S').
    MCC_SetPtPAccType(c_char; wGroupIndex)
        = |v| set_ptp(wGroupIndex, shapes(v), |s| &mut s.ptp_acc);
    /// PtP deceleration shape per axis ('T' or 'S').
    MCC_SetPtPDecType(c_char; wGroupIndex)
        = |v| set_ptp(wGroupIndex, shapes(v), |s| &mut s.ptp_dec);
    /// PtP acceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPAccTime(f64; wGroupIndex) = |v| set_ptp(wGroupIndex, times(v), |s| &mut s.ptp_acc_ms);
    /// PtP deceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPDecTime(f64; wGroupIndex) = |v| set_ptp(wGroupIndex, times(v), |s| &mut s.ptp_dec_ms);
}

per_axis_getters! {
    /// Reads the PtP acceleration shapes: 0 'T', 1 'S' (as the vendor's library answers).
    MCC_GetPtPAccType(c_char; wGroupIndex)
        = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc.map(shape_byte)));
    /// Reads the PtP deceleration shapes: 0 'T', 1 'S'.
    MCC_GetPtPDecType(c_char; wGroupIndex)
        = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec.map(shape_byte)));
    /// Reads the PtP acceleration times, ms.
    MCC_GetPtPAccTime(f64; wGroupIndex) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc_ms));
    /// Reads the PtP deceleration times, ms.
    MCC_GetPtPDecTime(f64; wGroupIndex) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec_ms));
}
