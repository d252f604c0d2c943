//! The extern "C" layer: argument checks, pointer checks, panic boundary, and Rust errors
//! to vendor return codes. One file per chapter of the manual; every entry point is a
//! plain `#[no_mangle] pub extern "C" fn` whose body calls [`guard`] and the core.

pub mod status;
pub mod system;
pub mod trajectory;

use crate::config::{CardIx, ChannelIx};
use crate::error::{McclError, McclResult};
use std::os::raw::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// How an entry point's return type reports a failure.
pub trait FfiReturn {
    /// The value returned for `e`.
    fn from_error(e: McclError) -> Self;
}

impl FfiReturn for c_int {
    fn from_error(e: McclError) -> Self {
        e.code()
    }
}

/// Functions returning `double` report errors as the (negative) vendor code converted to
/// double; none of their valid results is negative.
impl FfiReturn for f64 {
    fn from_error(e: McclError) -> Self {
        f64::from(e.code())
    }
}

impl FfiReturn for () {
    fn from_error(_: McclError) -> Self {}
}

/// Runs `f`, turning an error into the vendor code and a panic into `RUN_TIME_ERR`
/// (no panic ever crosses the C boundary).
pub fn guard<R: FfiReturn>(f: impl FnOnce() -> McclResult<R>) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(v)) => v,
        Ok(Err(e)) => R::from_error(e),
        Err(_) => R::from_error(McclError::RunTime),
    }
}

/// A card index from C.
pub fn card(w: u16) -> McclResult<CardIx> {
    CardIx::new(w)
}

/// A channel index from C.
pub fn channel(w: u16) -> McclResult<ChannelIx> {
    ChannelIx::new(w)
}

/// A finite number from C (`PARAMETER_ERR` for NaN and infinities).
pub fn finite(x: f64) -> McclResult<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(McclError::Parameter)
    }
}

/// Reads a struct the caller passed by pointer (`PARAMETER_ERR` for NULL).
///
/// # Safety
/// `p` must be NULL or point to a readable, initialised `T`.
pub unsafe fn read_in<T: Copy>(p: *const T) -> McclResult<T> {
    if p.is_null() {
        return Err(McclError::Parameter);
    }
    // SAFETY: non-null, and the caller guarantees it points to a readable T; unaligned
    // reads are tolerated because C callers may pass packed buffers.
    Ok(unsafe { p.read_unaligned() })
}

/// Checks an output pointer (`PARAMETER_ERR` for NULL) without writing to it, so a call
/// can validate all its outputs before it changes anything.
pub fn out_ok<T>(p: *mut T) -> McclResult<()> {
    if p.is_null() {
        Err(McclError::Parameter)
    } else {
        Ok(())
    }
}

/// Writes a result through a pointer already checked with [`out_ok`].
///
/// # Safety
/// `p` must be non-null and point to writable memory for a `T`.
pub unsafe fn write_out<T>(p: *mut T, v: T) {
    // SAFETY: the caller checked p with out_ok and guarantees it is writable.
    unsafe { p.write_unaligned(v) }
}

#[cfg(test)]
mod tests;
