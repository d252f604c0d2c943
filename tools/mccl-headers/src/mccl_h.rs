//! `include/MCCL.h`: the vendor types, constants, structs and callback types of cbindgen's
//! output, in the vendor's order and spelling.

use crate::cbindgen::{is_opaque_typedef, negative_define, without_sim_structs, Raw};
use crate::BANNER;
use std::collections::HashSet;
use std::fmt::Write as _;
use std::path::Path;

/// The names `pub const` declares in a Rust file (the vendor constants).
pub fn rust_const_names(path: &Path) -> Result<HashSet<String>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub const "))
        .filter_map(|l| l.split(':').next())
        .map(|n| n.trim().to_string())
        .collect())
}

pub fn mccl_h(raw: &Raw, vendor_consts: &HashSet<String>) -> Result<String, String> {
    // Only vendor constants go into MCCL.h (others are crate internals), and every vendor
    // constant must be there.
    let mut seen = HashSet::new();
    let mut kept = String::new();
    for line in without_sim_structs(&raw.decls).lines() {
        if let Some(rest) = line.strip_prefix("#define ") {
            let name = rest.split_whitespace().next().unwrap_or_default();
            if !vendor_consts.contains(name) {
                continue;
            }
            seen.insert(name.to_string());
        }
        // Opaque forward declarations are crate internals cbindgen saw in passing; every
        // vendor type is a complete struct.
        if is_opaque_typedef(line) {
            continue;
        }
        kept.push_str(line);
        kept.push('\n');
    }
    let mut missing: Vec<&String> = vendor_consts.difference(&seen).collect();
    missing.sort();
    if !missing.is_empty() {
        return Err(format!(
            "vendor constants cbindgen did not emit: {missing:?}"
        ));
    }
    // Callback typedefs get the vendor's MCC_CALLBACK calling-convention macro.
    let mut body = String::new();
    for line in kept.lines() {
        if line.starts_with("typedef") && line.contains("(*") {
            body.push_str(&line.replacen("(*", "(MCC_CALLBACK *", 1));
        } else if let Some(neg) = negative_define(line) {
            body.push_str(&neg);
        } else {
            body.push_str(line);
        }
        body.push('\n');
    }
    let body = in_type_order(&collapse_blank_lines(&body), &raw.type_order)?;
    let body = posture_by_reference(&body);
    let body = windows_base_types(&body)?;
    Ok(format!(
        "{BANNER}/* MCCL.h: types, constants and structures of the IMP-series motion control command\n * library (MCCLPCI_IMP), reproduced by libMCCLPCI_IMP. */\n#ifndef MCCL_H_LIBMCCLPCI_IMP\n#define MCCL_H_LIBMCCLPCI_IMP\n\n#include <stdint.h>\n#if defined(_WIN32)\n#include <windows.h>\n#endif\n\n#ifndef MCC_CALLBACK\n#if defined(_WIN32)\n#define MCC_CALLBACK __stdcall\n#else\n#define MCC_CALLBACK\n#endif\n#endif\n\n#define MULTI_CARD_SUPPORT\n\n/* The manuals declare interrupt routines `void _stdcall f(ENCINT *)`: on Windows MSVC's\n * spelling of __stdcall (which GCC in strict ISO mode does not know), on other systems\n * than Windows a calling convention keyword that means nothing. */\n#if defined(_WIN32)\n#ifndef _stdcall\n#define _stdcall __stdcall\n#endif\n#else\n#ifndef _stdcall\n#define _stdcall\n#endif\n#ifndef __stdcall\n#define __stdcall\n#endif\n#endif\n\n{}\n#endif /* MCCL_H_LIBMCCLPCI_IMP */\n",
        body.trim()
    ))
}

