//! The meeting point of a group (on the engine thread, never blocking) and the worker
//! that owns its device's serial line.

use std::time::Duration;

use parking_lot::{Condvar, Mutex};

use super::job::{Job, Report};

#[derive(Debug, Default)]
struct LinkState {
    job: Option<(u64, Job)>,
    stop: Option<u64>,
    report: Option<Report>,
    shutdown: bool,
}

/// The meeting point of a group and its device's worker. Every call holds a short lock
/// and never waits for the device.
#[derive(Debug, Default)]
pub struct Link {
    state: Mutex<LinkState>,
    wake: Condvar,
}

impl Link {
    /// Hands `job` to the worker (replacing a job it has not taken yet).
    pub fn post(&self, id: u64, job: Job) {
        let mut s = self.state.lock();
        s.job = Some((id, job));
        self.wake.notify_all();
    }

    /// Asks the worker to stop job `id` now (`S` on its motors); it still reports.
    pub fn request_stop(&self, id: u64) {
        let mut s = self.state.lock();
        s.stop = Some(id);
        self.wake.notify_all();
    }

    /// The report of job `id`, once there is one.
    pub fn take_report(&self, id: u64) -> Option<Report> {
        let mut s = self.state.lock();
        if s.report.is_some_and(|r| r.id == id) {
            s.report.take()
        } else {
            None
        }
    }

    /// Makes the worker stop what it runs and end.
    pub fn shutdown(&self) {
        let mut s = self.state.lock();
        s.shutdown = true;
        self.wake.notify_all();
    }

    pub(super) fn stop_wanted(&self, id: u64) -> bool {
        let s = self.state.lock();
        s.shutdown || s.stop == Some(id)
    }

    pub(super) fn shut_down(&self) -> bool {
        self.state.lock().shutdown
    }

    /// The next job; with `block`, waits for one. `None` at shutdown (or, without
    /// `block`, when there is none).
    pub(super) fn next_job(&self, block: bool) -> Option<(u64, Job)> {
        let mut s = self.state.lock();
        loop {
            if s.shutdown {
                return None;
            }
            if let Some(j) = s.job.take() {
                return Some(j);
            }
            if !block {
                return None;
            }
            self.wake.wait(&mut s);
        }
    }

    pub(super) fn report(&self, r: Report) {
        let mut s = self.state.lock();
        if s.stop == Some(r.id) {
            s.stop = None;
        }
        s.report = Some(r);
    }

    /// Waits up to `d` or until a stop of `id` or a shutdown is asked for.
    pub(super) fn pause(&self, id: u64, d: Duration) {
        let mut s = self.state.lock();
        if s.shutdown || s.stop == Some(id) {
            return;
        }
        let _ = self.wake.wait_for(&mut s, d);
    }
}
