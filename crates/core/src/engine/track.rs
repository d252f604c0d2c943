//! The progress of a running motion along a length (a path, or one axis's travel), one
//! period at a time, and how a hold, a continue, an override or a timed abort re-plans
//! what is left of it (the vendor's library, measured: docs/decisions.md "Motion as the
//! vendor's library runs it").

use crate::planner::{Shape, SteadyFraction, TickProfile};

/// Where a track is on its profile, as `COMMAND_INFO.nMotionPhase` shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Ramping up to its speed.
    Accelerating,
    /// At its speed.
    Cruising,
    /// Ramping down (to a lower speed or to a stop).
    Decelerating,
}

/// Where a track was one period ago.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Prev {
    /// At this distance (set where the profile changes, or when the stretch had ended).
    At(f64),
    /// One period back along the running profile (computed when asked: a step that only
    /// moves on does not compute it).
    PeriodBefore,
}

/// A motion's progress along `len`: the profile of the stretch running now (the plan
/// from rest, or a re-plan) and how far the stretches before it came.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Track {
    profile: TickProfile,
    /// Distance covered before `profile` started.
    s0: f64,
    /// Periods of `profile` done.
    k: u64,
    /// Distance one period ago (the last period's speed is what a re-plan starts from).
    prev: Prev,
    /// The whole length.
    len: f64,
    /// The feed speed it was planned with.
    base_feed: f64,
    /// The feed speed it runs at (`base_feed` times an override).
    feed: f64,
    ramps: (u32, u32),
    shapes: (Shape, Shape),
}

impl Track {
    /// A track running `profile` (planned from rest over `len` at `feed` with these
    /// ramps) from its start.
    pub fn new(
        profile: TickProfile,
        feed: f64,
        ramps: (u32, u32),
        shapes: (Shape, Shape),
    ) -> Track {
        Track {
            profile,
            s0: 0.0,
            k: 0,
            prev: Prev::At(0.0),
            len: profile.len(),
            base_feed: feed,
            feed,
            ramps,
            shapes,
        }
    }

    /// A track running `profile` from its start, whose override re-plans scale `nominal`,
    /// the speed it was planned at, while a continue after a hold runs at the speed the
    /// profile cruises at: a point-to-point axis, which the vendor's library re-plans
    /// under an override from its nominal speed [`mix_18`, `mix_23`].
    pub fn with_nominal(
        profile: TickProfile,
        nominal: f64,
        ramps: (u32, u32),
        shapes: (Shape, Shape),
    ) -> Track {
        Track {
            base_feed: nominal,
            ..Track::new(profile, profile.speed(), ramps, shapes)
        }
    }

    /// Distance covered.
    #[inline]
    pub fn dist(&self) -> f64 {
        if self.k >= self.profile.periods() {
            return self.s0 + self.profile.len();
        }
        self.s0 + self.profile.distance(self.k)
    }

    /// The fraction of the whole length covered: the profile's own fraction while the
    /// track runs its first plan (so that positions land on the vendor's doubles), the
    /// distance over the length after a re-plan.
    #[inline]
    pub fn fraction(&self) -> f64 {
        if self.s0 == 0.0 && self.profile.len() == self.len {
            return self.profile.fraction(self.k);
        }
        if self.len > 0.0 {
            self.dist() / self.len
        } else {
            1.0
        }
    }

    /// The periods of its first plan at the constant speed, when it runs that plan
    /// ([`TickProfile::steady`]): [`Track::fraction`] after `k` periods is then
    /// [`SteadyFraction::at`] of `k`, for `k` inside them.
    pub fn steady(&self) -> Option<SteadyFraction> {
        if self.s0 == 0.0 && self.profile.len() == self.len {
            self.profile.steady()
        } else {
            None
        }
    }

    /// Periods of the running stretch done.
    #[inline]
    pub fn periods_done(&self) -> u64 {
        self.k
    }

    /// Whether the running stretch has ended.
    #[inline]
    pub fn stretch_done(&self) -> bool {
        self.k >= self.profile.periods()
    }

