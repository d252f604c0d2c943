//! One motor's own motion: moves, rate moves, free runs and homing, started by a
//! command and advanced tick by tick, stopped by `S` or a home.

use super::{Emulator, MotorSettings, Profile, EPS, HOMING_SPEED, TICK_S};

/// The phases of homing (§4.14): seek the home, back off it, approach it again.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum HomePhase {
    Seek,
    BackOff,
    Approach,
}

/// What a single-motor motion is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Move,
    Rate,
    /// Free-running; `cmd_dir` is the direction given to `R`.
    Run {
        cmd_dir: u8,
    },
    /// Homing toward `home_dir` (modifier already applied).
    Home {
        home_dir: u8,
        phase: HomePhase,
    },
}

/// One motor's current motion (not synchronous).
#[derive(Debug, Clone)]
pub(super) struct Active {
    pub(super) kind: Kind,
    /// Direction of travel.
    pub(super) dir: u8,
    pub(super) start_tick: u64,
    pub(super) anchor: f64,
    pub(super) prof: Profile,
    /// Exact step count of a finite motion (for the final position).
    pub(super) target: Option<f64>,
}

/// One motor: its settings, its position (steps, continuous between ticks) and motion.
#[derive(Debug, Clone, Default)]
pub(super) struct Motor {
    pub(super) settings: MotorSettings,
    pub(super) x: f64,
    pub(super) active: Option<Active>,
    pub(super) energized: bool,
}

/// +1 in direction 0, −1 in direction 1.
pub(super) fn sign(dir: u8) -> f64 {
    if dir == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Integer step position reached at continuous position `x` moving in `dir`.
pub(super) fn step_pos(x: f64, dir: u8) -> f64 {
    if dir == 0 {
        (x + EPS).floor()
    } else {
        (x - EPS).ceil()
    }
}

impl Emulator {
    /// Start a single-motor motion now; if the home for its direction is
    /// already active it ends at once without a step (except homing, whose
    /// seek then ends immediately and the back-off begins at the next tick).
    pub(super) fn start(
        &mut self,
        m: usize,
        kind: Kind,
        dir: u8,
        prof: Profile,
        target: Option<f64>,
    ) {
        let inputs = self.inputs;
        let tick = self.tick;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let blocked = Self::home_of(&mo.settings, inputs, dir);
        let empty = target.is_some_and(|n| n <= 0.0);
        if (blocked && !matches!(kind, Kind::Home { .. })) || empty {
            mo.active = None;
            mo.energized = mo.settings.use_holding_current;
            return;
        }
        mo.x = mo.x.round();
        mo.active = Some(Active {
            kind,
            dir,
            start_tick: tick,
            anchor: mo.x,
            prof,
            target,
        });
        mo.energized = true;
    }

    pub(super) fn stop_motor(&mut self, m: usize) {
        if let Some(mo) = self.motors.get_mut(m) {
            if let Some(a) = mo.active.take() {
                mo.x = step_pos(mo.x, a.dir);
            }
            mo.energized = mo.settings.use_holding_current;
        }
    }

    /// Re-plan a free-running motor after a change of velocity,
    /// acceleration, deceleration or direction modifier.
    pub(super) fn replan_run(&mut self, m: usize) {
        let tick = self.tick;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let s = mo.settings;
        let Some(a) = mo.active.as_mut() else {
            return;
        };
        let Kind::Run { cmd_dir } = a.kind else {
            return;
        };
        let t = (tick - a.start_tick) as f64 * TICK_S;
        let (dist, v) = a.prof.eval(t);
        a.anchor += sign(a.dir) * dist;
        mo.x = a.anchor;
        a.start_tick = tick;
        let want = cmd_dir ^ u8::from(s.direction_modifier);
        let (acc, dec) = (f64::from(s.acceleration), f64::from(s.deceleration));
        a.prof = if want == a.dir {
            Profile::to_speed(v, f64::from(s.max_velocity), acc, dec)
        } else {
            Profile::to_rest(v, dec)
        };
    }

    pub(super) fn tick_motor(&mut self, m: usize) {
        let tick = self.tick;
        let inputs = self.inputs;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let Some(a) = mo.active.take() else {
            return;
        };
        let s = mo.settings;
        let t = (tick - a.start_tick) as f64 * TICK_S;
        let (dist, _) = a.prof.eval(t);
        let done = !a.prof.cruise && t + EPS >= a.prof.duration();
        let dist = match (done, a.target) {
            (true, Some(n)) => n,
            _ => dist,
        };
        mo.x = a.anchor + sign(a.dir) * dist;
        let home = |d: u8| Self::home_of(&s, inputs, d);
        // Homing transitions and limit stops.
        if let Kind::Home { home_dir, phase } = a.kind {
            let next = match phase {
                HomePhase::Seek if home(home_dir) => Some(HomePhase::BackOff),
                HomePhase::BackOff if !home(home_dir) => Some(HomePhase::Approach),
                HomePhase::BackOff if home(a.dir) => {
                    // Opposite home reached while backing off: give up.
                    mo.x = step_pos(mo.x, a.dir);
                    mo.energized = s.use_holding_current;
                    return;
                }
                HomePhase::Approach if home(home_dir) => None,
                _ => {
                    mo.active = Some(a);
                    return;
                }
            };
            mo.x = step_pos(mo.x, a.dir);
            match next {
                Some(phase) => {
                    let dir = if phase == HomePhase::BackOff {
                        home_dir ^ 1
                    } else {
                        home_dir
                    };
                    mo.active = Some(Active {
                        kind: Kind::Home { home_dir, phase },
                        dir,
                        start_tick: tick,
                        anchor: mo.x,
                        prof: Profile::constant(HOMING_SPEED, None),
                        target: None,
                    });
                }
                None => mo.energized = s.use_holding_current,
            }
            return;
        }
        if home(a.dir) {
            mo.x = step_pos(mo.x, a.dir);
            mo.energized = s.use_holding_current;
            return;
        }
        if done {
            if let Kind::Run { cmd_dir } = a.kind {
                // End of a deceleration for a direction change: reverse.
                mo.x = step_pos(mo.x, a.dir);
                let dir = cmd_dir ^ u8::from(s.direction_modifier);
                mo.active = Some(Active {
                    kind: a.kind,
                    dir,
                    start_tick: tick,
                    anchor: mo.x,
                    prof: Profile::to_speed(
                        0.0,
                        f64::from(s.max_velocity),
                        f64::from(s.acceleration),
                        f64::from(s.deceleration),
                    ),
                    target: None,
                });
                return;
            }
            mo.x = mo.x.round();
            mo.energized = s.use_holding_current;
            return;
        }
        mo.active = Some(a);
    }
}
