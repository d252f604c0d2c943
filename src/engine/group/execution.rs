//! Execution of the running commands, tick by tick (the model is in the module's
//! documentation, [`super`]): own time per command, starting, blending, retiring, and
//! sampling the position; the software over-travel check.

use super::GroupState;
use super::{InPosWait, Mode, ERR_OVER_TRAVEL, TIME_EPS};
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::trace::Note;
use crate::planner::Axes;
use crate::vendor::consts as c;

/// Converts between real time within a tick and a command's own time: general and PtP
/// motion run at the group's rate, delays in real time (paused while held).
#[derive(Debug, Clone, Copy)]
struct TickClock {
    dt: f64,
    dtau: f64,
    delay_dt: f64,
}

impl TickClock {
    fn per_tick(&self, cmd: &Command) -> f64 {
        match cmd.plan {
            Plan::Delay(_) => self.delay_dt,
            // Advanced by the custom-motion stage (`custom.rs`).
            Plan::Custom(_) => 0.0,
            _ => self.dtau,
        }
    }

    /// `real` seconds of this tick, in `cmd`'s own time.
    fn own_time(&self, real: f64, cmd: &Command) -> f64 {
        if self.dt > 0.0 {
            real / self.dt * self.per_tick(cmd)
        } else {
            0.0
        }
    }

    /// `own` time of `cmd` within this tick, in real seconds.
    fn real_time(&self, own: f64, cmd: &Command) -> f64 {
        let per = self.per_tick(cmd);
        if per > 0.0 {
            (own / per * self.dt).min(self.dt)
        } else {
            0.0
        }
    }
}

/// What a cruising tick adds to its command's own time: `TickClock::own_time(dt, ..)` of
/// a general or PtP command, dt / dt x `dtau`, and dt / dt is exactly 1 for the (finite,
/// positive) period.
#[inline]
fn cruise_step(dt: f64, dtau: f64) -> f64 {
    if dt > 0.0 {
        dtau
    } else {
        0.0
    }
}

/// The own time of `plan` from which a tick may do more than cruise (what `settle` and
/// `try_blend` act on): its end, and with blending on, the start of its deceleration;
/// `None` for commands that do not cruise.
#[inline]
fn cruise_end(plan: &Plan, blend_on: bool) -> Option<f64> {
    match plan {
        Plan::Path(m) => {
            let end = m.duration() - TIME_EPS;
            Some(if blend_on {
                end.min(m.decel_start() - TIME_EPS)
            } else {
                end
            })
        }
        Plan::Ptp(p) => Some(p.duration() - TIME_EPS),
        _ => None,
    }
}

/// How many of the sums `tau + step`, `tau + step + step`, ..., each rounded as the ticks
/// add them, are certainly below `end`, up to `max` (0 when unsure).
///
/// Each sum below `2·end` is rounded by at most `u = end · 2^-52` (half an ulp of `2·end`),
/// so after `k` additions the sum is at most `tau + k·(step + u)`. `k = room / (step +
/// u) - 1`, with `room` the exact `end - tau` less its own rounding and a margin, keeps
/// that below `end`; the division's rounding is what the 1 taken off covers.
fn sums_below(tau: f64, step: f64, end: f64, max: u32) -> u32 {
    if !(tau >= 0.0 && step >= 0.0 && end.is_finite() && tau < end) {
        return 0;
    }
    let u = end * f64::EPSILON;
    let room = (end - tau) * (1.0 - 1e-9) - u;
    if room <= 0.0 {
        return 0;
    }
    let k = (room / (step + u)).floor() - 1.0;
    if k >= f64::from(max) {
        max
    } else if k >= 1.0 {
        // 1 <= k < max: a whole number that fits.
        k as u32
    } else {
        0
    }
}

/// A command being executed and its own time.
#[derive(Debug, Clone)]
pub(super) struct Running {
    pub(super) cmd: Command,
    pub(super) tau: f64,
}

impl GroupState {
    /// One interpolation period of `dt` seconds.
    pub fn tick(&mut self, dt: f64) {
        if self.steady() && (self.tick_cruising(dt) || self.tick_idle()) {
            return;
        }
        self.tick_full(dt);
    }

    /// Whether the group's tick can take one of the short paths: not homing, no
    /// external executor, filters or kinematics, not held or aborting, no rate ramp and
    /// no over-travel check.
    fn steady(&self) -> bool {
        self.homing == 0
            && self.external.is_none()
            && self.post.is_none()
            && self.kin.is_none()
            && self.mode == Mode::Normal
            && self.rate.ramp.is_none()
            && self.ot_check == [false; AXES]
    }