    /// Whether the whole length is covered (and the stretch ended).
    pub fn arrived(&self) -> bool {
        self.stretch_done() && self.s0 + self.profile.len() >= self.len
    }

    /// [`Track::step`] of a track whose running stretch has not ended (a plan made
    /// sure): it moves one period on.
    #[inline(always)]
    pub fn step_within(&mut self) {
        debug_assert!(!self.stretch_done(), "the stretch runs on");
        self.prev = Prev::PeriodBefore;
        self.k += 1;
    }

    /// Moves one period on. Returns whether it moved.
    #[inline]
    pub fn step(&mut self) -> bool {
        if self.k >= self.profile.periods() {
            self.prev = Prev::At(self.dist());
            return false;
        }
        self.prev = Prev::PeriodBefore;
        self.k += 1;
        true
    }

    /// The distance one period ago.
    fn prev_dist(&self) -> f64 {
        match self.prev {
            Prev::At(d) => d,
            // `dist()` one period ago: `k - 1` is inside the profile.
            Prev::PeriodBefore => self.s0 + self.profile.distance(self.k - 1),
        }
    }

    /// Keeps the distance one period ago as a number, before the profile changes.
    fn fix_prev(&mut self) {
        self.prev = Prev::At(self.prev_dist());
    }

    /// The average speed over the last period (distance over the period).
    pub fn last_speed(&self) -> f64 {
        let t = self.profile.period();
        if t > 0.0 {
            (self.dist() - self.prev_dist()) / t
        } else {
            0.0
        }
    }

    /// Periods until the running stretch ends.
    pub fn periods_left(&self) -> u64 {
        self.profile.periods().saturating_sub(self.k)
    }

    /// Periods until the stretch starts decelerating (0 once it does).
    pub fn periods_to_decel(&self) -> u64 {
        self.profile.decel_start().saturating_sub(self.k)
    }

    /// Periods of the deceleration done (0 before it starts).
    pub fn decel_periods_done(&self) -> u64 {
        self.k.saturating_sub(self.profile.decel_start())
    }

    /// Periods until the acceleration ends (0 once it has).
    pub fn periods_to_cruise(&self) -> u64 {
        u64::from(self.profile.acc_periods()).saturating_sub(self.k)
    }

    /// Periods the running stretch stays in its phase ([`Track::phase`]) after this one:
    /// until the end of its acceleration, the start of its deceleration, or its end.
    pub fn periods_in_phase(&self) -> u64 {
        let p = &self.profile;
        if self.k <= u64::from(p.acc_periods()) && p.acc_periods() > 0 {
            self.periods_to_cruise()
        } else if self.k <= p.decel_start() {
            self.periods_to_decel()
        } else {
            self.periods_left()
        }
    }

    /// Where the running stretch is.
    pub fn phase(&self) -> Phase {
        let p = &self.profile;
        if self.k <= u64::from(p.acc_periods()) && p.acc_periods() > 0 {
            if p.start_speed() > p.speed() {
                Phase::Decelerating
            } else {
                Phase::Accelerating
            }
        } else if self.k <= p.decel_start() {
            Phase::Cruising
        } else {
            Phase::Decelerating
        }
    }

    /// Whether the running stretch is the last deceleration of the whole length (a hold
    /// then changes nothing).
    pub fn in_final_decel(&self) -> bool {
        self.k > self.profile.decel_start() && self.s0 + self.profile.len() >= self.len
    }

    fn restart(&mut self, profile: TickProfile) {
        self.fix_prev();
        self.s0 = self.dist();
        self.k = 0;
        self.profile = profile;
    }

    /// A hold or a timed abort: stops from the last period's speed (times `chord`, the
    /// last period's chord over its length: 1 but on an arc) with the deceleration `dec_s`
    /// gives at the full feed ([`TickProfile::stop`]).
    pub fn stop(&mut self, dec_s: f64, chord: f64) {
        self.stop_from(self.last_speed() * chord, dec_s);
    }

