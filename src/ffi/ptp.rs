//! Point-to-point acc/dec settings per axis (user manual §2.6.2 II; vendor header
//! "Point-to-Point Motion").

use super::{shape, shape_char, with_group};
use crate::error::McclError;
use std::os::raw::c_char;

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

per_axis_setters! {
    /// PtP acceleration shape per axis ('T' or 'S').
    MCC_SetPtPAccType(c_char; wGroupIndex) = |v| {
        let s = shapes(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc = s)
    };
    /// PtP deceleration shape per axis ('T' or 'S').
    MCC_SetPtPDecType(c_char; wGroupIndex) = |v| {
        let s = shapes(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec = s)
    };
    /// PtP acceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPAccTime(f64; wGroupIndex) = |v| {
        let t = times(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc_ms = t)
    };
    /// PtP deceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPDecTime(f64; wGroupIndex) = |v| {
        let t = times(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec_ms = t)
    };
}

per_axis_getters! {
    /// Reads the PtP acceleration shapes.
    MCC_GetPtPAccType(c_char; wGroupIndex)
        = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc.map(shape_char)));
    /// Reads the PtP deceleration shapes.
    MCC_GetPtPDecType(c_char; wGroupIndex)
        = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec.map(shape_char)));
    /// Reads the PtP acceleration times, ms.
    MCC_GetPtPAccTime(f64; wGroupIndex) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc_ms));
    /// Reads the PtP deceleration times, ms.
    MCC_GetPtPDecTime(f64; wGroupIndex) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec_ms));
}
