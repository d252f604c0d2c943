//! What the page asks for, and the checks every value passes before anything goes to
//! the board: the ranges of chapter 6 (taken from the codec), the dialog rules of
//! chapter 5 (one limit box per direction), and whole numbers only.
//!
//! A request that fails a check is answered with the field and the reason, and sends
//! nothing.

use mc3b::codec::{ACCEL_RANGE, CURRENT_RANGE, DEBOUNCE_RANGE, VELOCITY_RANGE};
use serde::Deserialize;

use crate::circle::{self, CirclePlan, CHORDS_RANGE, RADIUS_RANGE};
use crate::params::{Limit, MotorParams};

/// Motors of an MC3B.
pub const MOTORS: usize = 3;
/// Longest move: the step count is a 32-bit unsigned integer (§6.8, §2.2(h)).
pub const MAX_STEPS: u64 = u32::MAX as u64;

/// A request of the page (`POST /api/action`, JSON with an `action` field). Number
/// fields typed by a person are strings, so that "12.5" or "abc" gets its own message.
#[derive(Debug, Deserialize)]
#[serde(tag = "action", rename_all = "snake_case", deny_unknown_fields)]
pub enum Action {
    /// Port selection (§5.1): open this device and find the MC3B on it.
    Connect {
        /// Device path, e.g. `/dev/ttyUSB0`.
        port: String,
    },
    /// Leave the port (motors off, as `mcl_deinitialize`, §4.3).
    Disconnect,
    /// The limit switch debounce count (§4.10, §6.17).
    Debounce {
        /// 1..100.
        count: String,
    },
    /// Free run (§4.12, §6.7).
    Run {
        /// Motor 0..2.
        motor: u32,
        /// Direction 0/1.
        direction: u32,
    },
    /// Homing (§4.14, §6.9).
    Home {
        /// Motor 0..2.
        motor: u32,
        /// Direction 0/1.
        direction: u32,
    },
    /// Relative move (§4.13, §6.8).
    Move {
        /// Motor 0..2.
        motor: u32,
        /// Direction 0/1.
        direction: u32,
        /// Steps, 0..4294967295.
        steps: String,
    },
    /// Stop one motor (§4.15, §6.11).
    Stop {
        /// Motor 0..2.
        motor: u32,
    },
    /// Stop all three.
    StopAll,
    /// Synchronous move of all three from the control dialog's fields (§4.16, §6.12).
    SyncMove {
        /// Steps of motors 0, 1, 2.
        steps: [String; 3],
        /// Directions of motors 0, 1, 2.
        directions: [u32; 3],
    },
    /// The set parameters dialog's OK (§5.3).
    SetParams {
        /// Motor 0..2.
        motor: u32,
        /// The dialog's fields.
        params: ParamsForm,
    },
    /// The chained synchronous move dialog's OK (§5.4): a circle in an X-Y plane.
    Circle {
        /// Motor driving X.
        x_motor: u32,
        /// Motor driving Y.
        y_motor: u32,
        /// Radius, steps.
        radius: String,
        /// Number of chords (synchronous moves).
        chords: String,
        /// `ccw` or `cw`.
        direction: String,
    },
    /// A manual control slider (§5.5): signed speed, steps/s; 0 stops the motor.
    Manual {
        /// Motor 0..2.
        motor: u32,
        /// Steps/s, negative for direction 1.
        speed: i64,
    },
    /// The manual control dialog closes: its motors stop.
    ManualEnd,
}

/// The set parameters dialog's fields as typed.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParamsForm {
    /// Steps/s.
    pub max_velocity: String,
    /// Steps/s².
    pub acceleration: String,
    /// Steps/s².
    pub deceleration: String,
    /// The half steps box.
    pub half_steps: bool,
    /// The holding current box.
    pub holding_on: bool,
    /// mA.
    pub holding_current: String,
    /// mA.
    pub running_current: String,
    /// The direction 0 limit boxes that are checked (one at most).
    pub limit0: Vec<Limit>,
    /// The direction 1 limit boxes that are checked (one at most).
    pub limit1: Vec<Limit>,
}

