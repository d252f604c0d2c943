//! The page's operations: port selection (§5.1), the control dialog's commands (§5.2)
//! and set parameters (§5.3).

use std::time::Instant;

use mc3b::client::{Client, ClientError};
use mc3b::codec::Command;
use mc3b::emulator::{Emulator, PRODUCT_ID};

use super::line::{board_refusal, words};
use super::{Board, Conn, LinkState};
use crate::checks::{FieldError, Op, MOTORS};
use crate::params::{MotorParams, ID};
use crate::shared::{Refusal, Reply};

impl Board {
    /// Sends one motion command of an operation.
    pub(super) fn motion(&mut self, cmd: Command, what: &str) -> Reply {
        self.mark_moved();
        self.send(cmd, what).map_err(board_refusal)?;
        self.next_poll = Instant::now();
        Ok(format!("{what}: started"))
    }

    /// Carries out a checked operation.
    pub(super) fn execute(&mut self, op: Op) -> Reply {
        match op {
            Op::Connect(path) => self.connect(&path),
            Op::Disconnect => {
                self.connected()?;
                let path = self.conn.as_ref().map(|c| c.path.clone());
                self.leave("disconnected by the user");
                self.link = LinkState::None;
                self.last_port = path;
                Ok("port closed; the motors are off".into())
            }
            Op::Debounce(count) => {
                self.connected()?;
                self.send(
                    Command::SetDebounce { id: ID, count },
                    "the debounce count (N)",
                )
                .map_err(board_refusal)?;
                if let Some(c) = self.conn.as_mut() {
                    c.debounce = count;
                }
                Ok(format!("debounce count {count}"))
            }
            Op::Run { motor, direction } => {
                self.connected()?;
                self.in_manual(motor)?;
                self.motion(
                    Command::Run {
                        id: ID,
                        motor,
                        direction,
                    },
                    &format!("run motor {motor} in direction {direction} (R)"),
                )
            }
            Op::Home { motor, direction } => {
                self.connected()?;
                self.in_manual(motor)?;
                let has_limit = self
                    .conn
                    .as_ref()
                    .is_some_and(|c| c.params[motor as usize].limit(direction).is_some());
                if !has_limit {
                    return Err(Refusal {
                        status: 409,
                        message: format!(
                            "motor {motor} has no direction {direction} limit (set parameters): \
                             homing would run until stopped"
                        ),
                        fields: vec![FieldError {
                            field: format!("home.{motor}"),
                            message: "no limit switch in that direction".into(),
                        }],
                    });
                }
                self.motion(
                    Command::Home {
                        id: ID,
                        motor,
                        direction,
                    },
                    &format!("home motor {motor} in direction {direction} (H)"),
                )
            }
            Op::Move {
                motor,
                direction,
                steps,
            } => {
                self.connected()?;
                self.in_manual(motor)?;
                self.motion(
                    Command::Move {
                        id: ID,
                        motor,
                        steps,
                        direction,
                    },
                    &format!("move motor {motor} {steps} steps in direction {direction} (M)"),
                )
            }
            Op::SyncMove { steps, directions } => {
                self.connected()?;
                for m in 0..MOTORS as u32 {
                    self.in_manual(m)?;
                }
                // Without <execute> the move runs now and discards the chained-move
                // buffer (§6.12): nothing stored earlier can run with it.
                let r = self.motion(
                    Command::SyncMove {
                        id: ID,
                        steps,
                        directions,
                        execute: None,
                    },
                    "the synchronous move (Y)",
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.chain_dirty = false;
                }
                Ok(r)
            }
            Op::SetParams { motor, params } => self.set_params(motor, params),
            Op::Circle(plan) => self.circle(plan),
        }
    }

