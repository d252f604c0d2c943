//! The virtual card's engine: one thread per running system that ticks every interpolation
//! period on the [`Clock`], advances every group, and publishes snapshots that status
//! calls read without taking any lock.
//!
//! Locks: each group has its own mutex (a call on group 3 never waits for group 5); the
//! engine thread takes one group lock at a time and never holds one while user code runs,
//! so a callback may call any MCC_* function. Order: `system::SYSTEM`, then a group.

pub mod command;
pub mod group;
pub mod homing;
pub mod isr;
pub mod safety;
pub mod snapshot;
pub mod thread;
pub mod trace;

use crate::clock::{Clock, ClockMode, Next};
use crate::config::{GroupDef, AXES, CARDS, GROUPS};
use crate::error::{McclError, McclResult};
use crate::machine::Machine;
use command::AxisMech;
use group::GroupState;
use parking_lot::{Mutex, MutexGuard};
use snapshot::{GroupSnapshot, SnapshotCell};
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicI32, AtomicU32, AtomicU64, Ordering};
use std::sync::{Arc, Weak};
use std::thread::{JoinHandle, ThreadId};
use std::time::Duration;

use crate::config::MacTable;

/// The mechanism facts of a group's axes: mapped axes from their channel's parameters,
/// unmapped ones from the defaults (their planning result is ignored, §2.4.4).
pub fn axes_of(def: &GroupDef, mac: &MacTable) -> [AxisMech; AXES] {
    std::array::from_fn(|i| match def.channels[i] {
        Some(ch) => AxisMech::new(&mac[def.card.0][ch.0], Some((def.card.0, ch.0))),
        None => AxisMech::new(&crate::config::default_mac_param(), None),
    })
    .map(|a| a.in_unit(crate::config::unit_scale(def.unit)))
}

/// What the engine thread and the program's threads share.
#[derive(Debug)]
pub struct Shared {
    /// The tick clock.
    pub clock: Clock,
    /// Group slot -> position in `groups`.
    slots: [Option<usize>; GROUPS],
    /// The running groups.
    groups: Vec<Mutex<GroupState>>,
    /// Per position in `groups`: the axes whose pulses command their channel, one bit each.
    /// Several groups may map the same channel; the tick sends it the pulses of the last
    /// axis (in group order, then axis order) mapping it, so the others need none computed.
    /// The mapping is fixed while the engine runs (a group's channels come from its
    /// definition).
    commanding: Vec<u32>,
    /// Published state per group slot.
    snaps: Vec<SnapshotCell>,
    /// Per group slot: the tick count at its last status poll and last position read
    /// (virtual clocks: a repeated read at the same virtual time is a program waiting).
    last_poll: Vec<[AtomicU64; 2]>,
    /// Per group slot: the published motion status.
    status: Vec<AtomicI32>,
    /// A fast-clock poll in progress: group slot (or -1) and the status it saw; the engine
    /// ends the run of ticks when that status changes.
    watch: (AtomicI32, AtomicI32),
    /// Number of cards passed to `MCC_InitSystem`.
    pub cards: usize,
    /// The simulated machine behind the channels. Lock order: machine before a group.
    pub machine: Mutex<Machine>,
    /// Hardware limit switch check (`MCC_EnableLimitSwitchCheck` mode, -1 when off).
    pub limit_check: AtomicI32,
    /// `MCC_EnableDryRun` is in effect.
    pub dry_run: AtomicBool,
    /// Publish snapshots on every tick even under a virtual clock (set while code runs on
    /// the engine thread between ticks, i.e. interrupt callbacks are registered).
    pub live_snapshots: AtomicBool,
    /// Servo-on output per card, one bit per channel (`MCC_SetServoOn`/`Off`).
    pub servo_on: Vec<AtomicU32>,
    /// Position-ready output per card (`MCC_EnablePosReady`/`Disable`).
    pub pos_ready: Vec<AtomicBool>,
    /// Hardware FIFO depth reported while moving (`MCC_SetMaxPulseStockNum`).
    pub max_pulse_stock: AtomicU32,
    /// Timer, watchdog, DAC, ADC and remote I/O per card (`crate::card`).
    pub periph: Vec<crate::card::PeriphCell>,
    /// The interrupt routines registered per card (`isr`).
    pub isr: isr::IsrTable,
    /// The go home in progress (`MCC_Home`). Lock order: machine, then this, then a group.
    homing: Mutex<Option<homing::Homing>>,
    /// `MCC_GetGoHomeStatus`: [`homing::HOME_BUSY`], [`homing::HOME_DONE`] or
    /// [`homing::HOME_NONE`].
    home_status: AtomicI32,
    /// The tick count and count of go-home status reads at it (see [`Shared::poll`]).
    home_poll: AtomicU64,
    /// A fast-clock wait on the go-home status in progress: the status it saw, or
    /// `i32::MIN` when none.
    home_watch: AtomicI32,
    /// Cards whose channels 0..2 are an MC3B, one bit each.
    mc3b_cards: AtomicU32,
    /// The card whose MC3B runs a go home, or -1.
    mc3b_home_card: AtomicI32,
    trace: Mutex<Option<trace::Trace>>,
    /// Whether `trace` is `Some` (read without its lock on every tick).
    tracing: bool,
}

