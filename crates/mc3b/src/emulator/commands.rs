//! The commands of §6 as the device carries them out: the wire in and out, the
//! addressing, the checks and the answer to each.

use std::collections::VecDeque;

use super::motor::{HomePhase, Kind};
use super::sync::SyncSeg;
use super::{Emulator, Profile, CHAIN_CAPACITY, FIRMWARE_VERSION, PRODUCT_ID};
use crate::codec::{encode_response, Command, CommandCode, ErrorCode, Response, MOTORS};

impl Emulator {
    /// Feed wire bytes; returns the wire bytes of all replies.
    pub fn receive(&mut self, bytes: &[u8]) -> Vec<u8> {
        self.parser.feed(bytes);
        let mut out = Vec::new();
        while let Some(item) = self.parser.next_command() {
            let resp = match item {
                Ok(cmd) => self.handle(&cmd),
                Err(e) => match e.id {
                    Some(id) if id == self.id => Some(Response::Error { id, code: e.code }),
                    _ => None,
                },
            };
            if let Some(r) = resp {
                out.extend_from_slice(&encode_response(&r));
            }
        }
        out
    }

    /// Execute one typed command; `None` when it is not addressed to this
    /// controller.
    pub fn handle(&mut self, cmd: &Command) -> Option<Response> {
        if matches!(cmd, Command::Initialize { .. }) || cmd.id() == self.id {
            let code = cmd.code();
            if let Some(n) = CommandCode::ALL
                .iter()
                .position(|&c| c == code)
                .and_then(|i| self.received.get_mut(i))
            {
                *n += 1;
            }
        }
        if let Command::Initialize { id } = *cmd {
            self.initialize(id);
            return Some(Response::Ack {
                id,
                code: CommandCode::Initialize,
            });
        }
        let id = cmd.id();
        if id != self.id {
            return None;
        }
        Some(match self.execute(cmd) {
            Ok(r) => r,
            Err(code) => Response::Error { id, code },
        })
    }

