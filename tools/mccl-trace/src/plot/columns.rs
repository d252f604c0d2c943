//! Decimation of a time panel's series for display.

/// Decimated time series of one panel: per pixel column, per series,
/// (first, min, max, last).
pub(super) struct Columns {
    pub(super) n: usize,
    pub(super) t0: f64,
    pub(super) t1: f64,
    pub(super) series: Vec<Vec<Option<[f64; 4]>>>,
}

impl Columns {
    pub(super) fn new(n: usize, series: usize, t0: f64, t1: f64) -> Columns {
        Columns {
            n,
            t0,
            t1,
            series: vec![vec![None; n]; series],
        }
    }

    pub(super) fn push(&mut self, t: f64, s: usize, v: f64) {
        let f = if self.t1 > self.t0 {
            (t - self.t0) / (self.t1 - self.t0)
        } else {
            0.0
        };
        let c = ((f * self.n as f64) as usize).min(self.n - 1);
        let cell = &mut self.series[s][c];
        match cell {
            None => *cell = Some([v, v, v, v]),
            Some(a) => {
                a[1] = a[1].min(v);
                a[2] = a[2].max(v);
                a[3] = v;
            }
        }
    }
}