/// A value the checks refused: which field, and why in words.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct FieldError {
    /// The field's name in the request (`max_velocity`, `steps.1`, ...).
    pub field: String,
    /// The reason, for a person.
    pub message: String,
}

fn err(field: &str, message: String) -> FieldError {
    FieldError {
        field: field.to_string(),
        message,
    }
}

/// A checked request that the board thread carries out in turn.
#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    /// Open the port and find the MC3B.
    Connect(String),
    /// Motors off, port closed.
    Disconnect,
    /// `N`.
    Debounce(u32),
    /// `R`.
    Run {
        /// Motor.
        motor: u32,
        /// Direction.
        direction: u32,
    },
    /// `H`.
    Home {
        /// Motor.
        motor: u32,
        /// Direction.
        direction: u32,
    },
    /// `M`.
    Move {
        /// Motor.
        motor: u32,
        /// Direction.
        direction: u32,
        /// Steps.
        steps: u32,
    },
    /// `Y` without execute (runs now, §6.12).
    SyncMove {
        /// Steps of motors 0..2.
        steps: [u32; 3],
        /// Directions of motors 0..2.
        directions: [u32; 3],
    },
    /// `V`, `A`, `D`, `F`, `C`, `K`, `L` of one motor.
    SetParams {
        /// Motor.
        motor: u32,
        /// The values.
        params: MotorParams,
    },
    /// The chain of a circle.
    Circle(CirclePlan),
}

/// What a checked request asks the application for.
#[derive(Debug, Clone, PartialEq)]
pub enum Checked {
    /// A board operation, carried out in turn.
    Op(Op),
    /// Stop one motor (`Some`) or all three (`None`), before anything else.
    Stop(Option<u32>),
    /// A manual control speed (checked against the motor's maximum velocity by the
    /// caller, who knows it).
    Manual {
        /// Motor.
        motor: u32,
        /// Signed steps/s.
        speed: i64,
    },
    /// End manual control.
    ManualEnd,
}

/// A whole number typed in `field`, within `range`; `what` names the value and `unit`
/// and `section` say where the range comes from.
fn whole(
    field: &str,
    what: &str,
    text: &str,
    (lo, hi): (u64, u64),
    unit: &str,
    section: &str,
) -> Result<u64, FieldError> {
    let t = text.trim();
    let range = format!("{lo} to {hi}{unit}");
    if t.is_empty() {
        return Err(err(
            field,
            format!("{what}: empty; give a whole number from {range} ({section})"),
        ));
    }
    if !t.bytes().all(|b| b.is_ascii_digit()) {
        return Err(err(
            field,
            format!("{what}: \"{t}\" is not a whole number; give one from {range} ({section})"),
        ));
    }
    match t.parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(err(
            field,
            format!("{what} must be {range} ({section}); {t} is out of range"),
        )),
    }
}

fn to_u32(v: u64) -> u32 {
    u32::try_from(v).unwrap_or(u32::MAX)
}

fn range32((lo, hi): (u32, u32)) -> (u64, u64) {
    (u64::from(lo), u64::from(hi))
}

fn motor(field: &str, m: u32) -> Result<u32, FieldError> {
    if (m as usize) < MOTORS {
        Ok(m)
    } else {
        Err(err(
            field,
            format!("motor {m}: the MC3B has motors 0, 1 and 2"),
        ))
    }
}

fn direction(field: &str, d: u32) -> Result<u32, FieldError> {
    if d < 2 {
        Ok(d)
    } else {
        Err(err(field, format!("direction {d}: 0 or 1")))
    }
}

/// Collects the first error of each field.
struct Errors(Vec<FieldError>);

impl Errors {
    fn take<T>(&mut self, r: Result<T, FieldError>) -> Option<T> {
        match r {
            Ok(v) => Some(v),
            Err(e) => {
                self.0.push(e);
                None
            }
        }
    }
}

