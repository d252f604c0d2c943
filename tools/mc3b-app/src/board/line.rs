//! Talking to the board: a command and its acknowledgement fed to the model, the
//! status polls, and what the line's troubles do to the connection.

use std::time::{Duration, Instant};

use mc3b::client::{ClientError, MotorStatus};
use mc3b::codec::Command;

use super::{Board, LinkState, POLL_PERIOD};
use crate::checks::MOTORS;
use crate::params::ID;
use crate::shared::Refusal;

/// A client error in words: the device's refusals in the words of §6.19.
pub(super) fn words(e: &ClientError, what: &str, timeout: Duration) -> String {
    match e {
        ClientError::Device(code) => format!(
            "the MC3B refused {what}: error {} ({})",
            code.number(),
            code.meaning()
        ),
        ClientError::Timeout => format!(
            "no answer from the MC3B to {what} within {} ms: the line is silent (cable, \
             power?)",
            timeout.as_millis()
        ),
        ClientError::Io(io) => format!("the serial port failed during {what}: {io}"),
        ClientError::Unexpected(r) => {
            format!("the MC3B answered {what} with something that does not fit it ({r:?})")
        }
        ClientError::Garbled(p) => format!("unreadable answer from the MC3B to {what} ({p})"),
    }
}

/// A refusal of the page's request because of the board (502).
pub(super) fn board_refusal(message: String) -> Refusal {
    Refusal::new(502, message)
}

impl Board {
    /// Sends `cmd` and waits for its acknowledgement; feeds it to the model at the time
    /// the board got it. A reply that only came late is found by bringing the line back
    /// in step, and then counts as an acknowledgement. A failed port closes the
    /// connection (the link is lost).
    pub(super) fn send(&mut self, cmd: Command, what: &str) -> Result<(), String> {
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else {
            return Err("no MC3B connected".into());
        };
        let r = match c.client.command(&cmd) {
            Ok(()) => Ok(()),
            Err(e @ ClientError::Io(_)) => Err(e),
            Err(e) => c.client.settle(&cmd, e),
        };
        match r {
            Ok(()) => {
                let at = c.client.sent_at();
                if at > c.model_at {
                    c.model.advance(at - c.model_at);
                    c.model_at = at;
                }
                let _ = c.model.handle(&cmd);
                self.answered();
                Ok(())
            }
            Err(e) => {
                let msg = words(&e, what, timeout);
                self.failed(&e, &msg);
                Err(msg)
            }
        }
    }

    /// The board answered: the line is fine.
    pub(super) fn answered(&mut self) {
        let back = matches!(self.link, LinkState::Silent);
        if let Some(c) = self.conn.as_mut() {
            c.last_answer = Instant::now();
            c.silent_since = None;
        }
        self.link = LinkState::Ok;
        if back {
            self.event("info", "the MC3B answers again".into());
        }
    }

    /// A command or query failed with `e`: a silent line is shown as such, a failed
    /// port closes the connection.
    pub(super) fn failed(&mut self, e: &ClientError, msg: &str) {
        match e {
            ClientError::Io(io) => {
                let path = self
                    .conn
                    .as_ref()
                    .map(|c| c.path.clone())
                    .unwrap_or_default();
                let text = format!("the port {path} is gone ({io}): choose a port again to go on");
                self.conn = None;
                self.link = LinkState::Lost(text.clone());
                self.event("error", text);
            }
            ClientError::Timeout => {
                let first = self.link != LinkState::Silent;
                if let Some(c) = self.conn.as_mut() {
                    c.silent_since.get_or_insert_with(Instant::now);
                }
                self.link = LinkState::Silent;
                if first {
                    self.event("error", msg.to_string());
                }
            }
            _ => {}
        }
    }

    /// `Q` of motor `m`.
    pub(super) fn query(&mut self, m: usize) -> Result<MotorStatus, String> {
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else {
            return Err("no MC3B connected".into());
        };
        match c.client.query_status(ID, m as u32) {
            Ok(s) => {
                c.status[m] = Some(s);
                self.answered();
                Ok(s)
            }
            Err(e) => {
                let msg = words(&e, &format!("the status query of motor {m} (Q)"), timeout);
                self.failed(&e, &msg);
                Err(msg)
            }
        }
    }

    /// Polls the three motors and the limit inputs; reconciles the model and the
    /// manual control with what the board says.
    pub(super) fn poll(&mut self) {
        self.next_poll = Instant::now() + POLL_PERIOD;
        if let Some(c) = self.conn.as_mut() {
            c.moved_since_poll = false;
        }
        for m in 0..MOTORS {
            if self.shared.stop_pending() {
                return;
            }
            if self.query(m).is_err() {
                return;
            }
        }
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else { return };
        match c.client.query_limits(ID) {
            Ok(bits) => {
                c.inputs = Some(bits);
                self.answered();
            }
            Err(e) => {
                let msg = words(&e, "the limit input query (B)", timeout);
                self.failed(&e, &msg);
                return;
            }
        }
        self.reconcile();
    }

    /// Brings the model and the manual control in line with the board's answers.
    pub(super) fn reconcile(&mut self) {
        let mut ended = Vec::new();
        let Some(c) = self.conn.as_mut() else { return };
        let now = c.client.transport().now();
        if now > c.model_at {
            c.model.advance(now - c.model_at);
            c.model_at = now;
        }
        if let Some(bits) = c.inputs {
            c.model.set_inputs(bits);
        }
        for m in 0..MOTORS {
            let running = c.status[m].is_some_and(|s| s.running);
            if !running && c.model.is_running(m) {
                let _ = c.model.handle(&Command::Stop {
                    id: ID,
                    motor: m as u32,
                });
            }
            if !running && c.manual[m].is_some() {
                c.manual[m] = None;
                ended.push(m);
            }
        }
        for m in ended {
            self.event(
                "info",
                format!("motor {m} stopped by itself (a limit switch?): manual control ended"),
            );
            self.restore_velocity(m);
        }
    }
}
