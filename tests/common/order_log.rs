//! Interrupt routines that log their calls, for the tests of the interrupt framework: one
//! routine per kind and card, each recording its card, its kind's letter and the bytes of
//! the struct it was passed, in the order of the calls.

use parking_lot::Mutex;
use MCCLPCI_IMP::vendor::{ADCINT, ENCINT, HSKINT, LIOINT, PCLINT, RIOINT, TMRINT};

/// Every call of the routines below: card, kind's letter, the struct's bytes.
pub static ORDER_LOG: Mutex<Vec<(u8, char, Vec<u8>)>> = Mutex::new(Vec::new());

/// An interrupt routine `$name` for structs `$t` that logs `($card, $tag, bytes)`.
macro_rules! order_cb {
    ($name:ident, $t:ty, $card:expr, $tag:expr) => {
        pub unsafe extern "system" fn $name(p: *mut $t) {
            // SAFETY: the library passes a valid struct for the call's duration.
            let s = unsafe { *p };
            let bytes = (0..std::mem::size_of::<$t>())
                // SAFETY: reading the struct's own bytes (all BYTE fields).
                .map(|i| unsafe { *(std::ptr::addr_of!(s) as *const u8).add(i) })
                .collect();
            ORDER_LOG.lock().push(($card, $tag, bytes));
        }
    };
}

order_cb!(lio_order0, LIOINT, 0, 'L');
order_cb!(enc_order0, ENCINT, 0, 'E');
order_cb!(pcl_order0, PCLINT, 0, 'P');
order_cb!(adc_order0, ADCINT, 0, 'A');
order_cb!(tmr_order0, TMRINT, 0, 'T');
order_cb!(rio_order0, RIOINT, 0, 'R');
order_cb!(hsk_order0, HSKINT, 0, 'H');
order_cb!(lio_order1, LIOINT, 1, 'L');
order_cb!(enc_order1, ENCINT, 1, 'E');
order_cb!(pcl_order1, PCLINT, 1, 'P');
order_cb!(adc_order1, ADCINT, 1, 'A');
order_cb!(tmr_order1, TMRINT, 1, 'T');
order_cb!(rio_order1, RIOINT, 1, 'R');
order_cb!(hsk_order1, HSKINT, 1, 'H');