/// The set parameters dialog's values, checked (§6.2-§6.5, §6.16, and §5.3: one limit
/// box per direction at most).
fn params(form: &ParamsForm) -> Result<MotorParams, Vec<FieldError>> {
    let mut e = Errors(Vec::new());
    let v = e.take(whole(
        "max_velocity",
        "Maximum velocity",
        &form.max_velocity,
        range32(VELOCITY_RANGE),
        " steps/s",
        "§6.4",
    ));
    let a = e.take(whole(
        "acceleration",
        "Acceleration",
        &form.acceleration,
        range32(ACCEL_RANGE),
        " steps/s²",
        "§6.2",
    ));
    let d = e.take(whole(
        "deceleration",
        "Deceleration",
        &form.deceleration,
        range32(ACCEL_RANGE),
        " steps/s²",
        "§6.3",
    ));
    let ih = e.take(whole(
        "holding_current",
        "Holding current",
        &form.holding_current,
        range32(CURRENT_RANGE),
        " mA",
        "§6.16",
    ));
    let ir = e.take(whole(
        "running_current",
        "Running current",
        &form.running_current,
        range32(CURRENT_RANGE),
        " mA",
        "§6.16",
    ));
    let l0 = e.take(one_limit("limit0", 0, &form.limit0));
    let l1 = e.take(one_limit("limit1", 1, &form.limit1));
    match (v, a, d, ih, ir, l0, l1) {
        (Some(v), Some(a), Some(d), Some(ih), Some(ir), Some(l0), Some(l1)) if e.0.is_empty() => {
            Ok(MotorParams {
                max_velocity: to_u32(v),
                acceleration: to_u32(a),
                deceleration: to_u32(d),
                half_steps: form.half_steps,
                holding_on: form.holding_on,
                holding_current: to_u32(ih),
                running_current: to_u32(ir),
                limit0: l0,
                limit1: l1,
            })
        }
        _ => Err(e.0),
    }
}

fn one_limit(field: &str, dir: u32, boxes: &[Limit]) -> Result<Option<Limit>, FieldError> {
    match boxes {
        [] => Ok(None),
        [l] if l.bit <= 5 => Ok(Some(*l)),
        [l] => Err(err(
            field,
            format!(
                "Direction {dir} limit: input bit {} does not exist (0 to 5)",
                l.bit
            ),
        )),
        many => Err(err(
            field,
            format!(
                "Direction {dir} limit: only one of the twelve boxes may be checked ({} are, \
                 §5.3)",
                many.len()
            ),
        )),
    }
}

