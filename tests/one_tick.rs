//! One definition of a tick: the steps of a card's tick are called from the core's
//! `engine::tick::tick` alone (`crates/core/src/engine/tick.rs`), so a fast path (a
//! cruise tick) is that function with steps left out by its plan, never a second copy of
//! the sequence that a change could miss; the library's engine and the core's `Card`
//! both run that function. What the tick hands to its caller's hooks (the publication,
//! the go home, the peripherals) the library's engine does in its hooks alone
//! (`src/engine/tick.rs`). What a cruise tick leaves out is checked to change nothing a
//! program sees by `engine_cruise`.

#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;

use std::path::{Path, PathBuf};

/// The steps of a tick, as called: a group's period, its channels commanded (all, or
/// along a cruise plan's line the moving axes' alone), the machine's channels stepped or
/// deferred, the safety checks.
const STEPS: &[&str] = &[
    ".cruise_period(",
    ".command_channels(",
    ".command_moving_channels(",
    "defer_idle_card(",
    ".step_commanded(",
    ".set_deferred(",
    "safety::check_groups(",
];

/// What the engine's hooks do for the tick: the peripherals, the publication of a
/// cruising group, the go home.
const HOOKED: &[&str] = &[
    ".tick_peripherals(",
    ".publish_cruise_motion(",
    ".tick_homing(",
];

/// Who runs a tick: the engine and the core's card.
const RUN: &str = "tick::<";

/// The lines of `text` outside comments and unit tests that call `step`.
fn calls(text: &str, step: &str) -> usize {
    code_of(text).lines().filter(|l| l.contains(step)).count()
}

/// Every source file of the engine, the library's and the core's, with its path from
/// the repository.
fn engine_files() -> Vec<(String, String)> {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    for dir in ["src/engine", "crates/core/src/engine"] {
        for f in support::rust_files(&top.join(dir)) {
            let text = std::fs::read_to_string(&f).expect("read a source file");
            let name: PathBuf = f.strip_prefix(top).expect("under the repository").into();
            out.push((name.display().to_string(), text));
        }
    }
    out
}

/// The places each of `steps` is called from, outside `home`; fails unless `home` calls
/// every one of them.
fn called_only_from(steps: &[&str], home: &str) -> Vec<String> {
    let mut elsewhere = Vec::new();
    let mut at_home = Vec::new();
    for (name, text) in engine_files() {
        for step in steps {
            let n = calls(&text, step);
            if name == home {
                at_home.extend(std::iter::repeat_n(*step, n));
            } else if n > 0 {
                elsewhere.push(format!("{name}: {step} ({n})"));
            }
        }
    }
    for step in steps {
        assert!(
            at_home.contains(step),
            "{home} no longer calls {step}: update the list"
        );
    }
    elsewhere
}

#[test]
fn the_steps_of_a_tick_are_called_from_the_tick_alone() {
    let elsewhere = called_only_from(STEPS, "crates/core/src/engine/tick.rs");
    assert!(
        elsewhere.is_empty(),
        "a tick's steps called outside the core's tick: {elsewhere:#?}"
    );
    let elsewhere = called_only_from(HOOKED, "src/engine/tick.rs");
    assert!(
        elsewhere.is_empty(),
        "the engine's hooks called outside its tick: {elsewhere:#?}"
    );
}

#[test]
fn the_engine_and_the_card_run_the_same_tick() {
    let runners: Vec<String> = engine_files()
        .into_iter()
        .filter(|(_, text)| calls(text, RUN) > 0)
        .map(|(name, _)| name)
        .collect();
    assert_eq!(
        runners,
        ["src/engine/tick.rs", "crates/core/src/engine/card.rs"],
        "who runs the core's tick"
    );
}
