//! A group's cruise along a line: the periods of a cruise plan in which its one running
//! command is a line at its constant speed. What those periods compute from stays the
//! same for the whole plan (the line, the base position, the fraction's terms, which
//! axes move, where the feed speed comes from), so the plan copies it once into a
//! [`CruiseLine`] and each period computes only the moving axes' positions and speeds
//! and the feed speed, as the ordinary period computes them, to the bit.

use super::running::Progress;
use super::GroupState;
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::engine::snapshot::{axis_pulses, SnapshotCell};
use crate::machine::Channel;
use crate::planner::compose::{composed_speed, XYZ_MASK};
use crate::planner::{periods_f64, Axes, LineSeg, SteadyFraction};

/// Where a line's feed speed comes from (`GroupState::feed_speed` for a line).
#[derive(Debug, Clone, Copy)]
enum Feed {
    /// The speed of this axis: a line on the auxiliary axes alone, along its longest.
    Axis(usize),
    /// The speeds of X, Y and Z composed (the default composition).
    Xyz,
    /// The speeds composed over this mask.
    Composed(u32),
}

/// A moving axis that commands a channel, with what its pulses are computed from.
#[derive(Debug, Clone, Copy, Default)]
struct Commanding {
    axis: u8,
    channel: u8,
    /// The axis's reference offset and pulses per UU.
    offset: f64,
    factor: f64,
}

/// What a group's cruise periods along a line compute from, copied when a cruise plan
/// starts ([`GroupState::prepare_cruise`]), and valid for that plan's ticks: only
/// cruise ticks run until it ends, and nothing else changes the group meanwhile. Any
/// other period drops it.
#[derive(Debug, Clone)]
pub(super) struct CruiseLine {
    /// The running line.
    line: LineSeg,
    /// The fractions of the periods at its constant speed.
    fraction: SteadyFraction,
    /// The last period (of the running command's own count) it covers.
    last: u64,
    /// The period it was planned for, seconds.
    dt: f64,
    /// The axes whose position a period changes, `moving` of them: all those of the line
    /// except the ones that stand still at a speed of +0.
    axes: [u8; AXES],
    moving: u8,
    /// The position of everything finished, and per axis (bit i) whether it differs from
    /// the line's start: the position is then the base plus the distance along the line.
    base: Axes,
    shifted: u8,
    feed: Feed,
    /// The moving axes that command a channel of the card, `commanding` of them; and
    /// whether a period of the plan has commanded every channel of the group (from then
    /// on the others keep their command: their axes' pulses do not change).
    channels: [Commanding; AXES],
    commanding: u8,
    all_commanded: bool,
    /// Whether a period of the plan has published the whole motion part (from then on
    /// only the moving axes' words and the feed speed change).
    all_published: bool,
}

impl CruiseLine {
    /// The position of axis `i` after fraction `f` (strictly between 0 and 1), as
    /// `GroupState::compute_pos` computes it for one running path.
    #[inline(always)]
    fn axis(&self, i: usize, f: f64) -> f64 {
        let p = self.line.axis_at(i, f);
        if self.shifted >> i & 1 == 0 {
            p
        } else {
            self.base[i] + (p - self.line.start()[i])
        }
    }

    /// Period `k` of the running command: the moving axes' positions `pos` and speeds
    /// `vel` (from the positions one period before, in `pos`), and the feed speed.
    /// `None`, having changed nothing, where it does not cover the period.
    #[inline(always)]
    fn period(&self, k: u64, dt: f64, pos: &mut Axes, vel: &mut Axes) -> Option<f64> {
        if k > self.last || dt != self.dt {
            return None;
        }
        let f = self.fraction.at(k);
        if !(f > 0.0 && f < 1.0) {
            return None;
        }
        // X², Y², Z² (axes 0 to 2) summed in axis order as the speeds are computed, which
        // is the sum `composed_speed` makes of them (the axes left out add +0 exactly):
        // the feed speed without reading back the speeds just stored.
        let mut xyz = 0.0;
        for &a in &self.axes[..usize::from(self.moving).min(AXES)] {
            let i = usize::from(a) % AXES;
            let q = self.axis(i, f);
            let v = (q - pos[i]) / dt;
            vel[i] = v;
            pos[i] = q;
            if i < 3 {
                xyz += v * v;
            }
        }
        Some(match self.feed {
            Feed::Xyz => match xyz.sqrt() {
                inside if inside > 0.0 => inside,
                _ => composed_speed(vel, XYZ_MASK),
            },
            Feed::Axis(i) => vel[i % AXES].abs(),
            Feed::Composed(mask) => composed_speed(vel, mask),
        })
    }
}

