//! What an observer outside the program (the browser panel, `MCCL_PANEL`) sees of the
//! machine beyond the groups' snapshots: per card the channels' inputs, encoders,
//! converters, outputs, timer, watchdog and remote I/O words, and per group its override
//! and in-position status. The engine thread copies it at the end of a tick that publishes
//! the snapshots, only while an observer wants it, at most every [`VIEW_EVERY_NS`] of real
//! time, and under the virtual clocks also at the last tick of every run (so what the
//! waiting program reads next is shown); the observer reads the copy. Neither side ever waits for
//! the other: the engine skips a copy while the observer is reading the last one.
//!
//! Without an observer the tick only loads one atomic flag. With one, a tick that
//! publishes everything also reads the coarse monotonic clock; only a tick that copies
//! brings the channels' deferred steps up to date, so the ticks between copies stay as
//! cheap as without an observer (deferred steps, cruise ticks).

use crate::config::AXES;
use parking_lot::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Real time between two copies: 20 ms, at most 50 copies a second (read on the coarse
/// monotonic clock, so give or take its resolution, a few ms).
pub const VIEW_EVERY_NS: u64 = 20_000_000;

/// One channel as the card sees it.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ChannelView {
    /// Home sensor input, limit switch inputs (+, −) after the program's wiring setting.
    pub inputs: [bool; 3],
    /// Physical levels of the home sensor and the + and − switches (true: hit).
    pub raw: [bool; 3],
    /// Encoder count.
    pub encoder: i64,
    /// Motor position, UU of machine position.
    pub motor: f64,
    /// Pulses output so far.
    pub pulses: i64,
    /// D/A output, V.
    pub dac: f32,
    /// Voltage at the A/D input now, and the last converted value, V.
    pub adc: [f32; 2],
    /// LED lit.
    pub led: bool,
}

/// One card.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CardView {
    /// The channels 0..7.
    pub channels: [ChannelView; AXES],
    /// Emergency-stop input pressed.
    pub emergency: bool,
    /// Timer enabled, its period in system clocks of 10 ns.
    pub timer: (bool, u32),
    /// Watchdog enabled, its compare value, its count, resets so far.
    pub watchdog: (bool, u32, u64, u32),
    /// RIO words per set and port: inputs latched, outputs set.
    pub rio_in: [[u16; 4]; 2],
    /// RIO outputs per set and port.
    pub rio_out: [[u16; 4]; 2],
    /// A/D conversion running.
    pub adc_running: bool,
}

/// One group's part that is not in its snapshot.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct GroupView {
    /// Override ratio, percent.
    pub override_pct: f64,
    /// `MCC_GetInPosStatus` per axis.
    pub inpos: [u8; AXES],
}

/// A copy made by the engine thread.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct View {
    /// Ticks completed when it was made (0 and `made` false before the first copy).
    pub ticks: u64,
    /// Whether a copy was made yet.
    pub made: bool,
    /// `MCC_GetGoHomeStatus` without the waiting a spinning program gets.
    pub home_status: i32,
    /// Per card passed to `MCC_InitSystem`.
    pub cards: Vec<CardView>,
    /// Per group slot (`None`: no such group).
    pub groups: Vec<Option<GroupView>>,
}

/// The copy and the observer's request.
#[derive(Debug, Default)]
pub struct ViewCell {
    wanted: AtomicBool,
    next_ns: AtomicU64,
    view: Mutex<View>,
}

impl ViewCell {
    /// Asks the engine to keep copying (an observer is looking) or to stop.
    pub fn want(&self, on: bool) {
        self.wanted.store(on, Ordering::Relaxed);
    }

    /// Whether an observer asked for copies.
    pub fn wanted(&self) -> bool {
        self.wanted.load(Ordering::Relaxed)
    }

    /// Whether a copy may be due at the next tick that publishes everything, without
    /// counting it as made: what decides that a tick ahead is no cruise tick (which
    /// copies nothing). Between copies an observer costs the ticks nothing but this.
    pub(super) fn may_be_due(&self) -> bool {
        self.wanted() && crate::clock::coarse_monotonic_ns() >= self.next_ns.load(Ordering::Relaxed)
    }

    /// Stores `v` as the last copy, unless the observer is reading the last one: then
    /// this copy is skipped and the next tick makes one.
    pub(in crate::engine) fn offer(&self, v: View) {
        if let Some(mut cell) = self.view.try_lock() {
            *cell = v;
        } else {
            self.next_ns.store(0, Ordering::Relaxed);
        }
    }

    /// The last copy (waits only while the engine is writing one, a few µs).
    pub fn get(&self) -> View {
        self.view.lock().clone()
    }

    /// Whether this tick copies: an observer wants it, and [`VIEW_EVERY_NS`] passed since
    /// the last copy or the tick is the last of a run (virtual clocks). Asked once, at
    /// the start of a tick that publishes everything; a `true` counts as the copy made
    /// (the next is due [`VIEW_EVERY_NS`] later), so the tick must then copy.
    pub(super) fn due(&self, last_of_run: bool) -> bool {
        if !self.wanted() {
            return false;
        }
        let now = crate::clock::coarse_monotonic_ns();
        if last_of_run || now >= self.next_ns.load(Ordering::Relaxed) {
            self.next_ns
                .store(now.saturating_add(VIEW_EVERY_NS), Ordering::Relaxed);
            true
        } else {
            false
        }
    }
}
