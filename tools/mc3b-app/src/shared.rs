//! The meeting point of the HTTP side (many threads) and the board thread (the only one
//! that talks to the serial line): one operation at a time, stops and manual speeds
//! before anything else, the published state, and the pages' heartbeats.
//!
//! Every call holds the lock briefly and never while waiting for the board.

use std::sync::mpsc;
use std::sync::Arc;
use std::time::{Duration, Instant};

use parking_lot::{Condvar, Mutex};

use crate::checks::{FieldError, Op, MOTORS};
use crate::params::MotorParams;

/// A page that sent no heartbeat for this long is taken for gone: every motor that may
/// run is stopped. Pages send one at least every 250 ms.
pub const HEARTBEAT_TIMEOUT: Duration = Duration::from_millis(1000);
/// Longest wait of a request for its operation (a chain of 100 moves on a real line
/// takes under 2 s; each failed command at most the reply timeout and a resync).
pub const OP_WAIT: Duration = Duration::from_secs(60);
/// Longest wait of a stop request for the board thread to have sent its stops.
pub const STOP_WAIT: Duration = Duration::from_secs(10);

/// Why an operation was not carried out, as the HTTP answer says it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// HTTP status: 400 bad input, 409 not now, 502 the board refused or failed,
    /// 503 no board, 504 no answer from the board thread.
    pub status: u16,
    /// For a person.
    pub message: String,
    /// The fields at fault (bad input).
    pub fields: Vec<FieldError>,
}

impl Refusal {
    /// A refusal without fields.
    pub fn new(status: u16, message: impl Into<String>) -> Refusal {
        Refusal {
            status,
            message: message.into(),
            fields: Vec::new(),
        }
    }
}

/// The answer to an operation: what was done, or why not.
pub type Reply = Result<String, Refusal>;

/// What the board thread is to do next.
#[derive(Debug)]
pub enum Work {
    /// Stop these motors, for this reason; then report stop request `gen` done.
    Stop {
        /// Motors to stop.
        motors: [bool; MOTORS],
        /// Why (shown on the page).
        reason: String,
        /// The request's number.
        gen: u64,
    },
    /// Bring the manual control of the motors to these speeds (`None`: leave it).
    Manual([Option<i32>; MOTORS]),
    /// An operation; its reply goes to the sender.
    Op(Op, mpsc::Sender<Reply>),
    /// Nothing asked: poll the board if due, publish.
    Idle,
    /// The application ends.
    Shutdown,
}

#[derive(Default)]
struct Inner {
    op: Option<(Op, mpsc::Sender<Reply>)>,
    /// What the board thread does for an operation now (`None`: nothing).
    busy: Option<String>,
    stop_motors: [bool; MOTORS],
    stop_reason: String,
    stop_gen: u64,
    stop_done: u64,
    stop_result: String,
    manual: [Option<i32>; MOTORS],
    snapshot: Option<Arc<str>>,
    seq: u64,
    params: [MotorParams; MOTORS],
    connected: bool,
    /// A motor may run (per the last poll, or a motion command since).
    may_move: bool,
    last_heartbeat: Option<Instant>,
    /// A stop for the current heartbeat lapse was asked for already.
    lapse_handled: bool,
    streams: usize,
    shutdown: bool,
}

/// Shared by the HTTP threads and the board thread.
#[derive(Default)]
pub struct Shared {
    inner: Mutex<Inner>,
    /// The board thread waits here for work.
    wake: Condvar,
    /// Streams and stop requests wait here for the board thread.
    done: Condvar,
}

impl Shared {
    /// A new meeting point.
    pub fn new() -> Arc<Shared> {
        Arc::new(Shared::default())
    }

    /// Hands `op` to the board thread and waits for its reply. Refused with 409 while
    /// another operation runs (one at a time; a stop never waits for this).
    pub fn submit(&self, op: Op) -> Reply {
        let (tx, rx) = mpsc::channel();
        {
            let mut s = self.inner.lock();
            if s.shutdown {
                return Err(Refusal::new(503, "the application is ending"));
            }
            if s.op.is_some() || s.busy.is_some() {
                let what = s.busy.clone().unwrap_or_else(|| "another command".into());
                return Err(Refusal::new(
                    409,
                    format!("busy: {what} is still under way; try again when it is done"),
                ));
            }
            s.op = Some((op, tx));
            self.wake.notify_all();
        }
        rx.recv_timeout(OP_WAIT).unwrap_or_else(|_| {
            Err(Refusal::new(
                504,
                format!(
                    "the board thread did not answer within {} s",
                    OP_WAIT.as_secs()
                ),
            ))
        })
    }

