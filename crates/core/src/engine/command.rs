//! Queued motion commands: what a call captures (user manual §2.3 A–I) and how it is
//! planned. A command is planned completely when it is queued, starting from the end of
//! the previous queued command, so bad geometry is refused at call time and the engine
//! only samples plans.

use crate::config::{range, AXES};
use crate::error::{McclError, McclResult};
use crate::planner::{ramp_periods, Axes, Path, PathMove, PlanError, Plane, PtpMove, Shape};
use crate::vendor::SYS_MAC_PARAM;

/// `COMMAND_INFO.nType` codes (user manual §2.6.5).
pub mod ctype {
    /// Point-to-point (also jog).
    pub const PTP: i32 = 0;
    /// Linear.
    pub const LINE: i32 = 1;
    /// Clockwise arc or circle.
    pub const ARC_CW: i32 = 2;
    /// Counter-clockwise arc or circle.
    pub const ARC_CCW: i32 = 3;
    /// Clockwise helix.
    pub const HELIX_CW: i32 = 4;
    /// Counter-clockwise helix.
    pub const HELIX_CCW: i32 = 5;
    /// Motion delay (the user manual says 6; the vendor's library shows 8, and the
    /// blending and in-position switches two above the manual's numbers too).
    pub const DELAY: i32 = 8;
    /// Enable blending (the vendor's type: a queued command of one period).
    pub const BLEND_ON: i32 = 9;
    /// Disable blending.
    pub const BLEND_OFF: i32 = 10;
    /// Enable in-position check.
    pub const INPOS_ON: i32 = 11;
    /// Disable in-position check.
    pub const INPOS_OFF: i32 = 12;
}

/// What kind of curve a command is (its `COMMAND_INFO.nType`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Curve {
    /// Through a point to an end (`MCC_ArcXY`, `MCC_ArcXYZ`).
    ThreePoint,
    /// About a center (`MCC_ArcThetaXY`, `MCC_CircleXY`).
    Arc,
    /// A helix.
    Helix,
}

/// How a command moves (or what it switches).
///
/// Unboxed although its motions are large: commands are queued and run by value in the
/// group's queue, and a box would cost an allocation for every command queued.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum Plan {
    /// General motion: a path with its speed profile.
    Path(PathMove),
    /// Point-to-point (and jog): per-axis profiles.
    Ptp(PtpMove),
    /// Wait this many periods.
    Delay(u64),
    /// Queued blending switch.
    Blend(bool),
    /// Queued in-position switch for the axes in the mask.
    InPos(bool, u32),
    /// Queued output change (`MCC_Queue*OutputValue`), made when the queue reaches it.
    Output(Output),
    /// Custom motion: the program's callbacks give the path (`group/custom.rs`).
    Custom(super::custom_move::CustomMove),
    /// A command the vendor's library accepts and fails when it starts (an arc or circle
    /// with no geometry): it records this error record and stops the group.
    Fault(i32),
}

/// An output a queued command sets: the bits of `mask` take those of `value`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// The card's local outputs (the servo-on points 0..7).
    Local {
        /// Bits to change.
        mask: u16,
        /// Their new values.
        value: u16,
    },
    /// A remote output word: RIO set/port, or ARIO set/slave.
    Remote {
        /// ARIO rather than RIO.
        ario: bool,
        /// Set 0..1.
        set: u16,
        /// Port (RIO) or slave (ARIO).
        port: u16,
        /// Bits to change.
        mask: u16,
        /// Their new values.
        value: u16,
    },
}

/// One queued command.
#[derive(Debug, Clone)]
pub struct Command {
    /// Index returned to the caller.
    pub index: i32,
    /// `COMMAND_INFO.nType`.
    pub ctype: i32,
    /// `COMMAND_INFO.dfFeedSpeed`: feed speed (general), ratio (PtP) or delay (ms).
    pub info_feed: f64,
    /// Where the command ends (user coordinates).
    pub target: Axes,
    /// Acceleration time, ms (for `COMMAND_INFO`).
    pub acc_ms: f64,
    /// Deceleration time, ms.
    pub dec_ms: f64,
    /// The plan.
    pub plan: Plan,
    /// The posture a V6 command hands to the kinematics (`None`: the group's stays).
    pub posture: Option<u32>,
}

impl Command {
    /// Whether it moves axes (general or PtP motion).
    pub fn is_motion(&self) -> bool {
        matches!(self.plan, Plan::Path(_) | Plan::Ptp(_) | Plan::Custom(_))
    }