    /// The tick of a [steady](GroupState::steady) group with nothing to do: no command
    /// running or queued and no in-position check. The full tick would only set the
    /// position to where the finished commands left it and the status to `GMS_STOP`;
    /// this does just that. Returns false, having changed nothing, otherwise.
    fn tick_idle(&mut self) -> bool {
        if !self.running.is_empty() || !self.queue.is_empty() || self.inpos_wait.is_some() {
            return false;
        }
        // `compute_pos_vel` with no running command, and `update_status` of a group
        // with nothing active and not held.
        self.pos = self.base;
        self.vel = [0.0; AXES];
        self.status = c::GMS_STOP;
        true
    }

    /// [`GroupState::tick`] when the group does more than cruise or stand idle: kept out
    /// of line, so that the short paths, nearly every tick of most groups, stay small.
    #[inline(never)]
    fn tick_full(&mut self, dt: f64) {
        if self.homing != 0 && self.external.is_none() {
            // The homing sets the positions (`set_homing_axis`).
            self.update_status();
            return;
        }
        if self.external.is_some() {
            return self.tick_external(dt);
        }
        if self.post.is_some() {
            return self.tick_post(dt);
        }
        // Software over-travel compares with the position before the tick (only needed,
        // and so only copied, when a check is on).
        let before = (self.ot_check != [false; AXES]).then_some(self.pos);
        let dtau = self.advance_rate(dt);
        let delay_dt = if self.mode == Mode::Held { 0.0 } else { dt };
        let clock = TickClock { dt, dtau, delay_dt };
        if self.running.is_empty() {
            // An idle group starts its next command at the start of the tick.
            if self.may_start() {
                if let Some(cmd) = self.pop_next() {
                    let tau = clock.own_time(dt, &cmd);
                    self.start(cmd, tau);
                }
            }
        } else {
            for r in self.running.iter_mut() {
                r.tau += clock.own_time(dt, &r.cmd);
            }
            if let Some(r) = self.running.back() {
                self.newest_own_time = r.tau;
            }
        }
        self.settle(&clock);
        self.finish_abort();
        self.compute_pos_vel();
        if let Some(before) = before {
            self.check_over_travel(&before);
        }
        self.update_status();
    }

    /// How many of the next ticks, up to `max`, are certain to take the cruising or the
    /// idle path (`GroupState::tick_cruising`, `GroupState::tick_idle`) and to change
    /// nothing the rest of the engine's tick looks at: no output changes, no safety check,
    /// no go home result, the status unchanged, the published info unchanged (its key
    /// holds, so a publication need not look). 0 when the next tick may do more. Only the
    /// program changes what this depends on (under the groups' lock), besides the ticks.
    pub fn quiet_ticks_ahead(&self, dt: f64, max: u32) -> u32 {
        if !self.steady() || self.has_outputs() || self.has_safety_checks() {
            return 0;
        }
        let Some(key_until) = self.published_key_holds_below() else {
            return 0;
        };
        if self.running.is_empty() {
            let idle = self.queue.is_empty() && self.inpos_wait.is_none();
            // An idle group's status is `GMS_STOP` already after one idle tick.
            return if idle && self.status == c::GMS_STOP {
                max
            } else {
                0
            };
        }
        let Some(r) = self.running.front() else {
            return 0;
        };
        if self.running.len() != 1 || self.status != c::GMS_RUNNING {
            return 0;
        }
        match cruise_end(&r.cmd.plan, self.blend_on) {
            Some(end) => {
                let end = end.min(key_until);
                sums_below(r.tau, cruise_step(dt, self.rate.value * dt), end, max)
            }
            None => 0,
        }
    }

    /// The tick of a [steady](GroupState::steady) group in the middle of one general or
    /// PtP command: only the command's own time advances and the position is sampled.
    /// Returns false, having changed nothing, when the tick may do more (start, blend,
    /// end or retire a command); [`GroupState::tick`] then runs in full. The arithmetic
    /// is that of the full tick, operation for operation, so the positions are the same
    /// to the bit.
    fn tick_cruising(&mut self, dt: f64) -> bool {
        if self.running.len() != 1 {
            return false;
        }
        let dtau = self.rate.value * dt;
        let Some(r) = self.running.front_mut() else {
            return false;
        };
        let tau = r.tau + cruise_step(dt, dtau);
        // (A NaN end holds no tick back.)
        match cruise_end(&r.cmd.plan, self.blend_on) {
            Some(end) if tau >= end => return false,
            Some(_) => {}
            None => return false,
        }
        r.tau = tau;
        self.newest_own_time = tau;
        // `compute_pos_vel` with this one command, without finding it again.
        place_single(
            &mut self.pos,
            &mut self.vel,
            &self.base,
            &r.cmd,
            tau,
            self.rate.value,
        );
        // What `update_status` finds for a group running a motion command.
        self.status = c::GMS_RUNNING;
        true
    }

