//! Polls under a virtual clock: a program that reads a status or position again and
//! again at the same virtual time is waiting, so time runs for it (`stepped`: one tick,
//! `fast`: ticks until what it watches changes). A single read changes nothing.

use super::homing;
use super::shared::Shared;
use crate::clock::ClockMode;
use std::sync::atomic::{AtomicU64, Ordering};

/// Reads of one kind at the same virtual time that make a program "waiting" (a program
/// that checks a status twice is not spinning; one that reads it a third time is).
pub const SPIN_POLLS: u64 = 3;

fn pack_poll(tick: u64, count: u64) -> u64 {
    (tick << 8) | count.min(255)
}

fn unpack_poll(v: u64) -> (u64, u64) {
    (v >> 8, v & 0xFF)
}

impl Shared {
    /// A status poll of group `g` that found it busy with `status`. Under a virtual clock a
    /// poll repeated [`SPIN_POLLS`] times at the same virtual time is a program waiting:
    /// `stepped` runs one tick,
    /// `fast` runs ticks until the group's status is no longer `status` (at most
    /// [`crate::clock::FAST_POLL_MAX`]). A single status check changes nothing.
    pub fn poll(&self, g: u16, status: i32) {
        if !self.repeated(g, 0) {
            return;
        }
        match self.clock.mode() {
            ClockMode::Realtime => {}
            ClockMode::Stepped => self.clock.wait_ticks(1),
            ClockMode::Fast => {
                self.published.watch.1.store(status, Ordering::Release);
                self.published
                    .watch
                    .0
                    .store(i32::from(g), Ordering::Release);
                self.clock
                    .wait_ticks(self.clock.ticks_for(crate::clock::FAST_POLL_MAX));
                self.published.watch.0.store(-1, Ordering::Release);
            }
        }
        self.mark_polled(g, 0);
    }

    /// A position read of group `g` (`MCC_GetCurPos`): repeated [`SPIN_POLLS`] times at the
    /// same virtual time, it runs one tick, so `while (x < 10) MCC_GetCurPos(&x, ...)` moves.
    pub fn poll_position(&self, g: u16) {
        if self.repeated(g, 1)
            && self.published.status[usize::from(g)].load(Ordering::Acquire)
                != crate::vendor::consts::GMS_STOP
        {
            self.clock.wait_ticks(1);
        }
        self.mark_polled(g, 1);
    }

    /// Counts reads of one kind at the same virtual time; from the
    /// [`SPIN_POLLS`]th on the program is taken to be waiting.
    fn repeated(&self, g: u16, kind: usize) -> bool {
        match self.published.last_poll.get(usize::from(g)) {
            Some(l) => self.repeated_in(&l[kind]),
            None => false,
        }
    }

    fn repeated_in(&self, cell: &AtomicU64) -> bool {
        if !self.clock.mode().virtual_time() {
            return false;
        }
        let now = self.clock.ticks();
        let (tick, count) = unpack_poll(cell.load(Ordering::Acquire));
        let count = if tick == now { count + 1 } else { 1 };
        cell.store(pack_poll(now, count), Ordering::Release);
        count >= SPIN_POLLS
    }

    fn mark_polled(&self, g: u16, kind: usize) {
        if let Some(l) = self.published.last_poll.get(usize::from(g)) {
            self.mark_polled_in(&l[kind]);
        }
    }

    fn mark_polled_in(&self, cell: &AtomicU64) {
        let now = self.clock.ticks();
        let (tick, count) = unpack_poll(cell.load(Ordering::Acquire));
        if tick != now {
            // Time moved on during the poll: the next read is the first at this time.
            cell.store(pack_poll(now, 0), Ordering::Release);
        } else {
            cell.store(pack_poll(now, count), Ordering::Release);
        }
    }

    /// `MCC_GetGoHomeStatus`: the status, after letting virtual time run when the program
    /// spins on it (as [`Shared::poll`] does for motion status: `fast` runs ticks until
    /// the status changes, `stepped` one tick).
    pub fn home_status(&self) -> i32 {
        let status = self.home.home_status.load(Ordering::Acquire);
        if status == homing::HOME_BUSY && self.repeated_in(&self.home.home_poll) {
            match self.clock.mode() {
                ClockMode::Realtime => {}
                ClockMode::Stepped => self.clock.wait_ticks(1),
                ClockMode::Fast => {
                    self.home.home_watch.store(status, Ordering::Release);
                    self.clock
                        .wait_ticks(self.clock.ticks_for(crate::clock::FAST_POLL_MAX));
                    self.home.home_watch.store(i32::MIN, Ordering::Release);
                }
            }
            self.mark_polled_in(&self.home.home_poll);
        }
        homing::home_status_read(self.home.home_status.load(Ordering::Acquire))
    }

    /// During a tick: ends a fast-clock poll's run when its group's status changed.
    pub(super) fn check_watch(&self) {
        let h = self.home.home_watch.load(Ordering::Acquire);
        if h != i32::MIN && self.home.home_status.load(Ordering::Acquire) != h {
            self.clock.end_run_now();
        }
        let g = self.published.watch.0.load(Ordering::Acquire);
        if let Ok(g) = usize::try_from(g) {
            if self.published.status[g].load(Ordering::Acquire)
                != self.published.watch.1.load(Ordering::Acquire)
            {
                self.clock.end_run_now();
            }
        }
    }
}
