//! What the engine thread and the program's threads share ([`Shared`]): the clock, the
//! groups behind their one lock, the published snapshots and statuses, the simulated
//! machine, the card's outputs and peripherals, the routines and the go home in progress.
//! The tick ([`super::tick`]), the virtual-time polls ([`super::poll`]) and the go-home
//! control ([`super::crate::engine::homing::control`]) are methods of it in their own files.

mod card_state;
mod checks;
mod custom_stage;
mod home;
mod interrupts;
mod kinematics_stage;
mod observer;
mod routines;

use super::group::GroupState;
use super::snapshot::{GroupSnapshot, SnapshotCell};
use super::{axes_of, trace};
use crate::clock::{Clock, ClockMode};
use crate::config::{GroupDef, MacTable, AXES, GROUPS};
use crate::error::{McclError, McclResult};
use crate::machine::Machine;
use parking_lot::{MappedMutexGuard, Mutex, MutexGuard};
use std::sync::atomic::{AtomicBool, AtomicI32, AtomicU32, AtomicU64, AtomicUsize, Ordering};
use std::time::Duration;

/// What the engine thread and the program's threads share: the clock, the machine, the
/// peripherals and the observer's view, and its parts, one a concern.
#[derive(Debug)]
pub struct Shared {
    /// The tick clock.
    pub(super) clock: Clock,
    /// The length of a tick in ns, as the peripherals count it ([`super::tick::tick_ns`]).
    pub(super) tick_len_ns: u64,
    /// The simulated machine behind the channels ([`Shared::lock_machine`]). Lock order:
    /// machine before the groups.
    pub(super) machine: Mutex<Machine>,
    /// Threads other than the engine's waiting for the machine's or the groups' lock: the
    /// engine thread, which may keep both from one virtual tick to the next
    /// ([`super::running`]), lets them go at the next tick when this is not 0.
    pub(super) lock_wanted: AtomicU32,
    /// Timer, watchdog, DAC, ADC and remote I/O per card (`crate::card`).
    pub(super) periph: crate::card::PeriphCells,
    /// What an observer (the browser panel) sees beyond the snapshots (`view.rs`).
    pub(super) view: super::view::ViewCell,
    /// The running groups.
    pub(super) table: GroupTable,
    /// What the groups publish.
    pub(super) published: Publication,
    /// The card's outputs and modes.
    pub(super) outputs: CardOutputs,
    /// The routines registered.
    pub(super) routines: Routines,
    /// The go home.
    pub(super) home: HomeState,
    /// The trace file.
    pub(super) tracer: TraceFile,
    /// Cruise ticks.
    pub(super) cruise: CruiseState,
}

/// The running groups and where each group slot's is.
#[derive(Debug)]
pub(in crate::engine) struct GroupTable {
    /// Group slot -> position in `groups`, -1 for none. Written only with the groups'
    /// lock held (`MCC_CreateGroup`/`MCC_CloseGroup` while running, [`Shared::open_group`]);
    /// read without it where a stale answer is harmless.
    pub(in crate::engine) slots: [AtomicI32; GROUPS],
    /// The running groups, behind one lock: the tick visits every group every period,
    /// and one lock for all costs the engine one atomic operation per tick instead of one
    /// per group (a locked instruction drains the store buffer: two per group were a
    /// fifth of the tick at 48 groups). A program thread holds it only to
    /// queue or change one group, as it held that group's lock before.
    pub(in crate::engine) groups: Mutex<Vec<GroupState>>,
    /// Number of entries in `groups`, readable without its lock. Entries stay where
    /// they are (the engine's stages visit them by position); a group closed while
    /// running leaves a husk of no axis there until a new group takes its place.
    pub(in crate::engine) group_count: AtomicUsize,
}