    /// Asks for a stop of `motor` (`None`: all three) before anything else, for
    /// `reason`. Returns the request's number for [`Shared::wait_stop`].
    pub fn request_stop(&self, motor: Option<u32>, reason: &str) -> u64 {
        let mut s = self.inner.lock();
        match motor {
            Some(m) => {
                if let Some(f) = s.stop_motors.get_mut(m as usize) {
                    *f = true;
                }
            }
            None => s.stop_motors = [true; MOTORS],
        }
        if motor.is_none() {
            // A stop of everything also cancels speeds the sliders asked for.
            s.manual = [None; MOTORS];
        }
        s.stop_reason = reason.to_string();
        s.stop_gen += 1;
        self.wake.notify_all();
        s.stop_gen
    }

    /// Waits until stop request `gen` (or a later one) was carried out; its result, or
    /// `None` after [`STOP_WAIT`].
    pub fn wait_stop(&self, gen: u64) -> Option<String> {
        let deadline = Instant::now() + STOP_WAIT;
        let mut s = self.inner.lock();
        while s.stop_done < gen {
            if self.done.wait_until(&mut s, deadline).timed_out() {
                return None;
            }
        }
        Some(s.stop_result.clone())
    }

    /// A manual control slider asks for `speed` (steps/s, signed; 0 stops). Only the
    /// latest value per motor is kept.
    pub fn set_manual(&self, motor: u32, speed: i32) {
        let mut s = self.inner.lock();
        if let Some(slot) = s.manual.get_mut(motor as usize) {
            *slot = Some(speed);
        }
        self.wake.notify_all();
    }

    /// The maximum velocity recorded for `motor`, and whether a board is connected.
    pub fn motor_params(&self, motor: u32) -> (Option<MotorParams>, bool) {
        let s = self.inner.lock();
        (s.params.get(motor as usize).copied(), s.connected)
    }

    /// A page (or any client) shows it is there.
    pub fn heartbeat(&self) {
        let mut s = self.inner.lock();
        s.last_heartbeat = Some(Instant::now());
        s.lapse_handled = false;
    }

    /// A page opened its event stream. `None` when `max` streams are open already.
    pub fn stream_opened(&self, max: usize) -> Option<()> {
        let mut s = self.inner.lock();
        if s.streams >= max {
            return None;
        }
        s.streams += 1;
        s.last_heartbeat = Some(Instant::now());
        s.lapse_handled = false;
        Some(())
    }

    /// A page's event stream ended (the page closed, the browser died, the connection
    /// dropped): every motor that may run is stopped.
    pub fn stream_closed(&self) {
        let may_move = {
            let mut s = self.inner.lock();
            s.streams = s.streams.saturating_sub(1);
            s.may_move && s.connected
        };
        if may_move {
            self.request_stop(None, "a page closed (its event stream ended)");
        }
    }

    /// The page is being closed (`pagehide`): stop what may run.
    pub fn page_leaving(&self) {
        let may_move = {
            let s = self.inner.lock();
            s.may_move && s.connected
        };
        if may_move {
            self.request_stop(None, "a page was closed");
        }
    }

    /// The latest state as JSON and its number.
    pub fn snapshot(&self) -> (u64, Option<Arc<str>>) {
        let s = self.inner.lock();
        (s.seq, s.snapshot.clone())
    }

    /// Waits up to `timeout` for a state newer than `seq`.
    pub fn wait_snapshot(&self, seq: u64, timeout: Duration) -> (u64, Option<Arc<str>>) {
        let deadline = Instant::now() + timeout;
        let mut s = self.inner.lock();
        while s.seq <= seq && !s.shutdown {
            if self.done.wait_until(&mut s, deadline).timed_out() {
                break;
            }
        }
        (s.seq, s.snapshot.clone())
    }

    /// Ends the application: the board thread stops the motors and leaves.
    pub fn shutdown(&self) {
        let mut s = self.inner.lock();
        s.shutdown = true;
        self.wake.notify_all();
        self.done.notify_all();
    }

    /// Whether the application ends.
    pub fn shutting_down(&self) -> bool {
        self.inner.lock().shutdown
    }

    // ---- the board thread's side ----

