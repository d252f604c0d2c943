//! One tick of a card ([`tick`]): the go home, every group's period, the pulses to the
//! channels, the simulated machine's step, triggers and interrupts, the safety checks,
//! and what the caller does with each (publish, trace, show, deliver): the one definition
//! of a tick's steps. A cruise tick ([`CRUISE`]) is the same function with the steps its
//! plan made sure have nothing to do left out.
//!
//! The caller owns time and state shared with other threads: it passes the period and
//! the tick's number ([`TickCtx`]), and [`TickHooks`] receive what the tick produces
//! (publications, outputs, interrupts, trace) and provide what lives outside the
//! machine and its groups (the go home in progress, the peripherals). The library's
//! engine thread runs it with its published snapshots; [`super::card::Card`] runs it for
//! a caller who owns the card outright.

use super::command::Output;
use super::group::GroupState;
use super::homing::{apply_homing, HomeTick};
use super::safety;
use super::snapshot;
use crate::config::{AXES, CARDS};
use crate::interrupt::Interrupt;
use crate::machine::deferred::{DeferredSteps, Recording};
use crate::machine::{Channel, Machine};

/// The plan of a tick that runs every step.
pub const FULL: bool = false;
/// The plan of a cruise tick: the steps a quiet tick can need.
pub const CRUISE: bool = true;

/// What a tick needs to know of time and of the program's settings.
#[derive(Debug, Clone, Copy)]
pub struct TickCtx {
    /// The interpolation period, s.
    pub dt: f64,
    /// The tick's number (ticks run before it).
    pub n: u64,
    /// The period, ns exactly (virtual time at the end of the tick is `(n + 1) ×` it).
    pub period_nanos: u128,
    /// Whether this tick publishes everything (else statuses only).
    pub full: bool,
    /// Whether the locks were kept from the last tick (no other thread looked in
    /// between): ideal channels may defer their steps.
    pub carried: bool,
    /// `MCC_EnableDryRun` is in effect: the plan runs, nothing reaches the channels.
    pub dry_run: bool,
    /// The hardware limit switch check's mode, −1 off.
    pub limit_mode: i32,
}

impl TickCtx {
    /// Virtual time at the end of the tick, ns (what its trace rows and events carry).
    #[inline]
    pub fn end_ns(&self) -> u128 {
        u128::from(self.n + 1) * self.period_nanos
    }
}

/// What a caller keeps from one tick to the next: the cards found idle and the cruise
/// ticks still planned.
#[derive(Debug, Default, Clone, Copy)]
pub struct TickState {
    /// The cards found with nothing armed since the machine was last let go.
    idle_cards: IdleCards,
    /// How many more ticks the groups cruise for certain, as planned since the last tick
    /// that was not a cruise tick.
    cruise: u32,
    /// Per card, the channels its cruise ticks pass over (bit n for channel n): those at
    /// rest that no group commands ([`cruise_ahead`]).
    quiet: [u8; CARDS],
}

impl TickState {
    /// Whether `card` has nothing armed ([`IdleCards::idle`]).
    #[inline]
    pub fn card_idle(&mut self, card: usize, look: impl FnOnce() -> bool) -> bool {
        self.idle_cards.idle(card, look)
    }

    /// How many more ticks are cruise ticks for certain (0: the next is not).
    #[inline]
    pub fn cruise_left(&self) -> u32 {
        self.cruise
    }

    /// The channels of `card` its cruise ticks pass over: at rest, and commanded by no
    /// group.
    #[inline]
    fn quiet_channels(&self, card: usize) -> u8 {
        self.quiet.get(card).copied().unwrap_or(0)
    }

    /// The next `ticks` ticks are cruise ticks for certain, as a plan found; any tick
    /// that is not one, or peripherals that reset a group, end the plan.
    #[inline]
    pub fn plan_cruise(&mut self, ticks: u32) {
        self.cruise = ticks;
    }
}

