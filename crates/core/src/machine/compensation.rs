//! Gear backlash and gap compensation (user manual §2.7.5): forward and backward tables of
//! pulse corrections at points `dwInterval` pulses apart, point `wHome_No` at the home
//! position; the table follows the direction of motion, and between points the correction
//! is linear, truncated to whole pulses. The manual's example: interval 10000, home at
//! point 4, forward table ..., `[5] = 10`, `[6] = 12`: a move of +15000 pulses sends
//! 15000 + 10 + (int)(5000 / 10000 x 2) = 15011 pulses.

use crate::vendor::SYS_COMP_PARAM;

/// Parameters that turn compensation off (interval 0).
pub fn off() -> SYS_COMP_PARAM {
    SYS_COMP_PARAM {
        dwInterval: 0,
        wHome_No: 0,
        wPaddle: 0,
        nForwardTable: [0; 256],
        nBackwardTable: [0; 256],
    }
}

/// Compensation tables in effect for one channel (none: interval 0).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Compensation {
    interval: i64,
    home: usize,
    forward: Vec<i32>,
    backward: Vec<i32>,
    /// Direction of the last motion: true forward (the table in use).
    forward_dir: bool,
    last_cmd: i64,
}

impl Compensation {
    /// Tables from `MCC_SetCompParam` (interval 0 turns compensation off).
    pub fn new(p: &SYS_COMP_PARAM) -> Compensation {
        Compensation {
            interval: i64::from(p.dwInterval),
            home: usize::from(p.wHome_No).min(p.nForwardTable.len() - 1),
            forward: p.nForwardTable.to_vec(),
            backward: p.nBackwardTable.to_vec(),
            forward_dir: true,
            last_cmd: 0,
        }
    }

    /// Whether compensation is on.
    #[inline]
    pub fn active(&self) -> bool {
        self.interval > 0
    }

    /// The correction (pulses) to add to command position `cmd` (pulses from home).
    pub fn offset(&mut self, cmd: i64) -> i64 {
        if !self.active() {
            return 0;
        }
        if cmd > self.last_cmd {
            self.forward_dir = true;
        } else if cmd < self.last_cmd {
            self.forward_dir = false;
        }
        self.last_cmd = cmd;
        let table = if self.forward_dir {
            &self.forward
        } else {
            &self.backward
        };
        let last = table.len() as i64 - 1;
        // Point index of the segment start and the distance into the segment.
        let rel = cmd.div_euclid(self.interval);
        let into = cmd.rem_euclid(self.interval);
        let k = self.home as i64 + rel;
        if k < 0 {
            return i64::from(table[0]);
        }
        if k >= last {
            return i64::from(table[last as usize]);
        }
        let (a, b) = (
            i64::from(table[k as usize]),
            i64::from(table[k as usize + 1]),
        );
        // The straight line between the two points, rounded to the nearest pulse (halves
        // up), as the vendor's library counts (measured: 5.5 pulses into a segment from
        // 0 to 11 and from 11 to 0 both count 6).
        let x = (a * self.interval + into * (b - a)) as f64 / self.interval as f64;
        (x + 0.5).floor() as i64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn manual_example() -> SYS_COMP_PARAM {
        let mut p = SYS_COMP_PARAM {
            dwInterval: 10000,
            wHome_No: 4,
            wPaddle: 0,
            nForwardTable: [0; 256],
            nBackwardTable: [0; 256],
        };
        p.nForwardTable[..8].copy_from_slice(&[22, 20, 15, 11, 0, 10, 12, 15]);
        p
    }

    #[test]
    fn the_manuals_example_sends_15011_pulses() {
        let mut c = Compensation::new(&manual_example());
        assert_eq!(15000 + c.offset(15000), 15011);
    }

    #[test]
    fn points_segments_and_ends() {
        let mut c = Compensation::new(&manual_example());
        assert_eq!(c.offset(0), 0, "home point");
        assert_eq!(c.offset(10000), 10, "point 5");
        // Halves round up, as the vendor's library counts (scenario `compensation`).
        assert_eq!(c.offset(25000), 14, "12 + 5000/10000 x 3 = 13.5 -> 14");
        assert_eq!(c.offset(30000), 15, "point 7");
        // Past the measured points the table holds zeros (the manual: the table must
        // cover the whole travel): 15 + 5000/10000 x -15 = 7.5 -> 8.
        assert_eq!(c.offset(35000), 8);
        assert_eq!(c.offset(10_000_000), 0, "beyond point 255: the last entry");
        // Moving back uses the backward table (all zero here).
        assert_eq!(c.offset(20000), 0);
        let mut off = Compensation::new(&SYS_COMP_PARAM {
            dwInterval: 0,
            ..manual_example()
        });
        assert_eq!(off.offset(15000), 0, "interval 0: off");
    }

    #[test]
    fn below_home_interpolates_downwards() {
        let mut c = Compensation::new(&manual_example());
        // Forward table, point 3 (-10000) = 11, point 4 = 0: at -5000: 11 + 5000/10000 x -11 = 5.5 -> 5
        c.offset(-20000);
        c.offset(-5000); // moving forward from -20000
        assert_eq!(c.offset(-5000), 11 + (5000 * (0 - 11)) / 10000);
    }
}