    /// Where the plan starts.
    #[inline]
    pub fn start(&self) -> Axes {
        match &self.plan {
            Plan::Path(m) => m.path.start(),
            Plan::Ptp(p) => p.start(),
            Plan::Custom(m) => m.start,
            _ => self.target,
        }
    }
}

/// Per-axis mechanism facts the planner needs (from `SYS_MAC_PARAM` of the mapped channel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisMech {
    /// `(card, channel)` the axis drives, `None` when unmapped.
    pub channel: Option<(usize, usize)>,
    /// Pulses per UU: dwPPR x dfGearRatio / dfPitch, negative when wPosToEncoderDir is nonzero.
    pub factor: f64,
    /// Maximum safe speed, UU/s: (wRPM / 60) x dfPitch / dfGearRatio.
    pub safe_speed: f64,
    /// Work zone, UU.
    pub high: f64,
    /// Work zone, UU.
    pub low: f64,
}

impl AxisMech {
    /// The facts of an axis on `channel` with mechanism parameters `m`.
    pub fn new(m: &SYS_MAC_PARAM, channel: Option<(usize, usize)>) -> AxisMech {
        let factor = crate::config::conv_factor(m);
        AxisMech {
            channel,
            factor: if m.wPosToEncoderDir != 0 {
                -factor
            } else {
                factor
            },
            safe_speed: crate::planner::ptp_axis_speed(
                f64::from(m.wRPM),
                m.dfPitch,
                m.dfGearRatio,
                100.0,
            ),
            high: m.dfHighLimit,
            low: m.dfLowLimit,
        }
    }

    /// The same facts for a group whose lengths are in units of `k` mechanism units
    /// (`config::unit_scale`, `MCC_SetUnit`): k times the pulses per unit, speeds and
    /// the work zone divided by k.
    pub fn in_unit(self, k: f64) -> AxisMech {
        AxisMech {
            factor: self.factor * k,
            safe_speed: self.safe_speed / k,
            high: self.high / k,
            low: self.low / k,
            ..self
        }
    }
}

/// The motion settings of a group that queued commands capture (user manual §2.6).
///
/// `repr(C)` with `compose` first: publishing reads it every tick, and the group keeps
/// its settings right after the published key, which publishing reads too.
#[derive(Debug, Clone, PartialEq)]
#[repr(C)]
pub struct Settings {
    /// The axes that compose a line's path speed (`MCC_SetComposeAxis`; X|Y|Z).
    pub compose: u32,
    /// General-motion feed speed, UU/s (already clamped to the system maximum).
    pub feed: f64,
    /// General-motion acceleration time, ms.
    pub acc_ms: f64,
    /// General-motion deceleration time, ms.
    pub dec_ms: f64,
    /// General-motion acceleration shape.
    pub acc: Shape,
    /// General-motion deceleration shape.
    pub dec: Shape,
    /// PtP speed ratio, percent of the maximum safe speed.
    pub ptp_ratio: f64,
    /// PtP acceleration shape per axis.
    pub ptp_acc: [Shape; AXES],
    /// PtP deceleration shape per axis.
    pub ptp_dec: [Shape; AXES],
    /// PtP acceleration time per axis, ms.
    pub ptp_acc_ms: Axes,
    /// PtP deceleration time per axis, ms.
    pub ptp_dec_ms: Axes,
    /// Absolute (true) or incremental coordinates.
    pub absolute: bool,
    /// `MCC_EnableAccDecAfterIPO`: general motion is interpolated at the feed speed
    /// without acc/dec; the group's output filter accelerates and decelerates.
    pub acc_after_ipo: bool,
}

/// General-motion feed speed before `MCC_SetFeedSpeed` (UU/s): the vendor's library
/// reads 1 right after init (the manuals give none).
pub const DEFAULT_FEED: f64 = 1.0;
/// PtP ratio before `MCC_SetPtPSpeed` (percent): the vendor's library reads 1.
pub const DEFAULT_PTP_RATIO: f64 = 1.0;
/// Acc/dec time of every kind of motion before it is set (ms, user manual §2.6.2).
pub const DEFAULT_ACC_DEC_MS: f64 = 300.0;

impl Default for Settings {
    fn default() -> Self {
        Settings {
            feed: DEFAULT_FEED,
            acc_ms: DEFAULT_ACC_DEC_MS,
            dec_ms: DEFAULT_ACC_DEC_MS,
            // The vendor's library starts with S curves everywhere.
            acc: Shape::S,
            dec: Shape::S,
            ptp_ratio: DEFAULT_PTP_RATIO,
            ptp_acc: [Shape::S; AXES],
            ptp_dec: [Shape::S; AXES],
            ptp_acc_ms: [DEFAULT_ACC_DEC_MS; AXES],
            ptp_dec_ms: [DEFAULT_ACC_DEC_MS; AXES],
            absolute: true,
            compose: crate::planner::compose::XYZ_MASK,
            acc_after_ipo: false,
        }
    }
}

