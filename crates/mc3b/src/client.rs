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

use std::collections::VecDeque;
use std::fmt;
use std::io;
use std::sync::LazyLock;
use std::time::{Duration, Instant};

use crate::codec::{encode, Command, ErrorCode, ProtocolError, Response, ResponseParser};
use crate::emulator::Emulator;

/// Default time to wait for a reply.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(500);
/// Longest single read while waiting for a reply; see the module docs.
pub const WAIT_SLICE: Duration = Duration::from_millis(20);

/// A byte link to a device.
pub trait Transport {
    /// Write all of `data`.
    fn send(&mut self, data: &[u8]) -> io::Result<()>;
    /// Read what is available, waiting at most `timeout`; `Ok(0)` when
    /// nothing arrived in time.
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize>;
    /// Drop unread input (best effort).
    fn discard_input(&mut self) -> io::Result<()> {
        Ok(())
    }
    /// The device's time: for a real line the monotonic clock (since the first call in
    /// the process), for an in-process emulator its own clock.
    fn now(&self) -> Duration {
        monotonic()
    }
    /// Let `d` pass on the device side: a real line sleeps, an in-process emulator
    /// advances its clock.
    fn idle(&mut self, d: Duration) {
        std::thread::sleep(d);
    }
    /// Whether the device runs in real time (a serial line); `false` for an in-process
    /// emulator whose time only moves in [`Transport::idle`] and [`Transport::recv`].
    fn is_realtime(&self) -> bool {
        true
    }
}

/// Time since the first call in this process (a monotonic clock).
pub fn monotonic() -> Duration {
    static EPOCH: LazyLock<Instant> = LazyLock::new(Instant::now);
    EPOCH.elapsed()
}

impl Transport for Box<dyn Transport + Send> {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        self.as_mut().send(data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        self.as_mut().recv(buf, timeout)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.as_mut().discard_input()
    }
    fn now(&self) -> Duration {
        self.as_ref().now()
    }
    fn idle(&mut self, d: Duration) {
        self.as_mut().idle(d)
    }
    fn is_realtime(&self) -> bool {
        self.as_ref().is_realtime()
    }
}

/// Reply timeout from the environment: `MCL_TIMEOUT_MS` milliseconds if it holds a
/// positive integer, else [`DEFAULT_TIMEOUT`] (used by the `mcl_*` library and the
/// backend alike).
pub fn timeout_from_env() -> Duration {
    std::env::var("MCL_TIMEOUT_MS")
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .filter(|&ms| ms > 0)
        .map(Duration::from_millis)
        .unwrap_or(DEFAULT_TIMEOUT)
}

/// An in-process transport wired straight to an [`Emulator`]. Waiting for a
/// reply advances the emulator's clock by the wait time, so tests over it are
/// deterministic.
#[derive(Debug, Default)]
pub struct EmulatorLink {
    /// The device.
    pub emulator: Emulator,
    rx: VecDeque<u8>,
}

impl EmulatorLink {
    /// A link to a fresh emulator.
    pub fn new() -> Self {
        Self::default()
    }
}

impl Transport for EmulatorLink {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        let out = self.emulator.receive(data);
        self.rx.extend(out);
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        if self.rx.is_empty() {
            self.emulator.advance(timeout);
            return Ok(0);
        }
        let mut n = 0;
        while n < buf.len() {
            match (self.rx.pop_front(), buf.get_mut(n)) {
                (Some(b), Some(slot)) => *slot = b,
                _ => break,
            }
            n += 1;
        }
        Ok(n)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.rx.clear();
        Ok(())
    }
    fn now(&self) -> Duration {
        self.emulator.now()
    }
    fn idle(&mut self, d: Duration) {
        self.emulator.advance(d);
    }
    fn is_realtime(&self) -> bool {
        false
    }
}

/// Why a command failed.
#[derive(Debug)]
pub enum ClientError {
    /// No reply within the timeout.
    Timeout,
    /// The transport failed (including a hang-up).
    Io(io::Error),
    /// The device answered `<id>E<e>`.
    Device(ErrorCode),
    /// A frame that does not fit the command: another command's answer, or another
    /// controller's.
    Unexpected(Response),
    /// A frame that cannot be decoded (garbage, too long).
    Garbled(ProtocolError),
}

impl ClientError {
    /// Whether the device may have acted on the command although no good reply came
    /// (everything but a clean `<id>E<e>`).
    pub fn fate_unknown(&self) -> bool {
        !matches!(self, ClientError::Device(_))
    }
}

impl fmt::Display for ClientError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClientError::Timeout => write!(f, "timeout waiting for the MC3B"),
            ClientError::Io(e) => write!(f, "serial I/O error: {e}"),
            ClientError::Device(c) => write!(f, "MC3B error {}", c.number()),
            ClientError::Unexpected(r) => write!(f, "unexpected reply {r:?}"),
            ClientError::Garbled(e) => write!(f, "unreadable reply ({e})"),
        }
    }
}

impl std::error::Error for ClientError {}

