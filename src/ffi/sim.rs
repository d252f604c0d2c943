//! `MCCL_Sim.h`: an extension (not part of the vendor interface) that lets a test program
//! work the simulated machine at run time: press a limit switch or the emergency stop,
//! move a sensor, read what the card outputs and where the motor is. Every call checks
//! its arguments like the vendor functions.

use super::{
    card, channel, finite, with_machine, with_machine_channel, write_out, Card, Channel, Out,
};
use crate::error::McclError;
use crate::machine::Sensor;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Sensor numbers of `MCCL_SimSetSensor` and `MCCL_SimPlaceSensor`.
pub const MCCL_SIM_HOME: c_int = 0;
/// The + limit switch.
pub const MCCL_SIM_LIMIT_PLUS: c_int = 1;
/// The − limit switch.
pub const MCCL_SIM_LIMIT_MINUS: c_int = 2;
/// `nLevel` of `MCCL_SimSetSensor`: the sensor follows the motor's position again.
pub const MCCL_SIM_FOLLOW: c_int = -1;

/// Output numbers of `MCCL_SimGetOutput`: servo-on of the channel.
pub const MCCL_SIM_OUT_SERVO: c_int = 0;
/// The card's position-ready output.
pub const MCCL_SIM_OUT_POS_READY: c_int = 1;
/// The channel's LED output.
pub const MCCL_SIM_OUT_LED: c_int = 2;

fn sensor(n: c_int) -> Result<Sensor, McclError> {
    match n {
        MCCL_SIM_HOME => Ok(Sensor::Home),
        MCCL_SIM_LIMIT_PLUS => Ok(Sensor::LimitPlus),
        MCCL_SIM_LIMIT_MINUS => Ok(Sensor::LimitMinus),
        _ => Err(McclError::Parameter),
    }
}

/// Sets the physical level of a sensor (`MCCL_SIM_HOME`, `MCCL_SIM_LIMIT_PLUS`,
/// `MCCL_SIM_LIMIT_MINUS`): 1 hit (a normally-open switch closes), 0 not hit,
/// `MCCL_SIM_FOLLOW` (-1) back to following the motor's position.
#[no_mangle]
pub extern "C" fn MCCL_SimSetSensor(
    wCardIndex: WORD,
    wChannel: WORD,
    nSensor: c_int,
    nLevel: c_int,
) -> c_int {
    ffi_boundary! {
        let s = sensor(nSensor)?;
        let level = match nLevel {
            MCCL_SIM_FOLLOW => None,
            0 => Some(false),
            1 => Some(true),
            _ => return Err(McclError::Parameter),
        };
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            ch.force(s, level);
            Ok(())
        })?;
        Ok(c::NO_ERR)
    }
}

/// Places a sensor at machine position (UU): the home sensor's active region is
/// [dfFrom, dfTo]; a limit switch is at dfFrom (dfTo ignored). Both must be positions of
/// the channel (|x| x pulses per UU <= 1e15).
#[no_mangle]
pub extern "C" fn MCCL_SimPlaceSensor(
    wCardIndex: WORD,
    wChannel: WORD,
    nSensor: c_int,
    dfFrom: f64,
    dfTo: f64,
) -> c_int {
    ffi_boundary! {
        let s = sensor(nSensor)?;
        let (a, b) = (finite(dfFrom)?, finite(dfTo)?);
        if s == Sensor::Home && a > b {
            return Err(McclError::Parameter);
        }
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| ch.place_sensor(s, a, b))?;
        Ok(c::NO_ERR)
    }
}

/// Presses (1) or releases (0) the card's emergency-stop input.
#[no_mangle]
pub extern "C" fn MCCL_SimSetEmergencyStop(wCardIndex: WORD, nLevel: c_int) -> c_int {
    ffi_boundary! {
        if nLevel != 0 && nLevel != 1 {
            return Err(McclError::Parameter);
        }
        with_machine(Card(wCardIndex), |m, cd| {
            m.set_emergency(cd, nLevel == 1);
            Ok(c::NO_ERR)
        })
    }
}

/// Reads an output of the card: `MCCL_SIM_OUT_SERVO` (of the channel),
/// `MCCL_SIM_OUT_POS_READY` (of the card), `MCCL_SIM_OUT_LED` (of the channel): 1 on.
///
/// # Safety
/// `pnValue` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCCL_SimGetOutput(
    wCardIndex: WORD,
    wChannel: WORD,
    nOutput: c_int,
    pnValue: *mut c_int,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (card(wCardIndex)?, channel(wChannel)?);
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pnValue, || {
                let shared = system::active()?;
                let cd = shared.card(cd)?;
                let v = match nOutput {
                    MCCL_SIM_OUT_SERVO => {
                        let bits = shared.servo_on(cd);
                        shared.lock_machine().servo_output(cd, ch.0, bits)
                    }
                    MCCL_SIM_OUT_POS_READY => shared.pos_ready(cd),
                    MCCL_SIM_OUT_LED => shared.lock_machine().led_lit(cd, ch.0),
                    _ => return Err(McclError::Parameter),
                };
                Ok(c_int::from(v))
            })
        }
    }
}

