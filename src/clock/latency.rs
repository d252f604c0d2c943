//! A lock-free histogram of lateness (how long after its deadline something happened).
//!
//! The engine thread records one value per realtime tick; any thread reads it at any
//! time. Recording is a few relaxed atomic adds: no lock, no allocation, no system call.
//!
//! Resolution: 1 µs below 64 µs, then 32 buckets per power of two (a bucket is at most
//! 1/32 ≈ 3 % of its value wide), up to 2³² µs (71 minutes); later values count in the
//! last bucket. The maximum is kept exactly.

use std::sync::atomic::{AtomicU64, Ordering};

/// Values below this many µs have a bucket of their own (1 µs wide).
const LINEAR: u64 = 64;
/// Buckets per power of two above [`LINEAR`].
const SUB: u64 = 32;
/// log2(LINEAR).
const LINEAR_BITS: u32 = 6;
/// Powers of two covered above [`LINEAR`]: 2^6 .. 2^32 µs.
const OCTAVES: u64 = 26;
/// Number of buckets.
pub const BUCKETS: usize = (LINEAR + OCTAVES * SUB) as usize;

/// The bucket of a value in µs.
fn bucket(us: u64) -> usize {
    if us < LINEAR {
        return us as usize;
    }
    let octave = u64::from(63 - us.leading_zeros()); // floor(log2(us)) >= 6
    if octave >= u64::from(LINEAR_BITS) + OCTAVES {
        return BUCKETS - 1;
    }
    let sub = (us >> (octave - 5)) & (SUB - 1);
    (LINEAR + (octave - u64::from(LINEAR_BITS)) * SUB + sub) as usize
}

/// The smallest value (µs) that falls in bucket `i`.
fn bucket_floor(i: usize) -> u64 {
    let i = i as u64;
    if i < LINEAR {
        return i;
    }
    let octave = (i - LINEAR) / SUB + u64::from(LINEAR_BITS);
    let sub = (i - LINEAR) % SUB;
    (1 << octave) + (sub << (octave - 5))
}

/// Lateness counts (see the module documentation).
#[derive(Debug)]
pub struct LatencyHistogram {
    counts: Box<[AtomicU64]>,
    n: AtomicU64,
    sum_ns: AtomicU64,
    max_ns: AtomicU64,
}

impl Default for LatencyHistogram {
    fn default() -> Self {
        LatencyHistogram::new()
    }
}

impl LatencyHistogram {
    /// An empty histogram.
    pub fn new() -> LatencyHistogram {
        LatencyHistogram {
            counts: (0..BUCKETS).map(|_| AtomicU64::new(0)).collect(),
            n: AtomicU64::new(0),
            sum_ns: AtomicU64::new(0),
            max_ns: AtomicU64::new(0),
        }
    }

    /// Counts one lateness of `ns` nanoseconds.
    pub fn record_ns(&self, ns: u64) {
        self.counts[bucket(ns / 1000)].fetch_add(1, Ordering::Relaxed);
        self.n.fetch_add(1, Ordering::Relaxed);
        self.sum_ns.fetch_add(ns, Ordering::Relaxed);
        self.max_ns.fetch_max(ns, Ordering::Relaxed);
    }

    /// Adds every count of `other` to this one.
    pub fn merge(&self, other: &LatencyHistogram) {
        for (a, b) in self.counts.iter().zip(other.counts.iter()) {
            a.fetch_add(b.load(Ordering::Relaxed), Ordering::Relaxed);
        }
        self.n
            .fetch_add(other.n.load(Ordering::Relaxed), Ordering::Relaxed);
        self.sum_ns
            .fetch_add(other.sum_ns.load(Ordering::Relaxed), Ordering::Relaxed);
        self.max_ns
            .fetch_max(other.max_ns.load(Ordering::Relaxed), Ordering::Relaxed);
    }

    /// A copy of the counts as they are now.
    pub fn snapshot(&self) -> LatencyHistogram {
        let h = LatencyHistogram::new();
        h.merge(self);
        h
    }

    /// Adds what `now` counted since `then` (an earlier [`LatencyHistogram::snapshot`]
    /// of it). The maximum of that interval is known to its bucket only: the floor of
    /// the highest bucket that grew (exact below 64 µs, within 3 % above).
    pub fn merge_since(&self, now: &LatencyHistogram, then: &LatencyHistogram) {
        let mut top = None;
        for (i, ((a, b), c)) in self
            .counts
            .iter()
            .zip(now.counts.iter())
            .zip(then.counts.iter())
            .enumerate()
        {
            let d = b
                .load(Ordering::Relaxed)
                .saturating_sub(c.load(Ordering::Relaxed));
            if d > 0 {
                a.fetch_add(d, Ordering::Relaxed);
                top = Some(i);
            }
        }
        let n = now.count().saturating_sub(then.count());
        self.n.fetch_add(n, Ordering::Relaxed);
        let sum = now
            .sum_ns
            .load(Ordering::Relaxed)
            .saturating_sub(then.sum_ns.load(Ordering::Relaxed));
        self.sum_ns.fetch_add(sum, Ordering::Relaxed);
        if let Some(i) = top {
            self.max_ns
                .fetch_max(bucket_floor(i).saturating_mul(1000), Ordering::Relaxed);
        }
    }

