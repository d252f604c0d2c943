//! Trajectory planning controls (user manual §2.6.3; INTERFACE.md "Trajectory Planning").

use super::guard;
use crate::system;
use crate::vendor::DWORD;

/// Waits `dwTime` ms in the card's time: real time under the realtime clock, virtual time
/// under the fast and stepped clocks (the card runs while the program waits). Before
/// `MCC_InitSystem` it sleeps in real time.
#[no_mangle]
pub extern "C" fn MCC_TimeDelay(dwTime: DWORD) {
    guard(|| {
        match system::active() {
            Ok(shared) => shared.clock.delay_ms(dwTime),
            Err(_) => std::thread::sleep(std::time::Duration::from_millis(u64::from(dwTime))),
        }
        Ok(())
    })
}