    /// [`Track::stop`] from the speed `v0`.
    pub fn stop_from(&mut self, v0: f64, dec_s: f64) {
        let t = self.profile.period();
        // The full feed the deceleration is measured against: the speed the running
        // stretch cruises at (the feed rounded to whole periods), as the vendor's library
        // stops (measured: `mix_1`, a hold while accelerating; `arc_hold_cruise_t`).
        let full = if self.profile.speed() > 0.0 {
            self.profile.speed()
        } else {
            self.feed
        };
        let stop = TickProfile::stop(v0, full, dec_s, self.shapes.1, t);
        self.restart(stop);
    }

    /// A continue after a hold: what is left, from rest, with the track's feed and ramps.
    pub fn resume(&mut self) {
        self.resume_at(self.feed);
    }

    /// A continue after a hold: what is left, from rest, at the speed it was planned at
    /// times `ratio`, the override now in effect. The vendor's library re-plans the rest
    /// so at a continue, also when the override changed while it was held, or, for a
    /// PtP, while it ran on at its rate [`ptp_hold_ovr_*`, `mix_60`, `mix_73`].
    pub fn resume_nominal(&mut self, ratio: f64) {
        self.feed = self.base_feed * ratio;
        self.resume_at(self.feed);
    }

    fn resume_at(&mut self, feed: f64) {
        let left = (self.len - self.dist()).max(0.0);
        let t = self.profile.period();
        let p = TickProfile::plan(left, 0.0, feed, self.ramps.0, self.ramps.1, self.shapes, t);
        self.restart(p);
    }

    /// An override: what is left, from the last period's speed (times `chord`, see
    /// [`Track::stop`]), at the planned feed times `ratio`. When what is left is too short
    /// even for the ramp from that speed (no peak speed comes out: the end of a
    /// deceleration), the motion runs on as planned, as the vendor's library leaves it
    /// [`mix_17`, `mix_18`, `mix_24`]; the new rate is the next motions'.
    pub fn retarget(&mut self, ratio: f64, chord: f64) {
        let feed = self.base_feed * ratio;
        let left = (self.len - self.dist()).max(0.0);
        let v0 = self.last_speed() * chord;
        let t = self.profile.period();
        let p = TickProfile::plan(left, v0, feed, self.ramps.0, self.ramps.1, self.shapes, t);
        if p.speed() <= 0.0 && left > 0.0 {
            return;
        }
        self.feed = feed;
        self.restart(p);
    }

    /// A new feed (`MCC_ChangeFeedSpeed`), at `ratio`: re-plans what is left.
    pub fn set_base_feed(&mut self, feed: f64, ratio: f64, chord: f64) {
        self.base_feed = feed;
        self.retarget(ratio, chord);
    }

    /// Blending: the deceleration of the running stretch becomes an S ramp (the vendor
    /// blends with S ramps whatever the curve type).
    pub fn blend_out(&mut self) {
        self.fix_prev();
        self.profile = self.profile.with_shapes(self.shapes.0, Shape::S);
    }

    /// Blending: the acceleration of a motion that starts blended in is an S ramp.
    pub fn blend_in(&mut self) {
        let dec = self.profile_shapes().1;
        self.fix_prev();
        self.profile = self.profile.with_shapes(Shape::S, dec);
    }

