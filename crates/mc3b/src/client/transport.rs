//! The byte link a client talks over, and its clock.

use std::io;
use std::sync::LazyLock;
use std::time::{Duration, Instant};

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
fn monotonic() -> Duration {
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
