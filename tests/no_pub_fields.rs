//! The core's state is changed by methods, never by a field set from outside: no struct
//! of the engine (`src/engine`) or the core crate (`crates/core/src`) has a field the
//! C layer could reach (`pub`, and in the engine also `pub(crate)`), except plain
//! values, which keep no invariant and which the C layer is meant to fill or read as a
//! whole (a configuration, a snapshot, a settings record, a planned command's
//! description): [`VALUES`], each with why.
//!
//! The compiler does the rest: the engine's other fields are `pub(in crate::engine)` or
//! private, the core's `pub(crate)` or private, so the C entry points cannot set them.

#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;

use std::collections::BTreeMap;
use std::path::Path;

/// Plain values: their fields are their meaning.
const VALUES: &[(&str, &str)] = &[
    (
        "Settings",
        "a group's motion settings, captured by every queued command",
    ),
    (
        "GroupSnapshot",
        "what a status call reads, published each tick",
    ),
    ("Info", "the part of a snapshot that seldom changes"),
    ("Motion", "the part of a snapshot that changes every tick"),
    ("View", "the panel's copy of the cards"),
    ("CardView", "one card in the panel's copy"),
    ("ChannelView", "one channel in the panel's copy"),
    ("GroupView", "one group in the panel's copy"),
    (
        "Step",
        "a step of a go-home program, or a custom motion's step result",
    ),
    (
        "RtSettings",
        "the engine thread's real-time settings, read from the environment",
    ),
    ("Ctx", "what planning a command reads"),
    ("AxisMech", "an axis's mechanism facts"),
    ("InPosSettings", "the in-position settings a program sets"),
    ("HomeTick", "what a go-home tick did"),
    ("AxisOut", "what a go-home tick did to one axis"),
    (
        "Registration",
        "the kinematics functions a program registers",
    ),
    ("KinFns", "the kinematics functions of a group"),
    (
        "CustomSpec",
        "the callbacks of a custom motion and their settings",
    ),
    ("Blending", "the blending callbacks of a custom motion"),
    (
        "CustomBatch",
        "the calls the custom stage makes for a group",
    ),
    ("Trip", "the result of a safety check"),
    ("Command", "a planned command as queued"),
    (
        "TickCtx",
        "what a tick is told of time and the program's settings",
    ),
    ("SimConfig", "the simulated machine's configuration file"),
    ("CardSim", "one card of the configuration file"),
    ("ChannelSim", "one channel of the configuration file"),
    (
        "RioSlaveSim",
        "one remote I/O slave of the configuration file",
    ),
    ("Config", "what the program configures before init"),
    ("GroupDef", "a group's mapping and queue size"),
    ("ChannelSpec", "what the configuration says of a channel"),
    (
        "CardSettings",
        "the card settings the simulation keeps and reports",
    ),
    ("SensorLevels", "three sensor levels"),
    ("TrigOut", "one trigger-out point's settings"),
    ("Fired", "what a trigger tick raised"),
    ("DeferredSteps", "the period and number of deferred steps"),
    ("Pending", "interrupt causes as data"),
    ("PathMove", "a planned path motion"),
];

/// Per struct name: its fields visible outside its crate's private parts (`pub`, and
/// `pub(crate)` when `crate_wide` counts), with the file.
fn open_fields(dir: &Path, crate_wide: bool, out: &mut BTreeMap<String, (String, Vec<String>)>) {
    for f in support::rust_files(dir) {
        let name = f
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if name.starts_with("tests") || f.components().any(|c| c.as_os_str() == "tests") {
            continue;
        }
        let text = code_of(&std::fs::read_to_string(&f).expect("read a source file"));
        let mut current: Option<String> = None;
        for line in text.lines() {
            let t = line.trim_start();
            if let Some(rest) = t
                .strip_prefix("pub struct ")
                .or_else(|| t.strip_prefix("pub(crate) struct "))
                .or_else(|| t.strip_prefix("pub(super) struct "))
                .or_else(|| t.strip_prefix("pub(in crate::engine) struct "))
                .or_else(|| t.strip_prefix("struct "))
            {
                if line.ends_with('{') {
                    let n: String = rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    current = Some(n);
                }
                continue;
            }
            if line == "}" {
                current = None;
                continue;
            }
            let Some(s) = &current else { continue };
            let field = t.strip_prefix("pub ").or_else(|| {
                if crate_wide {
                    t.strip_prefix("pub(crate) ")
                } else {
                    None
                }
            });
            if let Some(field) = field {
                if let Some((n, _)) = field.split_once(':') {
                    if n.chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                    {
                        let e = out
                            .entry(s.clone())
                            .or_insert_with(|| (f.display().to_string(), Vec::new()));
                        e.1.push(n.to_string());
                    }
                }
            }
        }
    }
}

#[test]
fn only_plain_values_have_fields_the_c_layer_could_set() {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut open = BTreeMap::new();
    open_fields(&top.join("src/engine"), true, &mut open);
    open_fields(&top.join("crates/core/src"), false, &mut open);
    let values: Vec<&str> = VALUES.iter().map(|(n, _)| *n).collect();
    let unexpected: Vec<String> = open
        .iter()
        .filter(|(n, _)| !values.contains(&n.as_str()))
        .map(|(n, (f, fields))| format!("{n} ({f}): {}", fields.join(", ")))
        .collect();
    assert!(
        unexpected.is_empty(),
        "types with fields outside code can set (give them methods): {unexpected:#?}"
    );
    // Every listed value still has open fields: a type given methods leaves the list.
    let stale: Vec<&&str> = values.iter().filter(|n| !open.contains_key(**n)).collect();
    assert!(
        stale.is_empty(),
        "no open field any more, take them off VALUES: {stale:?}"
    );
}
