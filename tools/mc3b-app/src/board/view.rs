//! What the page sees of the board thread: the published state and the event log.

use serde::Serialize;

use super::{Board, LinkState, POLL_PERIOD};
use crate::checks::MOTORS;
use crate::params::MotorParams;
use crate::shared::HEARTBEAT_TIMEOUT;

/// Events kept for the page.
const EVENTS_KEPT: usize = 40;

/// One line of the page's event log.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Event {
    pub(super) id: u64,
    pub(super) level: &'static str,
    pub(super) text: String,
    pub(super) t_ms: u64,
}

/// The page's view of one motor.
#[derive(Serialize)]
struct MotorView {
    running: Option<bool>,
    home0: Option<bool>,
    home1: Option<bool>,
    position: i64,
    speed: f64,
    manual: Option<i32>,
    params: MotorParams,
}

/// The published state.
#[derive(Serialize)]
struct View<'a> {
    link: &'a str,
    port: Option<&'a str>,
    firmware: Option<String>,
    link_message: Option<&'a str>,
    last_answer_ms: Option<u64>,
    inputs: Option<u8>,
    debounce: u32,
    motors: Vec<MotorView>,
    busy: Option<&'a str>,
    circle: Option<Vec<[i64; 2]>>,
    circle_motors: Option<[u32; 2]>,
    events: Vec<&'a Event>,
    heartbeat_ms: u64,
    poll_ms: u64,
}

impl Board {
    pub(super) fn event(&mut self, level: &'static str, text: String) {
        let e = Event {
            id: self.next_event,
            level,
            text,
            t_ms: self.started.elapsed().as_millis() as u64,
        };
        self.next_event += 1;
        self.events.push_back(e);
        while self.events.len() > EVENTS_KEPT {
            self.events.pop_front();
        }
    }

    /// Publishes the state for the page.
    pub(super) fn publish(&mut self) {
        let conn = self.conn.as_ref();
        let motors = (0..MOTORS)
            .map(|m| {
                let st = conn.and_then(|c| c.status[m]);
                MotorView {
                    running: st.map(|s| s.running),
                    home0: st.map(|s| s.home0),
                    home1: st.map(|s| s.home1),
                    position: conn.map_or(0, |c| c.model.position(m)),
                    speed: conn.map_or(0.0, |c| (c.model.velocity(m) * 10.0).round() / 10.0),
                    manual: conn.and_then(|c| c.manual[m].map(|f| f.speed)),
                    params: conn.map_or(MotorParams::DEFAULT, |c| c.params[m]),
                }
            })
            .collect();
        let (link, link_message) = match &self.link {
            LinkState::None => ("none", None),
            LinkState::Ok => ("ok", None),
            LinkState::Silent => ("silent", None),
            LinkState::Lost(m) => ("lost", Some(m.as_str())),
        };
        let circle = conn.and_then(|c| c.circle.as_ref());
        let busy = self.shared.busy();
        let view = View {
            link,
            port: conn.map(|c| c.path.as_str()).or(self.last_port.as_deref()),
            firmware: conn.map(|c| format!("{}.{:02}", c.firmware / 100, c.firmware % 100)),
            link_message,
            last_answer_ms: conn.map(|c| c.last_answer.elapsed().as_millis() as u64),
            inputs: conn.and_then(|c| c.inputs),
            debounce: conn.map_or(1, |c| c.debounce),
            motors,
            busy: busy.as_deref(),
            circle: circle.map(|r| {
                r.plan
                    .points
                    .iter()
                    .map(|p| [r.start[0] + p[0], r.start[1] + p[1]])
                    .collect()
            }),
            circle_motors: circle.map(|r| [r.plan.x_motor, r.plan.y_motor]),
            events: self.events.iter().collect(),
            heartbeat_ms: HEARTBEAT_TIMEOUT.as_millis() as u64,
            poll_ms: POLL_PERIOD.as_millis() as u64,
        };
        let json = serde_json::to_string(&view).unwrap_or_else(|_| "{}".into());
        let params = conn.map_or([MotorParams::DEFAULT; MOTORS], |c| c.params);
        let may_move = conn.is_some_and(|c| {
            c.moved_since_poll
                || c.manual.iter().any(Option::is_some)
                || c.status.iter().any(|s| s.is_none_or(|s| s.running))
        });
        self.shared
            .publish(json, params, self.conn.is_some(), may_move);
    }
}
