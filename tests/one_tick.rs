//! One definition of a tick: the steps of a card's tick are called from `Shared::tick`
//! alone (`src/engine/tick.rs`), so a fast path (a cruise tick, `engine/cruise.rs`) is
//! that function with steps left out by its plan, never a second copy of the sequence
//! that a change could miss. What a cruise tick leaves out is checked to change nothing
//! a program sees by `engine_cruise`.

#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;

use std::path::Path;

/// The steps of a tick, as called: a group's period, its channels commanded, the
/// machine's channels stepped or deferred, the peripherals, the publication.
const STEPS: &[&str] = &[
    ".cruise_period(",
    ".command_channels(",
    "defer_idle_card(",
    ".step_commanded(",
    ".tick_peripherals(",
    ".set_deferred(",
    ".publish_motion(",
    ".tick_homing(",
    ".safety(",
];

/// The lines of `text` outside comments and unit tests that call `step`.
fn calls(text: &str, step: &str) -> usize {
    code_of(text).lines().filter(|l| l.contains(step)).count()
}

#[test]
fn the_steps_of_a_tick_are_called_from_the_tick_alone() {
    let engine = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/engine");
    let mut elsewhere = Vec::new();
    let mut in_tick = Vec::new();
    for f in support::rust_files(&engine) {
        let text = std::fs::read_to_string(&f).expect("read a source file");
        let name = f
            .strip_prefix(&engine)
            .expect("under src/engine")
            .display()
            .to_string();
        for step in STEPS {
            let n = calls(&text, step);
            if name == "tick.rs" {
                in_tick.extend(std::iter::repeat_n(*step, n));
            } else if n > 0 {
                elsewhere.push(format!("{name}: {step} ({n})"));
            }
        }
    }
    assert!(
        elsewhere.is_empty(),
        "a tick's steps called outside tick.rs: {elsewhere:#?}"
    );
    for step in STEPS {
        assert!(
            in_tick.contains(step),
            "the tick no longer calls {step}: update STEPS"
        );
    }
}
