//! `MCCL_Sim.h`: an extension (not part of the vendor interface) that lets a test program
//! work the simulated machine at run time: press a limit switch or the emergency stop,
//! move a sensor, read what the card outputs and where the motor is. Every call checks
//! its arguments like the vendor functions.

use super::{card, channel, finite, with_machine_channel, Card, Channel, Out};
use crate::error::McclError;
use crate::machine::Sensor;
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;
use std::sync::atomic::Ordering;

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
        with_machine_channel(Channel(wChannel), Card(wCardIndex), |ch| {
            // A sensor where the channel could never count to is refused.
            let f = ch.factor();
            crate::config::range::position(a, f)?;
            crate::config::range::position(b, f)?;
            ch.place(s, a, b);
            Ok(())
        })?;
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
        let shared = system::active()?;
        let cd = shared.card(card(wCardIndex)?)?;
        shared.machine.lock().emergency[cd] = nLevel == 1;
        Ok(c::NO_ERR)
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
        // SAFETY: NULL or writable, as this function's contract requires.
        let pnValue = unsafe { Out::new(pnValue) }?;
        let shared = system::active()?;
        let cd = shared.card(cd)?;
        let v = match nOutput {
            MCCL_SIM_OUT_SERVO => {
                // A trigger-out on the point overrides it while active (1 = servo off).
                let trig = shared.machine.lock().triggers[cd].trig_level[ch.0];
                match trig {
                    Some(off) => !off,
                    None => shared.servo_on[cd].load(Ordering::Acquire) >> ch.0 & 1 == 1,
                }
            }
            MCCL_SIM_OUT_POS_READY => shared.pos_ready[cd].load(Ordering::Acquire),
            MCCL_SIM_OUT_LED => shared.machine.lock().led_lit(cd, ch.0),
            _ => return Err(McclError::Parameter),
        };
        pnValue.write(c_int::from(v));
        Ok(c::NO_ERR)
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
        // SAFETY: NULL or writable, as this function's contract requires.
        let pdfMs = unsafe { Out::new(pdfMs) }?;
        let shared = system::active()?;
        let ms = shared.clock.now_ns() as f64 / 1e6;
        pdfMs.write(ms);
        Ok(c::NO_ERR)
    }
}
