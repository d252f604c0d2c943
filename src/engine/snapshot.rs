//! What a group publishes after every change, for status calls that must not wait for the
//! engine: a sequence lock over plain atomic words (one writer at a time: whoever holds
//! the group's lock; any number of readers, which retry while a write is in progress).

use crate::planner::Axes;
use crate::vendor::COMMAND_INFO;
use std::sync::atomic::{fence, AtomicU64, Ordering};

/// A group's published state.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct GroupSnapshot {
    /// Motion status (`GMS_*`).
    pub status: i32,
    /// Error record (0 when none).
    pub error: i32,
    /// Commands queued and not yet started.
    pub queued: i32,
    /// Command position in user coordinates (UU).
    pub pos: Axes,
    /// Command position in reference (machine) coordinates (UU).
    pub ref_pos: Axes,
    /// Pulse position per axis.
    pub pulses: [i64; 8],
    /// Velocity per axis (UU/s).
    pub vel: Axes,
    /// Tangential (path) speed (UU/s).
    pub path_speed: f64,
    /// The command being executed (type -1 when none).
    pub cmd: COMMAND_INFO,
}

const WORDS: usize = 3 + 8 * 4 + 1 + 15;

impl GroupSnapshot {
    fn to_words(self) -> [u64; WORDS] {
        let mut w = [0u64; WORDS];
        let mut i = 0;
        let mut put = |x: u64| {
            w[i] = x;
            i += 1;
        };
        put(self.status as u32 as u64);
        put(self.error as u32 as u64);
        put(self.queued as u32 as u64);
        self.pos.iter().for_each(|v| put(v.to_bits()));
        self.ref_pos.iter().for_each(|v| put(v.to_bits()));
        self.pulses.iter().for_each(|v| put(*v as u64));
        self.vel.iter().for_each(|v| put(v.to_bits()));
        put(self.path_speed.to_bits());
        let c = &self.cmd;
        put(c.nType as u32 as u64);
        put(c.nCommandIndex as u32 as u64);
        put(c.dfFeedSpeed.to_bits());
        c.dfPos.iter().for_each(|v| put(v.to_bits()));
        put(c.dfAcctime.to_bits());
        put(c.dfDectime.to_bits());
        put(c.nMotionPhase as u32 as u64);
        put(c.nCommandIndex_LD as u32 as u64);
        w
    }

    fn from_words(w: &[u64; WORDS]) -> GroupSnapshot {
        let mut it = w.iter().copied();
        let mut next = || it.next().unwrap_or(0);
        let status = next() as u32 as i32;
        let error = next() as u32 as i32;
        let queued = next() as u32 as i32;
        let pos = std::array::from_fn(|_| f64::from_bits(next()));
        let ref_pos = std::array::from_fn(|_| f64::from_bits(next()));
        let pulses = std::array::from_fn(|_| next() as i64);
        let vel = std::array::from_fn(|_| f64::from_bits(next()));
        let path_speed = f64::from_bits(next());
        let nType = next() as u32 as i32;
        let nCommandIndex = next() as u32 as i32;
        let dfFeedSpeed = f64::from_bits(next());
        let dfPos = std::array::from_fn(|_| f64::from_bits(next()));
        let dfAcctime = f64::from_bits(next());
        let dfDectime = f64::from_bits(next());
        let nMotionPhase = next() as u32 as i32;
        let nCommandIndex_LD = next() as u32 as i32;
        GroupSnapshot {
            status,
            error,
            queued,
            pos,
            ref_pos,
            pulses,
            vel,
            path_speed,
            cmd: COMMAND_INFO {
                nType,
                nCommandIndex,
                dfFeedSpeed,
                dfPos,
                dfAcctime,
                dfDectime,
                nMotionPhase,
                nCommandIndex_LD,
            },
        }
    }
}

/// A published [`GroupSnapshot`] (sequence lock).
#[derive(Debug)]
pub struct SnapshotCell {
    seq: AtomicU64,
    words: [AtomicU64; WORDS],
}

impl Default for SnapshotCell {
    fn default() -> Self {
        SnapshotCell {
            seq: AtomicU64::new(0),
            words: std::array::from_fn(|_| AtomicU64::new(0)),
        }
    }
}

impl SnapshotCell {
    /// Publishes `s`. Callers must be serialised (they hold the group's lock).
    pub fn store(&self, s: &GroupSnapshot) {
        let w = s.to_words();
        let seq = self.seq.load(Ordering::Relaxed);
        self.seq.store(seq.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        for (cell, v) in self.words.iter().zip(w) {
            cell.store(v, Ordering::Relaxed);
        }
        self.seq.store(seq.wrapping_add(2), Ordering::Release);
    }

    /// Reads the last published snapshot (never a torn one).
    pub fn load(&self) -> GroupSnapshot {
        loop {
            let s1 = self.seq.load(Ordering::Acquire);
            if s1 & 1 == 1 {
                std::hint::spin_loop();
                continue;
            }
            let mut w = [0u64; WORDS];
            for (v, cell) in w.iter_mut().zip(&self.words) {
                *v = cell.load(Ordering::Relaxed);
            }
            fence(Ordering::Acquire);
            if self.seq.load(Ordering::Relaxed) == s1 {
                return GroupSnapshot::from_words(&w);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let mut s = GroupSnapshot {
            status: 2,
            error: 0xF301,
            queued: 17,
            path_speed: 12.5,
            ..Default::default()
        };
        s.pos[3] = -1.25;
        s.ref_pos[7] = 9.0;
        s.pulses[1] = -123_456_789_012;
        s.vel[0] = 3.5;
        s.cmd.nType = -1;
        s.cmd.dfPos[5] = 42.0;
        s.cmd.nCommandIndex_LD = 77;
        let cell = SnapshotCell::default();
        cell.store(&s);
        assert_eq!(cell.load(), s);
    }

    #[test]
    fn readers_never_see_a_torn_snapshot() {
        let cell = std::sync::Arc::new(SnapshotCell::default());
        let w = cell.clone();
        let writer = std::thread::spawn(move || {
            for i in 0..20_000 {
                let v = f64::from(i);
                w.store(&GroupSnapshot {
                    pos: [v; 8],
                    vel: [v; 8],
                    ..Default::default()
                });
            }
        });
        for _ in 0..20_000 {
            let s = cell.load();
            assert!(s.pos.iter().chain(s.vel.iter()).all(|&x| x == s.pos[0]));
        }
        writer.join().unwrap();
    }
}
