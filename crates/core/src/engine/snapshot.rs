//! What a group publishes after every change, for status calls that must not wait for the
//! engine: a sequence lock over plain atomic words (one writer at a time: whoever holds
//! the group's lock; any number of readers, which retry while a write is in progress).

use crate::config::AXES;
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
    /// Whether a command is being executed.
    pub running: bool,
    /// The command being executed (or the last one started).
    pub cmd: COMMAND_INFO,
}

/// The part of a snapshot that changes on every tick of a moving group.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Motion {
    /// Motion status (`GMS_*`).
    pub status: i32,
    /// Command position in user coordinates (UU).
    pub pos: Axes,
    /// Velocity per axis (UU/s).
    pub vel: Axes,
    /// The feed speed of the last period (UU/s, `MCC_GetCurFeedSpeed`).
    pub feed: f64,
}

/// The part of a snapshot that changes when commands start, end or are queued.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Info {
    /// Error record (0 when none).
    pub error: i32,
    /// Commands queued and not yet started.
    pub queued: i32,
    /// Whether a command is being executed (`cmd` is then it; otherwise `cmd` names the
    /// last one started).
    pub running: bool,
    /// The command being executed.
    pub cmd: COMMAND_INFO,
    /// Reference position minus user position, per axis (UU).
    pub offset: Axes,
    /// Pulses per UU per axis (negative when the output is reversed).
    pub factor: Axes,
}

/// Rounds to the nearest whole pulse (halves away from zero) with a float-to-int
/// conversion instead of a libm call (an MC3B's step counts).
pub fn round_pulses(x: f64) -> i64 {
    if x >= 0.0 {
        (x + 0.5) as i64
    } else {
        (x - 0.5) as i64
    }
}

/// A tenth of a millionth of a pulse: how far short of a whole pulse a position may fall
/// and still count it (the vendor's library, measured: 1 − 1e-7 pulse counts, 1 − 1.5e-7
/// does not).
const PULSE_TOLERANCE: f64 = 1e-7;

/// The pulse count of a position `x` pulses from zero, as the vendor's library counts:
/// the whole pulses toward zero, a position within 1e-7 pulse short of a whole
/// pulse counting it (so that a position computed a rounding error short of a whole
/// pulse is not a pulse short). A float-to-int conversion: this runs for every axis on
/// every tick.
#[inline]
pub fn whole_pulses(x: f64) -> i64 {
    if x >= 0.0 {
        (x + PULSE_TOLERANCE) as i64
    } else {
        (x - PULSE_TOLERANCE) as i64
    }
}

/// The pulses of an axis at position `pos` (user coordinates) with its reference
/// `offset` and pulses per UU `factor`: [`whole_pulses`] of the reference position.
#[inline(always)]
pub fn axis_pulses(pos: f64, offset: f64, factor: f64) -> i64 {
    whole_pulses((pos + offset) * factor)
}

/// A pulse count in user units: what `MCC_GetCurPos` reads (the vendor's library reports
/// whole pulses); a position of an axis with no pulses per unit stays as it is.
#[inline]
pub fn pulses_to_pos(p: i64, factor: f64, exact: f64) -> f64 {
    if factor != 0.0 {
        p as f64 / factor
    } else {
        exact
    }
}

impl Motion {
    /// The feed speed of the last period (UU/s).
    pub fn path_speed(&self) -> f64 {
        self.feed
    }
}

impl GroupSnapshot {
    /// Assembles a snapshot from its two parts (pulses and reference position derived).
    pub fn from_parts(m: &Motion, i: &Info) -> GroupSnapshot {
        GroupSnapshot {
            status: m.status,
            error: i.error,
            queued: i.queued,
            pos: pos_of(&m.pos, &i.offset, &i.factor),
            ref_pos: ref_of(&m.pos, &i.offset, &i.factor),
            pulses: pulses_of(&m.pos, &i.offset, &i.factor),
            vel: m.vel,
            path_speed: m.path_speed(),
            running: i.running,
            cmd: i.cmd,
        }
    }
}

/// The pulse position of user position `pos`: its reference position times the pulses
/// per UU, in whole pulses ([`whole_pulses`]).
fn pulses_of(pos: &Axes, offset: &Axes, factor: &Axes) -> [i64; 8] {
    std::array::from_fn(|k| whole_pulses((pos[k] + offset[k]) * factor[k]))
}

/// The reference position a program reads of user position `pos`: its pulses in units.
fn ref_of(pos: &Axes, offset: &Axes, factor: &Axes) -> Axes {
    let p = pulses_of(pos, offset, factor);
    std::array::from_fn(|k| pulses_to_pos(p[k], factor[k], pos[k] + offset[k]))
}

