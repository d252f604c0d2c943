//! Stops and manual control (§5.5): free runs whose speed and direction change on
//! the fly.

use mc3b::codec::Command;

use super::Board;
use crate::checks::MOTORS;
use crate::params::ID;

/// A motor in manual control (§5.5): free-running since `R` in `run_dir`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct FreeRun {
    pub(super) run_dir: u32,
    pub(super) speed: i32,
}

impl Board {
    /// Stops the flagged motors (`S`), best effort each; ends their manual control.
    pub(super) fn stop(&mut self, motors: [bool; MOTORS], reason: &str) -> String {
        if self.conn.is_none() {
            return "no MC3B connected: nothing to stop".into();
        }
        let mut stopped = Vec::new();
        let mut errors = Vec::new();
        for (m, _) in motors.iter().enumerate().filter(|(_, &f)| f) {
            let cmd = Command::Stop {
                id: ID,
                motor: m as u32,
            };
            match self.send(cmd, &format!("stop motor {m} (S)")) {
                Ok(()) => stopped.push(m.to_string()),
                Err(e) => errors.push(e),
            }
            if self.conn.is_none() {
                break;
            }
        }
        for (m, _) in motors.iter().enumerate().filter(|(_, &f)| f) {
            let was_manual = self
                .conn
                .as_mut()
                .and_then(|c| c.manual.get_mut(m).and_then(Option::take))
                .is_some();
            if was_manual {
                self.restore_velocity(m);
            }
        }
        let text = if errors.is_empty() {
            format!("stopped motor {} ({reason})", stopped.join(", "))
        } else {
            format!(
                "stop ({reason}): stopped motor {}; {}",
                if stopped.is_empty() {
                    "none".to_string()
                } else {
                    stopped.join(", ")
                },
                errors.join("; ")
            )
        };
        self.event(
            if errors.is_empty() { "info" } else { "error" },
            text.clone(),
        );
        if self.conn.is_some() {
            self.poll();
        }
        text
    }

    /// After manual control the board's maximum velocity is the record's again.
    pub(super) fn restore_velocity(&mut self, m: usize) {
        let Some(v) = self.conn.as_ref().map(|c| c.params[m].max_velocity) else {
            return;
        };
        let cmd = Command::SetMaxVelocity {
            id: ID,
            motor: m as u32,
            value: v,
            direction_modifier: None,
        };
        if let Err(e) = self.send(cmd, &format!("the maximum velocity of motor {m} (V)")) {
            self.event("error", e);
        }
    }

    /// Brings manual control to the sliders' speeds (§5.5: free-running, §4.12, with
    /// on-the-fly changes of velocity and direction, §4.6, §6.4). Speed 0 stops the
    /// motor. Failures go to the event log (the slider's request has been answered).
    pub(super) fn manual(&mut self, targets: [Option<i32>; MOTORS]) {
        for (m, t) in targets.iter().enumerate() {
            let Some(speed) = *t else { continue };
            if let Err(e) = self.manual_one(m, speed) {
                self.event("error", format!("manual control of motor {m}: {e}"));
            }
        }
    }

    pub(super) fn manual_one(&mut self, m: usize, speed: i32) -> Result<(), String> {
        let Some(c) = self.conn.as_ref() else {
            return Err("no MC3B connected".into());
        };
        let current = c.manual[m];
        let running = c.status[m].is_some_and(|s| s.running);
        let mi = m as u32;
        if speed == 0 {
            if current.is_some() {
                self.send(
                    Command::Stop { id: ID, motor: mi },
                    &format!("stop motor {m} (S)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = None;
                }
                self.restore_velocity(m);
            }
            return Ok(());
        }
        let dir = u32::from(speed < 0);
        let v = speed.unsigned_abs().max(1);
        match current {
            None => {
                if running {
                    return Err(format!(
                        "motor {m} is running (not under manual control): stop it first"
                    ));
                }
                self.shared.set_may_move();
                self.send(
                    Command::SetMaxVelocity {
                        id: ID,
                        motor: mi,
                        value: v,
                        direction_modifier: None,
                    },
                    &format!("the speed of motor {m} (V)"),
                )?;
                self.mark_moved();
                self.send(
                    Command::Run {
                        id: ID,
                        motor: mi,
                        direction: dir,
                    },
                    &format!("free run of motor {m} (R)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = Some(FreeRun {
                        run_dir: dir,
                        speed,
                    });
                }
            }
            Some(fr) => {
                // §6.4: modifier 1 runs opposite to the direction R was given.
                let modifier = u32::from(dir != fr.run_dir);
                self.send(
                    Command::SetMaxVelocity {
                        id: ID,
                        motor: mi,
                        value: v,
                        direction_modifier: Some(modifier),
                    },
                    &format!("the speed of motor {m} (V)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = Some(FreeRun { speed, ..fr });
                }
            }
        }
        Ok(())
    }
}