    /// Port selection (§5.1): open `path`, look for the MC3B (`P`, §6.18) and initialize
    /// it (`I`, §6.1: motors off, the defaults).
    pub(super) fn connect(&mut self, path: &str) -> Reply {
        if self.conn.is_some() {
            self.leave(&format!("switching to {path}"));
        }
        self.last_port = Some(path.to_string());
        let transport = (self.opener)(path, self.timeout).map_err(|e| Refusal {
            status: 400,
            message: format!("cannot open {path}: {e}"),
            fields: vec![FieldError {
                field: "port".into(),
                message: format!("cannot open {path}: {e}"),
            }],
        })?;
        let mut client = Client::new(transport, self.timeout);
        let timeout = self.timeout;
        // A controller answers P at its ID; one whose ID an earlier program changed
        // answers only I (obeyed at any ID, §6.1), so try that before giving up. The
        // client would first bring the line back in step with a P that nobody answers:
        // a fresh client sends the I as it is.
        let found = match client.product_id(ID) {
            Err(e) if !matches!(e, ClientError::Io(_)) => {
                client = Client::new(client.into_transport(), timeout);
                client
                    .initialize(ID)
                    .and_then(|()| client.product_id(ID))
                    .map(|p| (p, true))
            }
            r => r.map(|p| (p, false)),
        };
        let ((product, firmware), initialized) = match found {
            Ok(f) => f,
            Err(ClientError::Timeout) => {
                return Err(board_refusal(format!(
                    "nothing answers on {path}: no MC3B replied to 0P or 0I within {} ms \
                     (§6.18); check that it is powered and on this port",
                    timeout.as_millis()
                )))
            }
            Err(e) => return Err(board_refusal(words(&e, "the product query (P)", timeout))),
        };
        if product != PRODUCT_ID {
            return Err(board_refusal(format!(
                "the device on {path} answers product {product}: not an MC3B (product 1, \
                 §6.18)"
            )));
        }
        if !initialized {
            client
                .initialize(ID)
                .map_err(|e| board_refusal(words(&e, "the initialization (I)", timeout)))?;
        }
        let now = client.transport().now();
        let mut model = Emulator::new();
        let _ = model.handle(&Command::Initialize { id: ID });
        self.conn = Some(Conn {
            path: path.to_string(),
            firmware,
            client,
            model,
            model_at: now,
            params: [MotorParams::DEFAULT; MOTORS],
            debounce: 1,
            chain_dirty: false,
            status: [None; MOTORS],
            inputs: None,
            manual: [None; MOTORS],
            moved_since_poll: false,
            last_answer: Instant::now(),
            silent_since: None,
            circle: None,
        });
        self.link = LinkState::Ok;
        let text = format!(
            "MC3B found on {path} (firmware {}.{:02}) and initialized: motors off, §6.1 defaults",
            firmware / 100,
            firmware % 100
        );
        self.event("info", text.clone());
        self.poll();
        Ok(text)
    }

    /// Turns the motors off (`0I`, best effort) and closes the port.
    pub(super) fn leave(&mut self, why: &str) {
        let Some(mut c) = self.conn.take() else {
            return;
        };
        let r = c.client.initialize(ID);
        let text = match r {
            Ok(()) => format!("{}: motors off (0I), port closed ({why})", c.path),
            Err(e) => format!(
                "{}: port closed ({why}); turning the motors off failed: {}",
                c.path,
                words(&e, "the initialization (I)", self.timeout)
            ),
        };
        self.event("info", text);
    }

    /// The set parameters dialog's OK (§5.3): every value, in the order V, A, D, F, C,
    /// K, L, once the motor is idle (the board refuses V, A, D, F while it moves).
    pub(super) fn set_params(&mut self, motor: u32, params: MotorParams) -> Reply {
        self.connected()?;
        let m = motor as usize;
        let st = self.query(m).map_err(board_refusal)?;
        if st.running {
            return Err(Refusal::new(
                409,
                format!(
                    "motor {motor} is running: stop it before changing its parameters (the \
                     MC3B takes them only from an idle motor, §4.4-§4.7)"
                ),
            ));
        }
        let mut applied = Vec::new();
        for (what, cmd) in params.commands(motor) {
            match self.send(cmd.clone(), &format!("the {what} of motor {motor}")) {
                Ok(()) => {
                    if let Some(c) = self.conn.as_mut() {
                        c.params[m].apply(&cmd);
                    }
                    applied.push(what);
                }
                Err(e) => {
                    let done = if applied.is_empty() {
                        "nothing applied".to_string()
                    } else {
                        format!("applied: {}", applied.join(", "))
                    };
                    self.event("error", format!("set parameters of motor {motor}: {e}"));
                    return Err(board_refusal(format!("{e}; {done}; the rest not sent")));
                }
            }
        }
        let text = format!("parameters of motor {motor} applied");
        self.event("info", text.clone());
        Ok(text)
    }
}