/// The user position a program reads of user position `pos`: the reference position it
/// reads less the offset.
fn pos_of(pos: &Axes, offset: &Axes, factor: &Axes) -> Axes {
    let r = ref_of(pos, offset, factor);
    std::array::from_fn(|k| {
        if offset[k] == 0.0 {
            r[k]
        } else {
            r[k] - offset[k]
        }
    })
}

const MOTION_WORDS: usize = 1 + 8 + 8 + 1;
const INFO_WORDS: usize = 2 + 15 + 8 + 8 + 1;

fn motion_from(w: &[u64; MOTION_WORDS]) -> Motion {
    Motion {
        status: w[0] as u32 as i32,
        pos: std::array::from_fn(|k| f64::from_bits(w[1 + k])),
        vel: std::array::from_fn(|k| f64::from_bits(w[9 + k])),
        feed: f64::from_bits(w[17]),
    }
}

fn info_words(i: &Info) -> [u64; INFO_WORDS] {
    let mut w = [0u64; INFO_WORDS];
    let c = &i.cmd;
    w[0] = i.error as u32 as u64;
    w[1] = i.queued as u32 as u64;
    w[2] = c.nType as u32 as u64;
    w[3] = c.nCommandIndex as u32 as u64;
    w[4] = c.dfFeedSpeed.to_bits();
    for k in 0..8 {
        w[5 + k] = c.dfPos[k].to_bits();
        w[17 + k] = i.offset[k].to_bits();
        w[25 + k] = i.factor[k].to_bits();
    }
    w[13] = c.dfAcctime.to_bits();
    w[14] = c.dfDectime.to_bits();
    w[15] = c.nMotionPhase as u32 as u64;
    w[16] = c.nCommandIndex_LD as u32 as u64;
    w[33] = u64::from(i.running);
    w
}

fn info_from(w: &[u64; INFO_WORDS]) -> Info {
    Info {
        error: w[0] as u32 as i32,
        queued: w[1] as u32 as i32,
        cmd: COMMAND_INFO {
            nType: w[2] as u32 as i32,
            nCommandIndex: w[3] as u32 as i32,
            dfFeedSpeed: f64::from_bits(w[4]),
            dfPos: std::array::from_fn(|k| f64::from_bits(w[5 + k])),
            dfAcctime: f64::from_bits(w[13]),
            dfDectime: f64::from_bits(w[14]),
            nMotionPhase: w[15] as u32 as i32,
            nCommandIndex_LD: w[16] as u32 as i32,
        },
        offset: std::array::from_fn(|k| f64::from_bits(w[17 + k])),
        factor: std::array::from_fn(|k| f64::from_bits(w[25 + k])),
        running: w[33] != 0,
    }
}

/// A sequence lock over `N` atomic words: one writer at a time, any number of readers,
/// which retry while a write is in progress.
#[derive(Debug)]
struct SeqWords<const N: usize> {
    seq: AtomicU64,
    words: [AtomicU64; N],
}

impl<const N: usize> Default for SeqWords<N> {
    fn default() -> Self {
        SeqWords {
            seq: AtomicU64::new(0),
            words: std::array::from_fn(|_| AtomicU64::new(0)),
        }
    }
}

impl<const N: usize> SeqWords<N> {
    fn store(&self, w: &[u64; N]) {
        self.store_by(|cells| {
            for (cell, v) in cells.iter().zip(w) {
                cell.store(*v, Ordering::Relaxed);
            }
        });
    }

    /// Stores the words `write` stores (relaxed) as one write: readers see all of them
    /// or none.
    #[inline]
    fn store_by(&self, write: impl FnOnce(&[AtomicU64; N])) {
        let seq = self.seq.load(Ordering::Relaxed);
        self.seq.store(seq.wrapping_add(1), Ordering::Relaxed);
        fence(Ordering::Release);
        write(&self.words);
        self.seq.store(seq.wrapping_add(2), Ordering::Release);
    }

    fn load(&self) -> [u64; N] {
        self.read(|cells| {
            let mut w = [0u64; N];
            for (v, cell) in w.iter_mut().zip(cells) {
                *v = cell.load(Ordering::Relaxed);
            }
            w
        })
    }

    /// What `read` makes of the words (relaxed loads of any of them) as one write left
    /// them: `read` runs again while a write is in progress or came in between.
    #[inline]
    fn read<R>(&self, read: impl Fn(&[AtomicU64; N]) -> R) -> R {
        loop {
            let s1 = self.seq.load(Ordering::Acquire);
            if s1 & 1 == 1 {
                std::hint::spin_loop();
                continue;
            }
            let r = read(&self.words);
            fence(Ordering::Acquire);
            if self.seq.load(Ordering::Relaxed) == s1 {
                return r;
            }
        }
    }
}

