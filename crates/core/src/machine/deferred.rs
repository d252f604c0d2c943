//! Deferred steps: while nothing but the engine's own tick can read a channel, an ideal
//! channel only records what it is commanded, and is brought up to date, to the same
//! fields its steps would have left, before anything reads it.
//!
//! The engine defers (see `Shared::tick`) only while it keeps the machine's lock from
//! one tick to the next (the quiet virtual clock: no other thread can lock the machine
//! in between), on ticks that copy no view for an observer (the panel), and only on
//! cards whose triggers are not armed, with no homing and no safety check that reads
//! the channels. It brings every
//! channel up to date ([`Machine::catch_up`](crate::machine::Machine::catch_up)) before it lets go of the lock and before
//! any tick that does not defer.
//!
//! What a step of an ideal channel leaves (see `Channel::step_ideal`) follows from the
//! commands alone: the command, output and motor from the last one; the output's history
//! (pulse speed and acceleration) from the last three; the last move, its index pulses
//! and the rest flag from the last two; the levels stay (no sensor follows an ideal
//! channel's motor, and only the program changes them otherwise, under the lock). Only
//! the index status needs the steps in between: a step passes an index pulse when its two
//! ends lie in different index intervals, and as the intervals grow with the position,
//! some step of a run of them passed one exactly when some output of the run lies in
//! another interval than the motor before the run. Each recorded output is checked
//! against a window of outputs known to lie in that interval (one comparison); only an
//! output outside it is looked up. The last index pulse's count is kept only for the
//! step that passed it (a latch reads it in that step, on a card whose triggers are
//! armed, which does not defer).

use super::SensorLevels;
use crate::config::CARDS;

/// What a channel stepping deferred keeps of the steps it did not make.
///
/// The steps of a run are numbered by the engine's tick (consecutive: a card that does
/// not defer at a tick brings its channels up to date first). Step `n` records its
/// output in `outputs[n % 4]`, which also holds the two outputs before the run's first
/// step, so that the last three outputs are always there. The run is `first..=` the
/// machine's last deferred step ([`DeferredSteps::last`]): every channel that defers
/// records at every tick that defers. Recording a step is then one store and the
/// window's check, whatever the run's length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Deferred {
    /// Whether steps are deferred (the channel is not up to date).
    pub(super) active: bool,
    /// The number of the run's first step.
    pub(super) first: u64,
    /// The outputs of the latest steps, step `n`'s at `n % 4`.
    pub(super) outputs: [i64; 4],
    /// Outputs that lie in the index interval of `start`, as [`OutputWindow`] checks
    /// them: the outputs of other intervals, and near its ends, are outside.
    pub(super) window: OutputWindow,
    /// Whether an output of the run lies in another index interval than `start` (the
    /// run passed an index pulse).
    pub(super) passed: bool,
    /// The motor's position before the first deferred step.
    pub(super) start: f64,
    /// The levels at the end of the last step made (the previous levels after one
    /// deferred step).
    pub(super) step_levels: SensorLevels,
}

impl Deferred {
    /// Nothing deferred.
    pub(super) const NONE: Deferred = Deferred {
        active: false,
        first: 0,
        outputs: [0; 4],
        window: OutputWindow::NONE,
        passed: false,
        start: 0.0,
        step_levels: SensorLevels {
            home: false,
            plus: false,
            minus: false,
        },
    };
}

/// The steps channels defer while the engine keeps the machine's lock: their period and
/// the number (the engine's tick) of the latest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeferredSteps {
    /// The period of the steps, s.
    pub dt: f64,
    /// The number of the latest step.
    pub last: u64,
}

/// Outputs `first..=last` as one check: `output - first`, as u64, below `len`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct OutputWindow {
    pub(super) first: i64,
    len: u64,
}

impl OutputWindow {
    /// Holds no output.
    pub(super) const NONE: OutputWindow = OutputWindow { first: 0, len: 0 };
    /// Holds every output but `i64::MAX`.
    pub(super) const ALL: OutputWindow = OutputWindow {
        first: i64::MIN,
        len: u64::MAX,
    };

    /// `first..=last` (none when `last < first`).
    pub(super) fn new(first: i64, last: i64) -> OutputWindow {
        if last < first {
            return OutputWindow::NONE;
        }
        OutputWindow {
            first,
            len: last.abs_diff(first) + 1,
        }
    }

    /// Whether `out` is in the window.
    #[inline]
    pub(super) fn holds(&self, out: i64) -> bool {
        (out.wrapping_sub(self.first) as u64) < self.len
    }
}

/// The slot of deferred step `n` in [`Deferred::outputs`].
#[inline]
pub(super) fn slot(n: u64) -> usize {
    (n % 4) as usize
}

