//! A transport to an emulator in the same process, for deterministic tests.

use std::collections::VecDeque;
use std::io;
use std::time::Duration;

use super::Transport;
use crate::emulator::Emulator;

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