impl From<io::Error> for ClientError {
    fn from(e: io::Error) -> Self {
        ClientError::Io(e)
    }
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
mod tests {
    use super::*;

    fn client() -> Client<EmulatorLink> {
        Client::new(EmulatorLink::new(), Duration::from_millis(100))
    }

    #[test]
    fn queries_and_acks_over_the_loopback() {
        let mut c = client();
        assert!(c.initialize(0).is_ok());
        assert_eq!(c.product_id(0).ok(), Some((1, 100)));
        assert_eq!(c.query_limits(0).ok(), Some(0));
        let st = c.query_status(0, 0).ok();
        assert_eq!(
            st,
            Some(MotorStatus {
                running: false,
                home0: false,
                home1: false
            })
        );
        assert!(c
            .command(&Command::Move {
                id: 0,
                motor: 0,
                steps: 100,
                direction: 0
            })
            .is_ok());
        assert_eq!(c.query_status(0, 0).ok().map(|s| s.bits()), Some(1));
    }

    #[test]
    fn device_errors_and_timeouts() {
        let mut c = client();
        let r = c.command(&Command::SetAcceleration {
            id: 0,
            motor: 0,
            value: 5,
        });
        assert!(matches!(r, Err(ClientError::Device(ErrorCode::OutOfRange))));
        // Controller 1 does not exist: silence -> timeout.
        let r = c.query_limits(1);
        assert!(matches!(r, Err(ClientError::Timeout)));
    }

    struct Scripted {
        replies: VecDeque<Vec<u8>>,
        sent: Vec<u8>,
    }
    impl Transport for Scripted {
        fn send(&mut self, data: &[u8]) -> io::Result<()> {
            self.sent.extend_from_slice(data);
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
            match self.replies.pop_front() {
                Some(r) => {
                    let n = r.len().min(buf.len());
                    buf[..n].copy_from_slice(&r[..n]);
                    Ok(n)
                }
                None => Ok(0),
            }
        }
    }

