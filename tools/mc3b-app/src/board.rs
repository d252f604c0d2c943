//! The board thread: the only one that talks to the serial line. It carries out the
//! page's operations one at a time, stops before anything else, polls the motor status
//! and the limit inputs, keeps the record of the settings the board acknowledged, and
//! publishes the state for the page.
//!
//! Decisions where the guide is silent:
//! * **Polling.** `Q0`, `Q1`, `Q2` and `B` every [`POLL_PERIOD`] (the guide's application
//!   about once a second). One round is 44 characters on the line, about 23 ms at 19200
//!   baud: under an eighth of the line, so commands never wait long behind it.
//! * **Positions.** The MC3B never reports one (§6.13). The page shows an estimate: a
//!   model of the device (the project's emulator) fed every acknowledged command at the
//!   time it was sent and the limit inputs the board reports; a motor the board reports
//!   idle is stopped in the model too. Against `mc3b-emu` the estimate is exact to a
//!   step or two; against a real board it is as good as that model.
//! * **Line trouble.** No answer within the reply timeout: the line is *silent* (shown,
//!   polling goes on, the client brings the line back in step, §6 has no sequence
//!   numbers). The port itself failing (unplugged adapter, closed pty): *lost*, the port
//!   is closed and the page asks for a port again.
//! * **Safety.** Every stop goes out before any other command; a chain upload checks
//!   for one between its moves. Leaving a port, and ending the application, send `0I`
//!   (motors off, as `mcl_deinitialize`, §4.3).

use std::collections::VecDeque;
use std::sync::Arc;
use std::time::{Duration, Instant};

use mc3b::client::{Client, MotorStatus, Transport};
use mc3b::emulator::Emulator;
use mc3b::serial::open_port;

use crate::checks::MOTORS;
use crate::params::MotorParams;
use crate::shared::{Refusal, Shared, Work};

mod chain;
mod line;
mod manual;
mod ops;
mod view;

use chain::CircleRun;
use manual::FreeRun;
use view::Event;

/// Time between two polls of the board.
pub const POLL_PERIOD: Duration = Duration::from_millis(200);
/// While a motor moves, the state is published at least this often (the estimated
/// positions move).
pub const MOVING_PUBLISH: Duration = Duration::from_millis(100);

/// Opens a serial device by path: a real port at 19200 8N1, or (tests) anything else.
pub type Opener = Box<dyn Fn(&str, Duration) -> Result<Box<dyn Transport + Send>, String> + Send>;

/// The opener of real serial ports.
pub fn serial_opener() -> Opener {
    Box::new(|path, timeout| {
        open_port(path, timeout)
            .map(|p| Box::new(p) as Box<dyn Transport + Send>)
            .map_err(|e| e.to_string())
    })
}

/// An open port with an MC3B on it.
struct Conn {
    path: String,
    firmware: u32,
    client: Client<Box<dyn Transport + Send>>,
    /// The device as the application believes it (see the module docs).
    model: Emulator,
    model_at: Duration,
    params: [MotorParams; MOTORS],
    debounce: u32,
    /// The chained-move buffer may hold moves of an upload cut short.
    chain_dirty: bool,
    status: [Option<MotorStatus>; MOTORS],
    inputs: Option<u8>,
    manual: [Option<FreeRun>; MOTORS],
    moved_since_poll: bool,
    last_answer: Instant,
    silent_since: Option<Instant>,
    circle: Option<CircleRun>,
}

/// What the line to the board is like, for the page.
#[derive(Debug, Clone, PartialEq)]
enum LinkState {
    /// No port chosen.
    None,
    /// Answers come.
    Ok,
    /// No answer since this long.
    Silent,
    /// The port failed and was closed.
    Lost(String),
}

/// The board thread's state.
pub struct Board {
    shared: Arc<Shared>,
    opener: Opener,
    timeout: Duration,
    conn: Option<Conn>,
    link: LinkState,
    last_port: Option<String>,
    events: VecDeque<Event>,
    next_event: u64,
    started: Instant,
    next_poll: Instant,
}

impl Board {
    /// A board thread's state, with no port open yet.
    pub fn new(shared: Arc<Shared>, opener: Opener, timeout: Duration) -> Board {
        let now = Instant::now();
        Board {
            shared,
            opener,
            timeout,
            conn: None,
            link: LinkState::None,
            last_port: None,
            events: VecDeque::new(),
            next_event: 1,
            started: now,
            next_poll: now,
        }
    }

    /// Runs until the application ends; then the motors are turned off (`0I`).
    pub fn run(mut self) {
        self.publish();
        loop {
            let moving = self.conn.as_ref().is_some_and(|c| {
                c.status.iter().flatten().any(|s| s.running) || c.moved_since_poll
            });
            let until = if self.conn.is_some() {
                if moving {
                    self.next_poll.min(Instant::now() + MOVING_PUBLISH)
                } else {
                    self.next_poll
                }
            } else {
                Instant::now() + Duration::from_secs(1)
            };
            match self.shared.next_work(until) {
                Work::Shutdown => {
                    self.leave("the application ends");
                    self.publish();
                    return;
                }
                Work::Stop {
                    motors,
                    reason,
                    gen,
                } => {
                    let r = self.stop(motors, &reason);
                    self.publish();
                    self.shared.stop_finished(gen, r);
                }
                Work::Manual(targets) => self.manual(targets),
                Work::Op(op, tx) => {
                    let r =
                        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.execute(op)))
                            .unwrap_or_else(|_| Err(Refusal::new(500, "internal error (a panic)")));
                    self.shared.set_busy(None);
                    let _ = tx.send(r);
                }
                Work::Idle => {
                    if self.conn.is_some() && Instant::now() >= self.next_poll {
                        self.poll();
                    }
                }
            }
            self.publish();
        }
    }

    fn mark_moved(&mut self) {
        if let Some(c) = self.conn.as_mut() {
            c.moved_since_poll = true;
        }
        self.shared.set_may_move();
    }

    fn connected(&self) -> Result<(), Refusal> {
        if self.conn.is_some() {
            Ok(())
        } else {
            Err(Refusal::new(
                503,
                "no MC3B connected: choose its port first (port selection)",
            ))
        }
    }

    fn in_manual(&self, m: u32) -> Result<(), Refusal> {
        if self
            .conn
            .as_ref()
            .is_some_and(|c| c.manual[m as usize].is_some())
        {
            return Err(Refusal::new(
                409,
                format!("motor {m} is under manual control: close manual control first"),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