    /// The next thing to do, waiting at most until `until` for one. Stops come first,
    /// then manual speeds, then an operation. A heartbeat lapse while a motor may run
    /// becomes a stop here.
    pub fn next_work(&self, until: Instant) -> Work {
        let mut s = self.inner.lock();
        loop {
            if s.shutdown {
                return Work::Shutdown;
            }
            let lapsed = s
                .last_heartbeat
                .is_none_or(|t| t.elapsed() > HEARTBEAT_TIMEOUT);
            if lapsed && s.may_move && s.connected && !s.lapse_handled {
                s.lapse_handled = true;
                s.stop_motors = [true; MOTORS];
                s.manual = [None; MOTORS];
                s.stop_reason = format!(
                    "no heartbeat from any page for {} s",
                    HEARTBEAT_TIMEOUT.as_secs_f64()
                );
                s.stop_gen += 1;
            }
            if s.stop_motors.iter().any(|&m| m) {
                let motors = std::mem::take(&mut s.stop_motors);
                return Work::Stop {
                    motors,
                    reason: std::mem::take(&mut s.stop_reason),
                    gen: s.stop_gen,
                };
            }
            if s.manual.iter().any(Option::is_some) {
                return Work::Manual(std::mem::take(&mut s.manual));
            }
            if let Some((op, tx)) = s.op.take() {
                s.busy = Some("the previous command".into());
                return Work::Op(op, tx);
            }
            let now = Instant::now();
            if now >= until {
                return Work::Idle;
            }
            // Wake at least every 100 ms to watch the heartbeat.
            let wait = (until - now).min(Duration::from_millis(100));
            let _ = self.wake.wait_for(&mut s, wait);
            if Instant::now() >= until {
                return Work::Idle;
            }
        }
    }

    /// Whether a stop was asked for (a long operation checks between its commands).
    pub fn stop_pending(&self) -> bool {
        let s = self.inner.lock();
        s.shutdown || s.stop_motors.iter().any(|&m| m)
    }

    /// Stop request `gen` was carried out with `result`.
    pub fn stop_finished(&self, gen: u64, result: String) {
        let mut s = self.inner.lock();
        s.stop_done = s.stop_done.max(gen);
        s.stop_result = result;
        self.done.notify_all();
    }

    /// What the board thread does for an operation now, if anything.
    pub fn busy(&self) -> Option<String> {
        self.inner.lock().busy.clone()
    }

    /// Says what the board thread does for an operation (`None`: done).
    pub fn set_busy(&self, what: Option<String>) {
        self.inner.lock().busy = what;
    }

    /// Publishes the state: its JSON, the parameter record, whether a board is
    /// connected and whether a motor may run.
    pub fn publish(
        &self,
        json: String,
        params: [MotorParams; MOTORS],
        connected: bool,
        may_move: bool,
    ) {
        let mut s = self.inner.lock();
        s.seq += 1;
        s.snapshot = Some(Arc::from(json));
        s.params = params;
        s.connected = connected;
        s.may_move = may_move;
        self.done.notify_all();
    }

    /// Marks that a motor may run from now on (a motion command went out), before the
    /// next publication.
    pub fn set_may_move(&self) {
        self.inner.lock().may_move = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn far() -> Instant {
        Instant::now() + Duration::from_secs(5)
    }

    #[test]
    fn a_closed_stream_stops_only_what_may_move() {
        let s = Shared::new();
        assert!(s.stream_opened(8).is_some());
        s.publish("{}".into(), [MotorParams::DEFAULT; MOTORS], true, false);
        s.stream_closed();
        assert!(!s.stop_pending(), "nothing runs: nothing to stop");
        assert!(s.stream_opened(8).is_some());
        s.publish("{}".into(), [MotorParams::DEFAULT; MOTORS], true, true);
        s.stream_closed();
        match s.next_work(far()) {
            Work::Stop { motors, reason, .. } => {
                assert_eq!(motors, [true; MOTORS]);
                assert!(reason.contains("page closed"), "{reason}");
            }
            w => panic!("{w:?}"),
        }
    }

    #[test]
    fn a_heartbeat_lapse_stops_once() {
        let s = Shared::new();
        s.publish("{}".into(), [MotorParams::DEFAULT; MOTORS], true, true);
        // No heartbeat ever: the first look stops everything, the next does not again.
        assert!(matches!(s.next_work(far()), Work::Stop { .. }));
        assert!(matches!(
            s.next_work(Instant::now() + Duration::from_millis(10)),
            Work::Idle
        ));
        // A fresh heartbeat: no stop.
        s.heartbeat();
        assert!(matches!(
            s.next_work(Instant::now() + Duration::from_millis(10)),
            Work::Idle
        ));
    }

    #[test]
    fn stops_come_before_operations_and_cancel_sliders() {
        let s = Shared::new();
        s.heartbeat();
        s.set_manual(1, 300);
        s.request_stop(Some(2), "button");
        match s.next_work(far()) {
            Work::Stop { motors, .. } => assert_eq!(motors, [false, false, true]),
            w => panic!("{w:?}"),
        }
        s.set_manual(1, 300);
        s.request_stop(None, "stop all");
        assert!(matches!(s.next_work(far()), Work::Stop { .. }));
        assert!(matches!(
            s.next_work(Instant::now() + Duration::from_millis(10)),
            Work::Idle
        ));
    }
}
