//! A running engine ([`Engine`]): starting its thread, the thread's loop (wait for the
//! clock, tick, deliver the routines), stopping and joining it.

use super::shared::Shared;
use super::{isr, thread, trace};
use crate::clock::{ClockMode, Next};
use crate::config::{GroupDef, MacTable};
use crate::machine::Machine;
use std::cell::RefCell;
use std::sync::{Arc, Weak};
use std::thread::{JoinHandle, ThreadId};
use std::time::Duration;

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
        let shared = Arc::new(Shared::new(
            mode,
            period,
            groups,
            mac,
            machine,
            trace,
            super::cruise::enabled_by_env(),
        ));
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
        if let Some(t) = self.shared.tracer.trace.lock().as_mut() {
            // No tick follows: what the groups noted since their last row (a call made
            // just before the close, an abort) and the ends of the commands the close
            // cuts short are written at the end of the last tick.
            let sh = &self.shared;
            let t_ns = u128::from(sh.clock.ticks()) * sh.clock.period_nanos();
            t.close_groups(t_ns, &mut sh.lock_groups());
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
    // The interrupts each tick collects, reused from tick to tick.
    let mut interrupts = isr::Collected::new();
    // The machine's and the groups' locks, kept from one tick to the next while nothing
    // in between needs them (`Shared::quiet_between_ticks`).
    let mut held: Option<super::tick::Held<'_>> = None;
    loop {
        // Within a run granted to a virtual clock the next tick is due at once (what
        // `wait_next` would find); otherwise the run ends (the program resumes and will
        // want the locks) or the clock decides.
        let next = if shared.clock.granted() {
            Next::Tick
        } else {
            super::tick::release(&mut held);
            shared.clock.wait_next()
        };
        match next {
            Next::Stop => {
                super::tick::release(&mut held);
                shared.custom_close();
                return;
            }
            Next::Tick => {
                // A tick, and while each ends quiet with the next one a cruise tick
                // (`cruise.rs`), the ticks after it, back to back.
                let mut cruise = false;
                loop {
                    let published = shared.tick_or_recover(&mut held, &mut interrupts, cruise);
                    // Quiet: no stage below has anything to run, and the locks stay held
                    // into the next tick.
                    let quiet = shared.quiet_between_ticks();
                    if !quiet {
                        super::tick::release(&mut held);
                        // The program's kinematics for the next tick, without any lock.
                        shared.kinematics_stage();
                    }
                    shared.check_watch();
                    if !published {
                        shared.end_of_run(held.as_mut());
                    }
                    if !quiet {
                        if shared.tracer.tracing && !interrupts.is_empty() {
                            shared.trace_interrupts(&interrupts);
                        }
                        // Custom-motion callbacks, then the interrupt callbacks collected
                        // in the tick, run here without any lock.
                        shared.custom_stage();
                        shared.routines.isr.deliver(&interrupts, &shared.clock);
                        shared.call_cycle_routines();
                    }
                    // Asked before the tick is counted: the next one is then due at once.
                    cruise = quiet && shared.cruise_next(&mut held);
                    shared.clock.tick_done();
                    if !cruise {
                        break;
                    }
                }
            }
        }
    }
}
