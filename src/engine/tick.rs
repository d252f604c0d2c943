//! One tick of the whole card on the engine thread ([`Shared::tick`]): the core's tick
//! (`mccl_core::engine::tick`, the one definition of its steps) on the machine and the
//! groups behind their locks, with this engine's hooks (the snapshots, the trace, the
//! view, the go home, the peripherals); the locks kept from one tick to the next
//! ([`Held`]); and the recovery from a panicking tick.

use super::group::GroupState;
use super::homing::HomeTick;
use super::shared::Shared;
use super::trace::Trace;
use super::{command, isr};
use crate::interrupt::Interrupt;
use crate::machine::Machine;
use mccl_core::engine::tick::{self as card_tick, TickCtx, TickHooks, TickState, CRUISE, FULL};
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
    /// ([`CRUISE`]): the core's [`tick`](card_tick::tick), the one definition of
    /// its steps, on the machine and groups `held` (taken here when it is empty; they
    /// stay there when the tick ends), with this engine's published snapshots, trace,
    /// view and peripherals as its hooks ([`EngineHooks`]).
    ///
    /// Snapshots are published every tick under the realtime clock and while
    /// `live_snapshots` is set (callbacks registered). Under a virtual clock the program
    /// is waiting while ticks run, so a long run publishes every [`PUBLISH_EVERY`] ticks
    /// and at its last tick (see [`Shared::end_of_run`]); statuses are published every
    /// tick. Returns whether it published everything; the interrupts to deliver are
    /// left in `interrupts`.
    fn tick<'a, const PLAN: bool>(
        &'a self,
        held: &mut Option<Held<'a>>,
        interrupts: &mut isr::Collected,
    ) -> bool {
        let cruise = PLAN == CRUISE;
        let n = self.clock.ticks();
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
        let trace = (!cruise && self.tracer.tracing).then(|| self.tracer.trace.lock());
        // The locks were kept from the last tick: no other thread looked in between.
        let carried = held.is_some();
        let held = held.get_or_insert_with(|| Held::lock(self));
        if cruise {
            // One writer: a load and a store, no read-modify-write.
            let ran = self.cruise.cruise_ticks.load(Ordering::Relaxed);
            self.cruise
                .cruise_ticks
                .store(ran.wrapping_add(1), Ordering::Relaxed);
        }
        let ctx = TickCtx {
            dt: self.clock.period_s(),
            n,
            period_nanos: self.clock.period_nanos(),
            full,
            carried,
            dry_run: self.outputs.dry_run.load(Ordering::Relaxed),
            limit_mode: if cruise { -1 } else { self.limit_check() },
        };
        let mut hooks = EngineHooks {
            shared: self,
            trace,
            interrupts,
        };
        card_tick::tick::<PLAN, _>(
            &mut held.machine,
            &mut held.groups,
            &mut held.state,
            &ctx,
            &mut hooks,
        );
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

/// The machine's and the groups' locks as the engine thread holds them through a tick
/// and, while [`Shared::quiet_between_ticks`], from one virtual tick to the next.
pub(super) struct Held<'a> {
    // Fields drop in order: the groups, then the machine (the reverse of locking).
    pub(super) groups: MutexGuard<'a, Vec<GroupState>>,
    pub(super) machine: MutexGuard<'a, Machine>,
    /// What the core's tick keeps from one tick to the next while the locks are held:
    /// the cards found idle, and how many more ticks the groups cruise for certain
    /// ([`Shared::cruise_next`]).
    pub(super) state: TickState,
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
            state: TickState::default(),
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

/// Lets go of the locks in `held`, if any ([`Held::release`]).
pub(super) fn release(held: &mut Option<Held<'_>>) {
    if let Some(h) = held.take() {
        h.release();
    }
}

/// The core tick's hooks on a running engine: what a tick produces goes to the published
/// snapshots and statuses, the trace (its lock held while tracing), the view and the
/// card's outputs; the go home and the peripherals are the shared state's.
struct EngineHooks<'s, 'i> {
    shared: &'s Shared,
    /// The trace, locked for the tick while tracing.
    trace: Option<MutexGuard<'s, Option<Trace>>>,
    /// Where the peripherals' tick collects the interrupts to deliver.
    interrupts: &'i mut isr::Collected,
}

impl TickHooks for EngineHooks<'_, '_> {
    #[inline(always)]
    fn probe(&mut self, point: &'static str) {
        crate::fault::point(point);
    }

    fn homing(&mut self, machine: &mut Machine, dt: f64) -> Option<HomeTick> {
        self.shared.tick_homing(machine, dt)
    }

    fn home_result(&mut self, status: i32) {
        let home = &self.shared.home;
        home.home_status.store(status, Ordering::Release);
        home.mc3b_home_card.store(-1, Ordering::Release);
    }

    fn outputs(&mut self, card: usize, outputs: &[command::Output]) {
        self.shared.make_outputs(card, outputs);
    }

    fn compensation(&mut self, g: &GroupState) {
        self.shared.store_compensation(g);
    }

    #[inline(always)]
    fn publish(&mut self, g: &mut GroupState, full: bool) {
        self.shared.publish_or_status(g, full);
    }

    /// The motion part when `full`; a status, which a cruise period leaves as it is, is
    /// published already (by the tick before the plan, or the one before that).
    #[inline(always)]
    fn publish_cruise(&mut self, g: &mut GroupState, full: bool) {
        if full {
            self.shared.publish_cruise_motion(g);
        }
        debug_assert_eq!(
            self.shared.published_status(g.index()),
            Some(g.status()),
            "group {}: the status a cruise period keeps is published",
            g.index()
        );
    }

    fn trace_group(&mut self, ctx: &TickCtx, g: &mut GroupState) {
        if let Some(t) = self.trace.as_deref_mut().and_then(Option::as_mut) {
            let t_ns = ctx.end_ns();
            t.row(t_ns, g);
            t.group_events(t_ns, g);
        }
    }

    fn view_due(&mut self) -> bool {
        self.shared.view.due(self.shared.clock.last_of_run())
    }

    fn publish_view(&mut self, machine: &Machine, groups: &[GroupState]) {
        self.shared.publish_view(machine, groups);
    }

    fn dac_trigger(&mut self, card: usize, n: usize) {
        if let Some(p) = self.shared.periph.get(card) {
            p.lock().dac_trigger(n);
        }
    }

    fn raise(&mut self, card: usize, cause: Interrupt) {
        self.shared.raise(card, cause);
    }

    fn trace_machine(&mut self, ctx: &TickCtx, machine: &Machine, homed: Option<&HomeTick>) {
        if let Some(t) = self.trace.as_deref_mut().and_then(Option::as_mut) {
            let t_ns = ctx.end_ns();
            t.machine_events(t_ns, machine);
            if let Some(h) = homed {
                t.home_events(t_ns, h.card, h.phase.0, h.phase.1, h.finished);
            }
        }
    }

    fn peripherals(&mut self, groups: &mut [GroupState]) -> bool {
        // The trace is let go first (lock order: groups, then a card's peripherals).
        self.trace = None;
        self.shared
            .tick_peripherals(self.shared.tick_len_ns, self.interrupts, groups)
    }
}
