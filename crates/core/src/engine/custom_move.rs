//! A custom motion command (`MCC_CustomMotion`, `MCC_InfiniteMotion`): what was queued,
//! and its progress as the custom stage drives it, period by period, along its track.

use super::custom::{CustomSpec, Interp};
use super::track::Track;
use crate::config::AXES;
use crate::planner::{Axes, Shape};
use std::sync::Arc;

/// A queued or running custom command.
#[derive(Debug, Clone)]
pub struct CustomMove {
    /// The callbacks and their settings.
    pub(in crate::engine) spec: Arc<CustomSpec>,
    /// Where the command started (the queue's end when queued, the group's position
    /// once started).
    pub(in crate::engine) start: Axes,
    /// Acceleration shape captured when queued.
    pub(in crate::engine) acc: Shape,
    /// Deceleration shape captured when queued.
    pub(in crate::engine) dec: Shape,
    run: Run,
}

/// Progress of a custom command.
#[derive(Debug, Clone, Default)]
struct Run {
    started: bool,
    /// The profile along the total distance, once `start` returned it.
    track: Option<Track>,
    /// The total distance `start` returned.
    tot: f64,
    /// Distance of the offset stored.
    dist: f64,
    /// Offset from the start for the coming tick.
    offset: Axes,
    /// Velocity per unit of own time.
    vel: Axes,
    ended: bool,
    /// Ex with blending on: `BlendingStart` returned TRUE; the blend lasts `interval`.
    blending: bool,
    blend_done: bool,
    interval: f64,
}

impl CustomMove {
    /// A custom command queued from `start`, with the group's ramp shapes.
    pub fn new(spec: Arc<CustomSpec>, start: Axes, acc: Shape, dec: Shape) -> CustomMove {
        CustomMove {
            spec,
            start,
            acc,
            dec,
            run: Run::default(),
        }
    }

    /// Starts it from `pos`: whether it had not started yet (only then is `pos` taken).
    pub fn start_at(&mut self, pos: Axes) -> bool {
        if self.run.started {
            return false;
        }
        self.run.started = true;
        self.start = pos;
        true
    }

    /// Takes the total distance `start` returned and the track along it.
    pub fn plan(&mut self, tot: f64, track: Track) {
        self.run.tot = tot;
        self.run.track = Some(track);
    }

    /// The total distance `start` returned (0 before).
    pub fn total(&self) -> f64 {
        self.run.tot
    }

    /// A blend with the command before, if `BlendingStart` accepts it, lasts `interval`.
    pub fn blend_over(&mut self, interval: f64) {
        self.run.interval = interval;
    }

    /// What `BlendingStart` returned.
    pub fn set_blending(&mut self, accepted: bool) {
        self.run.blending = accepted;
    }

    /// Whether it blends and the blend has not ended.
    pub fn blend_pending(&self) -> bool {
        self.run.blending && !self.run.blend_done
    }

    /// Ends a blend in progress (the command failed): whether one was.
    pub fn end_blend(&mut self) -> bool {
        let pending = self.blend_pending();
        self.run.blend_done |= pending;
        pending
    }

    /// The step of the coming tick along its track (None before `plan`): the distance
    /// the callback is asked for, whether it is the last.
    pub fn next_step(&self) -> Option<Step> {
        let mut next = *self.run.track.as_ref()?;
        next.step();
        let last = !self.infinite() && next.arrived();
        let dist = if last {
            self.run.tot
        } else {
            next.dist().max(self.run.dist)
        };
        Some(Step {
            dist,
            last,
            offset_now: self.run.offset,
        })
    }

    /// Stores the offset `next` the callback gave for `step` and moves the track on;
    /// `ended` ends the command. Returns whether its blend ended with this step
    /// (`BlendingEnd` is due).
    pub fn advance(&mut self, next: Axes, step: Step, ended: bool) -> bool {
        self.run.vel = [0.0; AXES];
        self.run.offset = next;
        if let Some(t) = self.run.track.as_mut() {
            t.step();
        }
        self.run.dist = step.dist;
        let blend_end = self.blend_pending() && (ended || step.dist >= self.run.interval);
        if blend_end {
            self.run.blend_done = true;
        }
        if ended {
            self.run.ended = true;
        }
        blend_end
    }

    /// Whether the stage ended it.
    pub fn ended(&self) -> bool {
        self.run.ended
    }

    /// Its track, once its total distance is known.
    pub fn track_mut(&mut self) -> Option<&mut Track> {
        self.run.track.as_mut()
    }

    /// Whether an override changes its speed (`bOverrideMotion`).
    pub fn follows_override(&self) -> bool {
        self.spec.override_motion
    }

    /// Position and velocity per own time: the start plus the offset stored.
    pub fn sample(&self) -> (Axes, Axes) {
        (
            std::array::from_fn(|i| self.start[i] + self.run.offset[i]),
            self.run.vel,
        )
    }

    pub fn infinite(&self) -> bool {
        matches!(self.spec.interp, Interp::Infinite(_))
    }
}

/// One period's step the stage computed: applied if the command still runs.
#[derive(Debug, Clone, Copy)]
pub struct Step {
    dist: f64,
    last: bool,
    /// The offset stored now (what the callback's output starts as).
    pub offset_now: Axes,
}

impl Step {
    /// The distance along the track the callback is asked for.
    pub fn dist(&self) -> f64 {
        self.dist
    }

    /// Whether it is the command's last.
    pub fn is_last(&self) -> bool {
        self.last
    }
}