    #[test]
    fn garbage_and_foreign_replies_fail_at_once_then_the_line_resyncs() {
        let t = Scripted {
            replies: VecDeque::from(vec![b"garbage\r".to_vec()]),
            sent: vec![],
        };
        let mut c = Client::new(t, Duration::from_millis(50));
        let r = c.query_limits(0);
        assert!(matches!(r, Err(ClientError::Garbled(_))), "{r:?}");
        assert!(!c.in_sync());
        // The next command first resyncs with 0P: the stale 0B5 before its answer is
        // dropped, then 0B is sent and its reply, in chunks, reassembled.
        c.transport().sent.clear();
        c.transport().replies = VecDeque::from(vec![
            b"0B5\r0P1,100\r".to_vec(),
            b"0".to_vec(),
            b"B3".to_vec(),
            b"7\r".to_vec(),
        ]);
        assert_eq!(c.query_limits(0).ok(), Some(37));
        assert_eq!(c.transport().sent, b"0P\r0B\r");
        assert!(c.in_sync());
        // Another controller's reply: no waiting for ours.
        c.transport().replies.push_back(b"1B4\r".to_vec());
        let r = c.query_limits(0);
        assert!(matches!(r, Err(ClientError::Unexpected(_))), "{r:?}");
        // A mismatched ack is reported, not taken as success.
        c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec(), b"0A\r".to_vec()]);
        let r = c.command(&Command::Stop { id: 0, motor: 0 });
        assert!(matches!(r, Err(ClientError::Unexpected(_))), "{r:?}");
        // A line longer than any reply fails before its CR arrives.
        c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec(), vec![b'7'; 200]]);
        let r = c.query_limits(0);
        assert!(
            matches!(r, Err(ClientError::Garbled(ProtocolError::LineTooLong))),
            "{r:?}"
        );
    }

    /// A transport whose reads overrun: each takes `stall` times what it was asked
    /// to wait (the reading thread not scheduled on a loaded host); the reply is
    /// there from the `ready_at`th read on.
    struct Stalling {
        reads: usize,
        ready_at: usize,
        stall: u32,
        reply: Vec<u8>,
        clock: Duration,
    }
    impl Transport for Stalling {
        fn send(&mut self, _: &[u8]) -> io::Result<()> {
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], t: Duration) -> io::Result<usize> {
            self.reads += 1;
            if self.reads < self.ready_at {
                self.clock += t * self.stall;
                return Ok(0);
            }
            // Data was waiting: the read returns as soon as it is scheduled.
            self.clock += Duration::from_millis(1) * self.stall;
            let n = self.reply.len().min(buf.len());
            buf[..n].copy_from_slice(&self.reply[..n]);
            self.reply.clear();
            Ok(n)
        }
        fn now(&self) -> Duration {
            self.clock
        }
    }

    #[test]
    fn the_timeout_counts_only_time_the_reply_could_have_been_read() {
        // Timeout 100 ms, slices of 20 ms, each read taking 10x as long: the reply
        // waiting at the 4th read comes after 3 x 200 + 10 = 610 ms of the host's
        // time but after 3 x 20 + 1 = 61 ms of watching: in time.
        let t = Stalling {
            reads: 0,
            ready_at: 4,
            stall: 10,
            reply: b"0B9\r".to_vec(),
            clock: Duration::ZERO,
        };
        let mut c = Client::new(t, Duration::from_millis(100));
        assert_eq!(c.query_limits(0).ok(), Some(9));
        assert_eq!(c.transport().clock, Duration::from_millis(610));
        // With nothing coming, the timeout is 5 slices of watching (1 s of stalls).
        c.transport().ready_at = usize::MAX;
        c.transport().reads = 0;
        let r = c.query_limits(0);
        assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
        assert_eq!(c.transport().reads, 5);
    }

    /// A device that answers each command line it is sent with the next scripted
    /// reply, only once the command was sent (unlike [`Scripted`], whose replies are
    /// there whenever the client reads); `arrived` holds bytes on the line not read yet.
    struct Answering {
        answers: VecDeque<Vec<u8>>,
        arrived: VecDeque<u8>,
        sent: Vec<u8>,
    }
    impl Answering {
        fn new(answers: &[&[u8]]) -> Answering {
            Answering {
                answers: answers.iter().map(|a| a.to_vec()).collect(),
                arrived: VecDeque::new(),
                sent: Vec::new(),
            }
        }
    }
    impl Transport for Answering {
        fn send(&mut self, data: &[u8]) -> io::Result<()> {
            self.sent.extend_from_slice(data);
            for _ in data.iter().filter(|&&b| b == b'\r') {
                if let Some(a) = self.answers.pop_front() {
                    self.arrived.extend(a);
                }
            }
            Ok(())
        }
        fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
            let mut n = 0;
            while let (Some(slot), Some(b)) = (buf.get_mut(n), self.arrived.pop_front()) {
                *slot = b;
                n += 1;
            }
            Ok(n)
        }
    }

    #[test]
    fn a_reply_that_lost_its_carriage_return_does_not_fail_the_next_call() {
        // 0B is answered "0B5" and the CR is lost on the line: the call times out.
        // The next call resyncs (0P) and then asks 0B again. The answer to 0P,
        // "0P1,100\r", follows the partial "0B5" on the line; read as one line it is
        // "0B50P1,100", which answers nothing, and the resync would time out too. The
        // partial line was complete as far as it will ever be when the timeout
        // expired: it is a reply of its own (a stale one), and the call succeeds.
        let t = Answering::new(&[b"0B5", b"0P1,100\r", b"0B7\r"]);
        let mut c = Client::new(t, Duration::from_millis(50));
        let r = c.query_limits(0);
        assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
        assert_eq!(c.query_limits(0).ok(), Some(7));
        assert_eq!(c.transport().sent, b"0B\r0P\r0B\r");
        assert!(c.in_sync());
        // The same when the bytes without their CR only arrive after the timeout,
        // before the next call: "0B6" waits on the line when the resync starts.
        c.transport().answers = VecDeque::from(vec![b"".to_vec()]);
        let r = c.query_limits(0);
        assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
        c.transport().arrived.extend(b"0B6");
        c.transport().answers = VecDeque::from(vec![b"0P1,100\r".to_vec(), b"0B3\r".to_vec()]);
        assert_eq!(c.query_limits(0).ok(), Some(3));
        // A command whose acknowledgement lost its CR is found done by `settle`.
        let stop = Command::Stop { id: 0, motor: 1 };
        c.transport().answers = VecDeque::from(vec![b"0S".to_vec(), b"0P1,100\r".to_vec()]);
        let e = c.command(&stop).err();
        assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
        let r = c.settle(&stop, ClientError::Timeout);
        assert!(r.is_ok(), "{r:?}");
    }

    #[test]
    fn settle_finds_a_late_acknowledgement() {
        // The ack of 0S1 comes only after the timeout: settle's resync reads it before
        // the 0P answer and reports the command done.
        let t = Scripted {
            replies: VecDeque::new(),
            sent: vec![],
        };
        let mut c = Client::new(t, Duration::from_millis(20));
        let stop = Command::Stop { id: 0, motor: 1 };
        let e = c.command(&stop).err();
        assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
        c.transport().replies = VecDeque::from(vec![b"0S\r0P1,100\r".to_vec()]);
        let r = c.settle(&stop, ClientError::Timeout);
        assert!(r.is_ok(), "{r:?}");
        assert_eq!(c.transport().sent, b"0S1\r0P\r");
        // No late reply: the original error stands (the command's fate is unknown).
        let e = c.command(&stop).err();
        assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
        c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec()]);
        let r = c.settle(&stop, ClientError::Timeout);
        assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
        // A late refusal is the device's error.
        let _ = c.command(&stop);
        c.transport().replies = VecDeque::from(vec![b"0E1\r0P1,100\r".to_vec()]);
        let r = c.settle(&stop, ClientError::Timeout);
        assert!(
            matches!(r, Err(ClientError::Device(ErrorCode::MotorRunning))),
            "{r:?}"
        );
    }
}
