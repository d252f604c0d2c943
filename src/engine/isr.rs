//! Interrupts of the virtual card: the registered callbacks (`MCC_Set*Routine`) and the
//! causes raised during a tick.
//!
//! # How a cause reaches a callback
//!
//! Every card has a [`Pending`] set of causes inside its [`crate::card::Peripherals`].
//! Anything that detects an interrupt condition raises it there:
//!
//! - the card's own peripherals (timer, ADC, remote I/O) during
//!   [`Shared::tick_peripherals`](crate::engine::Shared::tick_peripherals);
//! - the program, between ticks (a single ADC conversion started by `MCC_StartADCConv`);
//! - any other part of the engine (limit and home inputs, encoder index and compare,
//!   closed-loop errors) through [`Shared::raise`](crate::engine::Shared::raise)`(card, `[`Interrupt`]`)` — callable
//!   from anywhere, also with a group lock held (lock order: group, then peripherals).
//!
//! At the end of each tick [`Shared::tick_peripherals`](crate::engine::Shared::tick_peripherals) takes every card's pending causes
//! and the engine thread calls [`IsrTable::deliver`] after it released every lock: for
//! each card in index order, the LIO, ENC, PCL, ADC, TMR, RIO and HSK routines, in that
//! order, each once, with a struct holding every cause of its kind raised since the last
//! delivery (several fields may be non-zero at once). A field counts how many times its
//! cause occurred, saturating at 255 (`TMRINT.TIMER` = timer expirations in the tick). A
//! kind with no cause, or with no routine registered, is skipped and its causes dropped.
//!
//! Callbacks run on the engine thread with no library lock held, so they may call any
//! `MCC_*` function: `MCC_AbortMotionEx`, `MCC_GetCurPos`, even `MCC_CloseSystem` (which
//! from the engine thread only stops the clock; no further callback of that tick runs).
//! A routine unregistered by another thread while a tick delivers may run once more.

pub use crate::interrupt::{Interrupt, Kind, Pending, KINDS, ORDER};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The interrupts one tick collected: `(card, causes)` for each card with a cause, in
/// card order. Fixed capacity (one entry per card), so collecting them allocates nothing
/// on the tick's path.
#[derive(Debug, Clone)]
pub struct Collected {
    len: usize,
    items: [(usize, Pending); crate::config::CARDS],
}

impl Default for Collected {
    fn default() -> Self {
        Collected::new()
    }
}

impl Collected {
    /// Nothing collected.
    pub fn new() -> Collected {
        Collected {
            len: 0,
            items: [(0, Pending::default()); crate::config::CARDS],
        }
    }

    /// Adds the causes of `card` (one entry per card: beyond `crate::config::CARDS`
    /// entries the rest is dropped, which cannot happen as cards are at most that many).
    pub fn push(&mut self, card: usize, p: Pending) {
        if let Some(slot) = self.items.get_mut(self.len) {
            *slot = (card, p);
            self.len += 1;
        }
    }

    /// The entries, in the order pushed.
    pub fn as_slice(&self) -> &[(usize, Pending)] {
        &self.items[..self.len]
    }

    /// Whether nothing was collected.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Forgets what was collected (the engine thread reuses one `Collected` for every
    /// tick: at 88 bytes a card it was a kilobyte copied several times a tick).
    pub fn clear(&mut self) {
        self.len = 0;
    }
}

/// The registered routines: per card, one C function pointer per [`Kind`] (0 = none).
#[derive(Debug)]
pub struct IsrTable {
    slots: Vec<[AtomicUsize; KINDS]>,
    /// How many slots hold a routine: [`IsrTable::any`] is asked after every tick.
    registered: AtomicUsize,
}

/// The C signature every routine shares: `void f(XXXINT *)` (the struct differs by kind).
type RawIsr = unsafe extern "system" fn(*mut u8);

impl IsrTable {
    /// A table for `cards` cards with nothing registered.
    pub fn new(cards: usize) -> IsrTable {
        IsrTable {
            slots: (0..cards)
                .map(|_| std::array::from_fn(|_| AtomicUsize::new(0)))
                .collect(),
            registered: AtomicUsize::new(0),
        }
    }

    /// Registers the routine at address `f` (0 unregisters) for `kind` on `card` (a card
    /// checked with [`Shared::card`](crate::engine::Shared::card)).
    pub fn set(&self, card: usize, kind: Kind, f: usize) {
        let old = self.slots[card][kind as usize].swap(f, Ordering::AcqRel);
        // Each change between empty and registered moves the count (registrations from
        // several threads each see their own slot's old value). While two threads change
        // one slot at once the count can be off (even wrap) between their swaps and
        // counts: `any` may then answer wrongly for a tick, as if the registration had
        // come a tick earlier or later, and the count is right again after both.
        match (old != 0, f != 0) {
            (false, true) => {
                self.registered.fetch_add(1, Ordering::AcqRel);
            }
            (true, false) => {
                self.registered.fetch_sub(1, Ordering::AcqRel);
            }
            _ => {}
        }
    }