/// Checks a request. Every refusal names its fields; nothing of a refused request is
/// carried out.
pub fn check(action: &Action) -> Result<Checked, Vec<FieldError>> {
    let one = |r: Result<Checked, FieldError>| r.map_err(|e| vec![e]);
    match action {
        Action::Connect { port } => {
            let p = port.trim();
            if p.is_empty() {
                return Err(vec![err(
                    "port",
                    "Port: none chosen; pick one from the list or type its path".into(),
                )]);
            }
            Ok(Checked::Op(Op::Connect(p.to_string())))
        }
        Action::Disconnect => Ok(Checked::Op(Op::Disconnect)),
        Action::Debounce { count } => one(whole(
            "count",
            "Debounce count",
            count,
            range32(DEBOUNCE_RANGE),
            " samples",
            "§6.17",
        )
        .map(|c| Checked::Op(Op::Debounce(to_u32(c))))),
        Action::Run {
            motor: m,
            direction: d,
        } => one((|| {
            Ok(Checked::Op(Op::Run {
                motor: motor("motor", *m)?,
                direction: direction("direction", *d)?,
            }))
        })()),
        Action::Home {
            motor: m,
            direction: d,
        } => one((|| {
            Ok(Checked::Op(Op::Home {
                motor: motor("motor", *m)?,
                direction: direction("direction", *d)?,
            }))
        })()),
        Action::Move {
            motor: m,
            direction: d,
            steps,
        } => one((|| {
            Ok(Checked::Op(Op::Move {
                motor: motor("motor", *m)?,
                direction: direction("direction", *d)?,
                steps: to_u32(whole(
                    &format!("steps.{m}"),
                    &format!("Motor {m} steps"),
                    steps,
                    (0, MAX_STEPS),
                    "",
                    "§6.8",
                )?),
            }))
        })()),
        Action::Stop { motor: m } => one(motor("motor", *m).map(|m| Checked::Stop(Some(m)))),
        Action::StopAll => Ok(Checked::Stop(None)),
        Action::SyncMove { steps, directions } => {
            let mut e = Errors(Vec::new());
            let mut s = [0u32; 3];
            let mut d = [0u32; 3];
            for m in 0..MOTORS {
                if let Some(v) = e.take(whole(
                    &format!("steps.{m}"),
                    &format!("Motor {m} steps"),
                    &steps[m],
                    (0, MAX_STEPS),
                    "",
                    "§6.12",
                )) {
                    s[m] = to_u32(v);
                }
                if let Some(v) = e.take(direction(&format!("direction.{m}"), directions[m])) {
                    d[m] = v;
                }
            }
            if e.0.is_empty() {
                Ok(Checked::Op(Op::SyncMove {
                    steps: s,
                    directions: d,
                }))
            } else {
                Err(e.0)
            }
        }
        Action::SetParams {
            motor: m,
            params: form,
        } => {
            let m = motor("motor", *m).map_err(|e| vec![e])?;
            Ok(Checked::Op(Op::SetParams {
                motor: m,
                params: params(form)?,
            }))
        }
        Action::Circle {
            x_motor,
            y_motor,
            radius,
            chords,
            direction,
        } => {
            let mut e = Errors(Vec::new());
            let x = e.take(motor("x_motor", *x_motor));
            let y = e.take(motor("y_motor", *y_motor));
            if x.is_some() && x == y {
                e.0.push(err(
                    "y_motor",
                    format!("X and Y are both motor {x_motor}: choose two motors"),
                ));
            }
            let r = e.take(whole(
                "radius",
                "Radius",
                radius,
                RADIUS_RANGE,
                " steps",
                "each chord at most 2³²−1 steps, §6.12",
            ));
            let n = e.take(whole(
                "chords",
                "Chords",
                chords,
                CHORDS_RANGE,
                "",
                "a chain holds at most 100 moves, §4.17",
            ));
            let ccw = match direction.as_str() {
                "ccw" => Some(true),
                "cw" => Some(false),
                other => {
                    e.0.push(err(
                        "direction",
                        format!("Direction \"{other}\": ccw or cw"),
                    ));
                    None
                }
            };
            match (x, y, r, n, ccw) {
                (Some(x), Some(y), Some(r), Some(n), Some(ccw)) if e.0.is_empty() => {
                    circle::plan(x, y, to_u32(r), to_u32(n), ccw)
                        .map(|p| Checked::Op(Op::Circle(p)))
                        .map_err(|m| vec![err("radius", m)])
                }
                _ => Err(e.0),
            }
        }
        Action::Manual { motor: m, speed } => one(motor("motor", *m).map(|m| Checked::Manual {
            motor: m,
            speed: *speed,
        })),
        Action::ManualEnd => Ok(Checked::ManualEnd),
    }
}

