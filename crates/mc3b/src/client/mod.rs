//! Command/response client for the MC3B over any byte transport.
//!
//! The real transport is an RS-232 port at 19200 baud, 8 data bits, no
//! parity, one stop bit, no flow control (§3.2), opened with
//! [`open_port`](crate::serial::open_port); in tests, an [`EmulatorLink`].
//!
//! Decisions:
//! * The reply to a command is the first complete frame after it. A frame that
//!   cannot be decoded (garbage, a line longer than any reply, reported as soon
//!   as it passes [`MAX_LINE`](crate::codec::MAX_LINE) bytes), a frame from
//!   another controller ID, or a frame that does not answer the command fails
//!   the command at once ([`ClientError::Garbled`], [`ClientError::Unexpected`]):
//!   the line is corrupt, and waiting for the timeout would only delay saying so.
//! * The reply timeout counts only time in which the reply could have been read:
//!   the wait runs in slices of at most [`WAIT_SLICE`], and a slice that overran
//!   (the reading thread was not scheduled on a loaded host) counts as its
//!   planned length. A late reply on a busy host is not a dead device.
//! * After any failure but a clean device error (`<id>E<e>`), the line is *out of
//!   step*: a late reply may still arrive and would be taken for the next
//!   command's. Before the next command the client resynchronizes: it sends
//!   `<id>P` (a query with no effect) and reads everything up to its answer,
//!   dropping the frames before it ([`Client::resync`]); a line that does not
//!   answer fails the next command with that error, before it is sent. After a
//!   timeout, a line begun before the query (a reply whose CR was lost) is taken
//!   as ended: the query's answer is never read as its continuation.
//!   Otherwise stale input (line noise) is discarded before each command.
//! * A hang-up of the line (the device side of a pty closed: `EPIPE`/`EIO`, end of
//!   file) is an I/O error ([`ClientError::Io`]).

use std::time::Duration;

use crate::codec::{encode, Command, ProtocolError, Response, ResponseParser};

mod emulator_link;
mod error;
mod transport;

pub use emulator_link::EmulatorLink;
pub use error::ClientError;
pub use transport::Transport;

/// Default time to wait for a reply.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(500);
/// Longest single read while waiting for a reply; see the module docs.
pub const WAIT_SLICE: Duration = Duration::from_millis(20);

/// Reply timeout from the environment: `MCL_TIMEOUT_MS` milliseconds if it holds a
/// positive integer, else [`DEFAULT_TIMEOUT`] (the `mcl_*` library, the motion
/// library's MC3B backend and `mc3b-app` alike).
pub fn timeout_from_env() -> Duration {
    std::env::var("MCL_TIMEOUT_MS")
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .filter(|&ms| ms > 0)
        .map(Duration::from_millis)
        .unwrap_or(DEFAULT_TIMEOUT)
}

/// Motor status of §6.13.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MotorStatus {
    /// In motion.
    pub running: bool,
    /// At the direction 0 home.
    pub home0: bool,
    /// At the direction 1 home.
    pub home1: bool,
}

impl MotorStatus {
    /// Bit form of §4.18: bit 0 running, bit 1 home 0, bit 2 home 1.
    pub fn bits(self) -> i32 {
        i32::from(self.running) | i32::from(self.home0) << 1 | i32::from(self.home1) << 2
    }
}

/// A command/response client.
pub struct Client<T: Transport> {
    port: T,
    parser: ResponseParser,
    timeout: Duration,
    /// Every reply so far came in turn (see the module docs).
    in_sync: bool,
    /// The last failure was a timeout: the reply may still come, so the resync keeps
    /// the input. After any other failure the frame in turn came (and was bad), and
    /// the resync drops what is there (the rest of an overlong line, say).
    keep_input: bool,
    /// When the last command had been handed to the line (transport time).
    sent_at: Duration,
}