    /// Values counted.
    pub fn count(&self) -> u64 {
        self.n.load(Ordering::Relaxed)
    }

    /// The largest value, µs.
    pub fn max_us(&self) -> f64 {
        self.max_ns.load(Ordering::Relaxed) as f64 / 1000.0
    }

    /// The mean, µs (0 when empty).
    pub fn mean_us(&self) -> f64 {
        let n = self.count();
        if n == 0 {
            return 0.0;
        }
        self.sum_ns.load(Ordering::Relaxed) as f64 / n as f64 / 1000.0
    }

    /// The `q` quantile (0..=1), µs: the lower edge of the bucket holding the value of
    /// rank ceil(q × n), never above the maximum; 0 when empty.
    pub fn quantile_us(&self, q: f64) -> f64 {
        let n = self.count();
        if n == 0 {
            return 0.0;
        }
        let rank = ((q.clamp(0.0, 1.0) * n as f64).ceil() as u64).max(1);
        let mut seen = 0;
        for (i, c) in self.counts.iter().enumerate() {
            seen += c.load(Ordering::Relaxed);
            if seen >= rank {
                return (bucket_floor(i) as f64).min(self.max_us());
            }
        }
        self.max_us()
    }

    /// Counts of values in [`lo_us`, `hi_us`) µs (`hi_us` = `u64::MAX`: no upper bound),
    /// summed over whole buckets: exact when both bounds are powers of two or below 64.
    pub fn count_between(&self, lo_us: u64, hi_us: u64) -> u64 {
        self.counts
            .iter()
            .enumerate()
            .filter(|(i, _)| {
                let f = bucket_floor(*i);
                f >= lo_us && f < hi_us
            })
            .map(|(_, c)| c.load(Ordering::Relaxed))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn buckets_are_contiguous_and_narrow() {
        // Every bucket starts where the previous one ended, and is at most 1/32 of its
        // floor wide above 64 µs (2^k / 32 for the octave [2^k, 2^(k+1))).
        for i in 1..BUCKETS {
            assert!(bucket_floor(i) > bucket_floor(i - 1), "{i}");
            assert_eq!(bucket(bucket_floor(i)), i, "{i}");
            assert_eq!(bucket(bucket_floor(i) - 1), i - 1, "{i}");
        }
        assert_eq!(bucket_floor(64), 64);
        assert_eq!(bucket_floor(65), 66); // 64 + 1 x 2
        assert_eq!(bucket_floor(96), 128);
        assert_eq!(bucket(u64::MAX / 1000), BUCKETS - 1);
    }

    #[test]
    fn quantiles_of_known_values() {
        // 1000 values: 10 µs x 900, 100 µs x 90, 1000 µs x 9, 5000 µs x 1.
        // p50 and p90 (rank 500, 900) are 10; p99 (rank 990) is 100, whose bucket is
        // [100, 102) (octave 64..128, 2 µs wide); p99.9 (rank 999) is 1000, bucket
        // floor 992 (octave 512..1024, 16 µs wide: 512 + 30 x 16); max exactly 5000.
        let h = LatencyHistogram::new();
        for (us, k) in [(10u64, 900), (100, 90), (1000, 9), (5000, 1)] {
            for _ in 0..k {
                h.record_ns(us * 1000);
            }
        }
        assert_eq!(h.count(), 1000);
        assert_eq!(h.quantile_us(0.5), 10.0);
        assert_eq!(h.quantile_us(0.9), 10.0);
        assert_eq!(h.quantile_us(0.99), 100.0);
        assert_eq!(h.quantile_us(0.999), 992.0);
        assert_eq!(h.quantile_us(1.0), 4992.0_f64.min(5000.0));
        assert_eq!(h.max_us(), 5000.0);
        // mean = (9000 + 9000 + 9000 + 5000) / 1000 = 32 µs.
        assert_eq!(h.mean_us(), 32.0);
        assert_eq!(h.count_between(0, 16), 900);
        assert_eq!(h.count_between(64, 128), 90);
        assert_eq!(h.count_between(4096, u64::MAX), 1);
        let g = LatencyHistogram::new();
        g.merge(&h);
        g.merge(&h);
        // What came after a snapshot: 3 values of 20 us and one of 700 us (bucket
        // [688, 704): 512 + 11 x 16).
        let then = h.snapshot();
        for us in [20u64, 20, 20, 700] {
            h.record_ns(us * 1000);
        }
        let d = LatencyHistogram::new();
        d.merge_since(&h, &then);
        assert_eq!(d.count(), 4);
        assert_eq!(d.count_between(0, 64), 3);
        assert_eq!(d.max_us(), 688.0);
        assert_eq!(d.mean_us(), 190.0); // (60 + 700) / 4
        assert_eq!(g.count(), 2000);
        assert_eq!(g.quantile_us(0.99), 100.0);
        assert_eq!(g.max_us(), 5000.0);
    }
}
