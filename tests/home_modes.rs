//! `MCC_SetHomeConfig` checks the go-home parameters as the vendor's library does
//! (recorded scenario `home_config_before_init`): modes 0..19 are kept (the manual
//! describes 3..16), 20 and above refused; direction and sensor mode 0/1; acc/dec times
//! and speeds above 0. A refused configuration leaves the one set before. `MCC_Home`
//! runs only the modes the manual describes: a channel set to another mode makes it
//! `PARAMETER_ERR`, and nothing moves.

mod common;

use common::{fresh, init_ms};
use std::os::raw::c_long;
use MCCLPCI_IMP::ffi::coordinate::MCC_GetPulsePos;
use MCCLPCI_IMP::ffi::home::{MCC_GetGoHomeStatus, MCC_Home};
use MCCLPCI_IMP::ffi::system::{MCC_GetHomeConfig, MCC_SetHomeConfig};
use MCCLPCI_IMP::ffi::trajectory::MCC_TimeDelay;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::SYS_HOME_CONFIG;

/// A good configuration (the manual's §2.4.3 example) with mode `mode`.
fn cfg(mode: u16) -> SYS_HOME_CONFIG {
    SYS_HOME_CONFIG {
        wMode: mode,
        wDirection: 1,
        wSensorMode: SL_NORMAL_OPEN,
        nIndexCount: 0,
        dfAccTime: 300.0,
        dfDecTime: 300.0,
        dfHighSpeed: 10.0,
        dfLowSpeed: 2.0,
        dfOffset: 0.0,
        ..Default::default()
    }
}

fn set(mut h: SYS_HOME_CONFIG, ch: u16) -> i32 {
    // SAFETY: a valid pointer.
    unsafe { MCC_SetHomeConfig(&mut h, ch, 0) }
}

fn get(ch: u16) -> SYS_HOME_CONFIG {
    let mut h = SYS_HOME_CONFIG::default();
    // SAFETY: a valid pointer.
    assert_eq!(unsafe { MCC_GetHomeConfig(&mut h, ch, 0) }, NO_ERR);
    h
}

#[test]
fn modes_0_to_19_are_kept_the_rest_refused() {
    let _g = fresh();
    for m in 0..=19u16 {
        assert_eq!(set(cfg(m), 0), NO_ERR, "mode {m}");
        assert_eq!(get(0).wMode, m);
    }
    for m in [20u16, 0x7FFF, 0xFFFE, 0xFFFF] {
        assert_eq!(set(cfg(m), 0), PARAMETER_ERR, "mode {m}");
        assert_eq!(get(0).wMode, 19, "unchanged after mode {m}");
    }
}

#[test]
fn other_fields_as_the_vendor_checks_them() {
    let _g = fresh();
    let base = cfg(5);
    let refused = [
        SYS_HOME_CONFIG {
            wDirection: 2,
            ..base
        },
        SYS_HOME_CONFIG {
            wSensorMode: SL_UNUSED,
            ..base
        },
        SYS_HOME_CONFIG {
            nIndexCount: -1,
            ..base
        },
        SYS_HOME_CONFIG {
            dfAccTime: 0.0,
            ..base
        },
        SYS_HOME_CONFIG {
            dfDecTime: 0.0,
            ..base
        },
        SYS_HOME_CONFIG {
            dfDecTime: -1.0,
            ..base
        },
        SYS_HOME_CONFIG {
            dfHighSpeed: 0.0,
            ..base
        },
        SYS_HOME_CONFIG {
            dfLowSpeed: 0.0,
            ..base
        },
    ];
    assert_eq!(set(base, 0), NO_ERR);
    for (n, h) in refused.into_iter().enumerate() {
        assert_eq!(set(h, 0), PARAMETER_ERR, "case {n}");
        assert_eq!(get(0), base, "case {n} changed nothing");
    }
    // Accepted: a dec time of half a millisecond, a low speed above the high one, a
    // sensor normally closed.
    for h in [
        SYS_HOME_CONFIG {
            dfDecTime: 0.5,
            ..base
        },
        SYS_HOME_CONFIG {
            dfLowSpeed: 20.0,
            ..base
        },
        SYS_HOME_CONFIG {
            wSensorMode: SL_NORMAL_CLOSE,
            ..base
        },
    ] {
        assert_eq!(set(h, 0), NO_ERR);
        assert_eq!(get(0), h);
    }
}

fn pulses() -> [c_long; 8] {
    let mut p: [c_long; 8] = [0; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCC_GetPulsePos(a, b, c, d, e, f, g, h, 0) };
    assert_eq!(r, NO_ERR);
    p
}

#[test]
fn home_refuses_a_mode_the_manual_does_not_describe() {
    let _g = fresh();
    assert_eq!(set(cfg(17), 0), NO_ERR);
    assert_eq!(set(cfg(3), 1), NO_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    let before = pulses();
    let status = MCC_GetGoHomeStatus();
    // Channel 0 (mode 17) homed: refused, nothing starts.
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_GetGoHomeStatus(), status, "no homing started");
    MCC_TimeDelay(50);
    assert_eq!(pulses(), before);
    // Channel 0 left out: channel 1 (mode 3) homes.
    assert_eq!(MCC_Home(255, 0, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(MCC_GetGoHomeStatus(), 0, "homing");
}
