//! The one process-wide system: the configuration the program sets and, between
//! `MCC_InitSystem` and `MCC_CloseSystem`, the running virtual card (user manual §2.4–2.5).

use crate::clock::ClockMode;
use crate::config::{CardIx, ChannelIx, Config, GroupDef, AXES, GROUPS};
use crate::engine::{Engine, Shared};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;
use crate::vendor::{SYS_CARD_CONFIG, SYS_ENCODER_CONFIG, SYS_MAC_PARAM};
use once_cell::sync::Lazy;
use parking_lot::{Condvar, Mutex, MutexGuard, RwLock};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

/// The running part of the system.
#[derive(Debug)]
pub struct Running {
    /// The engine thread and its shared state.
    pub engine: Engine,
    /// Number of cards passed to `MCC_InitSystem`.
    pub cards: usize,
    /// The card types passed to `MCC_InitSystem`.
    pub card_types: Vec<u16>,
    /// Mechanism parameters in effect (taken at init and at `MCC_UpdateParam`).
    pub mac: [[SYS_MAC_PARAM; AXES]; crate::config::CARDS],
    /// Encoder configuration in effect.
    pub encoder: [[SYS_ENCODER_CONFIG; AXES]; crate::config::CARDS],
    /// The groups running, `(index, definition)`.
    pub groups: Vec<(usize, GroupDef)>,
    /// Started by `MCC_InitSimulation` rather than `MCC_InitSystem`.
    pub simulation: bool,
    /// The simulated machine's configuration (`MCCL_SIM`).
    pub sim: crate::sim::config::SimConfig,
    /// The MC3B devices behind cards with an `mc3b_port` (closed after the engine).
    pub mc3b: Vec<crate::mc3b::backend::Device>,
    /// The browser panel (`MCCL_PANEL`), stopped before the engine.
    #[cfg(feature = "panel")]
    pub panel: Option<crate::panel::Panel>,
}

/// Configuration plus the running card.
#[derive(Debug, Default)]
pub struct System {
    /// What the program has configured.
    pub config: Config,
    /// `Some` between a successful init and `MCC_CloseSystem`.
    pub running: Option<Running>,
    /// An init or close is under way (see [`Turn`]): no other may start meanwhile.
    changing: bool,
    /// Threads of engines stopped from their own thread (a routine that closed or
    /// replaced its system), joined by the next init or close on another thread.
    unjoined: Vec<JoinHandle<()>>,
}

static SYSTEM: Lazy<Mutex<System>> = Lazy::new(|| Mutex::new(System::default()));

/// Signalled when an init or close ends its turn or stops an engine.
static TURN_CHANGED: Condvar = Condvar::new();

/// The running engine's shared state, for calls that must not wait for the system lock
/// (status reads). `None` while the system is closed.
static ACTIVE: RwLock<Option<Arc<Shared>>> = RwLock::new(None);

/// The right to start or stop the system, held by one `MCC_InitSystem` or
/// `MCC_CloseSystem` at a time from its first check to its end; the system lock itself
/// is released while the call joins an engine thread (whose routine may be waiting for
/// that lock). Dropping the turn, also while unwinding, hands it to the next caller.
///
/// The rule this gives (docs/compatibility.md, "Init and close from several
/// threads and routines"): init and close take effect in the order
/// they take their turn, so the last one wins; when `MCC_CloseSystem` returns `NO_ERR` no
/// engine of the system it closed, nor one that a routine of it started, is left. A
/// routine of an engine that has been stopped cannot take a turn
/// (`COMMAND_NOTACCEPTED_ERR`): the program's init or close that stopped it came first.
struct Turn {
    sys: Option<MutexGuard<'static, System>>,
}

impl Turn {
    /// Waits for the turn (the system lock is released while waiting).
    fn take() -> McclResult<Turn> {
        let mut sys = SYSTEM.lock();
        loop {
            if crate::engine::on_retired_engine_thread() {
                return Err(McclError::NotAccepted);
            }
            if !sys.changing {
                break;
            }
            TURN_CHANGED.wait(&mut sys);
        }
        sys.changing = true;
        Ok(Turn { sys: Some(sys) })
    }

    /// The system, locked again if the turn had released the lock.
    fn sys(&mut self) -> &mut System {
        self.sys.get_or_insert_with(|| SYSTEM.lock())
    }

