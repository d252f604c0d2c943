//! A card and its groups as a value the caller owns and ticks ([`Card`]): the core's
//! façade. The caller owns time: nothing moves between two calls of [`Card::tick`], and
//! each runs the one definition of a tick ([`super::tick::tick`]) that the library's
//! engine thread runs too, on the same machine and groups.
//!
//! What the library adds around it: the clock and the thread, snapshots that other
//! threads read without a lock, the card's peripherals and interrupt routines, the go
//! home, the program's callbacks, the trace and the panel. A `Card` has none of those: a
//! tick here is the groups' periods, their channels and the safety checks.

use super::axes_of;
use super::command::{Command, Ctx};
use super::group::{commanding_axes, GroupState};
use super::tick::{self, TickCtx, TickHooks, TickState, FULL};
use crate::config::{GroupDef, MacTable};
use crate::error::{McclError, McclResult};
use crate::machine::Machine;
use std::time::Duration;

/// A simulated card: its machine and the groups that drive it, ticked by the caller.
///
/// ```
/// use mccl_core::config::{default_mac_param, GroupDef, AXES, CARDS};
/// use mccl_core::engine::card::Card;
/// use mccl_core::machine::{ChannelSpec, Machine};
/// use mccl_core::vendor::SYS_ENCODER_CONFIG;
/// use std::time::Duration;
///
/// let mac = [[default_mac_param(); AXES]; CARDS];
/// let enc = [[SYS_ENCODER_CONFIG::default(); AXES]; CARDS];
/// let machine = Machine::new(&mac, &enc, |_, _| ChannelSpec::default(), |_| false, 1);
/// // X on channel 0 of card 0, a queue of 100 commands.
/// let x = GroupDef::new([0, -1, -1, -1, -1, -1, -1, -1], 0, 100).unwrap();
/// let mut card = Card::new(machine, &[(0, x)], &mac, Duration::from_millis(1));
/// // 10 UU along X at the default feed, planned from where the group stands.
/// card.queue(0, |ctx| {
///     let mut to = ctx.from;
///     to[0] += 10.0;
///     ctx.line(to)
/// })
/// .unwrap();
/// while card.group(0).unwrap().busy() {
///     card.tick();
/// }
/// assert_eq!(card.group(0).unwrap().snapshot().pos[0], 10.0);
/// ```
#[derive(Debug)]
pub struct Card {
    machine: Machine,
    groups: Vec<GroupState>,
    state: TickState,
    period: Duration,
    ticks: u64,
    dry_run: bool,
    limit_mode: i32,
}

impl Card {
    /// A card of `machine` running `groups` (slot, definition) with the mechanism facts
    /// of `mac`, a tick every `period`, every group standing at 0.
    pub fn new(
        machine: Machine,
        groups: &[(usize, GroupDef)],
        mac: &MacTable,
        period: Duration,
    ) -> Card {
        let mut gs: Vec<GroupState> = groups
            .iter()
            .map(|(slot, def)| {
                GroupState::new(*slot, *def, axes_of(def, mac), period.as_secs_f64())
            })
            .collect();
        let commanded = commanding_axes(&gs);
        for (g, c) in gs.iter_mut().zip(commanded) {
            g.set_commanded(c);
        }
        Card {
            machine,
            groups: gs,
            state: TickState::default(),
            period,
            ticks: 0,
            dry_run: false,
            limit_mode: -1,
        }
    }

    /// One interpolation period of the whole card: every group's period, the pulses to
    /// the channels, the machine's step, the safety checks.
    pub fn tick(&mut self) {
        let ctx = TickCtx {
            dt: self.period.as_secs_f64(),
            n: self.ticks,
            period_nanos: self.period.as_nanos(),
            full: true,
            // Between two ticks the caller may look at the machine: every tick brings
            // the channels up to date.
            carried: false,
            dry_run: self.dry_run,
            limit_mode: self.limit_mode,
        };
        tick::tick::<FULL, _>(
            &mut self.machine,
            &mut self.groups,
            &mut self.state,
            &ctx,
            &mut Unwatched,
        );
        self.ticks += 1;
    }

    /// The ticks run.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Group `slot`, if the card runs it.
    pub fn group(&self, slot: usize) -> Option<&GroupState> {
        self.groups.iter().find(|g| g.index() == slot)
    }

    /// Group `slot`, to change (queue, hold, override ...), if the card runs it.
    pub fn group_mut(&mut self, slot: usize) -> Option<&mut GroupState> {
        self.groups.iter_mut().find(|g| g.index() == slot)
    }

    /// Plans a command with group `slot`'s context now and queues it; returns its index
    /// (`GROUP_PARAMETER_ERR` for a group the card does not run; otherwise what planning
    /// and queuing return).
    pub fn queue(
        &mut self,
        slot: usize,
        plan: impl FnOnce(&Ctx<'_>) -> McclResult<Command>,
    ) -> McclResult<i32> {
        let g = self.group_mut(slot).ok_or(McclError::Group)?;
        let cmd = plan(&g.ctx())?;
        g.enqueue(cmd)
    }

    /// The simulated machine: channels, encoders, sensors.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    /// The simulated machine, to change (press the emergency stop, place a sensor ...).
    pub fn machine_mut(&mut self) -> &mut Machine {
        &mut self.machine
    }

    /// Dry run (`MCC_EnableDryRun`): the groups plan and move, nothing reaches the
    /// channels.
    pub fn set_dry_run(&mut self, on: bool) {
        self.dry_run = on;
    }

    /// The hardware limit switch check (`MCC_EnableLimitSwitchCheck`) in `mode`
    /// ([`super::safety::limit_check_mode`]), or off with `None`.
    pub fn set_limit_check(&mut self, mode: Option<i32>) {
        self.limit_mode = mode.unwrap_or(-1);
    }
}

/// The hooks of a card nobody watches: no go home, no peripherals, nothing published.
struct Unwatched;

impl TickHooks for Unwatched {}
