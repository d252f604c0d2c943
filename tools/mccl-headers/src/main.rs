//! Generates the C headers of libMCCLPCI_IMP from the Rust sources.
//!
//! cbindgen reads the crate (vendor types, constants, `#[no_mangle] extern "C"` functions:
//! `mcl_*` and `MCCL_Sim*`; the `MCC_*` entry points are `extern "system"`, which cbindgen
//! skips, and the vendor table gives their prototypes);
//! this program then adds what cbindgen cannot express and writes:
//!
//! * `include/MCCL.h`      typedefs, constants, structs and ISR callback types;
//! * `include/MCCL_Fun.h`  the `MCC_*` prototypes of `vendor_prototypes.txt` with
//!   `MCC_API`/`MCC_CALL` and the vendor's C++ default arguments (visible to C++ only), in
//!   the vendor header's section order;
//! * `include/mccl.h`      the lower-case name the vendor's MCCL_Fun.h includes;
//! * `include/mcl.h`       the MC3B motor control library (`mcl_*`, MC3B User's Guide §4);
//! * `include/MCCL_Sim.h`  the simulation extension (`MCCL_Sim*`);
//! * `tests/vendor_prototypes.rs` a Rust test that binds every function of the vendor table
//!   to the function-pointer type its prototype spells, so the compiler checks each Rust
//!   signature against the table.
//!
//! `MCCL_Fun.h` is written from the vendor table rather than from cbindgen's output because
//! cbindgen does not read `extern "system"` functions, and every `MCC_*` entry point is
//! one. The generated test covers every one: a wrong parameter type, count, return type or
//! calling convention, or a table function the crate does not export, fails to compile. An
//! `extern "C"` `MCC_*` function, which cbindgen does see, is still checked against the
//! table here (return type, parameter count, types and names), and every `#define` against
//! the vendor constants of `crates/core/src/vendor/consts.rs`. `--check` compares instead of writing
//! and fails on drift.

use std::collections::{BTreeSet, HashSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// One parameter of a prototype.
#[derive(Debug, Clone, PartialEq)]
struct Param {
    /// Type tokens, e.g. `["SYS_MAC_PARAM", "*"]`.
    ty: Vec<String>,
    name: String,
    default: Option<String>,
}

/// One function prototype.
#[derive(Debug, Clone)]
struct Proto {
    ret: String,
    name: String,
    params: Vec<Param>,
}

/// Splits a C declaration into tokens, with `*` and `&` as tokens of their own.
fn tokens(s: &str) -> Vec<String> {
    s.replace('*', " * ")
        .replace('&', " & ")
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

fn parse_param(p: &str) -> Result<Param, String> {
    let (decl, default) = match p.split_once('=') {
        Some((d, v)) => (d, Some(v.trim().to_string())),
        None => (p, None),
    };
    let mut t = tokens(decl);
    let name = t.pop().ok_or_else(|| format!("empty parameter in {p:?}"))?;
    if t.is_empty() {
        return Err(format!("parameter without a type: {p:?}"));
    }
    Ok(Param {
        ty: t,
        name,
        default,
    })
}

/// Parses `ret name(params)` (a trailing `;` is allowed).
fn parse_proto(line: &str) -> Result<Proto, String> {
    let line = line.trim().trim_end_matches(';');
    let open = line
        .find('(')
        .ok_or_else(|| format!("no '(' in {line:?}"))?;
    let close = line
        .rfind(')')
        .ok_or_else(|| format!("no ')' in {line:?}"))?;
    let mut head = tokens(&line[..open]);
    let name = head.pop().ok_or_else(|| format!("no name in {line:?}"))?;
    let ret = head.join(" ");
    let inner = line[open + 1..close].trim();
    let params = if inner.is_empty() || inner == "void" {
        Vec::new()
    } else {
        inner
            .split(',')
            .map(parse_param)
            .collect::<Result<_, _>>()?
    };
    Ok(Proto { ret, name, params })
}

/// The vendor prototype table: sections in order, each with its prototypes.
struct Vendor {
    sections: Vec<(String, Vec<Proto>)>,
}

impl Vendor {
    fn load(path: &Path) -> Result<Vendor, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let mut sections: Vec<(String, Vec<Proto>)> = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if let Some(s) = line.strip_prefix("# section:") {
                sections.push((s.trim().to_string(), Vec::new()));
            } else if line.is_empty() || line.starts_with('#') {
                continue;
            } else {
                let p =
                    parse_proto(line).map_err(|e| format!("{}:{}: {e}", path.display(), n + 1))?;
                match sections.last_mut() {
                    Some((_, v)) => v.push(p),
                    None => {
                        return Err(format!("{}: prototype before any section", path.display()))
                    }
                }
            }
        }
        Ok(Vendor { sections })
    }

    fn find(&self, name: &str) -> Option<&Proto> {
        self.sections
            .iter()
            .flat_map(|(_, v)| v.iter())
            .find(|p| p.name == name)
    }
}

