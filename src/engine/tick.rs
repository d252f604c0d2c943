//! One tick of the whole card ([`Shared::tick`]): the go home, every group's tick, the
//! pulses to the channels, the simulated machine's step, triggers and interrupts, the
//! safety checks, the snapshots and the trace; and the recovery from a panicking tick.

use super::group::GroupState;
use super::shared::apply_homing;
use super::shared::Shared;
use super::{command, isr, snapshot};
use crate::config::AXES;
use crate::machine::deferred::{DeferredSteps, Recording};
use crate::machine::{Channel, Machine};
use parking_lot::MutexGuard;
use std::sync::atomic::Ordering;

/// Under a virtual clock, a long run of ticks publishes snapshots this often (and at its
/// last tick): the program is waiting meanwhile, so only other threads could look.
pub const PUBLISH_EVERY: u64 = 16;

impl Shared {
    /// [`Shared::tick`] (with `cruise`, when the locks are held, planned as a cruise tick),
    /// and after a panic inside it (a defect of the library) a defined state instead of
    /// a dead engine thread: every group stops where it stands, drops its queue and
    /// records [`safety::ERR_INTERNAL`]; the clock goes on. The locks the tick held were
    /// released while unwinding (parking_lot locks do not poison).
    pub(super) fn tick_or_recover<'a>(
        &'a self,
        held: &mut Option<Held<'a>>,
        interrupts: &mut isr::Collected,
        cruise: bool,
    ) -> bool {
        let cruise = cruise && held.is_some();
        let tick = || {
            if cruise {
                self.tick::<CRUISE>(held, interrupts)
            } else {
                self.tick::<FULL>(held, interrupts)
            }
        };
        match std::panic::catch_unwind(std::panic::AssertUnwindSafe(tick)) {
            Ok(published) => published,
            Err(_) => {
                // Channels with deferred steps up to date before the machine is let go.
                if let Some(h) = held.as_mut() {
                    h.machine.catch_up();
                }
                *held = None;
                self.stop_all_for_internal_error();
                interrupts.clear();
                true
            }
        }
    }

    /// One tick of the whole card: every step of it ([`FULL`]) or those of a cruise tick
    /// ([`CRUISE`]).
    ///
    /// Snapshots are published every tick under the realtime clock and while
    /// `live_snapshots` is set (callbacks registered). Under a virtual clock the program
    /// is waiting while ticks run, so a long run publishes every [`PUBLISH_EVERY`] ticks
    /// and at its last tick (see [`Shared::end_of_run`]); statuses are published every
    /// tick. Returns whether it published everything; the interrupts to deliver are
    /// left in `interrupts`. The machine's and the groups' locks are `held`'s (taken
    /// here when it is empty); they stay there when the tick ends.
    ///
    /// A cruise tick (`cruise.rs`; the locks held) runs the same steps in the same order
    /// and leaves out those its plan ([`Shared::cruise_next`]) made sure have nothing to
    /// do: the go home, a group's stages besides its period, the channels'
    /// compensation, the group's outputs, the safety checks, the trace, the view; every
    /// card defers its channels' steps. The plan is a constant of each instance, so
    /// the steps it leaves out are not in that instance's code at all.
    fn tick<'a, const PLAN: bool>(
        &'a self,
        held: &mut Option<Held<'a>>,
        interrupts: &mut isr::Collected,
    ) -> bool {
        let cruise = PLAN == CRUISE;
        let dt = self.clock.period_s();
        let n = self.clock.ticks();
        // The virtual time the trace and the triggers see, made only where they look.
        let t_ns = || self.running_tick_end_ns();
        // A cruise tick is inside its run and not its last, under a virtual clock.
        let full = if cruise {
            self.publishes_everything(n)
        } else {
            !self.clock.mode().virtual_time()
                || self.publishes_everything(n)
                || self.clock.last_of_run()
        };
        // The trace's lock only while tracing: an uncontended lock is still two atomic
        // operations a tick.
        let mut trace_guard = (!cruise && self.tracer.tracing).then(|| self.tracer.trace.lock());
        let mut trace = trace_guard.as_mut().and_then(|t| t.as_mut());
        // The locks were kept from the last tick: no other thread looked in between.
        let carried = held.is_some();
        let held = held.get_or_insert_with(|| Held::lock(self));
        if cruise {
            held.cruise = held.cruise.saturating_sub(1);
            // One writer: a load and a store, no read-modify-write.
            let ran = self.cruise.cruise_ticks.load(Ordering::Relaxed);
            self.cruise
                .cruise_ticks
                .store(ran.wrapping_add(1), Ordering::Relaxed);
        } else {
            // What this tick changes, no cruise plan made before it covers.
            held.cruise = 0;
        }
        let machine = &mut *held.machine;
        let dry = self.outputs.dry_run.load(Ordering::Relaxed);
        let homed = if cruise {
            None
        } else {
            self.tick_homing(machine, dt)
        };
        let groups = &mut *held.groups;
        // Whether a group has safety checks of its own, once every group has ticked.
        let mut group_checks = false;
        for g in groups.iter_mut() {
            if cruise {
                // A period along one command or standing idle: no stage, no output, no
                // homing result (`GroupState::quiet_ticks_ahead`).
                debug_assert!(
                    g.quiet_ticks_ahead(dt, 1) == 1,
                    "group {} cruises",
                    g.index()
                );
                g.cruise_period(dt);
                crate::fault::point("cruise tick");
            } else {
                g.tick(dt);
                g.kinematics_apply();
                crate::fault::point("group tick");
                if let Some(h) = &homed {
                    apply_homing(g, h);
                }
                if let Some(status) = g.take_home_result() {
                    // A go home on an MC3B ended.
                    self.home.home_status.store(status, Ordering::Release);
                    self.home.mc3b_home_card.store(-1, Ordering::Release);
                    g.end_homing();
                }
                if g.has_outputs() {
                    let outputs = g.take_outputs();
                    self.make_outputs(g.def().card.0, &outputs);
                }
            }
            // Dry run: the plan runs, nothing is sent to the channels (§2.6.3 IV).
            if !dry {
                g.command_channels(machine.cards_mut());
                if !cruise && (machine.compensating() || g.comp_pulses() != [0; AXES]) {
                    g.read_compensation(machine.cards_mut());
                    self.store_compensation(g);
                }
            }
            if cruise {
                // The plan holds the info unchanged (the published key holds).
                if full {
                    self.publish_motion(g);
                } else {
                    self.store_status(g);
                }
                continue;
            }
            self.publish_or_status(g, full);
            if let Some(t) = trace.as_deref_mut() {
                t.row(t_ns(), g);
                t.group_events(t_ns(), g);
            }
            group_checks |= g.has_safety_checks();
        }
        if let Some(h) = &homed {
            // The homed channels get the homing's position, grouped or not, dry run or not.
            for (ch, a) in h.axes.iter().enumerate() {
                if let (Some((x, _)), Some(chan)) = (a.pos, machine.channel_mut(h.card, ch)) {
                    let p = snapshot::round_pulses(x * chan.factor());
                    chan.command(p);
                }
            }
        }
        // Whether a safety check reads the channels this tick (and `Shared::safety` has
        // anything to do).
        let checks = !cruise && self.safety_reads_channels(machine, group_checks);
        // Ideal channels defer their steps (`machine::deferred`) on a tick whose locks
        // were kept from the last one, with no view copied for an observer, no homing and
        // no safety check that reads them, on a card whose triggers are not armed. Any
        // other tick brings them up to date first.
        // Whether this tick copies a view for an observer: decided once, here, so that a
        // view asked for in the middle of the tick waits for the next one instead of
        // reading channels this tick left deferred. The ticks between copies defer.
        let view = !cruise && full && self.view.due(self.clock.last_of_run());
        let defer = cruise || (carried && !view && homed.is_none() && !checks);
        if !defer {
            machine.catch_up();
        }
        let m = &mut *machine;
        let pending = if cruise { None } else { m.deferred() };
        let recorded = m.recording();
        let mut recording = Recording::default();
        let mut deferred = false;
        for (card, (chans, triggers, settings)) in m.cards_triggers_settings().enumerate() {
            // A cruise plan found every card idle.
            let idle = cruise
                || held
                    .idle_cards
                    .idle(card, || !triggers.armed(&settings.error_threshold));
            // Whether a channel of the card stepped (its index pulses to note).
            let stepped = if defer && idle {
                let (stepped, now) = defer_idle_card(chans, recorded.card(card), dt, n);
                recording.set_card(card, now);
                deferred = true;
                stepped
            } else {
                if let Some(d) = pending {
                    crate::machine::catch_up::catch_up_card(chans, triggers, d);
                }
                for chan in chans.iter_mut() {
                    chan.step_commanded(dt);
                }
                true
            };
            if idle {
                if stepped {
                    triggers.tick_idle(chans);
                }
                continue;
            }
            let prev: [crate::machine::SensorLevels; AXES] =
                std::array::from_fn(|i| chans[i].prev_levels());
            let thresholds = settings.error_threshold;
            let fired = triggers.tick(chans, &prev, &thresholds, t_ns());
            if !fired.interrupts.is_empty() {
                for &n in &fired.compares {
                    self.periph[card].lock().dac_trigger(n);
                }
                for i in fired.interrupts {
                    self.raise(card, i);
                }
            }
        }
        // Every card that did not defer is up to date now.
        machine.set_deferred(deferred.then_some(DeferredSteps { dt, last: n }), recording);
        if checks {
            self.safety(machine, groups, full, dt);
        }
        if let Some(t) = trace {
            t.machine_events(t_ns(), machine);
            if let Some(h) = &homed {
                t.home_events(t_ns(), h.card, h.phase.0, h.phase.1, h.finished);
            }
        }
        if view {
            self.publish_view(machine, groups);
        }
        drop(trace_guard);
        // Peripherals after the groups (lock order: groups, then a card's peripherals). A
        // card that ran (a timer, a watchdog) may have reset groups: a cruise plan ends.
        if !self.tick_peripherals(self.tick_len_ns, interrupts, groups) {
            held.cruise = 0;
        }
        full
    }

    /// After a tick that did not publish everything: if it ended the run (the waiting
    /// program resumes now), publishes every group (through `held` when the engine
    /// thread holds the locks).
    #[inline]
    pub(super) fn end_of_run(&self, held: Option<&mut Held<'_>>) {
        if self.clock.last_of_run() {
            self.publish_all(held);
        }
    }

    /// Publishes every group (through `held` when the engine thread holds the locks).
    /// Out of line: [`Shared::end_of_run`] is asked after most virtual ticks and finds a
    /// run's last tick seldom.
    #[inline(never)]
    fn publish_all(&self, held: Option<&mut Held<'_>>) {
        match held {
            Some(h) => h.groups.iter_mut().for_each(|g| self.publish(g)),
            None => self.for_each_group(|_| {}),
        }
    }

    /// Whether nothing between this tick and the next needs the machine's or the groups'
    /// locks or runs the program's code: a virtual clock (the program waits while ticks
    /// run), no trace, no routine, no kinematics or custom motion callbacks, and no other
    /// thread waiting for either lock. Then the engine thread keeps both locks into the
    /// next tick (four atomic operations a tick less) and skips the stages, which have
    /// nothing to run; a routine registered meanwhile is called from the next tick on.
    pub(super) fn quiet_between_ticks(&self) -> bool {
        self.clock.mode().virtual_time()
            && !self.tracer.tracing
            && !self.routines_any()
            && !self.routines.kinematics_on.load(Ordering::Acquire)
            && !super::custom::live()
            && self.lock_wanted.load(Ordering::Acquire) == 0
    }

    /// Virtual time, ns, at the end of the tick now running (the time its trace rows and
    /// events carry).
    pub(super) fn running_tick_end_ns(&self) -> u128 {
        u128::from(self.clock.ticks() + 1) * self.clock.period_nanos()
    }

    /// Writes the interrupts a tick collected to the trace's events file.
    pub(super) fn trace_interrupts(&self, collected: &isr::Collected) {
        let t_ns = self.running_tick_end_ns();
        if let Some(t) = self.tracer.trace.lock().as_mut() {
            t.interrupt_events(t_ns, collected, &self.routines.isr);
        }
    }

    /// Output changes of queued `MCC_Queue*OutputValue` commands.
    fn make_outputs(&self, card: usize, outputs: &[command::Output]) {
        for o in outputs {
            match *o {
                command::Output::Local { mask, value } => {
                    if let Some(s) = self.outputs.servo_on.get(card) {
                        let (m, v) = (u32::from(mask & 0xFF), u32::from(value & 0xFF));
                        let _ = s.fetch_update(Ordering::AcqRel, Ordering::Acquire, |old| {
                            Some(old & !m | v & m)
                        });
                    }
                }
                command::Output::Remote {
                    ario,
                    set,
                    port,
                    mask,
                    value,
                } => {
                    if let Some(p) = self.periph.get(card) {
                        let (mut p, set) = (p.lock(), usize::from(set));
                        // Set and port were checked when the command was queued.
                        let _ = if ario {
                            let s = p.remote_io_mut().ario_set_mut(set);
                            s.and_then(|s| s.set_output_bits(port, mask, value))
                        } else {
                            let s = p.remote_io_mut().rio_set_mut(set);
                            s.and_then(|s| s.set_output_bits(port, mask, value))
                        };
                    }
                }
            }
        }
    }
}

