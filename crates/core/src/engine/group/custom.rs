//! A group's side of custom motion (the stage is in `engine/custom.rs`): the running
//! custom command's state, what the stage calls next, and storing what it returned.
//!
//! A custom command does not advance in the tick (`execution.rs` leaves it to its stage):
//! the stage moves its track (`engine/track.rs`, the library's profile along the
//! total distance) one period ahead when it asks the callback for the next position. It
//! ends (the tick after retires it at the offset the callback gave last) when an infinite
//! motion's callback returns FALSE or sets `*AbortThisCommand`, or the track reaches the
//! total distance; FALSE from a custom motion's callback stops the group with error
//! record 0xF107. A hold, a continue and an override act on the track as on any motion's.

use super::GroupState;
use crate::config::{range, AXES};
use crate::engine::command::{Command, Ctx, Plan};
use crate::engine::custom::{
    CustomSpec, Interp, CTYPE_CUSTOM, ERR_CUSTOM_FALSE, ERR_CUSTOM_MOTION,
};
use crate::engine::custom_move::{CustomMove, Step};
use crate::engine::track::Track;
use crate::planner::{ramp_periods, Axes, TickProfile};
use std::os::raw::c_int;
use std::sync::Arc;

/// The periods at the feed an infinite motion's profile is planned over: it never gets
/// to their end (10¹⁵ periods of 1 ms are 31,000 years), so it accelerates and cruises
/// at the feed; few enough that a period's fraction of them keeps its digits (the
/// profile counts whole periods).
const INFINITE_PERIODS: f64 = 1e15;

/// A custom command queued at the end of `ctx`'s queue.
pub fn command(ctx: &Ctx<'_>, spec: Arc<CustomSpec>) -> Command {
    let s = ctx.settings;
    Command {
        index: 0,
        ctype: CTYPE_CUSTOM,
        info_feed: s.feed,
        target: ctx.from,
        acc_ms: s.acc_ms,
        dec_ms: s.dec_ms,
        plan: Plan::Custom(CustomMove::new(spec, ctx.from, s.acc, s.dec)),
        posture: None,
    }
}

/// Moves a queued command by `d`.
fn translate(cmd: &mut Command, d: &Axes) {
    match &mut cmd.plan {
        Plan::Path(m) => m.path.translate(d),
        Plan::Ptp(p) => p.translate(d),
        Plan::Custom(c) => {
            for (s, d) in c.start.iter_mut().zip(d) {
                *s += d;
            }
        }
        Plan::Delay(_) | Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_) | Plan::Fault(_) => {}
    }
    for (t, d) in cmd.target.iter_mut().zip(d) {
        *t += d;
    }
}

/// The callback the stage calls next for a group.
#[derive(Debug)]
pub enum Call {
    /// `pfnStartMotion`.
    Start {
        /// The command.
        spec: Arc<CustomSpec>,
        /// Its index.
        index: c_int,
        /// Where it starts.
        start: Axes,
    },
    /// `pfnBlendingStart` (Ex, blending on).
    BlendStart {
        /// The command.
        spec: Arc<CustomSpec>,
        /// Its index.
        index: c_int,
        /// Where it started.
        start: Axes,
        /// The blend interval (the acceleration ramp's distance).
        interval: f64,
    },
    /// `pfnInterpolation` (or `pfnBlending` while blending).
    Interp {
        /// The command.
        spec: Arc<CustomSpec>,
        /// Its index.
        index: c_int,
        /// Where it started.
        start: Axes,
        /// The group's position now.
        cur: Axes,
        /// The distance the profile reaches at the next tick.
        dist: f64,
        /// The total distance.
        tot: f64,
        /// Call `pfnBlending` instead.
        blend: bool,
        /// What to apply.
        step: Step,
    },
}

/// What the stage does for one group after a tick.
#[derive(Debug, Default)]
pub struct CustomBatch {
    /// The group index.
    pub group: usize,
    /// Started commands that ended: `cleanup` for each.
    pub cleanups: Vec<(c_int, Arc<CustomSpec>)>,
    /// The next callback.
    pub call: Option<Call>,
}

/// The group's custom commands that were started and not cleaned up yet.
#[derive(Debug, Default)]
pub struct CustomSide {
    started: Vec<(c_int, Arc<CustomSpec>)>,
}

impl GroupState {
    fn custom_running(&mut self, id: Option<u64>) -> Option<(c_int, &mut CustomMove)> {
        self.exec
            .running
            .iter_mut()
            .find_map(|r| match &mut r.cmd.plan {
                Plan::Custom(m) if id.is_none_or(|id| m.spec.id == id) && !m.ended() => {
                    Some((r.cmd.index, m))
                }
                _ => None,
            })
    }

    fn custom_is_running(&self, id: u64) -> bool {
        self.exec
            .running
            .iter()
            .any(|r| matches!(&r.cmd.plan, Plan::Custom(m) if m.spec.id == id))
    }

    /// Takes every started command for its cleanup (the engine is closing).
    pub fn custom_take_all(&mut self) -> Vec<(c_int, Arc<CustomSpec>)> {
        std::mem::take(&mut self.features.custom.started)
    }

