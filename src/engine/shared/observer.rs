//! Publishing what an observer (the browser panel) sees of the shared state.

use crate::config::GROUPS;
use crate::engine::view::*;
use crate::machine::Machine;
use std::sync::atomic::Ordering;

impl crate::engine::Shared {
    /// At the end of a tick whose start found a copy [due](ViewCell::due) (machine
    /// locked by the caller, every channel up to date): copies the view.
    pub(in crate::engine) fn publish_view(
        &self,
        machine: &Machine,
        running: &[crate::engine::group::GroupState],
    ) {
        let cards = (0..self.cards())
            .map(|cd| self.card_view(machine, cd))
            .collect();
        let mut groups = vec![None; GROUPS];
        for st in running {
            if let Some(g) = groups.get_mut(st.index()) {
                *g = Some(GroupView {
                    override_pct: st.override_pct(),
                    inpos: st.inpos_status(),
                });
            }
        }
        let v = View {
            ticks: self.clock.ticks() + 1,
            made: true,
            home_status: crate::engine::homing::home_status_read(
                self.home.home_status.load(Ordering::Acquire),
            ),
            cards,
            groups,
        };
        self.view.offer(v);
    }

    fn card_view(&self, machine: &Machine, cd: usize) -> CardView {
        let mut v = CardView {
            emergency: machine.emergency(cd),
            ..Default::default()
        };
        for (ch, cv) in v.channels.iter_mut().enumerate() {
            if let Some(c) = machine.channel(cd, ch) {
                let l = c.levels();
                cv.inputs = [l.home, l.plus, l.minus];
                cv.raw = [
                    c.raw_level(crate::machine::Sensor::Home),
                    c.raw_level(crate::machine::Sensor::LimitPlus),
                    c.raw_level(crate::machine::Sensor::LimitMinus),
                ];
                cv.encoder = c.encoder();
                cv.motor = c.position();
                cv.pulses = c.output_pulses();
            }
            cv.led = machine.led_lit(cd, ch);
        }
        if let Some(p) = self.periph.get(cd) {
            let p = p.lock();
            let inputs = p.adc_inputs();
            for (ch, cv) in v.channels.iter_mut().enumerate() {
                cv.dac = p.dac().output(ch);
                cv.adc = [inputs[ch], p.adc().input(ch)];
            }
            v.adc_running = p.adc().converting();
            v.timer = (p.timer().enabled(), p.timer().period());
            v.watchdog = (
                p.watchdog().enabled(),
                p.watchdog().compare(),
                p.watchdog().count(),
                p.watchdog().resets(),
            );
            for s in 0..2 {
                for port in 0..4u16 {
                    let set = &p.remote_io().rio_sets()[s];
                    v.rio_in[s][usize::from(port)] = set.input(port).unwrap_or(0);
                    v.rio_out[s][usize::from(port)] = set.output(port).unwrap_or(0);
                }
            }
        }
        v
    }
}