    /// Releases the system lock, keeping the turn.
    fn unlock(&mut self) {
        self.sys = None;
    }

    /// Takes the running system out and stops its engine (a routine of it that waits for
    /// a turn gives up now), then joins it and the threads left to join with the system
    /// lock released; a thread that cannot be joined here (this one) is kept for later.
    /// Returns whether a system was running.
    fn close_running(&mut self) -> bool {
        let sys = self.sys();
        let old = sys.running.take();
        let unjoined = std::mem::take(&mut sys.unjoined);
        *ACTIVE.write() = None;
        if let Some(r) = &old {
            r.engine.stop();
        }
        TURN_CHANGED.notify_all();
        self.unlock();
        let was_running = old.is_some();
        if was_running {
            // The vendor's library forgets its groups when it closes; the next init runs
            // those created since (or none: the default group only after
            // `MCC_CloseAllGroups`).
            let sys = self.sys();
            sys.config.groups = [None; GROUPS];
            sys.config.units = [crate::vendor::consts::UNIT_MM; GROUPS];
            self.unlock();
        }
        let mut keep = Vec::new();
        if let Some(r) = old {
            #[cfg(feature = "panel")]
            drop(r.panel);
            let Running { engine, mc3b, .. } = r;
            keep.extend(engine.finish());
            // The MC3B ports close after the engine that used them stopped.
            drop(mc3b);
        }
        let me = std::thread::current().id();
        for t in unjoined {
            if t.thread().id() == me {
                keep.push(t);
            } else {
                let _ = t.join();
            }
        }
        self.sys().unjoined.extend(keep);
        was_running
    }
}

impl Drop for Turn {
    fn drop(&mut self) {
        self.sys().changing = false;
        TURN_CHANGED.notify_all();
    }
}

/// Runs `f` with the system locked.
pub fn with<R>(f: impl FnOnce(&mut System) -> R) -> R {
    f(&mut SYSTEM.lock())
}

/// Runs `f` on the configuration the program sets (the system locked).
pub fn config<R>(f: impl FnOnce(&mut Config) -> R) -> R {
    f(&mut SYSTEM.lock().config)
}

/// The running engine's shared state (`INITIAL_MOTION_ERR` when the system is closed).
pub fn active() -> McclResult<Arc<Shared>> {
    ACTIVE.read().clone().ok_or(McclError::NotInitialized)
}

/// Interpolation period accepted by `MCC_InitSystem`/`MCC_InitSystemEx`: 1..=50 ms.
pub fn check_period_ms(ms: f64) -> McclResult<Duration> {
    if ms.is_finite() && (f64::from(c::IPO_PERIOD_MIN)..=f64::from(c::IPO_PERIOD_MAX)).contains(&ms)
    {
        Ok(Duration::from_nanos((ms * 1e6).round() as u64))
    } else {
        Err(McclError::Parameter)
    }
}

/// The card entries the vendor's library takes (all run the same virtual card here): the
/// PCI types 2..5, and the ISA types 0 and 1 at an I/O address 0x200..=0x3F0 with an
/// IRQ of 3, 5, 7, 10, 11, 12 or 15; anything else is `PARAMETER_ERR`.
pub fn check_card(card: &SYS_CARD_CONFIG) -> McclResult<()> {
    match card.wCardType {
        2..=5 => Ok(()),
        0 | 1
            if (0x200..=0x3F0).contains(&card.wCardAddress)
                && [3, 5, 7, 10, 11, 12, 15].contains(&card.wIRQ_No) =>
        {
            Ok(())
        }
        _ => Err(McclError::Parameter),
    }
}

/// How many channels a card of type `t` has, as the vendor's library counts them: the
/// 4-axis types 0 and 2, the 6-axis types 1 and 3, the 8-axis IMP types.
pub fn card_type_channels(t: u16) -> usize {
    match t {
        0 | 2 => 4,
        1 | 3 => 6,
        _ => AXES,
    }
}

/// The number of channels of card `cd` of the running system (every channel when the
/// card is not there).
pub fn card_channels(cd: usize) -> usize {
    SYSTEM
        .lock()
        .running
        .as_ref()
        .and_then(|r| r.card_types.get(cd).copied())
        .map_or(AXES, card_type_channels)
}

/// How `init` was reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InitKind {
    /// `MCC_InitSystem` / `MCC_InitSystemEx`.
    System,
    /// `MCC_InitSimulation`.
    Simulation,
}