    fn profile_shapes(&self) -> (Shape, Shape) {
        self.shapes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(len: f64) -> Track {
        let ramps = (100, 100);
        let shapes = (Shape::T, Shape::T);
        let p = TickProfile::plan(len, 0.0, 10.0, ramps.0, ramps.1, shapes, 0.001);
        Track::new(p, 10.0, ramps, shapes)
    }

    #[test]
    fn a_hold_at_speed_stops_half_a_deceleration_later() {
        // The vendor, 2 UU at 10 UU/s, 100 ms T ramps: held after 150 periods (1.0 UU, at
        // speed) it stops at 1.5 UU 101 periods later; continued, the 0.5 UU left run from
        // rest with a peak of 5 UU/s over 200 periods.
        let mut t = line(2.0);
        for _ in 0..150 {
            t.step();
        }
        assert!((t.dist() - 1.0).abs() < 1e-12);
        assert_eq!(t.phase(), Phase::Cruising);
        t.stop(0.1, 1.0);
        assert_eq!(t.periods_left(), 101);
        while t.step() {}
        assert!((t.dist() - 1.5).abs() < 1e-12);
        assert!(!t.arrived());
        t.resume();
        assert_eq!(t.periods_left(), 200);
        t.step();
        assert!((t.last_speed() - 0.025).abs() < 1e-9, "{}", t.last_speed());
        while t.step() {}
        assert!(t.arrived());
        assert_eq!(t.dist(), 2.0);
    }

    #[test]
    fn an_override_replans_from_the_last_periods_speed() {
        // The vendor: 40 % at period 30 of the acceleration; 352 periods at 3.9989 UU/s.
        let mut t = line(2.0);
        for _ in 0..30 {
            t.step();
        }
        t.retarget(0.4, 1.0);
        assert_eq!(t.periods_left(), 552);
        assert_eq!(t.phase(), Phase::Accelerating);
        t.step();
        assert!((t.last_speed() - 2.9552444690265496).abs() < 1e-9);
    }

    #[test]
    fn an_override_at_the_end_of_a_deceleration_changes_nothing() {
        // `mix_17`: a line of 0.042 UU at 9 UU/s with S ramps of 70 and 30 ms never
        // reaches its feed (peak 0.84 UU/s, 100 periods). 8 periods into its deceleration
        // (period 78) it runs at 0.7086 UU/s with 0.0063 UU left: the ramp from that
        // speed over 70 periods would take 0.0248 UU, so no re-plan fits and the vendor's
        // library lets it decelerate as planned; 140 % is the next motions' rate.
        let ramps = (70, 30);
        let shapes = (Shape::S, Shape::S);
        let p = TickProfile::plan(0.042, 0.0, 9.0, ramps.0, ramps.1, shapes, 0.001);
        let mut t = Track::new(p, 9.0, ramps, shapes);
        for _ in 0..78 {
            t.step();
        }
        assert_eq!(t.phase(), Phase::Decelerating);
        assert!(
            (t.last_speed() - 0.70863).abs() < 1e-4,
            "{}",
            t.last_speed()
        );
        let planned = t;
        t.retarget(1.4, 1.0);
        assert_eq!(t, planned, "the profile runs on");
        // While it accelerates (period 30, 0.2 UU/s, 0.039 UU left) a re-plan fits and is
        // made.
        let mut u = Track::new(p, 9.0, ramps, shapes);
        for _ in 0..30 {
            u.step();
        }
        let before = u;
        u.retarget(0.5, 1.0);
        assert_ne!(u, before);
    }

    #[test]
    fn a_point_to_point_axis_replans_from_its_nominal_speed() {
        // `mix_18`: an axis of 0.184247 UU at 0.5 UU/s (120 and 90 ms S ramps) cruises at
        // 0.49931 UU/s (whole periods). Started under a 70 % override, the vendor's
        // library plans it at 0.5 × 0.7 = 0.35 UU/s: 422 periods at speed, 0.349615 UU/s;
        // from the rounded speed (0.34952 UU/s) it would be 423 periods at 0.348953.
        let ramps = (120, 90);
        let shapes = (Shape::S, Shape::S);
        let p = TickProfile::plan(0.184247, 0.0, 0.5, ramps.0, ramps.1, shapes, 0.001);
        let mut t = Track::with_nominal(p, 0.5, ramps, shapes);
        t.retarget(0.7, 1.0);
        assert_eq!(t.periods_left(), 120 + 422 + 90);
        let mut rounded = Track::new(p, p.speed(), ramps, shapes);
        rounded.retarget(0.7, 1.0);
        assert_eq!(rounded.periods_left(), 120 + 423 + 90);
    }
}