/// The names `pub const` declares in a Rust file (the vendor constants).
fn rust_const_names(path: &Path) -> Result<HashSet<String>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub const "))
        .filter_map(|l| l.split(':').next())
        .map(|n| n.trim().to_string())
        .collect())
}

/// cbindgen's output, split into declarations and function prototypes.
struct Raw {
    /// Everything but the prototypes (typedefs, defines, structs), cbindgen's order.
    decls: String,
    protos: Vec<Proto>,
    /// The vendor types in the order MCCL.h declares them (cbindgen.toml, `[export]
    /// include`).
    type_order: Vec<String>,
}

fn run_cbindgen(root: &Path) -> Result<Raw, String> {
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

fn check_against_vendor(p: &Proto, v: &Proto) -> Result<(), String> {
    let same_types = p.params.len() == v.params.len()
        && p.params
            .iter()
            .zip(&v.params)
            .all(|(a, b)| a.ty == b.ty && a.name == b.name);
    if p.ret != v.ret || !same_types {
        return Err(format!(
            "{}: the Rust signature does not match the vendor prototype\n  rust:   {}\n  vendor: {}",
            p.name,
            render(p, None),
            render(v, None)
        ));
    }
    Ok(())
}

/// Renders a prototype; with `defaults`, appends `MCC_DEFAULT(v)` where the vendor has one.
fn render(p: &Proto, defaults: Option<&Proto>) -> String {
    let params: Vec<String> = p
        .params
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let mut s = String::new();
            for t in &a.ty {
                let ptr = t == "*" || t == "&";
                if !s.is_empty() && !(ptr && (s.ends_with('*') || s.ends_with('&'))) {
                    s.push(' ');
                }
                s.push_str(t);
            }
            if !(s.ends_with('*') || s.ends_with('&')) {
                s.push(' ');
            }
            s.push_str(&a.name);
            if let Some(d) = defaults
                .and_then(|v| v.params.get(i))
                .and_then(|v| v.default.as_ref())
            {
                let _ = write!(s, " MCC_DEFAULT({d})");
            }
            s
        })
        .collect();
    let params = if params.is_empty() {
        "void".to_string()
    } else {
        params.join(", ")
    };
    format!("{} {}({})", p.ret, p.name, params)
}

const BANNER: &str = "/* Generated by tools/mccl-headers from the Rust sources (cbindgen + vendor defaults).\n * Do not edit: run `cargo run -p mccl-headers` to regenerate. */\n";

