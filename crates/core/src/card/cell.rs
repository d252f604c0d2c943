//! Every card's [`Peripherals`] behind a mutex of its own ([`PeriphCell`]), and the one
//! word with which the engine counts a tick of every idle card at once
//! ([`PeriphCells::count_idle_tick`]) instead of taking their locks.
//!
//! The word holds a bit per card, set while the card's peripherals are
//! [idle](Peripherals::idle) as last unlocked, and above the bits a count of the
//! engine's ticks. Each tick the engine adds one to the count and gets the bits back, in
//! one atomic operation: the cards whose bit was set have had that tick counted (an idle
//! tick only moves time); the others it ticks under their lock. Whoever locks a card
//! clears its bit, in one atomic operation that also reads the count, and first runs the
//! ticks counted since the card's bit was set (`Peripherals::idle_ticks`); unlocking an
//! idle card sets its bit again and notes the count then. So every tick of a card either
//! was counted before a holder of its lock took the count (and that holder runs it before
//! changing anything) or runs under the lock afterwards, with what the holder changed:
//! every holder of the lock sees the state an engine ticking every card would have made.
//! One atomic operation a tick for all cards (a read-modify-write empties the processor's
//! store buffer: one a card cost about a tenth of a tick of 48 groups on 12 cards).

use super::Peripherals;
use crate::config::CARDS;
use parking_lot::{Mutex, MutexGuard};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// The bits of the word below the count: one per card.
const CARD_BITS: u32 = 16;
const _: () = assert!(CARDS <= CARD_BITS as usize, "a bit for every card");
/// The cards' bits.
const CARD_MASK: u64 = (1 << CARD_BITS) - 1;
/// One tick in the count.
const ONE_TICK: u64 = 1 << CARD_BITS;
/// The count's bits (the word's others), once shifted down.
const COUNT_MASK: u64 = u64::MAX >> CARD_BITS;

/// The peripherals of every card and the word that counts their idle ticks (see the
/// module).
#[derive(Debug)]
pub struct PeriphCells {
    cells: Vec<PeriphCell>,
    word: Arc<AtomicU64>,
}

impl PeriphCells {
    /// Default peripherals for `cards` cards (at most [`CARDS`]), for an engine whose
    /// ticks last `dt_ns`.
    pub fn new(cards: usize, dt_ns: u64) -> PeriphCells {
        let word = Arc::new(AtomicU64::new(0));
        let cells = (0..cards.min(CARDS))
            .map(|card| PeriphCell {
                locked: Mutex::new(Locked {
                    periph: Peripherals::default(),
                    idle_since: 0,
                }),
                word: Arc::clone(&word),
                bit: 1 << card,
                dt_ns,
            })
            .collect();
        PeriphCells { cells, word }
    }

    /// Card `card`'s peripherals, if there is such a card.
    pub fn get(&self, card: usize) -> Option<&PeriphCell> {
        self.cells.get(card)
    }

    /// Every card's peripherals, in card order.
    pub fn cells(&self) -> &[PeriphCell] {
        &self.cells
    }

    /// The engine's tick of the cards: counts it for every idle card and returns the
    /// cards it counted it for (bit c for card c); the others the engine ticks under
    /// their lock.
    #[inline]
    pub fn count_idle_tick(&self) -> u64 {
        self.word.fetch_add(ONE_TICK, Ordering::AcqRel) & CARD_MASK
    }
}

/// One card's [`Peripherals`] behind their mutex (see the module).
#[derive(Debug)]
pub struct PeriphCell {
    locked: Mutex<Locked>,
    /// The cards' word.
    word: Arc<AtomicU64>,
    /// The card's bit in it.
    bit: u64,
    /// The tick length the counted ticks have, ns.
    dt_ns: u64,
}

/// What a card's mutex guards.
#[derive(Debug)]
struct Locked {
    periph: Peripherals,
    /// The word's count when the card's bit was last set.
    idle_since: u64,
}

impl PeriphCell {
    /// Locks the peripherals (after running the ticks counted while they were idle).
    pub fn lock(&self) -> PeriphGuard<'_> {
        let mut locked = self.locked.lock();
        let was = self.word.fetch_and(!self.bit, Ordering::AcqRel);
        if was & self.bit != 0 {
            let n = (was >> CARD_BITS).wrapping_sub(locked.idle_since) & COUNT_MASK;
            if n > 0 {
                locked.periph.idle_ticks(n, self.dt_ns);
            }
        }
        PeriphGuard { cell: self, locked }
    }
}

/// The locked peripherals of a [`PeriphCell`]; unlocking an idle card lets the engine
/// count its ticks.
#[derive(Debug)]
pub struct PeriphGuard<'a> {
    cell: &'a PeriphCell,
    locked: MutexGuard<'a, Locked>,
}

impl std::ops::Deref for PeriphGuard<'_> {
    type Target = Peripherals;
    fn deref(&self) -> &Peripherals {
        &self.locked.periph
    }
}

impl std::ops::DerefMut for PeriphGuard<'_> {
    fn deref_mut(&mut self) -> &mut Peripherals {
        &mut self.locked.periph
    }
}