    /// What the stage does for this group after a tick of `dt` seconds.
    pub fn custom_batch(&mut self, dt: f64) -> CustomBatch {
        let mut batch = CustomBatch {
            group: self.index,
            ..CustomBatch::default()
        };
        if !self.features.custom.started.is_empty() {
            let started = std::mem::take(&mut self.features.custom.started);
            for (idx, spec) in started {
                if self.custom_is_running(spec.id) {
                    self.features.custom.started.push((idx, spec));
                } else {
                    batch.cleanups.push((idx, spec));
                }
            }
        }
        let pos = self.exec.pos;
        let Some((index, m)) = self.custom_running(None) else {
            return batch;
        };
        if m.start_at(pos) {
            let spec = m.spec.clone();
            for r in self.exec.running.iter_mut() {
                if matches!(&r.cmd.plan, Plan::Custom(c) if c.spec.id == spec.id) {
                    r.cmd.target = pos;
                }
            }
            self.info_touched();
            self.features.custom.started.push((index, spec.clone()));
            batch.call = Some(Call::Start {
                spec,
                index,
                start: pos,
            });
        } else {
            batch.call = self.custom_step(dt);
        }
        batch
    }

    /// `start` of command `id` returned `tot`: checks it, plans the profile, and returns
    /// the next call (None when the command is gone or the group stopped).
    pub fn custom_begin(&mut self, id: u64, tot: f64, dt: f64) -> Option<Call> {
        let (feed, acc_ms, dec_ms) = {
            let r = self.exec.running.iter().find(
                |r| matches!(&r.cmd.plan, Plan::Custom(m) if m.spec.id == id && !m.ended()),
            )?;
            (r.cmd.info_feed, r.cmd.acc_ms, r.cmd.dec_ms)
        };
        let blend_on = self.exec.blend_on;
        let ratio = self.speed_ratio();
        let (index, m) = self.custom_running(Some(id))?;
        // A custom motion that follows the override starts at the rate in effect, as a
        // line does.
        let feed = if m.follows_override() {
            feed * ratio
        } else {
            feed
        };
        let len = if m.infinite() {
            feed * dt * INFINITE_PERIODS
        } else {
            tot
        };
        let period_ms = dt * 1000.0;
        let ramps = ramp_periods(acc_ms, dec_ms, period_ms);
        let shapes = (m.acc, m.dec);
        if !(tot.is_finite() && tot >= 0.0 && feed > 0.0) {
            self.stop_for(Some(ERR_CUSTOM_MOTION));
            return None;
        }
        let profile = TickProfile::plan(len, 0.0, feed, ramps.0, ramps.1, shapes, dt);
        // Both ramp shapes cover half the peak speed times their time.
        let interval = 0.5 * profile.speed() * f64::from(ramps.0) * dt;
        m.plan(tot, Track::new(profile, feed, ramps, shapes));
        if m.spec.blending.is_some() && blend_on {
            m.blend_over(interval);
            return Some(Call::BlendStart {
                spec: m.spec.clone(),
                index,
                start: m.start,
                interval,
            });
        }
        self.custom_step(dt)
    }

    /// `BlendingStart` of command `id` returned `accepted`: the next call.
    pub fn custom_blending(&mut self, id: u64, accepted: bool, dt: f64) -> Option<Call> {
        let (_, m) = self.custom_running(Some(id))?;
        m.set_blending(accepted);
        self.custom_step(dt)
    }

    /// The interpolation call for the coming tick.
    fn custom_step(&mut self, _dt: f64) -> Option<Call> {
        let cur = self.exec.pos;
        let (index, m) = self.custom_running(None)?;
        let step = m.next_step()?;
        Some(Call::Interp {
            spec: m.spec.clone(),
            index,
            start: m.start,
            cur,
            dist: step.dist(),
            tot: m.total(),
            blend: m.blend_pending(),
            step,
        })
    }

    /// Stores what the interpolation callback of command `id` gave for the coming tick.
    /// Returns whether its blend ended with this call (`BlendingEnd` is due).
    pub fn custom_apply(
        &mut self,
        id: u64,
        ok: bool,
        abort: bool,
        next: &Axes,
        step: Step,
    ) -> bool {
        let axes = self.mech.axes;
        let offset = self.exec.offset;
        let Some((_, m)) = self.custom_running(Some(id)) else {
            return false;
        };
        if !ok && matches!(m.spec.interp, Interp::Custom(_)) {
            // As the vendor's library: FALSE is a failure, not an end. The group stops
            // where the last good offset put it, with error record 0xF107.
            let blend_end = m.end_blend();
            self.stop_for(Some(ERR_CUSTOM_FALSE));
            return blend_end;
        }
        let mask = m.spec.mask;
        let next: Axes = std::array::from_fn(|i| if mask & (1 << i) != 0 { next[i] } else { 0.0 });
        let bad = (0..AXES).any(|i| {
            let x = m.start[i] + next[i];
            !next[i].is_finite()
                || range::position(x, axes[i].factor).is_err()
                || range::position(x + offset[i], axes[i].factor).is_err()
        });
        if bad {
            self.stop_for(Some(ERR_CUSTOM_MOTION));
            return false;
        }
        let ended = !ok || abort || step.is_last();
        let blend_end = m.advance(next, step, ended);
        if ended {
            let target: Axes = std::array::from_fn(|i| m.start[i] + next[i]);
            for r in self.exec.running.iter_mut() {
                if matches!(&r.cmd.plan, Plan::Custom(c) if c.spec.id == id) {
                    r.cmd.target = target;
                }
            }
            self.info_touched();
            // Later commands were planned from where this one started (its end was not
            // known): they move with it, translated by its displacement, and so does the
            // queue's end.
            if next != [0.0; AXES] {
                for cmd in self.queued.commands.iter_mut() {
                    translate(cmd, &next);
                }
                for (q, d) in self.queued.end.iter_mut().zip(next) {
                    *q += d;
                }
            }
        }
        blend_end
    }
}
