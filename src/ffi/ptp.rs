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
    MCC_SetPtPAccType(
        cAccType0, cAccType1, cAccType2, cAccType3,
        cAccType4, cAccType5, cAccType6, cAccType7: c_char; wGroupIndex
    ) = |v| {
        let s = shapes(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc = s)
    };
    /// PtP deceleration shape per axis ('T' or 'S').
    MCC_SetPtPDecType(
        cDecType0, cDecType1, cDecType2, cDecType3,
        cDecType4, cDecType5, cDecType6, cDecType7: c_char; wGroupIndex
    ) = |v| {
        let s = shapes(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec = s)
    };
    /// PtP acceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPAccTime(
        dfAccTime0, dfAccTime1, dfAccTime2, dfAccTime3,
        dfAccTime4, dfAccTime5, dfAccTime6, dfAccTime7: f64; wGroupIndex
    ) = |v| {
        let t = times(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc_ms = t)
    };
    /// PtP deceleration time per axis, ms (0..=2^32 − 1).
    MCC_SetPtPDecTime(
        dfDecTime0, dfDecTime1, dfDecTime2, dfDecTime3,
        dfDecTime4, dfDecTime5, dfDecTime6, dfDecTime7: f64; wGroupIndex
    ) = |v| {
        let t = times(v)?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec_ms = t)
    };
}

per_axis_getters! {
    /// Reads the PtP acceleration shapes.
    MCC_GetPtPAccType(
        pcAccType0, pcAccType1, pcAccType2, pcAccType3,
        pcAccType4, pcAccType5, pcAccType6, pcAccType7: c_char; wGroupIndex
    ) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc.map(shape_char)));
    /// Reads the PtP deceleration shapes.
    MCC_GetPtPDecType(
        pcDecType0, pcDecType1, pcDecType2, pcDecType3,
        pcDecType4, pcDecType5, pcDecType6, pcDecType7: c_char; wGroupIndex
    ) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec.map(shape_char)));
    /// Reads the PtP acceleration times, ms.
    MCC_GetPtPAccTime(
        pdfAccTime0, pdfAccTime1, pdfAccTime2, pdfAccTime3,
        pdfAccTime4, pdfAccTime5, pdfAccTime6, pdfAccTime7: f64; wGroupIndex
    ) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc_ms));
    /// Reads the PtP deceleration times, ms.
    MCC_GetPtPDecTime(
        pdfDecTime0, pdfDecTime1, pdfDecTime2, pdfDecTime3,
        pdfDecTime4, pdfDecTime5, pdfDecTime6, pdfDecTime7: f64; wGroupIndex
    ) = with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec_ms));
}