/// `MCC_InitSystem`: validates everything first, then starts the virtual card. While a
/// system runs it is `RUN_TIME_ERR` (as the vendor's library answers); nothing changes
/// when validation fails.
pub fn init(period: Duration, cards: &[SYS_CARD_CONFIG], kind: InitKind) -> McclResult<()> {
    // A custom-motion callback may not replace the system its motion runs on.
    if crate::engine::custom::in_callback().is_some() {
        return Err(McclError::NotAccepted);
    }
    if cards.is_empty() || cards.len() > crate::config::CARDS {
        return Err(McclError::Parameter);
    }
    for card in cards {
        check_card(card)?;
    }
    let mode = ClockMode::from_env().map_err(|msg| {
        eprintln!("MCCL: MCC_InitSystem failed: {msg}");
        McclError::NotInitialized
    })?;
    let sim = crate::sim::config::SimConfig::from_env_value(
        std::env::var_os(crate::sim::config::ENV_VAR).as_deref(),
    )
    .map_err(|msg| {
        for line in msg.lines() {
            eprintln!("MCCL: MCC_InitSystem failed: {line}");
        }
        McclError::NotInitialized
    })?;
    let groups_for = |sys: &System| {
        let groups = sys.config.effective_groups();
        if groups.iter().any(|(_, g)| g.card.0 >= cards.len()) {
            Err(McclError::Group)
        } else {
            Ok(groups)
        }
    };
    let mut turn = Turn::take()?;
    groups_for(turn.sys())?;
    if turn.sys().running.is_some() {
        return Err(McclError::RunTime);
    }
    let sys = turn.sys();
    let groups = groups_for(sys)?;
    // The table holds what runs (the default group too, so that it can be closed).
    for (i, d) in &groups {
        sys.config.groups[*i] = Some(*d);
    }
    let trace = crate::engine::trace::Trace::from_env().map_err(|msg| {
        eprintln!("MCCL: MCC_InitSystem failed: {msg}");
        McclError::NotInitialized
    })?;
    // Cards whose channels 0..2 are an MC3B (never under MCC_InitSimulation): a real
    // device moves in real time, so the realtime clock runs.
    let mc3b = match kind {
        InitKind::System => {
            crate::mc3b::backend::open_devices(&sim, cards.len(), &groups, &sys.config.mac)?
        }
        InitKind::Simulation => Vec::new(),
    };
    let mode = if mc3b.is_empty() || mode == ClockMode::Realtime {
        mode
    } else {
        eprintln!("MCCL: an MC3B card runs in real time: MCCL_CLOCK is ignored");
        ClockMode::Realtime
    };
    let machine = crate::machine::Machine::new(
        &sys.config.mac,
        &sys.config.encoder,
        |c, ch| crate::machine::ChannelSpec::from_sim(sim.channel(c, ch)),
        |c| sim.card(c).emergency_stop,
        cards.len(),
    );
    let engine =
        Engine::start(mode, period, &groups, &sys.config.mac, machine, trace).map_err(|e| {
            eprintln!("MCCL: cannot start the engine thread: {e}");
            McclError::RunTime
        })?;
    // ADC inputs the configuration wires (default: ADC n reads DAC n of the card).
    for (c, p) in engine.shared().periphs().iter().enumerate() {
        let mut p = p.lock();
        for ch in 0..AXES {
            match sim.channel(c, ch).adc {
                Some(crate::sim::config::AdcSource::Volts(v)) => {
                    p.set_adc_source(ch, crate::card::adc::AdcSource::Constant(v))
                }
                Some(crate::sim::config::AdcSource::Dac(d)) => {
                    p.set_adc_source(ch, crate::card::adc::AdcSource::Dac(usize::from(d)))
                }
                None => {}
            }
        }
    }
    attach_mc3b(engine.shared(), &mc3b);
    // Kinematics registered before init take effect before any other thread can reach
    // the system; the program's initialisers run without the system lock.
    let kinematics = crate::engine::kinematics::registered();
    if !kinematics.is_empty() {
        turn.unlock();
        engine.shared().apply_kinematics(&kinematics)?;
        crate::engine::kinematics::clear_registered();
    }
    let sys = turn.sys();
    #[cfg(feature = "panel")]
    let panel = crate::panel::start_from_env(engine.shared(), &groups);
    #[cfg(not(feature = "panel"))]
    if std::env::var_os("MCCL_PANEL").is_some_and(|v| !v.is_empty() && v != "0") {
        eprintln!("MCCL: this library was built without the panel: MCCL_PANEL is ignored");
    }
    *ACTIVE.write() = Some(engine.shared().clone());
    debug_assert!(
        sys.running.is_none(),
        "only the turn's holder installs a system"
    );
    sys.running = Some(Running {
        engine,
        cards: cards.len(),
        card_types: cards.iter().map(|c| c.wCardType).collect(),
        mac: sys.config.mac,
        encoder: sys.config.encoder,
        groups,
        simulation: kind == InitKind::Simulation,
        sim,
        mc3b,
        #[cfg(feature = "panel")]
        panel,
    });
    Ok(())
}