/// A published [`GroupSnapshot`], in two sequence-locked parts: [`Motion`] (stored every
/// tick) and [`Info`] (stored when it changes).
#[derive(Debug, Default)]
pub struct SnapshotCell {
    motion: SeqWords<MOTION_WORDS>,
    info: SeqWords<INFO_WORDS>,
}

impl SnapshotCell {
    /// Publishes the motion part. Callers must be serialised (they hold the group's lock).
    pub fn store_motion(&self, m: &Motion) {
        self.store_motion_parts(m.status, &m.pos, &m.vel, m.feed);
    }

    /// Publishes the motion part from its fields, without assembling a [`Motion`] first
    /// (this runs for every group on every tick that publishes): the status, the 8
    /// positions, the 8 velocities and the feed speed, one word each, as `motion_from`
    /// reads them. Callers must be serialised.
    #[inline]
    pub fn store_motion_parts(&self, status: i32, pos: &Axes, vel: &Axes, feed: f64) {
        self.motion.store_by(|w| {
            w[0].store(status as u32 as u64, Ordering::Relaxed);
            for k in 0..8 {
                w[1 + k].store(pos[k].to_bits(), Ordering::Relaxed);
                w[9 + k].store(vel[k].to_bits(), Ordering::Relaxed);
            }
            w[17].store(feed.to_bits(), Ordering::Relaxed);
        });
    }

    /// Publishes the words of the motion part that a period of `axes` alone changes:
    /// their positions and speeds (of `pos` and `vel`) and the feed speed. The status
    /// and the other axes' words stay as the last publication left them, which must be
    /// this motion's. Callers must be serialised.
    #[inline]
    pub fn store_moving_parts(&self, axes: &[u8], pos: &Axes, vel: &Axes, feed: f64) {
        self.motion.store_by(|w| {
            for &a in axes {
                let k = usize::from(a) % AXES;
                w[1 + k].store(pos[k].to_bits(), Ordering::Relaxed);
                w[9 + k].store(vel[k].to_bits(), Ordering::Relaxed);
            }
            w[17].store(feed.to_bits(), Ordering::Relaxed);
        });
    }

    /// Publishes the info part. Callers must be serialised.
    pub fn store_info(&self, i: &Info) {
        self.info.store(&info_words(i));
    }

    /// Publishes both parts.
    pub fn store(&self, m: &Motion, i: &Info) {
        self.store_info(i);
        self.store_motion(m);
    }

    /// Reads the last published snapshot (each part never torn).
    pub fn load(&self) -> GroupSnapshot {
        let i = info_from(&self.info.load());
        let m = motion_from(&self.motion.load());
        GroupSnapshot::from_parts(&m, &i)
    }

    /// Reads only the motion part.
    pub fn load_motion(&self) -> Motion {
        motion_from(&self.motion.load())
    }

    /// Reads only the exact command position (user coordinates, UU): the 8 words of it,
    /// not the rest of the snapshot.
    pub fn load_exact_pos(&self) -> Axes {
        self.motion
            .read(|w| std::array::from_fn(|k| f64::from_bits(w[1 + k].load(Ordering::Relaxed))))
    }

    /// Reads the position in the program's coordinates (`MCC_GetCurRefPos`): whole pulses
    /// in user units less the offset, from the position's 8 words and the info's frame.
    pub fn load_program_pos(&self) -> Axes {
        let (offset, factor) = self.load_frame();
        pos_of(&self.load_exact_pos(), &offset, &factor)
    }

    /// Reads only the motion status (`GMS_*`), one word (`MCC_GetMotionStatus`, the call
    /// programs wait on).
    pub fn load_status(&self) -> i32 {
        self.motion
            .read(|w| w[0].load(Ordering::Relaxed) as u32 as i32)
    }

    /// Reads only the info part.
    pub fn load_info(&self) -> Info {
        info_from(&self.info.load())
    }

    /// Reads the position as the machine counts it (`MCC_GetCurPos`, which programs call
    /// in tight loops): the pulse count in UU, from the position's 8 words and the info's
    /// frame.
    /// `comp`: the compensation pulses of each axis's channel, which the vendor's library
    /// counts into this position.
    pub fn load_machine_pos(&self, comp: &[i64; 8]) -> Axes {
        let (offset, factor) = self.load_frame();
        let exact = self.load_exact_pos();
        let p = pulses_of(&exact, &offset, &factor);
        std::array::from_fn(|k| pulses_to_pos(p[k] + comp[k], factor[k], exact[k] + offset[k]))
    }

    /// Reads the pulse position from the position and the info's offsets and pulses per
    /// UU, as [`SnapshotCell::load`] makes it, with the compensation pulses `comp` added
    /// (`MCC_GetPulsePos`).
    pub fn load_pulses(&self, comp: &[i64; 8]) -> [i64; 8] {
        let (offset, factor) = self.load_frame();
        let p = pulses_of(&self.load_exact_pos(), &offset, &factor);
        std::array::from_fn(|k| p[k] + comp[k])
    }

