//! The fill and show functions of every struct: `fz_fill_S` draws each field as a
//! parameter of its type and name would be, `fz_show_S` logs them.

use crate::c::{c_ident, draw_prim, log_prim};
use crate::hint::hint;
use crate::view::{Base, Model};
use std::fmt::Write as _;

/// Writes the struct functions (inline: not every struct is a parameter).
pub fn write(o: &mut String, m: &Model) -> Result<(), String> {
    // Struct fill and show functions (inline: not every struct is a parameter).
    for name in m.structs.keys() {
        let f = c_ident(name);
        let _ = writeln!(o, "static inline void fz_fill_{f}(fz_t *z, {name} *v);");
        let _ = writeln!(
            o,
            "static inline void fz_show_{f}(fz_t *z, const {name} *v);"
        );
    }
    for (name, fields) in &m.structs {
        let f = c_ident(name);
        let _ = writeln!(
            o,
            "\nstatic inline void fz_fill_{f}(fz_t *z, {name} *v)\n{{"
        );
        let _ = writeln!(o, "    (void)z; memset(v, 0, sizeof *v);");
        for d in fields {
            let lv = format!("v->{}", d.name);
            match (&d.base, d.ptr, d.array) {
                (Base::Prim(p), 0, None) => {
                    draw_prim(o, &lv, &d.cbase, *p, hint(name, &d.name, *p))
                }
                (Base::Prim(p), 0, Some(n)) => {
                    let _ = writeln!(o, "    for (int i = 0; i < {n}; i++) {{");
                    draw_prim(
                        o,
                        &format!("{lv}[i]"),
                        &d.cbase,
                        *p,
                        hint(name, &d.name, *p),
                    );
                    let _ = writeln!(o, "    }}");
                }
                (Base::Struct(s), 0, None) => {
                    let _ = writeln!(o, "    fz_fill_{}(z, &{lv});", c_ident(s));
                }
                (Base::Struct(s), 0, Some(n)) => {
                    let _ = writeln!(
                        o,
                        "    for (int i = 0; i < {n}; i++) fz_fill_{}(z, &{lv}[i]);",
                        c_ident(s)
                    );
                }
                _ => {
                    return Err(format!(
                        "struct {name}: field {} of a kind the fuzzer cannot fill",
                        d.name
                    ))
                }
            }
        }
        let _ = writeln!(o, "}}");
        let _ = writeln!(
            o,
            "\nstatic inline void fz_show_{f}(fz_t *z, const {name} *v)\n{{"
        );
        let _ = writeln!(o, "    (void)z; (void)v;");
        for d in fields {
            match (&d.base, d.ptr, d.array) {
                (Base::Prim(p), 0, None) => {
                    let _ = writeln!(
                        o,
                        "    {};",
                        log_prim(*p, &d.name, &format!("v->{}", d.name))
                    );
                }
                (Base::Prim(p), 0, Some(n)) => {
                    let _ = writeln!(
                        o,
                        "    {}; fz_log_raw(z, \"..[{n}]\");",
                        log_prim(*p, &format!("{}[0]", d.name), &format!("v->{}[0]", d.name))
                    );
                }
                (Base::Struct(s), 0, None) => {
                    let _ = writeln!(o, "    fz_show_{}(z, &v->{});", c_ident(s), d.name);
                }
                (Base::Struct(s), 0, Some(_)) => {
                    let _ = writeln!(o, "    fz_show_{}(z, &v->{}[0]);", c_ident(s), d.name);
                }
                _ => {}
            }
        }
        let _ = writeln!(o, "}}");
    }
    Ok(())
}
