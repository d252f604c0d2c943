//! The routines, one per callback type, and their table `fz_cbs`: each counts its
//! deliveries in the runtime (and calls back into the library from there).

use crate::c::c_ident;
use crate::view::{Base, Model};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Writes the routines and their table; returns each callback type's index in it.
pub fn write<'m>(o: &mut String, m: &'m Model) -> BTreeMap<&'m String, usize> {
    // Routines, one per callback type.
    let cb_index: BTreeMap<&String, usize> = m
        .callbacks
        .keys()
        .enumerate()
        .map(|(i, k)| (k, i))
        .collect();
    for (i, (name, cb)) in m.callbacks.iter().enumerate() {
        let (conv, arg) = (&cb.conv, &cb.arg);
        if let Some(types) = &cb.several {
            let ret = if cb.ret == "void" {
                String::new()
            } else {
                "\n    return 1;".to_string()
            };
            // Every parameter gets a name of ours (the header may name them or not) and
            // is marked unused.
            let params: Vec<String> = types
                .iter()
                .enumerate()
                .map(|(k, t)| format!("{t} a{k}"))
                .collect();
            let unused: String = (0..params.len())
                .map(|k| format!("\n    (void)a{k};"))
                .collect();
            let _ = writeln!(
                o,
                "\nstatic {} {conv} fz_cb_{}({})\n{{{unused}\n    fz_routine({i}, NULL, 0);{ret}\n}}",
                cb.ret,
                c_ident(name),
                params.join(", ")
            );
            continue;
        }
        let (sig, size) = if arg == "void" || arg.is_empty() {
            ("void".to_string(), "0".to_string())
        } else {
            (format!("{arg} *p"), "sizeof(*p)".to_string())
        };
        let pass = if size == "0" { "NULL" } else { "p" };
        let _ = writeln!(
            o,
            "\nstatic void {conv} fz_cb_{}({sig})\n{{\n    fz_routine({i}, {pass}, {size});\n}}",
            c_ident(name)
        );
    }
    let _ = writeln!(o, "\nconst fz_cb_t fz_cbs[] = {{");
    for (name, cb) in &m.callbacks {
        let arg = if cb.several.is_some() {
            "void"
        } else {
            cb.arg.as_str()
        };
        let setters = m
            .funcs
            .iter()
            .filter(|f| {
                f.params
                    .iter()
                    .any(|d| d.base == Base::Callback(name.clone()))
            })
            .count();
        let _ = writeln!(
            o,
            "    {{\"{name}\", \"{arg}\", (void (*)(void))fz_cb_{}, {setters}, {}}},",
            c_ident(name),
            i32::from(cb.several.is_some())
        );
    }
    let _ = writeln!(o, "}};\nconst int fz_ncbs = {};", m.callbacks.len());
    cb_index
}