/// Under a virtual clock, a long run of ticks publishes snapshots this often (and at its
/// last tick): the program is waiting meanwhile, so only other threads could look.
pub const PUBLISH_EVERY: u64 = 16;

/// Reads of one kind at the same virtual time that make a program "waiting" (a program
/// that checks a status twice is not spinning; one that reads it a third time is).
pub const SPIN_POLLS: u64 = 3;

fn pack_poll(tick: u64, count: u64) -> u64 {
    (tick << 8) | count.min(255)
}

fn unpack_poll(v: u64) -> (u64, u64) {
    (v >> 8, v & 0xFF)
}

/// FIFO depth of the IMP card before `MCC_SetMaxPulseStockNum` (ZH manual §2.6.5: 60).
pub const DEFAULT_PULSE_STOCK: u32 = 60;

impl Shared {
    /// Locks group `g` (`GROUP_PARAMETER_ERR` when no such group runs).
    pub fn group(&self, g: u16) -> McclResult<MutexGuard<'_, GroupState>> {
        let slot = self
            .slots
            .get(usize::from(g))
            .copied()
            .flatten()
            .ok_or(McclError::Group)?;
        Ok(self.groups[slot].lock())
    }

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
                self.watch.1.store(status, Ordering::Release);
                self.watch.0.store(i32::from(g), Ordering::Release);
                self.clock
                    .wait_ticks(self.clock.ticks_for(crate::clock::FAST_POLL_MAX));
                self.watch.0.store(-1, Ordering::Release);
            }
        }
        self.mark_polled(g, 0);
    }

    /// A position read of group `g` (`MCC_GetCurPos`): repeated [`SPIN_POLLS`] times at the
    /// same virtual time, it runs one tick, so `while (x < 10) MCC_GetCurPos(&x, ...)` moves.
    pub fn poll_position(&self, g: u16) {
        if self.repeated(g, 1)
            && self.status[usize::from(g)].load(Ordering::Acquire)
                != crate::vendor::consts::GMS_STOP
        {
            self.clock.wait_ticks(1);
        }
        self.mark_polled(g, 1);
    }

    /// Counts reads of one kind at the same virtual time; from the
    /// [`SPIN_POLLS`]th on the program is taken to be waiting.
    fn repeated(&self, g: u16, kind: usize) -> bool {
        match self.last_poll.get(usize::from(g)) {
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
        if let Some(l) = self.last_poll.get(usize::from(g)) {
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
        let status = self.home_status.load(Ordering::Acquire);
        if status == homing::HOME_BUSY && self.repeated_in(&self.home_poll) {
            match self.clock.mode() {
                ClockMode::Realtime => {}
                ClockMode::Stepped => self.clock.wait_ticks(1),
                ClockMode::Fast => {
                    self.home_watch.store(status, Ordering::Release);
                    self.clock
                        .wait_ticks(self.clock.ticks_for(crate::clock::FAST_POLL_MAX));
                    self.home_watch.store(i32::MIN, Ordering::Release);
                }
            }
            self.mark_polled_in(&self.home_poll);
        }
        self.home_status.load(Ordering::Acquire)
    }

    /// `MCC_Home`: starts homing the channels of `card` whose order is 0..7 (255 skips
    /// one) with the go-home parameters `cfgs`. `COMMAND_NOTFINISHED_ERR` while a homing
    /// runs or a group driving one of the channels is busy, `COMMAND_NOTACCEPTED_ERR` in
    /// dry run (nothing moves, so no sensor can be found). Nothing changes on an error.
    pub fn start_homing(
        &self,
        card: usize,
        orders: [i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<()> {
        if self.dry_run.load(Ordering::Acquire) {
            return Err(McclError::NotAccepted);
        }
        if self.home_status.load(Ordering::Acquire) == homing::HOME_BUSY {
            return Err(McclError::NotFinished);
        }
        if self.mc3b_cards.load(Ordering::Acquire) & (1 << card) != 0 {
            return self.start_mc3b_homing(card, orders, cfgs);
        }
        let machine = self.machine.lock();
        let chans = machine.cards.get(card).ok_or(McclError::Parameter)?;
        let mut slot = self.homing.lock();
        if slot.is_some() {
            return Err(McclError::NotFinished);
        }
        let h = homing::Homing::new(card, orders, cfgs, chans);
        let chan_mask = h.channel_mask();
        let axes_of = |g: &GroupState| {
            (0..AXES).fold(0u32, |m, i| match g.axes[i].channel {
                Some((c, ch)) if c == card && chan_mask & (1 << ch) != 0 => m | 1 << i,
                _ => m,
            })
        };
        // Every group driving a homed channel must be idle; mark them, undo on failure.
        let mut marked: Vec<usize> = Vec::new();
        for (n, g) in self.groups.iter().enumerate() {
            let mut g = g.lock();
            let mask = axes_of(&g);
            if mask == 0 {
                continue;
            }
            if let Err(e) = g.begin_homing(mask) {
                drop(g);
                for &m in &marked {
                    let mut g = self.groups[m].lock();
                    g.end_homing();
                    self.publish(&mut g);
                }
                return Err(e);
            }
            self.publish(&mut g);
            marked.push(n);
        }
        if chan_mask == 0 {
            self.home_status.store(homing::HOME_DONE, Ordering::Release);
        } else {
            *slot = Some(h);
            self.home_status.store(homing::HOME_BUSY, Ordering::Release);
        }
        Ok(())
    }

    /// Marks `card` as an MC3B (its groups run on the device).
    pub fn mark_mc3b(&self, card: usize) {
        if card < 32 {
            self.mc3b_cards.fetch_or(1 << card, Ordering::AcqRel);
        }
    }

    /// `MCC_Home` on a card whose channels 0..2 are an MC3B: the device's own homing
    /// (`H`: seek the limit switch at the maximum velocity, back off and approach it at
    /// 10 steps/s), which is modes 9 and 16 of the manual; then phase 3 (`dfOffset`) as a
    /// move. `COMMAND_NOTACCEPTED_ERR` for another mode (the MC3B has no home sensor and
    /// no index input), a channel above 2, a channel no group drives, or a motor with no
    /// limit switch in the search direction (`mc3b_limit_bits`: it would seek for ever).
    fn start_mc3b_homing(
        &self,
        card: usize,
        orders: [i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<()> {
        let homed: Vec<usize> = (0..AXES)
            .filter(|&c| orders[c] != homing::ORDER_SKIP)
            .collect();
        if homed.is_empty() {
            self.home_status.store(homing::HOME_DONE, Ordering::Release);
            return Ok(());
        }
        for g in &self.groups {
            let mut g = g.lock();
            if g.def.card.0 != card || !g.is_external() {
                continue;
            }
            let (mask, stages, motors) = g.plan_mc3b_home(&orders, cfgs)?;
            g.begin_mc3b_home(mask, stages, motors)?;
            self.publish(&mut g);
            self.mc3b_home_card
                .store(i32::try_from(card).unwrap_or(-1), Ordering::Release);
            self.home_status.store(homing::HOME_BUSY, Ordering::Release);
            return Ok(());
        }
        Err(McclError::NotAccepted)
    }

    /// `MCC_AbortGoHome`: the homing channels decelerate to a stop and the homing ends
    /// without completing. `HOME_COMMAND_NOTCALLED_ERR` when no homing was started (or
    /// the last one was aborted); `NO_ERR` after one completed.
    pub fn abort_homing(&self) -> McclResult<()> {
        if let Ok(card) = usize::try_from(self.mc3b_home_card.load(Ordering::Acquire)) {
            self.for_each_group(|g| {
                if g.def.card.0 == card {
                    g.abort_mc3b_home();
                }
            });
            return Ok(());
        }
        match self.homing.lock().as_mut() {
            Some(h) => {
                h.abort();
                Ok(())
            }
            None if self.home_status.load(Ordering::Acquire) == homing::HOME_DONE => Ok(()),
            None => Err(McclError::HomeNotCalled),
        }
    }

    /// Drops a homing in progress (`MCC_ResetMotion`, `MCC_UpdateParam`): the channels
    /// stop where they are.
    fn cancel_homing(&self) {
        let mc3b = self.mc3b_home_card.swap(-1, Ordering::AcqRel) >= 0;
        if self.homing.lock().take().is_some() || mc3b {
            self.home_status.store(homing::HOME_NONE, Ordering::Release);
        }
    }

    /// One tick of the homing in progress (with the machine locked).
    fn tick_homing(&self, machine: &mut Machine, dt: f64) -> Option<homing::HomeTick> {
        // No lock on the tick's path while nothing is homed.
        if self.home_status.load(Ordering::Acquire) != homing::HOME_BUSY {
            return None;
        }
        let mut slot = self.homing.lock();
        let h = slot.as_mut()?;
        let card = h.card();
        let emergency = machine.emergency.get(card).copied().unwrap_or(false);
        let chans = machine.cards.get_mut(card)?;
        let out = h.tick(chans, emergency, dt);
        if let Some(status) = out.finished {
            *slot = None;
            self.home_status.store(status, Ordering::Release);
        }
        Some(out)
    }

    /// During a tick: ends a fast-clock poll's run when its group's status changed.
    fn check_watch(&self) {
        let h = self.home_watch.load(Ordering::Acquire);
        if h != i32::MIN && self.home_status.load(Ordering::Acquire) != h {
            self.clock.end_run_now();
        }
        let g = self.watch.0.load(Ordering::Acquire);
        if let Ok(g) = usize::try_from(g) {
            if self.status[g].load(Ordering::Acquire) != self.watch.1.load(Ordering::Acquire) {
                self.clock.end_run_now();
            }
        }
    }

    /// Whether group `g` runs.
    pub fn has_group(&self, g: u16) -> bool {
        self.slots.get(usize::from(g)).copied().flatten().is_some()
    }

    /// The last published state of group `g`, without locking.
    pub fn snapshot(&self, g: u16) -> McclResult<GroupSnapshot> {
        if !self.has_group(g) {
            return Err(McclError::Group);
        }
        Ok(self.snaps[usize::from(g)].load())
    }

    /// Publishes a group's state (call with its lock held) and, unless dry-running, the
    /// pulse counters of its channels.
    pub fn publish(&self, g: &mut GroupState) {
        let cell = &self.snaps[g.index];
        let info = g.info();
        if g.published_info().as_ref() != Some(&info) {
            cell.store_info(&info);
            *g.published_info() = Some(info);
        }
        let motion = g.motion();
        cell.store_motion(&motion);
        self.status[g.index].store(motion.status, Ordering::Release);
    }

    /// Checks that `card` is one of the cards passed to `MCC_InitSystem`.
    pub fn card(&self, card: crate::config::CardIx) -> McclResult<usize> {
        if card.0 < self.cards {
            Ok(card.0)
        } else {
            Err(McclError::Parameter)
        }
    }

    /// Whether a group driving channel `ch` of `card` is moving.
    pub fn channel_moving(&self, card: usize, ch: usize) -> bool {
        self.groups.iter().any(|g| {
            let g = g.lock();
            g.status() == crate::vendor::consts::GMS_RUNNING
                && g.axes.iter().any(|a| a.channel == Some((card, ch)))
        })
    }

    /// Every running group, locked one at a time.
    pub fn for_each_group(&self, mut f: impl FnMut(&mut GroupState)) {
        for g in &self.groups {
            let mut g = g.lock();
            f(&mut g);
            self.publish(&mut g);
        }
    }

    /// Resets every group (`MCC_ResetMotion`, `MCC_UpdateParam`) with new mechanism facts.
    pub fn reset_all(&self, mac: &MacTable) {
        self.cancel_homing();
        self.for_each_group(|g| {
            let axes = axes_of(&g.def, mac);
            g.reset(axes);
        });
    }

    /// One tick of the whole card.
    ///
    /// Snapshots are published every tick under the realtime clock and while
    /// `live_snapshots` is set (callbacks registered). Under a virtual clock the program
    /// is waiting while ticks run, so a long run publishes every [`PUBLISH_EVERY`] ticks
    /// and at its last tick (see [`Shared::end_of_run`]); statuses are published every
    /// tick. Returns whether it published everything, and the interrupts to deliver.
    fn tick(&self) -> (bool, isr::Collected) {
        let dt = self.clock.period().as_secs_f64();
        let n = self.clock.ticks();
        let t_ns = self.running_tick_end_ns();
        let full = !self.clock.mode().virtual_time()
            || self.live_snapshots.load(Ordering::Relaxed)
            || n % PUBLISH_EVERY == 0
            || self.clock.last_of_run();
        let mut trace = self.trace.lock();
        let mut machine = self.machine.lock();
        let dry = self.dry_run.load(Ordering::Relaxed);
        let mut cmds = [[None::<i64>; AXES]; CARDS];
        let mut own_checks = [false; GROUPS];
        let homed = self.tick_homing(&mut machine, dt);
        for (n, g) in self.groups.iter().enumerate() {
            let mut g = g.lock();
            g.tick(dt);
            crate::fault::point("group tick");
            if let Some(h) = &homed {
                apply_homing(&mut g, h);
            }
            if let Some(status) = g.take_home_result() {
                // A go home on an MC3B ended.
                self.home_status.store(status, Ordering::Release);
                self.mc3b_home_card.store(-1, Ordering::Release);
                g.end_homing();
            }
            own_checks[n] = g.has_safety_checks();
            if g.has_outputs() {
                let outputs = g.take_outputs();
                self.make_outputs(g.def.card.0, &outputs);
            }
            // Dry run: the plan runs, nothing is sent to the channels (§2.6.3 IV).
            if !dry {
                let mut axes = self.commanding[n];
                while axes != 0 {
                    let i = axes.trailing_zeros() as usize;
                    axes &= axes - 1;
                    if let Some((card, ch)) = g.axes[i].channel {
                        cmds[card][ch] = Some(g.pulses(i));
                    }
                }
            }
            if full {
                self.publish(&mut g);
            } else {
                self.status[g.index].store(g.status(), Ordering::Release);
            }
            if let Some(t) = trace.as_mut() {
                t.row(t_ns, &g);
                t.group_events(t_ns, &mut g);
            }
        }
        if let Some(h) = &homed {
            // The homed channels get the homing's position, grouped or not, dry run or not.
            for (ch, a) in h.axes.iter().enumerate() {
                if let (Some((x, _)), Some(chan)) = (a.pos, machine.channel(h.card, ch)) {
                    cmds[h.card][ch] = Some(snapshot::round_pulses(x * chan.factor()));
                }
            }
        }
        let now_ns = t_ns;
        let m = &mut *machine;
        for (card, chans) in m.cards.iter_mut().enumerate() {
            for (ch, chan) in chans.iter_mut().enumerate() {
                let cmd = cmds[card][ch].unwrap_or_else(|| chan.command_pulses());
                chan.step(cmd, dt);
            }
            let thresholds = m.settings[card].error_threshold;
            if m.triggers[card].tick_idle(chans, &thresholds) {
                continue;
            }
            let prev: [crate::machine::SensorLevels; AXES] =
                std::array::from_fn(|i| chans[i].prev_levels());
            let fired = m.triggers[card].tick(chans, &prev, &thresholds, now_ns);
            if !fired.interrupts.is_empty() {
                for &n in &fired.compares {
                    self.periph[card].lock().dac_trigger(n);
                }
                for i in fired.interrupts {
                    self.raise(card, i);
                }
            }
        }
        self.safety(&machine, full, dt, &own_checks);
        if let Some(t) = trace.as_mut() {
            t.machine_events(t_ns, &machine);
            if let Some(h) = &homed {
                t.home_events(t_ns, h.card, h.phase.0, h.phase.1, h.finished);
            }
        }
        drop(machine);
        drop(trace);
        (full, self.tick_peripherals(tick_ns(self.clock.period())))
    }

    /// Writes the interrupts a tick collected to the trace's events file.
    fn trace_interrupts(&self, collected: &isr::Collected) {
        let t_ns = self.running_tick_end_ns();
        if let Some(t) = self.trace.lock().as_mut() {
            t.interrupt_events(t_ns, collected, &self.isr);
        }
    }

    /// Virtual time, ns, at the end of the tick now running (the time its trace rows and
    /// events carry).
    fn running_tick_end_ns(&self) -> u128 {
        u128::from(self.clock.ticks() + 1) * self.clock.period().as_nanos()
    }

    /// Output changes of queued `MCC_Queue*OutputValue` commands.
    fn make_outputs(&self, card: usize, outputs: &[command::Output]) {
        for o in outputs {
            match *o {
                command::Output::Local { mask, value } => {
                    if let Some(s) = self.servo_on.get(card) {
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
                        let mut p = p.lock();
                        let sets = if ario { None } else { Some(&mut p.rio.rio) };
                        let r = match sets {
                            Some(rio) => rio.get_mut(usize::from(set)).map(|s| {
                                let old = s.output(port).unwrap_or(0);
                                s.set_output(port, old & !mask | value & mask)
                            }),
                            None => p.rio.ario.get_mut(usize::from(set)).map(|s| {
                                let old = s.output(port).unwrap_or(0);
                                s.set_output(port, old & !mask | value & mask)
                            }),
                        };
                        let _ = r;
                    }
                }
            }
        }
    }

    /// The checks that need the machine: emergency stop (0xF102), hardware limit
    /// switches (0xF701 + axis in the `_GEN_ERR` modes), tracking error (0xF801 + axis),
    /// pulse speed and acceleration limits (0xF203, 0xF204). A check that trips stops the
    /// group at once (its queue is dropped).
    fn safety(&self, machine: &Machine, full: bool, dt: f64, own_checks: &[bool; GROUPS]) {
        let limit_mode = self.limit_check.load(Ordering::Relaxed);
        // Checks every moving group needs; otherwise only groups with checks of their own
        // (tracking error, in-position) are looked at again.
        let global =
            limit_mode >= 0 || machine.emergency.iter().any(|&e| e) || machine.pulse_limits_set;
        for (n, g) in self.groups.iter().enumerate() {
            if !global && !own_checks[n] {
                continue;
            }
            let mut g = g.lock();
            if (!g.busy() && !g.has_safety_checks()) || g.homing() != 0 {
                // Homing watches its own limit switches and emergency stop.
                continue;
            }
            if g.inpos_waiting() {
                let mask = g.inpos_mask_waiting();
                let errs: [Option<f64>; AXES] = std::array::from_fn(|i| {
                    let (card, ch) = g.axes[i].channel?;
                    let chan = machine.channel(card, ch)?;
                    let f = g.axes[i].factor.abs();
                    (mask & (1 << i) != 0 && f > 0.0).then(|| chan.error_count() as f64 / f)
                });
                g.check_inpos(&errs, dt);
                if full {
                    self.publish(&mut g);
                } else {
                    self.status[g.index].store(g.status(), Ordering::Release);
                }
            }
            if let Some(code) = safety::check(&g, machine, limit_mode) {
                g.stop_for(code.record);
                if full {
                    self.publish(&mut g);
                } else {
                    self.status[g.index].store(g.status(), Ordering::Release);
                }
            }
        }
    }

    /// After a tick that did not publish everything: if it ended the run (the waiting
    /// program resumes now), publishes every group.
    fn end_of_run(&self) {
        if self.clock.last_of_run() {
            self.for_each_group(|_| {});
        }
    }

    /// [`Shared::tick`], and after a panic inside it (a defect of the library) a defined
    /// state instead of a dead engine thread: every group stops where it stands, drops
    /// its queue and records [`safety::ERR_INTERNAL`]; the clock goes on. The locks the
    /// tick held were released while unwinding (parking_lot locks do not poison).
    fn tick_or_recover(&self) -> (bool, isr::Collected) {
        match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.tick())) {
            Ok(done) => done,
            Err(_) => {
                self.stop_all_for_internal_error();
                (true, isr::Collected::default())
            }
        }
    }

    /// Stops every group where it stands with the error record [`safety::ERR_INTERNAL`]
    /// (the state after a caught panic that may have touched any group).
    pub fn stop_all_for_internal_error(&self) {
        self.for_each_group(|g| g.stop_for(Some(safety::ERR_INTERNAL)));
    }
}

thread_local! {
    /// On an engine thread: the engine it runs (see [`on_retired_engine_thread`]).
    static THIS_ENGINE: RefCell<Option<Weak<Shared>>> = const { RefCell::new(None) };
}

/// Whether the calling thread is the thread of an engine that has been stopped (a
/// routine still running for a system that is being closed or replaced). Such a routine
/// may not start or close a system: the program's close or init has already taken over.
pub fn on_retired_engine_thread() -> bool {
    THIS_ENGINE.with(|e| {
        e.borrow()
            .as_ref()
            .is_some_and(|w| w.upgrade().is_none_or(|s| s.clock.stopped()))
    })
}

/// The length of a tick in ns, as the peripherals count it.
fn tick_ns(period: Duration) -> u64 {
    u64::try_from(period.as_nanos()).unwrap_or(u64::MAX)
}

/// Applies a tick of homing to a group that drives homed channels: their positions and
/// speeds, the zeroing at the working home, error records, and the end of the homing.
fn apply_homing(g: &mut GroupState, h: &homing::HomeTick) {
    if g.homing() == 0 {
        return;
    }
    for i in 0..AXES {
        if g.homing() & (1 << i) == 0 {
            continue;
        }
        let Some((card, ch)) = g.axes[i].channel else {
            continue;
        };
        let Some(a) = h.axes.get(ch).filter(|_| card == h.card) else {
            continue;
        };
        if a.zeroed {
            g.home_zero_axis(i);
        }
        if let Some((x, v)) = a.pos {
            g.set_homing_axis(i, x, v);
        }
        if let Some(record) = a.record {
            g.set_error(record);
        }
    }
    if h.finished.is_some() {
        g.end_homing();
    }
}

/// [`Shared::commanding`] for `groups`: per group, the axes that are the last (in group
/// order, then axis order) to map their channel.
fn commanding_axes(groups: &[Mutex<GroupState>]) -> Vec<u32> {
    let mut last = [[None::<(usize, usize)>; AXES]; CARDS];
    for (n, g) in groups.iter().enumerate() {
        for (i, ax) in g.lock().axes.iter().enumerate() {
            if let Some((card, ch)) = ax.channel {
                if let Some(c) = last.get_mut(card) {
                    c[ch] = Some((n, i));
                }
            }
        }
    }
    let mut out = vec![0u32; groups.len()];
    for (n, i) in last.iter().flatten().flatten() {
        out[*n] |= 1 << i;
    }
    out
}

/// A running engine thread.
#[derive(Debug)]
pub struct Engine {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
    thread_id: ThreadId,
}

impl Engine {
    /// Starts the engine for `groups` with the given clock mode, period and mechanism
    /// parameters; `trace` is the CSV file to record every tick in (`MCCL_TRACE`).
    pub fn start(
        mode: ClockMode,
        period: Duration,
        groups: &[(usize, GroupDef)],
        mac: &MacTable,
        machine: Machine,
        trace: Option<trace::Trace>,
    ) -> std::io::Result<Engine> {
        let cards = machine.cards.len();
        let mut slots = [None; GROUPS];
        let mut gs = Vec::with_capacity(groups.len());
        for (n, (i, d)) in groups.iter().enumerate() {
            slots[*i] = Some(n);
            gs.push(Mutex::new(GroupState::new(*i, *d, axes_of(d, mac))));
        }
        let mut trace = trace;
        if let Some(t) = trace.as_mut() {
            for g in &gs {
                t.start_group(&mut g.lock(), mac, &machine);
            }
        }
        let commanding = commanding_axes(&gs);
        let shared = Arc::new(Shared {
            clock: Clock::new(mode, period),
            slots,
            commanding,
            last_poll: (0..GROUPS)
                .map(|_| std::array::from_fn(|_| AtomicU64::new(u64::MAX)))
                .collect(),
            status: (0..GROUPS).map(|_| AtomicI32::new(-1)).collect(),
            watch: (AtomicI32::new(-1), AtomicI32::new(0)),
            groups: gs,
            snaps: (0..GROUPS).map(|_| SnapshotCell::default()).collect(),
            cards: machine.cards.len(),
            machine: Mutex::new(machine),
            limit_check: AtomicI32::new(-1),
            dry_run: AtomicBool::new(false),
            live_snapshots: AtomicBool::new(false),
            servo_on: (0..cards).map(|_| AtomicU32::new(0)).collect(),
            pos_ready: (0..cards).map(|_| AtomicBool::new(false)).collect(),
            max_pulse_stock: AtomicU32::new(DEFAULT_PULSE_STOCK),
            periph: (0..cards)
                .map(|_| crate::card::PeriphCell::new(tick_ns(period)))
                .collect(),
            isr: isr::IsrTable::new(cards),
            homing: Mutex::new(None),
            home_status: AtomicI32::new(homing::HOME_NONE),
            home_poll: AtomicU64::new(u64::MAX),
            home_watch: AtomicI32::new(i32::MIN),
            mc3b_cards: AtomicU32::new(0),
            mc3b_home_card: AtomicI32::new(-1),
            tracing: trace.is_some(),
            trace: Mutex::new(trace),
        });
        shared.for_each_group(|_| {});
        let s2 = shared.clone();
        // The thread says when it is ready to tick (its real-time settings made, the
        // clock's deadlines counting from then); under the realtime clock this waits for
        // it, so tick 0 is due about when MCC_InitSystem returns.
        let (ready_tx, ready_rx) = std::sync::mpsc::sync_channel::<()>(1);
        let thread = std::thread::Builder::new()
            .name("mccl-engine".into())
            .spawn(move || {
                THIS_ENGINE.with(|e| *e.borrow_mut() = Some(Arc::downgrade(&s2)));
                run(&s2, ready_tx)
            })?;
        if mode == ClockMode::Realtime {
            // Err only if the thread ended without a word (it cannot before its loop).
            let _ = ready_rx.recv();
        }
        let thread_id = thread.thread().id();
        Ok(Engine {
            shared,
            thread: Some(thread),
            thread_id,
        })
    }

    /// What the engine shares.
    pub fn shared(&self) -> &Arc<Shared> {
        &self.shared
    }

    /// Stops the clock: the engine runs no further tick and every waiter returns. The
    /// thread ends once the tick or routine it is in returns ([`Engine::finish`]).
    pub fn stop(&self) {
        self.shared.clock.stop();
    }

    /// Stops the clock and joins the thread. Called from the engine's own thread (a
    /// routine that closes or replaces its system) it cannot join itself: it returns the
    /// thread's handle, for a later call on another thread to join.
    pub fn finish(mut self) -> Option<JoinHandle<()>> {
        // Drop stops the clock, joins a thread still in `self.thread`, flushes the trace.
        if self.is_engine_thread() {
            self.thread.take()
        } else {
            None
        }
    }

    /// Whether the calling thread is this engine's thread.
    pub fn is_engine_thread(&self) -> bool {
        std::thread::current().id() == self.thread_id
    }
}

/// Stops the clock and joins the thread. From the engine thread itself (a callback that
/// closes the system) it only stops: the thread ends when the callback returns (see
/// [`Engine::finish`], which hands that thread on to be joined later).
impl Drop for Engine {
    fn drop(&mut self) {
        self.shared.clock.stop();
        if let Some(t) = self.thread.take() {
            if std::thread::current().id() != self.thread_id {
                let _ = t.join();
            }
        }
        if let Some(t) = self.shared.trace.lock().as_mut() {
            t.flush();
        }
    }
}

fn run(shared: &Shared, ready: std::sync::mpsc::SyncSender<()>) {
    shared.clock.set_engine_thread();
    if shared.clock.mode() == ClockMode::Realtime {
        // Timer slack and the optional MCCL_RT_* settings (never fatal).
        thread::setup_current_thread(false);
    }
    // Realtime deadlines count from here: a thread that was slow to start (a loaded
    // host, mlockall) does not begin with a burst of late ticks.
    shared.clock.start_now();
    let _ = ready.send(());
    drop(ready);
    loop {
        match shared.clock.wait_next() {
            Next::Stop => return,
            Next::Tick => {
                let (published, interrupts) = shared.tick_or_recover();
                shared.check_watch();
                if !published {
                    shared.end_of_run();
                }
                if shared.tracing && !interrupts.is_empty() {
                    shared.trace_interrupts(&interrupts);
                }
                // Interrupt callbacks collected in the tick run here, without any lock.
                shared.isr.deliver(&interrupts, &shared.clock);
                shared.clock.tick_done();
            }
        }
    }
}
