//! `include/MCCL_Fun.h`: the vendor table's prototypes with `MCC_API`/`MCC_CALL` and the
//! C++ default arguments, checked against what cbindgen sees.

use crate::cbindgen::Raw;
use crate::vendor::{check_against_vendor, render, Vendor};
use crate::BANNER;
use std::fmt::Write as _;

/// `include/MCCL_Fun.h`: every prototype of the vendor table, in its section order, with the
/// vendor's C++ default arguments.
///
/// The prototypes come from the table, not from cbindgen: cbindgen does not read the
/// `extern "system"` entry points (every `MCC_*` is one: stdcall on 32-bit Windows), and
/// the generated `tests/vendor_prototypes.rs` makes the compiler check every Rust signature
/// against the table instead. The functions cbindgen does see are still checked here, and
/// an exported function that belongs in no header is an error.
pub fn mccl_fun_h(raw: &Raw, vendor: &Vendor) -> Result<String, String> {
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
