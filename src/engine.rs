//! The virtual card's engine: one thread per running system that ticks every interpolation
//! period on the [`Clock`], advances every group, and publishes a snapshot that status
//! calls read without taking the engine lock.
//!
//! Lock order: `system::SYSTEM` before [`Shared::card`]; the engine thread takes only
//! `card`, and never while it runs user code, so a callback may call any MCC_* function.

use crate::clock::{Clock, ClockMode, Next};
use crate::config::{GroupDef, GROUPS};
use crate::vendor::consts as c;
use parking_lot::Mutex;
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::Arc;
use std::thread::{JoinHandle, ThreadId};
use std::time::Duration;

/// One group as the card runs it.
#[derive(Debug, Clone)]
pub struct GroupRuntime {
    /// Group index (0..95).
    pub index: usize,
    /// The mapping and queue size the group was created with.
    pub def: GroupDef,
    /// Motion status (`GMS_*`).
    pub status: i32,
}

impl GroupRuntime {
    fn new(index: usize, def: GroupDef) -> GroupRuntime {
        GroupRuntime {
            index,
            def,
            status: c::GMS_STOP,
        }
    }

    /// Whether the group still has motion to run (its status is not `GMS_STOP`).
    pub fn busy(&self) -> bool {
        self.status != c::GMS_STOP
    }
}

/// The card state the engine owns; settings calls lock it briefly.
#[derive(Debug)]
pub struct CardState {
    /// The running groups, by group index order.
    pub groups: Vec<GroupRuntime>,
}

impl CardState {
    fn new(groups: &[(usize, GroupDef)]) -> CardState {
        CardState {
            groups: groups
                .iter()
                .map(|&(i, d)| GroupRuntime::new(i, d))
                .collect(),
        }
    }

    /// The running group with index `g`.
    pub fn group_mut(&mut self, g: usize) -> Option<&mut GroupRuntime> {
        self.groups.iter_mut().find(|r| r.index == g)
    }

    /// The running group with index `g`.
    pub fn group(&self, g: usize) -> Option<&GroupRuntime> {
        self.groups.iter().find(|r| r.index == g)
    }

    /// Whether any group has work (the fast clock ticks while this is true).
    pub fn busy(&self) -> bool {
        self.groups.iter().any(GroupRuntime::busy)
    }

    /// Returns every group to the state right after `MCC_InitSystem` (§2.4.2: UpdateParam
    /// and ResetMotion both do this).
    pub fn reset(&mut self) {
        for g in &mut self.groups {
            *g = GroupRuntime::new(g.index, g.def);
        }
    }

    /// One interpolation period of the card.
    fn tick(&mut self, _dt: Duration) {
        // Groups advance their motion here; with nothing queued they stay at GMS_STOP.
    }
}

/// What the engine thread and the program's threads share.
#[derive(Debug)]
pub struct Shared {
    /// The tick clock.
    pub clock: Clock,
    /// The card state (engine lock).
    pub card: Mutex<CardState>,
    /// Motion status per group slot, published after every change (`GMS_*`, or -1 for a
    /// slot with no running group). Read without the engine lock.
    pub status: [AtomicI32; GROUPS],
    /// `MCC_EnableDryRun` is in effect.
    pub dry_run: AtomicBool,
}

impl Shared {
    /// Publishes the groups' statuses for lock-free readers.
    pub fn publish(&self, card: &CardState) {
        for g in &card.groups {
            self.status[g.index].store(g.status, Ordering::Release);
        }
    }
}

/// A running engine thread.
#[derive(Debug)]
pub struct Engine {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
    thread_id: ThreadId,
}

impl Engine {
    /// Starts the engine for `groups` with the given clock mode and period.
    pub fn start(
        mode: ClockMode,
        period: Duration,
        groups: &[(usize, GroupDef)],
    ) -> std::io::Result<Engine> {
        let shared = Arc::new(Shared {
            clock: Clock::new(mode, period),
            card: Mutex::new(CardState::new(groups)),
            status: std::array::from_fn(|_| AtomicI32::new(-1)),
            dry_run: AtomicBool::new(false),
        });
        shared.publish(&shared.card.lock());
        let s2 = shared.clone();
        let thread = std::thread::Builder::new()
            .name("mccl-engine".into())
            .spawn(move || run(&s2))?;
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

    /// Stops the clock and joins the thread. Called from the engine thread itself (a
    /// callback that closes the system), it only stops: the thread ends when the callback
    /// returns.
    pub fn shutdown(self) {
        drop(self);
    }

    /// Whether the calling thread is this engine's thread.
    pub fn is_engine_thread(&self) -> bool {
        std::thread::current().id() == self.thread_id
    }
}

impl Drop for Engine {
    fn drop(&mut self) {
        self.shared.clock.stop();
        if let Some(t) = self.thread.take() {
            if std::thread::current().id() != self.thread_id {
                let _ = t.join();
            }
        }
    }
}

fn run(shared: &Shared) {
    shared.clock.set_engine_thread();
    let period = shared.clock.period();
    loop {
        let busy = || shared.card.lock().busy();
        match shared.clock.wait_next(&busy) {
            Next::Stop => return,
            Next::Tick => {
                {
                    let mut card = shared.card.lock();
                    card.tick(period);
                    shared.publish(&card);
                }
                // Interrupt callbacks collected in the tick run here, without the lock.
                shared.clock.tick_done();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_tick_and_shutdown() {
        let e = Engine::start(
            ClockMode::Stepped,
            Duration::from_millis(2),
            &[(0, GroupDef::default_group())],
        )
        .unwrap();
        assert_eq!(e.shared().status[0].load(Ordering::Acquire), c::GMS_STOP);
        assert_eq!(e.shared().status[1].load(Ordering::Acquire), -1);
        e.shared().clock.delay_ms(10);
        assert_eq!(e.shared().clock.ticks(), 5);
        e.shutdown();
    }
}