    /// The info's offsets (reference minus user position) and pulses per UU, per axis.
    fn load_frame(&self) -> (Axes, Axes) {
        self.info.read(|w| {
            let word = |i: usize| f64::from_bits(w[i].load(Ordering::Relaxed));
            (
                std::array::from_fn(|k| word(17 + k)),
                std::array::from_fn(|k| word(25 + k)),
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn motion_stored_from_its_parts_lies_in_its_words_and_reads_back() {
        let mut m = Motion {
            status: -3,
            feed: 2.5,
            ..Default::default()
        };
        for k in 0..8 {
            m.pos[k] = -1.5 * k as f64 + 0.25;
            m.vel[k] = 7.0 / (k as f64 + 1.0);
        }
        let c = SnapshotCell::default();
        c.store_motion_parts(m.status, &m.pos, &m.vel, m.feed);
        // Word 0 the status (its 32 bits), 1..=8 the positions, 9..=16 the velocities,
        // 17 the feed speed.
        let mut words = [0u64; MOTION_WORDS];
        words[0] = 0xFFFF_FFFD;
        for k in 0..8 {
            words[1 + k] = m.pos[k].to_bits();
            words[9 + k] = m.vel[k].to_bits();
        }
        words[17] = 2.5f64.to_bits();
        assert_eq!(c.motion.load(), words);
        assert_eq!(c.load_motion(), m);
        assert_eq!(c.load_exact_pos(), m.pos);
        assert_eq!(c.load_status(), -3);
    }

    #[test]
    fn round_trip() {
        let mut m = Motion {
            status: 2,
            feed: 4.0,
            ..Default::default()
        };
        m.pos[3] = -1.25;
        m.pos[1] = -2.0;
        m.vel[0] = 3.5;
        let mut i = Info {
            error: 0xF301,
            queued: 17,
            ..Default::default()
        };
        i.offset[7] = 9.0;
        i.factor = [500.0; 8];
        i.factor[1] = -1000.0;
        i.cmd.nType = -1;
        i.cmd.dfPos[5] = 42.0;
        i.cmd.nCommandIndex_LD = 77;
        let cell = SnapshotCell::default();
        cell.store(&m, &i);
        let s = cell.load();
        assert_eq!((s.status, s.error, s.queued), (2, 0xF301, 17));
        assert_eq!(s.pos, m.pos);
        assert_eq!(s.vel, m.vel);
        assert_eq!(s.ref_pos[7], 9.0);
        assert_eq!(s.pulses[3], -625, "-1.25 x 500");
        assert_eq!(s.pulses[1], 2000, "-2 x -1000");
        assert_eq!(s.pulses[7], 4500);
        assert_eq!(s.cmd, i.cmd);
        assert_eq!(cell.load_motion(), m);
        assert_eq!(cell.load_info(), i);
        assert_eq!(cell.load_status(), 2);
        assert_eq!(cell.load_exact_pos(), m.pos);
        assert_eq!(cell.load_machine_pos(&[0; 8]), s.ref_pos);
        assert_eq!(cell.load_program_pos(), s.pos);
        assert_eq!(cell.load_pulses(&[0; 8]), s.pulses);
        // Compensation pulses count into the machine's position and pulses only.
        let comp = [3, 0, 0, 0, 0, 0, 0, 0];
        assert_eq!(cell.load_pulses(&comp)[0], s.pulses[0] + 3);
        assert_eq!(cell.load_machine_pos(&comp)[0], s.ref_pos[0] + 3.0 / 500.0);
        assert_eq!(cell.load_program_pos()[0], s.pos[0]);
    }

    #[test]
    fn pulses_round_halves_away_from_zero() {
        assert_eq!(round_pulses(2.5), 3);
        assert_eq!(round_pulses(-2.5), -3);
        assert_eq!(round_pulses(2.4999), 2);
        assert_eq!(round_pulses(-0.4), 0);
    }

    #[test]
    fn readers_never_see_a_torn_snapshot() {
        let cell = std::sync::Arc::new(SnapshotCell::default());
        let w = cell.clone();
        let writer = std::thread::spawn(move || {
            for i in 0..20_000 {
                let v = f64::from(i);
                w.store_motion(&Motion {
                    pos: [v; 8],
                    vel: [v; 8],
                    ..Default::default()
                });
            }
        });
        for _ in 0..20_000 {
            let s = cell.load();
            assert!(s.pos.iter().chain(s.vel.iter()).all(|&x| x == s.pos[0]));
            let p = cell.load_exact_pos();
            assert!(p.iter().all(|&x| x == p[0]), "{p:?}");
        }
        writer.join().unwrap();
    }
}