impl Drop for PeriphGuard<'_> {
    fn drop(&mut self) {
        // Still locked here (the mutex guard drops after this).
        if self.locked.periph.idle() {
            let was = self.cell.word.fetch_or(self.cell.bit, Ordering::AcqRel);
            self.locked.idle_since = was >> CARD_BITS;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::card::rio;
    use crate::interrupt::Pending;

    /// The same change made to both copies.
    fn change(p: &mut Peripherals, k: u64) {
        fn rio(p: &mut Peripherals, set: usize) -> &mut rio::Set<{ rio::RIO_PORTS }> {
            p.rio.rio_set_mut(set).unwrap()
        }
        fn ario(p: &mut Peripherals, set: usize) -> &mut rio::Set<{ rio::ARIO_SLAVES }> {
            p.rio.ario_set_mut(set).unwrap()
        }
        let set = (k / 16 % 2) as usize;
        let slave = (k / 32 % 4) as u16;
        match k % 20 {
            0 => p.rio.set_ario_update_rate(set, 300.0).unwrap(),
            1 => p.rio.set_ario_update_rate(set, 1700.0).unwrap(),
            2 => p.rio.set_ario_clock_divider(set, 2000).unwrap(),
            3 => p.rio.set_ario_node_delay(3000),
            4 | 5 => ario(p, set).set_slave_control(slave, true).unwrap(),
            6..=8 => ario(p, set).set_slave_control(slave, false).unwrap(),
            9 => ario(p, set).set_output(slave, (k >> 8) as u16).unwrap(),
            10 => {
                let on = p.rio.rio_sets()[set].control();
                p.rio.set_rio_control(set, !on).unwrap();
            }
            11 => rio(p, set).set_slave_control(slave, k & 64 != 0).unwrap(),
            12 => rio(p, set).set_output(0, (k >> 8) as u16).unwrap(),
            13 => {
                p.timer.set_period(70_000).unwrap();
                p.timer.set_trigger(true);
                p.timer.set_enabled(k & 128 != 0);
            }
            14 => ario(p, set)
                .set_input_trigger((k % 8) as u16, true)
                .unwrap(),
            16 => p.dac.set_output((k >> 8) as usize % 8, 1.0).unwrap(),
            17 => p.dac.set_update_rate(300.0).unwrap(),
            18 => p.rio.set_rio_update_rate(set, 700.0).unwrap(),
            19 => p.rio.set_rio_clock_divider(set, 3000).unwrap(),
            _ => p
                .rio
                .set_slave_failed(true, set, usize::from(slave), k & 256 != 0),
        }
    }

    /// Back to idle (the ARIO timing keeps its phase and settings).
    fn make_idle(p: &mut Peripherals) {
        p.timer.set_enabled(false);
        for set in 0..2 {
            p.rio.set_rio_control(set, false).unwrap();
            for slave in 0..32 {
                let ario = p.rio.ario_set_mut(set).unwrap();
                ario.set_slave_control(slave, false).unwrap();
            }
        }
    }

    #[test]
    fn counted_idle_ticks_give_the_state_of_ticking_every_time() {
        // `plain` ticks every card every time; `cells` as the engine does: the ticks of
        // idle cards are counted (one operation for all) and run when a card is next
        // locked, the others run under the lock. Three cards, changed at random, each
        // idle for long stretches and busy for others, independently.
        let dt = 1_000_000;
        let cells = PeriphCells::new(3, dt);
        let mut plain: Vec<Peripherals> = (0..3).map(|_| Peripherals::default()).collect();
        let mut seed: u64 = 99;
        let mut counted = [0; 3];
        for n in 0..50_000 {
            let idle = cells.count_idle_tick();
            for (card, (cell, plain)) in cells.cells().iter().zip(&mut plain).enumerate() {
                let fired = if idle >> card & 1 == 1 {
                    counted[card] += 1;
                    Pending::default()
                } else {
                    let mut p = cell.lock();
                    assert!(!p.tick(dt));
                    std::mem::take(&mut p.pending)
                };
                assert!(!plain.tick(dt));
                assert_eq!(
                    fired,
                    std::mem::take(&mut plain.pending),
                    "card {card}, tick {n}"
                );
            }
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let card = (seed >> 40) as usize % 3;
            let (cell, copy) = (&cells.cells()[card], &mut plain[card]);
            // Changes now and then, long idle stretches in between.
            if (seed >> 33) % 40 == 0 {
                let k = seed >> 20;
                change(&mut cell.lock(), k);
                change(copy, k);
            } else if (seed >> 33) % 300 == 1 {
                make_idle(&mut cell.lock());
                make_idle(copy);
            }
            if n % 101 == 0 {
                for (cell, plain) in cells.cells().iter().zip(&plain) {
                    assert_eq!(*cell.lock(), *plain, "tick {n}");
                }
            }
        }
        for (card, (cell, plain)) in cells.cells().iter().zip(&plain).enumerate() {
            assert_eq!(*cell.lock(), *plain, "card {card}");
            assert!(
                counted[card] > 5_000,
                "card {card}: idle stretches were counted ({})",
                counted[card]
            );
        }
    }

    #[test]
    fn a_card_counts_only_the_ticks_of_its_own_idle_stretch() {
        // Card 0 made idle, card 1 left busy (its remote I/O on, as by default): 10
        // engine ticks count for card 0 alone, and locking card 0 runs exactly those 10
        // (its ARIO timing moved 10 ticks, as peripherals ticked 10 times).
        let dt = 1_000_000;
        let cells = PeriphCells::new(2, dt);
        let mut plain = Peripherals::default();
        for p in [&mut *cells.cells()[0].lock(), &mut plain] {
            make_idle(p);
            // One transfer, which the ARIO sets' idleness needs to have seen.
            assert!(!p.tick(dt));
            p.pending = Default::default();
        }
        drop(cells.cells()[1].lock());
        for _ in 0..10 {
            assert_eq!(cells.count_idle_tick(), 0b01);
            assert!(!plain.tick(dt));
        }
        assert_eq!(*cells.cells()[0].lock(), plain);
        // Locked and let go again: the count starts over from there.
        assert_eq!(cells.count_idle_tick(), 0b01);
        assert!(!plain.tick(dt));
        assert_eq!(*cells.cells()[0].lock(), plain);
    }
}