/// Where the motor of a channel is: machine position in UU, and pulses output so far.
///
/// # Safety
/// Both pointers must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCCL_SimGetMotor(
    wCardIndex: WORD,
    wChannel: WORD,
    pdfPosition: *mut f64,
    pllPulses: *mut std::os::raw::c_longlong,
) -> c_int {
    ffi_boundary! {
        // SAFETY: NULL or writable, as this function's contract requires.
        let pdfPosition = unsafe { Out::new(pdfPosition) }?;
        // SAFETY: NULL or writable, as this function's contract requires.
        let pllPulses = unsafe { Out::new(pllPulses) }?;
        let (p, n) = with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            Ok((ch.position(), ch.output_pulses()))
        })?;
        pdfPosition.write(p);
        pllPulses.write(n);
        Ok(c::NO_ERR)
    }
}

/// Virtual time since `MCC_InitSystem`, ms (ticks x interpolation period).
///
/// # Safety
/// `pdfMs` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCCL_SimGetTime(pdfMs: *mut f64) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { write_out(pdfMs, || Ok(system::active()?.clock().now_ns() as f64 / 1e6)) }
    }
}

/// Number of lateness buckets in [`MCCL_CLOCK_STATS`].
pub const MCCL_SIM_CLOCK_BUCKETS: usize = 16;

/// What the clock of the running system did (`MCCL_SimGetClockStats`). Lateness is how
/// long after its deadline (`start + n x period` on the monotonic clock) a realtime tick
/// started; under the `fast` and `stepped` clocks there are no deadlines and every
/// lateness field is 0. Percentiles are accurate to 1 µs below 64 µs and to 3 % above.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct MCCL_CLOCK_STATS {
    /// Ticks run since `MCC_InitSystem`.
    pub ullTicks: u64,
    /// Realtime ticks that started a period or more after their deadline (caught up).
    pub ullMissed: u64,
    /// Median lateness, µs.
    pub dfP50Us: f64,
    /// 99th percentile of the lateness, µs.
    pub dfP99Us: f64,
    /// 99.9th percentile of the lateness, µs.
    pub dfP999Us: f64,
    /// Largest lateness, µs.
    pub dfMaxUs: f64,
    /// Mean lateness, µs.
    pub dfMeanUs: f64,
    /// Realtime ticks by lateness: bucket 0 below 16 µs, bucket k (k = 1..14) from
    /// 2^(k+3) to below 2^(k+4) µs (16-32, 32-64, ..., 131072-262144), bucket 15 262144 µs
    /// or more.
    pub ullBucket: [u64; MCCL_SIM_CLOCK_BUCKETS],
}

/// The statistics of a clock (see [`MCCL_CLOCK_STATS`]).
pub fn clock_stats(clock: &crate::clock::Clock) -> MCCL_CLOCK_STATS {
    stats_of(clock.ticks(), clock.missed(), clock.lateness())
}

fn stats_of(
    ticks: u64,
    missed: u64,
    h: &crate::clock::latency::LatencyHistogram,
) -> MCCL_CLOCK_STATS {
    let mut st = MCCL_CLOCK_STATS {
        ullTicks: ticks,
        ullMissed: missed,
        dfP50Us: h.quantile_us(0.5),
        dfP99Us: h.quantile_us(0.99),
        dfP999Us: h.quantile_us(0.999),
        dfMaxUs: h.max_us(),
        dfMeanUs: h.mean_us(),
        ullBucket: [0; MCCL_SIM_CLOCK_BUCKETS],
    };
    for (k, b) in st.ullBucket.iter_mut().enumerate() {
        let lo = if k == 0 { 0 } else { 1u64 << (k + 3) };
        let hi = if k + 1 == MCCL_SIM_CLOCK_BUCKETS {
            u64::MAX
        } else {
            1u64 << (k + 4)
        };
        *b = h.count_between(lo, hi);
    }
    st
}

