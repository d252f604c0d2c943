//! Custom motion (`MCC_CustomMotion`, `MCC_CustomMotionEx`, `MCC_InfiniteMotion`): a
//! queued command whose geometry the program's callbacks supply, run by the library's own
//! speed profile (docs/compatibility.md, "Custom motion").
//!
//! # The stage after a tick
//!
//! The callbacks run on the engine thread with no library lock held, like routines, in a
//! stage after each tick (`Shared::custom_stage`, called by the engine thread's loop
//! before the routines are delivered). For each group, after tick k:
//!
//! 1. under the group lock: the started custom commands that are no longer running (they
//!    ended, or were aborted or reset) are taken; the lock is released and their
//!    `cleanup` is called, once each;
//! 2. under the lock: a custom command that started in tick k is marked started (its
//!    start position is the group's position); released, `start` is called and returns
//!    the total distance; under the lock again it is checked (finite, ≥ 0; otherwise the
//!    group stops with error record 0xF10A) and the speed profile over it is made;
//! 3. under the lock: the distance `cur_dist` the speed profile reaches at tick k+1 (the
//!    group's time scale — override, hold, abort — advanced by one period on a copy);
//!    released, `interp` (or the blending callback) is called; under the lock the offset
//!    it wrote is stored for tick k+1 to show. The total reached, or
//!    `*AbortThisCommand` set, make tick k+1 the command's last; FALSE from a custom
//!    motion's callback stops the group where it stands with error record 0xF107 (the
//!    offset written with FALSE is not used), FALSE from an infinite motion's ends it.
//!
//! While a callback runs, the library marks the thread: queueing into the callback's own
//! group and `MCC_InitSystem`/`MCC_CloseSystem` are refused with `COMMAND_NOTACCEPTED_ERR`
//! instead of deadlocking or pulling the system away under it.

use crate::vendor::{
    CUSTOM_BLENDING, CUSTOM_BLENDING_END, CUSTOM_BLENDING_START, CUSTOM_CLEANUP,
    CUSTOM_INTERPOLATION, CUSTOM_START_MOTION, INFINITE_INTERPOLATION,
};
use std::os::raw::{c_int, c_void};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Error record of a custom motion whose callback gave an unusable value: a total
/// distance that is negative or not finite, or an offset that is not finite or out of
/// the position range (0xF10A, the library's own).
pub const ERR_CUSTOM_MOTION: i32 = crate::error_record::ErrorRecord::CustomMotion.code();

/// Error record of a custom motion whose interpolation callback returned FALSE (0xF107,
/// as the vendor's library records it): the group stops where the callback's last good
/// offset put it.
pub const ERR_CUSTOM_FALSE: i32 = crate::error_record::ErrorRecord::CustomInterpolation.code();

/// `COMMAND_INFO.nType` of a custom or infinite motion: 20, as the vendor's library
/// reports it (the manual's table does not list it).
pub const CTYPE_CUSTOM: i32 = 20;

/// The interpolation callback of a command.
#[derive(Debug, Clone, Copy)]
pub enum Interp {
    /// `MCC_CustomMotion(Ex)`: ends at the total distance or on FALSE.
    Custom(
        unsafe extern "system" fn(
            c_int,
            c_int,
            c_int,
            *const f64,
            *const f64,
            f64,
            f64,
            *mut f64,
            *mut c_void,
        ) -> c_int,
    ),
    /// `MCC_InfiniteMotion`: ends on FALSE or when it sets `*AbortThisCommand`.
    Infinite(
        unsafe extern "system" fn(
            c_int,
            c_int,
            c_int,
            *const f64,
            *const f64,
            f64,
            f64,
            *mut f64,
            *mut c_void,
            *mut c_int,
        ) -> c_int,
    ),
}

/// The three blending callbacks of `MCC_CustomMotionEx`.
#[derive(Debug, Clone, Copy)]
pub struct Blending {
    /// `CUSTOM_BLENDING_START`.
    pub start: CUSTOM_BLENDING_START,
    /// `CUSTOM_BLENDING`.
    pub blend: CUSTOM_BLENDING,
    /// `CUSTOM_BLENDING_END`.
    pub end: CUSTOM_BLENDING_END,
}

/// What a custom motion call registered (shared by the queued command and the stage).
#[derive(Debug)]
pub struct CustomSpec {
    /// Unique per queued command (identifies it across the stage's lock releases).
    pub id: u64,
    /// The count of custom commands alive this spec is counted in.
    live: &'static AtomicUsize,
    /// `pfnStartMotion` (never NULL).
    pub start:
        unsafe extern "system" fn(c_int, c_int, c_int, c_int, *const f64, *mut c_void) -> f64,
    /// `pfnInterpolation` (never NULL).
    pub interp: Interp,
    /// `pfnCleanUp` (may be NULL).
    pub cleanup: CUSTOM_CLEANUP,
    /// `MCC_CustomMotionEx`'s blending callbacks, when all three are given.
    pub blending: Option<Blending>,
    /// The program's buffer, handed back to every callback.
    pub buffer: usize,
    /// Whether the override ratio changes this motion's speed.
    pub override_motion: bool,
    /// The axes the offsets move (`dwAxisMask`).
    pub mask: u32,
    /// Absolute coordinates when queued (`bAbsolute` of `start`).
    pub absolute: bool,
}

impl CustomSpec {
    /// A spec with the id `id` (unique per queued command), counted in `live` until
    /// dropped: the caller owns the count of custom commands alive, which tells the
    /// engine whether the custom stage has anything to do.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        id: u64,
        live: &'static AtomicUsize,
        start: CUSTOM_START_MOTION,
        interp: Interp,
        cleanup: CUSTOM_CLEANUP,
        blending: Option<Blending>,
        buffer: *mut c_void,
        override_motion: bool,
        mask: u32,
        absolute: bool,
    ) -> Option<CustomSpec> {
        let start = start?;
        live.fetch_add(1, Ordering::AcqRel);
        Some(CustomSpec {
            id,
            live,
            start,
            interp,
            cleanup,
            blending,
            buffer: buffer as usize,
            override_motion,
            mask,
            absolute,
        })
    }
}

impl Drop for CustomSpec {
    fn drop(&mut self) {
        self.live.fetch_sub(1, Ordering::AcqRel);
    }
}

/// Helper for [`CustomSpec::new`] with a custom interpolation callback.
pub fn custom_interp(f: CUSTOM_INTERPOLATION) -> Option<Interp> {
    f.map(Interp::Custom)
}

/// Helper for [`CustomSpec::new`] with an infinite interpolation callback.
pub fn infinite_interp(f: INFINITE_INTERPOLATION) -> Option<Interp> {
    f.map(Interp::Infinite)
}