    pub(super) fn start(&mut self, cmd: Command, tau: f64) {
        let cmd = self.kinematics_start(cmd);
        if cmd.is_motion() {
            self.inpos_status = [0; AXES];
        }
        if let Some(p) = self.rate.pending_override.take() {
            self.override_pct = p;
            if self.mode == Mode::Normal {
                self.retarget_rate();
            }
        }
        self.info_touched();
        self.cmd_index.ld = self.cmd_index.ld.wrapping_add(1);
        self.cmd_index.last_started = Some((cmd.index, self.cmd_index.ld));
        self.note(Note::Start {
            index: cmd.index,
            ctype: cmd.ctype,
        });
        if self.single_block {
            self.single_block_credit = false;
        }
        self.running.push_back(Running { cmd, tau });
        self.newest_own_time = tau;
    }

    /// Software over-travel (user manual §2.6.1): with the check on, an axis never goes
    /// further out of its work zone (dfLowLimit..dfHighLimit). A tick that would take it
    /// out stops the group where it was, records 0xF301 + axis, and motion waits for
    /// `MCC_ClearError`; a move back into the zone is allowed.
    fn check_over_travel(&mut self, before: &Axes) {
        for i in 0..AXES {
            if !self.ot_check[i] || self.axes[i].channel.is_none() {
                continue;
            }
            let (p, b) = (self.pos[i], before[i]);
            let out = (p > self.axes[i].high && p > b) || (p < self.axes[i].low && p < b);
            if out {
                self.pos = *before;
                self.stop_here();
                self.set_error(ERR_OVER_TRAVEL + i as i32);
                return;
            }
        }
    }

    /// After the running commands advanced: blends in the next command, retires finished
    /// commands and hands the rest of the tick to their successors.
    fn settle(&mut self, clock: &TickClock) {
        // Bounded: each pass starts or retires one command.
        for _ in 0..(self.queue.len() + self.running.len() + 2) * 2 {
            if self.try_blend() {
                continue;
            }
            let Some(first) = self.running.front() else {
                return;
            };
            let dur = first.cmd.duration();
            if first.tau < dur - TIME_EPS {
                return;
            }
            let spare = clock.real_time((first.tau - dur).max(0.0), &first.cmd);
            let Some(done) = self.running.pop_front() else {
                return;
            };
            self.info_touched();
            self.note(Note::End {
                index: done.cmd.index,
                ctype: done.cmd.ctype,
                stopped: false,
            });
            if self.running.is_empty() {
                self.base = done.cmd.target;
                if done.cmd.is_motion() && self.inpos_mask != 0 {
                    self.note(Note::InPosBegin(self.inpos_mask));
                    self.inpos_wait = Some(InPosWait {
                        mask: self.inpos_mask,
                        elapsed: 0.0,
                        settled: 0.0,
                        settings: self.inpos,
                    });
                    if self.inpos_wait.is_some_and(|w| w.blocks()) {
                        return;
                    }
                }
            } else {
                let s = done.cmd.start();
                for ((b, t), s) in self.base.iter_mut().zip(done.cmd.target).zip(s) {
                    *b += t - s;
                }
                continue;
            }
            if self.mode == Mode::HoldAtBlockEnd {
                self.mode = Mode::Held;
                self.rate.value = 0.0;
                self.rate.ramp = None;
                return;
            }
            if !self.may_start() {
                return;
            }
            let Some(next) = self.pop_next() else {
                return;
            };
            let tau = clock.own_time(spare, &next);
            self.start(next, tau);
        }
    }

    /// Blending: when the newest general motion has reached its deceleration and the next
    /// queued motion is general too, starts it (docs/decisions.md). Returns whether it did.
    fn try_blend(&mut self) -> bool {
        if !self.blend_on || !self.may_start() {
            return false;
        }
        let Some(last) = self.running.back() else {
            return false;
        };
        let Plan::Path(m) = &last.cmd.plan else {
            return false;
        };
        let ds = m.decel_start();
        if last.tau < ds - TIME_EPS || last.tau >= m.duration() - TIME_EPS || m.duration() <= 0.0 {
            return false;
        }
        let over = (last.tau - ds).max(0.0);
        if !matches!(self.peek_motion(), Some(Plan::Path(_))) {
            return false;
        }
        match self.pop_next() {
            Some(next) => {
                self.start(next, over);
                true
            }
            None => false,
        }
    }

