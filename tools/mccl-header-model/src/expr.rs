//! The constant expressions of `#define` values.

use std::collections::BTreeMap;

/// Evaluates a constant expression of `#define` values: integers (decimal or hex), names of
/// earlier constants, unary minus, `+ - * / << >> |` and parentheses.
pub fn eval_expr(s: &str, consts: &BTreeMap<String, i64>) -> Result<i64, String> {
    struct P<'a> {
        t: Vec<String>,
        i: usize,
        c: &'a BTreeMap<String, i64>,
    }
    impl P<'_> {
        fn peek(&self) -> Option<&str> {
            self.t.get(self.i).map(String::as_str)
        }
        fn next(&mut self) -> Option<String> {
            let v = self.t.get(self.i).cloned();
            self.i += 1;
            v
        }
        fn expr(&mut self, min: u8) -> Result<i64, String> {
            let mut lhs = self.unary()?;
            loop {
                let (prec, op) = match self.peek() {
                    Some("|") => (1, "|"),
                    Some("<<") => (2, "<<"),
                    Some(">>") => (2, ">>"),
                    Some("+") => (3, "+"),
                    Some("-") => (3, "-"),
                    Some("*") => (4, "*"),
                    Some("/") => (4, "/"),
                    _ => break,
                };
                if prec < min {
                    break;
                }
                self.i += 1;
                let rhs = self.expr(prec + 1)?;
                lhs = match op {
                    "|" => lhs | rhs,
                    "<<" => lhs
                        .checked_shl(u32::try_from(rhs).map_err(|e| e.to_string())?)
                        .ok_or("shift overflow")?,
                    ">>" => lhs >> rhs,
                    "+" => lhs.checked_add(rhs).ok_or("overflow")?,
                    "-" => lhs.checked_sub(rhs).ok_or("overflow")?,
                    "*" => lhs.checked_mul(rhs).ok_or("overflow")?,
                    _ => lhs.checked_div(rhs).ok_or("division by zero")?,
                };
            }
            Ok(lhs)
        }
        fn unary(&mut self) -> Result<i64, String> {
            match self.next().as_deref() {
                Some("-") => Ok(-self.unary()?),
                Some("(") => {
                    let v = self.expr(0)?;
                    if self.next().as_deref() != Some(")") {
                        return Err("missing ')'".into());
                    }
                    Ok(v)
                }
                Some(tok) => {
                    let t = tok.trim_end_matches(['u', 'U', 'l', 'L']);
                    if let Some(h) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
                        i64::from_str_radix(h, 16).map_err(|e| format!("{tok}: {e}"))
                    } else if t.starts_with(|c: char| c.is_ascii_digit()) {
                        t.parse::<i64>().map_err(|e| format!("{tok}: {e}"))
                    } else {
                        self.c
                            .get(tok)
                            .copied()
                            .ok_or_else(|| format!("unknown name {tok:?}"))
                    }
                }
                None => Err("unexpected end of expression".into()),
            }
        }
    }
    let mut toks = Vec::new();
    let cs: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_alphanumeric() || c == '_' {
            let st = i;
            while i < cs.len() && (cs[i].is_alphanumeric() || cs[i] == '_') {
                i += 1;
            }
            toks.push(cs[st..i].iter().collect());
        } else if (c == '<' || c == '>') && cs.get(i + 1) == Some(&c) {
            toks.push(format!("{c}{c}"));
            i += 2;
        } else if "()+-*/|".contains(c) {
            toks.push(c.to_string());
            i += 1;
        } else {
            return Err(format!("unexpected character {c:?}"));
        }
    }
    let mut p = P {
        t: toks,
        i: 0,
        c: consts,
    };
    let v = p.expr(0)?;
    if p.i != p.t.len() {
        return Err(format!("trailing tokens in {s:?}"));
    }
    Ok(v)
}