/// Makes every group on the card of an MC3B device run its commands on the device.
fn attach_mc3b(shared: &Shared, devices: &[crate::mc3b::backend::Device]) {
    for d in devices {
        shared.mark_mc3b(d.card());
        let limits = d.limits();
        shared.for_each_group(|g| {
            if g.def().card.0 == d.card() {
                let mut x = crate::mc3b::backend::Executor::new(d.link(), g.axes());
                x.set_limits(limits.map(|l| [l[0] != 0, l[2] != 0]));
                g.attach_external(Box::new(x));
            }
        });
    }
}

/// Whether the running system was started by `MCC_InitSimulation`.
pub fn is_simulation() -> bool {
    SYSTEM.lock().running.as_ref().is_some_and(|r| r.simulation)
}

/// Whether the running system drives an MC3B (a card with `mc3b_port`).
pub fn has_mc3b() -> bool {
    SYSTEM
        .lock()
        .running
        .as_ref()
        .is_some_and(|r| !r.mc3b.is_empty())
}

/// `MCC_CloseSystem`: stops the engine and joins its thread (nothing to do, and no error,
/// when nothing runs). The configuration is kept for the next init.
pub fn close() -> McclResult<()> {
    // A custom-motion callback may not close the system its motion runs on.
    if crate::engine::custom::in_callback().is_some() {
        return Err(McclError::NotAccepted);
    }
    let mut turn = Turn::take()?;
    turn.close_running();
    Ok(())
}

/// `MCC_ResetMotion`, as the vendor's library does it: every group returns to its state
/// right after init with its settings kept (`GroupState::reset_motion`); when any group
/// was busy the call still does so and answers `COMMAND_NOTACCEPTED_ERR`.
pub fn reset_motion() -> McclResult<()> {
    let sys = SYSTEM.lock();
    let r = sys.running.as_ref().ok_or(McclError::NotInitialized)?;
    let shared = r.engine.shared();
    let busy = shared.reset_motion();
    // The vendor's library answers so for a busy card, and resets it all the same.
    if busy {
        return Err(McclError::NotAccepted);
    }
    Ok(())
}

/// `MCC_UpdateParam`: the mechanism and encoder parameters set since init take effect,
/// and motion resets as with `MCC_ResetMotion` (§2.4.2).
pub fn update_param() -> McclResult<()> {
    let mut sys = SYSTEM.lock();
    let (mac, encoder) = (sys.config.mac, sys.config.encoder);
    let r = sys.running.as_mut().ok_or(McclError::NotInitialized)?;
    r.mac = mac;
    r.encoder = encoder;
    let shared = r.engine.shared();
    {
        let mut m = shared.lock_machine();
        for (c, chans) in m.cards_mut().iter_mut().enumerate() {
            for (ch, chan) in chans.iter_mut().enumerate() {
                chan.set_params(mac[c][ch], encoder[c][ch]);
                chan.rezero();
            }
        }
    }
    shared.reset_all(&r.mac);
    Ok(())
}

impl System {
    /// Whether DAC channel `ch` of card `cd` is free for the DAC calls: a channel whose
    /// mechanism parameters in effect say `OCM_VOLTAGE` drives its axis
    /// (`VOLTAGE_COMMAND_CHANNEL_ERR`); `INITIAL_MOTION_ERR` when nothing runs.
    pub fn dac_channel_free(&self, cd: usize, ch: usize) -> McclResult<()> {
        match self.running.as_ref().map(|r| r.mac[cd][ch].wCommandMode) {
            None => Err(McclError::NotInitialized),
            Some(c::OCM_VOLTAGE) => Err(McclError::VoltageChannel),
            Some(_) => Ok(()),
        }
    }