/// What each group slot publishes, read without the groups' lock.
#[derive(Debug)]
pub(in crate::engine) struct Publication {
    /// Published state per group slot.
    pub(in crate::engine) snaps: Vec<SnapshotCell>,
    /// Per group slot and axis: the compensation pulses its channel adds to the command
    /// (`MCC_UpdateCompParam`), written by the tick while compensation is on.
    pub(in crate::engine) comp: Vec<[AtomicI32; AXES]>,
    /// Per group slot: the tick count at its last status poll and last position read
    /// (virtual clocks: a repeated read at the same virtual time is a program waiting).
    pub(in crate::engine) last_poll: Vec<[AtomicU64; 2]>,
    /// Per group slot: the published motion status.
    pub(in crate::engine) status: Vec<AtomicI32>,
    /// A fast-clock poll in progress: group slot (or -1) and the status it saw; the engine
    /// ends the run of ticks when that status changes.
    pub(in crate::engine) watch: (AtomicI32, AtomicI32),
}

/// The card's outputs and modes the program sets.
#[derive(Debug)]
pub(in crate::engine) struct CardOutputs {
    /// Hardware limit switch check (`MCC_EnableLimitSwitchCheck` mode, -1 when off).
    pub(in crate::engine) limit_check: AtomicI32,
    /// `MCC_EnableDryRun` is in effect.
    pub(in crate::engine) dry_run: AtomicBool,
    /// Servo-on output per card, one bit per channel (`MCC_SetServoOn`/`Off`).
    pub(in crate::engine) servo_on: Vec<AtomicU32>,
    /// Position-ready output per card (`MCC_EnablePosReady`/`Disable`).
    pub(in crate::engine) pos_ready: Vec<AtomicBool>,
    /// Hardware FIFO depth reported while moving (`MCC_SetMaxPulseStockNum`).
    pub(in crate::engine) max_pulse_stock: AtomicU32,
}

/// The program's routines and callbacks registered, and what they make the engine do.
#[derive(Debug)]
pub(in crate::engine) struct Routines {
    /// The interrupt routines registered per card (`isr`).
    pub(in crate::engine) isr: crate::engine::isr::IsrTable,
    /// The per-period routines (`cycle`).
    pub(in crate::engine) cycle: super::cycle::CycleRoutines,
    /// Publish snapshots on every tick even under a virtual clock (set while code runs on
    /// the engine thread between ticks, i.e. interrupt callbacks are registered).
    pub(in crate::engine) live_snapshots: AtomicBool,
    /// A group is kinematic: the engine runs the kinematics stage after each tick.
    pub(in crate::engine) kinematics_on: AtomicBool,
}

/// The go home of one card (`MCC_Home`) and the MC3B cards.
#[derive(Debug)]
pub(in crate::engine) struct HomeState {
    /// The go home in progress (`MCC_Home`). Lock order: machine, then this, then a group.
    pub(in crate::engine) homing: Mutex<Option<crate::engine::homing::Homing>>,
    /// `MCC_GetGoHomeStatus`: [`crate::engine::homing::HOME_BUSY`], [`crate::engine::homing::HOME_DONE`] or
    /// [`crate::engine::homing::HOME_NONE`].
    pub(in crate::engine) home_status: AtomicI32,
    /// The tick count and count of go-home status reads at it (see [`Shared::poll`]).
    pub(in crate::engine) home_poll: AtomicU64,
    /// A fast-clock wait on the go-home status in progress: the status it saw, or
    /// `i32::MIN` when none.
    pub(in crate::engine) home_watch: AtomicI32,
    /// Cards whose channels 0..2 are an MC3B, one bit each.
    pub(in crate::engine) mc3b_cards: AtomicU32,
    /// The card whose MC3B runs a go home, or -1.
    pub(in crate::engine) mc3b_home_card: AtomicI32,
}

/// The trace file (`MCCL_TRACE`).
#[derive(Debug)]
pub(in crate::engine) struct TraceFile {
    pub(in crate::engine) trace: Mutex<Option<trace::Trace>>,
    /// Whether `trace` is `Some` (read without its lock on every tick).
    pub(in crate::engine) tracing: bool,
}

