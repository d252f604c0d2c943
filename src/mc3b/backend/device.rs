//! An MC3B behind a card: the worker on its own thread, opened for the cards that name
//! an `mc3b_port`, and the groups of such a card attached to it.

use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

use super::limits::{motor_limits, LimitMasks};
use super::link::Link;
use super::worker::connect_with;
use super::MOTORS;
use ::mc3b::client::Transport;
use ::mc3b::serial::open_port;

/// An MC3B behind a card: the worker on its own thread. Dropping it stops a running job
/// (`S`) and ends the thread; the port closes with it.
#[derive(Debug)]
pub struct Device {
    card: usize,
    link: Arc<Link>,
    thread: Option<JoinHandle<()>>,
    limits: [LimitMasks; MOTORS],
}

impl Device {
    /// Opens the serial port at `path` (19200 8N1), greets the MC3B and starts the
    /// worker. The error says what failed.
    /// `limits` are the motors' limit masks (`L`), set before anything moves.
    pub fn open(
        card: usize,
        path: &str,
        timeout: Duration,
        limits: &[LimitMasks; MOTORS],
    ) -> Result<Device, String> {
        let port = open_port(path, timeout).map_err(|e| format!("cannot open {path}: {e}"))?;
        Device::start(card, Box::new(port), timeout, limits).map_err(|e| format!("{path}: {e}"))
    }

    /// [`Device::open`] over any transport.
    pub fn start(
        card: usize,
        transport: Box<dyn Transport + Send>,
        timeout: Duration,
        limits: &[LimitMasks; MOTORS],
    ) -> Result<Device, String> {
        let (link, worker) = connect_with(transport, timeout, limits)?;
        if link.shut_down() {
            return Err("link closed".into());
        }
        let thread = std::thread::Builder::new()
            .name(format!("mccl-mc3b-{card}"))
            .spawn(move || worker.run())
            .map_err(|e| format!("cannot start the MC3B thread: {e}"))?;
        Ok(Device {
            card,
            link,
            thread: Some(thread),
            limits: *limits,
        })
    }

    /// The limit masks set on the device's motors.
    pub fn limits(&self) -> [LimitMasks; MOTORS] {
        self.limits
    }

    /// The card whose channels 0..2 this MC3B is.
    pub fn card(&self) -> usize {
        self.card
    }

    /// The link groups on this card use.
    pub fn link(&self) -> Arc<Link> {
        self.link.clone()
    }
}

impl Drop for Device {
    fn drop(&mut self) {
        self.link.shutdown();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// Reply timeout of the backend: `MCL_TIMEOUT_MS` (a positive integer of ms, as for the
/// `mcl_*` library) or 500 ms.
pub fn reply_timeout() -> Duration {
    ::mc3b::client::timeout_from_env()
}

/// Opens the MC3B of every card of `sim` (among the first `cards`) that names an
/// `mc3b_port`, for the groups that will run. Refused, with a message on stderr: two
/// groups driving channels 0..2 of one MC3B (`GROUP_PARAMETER_ERR`: the device runs one
/// job at a time), a port that cannot be opened or an MC3B that does not answer
/// (`INITIAL_MOTION_ERR`).
pub fn open_devices(
    sim: &crate::sim::config::SimConfig,
    cards: usize,
    groups: &[(usize, crate::config::GroupDef)],
    mac: &crate::config::MacTable,
) -> crate::error::McclResult<Vec<Device>> {
    use crate::error::McclError;
    let mut devices = Vec::new();
    for (card, mac) in mac.iter().enumerate().take(cards) {
        let Some(path) = sim.card(card).mc3b_port.as_deref() else {
            continue;
        };
        let drivers: Vec<usize> = groups
            .iter()
            .filter(|(_, g)| {
                g.card.0 == card && g.channels.iter().flatten().any(|ch| ch.0 < MOTORS)
            })
            .map(|(i, _)| *i)
            .collect();
        if let [a, b, ..] = drivers.as_slice() {
            eprintln!(
                "MCCL: MCC_InitSystem failed: card {card} is an MC3B ({path}): groups {a} and \
                 {b} both drive its channels 0..2 (one group per MC3B)"
            );
            return Err(McclError::Group);
        }
        let limits: [LimitMasks; MOTORS] =
            std::array::from_fn(|m| motor_limits(sim.channel(card, m), &mac[m]));
        match Device::open(card, path, reply_timeout(), &limits) {
            Ok(d) => devices.push(d),
            Err(msg) => {
                eprintln!("MCCL: MCC_InitSystem failed: card {card} (MC3B): {msg}");
                return Err(McclError::NotInitialized);
            }
        }
    }
    Ok(devices)
}
