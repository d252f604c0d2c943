//! Command/response client for the MC3B over any byte transport.
//!
//! The real transport is an RS-232 port at 19200 baud, 8 data bits, no
//! parity, one stop bit, no flow control (§3.2), opened with [`open_port`].
//! On a pseudo-terminal the modem-control ioctls (DTR/RTS/CTS...) fail with
//! `ENOTTY`; the client never needs them, so it neither sets nor reads them
//! and such failures cannot occur on its path.
//!
//! Decisions:
//! * Before each command, stale input (a late reply to a command that timed
//!   out, line noise) is discarded.
//! * Frames that cannot be decoded, and frames from other controller IDs,
//!   are skipped while waiting; if no matching reply arrives within the
//!   timeout the result is [`ClientError::Timeout`].
//! * A hang-up of the line (the device side of a pty closed: `EPIPE`/`EIO`)
//!   is an I/O error; the C library reports it as a TIMEOUT, like a pulled
//!   cable on a real port.

use std::collections::VecDeque;
use std::fmt;
use std::io;
use std::time::{Duration, Instant};

use serialport::{ClearBuffer, DataBits, FlowControl, Parity, SerialPort, StopBits, TTYPort};

use super::codec::{encode, Command, ErrorCode, Response, ResponseParser};
use super::emulator::Emulator;

/// Baud rate of the MC3B (fixed, §2.2).
pub const BAUD_RATE: u32 = 19_200;
/// Default time to wait for a reply.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(500);

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
    static EPOCH: once_cell::sync::Lazy<Instant> = once_cell::sync::Lazy::new(Instant::now);
    EPOCH.elapsed()
}

fn serial_send(port: &mut dyn SerialPort, data: &[u8]) -> io::Result<()> {
    port.write_all(data)?;
    port.flush()
}

fn serial_recv(port: &mut dyn SerialPort, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
    port.set_timeout(timeout.max(Duration::from_millis(1)))
        .map_err(io::Error::from)?;
    match port.read(buf) {
        Ok(0) => {
            // EOF on a tty: the other side hung up.
            Err(io::Error::new(
                io::ErrorKind::BrokenPipe,
                "serial line hung up",
            ))
        }
        Ok(n) => Ok(n),
        Err(e) if e.kind() == io::ErrorKind::TimedOut => Ok(0),
        Err(e) if e.kind() == io::ErrorKind::Interrupted => Ok(0),
        Err(e) => Err(e),
    }
}

impl Transport for TTYPort {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        serial_send(self, data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        serial_recv(self, buf, timeout)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.clear(ClearBuffer::Input).map_err(io::Error::from)
    }
}

impl Transport for Box<dyn SerialPort> {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        serial_send(self.as_mut(), data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        serial_recv(self.as_mut(), buf, timeout)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.clear(ClearBuffer::Input).map_err(io::Error::from)
    }
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

/// Open a serial device at 19200 8N1 without flow control.
pub fn open_port(path: &str, timeout: Duration) -> Result<TTYPort, serialport::Error> {
    let builder = serialport::new(path, BAUD_RATE)
        .data_bits(DataBits::Eight)
        .parity(Parity::None)
        .stop_bits(StopBits::One)
        .flow_control(FlowControl::None)
        .timeout(timeout);
    let port = TTYPort::open(&builder)?;
    // Best effort: a pty may refuse some tty requests.
    let _ = port.clear(ClearBuffer::All);
    Ok(port)
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
    /// No matching reply within the timeout.
    Timeout,
    /// The transport failed (including a hang-up).
    Io(io::Error),
    /// The device answered `<id>E<e>`.
    Device(ErrorCode),
    /// The device answered something that does not fit the command.
    Unexpected(Response),
}

impl fmt::Display for ClientError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClientError::Timeout => write!(f, "timeout waiting for the MC3B"),
            ClientError::Io(e) => write!(f, "serial I/O error: {e}"),
            ClientError::Device(c) => write!(f, "MC3B error {}", c.number()),
            ClientError::Unexpected(r) => write!(f, "unexpected reply {r:?}"),
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
}

impl<T: Transport> Client<T> {
    /// Wrap a transport; `timeout` bounds each reply wait.
    pub fn new(port: T, timeout: Duration) -> Self {
        Client {
            port,
            parser: ResponseParser::new(),
            timeout,
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

    /// Send `cmd` and wait for the reply addressed from its controller ID.
    /// `<id>E<e>` becomes [`ClientError::Device`].
    pub fn transact(&mut self, cmd: &Command) -> Result<Response, ClientError> {
        self.parser.clear();
        let _ = self.port.discard_input();
        self.port.send(&encode(cmd))?;
        let id = cmd.id();
        // The transport's clock: real time on a serial line, the emulator's own time on
        // an in-process link (so a timeout there costs no real time).
        let deadline = self.port.now() + self.timeout;
        let mut buf = [0u8; 256];
        loop {
            while let Some(item) = self.parser.next_response() {
                match item {
                    Ok(Response::Error { id: rid, code }) if rid == id => {
                        return Err(ClientError::Device(code))
                    }
                    Ok(r) if r.id() == id => return Ok(r),
                    // Noise or another controller's reply: keep waiting.
                    _ => {}
                }
            }
            let now = self.port.now();
            if now >= deadline {
                return Err(ClientError::Timeout);
            }
            let n = self.port.recv(&mut buf, deadline - now)?;
            self.parser.feed(buf.get(..n).unwrap_or(&[]));
        }
    }

    /// Send a command that is answered by a bare acknowledgement.
    pub fn command(&mut self, cmd: &Command) -> Result<(), ClientError> {
        match self.transact(cmd)? {
            Response::Ack { code, .. } if code == cmd.code() => Ok(()),
            other => Err(ClientError::Unexpected(other)),
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
            other => Err(ClientError::Unexpected(other)),
        }
    }

    /// `<id>B` (§6.14): the debounced limit input byte.
    pub fn query_limits(&mut self, id: u8) -> Result<u8, ClientError> {
        match self.transact(&Command::QueryLimits { id })? {
            Response::Limits { bits, .. } => Ok(bits),
            other => Err(ClientError::Unexpected(other)),
        }
    }

    /// `<id>P` (§6.18): `(product, firmware version)`.
    pub fn product_id(&mut self, id: u8) -> Result<(u32, u32), ClientError> {
        match self.transact(&Command::QueryProductId { id })? {
            Response::ProductId {
                product, version, ..
            } => Ok((product, version)),
            other => Err(ClientError::Unexpected(other)),
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
    fn noise_and_foreign_ids_are_skipped_and_chunks_reassembled() {
        let t = Scripted {
            replies: VecDeque::from(vec![
                b"garbage\r\n1B4\r".to_vec(),
                b"\n0".to_vec(),
                b"B3".to_vec(),
                b"7\r".to_vec(),
            ]),
            sent: vec![],
        };
        let mut c = Client::new(t, Duration::from_millis(50));
        assert_eq!(c.query_limits(0).ok(), Some(37));
        assert_eq!(c.transport().sent, b"0B\r");
        // A mismatched ack is reported, not taken as success.
        c.transport().replies.push_back(b"0A\r".to_vec());
        let r = c.command(&Command::Stop { id: 0, motor: 0 });
        assert!(matches!(r, Err(ClientError::Unexpected(_))));
    }
}