/// Cruise ticks (`cruise.rs`).
#[derive(Debug)]
pub(in crate::engine) struct CruiseState {
    /// Whether quiet ticks may be cruise ticks (`cruise.rs`; `MCCL_CRUISE=0` turns them
    /// off).
    pub(in crate::engine) cruise_enabled: bool,
    /// The cruise ticks run (written by the engine thread alone).
    pub(in crate::engine) cruise_ticks: AtomicU64,
}

/// FIFO depth of the IMP card before `MCC_SetMaxPulseStockNum`: 1, as the vendor's library
/// reads right after init (the ZH manual §2.6.5 speaks of 60 during continuous motion).
pub const DEFAULT_PULSE_STOCK: u32 = 1;

impl Shared {
    /// The shared state of an engine about to start: `groups` (slot, definition) with
    /// the mechanism facts of `mac`, the machine, the trace (whose group headers are
    /// written here) and whether quiet ticks may be cruise ticks. Every group is published
    /// once by the caller.
    pub(super) fn new(
        mode: ClockMode,
        period: Duration,
        groups: &[(usize, GroupDef)],
        mac: &MacTable,
        machine: Machine,
        trace: Option<trace::Trace>,
        cruise: bool,
    ) -> Shared {
        let cards = machine.cards().len();
        let slots: [AtomicI32; GROUPS] = std::array::from_fn(|_| AtomicI32::new(-1));
        let mut gs = Vec::with_capacity(groups.len());
        for (n, (i, d)) in groups.iter().enumerate() {
            slots[*i].store(n as i32, Ordering::Relaxed);
            gs.push(GroupState::new(
                *i,
                *d,
                axes_of(d, mac),
                period.as_secs_f64(),
            ));
        }
        let mut trace = trace;
        if let Some(t) = trace.as_mut() {
            for g in &mut gs {
                t.start_group(g, mac, &machine);
            }
        }
        let commanded = crate::engine::group::commanding_axes(&gs);
        for (g, c) in gs.iter_mut().zip(commanded) {
            g.set_commanded(c);
        }
        let group_count = AtomicUsize::new(gs.len());
        Shared {
            clock: Clock::new(mode, period),
            tick_len_ns: tick_ns(period),
            machine: Mutex::new(machine),
            lock_wanted: AtomicU32::new(0),
            periph: crate::card::PeriphCells::new(cards, tick_ns(period)),
            view: super::view::ViewCell::default(),
            table: GroupTable {
                slots,
                groups: Mutex::new(gs),
                group_count,
            },
            published: Publication {
                snaps: (0..GROUPS).map(|_| SnapshotCell::default()).collect(),
                comp: (0..GROUPS)
                    .map(|_| std::array::from_fn(|_| AtomicI32::new(0)))
                    .collect(),
                last_poll: (0..GROUPS)
                    .map(|_| std::array::from_fn(|_| AtomicU64::new(u64::MAX)))
                    .collect(),
                status: (0..GROUPS).map(|_| AtomicI32::new(-1)).collect(),
                watch: (AtomicI32::new(-1), AtomicI32::new(0)),
            },
            outputs: CardOutputs {
                limit_check: AtomicI32::new(-1),
                dry_run: AtomicBool::new(false),
                servo_on: (0..cards).map(|_| AtomicU32::new(0)).collect(),
                pos_ready: (0..cards).map(|_| AtomicBool::new(false)).collect(),
                max_pulse_stock: AtomicU32::new(DEFAULT_PULSE_STOCK),
            },
            routines: Routines {
                isr: crate::engine::isr::IsrTable::new(cards),
                cycle: Default::default(),
                live_snapshots: AtomicBool::new(false),
                kinematics_on: AtomicBool::new(false),
            },
            home: HomeState {
                homing: Mutex::new(None),
                // The vendor's library reads 1 (done) right after init.
                home_status: AtomicI32::new(crate::engine::homing::HOME_DONE),
                home_poll: AtomicU64::new(u64::MAX),
                home_watch: AtomicI32::new(i32::MIN),
                mc3b_cards: AtomicU32::new(0),
                mc3b_home_card: AtomicI32::new(-1),
            },
            tracer: TraceFile {
                tracing: trace.is_some(),
                trace: Mutex::new(trace),
            },
            cruise: CruiseState {
                cruise_enabled: cruise,
                cruise_ticks: AtomicU64::new(0),
            },
        }
    }

