//! The table of functions `fz_funcs` the runtime draws from, and `fz_register_all`, which
//! arms every routine of a card.

use crate::view::{Base, Decl, Model};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Writes the function table and the registration of every routine.
pub fn write(o: &mut String, m: &Model, cb_index: &BTreeMap<&String, usize>) {
    // The table.
    let _ = writeln!(o, "\nconst fz_func_t fz_funcs[] = {{");
    for f in &m.funcs {
        let mut flags = Vec::new();
        if f.name.starts_with("MCC_Init") {
            flags.push("FZ_F_INIT");
        }
        if f.name == "MCC_CloseSystem" {
            flags.push("FZ_F_CLOSE");
        }
        let setter = f.params.iter().any(|d| matches!(d.base, Base::Callback(_)));
        if setter {
            flags.push("FZ_F_ROUTINE_SETTER");
        }
        if flags.is_empty() {
            flags.push("0");
        }
        let _ = writeln!(
            o,
            "    {{\"{}\", \"{}\", fz_call_{}, {}}},",
            f.name,
            f.header,
            f.name,
            flags.join(" | ")
        );
    }
    let _ = writeln!(o, "}};\nconst int fz_nfuncs = {};", m.funcs.len());

    // Registers every routine on a card: each setter that takes one callback and
    // otherwise only card indices (the arming step of the runtime uses it).
    let _ = writeln!(o, "\nvoid fz_register_all(fz_t *z, int card)\n{{");
    for (fi, f) in m.funcs.iter().enumerate() {
        let cbs: Vec<&Decl> = f
            .params
            .iter()
            .filter(|d| matches!(d.base, Base::Callback(_)))
            .collect();
        let rest_cards = f.params.iter().all(|d| {
            matches!(d.base, Base::Callback(_))
                || (d.ptr == 0 && d.name.contains("Card") && !d.name.contains("CardNo"))
        });
        if cbs.len() != 1 || !rest_cards {
            continue;
        }
        let args: Vec<String> = f
            .params
            .iter()
            .map(|d| match &d.base {
                Base::Callback(cb) => format!("({})fz_cbs[{}].fn", d.cty, cb_index[cb]),
                _ => format!("({})card", d.cty),
            })
            .collect();
        let Base::Callback(cb) = &cbs[0].base else {
            continue;
        };
        let _ = writeln!(
            o,
            "    fz_begin(z, {fi}); fz_log_cb(z, \"{}\", fz_cbs[{}].fn); fz_log_i(z, \"card\", card);\n    fz_call_start(z, {fi});\n    fz_end_int(z, {fi}, (long long){}({}), FZ_CODES_VENDOR);",
            cbs[0].name,
            cb_index[cb],
            f.name,
            args.join(", ")
        );
    }
    let _ = writeln!(o, "}}");
}
