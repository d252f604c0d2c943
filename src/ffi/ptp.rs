//! Point-to-point acc/dec settings per axis (user manual §2.6.2 II; vendor header
//! "Point-to-Point Motion").

use super::{shape, shape_char, with_group, write_outs};
use crate::error::McclError;
use crate::vendor::WORD;
use std::os::raw::{c_char, c_int};

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

/// PtP acceleration shape per axis ('T' or 'S').
#[no_mangle]
pub extern "C" fn MCC_SetPtPAccType(
    cAccType0: c_char,
    cAccType1: c_char,
    cAccType2: c_char,
    cAccType3: c_char,
    cAccType4: c_char,
    cAccType5: c_char,
    cAccType6: c_char,
    cAccType7: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = shapes([
            cAccType0, cAccType1, cAccType2, cAccType3, cAccType4, cAccType5, cAccType6, cAccType7,
        ])?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc = s)
    }
}

/// Reads the PtP acceleration shapes.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPtPAccType(
    pcAccType0: *mut c_char,
    pcAccType1: *mut c_char,
    pcAccType2: *mut c_char,
    pcAccType3: *mut c_char,
    pcAccType4: *mut c_char,
    pcAccType5: *mut c_char,
    pcAccType6: *mut c_char,
    pcAccType7: *mut c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pcAccType0, pcAccType1, pcAccType2, pcAccType3, pcAccType4, pcAccType5, pcAccType6,
            pcAccType7,
        ];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc.map(shape_char)))
            })
        }
    }
}

/// PtP deceleration shape per axis ('T' or 'S').
#[no_mangle]
pub extern "C" fn MCC_SetPtPDecType(
    cDecType0: c_char,
    cDecType1: c_char,
    cDecType2: c_char,
    cDecType3: c_char,
    cDecType4: c_char,
    cDecType5: c_char,
    cDecType6: c_char,
    cDecType7: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = shapes([
            cDecType0, cDecType1, cDecType2, cDecType3, cDecType4, cDecType5, cDecType6, cDecType7,
        ])?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec = s)
    }
}

/// Reads the PtP deceleration shapes.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPtPDecType(
    pcDecType0: *mut c_char,
    pcDecType1: *mut c_char,
    pcDecType2: *mut c_char,
    pcDecType3: *mut c_char,
    pcDecType4: *mut c_char,
    pcDecType5: *mut c_char,
    pcDecType6: *mut c_char,
    pcDecType7: *mut c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pcDecType0, pcDecType1, pcDecType2, pcDecType3, pcDecType4, pcDecType5, pcDecType6,
            pcDecType7,
        ];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec.map(shape_char)))
            })
        }
    }
}

/// PtP acceleration time per axis, ms (0..=2^32 − 1).
#[no_mangle]
pub extern "C" fn MCC_SetPtPAccTime(
    dfAccTime0: f64,
    dfAccTime1: f64,
    dfAccTime2: f64,
    dfAccTime3: f64,
    dfAccTime4: f64,
    dfAccTime5: f64,
    dfAccTime6: f64,
    dfAccTime7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let t = times([
            dfAccTime0, dfAccTime1, dfAccTime2, dfAccTime3, dfAccTime4, dfAccTime5, dfAccTime6,
            dfAccTime7,
        ])?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_acc_ms = t)
    }
}

/// Reads the PtP acceleration times, ms.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPtPAccTime(
    pdfAccTime0: *mut f64,
    pdfAccTime1: *mut f64,
    pdfAccTime2: *mut f64,
    pdfAccTime3: *mut f64,
    pdfAccTime4: *mut f64,
    pdfAccTime5: *mut f64,
    pdfAccTime6: *mut f64,
    pdfAccTime7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pdfAccTime0,
            pdfAccTime1,
            pdfAccTime2,
            pdfAccTime3,
            pdfAccTime4,
            pdfAccTime5,
            pdfAccTime6,
            pdfAccTime7,
        ];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings.ptp_acc_ms))
            })
        }
    }
}

/// PtP deceleration time per axis, ms (0..=2^32 − 1).
#[no_mangle]
pub extern "C" fn MCC_SetPtPDecTime(
    dfDecTime0: f64,
    dfDecTime1: f64,
    dfDecTime2: f64,
    dfDecTime3: f64,
    dfDecTime4: f64,
    dfDecTime5: f64,
    dfDecTime6: f64,
    dfDecTime7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let t = times([
            dfDecTime0, dfDecTime1, dfDecTime2, dfDecTime3, dfDecTime4, dfDecTime5, dfDecTime6,
            dfDecTime7,
        ])?;
        super::update_group(wGroupIndex, |g| g.settings.ptp_dec_ms = t)
    }
}

/// Reads the PtP deceleration times, ms.
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetPtPDecTime(
    pdfDecTime0: *mut f64,
    pdfDecTime1: *mut f64,
    pdfDecTime2: *mut f64,
    pdfDecTime3: *mut f64,
    pdfDecTime4: *mut f64,
    pdfDecTime5: *mut f64,
    pdfDecTime6: *mut f64,
    pdfDecTime7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pdfDecTime0,
            pdfDecTime1,
            pdfDecTime2,
            pdfDecTime3,
            pdfDecTime4,
            pdfDecTime5,
            pdfDecTime6,
            pdfDecTime7,
        ];
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_outs(p, || {
                with_group(wGroupIndex, |g| Ok(g.settings.ptp_dec_ms))
            })
        }
    }
}
