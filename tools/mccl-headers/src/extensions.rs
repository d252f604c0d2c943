//! The headers beside the vendor's two: `mcl.h` (the MC3B library), `MCCL_Sim.h` (the
//! simulation extension) and `mccl.h` (the lower-case name the vendor's header includes).

use crate::cbindgen::{negative_define, sim_structs, Raw};
use crate::vendor::render;
use crate::BANNER;
use std::fmt::Write as _;

/// `include/mcl.h`: the MC3B motor control library (MC3B User's Guide §4): its status
/// codes (`MCL_*`, named here; the guide only numbers them) and the `mcl_*` functions.
pub fn mcl_h(raw: &Raw) -> String {
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

/// C++ default arguments of the MC3B library (MC3B User's Guide §4.6 and §4.16).
const MCL_DEFAULTS: &[(&str, &str, &str)] = &[
    ("mcl_set_motor_maximum_velocity", "direction_modifier", "0"),
    ("mcl_synchronous_move_motor", "execute", "true"),
];

/// `include/MCCL_Sim.h`: the simulation extension (`MCCL_Sim*` functions and their
/// `MCCL_SIM_*` constants); not part of the vendor interface.
pub fn mccl_sim_h(raw: &Raw) -> String {
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

pub fn mccl_lower_h() -> String {
    format!("{BANNER}/* mccl.h: the lower-case name the vendor's MCCL_Fun.h includes. */\n#ifndef MCCL_LOWER_H_LIBMCCLPCI_IMP\n#define MCCL_LOWER_H_LIBMCCLPCI_IMP\n#include \"MCCL.h\"\n#endif\n")
}