impl<T: Transport> Client<T> {
    /// Wrap a transport; `timeout` bounds each reply wait.
    pub fn new(port: T, timeout: Duration) -> Self {
        Client {
            port,
            parser: ResponseParser::new(),
            timeout,
            in_sync: true,
            keep_input: false,
            sent_at: Duration::ZERO,
        }
    }

    /// The transport.
    pub fn transport(&mut self) -> &mut T {
        &mut self.port
    }

    /// Give the transport back.
    pub fn into_transport(self) -> T {
        self.port
    }

    /// The reply timeout.
    pub fn timeout(&self) -> Duration {
        self.timeout
    }

    /// Transport time at which the last command had been written (and, on a real
    /// port, drained onto the line): when the device got it.
    pub fn sent_at(&self) -> Duration {
        self.sent_at
    }

    /// Whether the line is in step (no reply may be outstanding).
    pub fn in_sync(&self) -> bool {
        self.in_sync
    }

    /// The next frame, waiting while `waited` (what was waited for so far, counted as
    /// the module docs say) is below the timeout.
    fn read_frame(
        &mut self,
        waited: &mut Duration,
    ) -> Result<Result<Response, ProtocolError>, ClientError> {
        let mut buf = [0u8; 256];
        loop {
            if let Some(item) = self.parser.next_response() {
                return Ok(item);
            }
            if *waited >= self.timeout {
                return Err(ClientError::Timeout);
            }
            let slice = (self.timeout - *waited).min(WAIT_SLICE);
            let t0 = self.port.now();
            let n = self.port.recv(&mut buf, slice)?;
            if n == 0 {
                // Nothing arrived in the slice (however long it really took).
                *waited += slice;
            } else {
                *waited += self.port.now().saturating_sub(t0).min(slice);
                self.parser.feed(buf.get(..n).unwrap_or(&[]));
            }
        }
    }

    /// Feeds the parser what the line holds already, without waiting for more.
    fn take_waiting_input(&mut self) -> Result<(), ClientError> {
        let mut buf = [0u8; 256];
        // Bounded: a line that never falls silent (noise) is read by the resync anyway.
        for _ in 0..16 {
            let n = self.port.recv(&mut buf, Duration::ZERO)?;
            if n == 0 {
                break;
            }
            self.parser.feed(buf.get(..n).unwrap_or(&[]));
        }
        Ok(())
    }

    /// Brings the line back in step: sends `<id>P` and reads up to its answer.
    /// Returns the well-formed frames of controller `id` that came before it: late
    /// replies to earlier commands, oldest first. Garbage and other controllers'
    /// frames are dropped. Fails when the device does not answer in time.
    pub fn resync(&mut self, id: u8) -> Result<Vec<Response>, ClientError> {
        self.in_sync = false;
        if std::mem::take(&mut self.keep_input) {
            // After a timeout, input that is already here is kept: it may be the late
            // reply. Its last line ends here: whatever of it came in the timeout and
            // since is all that will come (a CR lost on the line), and the answer to
            // the query must not be read glued to it.
            self.take_waiting_input()?;
            self.parser.end_line();
        } else {
            self.parser.clear();
            let _ = self.port.discard_input();
        }
        self.port.send(&encode(&Command::QueryProductId { id }))?;
        let mut stale = Vec::new();
        // One timeout for the whole resync, however many frames come before the answer.
        let mut waited = Duration::ZERO;
        loop {
            let frame = self.read_frame(&mut waited).inspect_err(|e| {
                self.keep_input = matches!(e, ClientError::Timeout);
            })?;
            match frame {
                Ok(Response::ProductId { id: rid, .. }) if rid == id => {
                    // Whatever follows the answer was not asked for.
                    self.parser.clear();
                    self.in_sync = true;
                    return Ok(stale);
                }
                // (Only the first matters to `settle`; a few more are kept.)
                Ok(r) if r.id() == id && stale.len() < 64 => stale.push(r),
                _ => {}
            }
        }
    }

