//! Custom motion's stage after each tick, on the shared state: the program's callbacks called with no lock held, their results stored in the groups.

use super::Shared;
use crate::config::AXES;
use crate::engine::custom::*;
use crate::engine::group::custom::{Call, CustomBatch};
use crate::planner::Axes;
use std::os::raw::{c_int, c_void};

const N_AXES: c_int = AXES as c_int;

impl Shared {
    /// The stage after a tick (module documentation). Call on the engine thread with no
    /// lock held.
    pub(in crate::engine) fn custom_stage(&self) {
        if !live() {
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
    pub(in crate::engine) fn custom_close(&self) {
        if !live() {
            return;
        }
        for n in 0..self.group_count() {
            let (group, specs) = {
                let Some(mut g) = self.nth_group(n) else {
                    return;
                };
                (g.index(), g.custom_take_all())
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

/// Calls `BlendingStart` of an Ex command (see [`crate::engine::group::custom`]): all seven points
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