    /// Whether any routine is registered on any card.
    pub fn any(&self) -> bool {
        self.registered.load(Ordering::Acquire) != 0
    }

    /// The address registered for `kind` on `card` (0 when none).
    pub fn get(&self, card: usize, kind: Kind) -> usize {
        self.slots
            .get(card)
            .map_or(0, |s| s[kind as usize].load(Ordering::Acquire))
    }

    /// Calls the routines for the causes collected in a tick, in the order of the module
    /// documentation. Call with no lock held. Stops when the clock is stopped (a routine
    /// closed the system).
    pub fn deliver(&self, collected: &Collected, clock: &crate::clock::Clock) {
        for (card, pending) in collected.as_slice() {
            for kind in ORDER {
                let bytes = pending.bytes(kind);
                if bytes.iter().all(|&b| b == 0) {
                    continue;
                }
                let f = self.get(*card, kind);
                if f == 0 {
                    continue;
                }
                if clock.stopped() {
                    return;
                }
                // A fresh copy per call: the routine may write to its struct.
                let mut buf = [0u8; 24];
                buf[..bytes.len()].copy_from_slice(bytes);
                // SAFETY: `f` was stored from a non-null `XXXISR` of this kind, a C
                // function taking a pointer to that kind's struct. `buf` holds the
                // struct's bytes (all its fields are BYTE, no padding, alignment 1) and
                // outlives the call; C routines cannot unwind into Rust.
                unsafe {
                    let f: RawIsr = std::mem::transmute::<usize, RawIsr>(f);
                    f(buf.as_mut_ptr());
                }
            }
        }
    }
}

/// Error record of a card reset by its watchdog, set on every group of that card
/// (no vendor code exists; 0xF103 is unused by the vendor's table, see docs/decisions.md).
pub const ERR_WATCHDOG_RESET: i32 = crate::error_record::ErrorRecord::WatchdogReset.code();

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn any_counts_registered_routines() {
        // Two cards: register on both, replace one routine with another, unregister one
        // twice; `any` holds exactly while a slot is non-zero.
        let t = IsrTable::new(2);
        assert!(!t.any());
        t.set(0, Kind::Tmr, 0x1000);
        t.set(1, Kind::Enc, 0x2000);
        t.set(1, Kind::Enc, 0x3000);
        assert!(t.any());
        t.set(1, Kind::Enc, 0);
        t.set(1, Kind::Enc, 0);
        assert!(t.any(), "card 0's timer routine is still there");
        assert_eq!(t.get(0, Kind::Tmr), 0x1000);
        t.set(0, Kind::Tmr, 0);
        assert!(!t.any());
        t.set(0, Kind::Lio, 0);
        assert!(!t.any(), "unregistering an empty slot counts nothing");
    }

    #[test]
    fn collected_holds_one_entry_per_card_in_order() {
        let mut c = Collected::new();
        assert!(c.is_empty());
        let mut p = Pending::default();
        p.raise(Interrupt::Timer(1));
        for card in [3, 0, 11] {
            c.push(card, p);
        }
        let cards: Vec<usize> = c.as_slice().iter().map(|(k, _)| *k).collect();
        assert_eq!(cards, [3, 0, 11], "in the order pushed");
        assert_eq!(c.as_slice()[1].1.tmr, [1]);
        // 12 cards at most (MAX_CARD_NUM): a 13th entry is dropped, nothing panics.
        for card in 0..20 {
            c.push(card, p);
        }
        assert_eq!(c.as_slice().len(), crate::config::CARDS);
        assert_eq!(c.as_slice()[11].0, 8);
    }

    #[test]
    fn pending_fields_land_on_the_struct_bytes() {
        let mut p = Pending::default();
        assert!(p.is_empty());
        p.raise(Interrupt::LioOtn(2));
        p.raise(Interrupt::LioHome(7));
        p.raise(Interrupt::AdcComp(0));
        p.raise(Interrupt::AdcComp(0));
        p.raise(Interrupt::AdcTag);
        p.raise(Interrupt::Timer(300));
        p.raise(Interrupt::RioFail);
        assert_eq!(p.lio[10], 1);
        assert_eq!(p.lio[23], 1);
        assert_eq!(p.adc[0], 2, "counted");
        assert_eq!(p.adc[9], 1);
        assert_eq!(p.tmr[0], 255, "saturates");
        assert_eq!(p.rio[8], 1);
        assert!(!p.is_empty());
        let q = p;
        p.raise(Interrupt::EncComp(8));
        p.raise(Interrupt::LioOtp(200));
        assert_eq!(p, q, "out-of-range channels are ignored");
    }
}
