//! The handshake between the host and the card (vendor header: `MCC_SetHSKRoutine`,
//! `MCC_HostInterrupt`, `MCC_SlaveInterrupt`; the manuals describe none of them).
//!
//! The card is the slave on the bus; the HSK routine is the host's. Two directions:
//!
//! - `MCC_SlaveInterrupt`: the card (the slave) interrupts the host: one `HANDSHAKE`
//!   cause is raised at once and reaches the HSK routine after the next tick, as any
//!   cause raised between ticks.
//! - `MCC_HostInterrupt`: the host interrupts the card. The card counts the request
//!   and acknowledges it in its next tick by interrupting the host: one `HANDSHAKE`
//!   cause per request, delivered after that tick. The virtual card runs no program of
//!   its own, so the acknowledgement is all it does with the request.

use crate::interrupt::{Interrupt, Pending};

/// The card's side of the handshake.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Handshake {
    /// Host interrupts received and not yet acknowledged.
    waiting: u64,
    /// Host interrupts received since init.
    received: u64,
}

impl Handshake {
    /// `MCC_HostInterrupt`: the card receives a request (acknowledged next tick).
    pub fn host_interrupt(&mut self) {
        self.waiting = self.waiting.saturating_add(1);
        self.received = self.received.saturating_add(1);
    }

    /// `MCC_SlaveInterrupt`: the card interrupts the host now.
    pub fn slave_interrupt(&mut self, p: &mut Pending) {
        p.raise(Interrupt::Handshake);
    }

    /// Host interrupts received since init (each one also acknowledged, at the tick after
    /// it): what the card has seen of the host, for a test or a diagnostic.
    pub fn received(&self) -> u64 {
        self.received
    }

    /// Whether a request waits for its acknowledgement.
    pub fn waiting(&self) -> bool {
        self.waiting > 0
    }

    /// One tick: every waiting request is acknowledged with a handshake to the host.
    pub(crate) fn tick(&mut self, p: &mut Pending) {
        for _ in 0..std::mem::take(&mut self.waiting).min(255) {
            p.raise(Interrupt::Handshake);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn host_requests_are_acknowledged_at_the_next_tick_slave_ones_at_once() {
        let mut h = Handshake::default();
        let mut p = Pending::default();
        h.host_interrupt();
        h.host_interrupt();
        assert!(p.is_empty(), "not before the card's tick");
        assert!(h.waiting());
        h.slave_interrupt(&mut p);
        assert_eq!(p.hsk, [1], "the slave's own interrupt at once");
        h.tick(&mut p);
        assert_eq!(p.hsk, [3], "two acknowledgements");
        assert!(!h.waiting());
        let mut q = Pending::default();
        h.tick(&mut q);
        assert!(q.is_empty(), "each request acknowledged once");
        assert_eq!(h.received(), 2);
    }
}