    fn finish_abort(&mut self) {
        if self.mode == Mode::Aborting && self.rate.ramp.is_none() && self.rate.value == 0.0 {
            self.compute_pos_vel();
            self.stop_here();
        }
    }

    fn compute_pos_vel(&mut self) {
        if let (1, Some(r)) = (self.running.len(), self.running.front()) {
            // The usual case, without the sums (the same operations as below).
            place_single(
                &mut self.pos,
                &mut self.vel,
                &self.base,
                &r.cmd,
                r.tau,
                self.rate.value,
            );
            return;
        }
        let mut pos = self.base;
        let mut vel = [0.0; AXES];
        for r in &self.running {
            let (p, v) = r.cmd.sample(r.tau);
            let s = r.cmd.start();
            let scale = if matches!(r.cmd.plan, Plan::Delay(_)) {
                0.0
            } else {
                self.rate.value
            };
            for i in 0..AXES {
                pos[i] += p[i] - s[i];
                vel[i] += v[i] * scale;
            }
        }
        self.pos = pos;
        self.vel = vel;
    }
}

/// The position and velocity of a group whose one running command is `cmd`, at its own
/// time `tau`: the group stood at `base` when the command started and runs at `rate`
/// (`compute_pos_vel` with one command, also the cruise path's).
#[inline(always)]
fn place_single(pos: &mut Axes, vel: &mut Axes, base: &Axes, cmd: &Command, tau: f64, rate: f64) {
    let s = cmd.start();
    let mut v = [0.0; AXES];
    if *base == s {
        // The command starts where the group stands (nearly always): every axis takes
        // the branch `p[i]` of the loop below, so the sample is the position.
        cmd.sample_into(tau, pos, &mut v);
    } else {
        let mut p = [0.0; AXES];
        cmd.sample_into(tau, &mut p, &mut v);
        // An axis that starts where the group stands takes the sample as it is (adding
        // and taking away the start could round); branch-free, so that it vectorizes.
        #[allow(clippy::needless_range_loop)] // indexes four arrays; vectorizes
        for i in 0..AXES {
            let moved = base[i] + (p[i] - s[i]);
            pos[i] = if base[i] == s[i] { p[i] } else { moved };
        }
    }
    let scale = if matches!(cmd.plan, Plan::Delay(_)) {
        0.0
    } else {
        rate
    };
    // `0.0 +` as in the sums of `compute_pos_vel` (it turns -0.0 into 0.0).
    for (out, v) in vel.iter_mut().zip(v) {
        *out = 0.0 + v * scale;
    }
}

#[cfg(test)]
mod tests {
    use super::sums_below;

    #[test]
    fn sums_below_promises_only_sums_below_the_end_and_nearly_all_of_them() {
        // Pseudo-random own times, steps and ends: 1 ms ticks at rates from 0 to 2x,
        // commands from 10 ms to 2^40 s, started anywhere before their end. The sums are
        // made as the ticks make them: every sum promised is below the end, and the
        // promise falls short of the truth by at most 2 (no more than the margin).
        let mut seed = 99u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let max = 64;
        let (mut promised, mut near_end) = (0u64, 0);
        for case in 0..20_000 {
            let end = 0.01 * 2f64.powf(next() * 47.0);
            let step = if case % 50 == 0 { 0.0 } else { 0.002 * next() };
            // Mostly close to the end, where it matters.
            let tau = if case % 2 == 0 {
                end * next()
            } else {
                (end - step * 70.0 * next()).max(0.0)
            };
            let k = sums_below(tau, step, end, max);
            let mut sum = tau;
            let mut below = 0;
            while below < max {
                sum += step;
                if sum >= end {
                    break;
                }
                below += 1;
            }
            assert!(
                k <= below,
                "tau {tau}, step {step}, end {end}: promised {k}, {below} below"
            );
            assert!(
                below - k <= 2 || end * f64::EPSILON * 64.0 > step,
                "tau {tau}, step {step}, end {end}: promised {k}, {below} below"
            );
            promised += u64::from(k);
            near_end += usize::from(below < max);
        }
        assert!(
            promised > 20_000 * 20 && near_end > 5_000,
            "{promised}, {near_end}"
        );
        // What is not a cruise: NaN, a start at or past the end, a negative step.
        assert_eq!(sums_below(f64::NAN, 0.001, 1.0, max), 0);
        assert_eq!(sums_below(1.0, 0.001, 1.0, max), 0);
        assert_eq!(sums_below(0.5, -0.001, 1.0, max), 0);
        assert_eq!(sums_below(0.5, 0.001, f64::INFINITY, max), 0);
        assert_eq!(sums_below(0.5, 0.0, 1.0, max), max);
    }
}