    /// After `cmd` failed with an error whose fate is unknown
    /// ([`ClientError::fate_unknown`]): resynchronizes, and if the device's late
    /// reply to `cmd` was among the frames before the resync answer, returns what it
    /// said (`Ok` for its acknowledgement). `Err(original)` when no reply to it came
    /// (the command was lost or its reply was unreadable); the resync's error when
    /// the device does not answer at all.
    pub fn settle(&mut self, cmd: &Command, original: ClientError) -> Result<(), ClientError> {
        if !original.fate_unknown() {
            return Err(original);
        }
        // Only a timeout can leave the reply still to come; after a garbled,
        // foreign or wrong reply the frame in turn was that one.
        let timed_out = matches!(original, ClientError::Timeout);
        let stale = self.resync(cmd.id())?;
        match (timed_out, stale.first()) {
            (true, Some(Response::Ack { code, .. })) if *code == cmd.code() => Ok(()),
            (true, Some(Response::Error { code, .. })) => Err(ClientError::Device(*code)),
            _ => Err(original),
        }
    }

    /// Send `cmd` and wait for the reply addressed from its controller ID.
    /// `<id>E<e>` becomes [`ClientError::Device`].
    pub fn transact(&mut self, cmd: &Command) -> Result<Response, ClientError> {
        if self.in_sync {
            self.parser.clear();
            let _ = self.port.discard_input();
        } else {
            self.resync(cmd.id())?;
        }
        self.in_sync = false;
        self.port.send(&encode(cmd))?;
        self.sent_at = self.port.now();
        let id = cmd.id();
        let mut waited = Duration::ZERO;
        let frame = self.read_frame(&mut waited).inspect_err(|e| {
            self.keep_input = matches!(e, ClientError::Timeout);
        })?;
        match frame {
            Ok(Response::Error { id: rid, code }) if rid == id => {
                self.in_sync = true;
                Err(ClientError::Device(code))
            }
            Ok(r) if r.id() == id => {
                self.in_sync = true;
                Ok(r)
            }
            Ok(r) => Err(ClientError::Unexpected(r)),
            Err(e) => Err(ClientError::Garbled(e)),
        }
    }

    /// A reply of the wrong kind: the line is out of step.
    fn unexpected(&mut self, r: Response) -> ClientError {
        self.in_sync = false;
        ClientError::Unexpected(r)
    }

    /// Send a command that is answered by a bare acknowledgement.
    pub fn command(&mut self, cmd: &Command) -> Result<(), ClientError> {
        match self.transact(cmd)? {
            Response::Ack { code, .. } if code == cmd.code() => Ok(()),
            other => Err(self.unexpected(other)),
        }
    }

    /// `<id>I` (§6.1).
    pub fn initialize(&mut self, id: u8) -> Result<(), ClientError> {
        self.command(&Command::Initialize { id })
    }

    /// `<id>Q<m>` (§6.13).
    pub fn query_status(&mut self, id: u8, motor: u32) -> Result<MotorStatus, ClientError> {
        match self.transact(&Command::QueryStatus { id, motor })? {
            Response::Status {
                running,
                home0,
                home1,
                ..
            } => Ok(MotorStatus {
                running,
                home0,
                home1,
            }),
            other => Err(self.unexpected(other)),
        }
    }

    /// `<id>B` (§6.14): the debounced limit input byte.
    pub fn query_limits(&mut self, id: u8) -> Result<u8, ClientError> {
        match self.transact(&Command::QueryLimits { id })? {
            Response::Limits { bits, .. } => Ok(bits),
            other => Err(self.unexpected(other)),
        }
    }

    /// `<id>P` (§6.18): `(product, firmware version)`.
    pub fn product_id(&mut self, id: u8) -> Result<(u32, u32), ClientError> {
        match self.transact(&Command::QueryProductId { id })? {
            Response::ProductId {
                product, version, ..
            } => Ok((product, version)),
            other => Err(self.unexpected(other)),
        }
    }
}

#[cfg(test)]
mod tests;