/// A manual control speed for a motor whose maximum velocity (the control page's
/// limit, §5.5) is `max`: |speed| ≤ max.
pub fn manual_speed(motor: u32, speed: i64, max: u32) -> Result<i32, FieldError> {
    if speed.unsigned_abs() > u64::from(max) {
        return Err(err(
            &format!("speed.{motor}"),
            format!(
                "Motor {motor} speed {speed} steps/s: beyond its maximum velocity of {max} \
                 steps/s (set parameters)"
            ),
        ));
    }
    Ok(i32::try_from(speed).unwrap_or(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn form() -> ParamsForm {
        ParamsForm {
            max_velocity: "1000".into(),
            acceleration: "5000".into(),
            deceleration: "5000".into(),
            half_steps: true,
            holding_on: false,
            holding_current: "500".into(),
            running_current: "2000".into(),
            limit0: vec![],
            limit1: vec![],
        }
    }

    #[test]
    fn ranges_are_chapter_six() {
        // Each range end is accepted and one past it refused (§6.2, §6.3, §6.4, §6.16).
        for (v, ok) in [("1", true), ("5000", true), ("0", false), ("5001", false)] {
            let f = ParamsForm {
                max_velocity: v.into(),
                ..form()
            };
            assert_eq!(params(&f).is_ok(), ok, "velocity {v}");
        }
        for (v, ok) in [
            ("100", true),
            ("100000", true),
            ("99", false),
            ("100001", false),
        ] {
            let f = ParamsForm {
                acceleration: v.into(),
                deceleration: v.into(),
                ..form()
            };
            assert_eq!(params(&f).is_ok(), ok, "acceleration {v}");
        }
        for (v, ok) in [("0", true), ("2000", true), ("2001", false)] {
            let f = ParamsForm {
                holding_current: v.into(),
                running_current: v.into(),
                ..form()
            };
            assert_eq!(params(&f).is_ok(), ok, "current {v}");
        }
        assert_eq!(params(&form()), Ok(MotorParams::DEFAULT));
    }

    #[test]
    fn refusals_name_the_field_and_the_rule() {
        let f = ParamsForm {
            max_velocity: "6000".into(),
            acceleration: "12.5".into(),
            limit0: vec![
                Limit { bit: 0, high: true },
                Limit {
                    bit: 3,
                    high: false,
                },
            ],
            ..form()
        };
        let e = params(&f).expect_err("refused");
        let fields: Vec<&str> = e.iter().map(|e| e.field.as_str()).collect();
        assert_eq!(fields, ["max_velocity", "acceleration", "limit0"]);
        assert_eq!(
            e[0].message,
            "Maximum velocity must be 1 to 5000 steps/s (§6.4); 6000 is out of range"
        );
        assert!(e[1].message.contains("\"12.5\" is not a whole number"));
        assert!(e[2].message.contains("only one of the twelve boxes"));
        let bad_bit = ParamsForm {
            limit1: vec![Limit { bit: 6, high: true }],
            ..form()
        };
        assert!(params(&bad_bit).expect_err("bit 6")[0]
            .message
            .contains("bit 6 does not exist"));
    }

    #[test]
    fn steps_motors_directions_and_ports() {
        let mv = |steps: &str, motor: u32, direction: u32| {
            check(&Action::Move {
                motor,
                direction,
                steps: steps.into(),
            })
        };
        assert_eq!(
            mv("4294967295", 2, 1),
            Ok(Checked::Op(Op::Move {
                motor: 2,
                direction: 1,
                steps: u32::MAX
            }))
        );
        assert!(mv("4294967296", 0, 0).is_err());
        assert!(mv("-5", 0, 0).is_err());
        assert!(mv("5", 3, 0).is_err());
        assert!(mv("5", 0, 2).is_err());
        let e = check(&Action::Connect { port: "  ".into() }).expect_err("no port");
        assert_eq!(e[0].field, "port");
        assert!(check(&Action::Debounce {
            count: "101".into()
        })
        .is_err());
        let sync = check(&Action::SyncMove {
            steps: ["1".into(), "x".into(), "".into()],
            directions: [0, 1, 5],
        })
        .expect_err("refused");
        let fields: Vec<&str> = sync.iter().map(|e| e.field.as_str()).collect();
        assert_eq!(fields, ["steps.1", "steps.2", "direction.2"]);
        assert!(manual_speed(0, -800, 800).is_ok());
        assert!(manual_speed(0, 801, 800).is_err());
    }

    #[test]
    fn circle_needs_two_motors_and_chain_sized_chords() {
        let c = |x, y, r: &str, n: &str, d: &str| {
            check(&Action::Circle {
                x_motor: x,
                y_motor: y,
                radius: r.into(),
                chords: n.into(),
                direction: d.into(),
            })
        };
        assert!(c(0, 1, "300", "36", "ccw").is_ok());
        assert!(c(0, 0, "300", "36", "ccw").is_err());
        assert!(
            c(0, 1, "300", "101", "ccw").is_err(),
            "over the chain's 100"
        );
        assert!(c(0, 1, "300", "2", "ccw").is_err());
        assert!(c(0, 1, "300", "36", "up").is_err());
        assert!(c(0, 1, "3", "100", "cw").is_err(), "chords of no steps");
    }
}