fn mccl_h(raw: &Raw, vendor_consts: &HashSet<String>) -> Result<String, String> {
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
fn posture_by_reference(body: &str) -> String {
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
fn windows_base_types(body: &str) -> Result<String, String> {
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
/// the `extern "system"` functions, which it does not read); MCCL.h instead
/// declares the vendor types in one fixed order, each after the types it uses. A type
/// missing from `order` is an error.
fn in_type_order(body: &str, order: &[String]) -> Result<String, String> {
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

/// The `typedef struct { ... } MCCL_*;` blocks of cbindgen's output (the simulation
/// extension's structs, which go into MCCL_Sim.h), each as its lines.
fn sim_structs(decls: &str) -> Vec<String> {
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
fn without_sim_structs(decls: &str) -> String {
    let mut text = decls.to_string();
    for b in sim_structs(decls) {
        text = text.replace(&b, "");
    }
    text
}

/// `typedef struct X X;`
fn is_opaque_typedef(line: &str) -> bool {
    let Some(rest) = line.strip_prefix("typedef struct ") else {
        return false;
    };
    let mut it = rest.trim_end_matches(';').split_whitespace();
    matches!((it.next(), it.next(), it.next()), (Some(a), Some(b), None) if a == b)
}

/// `#define NAME -1` becomes `#define NAME (-1)`, so `x-NAME` cannot turn into `x--1`.
fn negative_define(line: &str) -> Option<String> {
    let rest = line.strip_prefix("#define ")?;
    let (name, value) = rest.split_once(' ')?;
    let value = value.trim();
    if value.starts_with('-') && value[1..].chars().all(|c| c.is_ascii_digit()) {
        Some(format!("#define {name} ({value})"))
    } else {
        None
    }
}

fn collapse_blank_lines(s: &str) -> String {
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

/// `include/MCCL_Fun.h`: every prototype of the vendor table, in its section order, with the
/// vendor's C++ default arguments.
///
/// The prototypes come from the table, not from cbindgen: an `extern "system"` entry point
/// is invisible to cbindgen, and the generated `tests/vendor_prototypes.rs` makes the
/// compiler check every Rust signature against the table instead. The functions cbindgen does see are still checked here, and
/// an exported function that belongs in no header is an error.
fn mccl_fun_h(raw: &Raw, vendor: &Vendor) -> Result<String, String> {
    for p in &raw.protos {
        if p.name.starts_with("mcl_") || p.name.starts_with("MCCL_Sim") {
            continue; // include/mcl.h, include/MCCL_Sim.h
        }
        if !p.name.starts_with("MCC_") {
            return Err(format!(
                "{}: exported function without a header to go in (MCC_* -> MCCL_Fun.h, mcl_* -> mcl.h, MCCL_Sim* -> MCCL_Sim.h)",
                p.name
            ));
        }
        let v = vendor
            .find(&p.name)
            .ok_or_else(|| format!("{}: not a vendor function (vendor_prototypes.txt)", p.name))?;
        check_against_vendor(p, v)?;
    }
    let mut out = String::new();
    out.push_str(BANNER);
    out.push_str(
        "/* MCCL_Fun.h: the functions of the IMP-series motion control command library that\n * libMCCLPCI_IMP implements. C++ callers get the vendor's default arguments. */\n#ifndef MCCL_FUN_H_LIBMCCLPCI_IMP\n#define MCCL_FUN_H_LIBMCCLPCI_IMP\n\n#include \"MCCL.h\"\n\n#ifndef MCC_CALL\n#if defined(_WIN32)\n#define MCC_CALL __stdcall\n#else\n#define MCC_CALL\n#endif\n#endif\n\n#ifndef MCC_API\n#if defined(_WIN32) && defined(MCCL_EXPORTS)\n#define MCC_API __declspec(dllexport)\n#elif defined(_WIN32)\n#define MCC_API __declspec(dllimport)\n#else\n#define MCC_API\n#endif\n#endif\n\n#ifdef __cplusplus\n#define MCC_DEFAULT(v) = v\nextern \"C\" {\n#else\n#define MCC_DEFAULT(v)\n#endif\n",
    );
    for (section, protos) in &vendor.sections {
        if protos.is_empty() {
            continue;
        }
        let _ = write!(out, "\n/* {section} */\n");
        for v in protos {
            let line = render(v, Some(v));
            let (ret, rest) = line.split_once(' ').unwrap_or(("", &line));
            let _ = writeln!(out, "MCC_API {ret} MCC_CALL {rest};");
        }
    }
    out.push_str("\n#ifdef __cplusplus\n} /* extern \"C\" */\n#endif\n\n#endif /* MCCL_FUN_H_LIBMCCLPCI_IMP */\n");
    Ok(out)
}

/// `include/mcl.h`: the MC3B motor control library (MC3B User's Guide §4): its status
/// codes (`MCL_*`, named here; the guide only numbers them) and the `mcl_*` functions.
fn mcl_h(raw: &Raw) -> String {
    let mut out = String::new();
    out.push_str(BANNER);
    out.push_str("/* mcl.h: the MC3B stepper controller's motor control library (MC3B User's Guide\n * section 4), exported by libMCCLPCI_IMP. Every function returns one of the MCL_* codes. */\n#ifndef MCL_H_LIBMCCLPCI_IMP\n#define MCL_H_LIBMCCLPCI_IMP\n\n");
    out.push_str("#ifdef __cplusplus\n#define MCL_DEFAULT(v) = v\n#else\n#include <stdbool.h>\n#define MCL_DEFAULT(v)\n#endif\n\n");
    for line in raw.decls.lines() {
        if line.starts_with("#define MCL_") {
            out.push_str(line);
            out.push('\n');
        }
    }
    out.push_str("\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    for p in raw.protos.iter().filter(|p| p.name.starts_with("mcl_")) {
        let mut line = render(p, None);
        // The guide's two C++ default arguments (§4.6, §4.16).
        for (f, arg, v) in MCL_DEFAULTS {
            if p.name == *f {
                line = line.replace(&format!(" {arg})"), &format!(" {arg} MCL_DEFAULT({v}))"));
            }
        }
        let _ = writeln!(out, "{line};");
    }
    out.push_str(
        "\n#ifdef __cplusplus\n} /* extern \"C\" */\n#endif\n\n#endif /* MCL_H_LIBMCCLPCI_IMP */\n",
    );
    out
}

/// `include/MCCL_Sim.h`: the simulation extension (`MCCL_Sim*` functions and their
/// `MCCL_SIM_*` constants); not part of the vendor interface.
fn mccl_sim_h(raw: &Raw) -> String {
    let mut out = String::new();
    out.push_str(BANNER);
    out.push_str("/* MCCL_Sim.h: work the simulated machine of libMCCLPCI_IMP at run time (press a limit\n * switch or the emergency stop, move a sensor, read outputs and the motor). An extension:\n * not part of the vendor's interface. Every function returns a vendor code (NO_ERR, ...). */\n#ifndef MCCL_SIM_H_LIBMCCLPCI_IMP\n#define MCCL_SIM_H_LIBMCCLPCI_IMP\n\n#include \"MCCL.h\"\n\n");
    for line in raw.decls.lines() {
        if line.starts_with("#define MCCL_SIM_") {
            out.push_str(&negative_define(line).unwrap_or_else(|| line.to_string()));
            out.push('\n');
        }
    }
    for b in sim_structs(&raw.decls) {
        out.push('\n');
        out.push_str(&b);
    }
    out.push_str("\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    for p in raw.protos.iter().filter(|p| p.name.starts_with("MCCL_Sim")) {
        let _ = writeln!(out, "{};", render(p, None));
    }
    out.push_str("\n#ifdef __cplusplus\n} /* extern \"C\" */\n#endif\n\n#endif /* MCCL_SIM_H_LIBMCCLPCI_IMP */\n");
    out
}

/// C++ default arguments of the MC3B library (MC3B User's Guide §4.6 and §4.16).
const MCL_DEFAULTS: &[(&str, &str, &str)] = &[
    ("mcl_set_motor_maximum_velocity", "direction_modifier", "0"),
    ("mcl_synchronous_move_motor", "execute", "true"),
];

fn mccl_lower_h() -> String {
    format!("{BANNER}/* mccl.h: the lower-case name the vendor's MCCL_Fun.h includes. */\n#ifndef MCCL_LOWER_H_LIBMCCLPCI_IMP\n#define MCCL_LOWER_H_LIBMCCLPCI_IMP\n#include \"MCCL.h\"\n#endif\n")
}

/// The Rust spelling of a vendor C type (`WORD *` -> `*mut WORD`), with the crate's names:
/// `std::os::raw` for C's integers, the vendor typedefs, structs and callback types of
/// `src/vendor` under their own names.
fn rust_type(ty: &[String]) -> Result<String, String> {
    let stars = ty.iter().rev().take_while(|t| *t == "*").count();
    let base = ty[..ty.len() - stars].join(" ");
    let base = match base.as_str() {
        "int" => "c_int",
        "double" => "f64",
        "float" => "f32",
        "char" => "c_char",
        "long" => "c_long",
        "long long" => "c_longlong",
        "void" if stars > 0 => "c_void",
        b if !b.is_empty() && b.chars().all(|c| c.is_ascii_uppercase() || c == '_') => b,
        _ => {
            return Err(format!(
                "no Rust spelling for the C type {:?}",
                ty.join(" ")
            ))
        }
    };
    Ok(format!("{}{base}", "*mut ".repeat(stars)))
}

/// The Rust function-pointer type a vendor prototype must have: `unsafe` when it takes a
/// pointer (the caller vouches for it), `extern "system"` (the vendor's `MCC_CALL`), no
/// return type for `void`.
fn rust_fn_type(v: &Proto) -> Result<String, String> {
    let params = v
        .params
        .iter()
        .map(|p| rust_type(&p.ty))
        .collect::<Result<Vec<_>, _>>()?;
    let unsafety = if v.params.iter().any(|p| p.ty.iter().any(|t| t == "*")) {
        "unsafe "
    } else {
        ""
    };
    let ret = match v.ret.as_str() {
        "void" => String::new(),
        r => format!(" -> {}", rust_type(&tokens(r))?),
    };
    Ok(format!(
        "{unsafety}extern \"system\" fn({}){ret}",
        params.join(", ")
    ))
}

/// The modules of `src/ffi` that declare entry points (not `mod.rs`, not the unit tests).
fn ffi_modules(root: &Path) -> Result<Vec<String>, String> {
    let dir = root.join("src/ffi");
    let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut out = Vec::new();
    for e in entries {
        let name = e.map_err(|e| e.to_string())?.file_name();
        let name = name.to_string_lossy();
        if let Some(m) = name.strip_suffix(".rs") {
            if m != "mod" && !m.starts_with("tests") {
                out.push(m.to_string());
            }
        }
    }
    out.sort();
    Ok(out)
}

/// `tests/vendor_prototypes.rs`: one typed binding per prototype of the vendor table, so the
/// compiler checks each entry point's Rust signature (parameter count, types, return type)
/// against the table. A function of the table that the crate does not export fails the
/// build too.
fn prototype_test(vendor: &Vendor, modules: &[String]) -> Result<String, String> {
    let mut names: BTreeSet<String> = BTreeSet::new();
    let mut body = String::new();
    let mut count = 0;
    for (section, protos) in &vendor.sections {
        if protos.is_empty() {
            continue;
        }
        let _ = writeln!(body, "    // {section}");
        for v in protos {
            let ty = rust_fn_type(v)?;
            // The type names the binding uses, for the generated `use` lines.
            let words = ty.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'));
            let is_type = |w: &&str| {
                !w.is_empty()
                    && *w != "C"
                    && (w.starts_with("c_")
                        || w.chars().all(|c| c.is_ascii_uppercase() || c == '_'))
            };
            names.extend(words.filter(is_type).map(str::to_string));
            let _ = writeln!(body, "    let _: {ty} = {};", v.name);
            count += 1;
        }
    }
    let (raw, crate_types): (Vec<String>, Vec<String>) =
        names.into_iter().partition(|n| n.starts_with("c_"));
    let mut out = String::new();
    out.push_str("//! Generated by tools/mccl-headers from tools/mccl-headers/vendor_prototypes.txt.\n//! Do not edit: run `cargo run -p mccl-headers` to regenerate.\n//!\n//! Every function of the vendor table, bound to the Rust function-pointer type its C\n//! prototype spells: this file compiles only if each entry point exists with exactly that\n//! parameter list and return type. The C header `MCCL_Fun.h` is written from the same\n//! table.\n\n// Every module of src/ffi is searched; some export no vendor function (the simulation\n// extension).\n#![allow(unused_imports)]\n\n");
    let _ = writeln!(out, "use std::os::raw::{{{}}};", raw.join(", "));
    for m in modules {
        let _ = writeln!(out, "use MCCLPCI_IMP::ffi::{m}::*;");
    }
    let _ = writeln!(
        out,
        "use MCCLPCI_IMP::vendor::{{{}}};",
        crate_types.join(", ")
    );
    let _ = write!(
        out,
        "\n/// The {count} prototypes of the vendor table (vendor_prototypes.txt), in its order.\n#[test]\nfn every_vendor_function_has_the_vendor_signature() {{\n{body}}}\n"
    );
    rustfmt(&out)
}

/// `text` as `cargo fmt` leaves it, so the generated test passes the format check as written.
fn rustfmt(text: &str) -> Result<String, String> {
    use std::io::Write as _;
    use std::process::{Command, Stdio};
    let mut child = Command::new("rustfmt")
        .args(["--edition", "2021"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .map_err(|e| format!("rustfmt: {e}"))?;
    child
        .stdin
        .take()
        .ok_or("rustfmt: no stdin")?
        .write_all(text.as_bytes())
        .map_err(|e| format!("rustfmt: {e}"))?;
    let out = child
        .wait_with_output()
        .map_err(|e| format!("rustfmt: {e}"))?;
    if !out.status.success() {
        return Err("rustfmt failed on the generated prototype test".to_string());
    }
    String::from_utf8(out.stdout).map_err(|e| format!("rustfmt: {e}"))
}

fn generate(root: &Path) -> Result<Vec<(PathBuf, String)>, String> {
    let here = root.join("tools/mccl-headers");
    let vendor = Vendor::load(&here.join("vendor_prototypes.txt"))?;
    let consts = rust_const_names(&root.join("crates/core/src/vendor/consts.rs"))?;
    let raw = run_cbindgen(root)?;
    let inc = root.join("include");
    Ok(vec![
        (inc.join("MCCL.h"), mccl_h(&raw, &consts)?),
        (inc.join("MCCL_Fun.h"), mccl_fun_h(&raw, &vendor)?),
        (inc.join("mccl.h"), mccl_lower_h()),
        (inc.join("mcl.h"), mcl_h(&raw)),
        (inc.join("MCCL_Sim.h"), mccl_sim_h(&raw)),
        (
            root.join("tests/vendor_prototypes.rs"),
            prototype_test(&vendor, &ffi_modules(root)?)?,
        ),
    ])
}

fn main() -> ExitCode {
    let check = std::env::args().any(|a| a == "--check");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap_or(root);
    let files = match generate(&root) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("mccl-headers: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut drift = false;
    for (path, text) in files {
        let old = std::fs::read_to_string(&path).unwrap_or_default();
        if old == text {
            continue;
        }
        if check {
            eprintln!(
                "mccl-headers: {} is out of date; run `cargo run -p mccl-headers` and commit it",
                path.display()
            );
            drift = true;
        } else {
            if let Some(dir) = path.parent() {
                if let Err(e) = std::fs::create_dir_all(dir) {
                    eprintln!("mccl-headers: {}: {e}", dir.display());
                    return ExitCode::FAILURE;
                }
            }
            if let Err(e) = std::fs::write(&path, text) {
                eprintln!("mccl-headers: {}: {e}", path.display());
                return ExitCode::FAILURE;
            }
            println!("wrote {}", path.display());
        }
    }
    if drift {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_defaults_and_pointers() {
        let p = parse_proto(
            "int MCC_SetMacParam(SYS_MAC_PARAM *pstMacParam, WORD wChannel, WORD wCardIndex = 0)",
        )
        .unwrap();
        assert_eq!(p.ret, "int");
        assert_eq!(p.params.len(), 3);
        assert_eq!(p.params[0].ty, vec!["SYS_MAC_PARAM", "*"]);
        assert_eq!(p.params[2].default.as_deref(), Some("0"));
        assert_eq!(
            render(&p, Some(&p)),
            "int MCC_SetMacParam(SYS_MAC_PARAM *pstMacParam, WORD wChannel, WORD wCardIndex MCC_DEFAULT(0))"
        );
        let q = parse_proto("double MCC_GetSysMaxSpeed(void);").unwrap();
        assert!(q.params.is_empty());
        assert_eq!(render(&q, None), "double MCC_GetSysMaxSpeed(void)");
    }

    #[test]
    fn mismatch_is_an_error() {
        let v = parse_proto("int MCC_CloseGroup(int nGroupIndex)").unwrap();
        let wrong_type = parse_proto("int MCC_CloseGroup(WORD nGroupIndex)").unwrap();
        let wrong_name = parse_proto("int MCC_CloseGroup(int nGroup)").unwrap();
        let wrong_ret = parse_proto("double MCC_CloseGroup(int nGroupIndex)").unwrap();
        let extra = parse_proto("int MCC_CloseGroup(int nGroupIndex, int x)").unwrap();
        for p in [wrong_type, wrong_name, wrong_ret, extra] {
            assert!(check_against_vendor(&p, &v).is_err(), "{p:?}");
        }
        assert!(check_against_vendor(&v, &v).is_ok());
    }

    #[test]
    fn rust_types_of_prototypes() {
        let p = |s| rust_fn_type(&parse_proto(s).unwrap()).unwrap();
        assert_eq!(
            p("int MCC_SetPGain(WORD wGain0, WORD wCardIndex = 0)"),
            "extern \"system\" fn(WORD, WORD) -> c_int"
        );
        assert_eq!(
            p("int MCC_GetPulsePos(long *plX, long long *plY, void *pv, char c)"),
            "unsafe extern \"system\" fn(*mut c_long, *mut c_longlong, *mut c_void, c_char) -> c_int"
        );
        assert_eq!(
            p("void MCC_GetVersion(char *strVersion)"),
            "unsafe extern \"system\" fn(*mut c_char)"
        );
        assert_eq!(
            p("double MCC_GetSysMaxSpeed()"),
            "extern \"system\" fn() -> f64"
        );
        assert!(rust_fn_type(&parse_proto("int f(unsigned short w)").unwrap()).is_err());
    }

    #[test]
    fn type_declarations_follow_the_given_order() {
        let body = "#define A 1\n\ntypedef struct {\n  T x;\n} S;\n\ntypedef uint16_t T;\n\ntypedef void (MCC_CALLBACK *F)(S *p);\n\n#define B 2";
        let order = ["T", "S", "F"].map(String::from);
        assert_eq!(
            in_type_order(body, &order).unwrap(),
            "#define A 1\n\ntypedef uint16_t T;\n\ntypedef struct {\n  T x;\n} S;\n\ntypedef void (MCC_CALLBACK *F)(S *p);\n\n#define B 2"
        );
        assert!(in_type_order(body, &order[..2]).is_err());
    }

    #[test]
    fn posture_is_a_reference_in_cpp_and_a_pointer_in_c() {
        let body = "typedef void (MCC_CALLBACK *G)(int n);\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD *dwPosture, void *p);\n";
        assert_eq!(
            posture_by_reference(body),
            "typedef void (MCC_CALLBACK *G)(int n);\n#ifdef __cplusplus\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD &dwPosture, void *p);\n#else\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD *dwPosture, void *p);\n#endif\n"
        );
    }

    #[test]
    fn vendor_table_has_all_344_plus_one() {
        let here = Path::new(env!("CARGO_MANIFEST_DIR"));
        let v = Vendor::load(&here.join("vendor_prototypes.txt")).unwrap();
        let n: usize = v.sections.iter().map(|(_, p)| p.len()).sum();
        assert_eq!(n, 345);
        let p = v.find("MCC_CreateGroupEx").unwrap();
        assert_eq!(p.params[9].default.as_deref(), Some("MOTION_QUEUE_SIZE"));
    }
}
