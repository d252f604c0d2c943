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
//! While a callback runs, the thread is marked ([`in_callback`]): queueing into the
//! callback's own group and `MCC_InitSystem`/`MCC_CloseSystem` are refused with
//! `COMMAND_NOTACCEPTED_ERR` instead of deadlocking or pulling the system away under it.

use super::group::custom::{Call, CustomBatch};
use super::Shared;
use crate::config::AXES;
use crate::planner::Axes;
use crate::vendor::{
    CUSTOM_BLENDING, CUSTOM_BLENDING_END, CUSTOM_BLENDING_START, CUSTOM_CLEANUP,
    CUSTOM_INTERPOLATION, CUSTOM_START_MOTION, INFINITE_INTERPOLATION,
};
use std::cell::Cell;
use std::os::raw::{c_int, c_void};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

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

/// Custom motion commands alive anywhere (queued, running or awaiting cleanup): while
/// none is, the stage costs one atomic load a tick.
static LIVE: AtomicUsize = AtomicUsize::new(0);

/// Whether a custom command of any system may have callbacks to run (see `LIVE`).
pub(super) fn live() -> bool {
    LIVE.load(Ordering::Acquire) != 0
}
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

impl CustomSpec {
    /// A spec with a fresh id, counted as alive until dropped.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
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
        LIVE.fetch_add(1, Ordering::AcqRel);
        Some(CustomSpec {
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
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
        LIVE.fetch_sub(1, Ordering::AcqRel);
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

thread_local! {
    /// The group whose custom-motion callback this thread is running, if any.
    static IN_CALLBACK: Cell<Option<usize>> = const { Cell::new(None) };
}

/// The group whose callback the calling thread is running for the library: a custom
/// motion's, or a kinematics initialiser or forward kinematics run while the card starts.
pub fn in_callback() -> Option<usize> {
    IN_CALLBACK.with(Cell::get)
}

/// Runs `f`, the program's code, marked as a callback of `group` ([`in_callback`]).
pub(crate) fn as_callback<R>(group: usize, f: impl FnOnce() -> R) -> R {
    let prev = IN_CALLBACK.with(|c| c.replace(Some(group)));
    let r = f();
    IN_CALLBACK.with(|c| c.set(prev));
    r
}

const N_AXES: c_int = AXES as c_int;

impl Shared {
    /// The stage after a tick (module documentation). Call on the engine thread with no
    /// lock held.
    pub(super) fn custom_stage(&self) {
        if LIVE.load(Ordering::Acquire) == 0 {
            return;
        }
        let dt = self.clock.period().as_secs_f64();
        for n in 0..self.group_count() {
            if self.clock.stopped() {
                return;
            }
            let batch = {
                let Some(mut g) = self.nth_group(n) else {
                    return;
                };
                let batch = g.custom_batch(dt);
                if batch.call.is_some() {
                    // Status calls from the callback read what the group shows now (a
                    // virtual clock's run publishes only every few ticks).
                    self.publish(&mut g);
                }
                batch
            };
            self.run_batch(n, batch, dt);
        }
    }

    /// After the engine's last tick: every started custom command gets its cleanup.
    pub(super) fn custom_close(&self) {
        if LIVE.load(Ordering::Acquire) == 0 {
            return;
        }
        for n in 0..self.group_count() {
            let (group, specs) = {
                let Some(mut g) = self.nth_group(n) else {
                    return;
                };
                (g.index, g.custom_take_all())
            };
            for (idx, spec) in specs {
                cleanup(group, idx, &spec);
            }
        }
    }

    /// Runs the callbacks `batch` asks for, for the group at position `n`, locking the
    /// group only between them.
    fn run_batch(&self, n: usize, batch: CustomBatch, dt: f64) {
        let group = batch.group;
        for (idx, spec) in &batch.cleanups {
            cleanup(group, *idx, spec);
        }
        let mut call = batch.call;
        if let Some(Call::Start { spec, index, start }) = call {
            if self.clock.stopped() {
                return;
            }
            let tot = as_callback(group, || {
                // SAFETY: `spec.start` is a non-NULL C function of the CUSTOM_START_MOTION
                // type the program registered; `start` holds AXES values and outlives the
                // call; the buffer is the program's own pointer, handed back unchanged.
                unsafe {
                    (spec.start)(
                        group as c_int,
                        N_AXES,
                        index,
                        c_int::from(spec.absolute),
                        start.as_ptr(),
                        spec.buffer as *mut c_void,
                    )
                }
            });
            call = self
                .nth_group(n)
                .and_then(|mut g| g.custom_begin(spec.id, tot, dt));
        }
        if let Some(Call::BlendStart {
            spec,
            index,
            start,
            interval,
        }) = call
        {
            if self.clock.stopped() {
                return;
            }
            let accepted = blending_start(group, index, &spec, &start, interval);
            call = self
                .nth_group(n)
                .and_then(|mut g| g.custom_blending(spec.id, accepted, dt));
        }
        if let Some(Call::Interp {
            spec,
            index,
            start,
            cur,
            dist,
            tot,
            blend,
            step,
        }) = call
        {
            if self.clock.stopped() {
                return;
            }
            let mut next: Axes = step.offset_now;
            let mut abort: c_int = 0;
            let ok = as_callback(group, || {
                let buf = spec.buffer as *mut c_void;
                // SAFETY: the callbacks are non-NULL C functions of the registered types;
                // every pointer passed points to AXES values (or one BOOL) on this stack
                // frame that outlive the call; `next` and `abort` are writable.
                unsafe {
                    match (blend, spec.interp) {
                        (true, _) => match spec.blending.and_then(|b| b.blend) {
                            Some(f) => f(
                                group as c_int,
                                N_AXES,
                                index,
                                start.as_ptr(),
                                start.as_ptr(),
                                cur.as_ptr(),
                                dist,
                                next.as_mut_ptr(),
                                buf,
                            ),
                            None => 0,
                        },
                        (false, Interp::Custom(f)) => f(
                            group as c_int,
                            N_AXES,
                            index,
                            start.as_ptr(),
                            cur.as_ptr(),
                            dist,
                            tot,
                            next.as_mut_ptr(),
                            buf,
                        ),
                        (false, Interp::Infinite(f)) => f(
                            group as c_int,
                            N_AXES,
                            index,
                            start.as_ptr(),
                            cur.as_ptr(),
                            dist,
                            tot,
                            next.as_mut_ptr(),
                            buf,
                            &mut abort,
                        ),
                    }
                }
            });
            // Published at once: a callback that failed stops the group now, and the
            // program's cycle routine of this period already reads the stop.
            let blend_end = self.nth_group(n).is_some_and(|mut g| {
                let blend_end = g.custom_apply(spec.id, ok != 0, abort != 0, &next, step);
                self.publish(&mut g);
                blend_end
            });
            if blend_end {
                if let Some(f) = spec.blending.and_then(|b| b.end) {
                    // SAFETY: a non-NULL CUSTOM_BLENDING_END of the program; the buffer is
                    // its own pointer.
                    as_callback(group, || unsafe {
                        f(group as c_int, index, spec.buffer as *mut c_void)
                    });
                }
            }
        }
    }
}

/// Calls `cleanup` of a command that was started (NULL: nothing to call).
fn cleanup(group: usize, index: c_int, spec: &CustomSpec) {
    if let Some(f) = spec.cleanup {
        // SAFETY: a non-NULL CUSTOM_CLEANUP the program registered; the buffer is the
        // program's own pointer, handed back unchanged.
        as_callback(group, || unsafe {
            f(group as c_int, index, spec.buffer as *mut c_void)
        });
    }
}

/// Calls `BlendingStart` of an Ex command (see [`super::group::custom`]): all seven points
/// are the command's start position; returns what it returned.
fn blending_start(
    group: usize,
    index: c_int,
    spec: &CustomSpec,
    start: &Axes,
    interval: f64,
) -> bool {
    let Some(f) = spec.blending.and_then(|b| b.start) else {
        return false;
    };
    let p = start.as_ptr();
    // SAFETY: a non-NULL CUSTOM_BLENDING_START of the program; every point is `start`
    // (AXES values that outlive the call); the buffer is the program's own pointer.
    as_callback(group, || unsafe {
        f(
            group as c_int,
            N_AXES,
            index,
            c_int::from(spec.absolute),
            p,
            p,
            p,
            p,
            p,
            p,
            p,
            interval,
            spec.buffer as *mut c_void,
        )
    }) != 0
}