/// What the caller of [`tick`] does with what the tick produces, and provides of what
/// lives outside the machine and its groups. Every method has a default that does
/// nothing (or finds nothing), which is a card nobody watches.
pub trait TickHooks {
    /// A named point inside the tick (a test's fault injection).
    #[inline(always)]
    fn probe(&mut self, _point: &'static str) {}
    /// One tick of the go home in progress on the machine, if any.
    fn homing(&mut self, _machine: &mut Machine, _dt: f64) -> Option<HomeTick> {
        None
    }
    /// A go home run by a group's external executor ended with `status`.
    fn home_result(&mut self, _status: i32) {}
    /// Output changes the queue of a group of `card` reached.
    fn outputs(&mut self, _card: usize, _outputs: &[Output]) {}
    /// The compensation pulses group `g` read from its channels.
    fn compensation(&mut self, _g: &GroupState) {}
    /// Group `g` after its period (or a check that changed it): everything when `full`,
    /// else its status.
    #[inline(always)]
    fn publish(&mut self, _g: &mut GroupState, _full: bool) {}
    /// Group `g` after a cruise period (its info known unchanged): its motion when
    /// `full`. Its status, which a cruise period keeps, was published before the plan.
    #[inline(always)]
    fn publish_cruise(&mut self, _g: &mut GroupState, _full: bool) {}
    /// Group `g`'s row and events at the end of the tick `ctx` (while tracing).
    fn trace_group(&mut self, _ctx: &TickCtx, _g: &mut GroupState) {}
    /// Whether this tick copies a view of the card for an observer (decided once, so
    /// that channels left deferred are never copied).
    fn view_due(&mut self) -> bool {
        false
    }
    /// The copy for an observer.
    fn publish_view(&mut self, _machine: &Machine, _groups: &[GroupState]) {}
    /// A trigger of `card` fired its DAC compare output `n`.
    fn dac_trigger(&mut self, _card: usize, _n: usize) {}
    /// An interrupt cause of `card`.
    fn raise(&mut self, _card: usize, _cause: Interrupt) {}
    /// The machine's events at the end of the tick `ctx` and the go home's (while
    /// tracing).
    fn trace_machine(&mut self, _ctx: &TickCtx, _machine: &Machine, _homed: Option<&HomeTick>) {}
    /// The card's peripherals, after the groups; false when they reset a group (a cruise
    /// plan then ends).
    fn peripherals(&mut self, _groups: &mut [GroupState]) -> bool {
        true
    }
}

/// One tick of the card (`machine` and its `groups`): every step ([`FULL`]) or those of
/// a cruise tick ([`CRUISE`]), which its plan made sure are all a quiet tick needs (no go
/// home, a group's period alone with no stage or output, no compensation, safety check,
/// trace or view; every card defers its channels' steps). The plan is a constant of
/// each instance, so the steps it leaves out are not in that instance's code at all.
#[inline(always)]
pub fn tick<const PLAN: bool, H: TickHooks>(
    machine: &mut Machine,
    groups: &mut [GroupState],
    state: &mut TickState,
    ctx: &TickCtx,
    hooks: &mut H,
) {
    let cruise = PLAN == CRUISE;
    let dt = ctx.dt;
    let n = ctx.n;
    let full = ctx.full;
    if cruise {
        state.cruise = state.cruise.saturating_sub(1);
    } else {
        // What this tick changes, no cruise plan made before it covers.
        state.cruise = 0;
    }
    let homed = if cruise {
        None
    } else {
        hooks.homing(machine, dt)
    };
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
            hooks.probe("cruise tick");
        } else {
            g.tick(dt);
            g.kinematics_apply();
            hooks.probe("group tick");
            if let Some(h) = &homed {
                apply_homing(g, h);
            }
            if let Some(status) = g.take_home_result() {
                // A go home on an MC3B ended.
                hooks.home_result(status);
                g.end_homing();
            }
            if g.has_outputs() {
                let outputs = g.take_outputs();
                hooks.outputs(g.def().card.0, &outputs);
            }
        }
        // Dry run: the plan runs, nothing is sent to the channels (§2.6.3 IV).
        if !ctx.dry_run {
            // A cruise period along a line commands the moving axes' channels alone.
            if !(cruise && g.command_moving_channels(machine.cards_mut())) {
                g.command_channels(machine.cards_mut());
            }
            if !cruise && (machine.compensating() || g.comp_pulses() != [0; AXES]) {
                g.read_compensation(machine.cards_mut());
                hooks.compensation(g);
            }
        }
        if cruise {
            // The plan holds the info unchanged (the published key holds).
            hooks.publish_cruise(g, full);
            continue;
        }
        hooks.publish(g, full);
        hooks.trace_group(ctx, g);
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
    // Whether a safety check reads the channels this tick.
    let checks = !cruise && safety::reads_channels(ctx.limit_mode, machine, group_checks);
    // Whether this tick copies a view for an observer: decided once, here, so that a
    // view asked for in the middle of the tick waits for the next one instead of
    // reading channels this tick left deferred. The ticks between copies defer.
    let view = !cruise && full && hooks.view_due();
    // Ideal channels defer their steps (`machine::deferred`) on a tick whose locks were
    // kept from the last one, with no view copied for an observer, no homing and no
    // safety check that reads them, on a card whose triggers are not armed. Any other
    // tick brings them up to date first.
    let defer = cruise || (ctx.carried && !view && homed.is_none() && !checks);
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
        let idle = cruise || state.card_idle(card, || !triggers.armed(&settings.error_threshold));
        // Whether a channel of the card stepped (its index pulses to note).
        let stepped = if defer && idle {
            let quiet = if cruise {
                state.quiet_channels(card)
            } else {
                0
            };
            let (stepped, now) = defer_idle_card(chans, recorded.card(card), quiet, dt, n);
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
        let fired = triggers.tick(chans, &prev, &thresholds, ctx.end_ns());
        if !fired.interrupts.is_empty() {
            for &n in &fired.compares {
                hooks.dac_trigger(card, n);
            }
            for i in fired.interrupts {
                hooks.raise(card, i);
            }
        }
    }
    // Every card that did not defer is up to date now.
    machine.set_deferred(deferred.then_some(DeferredSteps { dt, last: n }), recording);
    if checks {
        safety::check_groups(machine, groups, ctx.limit_mode, dt, |g| {
            hooks.publish(g, full)
        });
    }
    if !cruise {
        hooks.trace_machine(ctx, machine, homed.as_ref());
    }
    if view {
        hooks.publish_view(machine, groups);
    }
    // Peripherals after the groups. A card that ran (a timer, a watchdog) may have reset
    // groups: a cruise plan ends.
    if !hooks.peripherals(groups) {
        state.cruise = 0;
    }
}