/// The channels that recorded a deferred step at the last tick and so record the next
/// one without asking ([`Channel::record_step`](crate::machine::Channel::record_step)): ideal, with steps deferred since they
/// were last brought up to date. A byte a card, bit n for channel n.
///
/// The tick that defers builds it afresh; bringing channels up to date empties it, and
/// nothing else can change what it records: a channel's being ideal changes only with
/// the program's settings, made under the machine's lock, which the engine lets go of
/// only after bringing every channel up to date.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Recording([u8; CARDS]);

impl Recording {
    /// The channels of `card` that record (bit `ch`).
    #[inline]
    pub fn card(&self, card: usize) -> u8 {
        self.0.get(card).copied().unwrap_or(0)
    }

    /// Notes that the channels `mask` of `card` record (a card past the last is left
    /// out: it never records).
    #[inline]
    pub fn set_card(&mut self, card: usize, mask: u8) {
        if let Some(m) = self.0.get_mut(card) {
            *m = mask;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::AXES;
    use crate::config::{default_encoder_config, default_mac_param};
    use crate::machine::{Channel, ChannelSpec, Machine};
    use crate::vendor::SYS_MAC_PARAM;

    /// Deferred steps of 1 ms, the last numbered `last`.
    fn steps(last: u64) -> DeferredSteps {
        DeferredSteps { dt: 0.001, last }
    }

    /// A channel as `Debug` shows it, without what only deferring keeps and the last index
    /// count (compared where it is read, below).
    fn shown(c: &Channel) -> String {
        let mut c = c.clone();
        c.forget_deferring();
        format!("{c:?}")
    }

    #[test]
    fn deferred_steps_leave_what_the_steps_leave() {
        // Two copies of an ideal channel with an index pulse every 4 counts: one steps
        // every command, the other defers runs of 1, 2, 3, ... 9 commands and is brought
        // up to date after each run. Commands: a pseudo-random walk of small, zero and
        // large steps (so runs cross pulses, stand still, come back within one interval,
        // rest). After each run every field is the same (but the last index count, which
        // must be the same whenever the last step passed a pulse, the only time it is
        // read), and the deferred run passed a pulse exactly when one of the steps did.
        // A counter restart between runs moves the frame.
        let mac = SYS_MAC_PARAM {
            dwPPR: 4,
            ..default_mac_param()
        };
        let mut a = Channel::new(ChannelSpec::default(), mac, default_encoder_config());
        assert!(a.ideal());
        let mut b = a.clone();
        let (mut seed, mut cmd) = (7u64, 0i64);
        // The engine's tick numbers the steps; starting near the end of the u64 range,
        // the ~15,000 steps wrap around it.
        let mut n = u64::MAX - 7000;
        let (mut runs, mut passed_runs, mut resting_runs) = (0, 0, 0);
        for run in 0..3000usize {
            let len = 1 + run % 9;
            let mut passed = false;
            for _ in 0..len {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                cmd += match seed >> 61 {
                    0..=2 => 0,
                    3 => 1,
                    4 => -1,
                    5 => ((seed >> 20) % 7) as i64 - 3,
                    _ => ((seed >> 20) % 41) as i64 - 20,
                };
                a.command(cmd);
                a.step_commanded(0.001);
                passed |= a.index_events() > 0;
                b.command(cmd);
                b.step_or_defer(0.001, n);
                n = n.wrapping_add(1);
            }
            let deferred = b.deferring();
            let b_passed = b.catch_up(steps(n.wrapping_sub(1)));
            assert!(!b.deferring());
            assert_eq!(shown(&a), shown(&b), "run {run}");
            assert_eq!(b_passed, passed, "run {run}: an index pulse passed");
            if a.index_events() > 0 {
                assert_eq!(a.last_index_count(), b.last_index_count(), "run {run}");
            }
            runs += usize::from(deferred);
            passed_runs += usize::from(passed);
            resting_runs += usize::from(a.resting());
            if run % 500 == 499 {
                a.rezero();
                b.rezero();
            }
        }
        // The walk covered each case many times.
        assert!(runs > 2000, "{runs} runs deferred");
        assert!(
            passed_runs > 500 && passed_runs < runs,
            "{passed_runs} of {runs}"
        );
        assert!(resting_runs > 50, "{resting_runs} runs ended at rest");
    }

    #[test]
    fn a_run_passes_an_index_pulse_exactly_when_a_step_does_at_the_interval_ends() {
        // Index pulses every 5 pulses, frames shifted by whole and fractional pulses (a
        // lagging motor's counter restart leaves a fractional frame) and one far out (the
        // window's bounds not exact there: every output is looked up). From every start
        // in -12..=12, a run of two deferred steps to every output in -12..=12 and back:
        // it passed a pulse exactly when stepping did, and leaves the same channel. The
        // outputs near an interval's ends lie outside the window and are looked up, so a
        // window reaching past them would miss pulses here.
        let mac = SYS_MAC_PARAM {
            dwPPR: 5,
            ..default_mac_param()
        };
        let far = (1u64 << 53) as f64;
        let mut n = 0u64;
        for shift in [0.0, 1.0, 0.5, -0.25, 0.75, 2.5, far] {
            let mut a = Channel::new(ChannelSpec::default(), mac, default_encoder_config());
            a.restart_counter(shift, 0);
            let (mut passed_runs, mut runs) = (0, 0);
            for from in -12..=12 {
                for to in -12..=12 {
                    a.command(from);
                    a.step_commanded(0.001);
                    a.step_commanded(0.001);
                    let mut b = a.clone();
                    let mut passed = false;
                    for cmd in [to, from] {
                        a.command(cmd);
                        a.step_commanded(0.001);
                        passed |= a.index_events() > 0;
                        b.command(cmd);
                        b.step_or_defer(0.001, n);
                        n += 1;
                    }
                    assert!(b.deferring() || to == from);
                    let what = format!("shift {shift}, {from} -> {to}");
                    assert_eq!(b.catch_up(steps(n - 1)), passed, "{what}");
                    assert_eq!(shown(&a), shown(&b), "{what}");
                    runs += 1;
                    passed_runs += usize::from(passed);
                }
            }
            // About half the pairs lie in different intervals.
            assert!(
                passed_runs > runs / 3 && passed_runs < runs,
                "{passed_runs}/{runs}"
            );
        }
    }

    #[test]
    fn a_channel_at_rest_defers_nothing() {
        // At rest at 0: a deferred step with the same command records nothing, so the
        // channel stays up to date; a new command starts deferring.
        let mut c = Channel::new(
            ChannelSpec::default(),
            default_mac_param(),
            default_encoder_config(),
        );
        for _ in 0..3 {
            c.step_commanded(0.001);
        }
        assert!(c.resting());
        c.step_or_defer(0.001, 0);
        assert!(!c.deferring());
        c.command(5);
        c.step_or_defer(0.001, 1);
        assert!(c.deferring());
        assert!(
            !c.catch_up(steps(1)),
            "no pulse between 0 and 5 (every 2000)"
        );
        assert_eq!(
            (c.command_pulses(), c.output_pulses(), c.actual_pulses()),
            (5, 5, 5.0)
        );
    }

    #[test]
    fn a_recorded_step_is_the_deferred_step() {
        // Two recording channels, commanded alike: one asks (`step_or_defer`), the other
        // records without asking (`record_step`); they stay equal, up to date too.
        let mut asks = Channel::new(
            ChannelSpec::default(),
            default_mac_param(),
            default_encoder_config(),
        );
        asks.command(3);
        asks.step_or_defer(0.001, 10);
        let mut records = asks.clone();
        for (n, cmd) in (11..).zip([7, 4, 4, -2, 9]) {
            asks.command(cmd);
            records.command(cmd);
            asks.step_or_defer(0.001, n);
            records.record_step(n);
            assert_eq!(format!("{asks:?}"), format!("{records:?}"), "at {cmd}");
        }
        assert_eq!(asks.catch_up(steps(15)), records.catch_up(steps(15)));
        assert_eq!(format!("{asks:?}"), format!("{records:?}"));
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "steps not consecutive")]
    fn a_deferred_tick_that_skips_a_number_is_caught_in_debug_builds() {
        // The runs' last step is the machine's: a tick missed between two deferring
        // ticks would leave the slots of the last three outputs wrong.
        let mac = [[default_mac_param(); AXES]; CARDS];
        let enc = [[default_encoder_config(); AXES]; CARDS];
        let mut m = Machine::new(&mac, &enc, |_, _| ChannelSpec::default(), |_| false, 1);
        m.set_deferred(Some(steps(5)), Recording::default());
        m.set_deferred(Some(steps(6)), Recording::default());
        m.set_deferred(Some(steps(8)), Recording::default());
    }

    #[test]
    fn recording_keeps_eight_channels_a_card() {
        let mut r = Recording::default();
        r.set_card(0, 0b1010_0001);
        r.set_card(CARDS - 1, 0xFF);
        r.set_card(3, 0x7F);
        r.set_card(CARDS, 0xFF);
        let mut expected = vec![0; CARDS + 1];
        (expected[0], expected[3], expected[CARDS - 1]) = (0xA1, 0x7F, 0xFF);
        assert_eq!(
            (0..=CARDS).map(|c| r.card(c)).collect::<Vec<_>>(),
            expected,
            "a card past the last never records"
        );
        // Replacing a card's channels leaves its neighbours.
        r.set_card(3, 0x01);
        assert_eq!(
            (r.card(0), r.card(3), r.card(CARDS - 1)),
            (0xA1, 0x01, 0xFF)
        );
    }
}