    /// `MCC_CreateGroupEx`: the lowest free slot, `PARAMETER_ERR` when a channel is
    /// another group's. While the card runs the group runs at once, from where its
    /// channels stand (as the vendor's library does; not on an MC3B card, whose groups
    /// the device runs: `COMMAND_NOTACCEPTED_ERR`).
    pub fn create_group(&mut self, def: GroupDef) -> McclResult<usize> {
        if let Some(r) = &self.running {
            let shared = r.engine.shared();
            shared.card(def.card)?;
            if shared.is_mc3b(def.card.0) {
                return Err(McclError::NotAccepted);
            }
        }
        let slot = self.config.create_group(def)?;
        if let Some(r) = &mut self.running {
            let mut def = def;
            def.unit = self.config.units[slot];
            r.engine.shared().open_group(slot, def, &r.mac);
            r.groups.push((slot, def));
        }
        Ok(slot)
    }

    /// `MCC_CloseGroup` (no such group: `PARAMETER_ERR`, as the vendor's library
    /// answers). While the card runs the group stops where it stands and goes.
    pub fn close_group(&mut self, g: i32) -> McclResult<()> {
        let slot = usize::try_from(g)
            .ok()
            .filter(|&g| g < GROUPS)
            .ok_or(McclError::Parameter)?;
        if self.running.as_ref().is_some_and(|r| {
            r.groups
                .iter()
                .any(|(i, d)| *i == slot && r.engine.shared().is_mc3b(d.card.0))
        }) {
            return Err(McclError::NotAccepted);
        }
        match self.config.groups[slot].take() {
            Some(_) => {
                self.config.units[slot] = crate::vendor::consts::UNIT_MM;
                if let Some(r) = &mut self.running {
                    r.engine.shared().close_group(slot, &r.mac);
                    r.groups.retain(|(i, _)| *i != slot);
                }
                Ok(())
            }
            None => Err(McclError::Parameter),
        }
    }

    /// `MCC_CloseAllGroups`: the table empties, and the next init without a group
    /// created runs the default group again. While the card runs every group goes (none
    /// on an MC3B card: `COMMAND_NOTACCEPTED_ERR`).
    pub fn close_all_groups(&mut self) -> McclResult<()> {
        if let Some(r) = &self.running {
            let shared = r.engine.shared();
            if r.groups.iter().any(|(_, d)| shared.is_mc3b(d.card.0)) {
                return Err(McclError::NotAccepted);
            }
            for (slot, _) in &r.groups {
                shared.close_group(*slot, &r.mac);
            }
        }
        if let Some(r) = &mut self.running {
            r.groups.clear();
        }
        self.config.groups = [None; GROUPS];
        self.config.units = [crate::vendor::consts::UNIT_MM; GROUPS];
        self.config.explicit_groups = false;
        Ok(())
    }

    /// The definition of group `g` as it runs now (running) or will run (closed).
    pub fn group_def(&self, g: u16) -> McclResult<GroupDef> {
        let g = usize::from(g);
        match &self.running {
            Some(r) => r.groups.iter().find(|(i, _)| *i == g).map(|(_, d)| *d),
            None => self
                .config
                .effective_groups()
                .into_iter()
                .find(|(i, _)| *i == g)
                .map(|(_, d)| d),
        }
        .ok_or(McclError::Group)
    }

    /// `MCC_GetConvFactor`: pulses per user unit of a channel with the mechanism
    /// parameters in effect ([`System::mac_in_effect`]).
    /// Negative when the channel's output is reversed (`wPosToEncoderDir` nonzero), as
    /// the vendor's library answers.
    pub fn conv_factor(&self, card: CardIx, ch: ChannelIx) -> f64 {
        let mac = self.mac_in_effect(card, ch);
        let f = crate::config::conv_factor(&mac);
        if mac.wPosToEncoderDir != 0 {
            -f
        } else {
            f
        }
    }

    /// The mechanism parameters in effect for a channel (running: those applied at init
    /// or `MCC_UpdateParam`; closed: those set).
    pub fn mac_in_effect(&self, card: CardIx, ch: ChannelIx) -> SYS_MAC_PARAM {
        match &self.running {
            Some(r) => r.mac[card.0][ch.0],
            None => self.config.mac[card.0][ch.0],
        }
    }
}
