//! cbindgen's view of the crate: its declarations (typedefs, defines, structs) and
//! function prototypes, and the pieces of it each header takes.

use crate::vendor::{parse_proto, Proto};
use std::path::Path;

/// cbindgen's output, split into declarations and function prototypes.
pub struct Raw {
    /// Everything but the prototypes (typedefs, defines, structs), cbindgen's order.
    pub decls: String,
    /// Its function prototypes.
    pub protos: Vec<Proto>,
    /// The vendor types in the order MCCL.h declares them (cbindgen.toml, `[export]
    /// include`).
    pub type_order: Vec<String>,
}

pub fn run_cbindgen(root: &Path) -> Result<Raw, String> {
    let cfg = cbindgen::Config::from_file(root.join("cbindgen.toml"))?;
    let type_order = cfg.export.include.clone();
    let bindings = cbindgen::Builder::new()
        .with_crate(root)
        .with_config(cfg)
        .generate()
        .map_err(|e| format!("cbindgen: {e}"))?;
    let mut out = Vec::new();
    bindings.write(&mut out);
    let text = String::from_utf8(out).map_err(|e| e.to_string())?;
    let mut decls = String::new();
    let mut protos = Vec::new();
    for line in text.lines() {
        let is_proto = line.ends_with(");")
            && !line.starts_with("typedef")
            && !line.starts_with('#')
            && !line.starts_with(' ');
        if is_proto {
            protos.push(parse_proto(line)?);
        } else if !line.starts_with("#include") {
            decls.push_str(line);
            decls.push('\n');
        }
    }
    Ok(Raw {
        decls,
        protos,
        type_order,
    })
}

/// The `typedef struct { ... } MCCL_*;` blocks of cbindgen's output (the simulation
/// extension's structs, which go into MCCL_Sim.h), each as its lines.
pub fn sim_structs(decls: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut block: Option<String> = None;
    for line in decls.lines() {
        if line.starts_with("typedef struct") && line.ends_with('{') {
            block = Some(String::new());
        }
        if let Some(b) = block.as_mut() {
            b.push_str(line);
            b.push('\n');
            if line.starts_with('}') {
                if line.starts_with("} MCCL_") {
                    out.push(b.clone());
                }
                block = None;
            }
        }
    }
    out
}

/// `decls` without the blocks of [`sim_structs`].
pub fn without_sim_structs(decls: &str) -> String {
    let mut text = decls.to_string();
    for b in sim_structs(decls) {
        text = text.replace(&b, "");
    }
    text
}

/// `typedef struct X X;`
pub fn is_opaque_typedef(line: &str) -> bool {
    let Some(rest) = line.strip_prefix("typedef struct ") else {
        return false;
    };
    let mut it = rest.trim_end_matches(';').split_whitespace();
    matches!((it.next(), it.next(), it.next()), (Some(a), Some(b), None) if a == b)
}

/// `#define NAME -1` becomes `#define NAME (-1)`, so `x-NAME` cannot turn into `x--1`.
pub fn negative_define(line: &str) -> Option<String> {
    let rest = line.strip_prefix("#define ")?;
    let (name, value) = rest.split_once(' ')?;
    let value = value.trim();
    if value.starts_with('-') && value[1..].chars().all(|c| c.is_ascii_digit()) {
        Some(format!("#define {name} ({value})"))
    } else {
        None
    }
}