/// The steps of an idle card's channels on a tick that defers, tick `n` of `dt`: the
/// channels that recorded at the last tick (`known`, bit n for channel n) record again
/// without asking; the others step or start recording. Returns whether a channel stepped
/// (its index pulses to note) and the channels recording now.
#[inline(always)]
pub(super) fn defer_idle_card(
    chans: &mut [Channel; AXES],
    known: u8,
    dt: f64,
    n: u64,
) -> (bool, u8) {
    let (mut stepped, mut now) = (false, known);
    if known == 0xFF {
        // Every channel records (the card's whole machine moving): a loop of its own,
        // without the bit tests, which LLVM unrolls (the loop below alone made the
        // 1-group tick 118 instructions longer).
        for chan in chans.iter_mut() {
            chan.record_step(n);
        }
    } else {
        for (ch, chan) in chans.iter_mut().enumerate() {
            if known >> ch & 1 == 1 {
                chan.record_step(n);
            } else {
                stepped |= chan.step_or_defer(dt, n);
                if chan.deferring() {
                    now |= 1 << ch;
                }
            }
        }
    }
    (stepped, now)
}

/// The plan of a tick ([`Shared::tick`]) that runs every step.
const FULL: bool = false;
/// The plan of a cruise tick: the steps a quiet tick can need (`cruise.rs`).
const CRUISE: bool = true;