/// The kinematics callbacks (`FWDKINEFUN`, `INVKINEFUN`) take the posture as the vendor's
/// header declares it, a C++ reference `DWORD &dwPosture`, so that a C++ program whose
/// callbacks are written for the vendor's header converts to the callback type; C has no
/// references and keeps the pointer, `DWORD *dwPosture` (the same ABI: a reference is
/// passed as the address). cbindgen writes the pointer form; each typedef with it becomes
/// an `#ifdef __cplusplus` pair.
pub fn posture_by_reference(body: &str) -> String {
    const C_FORM: &str = "DWORD *dwPosture";
    let mut out = String::new();
    for line in body.lines() {
        if line.starts_with("typedef") && line.contains(C_FORM) {
            let cpp = line.replace(C_FORM, "DWORD &dwPosture");
            let _ = write!(out, "#ifdef __cplusplus\n{cpp}\n#else\n{line}\n#endif\n");
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// The four base types as cbindgen declares them, in the order of cbindgen.toml.
const BASE_TYPES: &str =
    "typedef uint16_t WORD;\n\ntypedef uint8_t BYTE;\n\ntypedef uint32_t DWORD;\n\ntypedef int BOOL;";

/// `body` with the base types taken from `<windows.h>` on Windows, as the vendor's header
/// does: a program that includes `<windows.h>` as well (most Windows programs do) then
/// sees one definition of each instead of a conflicting one (`DWORD` is `unsigned long`
/// there, 32 bits like `uint32_t` but another type to a C compiler).
pub fn windows_base_types(body: &str) -> Result<String, String> {
    if !body.contains(BASE_TYPES) {
        return Err(format!(
            "MCCL.h: the base types are not declared as expected:\n{BASE_TYPES}"
        ));
    }
    Ok(body.replacen(
        BASE_TYPES,
        &format!(
            "/* On Windows the base types are those of <windows.h> (included above), as in the\n * vendor's header. */\n#if !defined(_WIN32)\n{BASE_TYPES}\n#endif"
        ),
        1,
    ))
}

/// The name a type declaration block declares: `typedef ... NAME;`, `typedef struct {
/// ... } NAME;` or `typedef R (MCC_CALLBACK *NAME)(...);`; `None` for other blocks.
fn declared_type(block: &str) -> Option<String> {
    let first = block.lines().next()?;
    if !first.starts_with("typedef") {
        return None;
    }
    if let Some(rest) = first.split_once("(MCC_CALLBACK *").map(|(_, r)| r) {
        return rest.split(')').next().map(str::to_string);
    }
    let last = block.trim_end().strip_suffix(';')?;
    let name: String = last
        .chars()
        .rev()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    Some(name.chars().rev().collect())
}

/// `body` with its type declarations in `order`, each in the place of one of them (the
/// defines stay where cbindgen put them). cbindgen declares a type where the first
/// function using it makes it need one, so its order follows the Rust sources (and misses
/// the `extern "system"` entry points, which it does not read); MCCL.h instead
/// declares the vendor types in one fixed order, each after the types it uses. A type
/// missing from `order` is an error.
pub fn in_type_order(body: &str, order: &[String]) -> Result<String, String> {
    let blocks: Vec<&str> = body.split("\n\n").collect();
    let mut typed: Vec<(usize, &str)> = Vec::new();
    for b in &blocks {
        if let Some(name) = declared_type(b) {
            let rank = order.iter().position(|n| *n == name).ok_or_else(|| {
                format!(
                    "{name}: a type MCCL.h declares is missing from cbindgen.toml [export] include"
                )
            })?;
            typed.push((rank, b));
        }
    }
    typed.sort_by_key(|(rank, _)| *rank);
    let mut sorted = typed.into_iter().map(|(_, b)| b);
    let out: Vec<&str> = blocks
        .iter()
        .map(|b| match declared_type(b) {
            Some(_) => sorted.next().unwrap_or(b),
            None => b,
        })
        .collect();
    Ok(out.join("\n\n"))
}

pub fn collapse_blank_lines(s: &str) -> String {
    let mut out = String::new();
    let mut blank = 0;
    for line in s.lines() {
        if line.trim().is_empty() {
            blank += 1;
            if blank > 1 {
                continue;
            }
        } else {
            blank = 0;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}