/// How many of the next ticks, up to `most`, are certain to be cruise ticks for the card
/// (`machine` and its `groups`, ticks of `dt`): every card idle (nothing armed, known in
/// `state`), no safety check reading the channels (`limit_mode`, −1 off), every group
/// quiet that far ahead ([`GroupState::quiet_ticks_ahead`]). 0: the next is not. What
/// only other threads change (a routine, the trace, a view asked for) is the caller's to
/// rule out. For the ticks it finds, each group copies what its periods along a line
/// compute from ([`GroupState::prepare_cruise`]), and `state` notes the channels that
/// stand (at rest, commanded by no group), which those ticks pass over.
pub fn cruise_ahead(
    machine: &Machine,
    groups: &mut [GroupState],
    state: &mut TickState,
    dt: f64,
    limit_mode: i32,
    most: u32,
) -> u32 {
    if safety::reads_channels(limit_mode, machine, false) {
        return 0;
    }
    for (card, (triggers, settings)) in machine.triggers_and_settings().enumerate() {
        if !state.card_idle(card, || !triggers.armed(&settings.error_threshold)) {
            return 0;
        }
    }
    let mut ahead = most;
    for g in groups.iter() {
        ahead = ahead.min(g.quiet_ticks_ahead(dt, ahead));
        if ahead == 0 {
            return 0;
        }
    }
    // The channels no group commands, at rest: nothing changes them while the groups
    // cruise.
    let mut commanded = [0u8; CARDS];
    for g in groups.iter_mut() {
        g.prepare_cruise(dt, ahead);
        let (card, mask) = g.commanded_channels();
        if let Some(c) = commanded.get_mut(card) {
            *c |= mask;
        }
    }
    state.quiet = [0; CARDS];
    for ((quiet, chans), commanded) in state.quiet.iter_mut().zip(machine.cards()).zip(commanded) {
        for (ch, chan) in chans.iter().enumerate() {
            if commanded >> ch & 1 == 0 && chan.stays_at_rest(dt) {
                *quiet |= 1 << ch;
            }
        }
    }
    ahead
}

/// The steps of an idle card's channels on a tick that defers, tick `n` of `dt`: the
/// channels that recorded at the last tick (`known`, bit n for channel n) record again
/// without asking; those of `quiet` (at rest, commanded by no group, on a cruise tick) are
/// passed over; the others step or start recording. Returns whether a channel stepped
/// (its index pulses to note) and the channels recording now.
#[inline(always)]
fn defer_idle_card(
    chans: &mut [Channel; AXES],
    known: u8,
    quiet: u8,
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
        debug_assert!(
            (0..AXES).all(|ch| quiet >> ch & 1 == 0 || chans[ch].stays_at_rest(dt)),
            "a quiet channel stays at rest"
        );
        // The channels of each kind, one set bit at a time (channels do not meet).
        let mut record = known;
        while record != 0 {
            chans[record.trailing_zeros() as usize % AXES].record_step(n);
            record &= record - 1;
        }
        let mut ask = !(known | quiet);
        while ask != 0 {
            let ch = ask.trailing_zeros() as usize % AXES;
            stepped |= chans[ch].step_or_defer(dt, n);
            if chans[ch].deferring() {
                now |= 1 << ch;
            }
            ask &= ask - 1;
        }
    }
    (stepped, now)
}

/// The cards a tick found with nothing armed ([`CardTriggers::armed`]) while the caller
/// holds the machine.
///
/// What arms a card (compares, index and input interrupts, latches, closed-loop
/// thresholds) only the program sets, under the machine's lock; the tick itself only
/// disarms (a trigger-out's hold ends), and a card with nothing armed runs no trigger
/// tick at all. So a card found idle stays idle for as long as the caller keeps the
/// machine, and the next tick need not look again; a card found armed is looked at every
/// tick.
///
/// [`CardTriggers::armed`]: crate::machine::triggers::CardTriggers::armed
#[derive(Debug, Default, Clone, Copy)]
pub struct IdleCards([bool; CARDS]);

impl IdleCards {
    /// Whether `card` has nothing armed: known, or found by `look` (and then known from
    /// now on, if so; a card past the last is always looked at).
    #[inline]
    pub fn idle(&mut self, card: usize, look: impl FnOnce() -> bool) -> bool {
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