impl GroupState {
    /// Copies what the group's next `ticks` periods compute from, when they are cruise
    /// periods along a line at its constant speed (see the module); drops any copy of
    /// an earlier plan otherwise. `dt`: the period, seconds.
    pub fn prepare_cruise(&mut self, dt: f64, ticks: u32) {
        self.exec.cruise = self.cruise_line(dt, ticks);
    }

    /// The [`CruiseLine`] of the next `ticks` periods, if they run along a line at its
    /// constant speed, with nothing else to do (what `GroupState::one_path_period`
    /// asks).
    fn cruise_line(&self, dt: f64, ticks: u32) -> Option<CruiseLine> {
        if dt.is_nan() || dt <= 0.0 {
            return None;
        }
        let r = self.plain_running()?;
        let (Progress::Path { track, sync: None }, Plan::Path(m)) = (&r.progress, &r.cmd.plan)
        else {
            return None;
        };
        let line = m.path.as_line()?;
        let fraction = track.steady()?;
        let done = track.periods_done();
        if done + 1 < fraction.first() {
            return None;
        }
        let last = fraction.last().min(done + u64::from(ticks));
        let feed = if m.path.aux_only() {
            Feed::Axis(m.path.lead_axis())
        } else if self.settings.compose == XYZ_MASK {
            Feed::Xyz
        } else {
            Feed::Composed(self.settings.compose)
        };
        let mut plan = CruiseLine {
            line: line.clone(),
            fraction,
            last,
            dt,
            axes: [0; AXES],
            moving: 0,
            base: self.exec.base,
            shifted: 0,
            feed,
            channels: [Commanding::default(); AXES],
            commanding: 0,
            all_commanded: false,
            all_published: false,
        };
        for i in 0..AXES {
            if self.exec.base[i] != line.start()[i] {
                plan.shifted |= 1 << i;
            }
        }
        for i in 0..AXES {
            // An axis the line does not move stays where it is at a speed of +0: left
            // alone if it is there already (any fraction gives it the same position).
            let (p, v) = (self.exec.pos[i], self.exec.vel[i]);
            let still = line.delta()[i] == 0.0
                && p.is_finite()
                && plan.axis(i, 0.5).to_bits() == p.to_bits()
                && v.to_bits() == 0;
            if !still {
                plan.axes[usize::from(plan.moving)] = i as u8;
                plan.moving += 1;
            }
        }
        for (i, ch) in self.mech.commanded.pairs() {
            if plan.axes[..usize::from(plan.moving)].contains(&(i as u8)) {
                plan.channels[usize::from(plan.commanding)] = Commanding {
                    axis: i as u8,
                    channel: ch as u8,
                    offset: self.exec.offset[i],
                    factor: self.mech.axes[i].factor,
                };
                plan.commanding += 1;
            }
        }
        Some(plan)
    }

    /// The channels of a cruise period along a cruise plan's line, once a period of the
    /// plan has commanded every channel of the group: only the moving axes' channels (the
    /// others would get the command they have), and true. False, having commanded
    /// nothing, otherwise: the caller commands every channel
    /// ([`GroupState::command_channels`]), which the plan then counts as done.
    #[inline(always)]
    pub fn command_moving_channels(&mut self, cards: &mut [[Channel; AXES]]) -> bool {
        let Some(plan) = &mut self.exec.cruise else {
            return false;
        };
        if !plan.all_commanded {
            plan.all_commanded = true;
            return false;
        }
        let Some(chans) = cards.get_mut(self.mech.commanded.card()) else {
            return true;
        };
        for c in &plan.channels[..usize::from(plan.commanding).min(AXES)] {
            let pos = self.exec.pos[usize::from(c.axis) % AXES];
            chans[usize::from(c.channel) % AXES].command(axis_pulses(pos, c.offset, c.factor));
        }
        true
    }