/// The machine's and the groups' locks as the engine thread holds them through a tick
/// and, while [`Shared::quiet_between_ticks`], from one virtual tick to the next.
pub(super) struct Held<'a> {
    // Fields drop in order: the groups, then the machine (the reverse of locking).
    pub(super) groups: MutexGuard<'a, Vec<GroupState>>,
    pub(super) machine: MutexGuard<'a, Machine>,
    /// The cards found with nothing armed since the locks were taken.
    pub(super) idle_cards: IdleCards,
    /// How many more ticks the groups cruise for certain ([`Shared::cruise_next`]), as
    /// planned since the last tick that was not a cruise tick.
    pub(super) cruise: u32,
    /// Quiet ticks to let pass before planning again, after a plan found none.
    pub(super) replan_in: u32,
}

impl<'a> Held<'a> {
    /// Locks the machine, then the groups.
    fn lock(shared: &'a Shared) -> Held<'a> {
        let machine = shared.machine.lock();
        let groups = shared.table.groups.lock();
        Held {
            groups,
            machine,
            idle_cards: IdleCards::default(),
            cruise: 0,
            replan_in: 0,
        }
    }

    /// Unlocks both, handing each to a thread waiting for it if there is one (the engine
    /// thread would otherwise take them back at its next tick before a woken thread runs),
    /// with every channel's deferred steps made first.
    fn release(mut self) {
        self.machine.catch_up();
        MutexGuard::unlock_fair(self.groups);
        MutexGuard::unlock_fair(self.machine);
    }
}

/// The cards a tick found with nothing armed ([`CardTriggers::armed`]) while the engine
/// holds the machine's lock.
///
/// What arms a card (compares, index and input interrupts, latches, closed-loop
/// thresholds) only the program sets, under the machine's lock; the tick itself only
/// disarms (a trigger-out's hold ends), and a card with nothing armed runs no trigger
/// tick at all. So a card found idle stays idle for as long as the engine keeps the lock,
/// and the next tick need not look again; a card found armed is looked at every tick.
///
/// [`CardTriggers::armed`]: crate::machine::triggers::CardTriggers::armed
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct IdleCards([bool; crate::config::CARDS]);

impl IdleCards {
    /// Whether `card` has nothing armed: known, or found by `look` (and then known from
    /// now on, if so; a card past the last is always looked at).
    #[inline]
    pub(super) fn idle(&mut self, card: usize, look: impl FnOnce() -> bool) -> bool {
        match self.0.get_mut(card) {
            Some(true) => true,
            Some(known) => {
                *known = look();
                *known
            }
            None => look(),
        }
    }
}

/// Lets go of the locks in `held`, if any ([`Held::release`]).
pub(super) fn release(held: &mut Option<Held<'_>>) {
    if let Some(h) = held.take() {
        h.release();
    }
}

#[cfg(test)]
mod tests {
    use super::IdleCards;

    #[test]
    fn a_card_found_idle_is_not_looked_at_again_an_armed_one_is() {
        let mut idle = IdleCards::default();
        let mut looks = 0;
        let mut look = |answer: bool| {
            looks += 1;
            answer
        };
        // Card 2 armed: looked at every time; card 5 idle: once; a card past the last:
        // every time.
        let past = crate::config::CARDS;
        assert!(!idle.idle(2, || look(false)));
        assert!(!idle.idle(2, || look(false)));
        assert!(idle.idle(5, || look(true)));
        assert!(idle.idle(5, || look(false)), "known idle: not asked");
        assert!(idle.idle(2, || look(true)));
        assert!(
            idle.idle(2, || look(false)),
            "found idle: known from then on"
        );
        assert!(idle.idle(past, || look(true)));
        assert!(
            !idle.idle(past, || look(false)),
            "past the last card: always asked"
        );
        assert_eq!(looks, 6);
    }
}
