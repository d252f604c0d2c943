//! Fault injection for the library's own tests: a named point where a test can make the
//! code panic, to check that a panic leaves a defined state (see `ffi::guard`). Outside
//! `cfg(test)` a point compiles to nothing.

#[cfg(test)]
static ARMED: parking_lot::Mutex<Option<&'static str>> = parking_lot::Mutex::new(None);

/// Panics here if a test armed the point `name` (once); otherwise does nothing.
#[inline(always)]
pub fn point(name: &'static str) {
    #[cfg(test)]
    {
        let mut armed = ARMED.lock();
        if *armed == Some(name) {
            *armed = None;
            drop(armed);
            panic!("injected fault at {name}");
        }
    }
    #[cfg(not(test))]
    let _ = name;
}

/// Arms the point `name`: the next pass through it panics.
#[cfg(test)]
pub fn arm(name: &'static str) {
    *ARMED.lock() = Some(name);
}

/// Whether the armed point has fired (or none was armed).
#[cfg(test)]
pub fn fired() -> bool {
    ARMED.lock().is_none()
}