    /// Publishes the motion part after a cruise period ([`GroupState::store_motion`]):
    /// along a cruise plan's line, once a period of the plan has published all of it,
    /// only the words a period changes (the moving axes' and the feed speed).
    #[inline(always)]
    pub fn store_cruise_motion(&mut self, cell: &SnapshotCell) {
        match &mut self.exec.cruise {
            Some(plan) if plan.all_published => {
                let moving = &plan.axes[..usize::from(plan.moving).min(AXES)];
                cell.store_moving_parts(moving, &self.exec.pos, &self.exec.vel, self.exec.feed_now);
                // What readers find is all of the motion (the status too), to the bit.
                #[cfg(debug_assertions)]
                {
                    let bits = |m: &crate::engine::snapshot::Motion| {
                        let (p, v) = (m.pos.map(f64::to_bits), m.vel.map(f64::to_bits));
                        (m.status, p, v, m.feed.to_bits())
                    };
                    assert_eq!(bits(&cell.load_motion()), bits(&self.motion()));
                }
            }
            Some(plan) => {
                plan.all_published = true;
                self.store_motion(cell);
            }
            None => self.store_motion(cell),
        }
    }

    /// A cruise period along the line of [`GroupState::prepare_cruise`]: what
    /// `GroupState::one_path_period` does then, for the moving axes only. False, having
    /// changed nothing, when there is no such line or it does not cover this period.
    #[inline(always)]
    pub(super) fn cruise_line_period(&mut self, dt: f64) -> bool {
        let Some(plan) = &self.exec.cruise else {
            return false;
        };
        let Some(r) = self.exec.running.front_mut() else {
            return false;
        };
        let Progress::Path { track, .. } = &mut r.progress else {
            return false;
        };
        #[cfg(debug_assertions)]
        let before = (self.exec.pos, self.exec.vel, *track, r.periods);
        let Some(feed) = plan.period(
            track.periods_done() + 1,
            dt,
            &mut self.exec.pos,
            &mut self.exec.vel,
        ) else {
            return false;
        };
        r.periods += 1;
        track.step_within();
        self.exec.feed_now = feed;
        self.publishing.newest_own_time = periods_f64(r.periods);
        #[cfg(debug_assertions)]
        self.check_cruise_line_period(dt, before);
        true
    }

    /// The first running command's track and periods, if it runs along a path.
    #[cfg(debug_assertions)]
    fn front_track(&self) -> Option<(crate::engine::track::Track, u64)> {
        match self.exec.running.front() {
            Some(r) => match &r.progress {
                Progress::Path { track, .. } => Some((*track, r.periods)),
                _ => None,
            },
            None => None,
        }
    }