    /// Locks group `g` (`GROUP_PARAMETER_ERR` when no such group runs). The groups share
    /// one lock (see `Shared::groups`): never call this while holding a group.
    pub fn group(&self, g: u16) -> McclResult<MappedMutexGuard<'_, GroupState>> {
        let gs = self.lock_groups();
        let n = self.position_of(g).ok_or(McclError::Group)?;
        MutexGuard::try_map(gs, |gs| gs.get_mut(n)).map_err(|_| McclError::Group)
    }

    /// The position in `groups` of group slot `g`, when it runs.
    fn position_of(&self, g: u16) -> Option<usize> {
        let n = self
            .table
            .slots
            .get(usize::from(g))?
            .load(Ordering::Acquire);
        usize::try_from(n).ok()
    }

    /// `MCC_CreateGroup` while the card runs: group `slot` runs from now on with `def`,
    /// its axes where their channels' pulse counts put them (as the vendor's library
    /// starts a group made then), and the channels it shares with older groups are its
    /// own from now on.
    pub fn open_group(&self, slot: usize, def: GroupDef, mac: &MacTable) {
        let mut machine = self.lock_machine();
        machine.catch_up();
        let mut gs = self.lock_groups();
        let mut g = GroupState::new(slot, def, axes_of(&def, mac), self.clock.period_s());
        g.start_at_channels(machine.cards());
        if let Some(t) = self.tracer.trace.lock().as_mut() {
            t.start_group(&mut g, mac, &machine);
        }
        // A husk of the same slot first (so that no other entry publishes as `slot`),
        // then any husk, then a new entry.
        let husk = |want: Option<usize>| {
            (0..gs.len()).find(|&n| {
                let idx = gs[n].index();
                self.position_of(idx as u16) != Some(n) && want.is_none_or(|w| w == idx)
            })
        };
        let n = match husk(Some(slot)).or_else(|| husk(None)) {
            Some(n) => {
                gs[n] = g;
                n
            }
            None => {
                gs.push(g);
                self.table.group_count.store(gs.len(), Ordering::Release);
                gs.len() - 1
            }
        };
        self.table.slots[slot].store(n as i32, Ordering::Release);
        self.remap_channels(&mut gs);
        self.publish(&mut gs[n]);
    }

    /// `MCC_CloseGroup` while the card runs: group `slot` stops where it stands and goes;
    /// its channels keep their pulse counts.
    pub fn close_group(&self, slot: usize, mac: &MacTable) {
        let mut gs = self.lock_groups();
        let Some(n) = self.position_of(slot as u16) else {
            return;
        };
        let husk = GroupDef::none(gs[n].def().card);
        gs[n] = GroupState::new(slot, husk, axes_of(&husk, mac), self.clock.period_s());
        self.table.slots[slot].store(-1, Ordering::Release);
        self.published.status[slot].store(-1, Ordering::Release);
        self.remap_channels(&mut gs);
    }

    /// Which group commands which channel, after the groups changed.
    fn remap_channels(&self, gs: &mut [GroupState]) {
        let commanded = crate::engine::group::commanding_axes(gs);
        for (g, c) in gs.iter_mut().zip(commanded) {
            g.set_commanded(c);
        }
    }

    /// Locks the simulated machine (lock order: before the groups).
    pub fn lock_machine(&self) -> MutexGuard<'_, Machine> {
        wanted(&self.lock_wanted, &self.machine)
    }

    /// Locks the groups, for anyone but the engine's tick.
    pub(super) fn lock_groups(&self) -> MutexGuard<'_, Vec<GroupState>> {
        wanted(&self.lock_wanted, &self.table.groups)
    }

    /// Number of running groups (positions 0.. in the groups' lock).
    pub(super) fn group_count(&self) -> usize {
        self.table.group_count.load(Ordering::Acquire)
    }

    /// Locks the group at position `n` of the running groups (not its slot): for the
    /// engine's stages, which visit every group one at a time and release the lock
    /// around the program's callbacks.
    pub(super) fn nth_group(&self, n: usize) -> Option<MappedMutexGuard<'_, GroupState>> {
        MutexGuard::try_map(self.lock_groups(), |gs| gs.get_mut(n)).ok()
    }

    /// Marks `card` as an MC3B (its groups run on the device).
    pub fn mark_mc3b(&self, card: usize) {
        if card < 32 {
            self.home.mc3b_cards.fetch_or(1 << card, Ordering::AcqRel);
        }
    }

    /// The compensation pulses each axis of group `g` has (0 without compensation).
    pub fn compensation(&self, g: u16) -> [i64; 8] {
        match self.published.comp.get(usize::from(g)) {
            Some(c) => std::array::from_fn(|i| i64::from(c[i].load(Ordering::Acquire))),
            None => [0; 8],
        }
    }

    /// Publishes what [`GroupState::read_compensation`] found.
    pub(super) fn store_compensation(&self, g: &GroupState) {
        if let Some(c) = self.published.comp.get(g.index()) {
            for (cell, v) in c.iter().zip(g.comp_pulses()) {
                cell.store(v, Ordering::Release);
            }
        }
    }

    /// Whether `card` is an MC3B.
    pub fn is_mc3b(&self, card: usize) -> bool {
        card < 32 && self.home.mc3b_cards.load(Ordering::Acquire) >> card & 1 == 1
    }

    /// Whether group `g` runs.
    pub fn has_group(&self, g: u16) -> bool {
        self.position_of(g).is_some()
    }

    /// The last published state of group `g`, without locking.
    pub fn snapshot(&self, g: u16) -> McclResult<GroupSnapshot> {
        Ok(self.published(g)?.load())
    }

    /// Where group `g` publishes its snapshot, for a status call that reads only the part
    /// it returns ([`SnapshotCell::load_status`], [`SnapshotCell::load_exact_pos`], ...): a
    /// call that programs repeat in tight loops should not pay for the whole snapshot.
    pub fn published(&self, g: u16) -> McclResult<&SnapshotCell> {
        if !self.has_group(g) {
            return Err(McclError::Group);
        }
        self.published
            .snaps
            .get(usize::from(g))
            .ok_or(McclError::Group)
    }

    /// Publishes the motion part of a group after a cruise period (call with its lock
    /// held): its info is known unchanged since it was published (its key holds), and
    /// its status too (a cruise period keeps it), so what [`Shared::publish`] does then,
    /// without looking: the motion part ([`GroupState::store_cruise_motion`]).
    #[inline(always)]
    pub fn publish_cruise_motion(&self, g: &mut GroupState) {
        debug_assert!(
            g.published_key_holds(),
            "group {}: info unchanged",
            g.index()
        );
        if let Some(cell) = self.published.snaps.get(g.index()) {
            g.store_cruise_motion(cell);
        }
    }

    /// Publishes `g` on a tick that publishes everything, else its status.
    #[inline(always)]
    pub(super) fn publish_or_status(&self, g: &mut GroupState, full: bool) {
        if full {
            self.publish(g);
        } else {
            self.store_status(g);
        }
    }

    /// The status published for the group at `index`.
    pub(super) fn published_status(&self, index: usize) -> Option<i32> {
        let s = self.published.status.get(index)?;
        Some(s.load(Ordering::Acquire))
    }

    /// Stores a group's status where status calls read it without the snapshot.
    #[inline(always)]
    pub(super) fn store_status(&self, g: &GroupState) {
        if let Some(s) = self.published.status.get(g.index()) {
            s.store(g.status(), Ordering::Release);
        }
    }

    /// Publishes a group's state (call with its lock held): the info part when its key
    /// changed, the motion part and the status.
    ///
    /// Inlined into the tick (a call cost every group 14 instructions of frame), with the
    /// rare rebuild of the info key out of line so that the tick's frame does not grow.
    #[inline(always)]
    pub fn publish(&self, g: &mut GroupState) {
        let cell = &self.published.snaps[g.index()];
        if g.info_changed() {
            publish_info(cell, g);
        } else {
            // An unchanged key must mean an unchanged info (a writer that forgot
            // `info_touched` would leave readers with a stale info).
            #[cfg(debug_assertions)]
            debug_assert_eq!(g.published_info(), Some(&g.info()), "group {}", g.index());
        }
        g.store_motion(cell);
        self.store_status(g);
    }

    /// Checks that `card` is one of the cards passed to `MCC_InitSystem`.
    pub fn card(&self, card: crate::config::CardIx) -> McclResult<usize> {
        if card.0 < self.cards() {
            Ok(card.0)
        } else {
            Err(McclError::Parameter)
        }
    }

    /// Whether a group driving channel `ch` of `card` has a command running (the period
    /// the status still reads running after the last command is not one).
    pub fn channel_moving(&self, card: usize, ch: usize) -> bool {
        self.lock_groups()
            .iter()
            .any(|g| g.commands_running() && g.axes().iter().any(|a| a.channel == Some((card, ch))))
    }

    /// `MCC_ResetMotion`: homing stops and every group resets
    /// ([`GroupState::reset_motion`]); what the groups show changes from the next period,
    /// as the vendor's library publishes it. Whether a group was busy.
    pub fn reset_motion(&self) -> bool {
        self.reset_homing();
        let mut busy = false;
        for g in self.lock_groups().iter_mut() {
            busy |= g.busy();
            g.reset_motion();
        }
        busy
    }

    /// Every running group, locked one at a time.
    pub fn for_each_group(&self, mut f: impl FnMut(&mut GroupState)) {
        for g in self.lock_groups().iter_mut() {
            f(g);
            self.publish(g);
        }
    }

    /// Resets every group (`MCC_ResetMotion`, `MCC_UpdateParam`) with new mechanism facts.
    pub fn reset_all(&self, mac: &MacTable) {
        self.cancel_homing();
        self.for_each_group(|g| {
            let axes = axes_of(g.def(), mac);
            g.reset(axes);
        });
    }

    /// Stops every group where it stands with the error record [`crate::engine::safety::ERR_INTERNAL`]
    /// (the state after a caught panic that may have touched any group).
    pub fn stop_all_for_internal_error(&self) {
        self.for_each_group(|g| g.stop_for(Some(crate::engine::safety::ERR_INTERNAL)));
    }
}

/// The info part of [`Shared::publish`], out of line (it seldom changes): builds group
/// `g`'s info and stores it in `cell`.
#[inline(never)]
fn publish_info(cell: &SnapshotCell, g: &mut GroupState) {
    let info = g.info();
    cell.store_info(&info);
    #[cfg(debug_assertions)]
    g.keep_published_info(info);
}

/// The length of a tick in ns, as the peripherals count it.
fn tick_ns(period: Duration) -> u64 {
    u64::try_from(period.as_nanos()).unwrap_or(u64::MAX)
}

/// Locks `m` counting the caller in `wanted` while it may wait: the engine thread, which
/// may hold the lock from one virtual tick to the next, sees the count and lets go.
fn wanted<'a, T>(wanted: &AtomicU32, m: &'a Mutex<T>) -> MutexGuard<'a, T> {
    if let Some(g) = m.try_lock() {
        return g;
    }
    wanted.fetch_add(1, Ordering::AcqRel);
    let g = m.lock();
    wanted.fetch_sub(1, Ordering::AcqRel);
    g
}