    fn execute(&mut self, cmd: &Command) -> Result<Response, ErrorCode> {
        cmd.validate()?;
        let id = self.id;
        let ack = Response::Ack {
            id,
            code: cmd.code(),
        };
        let idx = |m: u32| -> Result<usize, ErrorCode> {
            if m < MOTORS {
                Ok(m as usize)
            } else {
                Err(ErrorCode::OutOfRange)
            }
        };
        let flag8 = |v: u32| u8::from(v != 0);
        match *cmd {
            Command::Initialize { .. } => Ok(ack),
            Command::SetAcceleration { motor, value, .. }
            | Command::SetDeceleration { motor, value, .. } => {
                let m = idx(motor)?;
                let on_the_fly = self.free_running(m);
                if self.motor_busy(m) && !on_the_fly {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = &mut self.motors[m].settings;
                if matches!(cmd, Command::SetAcceleration { .. }) {
                    s.acceleration = value;
                } else {
                    s.deceleration = value;
                }
                if on_the_fly {
                    self.replan_run(m);
                }
                Ok(ack)
            }
            Command::SetMaxVelocity {
                motor,
                value,
                direction_modifier,
                ..
            } => {
                let m = idx(motor)?;
                let on_the_fly = self.free_running(m);
                if self.motor_busy(m) && !on_the_fly {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = &mut self.motors[m].settings;
                s.max_velocity = value;
                s.direction_modifier = direction_modifier.unwrap_or(0) != 0;
                if on_the_fly {
                    self.replan_run(m);
                }
                Ok(ack)
            }
            Command::SetLimits {
                motor,
                h0_and,
                h0_xor,
                h1_and,
                h1_xor,
                ..
            } => {
                let m = idx(motor)?;
                let b = |v: u32| u8::try_from(v).map_err(|_| ErrorCode::OutOfRange);
                self.motors[m].settings.limit_masks =
                    [b(h0_and)?, b(h0_xor)?, b(h1_and)?, b(h1_xor)?];
                Ok(ack)
            }
            Command::SetHalfStep { motor, half, .. } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                self.motors[m].settings.half_steps = half != 0;
                Ok(ack)
            }
            Command::SetHoldingCurrent { motor, enable, .. } => {
                let m = idx(motor)?;
                let mo = &mut self.motors[m];
                mo.settings.use_holding_current = enable != 0;
                mo.energized = enable != 0;
                Ok(ack)
            }
            Command::SetCurrentLimits {
                motor,
                holding,
                running,
                ..
            } => {
                let m = idx(motor)?;
                let s = &mut self.motors[m].settings;
                s.holding_current = holding;
                s.running_current = running;
                Ok(ack)
            }
            Command::SetDebounce { count, .. } => {
                self.debounce_count = count;
                Ok(ack)
            }
            Command::Run {
                motor, direction, ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let cmd_dir = flag8(direction);
                let dir = cmd_dir ^ u8::from(self.motors[m].settings.direction_modifier);
                let s = self.motors[m].settings;
                let prof = Profile::to_speed(
                    0.0,
                    f64::from(s.max_velocity),
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                );
                self.start(m, Kind::Run { cmd_dir }, dir, prof, None);
                Ok(ack)
            }
            Command::Move {
                motor,
                steps,
                direction,
                ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = self.motors[m].settings;
                let n = f64::from(steps);
                let prof = Profile::trapezoid(
                    n,
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                    f64::from(s.max_velocity),
                );
                self.start(m, Kind::Move, flag8(direction), prof, Some(n));
                Ok(ack)
            }
            Command::RateMove {
                motor,
                steps,
                direction,
                rate,
                ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let n = f64::from(steps);
                let v = 100_000.0 / f64::from(rate.max(1));
                self.start(
                    m,
                    Kind::Rate,
                    flag8(direction),
                    Profile::constant(v, Some(n)),
                    Some(n),
                );
                Ok(ack)
            }
            Command::Home {
                motor, direction, ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = self.motors[m].settings;
                let dir = flag8(direction) ^ u8::from(s.direction_modifier);
                let prof = Profile::to_speed(
                    0.0,
                    f64::from(s.max_velocity),
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                );
                let kind = Kind::Home {
                    home_dir: dir,
                    phase: HomePhase::Seek,
                };
                self.start(m, kind, dir, prof, None);
                Ok(ack)
            }
            Command::Stop { motor, .. } => {
                let m = idx(motor)?;
                if self.sync.is_some() {
                    self.stop_sync();
                } else {
                    self.stop_motor(m);
                }
                Ok(ack)
            }
            Command::SyncMove {
                steps,
                directions,
                execute,
                ..
            } => {
                let seg = SyncSeg {
                    steps,
                    dirs: [
                        flag8(directions[0]),
                        flag8(directions[1]),
                        flag8(directions[2]),
                    ],
                };
                match execute {
                    Some(0) => {
                        // Room is kept for the move that executes the chain.
                        if self.chain.len() + 1 >= CHAIN_CAPACITY {
                            return Err(ErrorCode::OutOfRange);
                        }
                        self.chain.push(seg);
                    }
                    Some(_) => {
                        if (0..3).any(|m| self.motor_busy(m)) {
                            return Err(ErrorCode::MotorRunning);
                        }
                        if self.chain.len() >= CHAIN_CAPACITY {
                            return Err(ErrorCode::OutOfRange);
                        }
                        self.chain.push(seg);
                        let queue: VecDeque<SyncSeg> = self.chain.drain(..).collect();
                        self.start_sync(queue);
                    }
                    None => {
                        if (0..3).any(|m| self.motor_busy(m)) {
                            return Err(ErrorCode::MotorRunning);
                        }
                        self.chain.clear();
                        self.start_sync(VecDeque::from([seg]));
                    }
                }
                Ok(ack)
            }
            Command::QueryStatus { motor, .. } => {
                let m = idx(motor)?;
                Ok(Response::Status {
                    id,
                    running: self.is_running(m),
                    home0: self.at_home(m, 0),
                    home1: self.at_home(m, 1),
                })
            }
            Command::QueryLimits { .. } => Ok(Response::Limits {
                id,
                bits: self.inputs,
            }),
            Command::QueryProductId { .. } => Ok(Response::ProductId {
                id,
                product: PRODUCT_ID,
                version: FIRMWARE_VERSION,
            }),
        }
    }
}