    /// In debug builds, every cruise period along a line is run again as the ordinary
    /// period and must give the same doubles.
    #[cfg(debug_assertions)]
    fn check_cruise_line_period(
        &mut self,
        dt: f64,
        before: (Axes, Axes, crate::engine::track::Track, u64),
    ) {
        let bits = |a: &Axes| a.map(f64::to_bits);
        let after = (
            bits(&self.exec.pos),
            bits(&self.exec.vel),
            self.exec.feed_now.to_bits(),
            self.publishing.newest_own_time.to_bits(),
        );
        let after_track = self.front_track();
        let (pos, vel, track, periods) = before;
        self.exec.pos = pos;
        self.exec.vel = vel;
        if let Some(r) = self.exec.running.front_mut() {
            r.progress = Progress::Path { track, sync: None };
            r.periods = periods;
        }
        assert!(self.one_path_period(dt, false), "an ordinary path period");
        let ordinary = (
            bits(&self.exec.pos),
            bits(&self.exec.vel),
            self.exec.feed_now.to_bits(),
            self.publishing.newest_own_time.to_bits(),
        );
        assert_eq!(
            after, ordinary,
            "group {}: a cruise period along a line",
            self.index
        );
        let ordinary_track = self.front_track();
        assert_eq!(after_track, ordinary_track, "group {}", self.index);
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_group;
    use super::*;

    /// 1 ms periods, as the test group's.
    const DT: f64 = 0.001;

    /// [`test_group`] running a line to `to` from 0.
    fn group_on_line(to: Axes) -> GroupState {
        let mut g = test_group();
        let cmd = g.ctx().line(to).expect("line");
        g.enqueue(cmd).expect("queued");
        g
    }

    /// What a program reads of a period: positions, speeds and the feed speed, as bits.
    fn seen(g: &GroupState) -> ([u64; AXES], [u64; AXES], u64) {
        let m = g.motion();
        (
            m.pos.map(f64::to_bits),
            m.vel.map(f64::to_bits),
            m.feed.to_bits(),
        )
    }

    #[test]
    fn a_cruise_along_a_line_reads_as_the_ordinary_periods_to_the_bit() {
        // X, Y and the fourth axis move (X and Y compose the feed speed, the fourth does
        // not); Z and the others stand. The line's XYZ length is √125 ≈ 11.18 UU at
        // 10 UU/s: accelerating to period 100, at speed to period 1119, then
        // decelerating. Both groups run the ordinary periods to period 150; then one
        // cruises along a plan of 2000 ticks, the other runs on as before.
        let to = [10.0, -5.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0];
        let (mut plain, mut cruising) = (group_on_line(to), group_on_line(to));
        for _ in 0..150 {
            plain.tick(DT);
            cruising.tick(DT);
        }
        assert_eq!(seen(&plain), seen(&cruising));
        cruising.prepare_cruise(DT, 2000);
        let plan = cruising
            .exec
            .cruise
            .clone()
            .expect("a cruise along the line");
        assert_eq!(&plan.axes[..usize::from(plan.moving)], [0, 1, 3]);
        let mut cruised = 0;
        for tick in 151.. {
            plain.tick(DT);
            if !cruising.cruise_line_period(DT) {
                // The plan covers the periods at speed alone: its last is where the
                // deceleration starts, and it leaves the next one as it was.
                assert_eq!(tick - 1, plan.last, "the plan ends where it said");
                break;
            }
            cruised += 1;
            assert_eq!(seen(&plain), seen(&cruising), "period {tick}");
        }
        // The deceleration's start: 100 ramp periods plus the periods at speed. The two
        // ramps cover 0.5 UU each (half the speed for 0.1 s), the periods at speed the
        // other √125 − 1 = 10.1803 UU at 0.01 UU a period: 1018.03, rounded up to whole
        // periods (the speed lowered to fit).
        assert_eq!(plan.last, 100 + 1019);
        assert_eq!(cruised, plan.last - 150);
    }

    #[test]
    fn a_plan_covers_no_acceleration_and_no_other_path() {
        // In the acceleration: no cruise yet (the fraction is not a sum there).
        let mut g = group_on_line([10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        for _ in 0..50 {
            g.tick(DT);
        }
        g.prepare_cruise(DT, 10);
        assert!(g.exec.cruise.is_none(), "accelerating");
        // At speed: a plan, which an ordinary period drops.
        for _ in 0..100 {
            g.tick(DT);
        }
        g.prepare_cruise(DT, 10);
        assert!(g.exec.cruise.is_some(), "at speed");
        g.tick(DT);
        assert!(g.exec.cruise.is_none(), "an ordinary period drops the plan");
        // A plan of another period length than the tick's covers nothing.
        g.prepare_cruise(DT, 10);
        assert!(!g.cruise_line_period(2.0 * DT));
    }
}
