//! C snippets the generated file is made of: identifiers, drawing and logging a scalar.

use crate::view::Prim;
use std::fmt::Write as _;

/// `s` as a C identifier (every other character an underscore).
pub fn c_ident(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// Statements that draw one scalar of type `p` into the lvalue `lv`.
pub fn draw_prim(out: &mut String, lv: &str, cty: &str, p: Prim, h: &str) {
    match p {
        Prim::Int(bits, signed) => {
            let _ = writeln!(
                out,
                "    {lv} = ({cty})fz_int(z, {h}, {bits}, {});",
                signed as i32
            );
        }
        Prim::Char => {
            let _ = writeln!(out, "    {lv} = ({cty})fz_char(z, {h});");
        }
        Prim::Bool => {
            let _ = writeln!(out, "    {lv} = ({cty})(fz_int(z, FZ_H_BOOL, 8, 0) & 1);");
        }
        Prim::F32 => {
            let _ = writeln!(out, "    {lv} = ({cty})fz_real(z, {h}, 1);");
        }
        Prim::F64 => {
            let _ = writeln!(out, "    {lv} = ({cty})fz_real(z, {h}, 0);");
        }
    }
}

/// A call that appends the scalar `v` (named `name`) to the current log line.
pub fn log_prim(p: Prim, name: &str, v: &str) -> String {
    match p {
        Prim::Int(_, true) => format!("fz_log_i(z, \"{name}\", (long long)({v}))"),
        Prim::Int(_, false) | Prim::Bool => {
            format!("fz_log_u(z, \"{name}\", (unsigned long long)({v}))")
        }
        Prim::Char => format!("fz_log_c(z, \"{name}\", (int)({v}))"),
        Prim::F32 | Prim::F64 => format!("fz_log_r(z, \"{name}\", (double)({v}))"),
    }
}
