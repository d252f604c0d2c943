//! The chained synchronous move of §5.4: a circle of chords uploaded as one chain.

use std::time::Instant;

use mc3b::codec::Command;

use super::line::board_refusal;
use super::Board;
use crate::checks::MOTORS;
use crate::circle::CirclePlan;
use crate::params::ID;
use crate::shared::{Refusal, Reply};

/// A circle under way, for the drawing.
#[derive(Debug, Clone)]
pub(super) struct CircleRun {
    pub(super) plan: CirclePlan,
    pub(super) start: [i64; 2],
}

impl Board {
    /// The chained synchronous move (§5.4, §4.17): all three motors idle (§4.16), the
    /// buffer cleared of an earlier upload cut short, the chords stored with execute 0
    /// and the last sent with execute 1. A stop during the upload ends it; what was
    /// stored is discarded before the next chain.
    pub(super) fn circle(&mut self, plan: CirclePlan) -> Reply {
        self.connected()?;
        for m in 0..MOTORS {
            self.in_manual(m as u32)?;
            if self.query(m).map_err(board_refusal)?.running {
                return Err(Refusal::new(
                    409,
                    format!(
                        "motor {m} is running: a chained move needs all three motors idle \
                         (§4.16)"
                    ),
                ));
            }
        }
        if self.conn.as_ref().is_some_and(|c| c.chain_dirty) {
            self.send(
                Command::SyncMove {
                    id: ID,
                    steps: [0; 3],
                    directions: [0; 3],
                    execute: None,
                },
                "discarding the chained-move buffer (Y without execute)",
            )
            .map_err(board_refusal)?;
            if let Some(c) = self.conn.as_mut() {
                c.chain_dirty = false;
            }
        }
        let moves = plan.moves();
        let n = moves.len();
        let (xm, ym) = (plan.x_motor as usize, plan.y_motor as usize);
        if let Some(c) = self.conn.as_mut() {
            c.circle = Some(CircleRun {
                start: [c.model.position(xm), c.model.position(ym)],
                plan: plan.clone(),
            });
        }
        for (k, mv) in moves.iter().enumerate() {
            if self.shared.stop_pending() {
                return Err(Refusal::new(
                    409,
                    format!(
                        "stopped during the upload after {k} of {n} chords: nothing of the \
                         chain runs (the stored chords are discarded before the next chain)"
                    ),
                ));
            }
            if k % 10 == 0 {
                self.shared
                    .set_busy(Some(format!("the circle's upload ({k} of {n} chords)")));
                self.publish();
            }
            let mut steps = [0u32; 3];
            let mut dirs = [0u32; 3];
            steps[xm] = mv[0].0;
            dirs[xm] = mv[0].1;
            steps[ym] = mv[1].0;
            dirs[ym] = mv[1].1;
            let last = k + 1 == n;
            if last {
                self.mark_moved();
            }
            if let Some(c) = self.conn.as_mut() {
                // From the first store on, the buffer may hold chords until the last
                // one's execute.
                c.chain_dirty = true;
            }
            let cmd = Command::SyncMove {
                id: ID,
                steps,
                directions: dirs,
                execute: Some(u32::from(last)),
            };
            self.send(cmd, &format!("chord {} of {n} (Y)", k + 1))
                .map_err(board_refusal)?;
        }
        if let Some(c) = self.conn.as_mut() {
            c.chain_dirty = false;
        }
        self.next_poll = Instant::now();
        let text = format!(
            "circle of radius {} steps in {n} chords on motors {xm} (X) and {ym} (Y): running",
            plan.radius
        );
        self.event("info", text.clone());
        Ok(text)
    }
}
