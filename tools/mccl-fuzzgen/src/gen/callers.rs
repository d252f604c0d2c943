//! The callers, one per function: each draws its arguments (canaries around every
//! pointer), logs them, makes the call and checks the result.

use crate::c::{c_ident, draw_prim, log_prim};
use crate::hint::{count, hint};
use crate::view::{Base, Codes, Model, Prim};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Writes `fz_call_F` for every function.
pub fn write(o: &mut String, m: &Model, cb_index: &BTreeMap<&String, usize>) -> Result<(), String> {
    // Callers: the log line starts with the name; each argument is logged as drawn.
    for (fi, f) in m.funcs.iter().enumerate() {
        let _ = writeln!(o, "\nstatic void fz_call_{}(fz_t *z)\n{{", f.name);
        let _ = writeln!(o, "    fz_begin(z, {fi});");
        let mut args = Vec::new();
        let mut finite_checks = Vec::new();
        for (k, d) in f.params.iter().enumerate() {
            let a = format!("a{k}");
            args.push(a.clone());
            let pname = if d.name.is_empty() {
                format!("arg{k}")
            } else {
                d.name.clone()
            };
            match (&d.base, d.ptr) {
                (Base::Prim(p), 0) => {
                    let _ = writeln!(o, "    {} {a};", d.cty);
                    draw_prim(o, &a, &d.cty, *p, hint(&f.name, &pname, *p));
                    let _ = writeln!(o, "    {};", log_prim(*p, &pname, &a));
                    if matches!(p, Prim::F32 | Prim::F64) {
                        let _ = writeln!(o, "    fz_arg_real(z, (double){a});");
                    }
                }
                (Base::Callback(cb), 0) => {
                    let _ = writeln!(
                        o,
                        "    {} {a} = ({})fz_callback(z, {});",
                        d.cty, d.cty, cb_index[cb]
                    );
                    let _ = writeln!(o, "    fz_log_cb(z, \"{pname}\", (void (*)(void)){a});");
                }
                (base, 1) => {
                    let elem = if d.cbase == "void" {
                        "1".to_string()
                    } else {
                        format!("sizeof({})", d.cbase)
                    };
                    let n = count(d);
                    let _ = writeln!(o, "    unsigned char *{a}_b = fz_ptr(z, {k}, {elem}, {n});");
                    let _ = writeln!(o, "    fz_log_p(z, \"{pname}\", {k});");
                    // Fill through an aligned temporary (the buffer may be misaligned).
                    match base {
                        Base::Struct(s) => {
                            let s_id = c_ident(s);
                            let _ = writeln!(
                                o,
                                "    if ({a}_b) for (int i = 0; i < {n}; i++) {{\n        {cb} t; fz_fill_{s_id}(z, &t); memcpy({a}_b + i * sizeof t, &t, sizeof t);\n        if (i == 0) {{ fz_log_raw(z, \"{{\"); fz_show_{s_id}(z, &t); fz_log_raw(z, \"}}\"); }}\n    }}",
                                cb = d.cbase
                            );
                        }
                        Base::Prim(p) => {
                            let _ = writeln!(
                                o,
                                "    if ({a}_b) for (int i = 0; i < {n}; i++) {{\n        {} t;",
                                d.cbase
                            );
                            let real_out = matches!(p, Prim::F32 | Prim::F64) && !d.is_const;
                            if real_out {
                                // An output: a finite sentinel, so that a non-finite
                                // value found after a successful call was written by it.
                                let _ = writeln!(o, "        t = ({})12345.5;", d.cbase);
                                finite_checks.push(format!(
                                    "fz_check_finite(z, {k}, {a}_b, {n}, {})",
                                    (*p == Prim::F32) as i32
                                ));
                            } else {
                                draw_prim(o, "t", &d.cbase, *p, hint(&f.name, &pname, *p));
                            }
                            let _ = writeln!(
                                o,
                                "        memcpy({a}_b + i * sizeof t, &t, sizeof t);\n    }}"
                            );
                        }
                        Base::Void => {}
                        Base::Callback(_) => unreachable!("rejected by the parser"),
                    }
                    let _ = writeln!(o, "    {} {a} = ({}){a}_b;", d.cty, d.cty);
                }
                _ => return Err(format!("{}: parameter {pname} not supported", f.name)),
            }
        }
        let call = format!("{}({})", f.name, args.join(", "));
        let codes = match f.codes {
            Codes::Vendor => "FZ_CODES_VENDOR",
            Codes::Mcl => "FZ_CODES_MCL",
            Codes::None => "FZ_CODES_NONE",
        };
        let _ = writeln!(o, "    fz_call_start(z, {fi});");
        match &f.ret.base {
            Base::Void => {
                let _ = writeln!(o, "    {call};\n    fz_end_void(z, {fi});");
            }
            Base::Prim(Prim::F32) | Base::Prim(Prim::F64) => {
                let _ = writeln!(
                    o,
                    "    double r = (double){call};\n    fz_end_real(z, {fi}, r, {codes});"
                );
            }
            Base::Prim(_) => {
                let _ = writeln!(
                    o,
                    "    long long r = (long long){call};\n    fz_end_int(z, {fi}, r, {codes});"
                );
                // Doubles a successful call wrote must be finite.
                for c in &finite_checks {
                    let _ = writeln!(o, "    if (r == 0) {c};");
                }
            }
            _ => return Err(format!("{}: return type not supported", f.name)),
        }
        let _ = writeln!(o, "}}");
    }
    Ok(())
}
