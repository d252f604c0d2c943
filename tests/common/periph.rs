//! What the peripheral tests read of the running system: a card's peripherals (to read,
//! or to change as the simulated hardware would), a group's status and its X position.

use MCCLPCI_IMP::card::Peripherals;
use MCCLPCI_IMP::ffi::coordinate::MCC_GetCurPos;
use MCCLPCI_IMP::vendor::consts::NO_ERR;

/// A copy of card `card`'s peripherals as they are now.
pub fn periph(card: usize) -> Peripherals {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .periph(card)
        .unwrap()
        .lock()
        .clone()
}

/// Runs `f` on card `card`'s peripherals, under their lock (as the simulated hardware
/// changes them).
pub fn with_periph<R>(card: usize, f: impl FnOnce(&mut Peripherals) -> R) -> R {
    f(&mut MCCLPCI_IMP::system::active()
        .unwrap()
        .periph(card)
        .unwrap()
        .lock())
}

/// Group `g`'s motion status, from the snapshot of the last tick.
pub fn status(g: u16) -> i32 {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(g)
        .unwrap()
        .status
}

/// Group `g`'s X position (`MCC_GetCurPos`, which must succeed).
pub fn x_pos(g: u16) -> f64 {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, g) }, NO_ERR);
    p[0]
}