/// Reads what the clock of the running system did: ticks, missed ticks and how late
/// realtime ticks started (see `MCCL_CLOCK_STATS`). `INITIAL_MOTION_ERR` before
/// `MCC_InitSystem`.
///
/// # Safety
/// `pstStats` must be NULL (refused with `PARAMETER_ERR`) or point to a writable
/// `MCCL_CLOCK_STATS`.
#[no_mangle]
pub unsafe extern "C" fn MCCL_SimGetClockStats(pstStats: *mut MCCL_CLOCK_STATS) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { write_out(pstStats, || Ok(clock_stats(system::active()?.clock()))) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::system::MCC_CloseSystem;
    use crate::ffi::tests::{fresh, init_ms};
    use crate::ffi::trajectory::MCC_TimeDelay;
    use std::time::{Duration, Instant};

    #[test]
    fn clock_stats_checks_and_counts_under_a_virtual_clock() {
        let _g = fresh(); // stepped clock
        let mut st = MCCL_CLOCK_STATS::default();
        // SAFETY: a valid struct, and NULL (refused).
        unsafe {
            assert_eq!(MCCL_SimGetClockStats(&mut st), c::INITIAL_MOTION_ERR);
            assert_eq!(
                MCCL_SimGetClockStats(std::ptr::null_mut()),
                c::PARAMETER_ERR
            );
        }
        assert_eq!(init_ms(1, 2), c::NO_ERR);
        MCC_TimeDelay(7); // ceil(7 / 2) = 4 ticks
                          // SAFETY: a valid struct.
        assert_eq!(unsafe { MCCL_SimGetClockStats(&mut st) }, c::NO_ERR);
        // No deadlines under a virtual clock: 4 ticks, nothing late.
        assert_eq!(
            st,
            MCCL_CLOCK_STATS {
                ullTicks: 4,
                ..Default::default()
            }
        );
        assert_eq!(MCC_CloseSystem(), c::NO_ERR);
        assert_eq!(
            // SAFETY: a valid struct.
            unsafe { MCCL_SimGetClockStats(&mut st) },
            c::INITIAL_MOTION_ERR
        );
    }

    #[test]
    fn clock_stats_buckets_are_powers_of_two() {
        // 10 us -> [0] (< 16); 16 and 31 us -> [1] (16..32); 100 us -> [3] (64..128);
        // 300,000 us -> [15] (>= 262,144). p50 of 5 values = rank 3 = 31 us.
        let h = crate::clock::latency::LatencyHistogram::new();
        for us in [10u64, 16, 31, 100, 300_000] {
            h.record_ns(us * 1000);
        }
        let st = stats_of(7, 1, &h);
        let mut want = [0u64; MCCL_SIM_CLOCK_BUCKETS];
        want[0] = 1;
        want[1] = 2;
        want[3] = 1;
        want[15] = 1;
        assert_eq!(st.ullBucket, want);
        assert_eq!((st.ullTicks, st.ullMissed), (7, 1));
        assert_eq!(st.dfP50Us, 31.0);
        assert_eq!(st.dfMaxUs, 300_000.0);
        // mean = (10 + 16 + 31 + 100 + 300000) / 5 = 60031.4 us.
        assert!((st.dfMeanUs - 60_031.4).abs() < 1e-6, "{}", st.dfMeanUs);
    }

    #[test]
    fn clock_stats_count_realtime_ticks() {
        // Real time: only what holds on a loaded host is checked, and a clock that does
        // not tick fails after 10 s with a message instead of hanging.
        let _g = fresh();
        std::env::set_var("MCCL_CLOCK", "realtime");
        assert_eq!(init_ms(1, 1), c::NO_ERR);
        let shared = crate::system::active().unwrap();
        let t = Instant::now();
        while shared.clock().ticks() < 20 {
            assert!(
                t.elapsed() < Duration::from_secs(10),
                "the realtime clock ran {} ticks of 1 ms in 10 s",
                shared.clock().ticks()
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        let mut st = MCCL_CLOCK_STATS::default();
        // SAFETY: a valid struct.
        assert_eq!(unsafe { MCCL_SimGetClockStats(&mut st) }, c::NO_ERR);
        assert_eq!(MCC_CloseSystem(), c::NO_ERR);
        std::env::set_var("MCCL_CLOCK", "stepped");
        assert!(st.ullTicks >= 20, "{st:?}");
        // Every tick started counts its lateness (ticks are read first, so the
        // histogram holds at least as many).
        let counted: u64 = st.ullBucket.iter().sum();
        assert!(counted >= st.ullTicks, "{st:?}");
        assert!(st.ullMissed <= counted, "{st:?}");
        assert!(
            st.dfP50Us <= st.dfP99Us && st.dfP99Us <= st.dfP999Us,
            "{st:?}"
        );
        assert!(st.dfP999Us <= st.dfMaxUs, "{st:?}");
    }
}