pub fn plan_err(e: PlanError) -> McclError {
    match e {
        PlanError::BadArc | PlanError::BadParameter(_) => McclError::Parameter,
    }
}

/// Everything a planning call needs to know about its group.
#[derive(Debug, Clone, Copy)]
pub struct Ctx<'a> {
    /// The settings at call time.
    pub settings: &'a Settings,
    /// Per-axis mechanism facts.
    pub axes: &'a [AxisMech; AXES],
    /// End of the previous queued command (user coordinates).
    pub from: Axes,
    /// Reference position − user position per axis (`MCC_DefinePos` moves it).
    pub offset: Axes,
    /// The interpolation period, seconds (moves are planned in whole periods).
    pub period_s: f64,
}

impl Ctx<'_> {
    /// Resolves a target: absolute, or relative to the end of the queue; axes outside
    /// `mask` keep their position (docs/decisions.md, "Axis masks").
    pub fn resolve(&self, args: &Axes, mask: u32) -> Axes {
        std::array::from_fn(|i| {
            // An axis the group lacks does not move, as on the vendor's card (a line on
            // a group of no axis is a move of no length: `group_no_axes_line`).
            if mask & (1 << i) == 0 || self.axes[i].channel.is_none() {
                self.from[i]
            } else if self.settings.absolute {
                args[i]
            } else {
                self.from[i] + args[i]
            }
        })
    }

    /// Resolves a plane point (2 coordinates on the plane's axes).
    pub fn resolve_plane(&self, plane: Plane, p: [f64; 2]) -> [f64; 2] {
        let (a, b, _) = plane.axes();
        if self.settings.absolute {
            p
        } else {
            [self.from[a] + p[0], self.from[b] + p[1]]
        }
    }

    /// Resolves one coordinate of axis `i`.
    pub fn resolve_axis(&self, i: usize, v: f64) -> f64 {
        if self.settings.absolute {
            v
        } else {
            self.from[i] + v
        }
    }

    /// Checks resolved points `(axis, user coordinate)` a command names (targets, via
    /// points, centers) against the position range of their axes, in user and reference
    /// coordinates, before any geometry is built from them (an out-of-range point is a
    /// bad parameter, not a bad arc).
    pub fn check_points(&self, pts: &[(usize, f64)]) -> Result<(), PlanError> {
        for &(i, x) in pts {
            let f = self.axes[i].factor;
            if range::position(x, f).is_err() || range::position(x + self.offset[i], f).is_err() {
                return Err(PlanError::BadParameter("position out of range"));
            }
        }
        Ok(())
    }

    /// The ranges every queued move must keep (`config::range`): each axis's interval of
    /// positions over the move (`extent`), in user and in reference coordinates, within
    /// the pulse range of the axis; the move's duration within the longest time.
    fn check_reach(&self, extent: &[(f64, f64); AXES], duration_s: f64) -> McclResult<()> {
        for ((&(lo, hi), off), a) in extent.iter().zip(&self.offset).zip(self.axes) {
            for x in [lo, hi, lo + off, hi + off] {
                range::position(x, a.factor)?;
            }
        }
        range::duration_s(duration_s)?;
        Ok(())
    }

    /// The acceleration and deceleration of general motion and point-to-point, in
    /// periods ([`ramp_periods`]), and what `COMMAND_INFO` shows of them (ms).
    fn ramps(&self) -> ((u32, u32), (f64, f64)) {
        let s = self.settings;
        let (na, nd) = if s.acc_after_ipo {
            (0, 0)
        } else {
            ramp_periods(s.acc_ms, s.dec_ms, self.period_ms())
        };
        let p = self.period_ms();
        ((na, nd), (f64::from(na) * p, f64::from(nd) * p))
    }

    /// The period in milliseconds.
    fn period_ms(&self) -> f64 {
        self.period_s * 1000.0
    }

    fn general(&self, path: Path, ctype: i32) -> McclResult<Command> {
        let s = self.settings;
        // After-interpolation acc/dec: the interpolation runs at the feed speed from the
        // first period to the last; the group's filter makes the ramps.
        let (ramps, (acc_ms, dec_ms)) = self.ramps();
        let mv = PathMove::new(path, s.feed, ramps, (s.acc, s.dec), self.period_s);
        self.check_reach(&mv.path.extent(), mv.periods() as f64 * self.period_s)?;
        let target = mv.path.end();
        Ok(Command {
            index: 0,
            ctype,
            info_feed: s.feed,
            target,
            acc_ms,
            dec_ms,
            plan: Plan::Path(mv),
            posture: None,
        })
    }

    /// A linear move to `target` (already resolved).
    pub fn line(&self, target: Axes) -> McclResult<Command> {
        let mut path = Path::try_line(&self.from, &target).map_err(plan_err)?;
        if self.settings.compose != crate::planner::compose::XYZ_MASK {
            path = crate::planner::compose::line(&self.from, &target, self.settings.compose);
        }
        self.general(path, ctype::LINE)
    }

    /// An arc, circle or helix path already built from `self.from`. A three-point arc
    /// reports `ARC_CCW` whichever way it turns, as the vendor's library does.
    pub fn curve(&self, path: Path, kind: Curve) -> McclResult<Command> {
        let ccw = path.is_ccw().unwrap_or(true);
        let ctype = match (kind, ccw) {
            (Curve::ThreePoint, _) => ctype::ARC_CCW,
            (Curve::Arc, false) => ctype::ARC_CW,
            (Curve::Arc, true) => ctype::ARC_CCW,
            (Curve::Helix, false) => ctype::HELIX_CW,
            (Curve::Helix, true) => ctype::HELIX_CCW,
        };
        self.general(path, ctype)
    }

    /// A curve whose geometry is bad (`kind` as [`Ctx::curve`] would report it): queued
    /// like any, it records `code` when it starts (the vendor's library accepts it).
    pub fn fault(&self, kind: Curve, code: i32) -> Command {
        let ctype = match kind {
            Curve::Helix => ctype::HELIX_CCW,
            _ => ctype::ARC_CCW,
        };
        Command {
            index: 0,
            ctype,
            info_feed: self.settings.feed,
            target: self.from,
            acc_ms: 0.0,
            dec_ms: 0.0,
            plan: Plan::Fault(code),
            posture: None,
        }
    }

    /// Point-to-point to `target` at `ratio` percent of each axis's safe speed;
    /// `sync`: all axes end together (MCC_SyncPtP). Every axis ramps with the group's
    /// acceleration and deceleration (the vendor's library does not use the PtP times and
    /// types, which it keeps and reports).
    pub fn ptp(&self, target: Axes, ratio: f64, sync: bool) -> McclResult<Command> {
        let s = self.settings;
        let speed: Axes = std::array::from_fn(|i| self.axes[i].safe_speed * ratio / 100.0);
        let (ramps, (acc_ms, dec_ms)) = self.ramps();
        let mv = PtpMove::new(
            &self.from,
            &target,
            &speed,
            &[ramps; AXES],
            &[(s.acc, s.dec); AXES],
            self.period_s,
            sync,
        )
        .map_err(plan_err)?;
        let extent: [(f64, f64); AXES] =
            std::array::from_fn(|i| (self.from[i].min(target[i]), self.from[i].max(target[i])));
        self.check_reach(&extent, mv.periods() as f64 * self.period_s)?;
        Ok(Command {
            index: 0,
            ctype: ctype::PTP,
            info_feed: ratio,
            target: mv.end(),
            acc_ms,
            dec_ms,
            plan: Plan::Ptp(mv),
            posture: None,
        })
    }

    /// A delay of `ms` milliseconds: whole periods, rounded up.
    pub fn delay(&self, ms: f64) -> Command {
        let p = self.period_ms();
        let periods = if p > 0.0 {
            (ms / p).ceil().max(0.0) as u64
        } else {
            0
        };
        Command {
            index: 0,
            ctype: ctype::DELAY,
            info_feed: ms,
            target: self.from,
            acc_ms: 0.0,
            dec_ms: 0.0,
            plan: Plan::Delay(periods),
            posture: None,
        }
    }

    /// A queued switch (blending or in-position).
    pub fn marker(&self, plan: Plan) -> Command {
        let ctype = match plan {
            Plan::Blend(true) => ctype::BLEND_ON,
            Plan::Blend(false) => ctype::BLEND_OFF,
            Plan::InPos(true, _) => ctype::INPOS_ON,
            Plan::InPos(false, _) => ctype::INPOS_OFF,
            // Not one of the manual's types: an output change never runs as a command.
            _ => -1,
        };
        Command {
            index: 0,
            ctype,
            info_feed: 0.0,
            target: self.from,
            acc_ms: 0.0,
            dec_ms: 0.0,
            plan,
            posture: None,
        }
    }
}
