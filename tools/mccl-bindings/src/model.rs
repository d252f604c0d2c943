//! The C side: a parser for the generated headers `include/MCCL.h` and `include/MCCL_Fun.h`
//! (their regular, generator-written format) and the C struct layout rules.
//!
//! Everything the bindings generator writes and everything the checker compares comes from
//! the [`Header`] built here, so the C headers stay the single source of truth.

use std::collections::BTreeMap;
use std::fmt;

/// An error with the place it was found (`file:line: message`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error(pub String);

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

/// Builds an [`Error`] located at `file:line`.
pub fn err_at(file: &str, line: usize, msg: impl fmt::Display) -> Error {
    Error(format!("{file}:{line}: {msg}"))
}

/// A C type as far as the ABI is concerned (qualifiers such as `const` are dropped).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CType {
    /// `void` (only as a return type or behind a pointer).
    Void,
    /// A fixed-width integer (`WORD`, `DWORD`, `BYTE`, `int`, `int32_t`, `short`, ...).
    Int {
        /// Width in bytes.
        bytes: u8,
        /// Whether the C type is signed.
        signed: bool,
    },
    /// `BOOL` (an `int`, kept apart so the bindings can map it to a boolean).
    Bool,
    /// Plain `char` (a character, or a string behind a pointer).
    Char,
    /// C `long` / `unsigned long`: 4 bytes on Windows (LLP64), 8 on LP64 Linux.
    CLong {
        /// Whether the C type is signed.
        signed: bool,
    },
    /// `double` (8) or `float` (4).
    Float(u8),
    /// A struct, by its canonical name (typedef aliases resolved).
    Struct(String),
    /// A callback typedef (a function pointer), by name.
    Callback(String),
    /// A pointer (or a C++ reference) to the inner type.
    Ptr(Box<CType>),
}

impl CType {
    /// Whether this type, or anything it points to, is a C `long`.
    pub fn has_clong(&self) -> bool {
        match self {
            CType::CLong { .. } => true,
            CType::Ptr(t) => t.has_clong(),
            _ => false,
        }
    }
}

/// One struct field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Field {
    /// Field name.
    pub name: String,
    /// Element type.
    pub ty: CType,
    /// Array length for `T name[N]`.
    pub count: Option<usize>,
}

/// A `typedef struct { ... } NAME;`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Struct {
    /// Typedef name.
    pub name: String,
    /// Fields in declaration order.
    pub fields: Vec<Field>,
}

/// A function or callback parameter.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Param {
    /// Parameter name (`arg<i>` when the header leaves it out).
    pub name: String,
    /// Parameter type.
    pub ty: CType,
    /// The C++ default argument (`MCC_DEFAULT(v)`), as written.
    pub default: Option<String>,
}

/// A function prototype or a callback typedef signature.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Func {
    /// Function (or typedef) name.
    pub name: String,
    /// Return type.
    pub ret: CType,
    /// Parameters in order.
    pub params: Vec<Param>,
    /// The header section (`/* System Management */`) it was declared under.
    pub section: String,
}

impl Func {
    /// Whether any parameter or the return value involves a C `long`.
    pub fn has_clong(&self) -> bool {
        self.ret.has_clong() || self.params.iter().any(|p| p.ty.has_clong())
    }
}

/// A `#define NAME value` with an integer value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Const {
    /// Macro name.
    pub name: String,
    /// Evaluated value.
    pub value: i64,
}

/// What a type name stands for after `typedef`s.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Named {
    Scalar(CType),
    Struct(String),
}

/// Everything the generated headers declare.
#[derive(Debug, Clone, Default)]
pub struct Header {
    /// Integer constants in header order.
    pub consts: Vec<Const>,
    /// Structs in header order (aliases appear under their own name with the target's fields).
    pub structs: Vec<Struct>,
    /// `typedef STRUCT ALIAS;` pairs: alias -> canonical struct name.
    pub aliases: BTreeMap<String, String>,
    /// Callback typedefs in header order.
    pub callbacks: Vec<Func>,
    /// Function prototypes in header order.
    pub funcs: Vec<Func>,
    names: BTreeMap<String, Named>,
}

fn primitive(words: &[&str]) -> Option<CType> {
    let w: Vec<&str> = words.iter().copied().filter(|w| *w != "const").collect();
    let t = match w.as_slice() {
        ["void"] => CType::Void,
        ["char"] => CType::Char,
        ["signed", "char"] | ["int8_t"] => CType::Int {
            bytes: 1,
            signed: true,
        },
        ["unsigned", "char"] | ["uint8_t"] => CType::Int {
            bytes: 1,
            signed: false,
        },
        ["short"] | ["short", "int"] | ["int16_t"] => CType::Int {
            bytes: 2,
            signed: true,
        },
        ["unsigned", "short"] | ["unsigned", "short", "int"] | ["uint16_t"] => CType::Int {
            bytes: 2,
            signed: false,
        },
        ["int"] | ["signed"] | ["signed", "int"] | ["int32_t"] => CType::Int {
            bytes: 4,
            signed: true,
        },
        ["unsigned"] | ["unsigned", "int"] | ["uint32_t"] => CType::Int {
            bytes: 4,
            signed: false,
        },
        ["long"] | ["long", "int"] | ["signed", "long"] => CType::CLong { signed: true },
        ["unsigned", "long"] | ["unsigned", "long", "int"] => CType::CLong { signed: false },
        ["long", "long"] | ["long", "long", "int"] | ["int64_t"] => CType::Int {
            bytes: 8,
            signed: true,
        },
        ["unsigned", "long", "long"] | ["uint64_t"] => CType::Int {
            bytes: 8,
            signed: false,
        },
        ["double"] => CType::Float(8),
        ["float"] => CType::Float(4),
        _ => return None,
    };
    Some(t)
}

/// Splits a C declaration into words, with `*`, `&`, `[`, `]` as words of their own.
fn words(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for ch in s.chars() {
        if ch.is_alphanumeric() || ch == '_' {
            cur.push(ch);
        } else {
            if !cur.is_empty() {
                out.push(std::mem::take(&mut cur));
            }
            if matches!(ch, '*' | '&' | '[' | ']') {
                out.push(ch.to_string());
            }
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

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

impl Header {
    /// Parses `MCCL.h` then `MCCL_Fun.h` (file names are used in error messages only).
    pub fn parse(mccl_h: (&str, &str), fun_h: (&str, &str)) -> Result<Header, Error> {
        let mut h = Header::default();
        h.parse_types(mccl_h.0, mccl_h.1)?;
        h.parse_funcs(fun_h.0, fun_h.1)?;
        Ok(h)
    }

    /// Resolves a type given as words (e.g. `["SYS_MAC_PARAM", "*"]`).
    fn resolve(&self, ws: &[String]) -> Result<CType, String> {
        let mut base: Vec<&str> = Vec::new();
        let mut ptrs = 0;
        for w in ws {
            match w.as_str() {
                "*" | "&" => ptrs += 1,
                "const" | "volatile" | "struct" => {}
                s => base.push(s),
            }
        }
        let mut t = if let Some(p) = primitive(&base) {
            p
        } else if base.len() == 1 {
            match self.names.get(base[0]) {
                Some(Named::Scalar(t)) => t.clone(),
                Some(Named::Struct(s)) => CType::Struct(s.clone()),
                None if self.callbacks.iter().any(|c| c.name == base[0]) => {
                    CType::Callback(base[0].to_string())
                }
                None => return Err(format!("unknown type {:?}", base[0])),
            }
        } else {
            return Err(format!("unknown type {:?}", base.join(" ")));
        };
        for _ in 0..ptrs {
            t = CType::Ptr(Box::new(t));
        }
        Ok(t)
    }

    fn parse_params(&self, inner: &str) -> Result<Vec<Param>, String> {
        let inner = inner.trim();
        if inner.is_empty() || inner == "void" {
            return Ok(Vec::new());
        }
        let mut out = Vec::new();
        for (i, p) in inner.split(',').enumerate() {
            let (decl, default) = match p.find("MCC_DEFAULT(") {
                Some(at) => {
                    let rest = &p[at + "MCC_DEFAULT(".len()..];
                    let end = rest
                        .rfind(')')
                        .ok_or_else(|| format!("unclosed MCC_DEFAULT in {p:?}"))?;
                    (&p[..at], Some(rest[..end].trim().to_string()))
                }
                None => (p, None),
            };
            let mut ws = words(decl);
            let named = ws.len() >= 2
                && ws
                    .last()
                    .is_some_and(|w| w != "*" && w != "&" && primitive(&[w.as_str()]).is_none())
                && self.resolve(&ws).is_err();
            let name = if named {
                ws.pop().unwrap_or_default()
            } else {
                format!("arg{i}")
            };
            let ty = self.resolve(&ws)?;
            out.push(Param { name, ty, default });
        }
        Ok(out)
    }

    fn parse_types(&mut self, file: &str, text: &str) -> Result<(), Error> {
        let mut depth = 0usize;
        // One entry per open `#if`: whether it is an `#ifdef __cplusplus` still in its
        // C++ branch. The bindings take the C declarations; a type the header declares
        // twice (a C++ form, then a C form under `#else`) is read once, in its C form.
        let mut cpp_only: Vec<bool> = Vec::new();
        let mut values: BTreeMap<String, i64> = BTreeMap::new();
        let mut open: Option<(usize, Vec<Field>)> = None;
        for (n, raw) in text.lines().enumerate() {
            let ln = n + 1;
            let line = raw.trim();
            if let Some((_, fields)) = open.as_mut() {
                if let Some(rest) = line.strip_prefix('}') {
                    let name = rest.trim().trim_end_matches(';').trim().to_string();
                    let (_, fields) = open.take().unwrap_or_default();
                    self.names.insert(name.clone(), Named::Struct(name.clone()));
                    self.structs.push(Struct { name, fields });
                    continue;
                }
                if line.is_empty() {
                    continue;
                }
                let decl = line
                    .strip_suffix(';')
                    .ok_or_else(|| err_at(file, ln, "struct field without ';'"))?;
                let mut ws = words(decl);
                let mut count = None;
                if ws.last().map(String::as_str) == Some("]") {
                    let lb = ws
                        .iter()
                        .rposition(|w| w == "[")
                        .ok_or_else(|| err_at(file, ln, "unbalanced '['"))?;
                    let expr = ws[lb + 1..ws.len() - 1].join(" ");
                    let v = eval_expr(&expr, &values).map_err(|e| err_at(file, ln, e))?;
                    count = Some(
                        usize::try_from(v).map_err(|_| err_at(file, ln, "negative array size"))?,
                    );
                    ws.truncate(lb);
                }
                let name = ws
                    .pop()
                    .ok_or_else(|| err_at(file, ln, "empty field declaration"))?;
                let ty = self.resolve(&ws).map_err(|e| err_at(file, ln, e))?;
                fields.push(Field { name, ty, count });
                continue;
            }
            if line.starts_with("#if") {
                depth += 1;
                cpp_only.push(line == "#ifdef __cplusplus");
            } else if line.starts_with("#else") {
                if let Some(top) = cpp_only.last_mut() {
                    *top = false;
                }
            } else if line.starts_with("#endif") {
                depth = depth.saturating_sub(1);
                cpp_only.pop();
            } else if cpp_only.contains(&true) {
                continue;
            } else if let Some(rest) = line.strip_prefix("#define ") {
                let (name, value) = match rest.split_once(char::is_whitespace) {
                    Some((a, b)) => (a, b.trim()),
                    None => (rest.trim(), ""),
                };
                // Macros inside nested #if blocks (calling conventions) and value-less
                // flags (include guards, MULTI_CARD_SUPPORT) are not constants.
                if depth > 1 || value.is_empty() {
                    continue;
                }
                let v = eval_expr(value, &values)
                    .map_err(|e| err_at(file, ln, format!("#define {name}: {e}")))?;
                values.insert(name.to_string(), v);
                self.consts.push(Const {
                    name: name.to_string(),
                    value: v,
                });
            } else if line == "typedef struct {" {
                open = Some((ln, Vec::new()));
            } else if let Some(rest) = line.strip_prefix("typedef ") {
                let rest = rest.trim_end_matches(';');
                if let Some(open_paren) = rest.find("(MCC_CALLBACK *").or_else(|| rest.find("(*")) {
                    // typedef RET (MCC_CALLBACK *NAME)(PARAMS);
                    let ret_ws = words(&rest[..open_paren]);
                    let after = &rest[open_paren..];
                    let star = after.find('*').unwrap_or(0);
                    let close = after
                        .find(')')
                        .ok_or_else(|| err_at(file, ln, "callback typedef without ')'"))?;
                    let name = after[star + 1..close].trim().to_string();
                    let params_s = after[close + 1..].trim();
                    let inner = params_s
                        .strip_prefix('(')
                        .and_then(|s| s.strip_suffix(')'))
                        .ok_or_else(|| err_at(file, ln, "callback parameters not in (...)"))?;
                    let ret = self.resolve(&ret_ws).map_err(|e| err_at(file, ln, e))?;
                    let params = self.parse_params(inner).map_err(|e| err_at(file, ln, e))?;
                    self.callbacks.push(Func {
                        name,
                        ret,
                        params,
                        section: String::new(),
                    });
                } else {
                    let mut ws = words(rest);
                    let name = ws
                        .pop()
                        .ok_or_else(|| err_at(file, ln, "typedef without a name"))?;
                    let target = if name == "BOOL" {
                        CType::Bool
                    } else {
                        self.resolve(&ws).map_err(|e| err_at(file, ln, e))?
                    };
                    match target {
                        CType::Struct(s) => {
                            let fields = self
                                .structs
                                .iter()
                                .find(|x| x.name == s)
                                .map(|x| x.fields.clone())
                                .ok_or_else(|| err_at(file, ln, format!("alias of unknown {s}")))?;
                            self.aliases.insert(name.clone(), s.clone());
                            self.names.insert(name.clone(), Named::Struct(s));
                            self.structs.push(Struct { name, fields });
                        }
                        t => {
                            self.names.insert(name, Named::Scalar(t));
                        }
                    }
                }
            }
        }
        if let Some((ln, _)) = open {
            return Err(err_at(file, ln, "struct not closed"));
        }
        Ok(())
    }

    fn parse_funcs(&mut self, file: &str, text: &str) -> Result<(), Error> {
        let mut section = String::new();
        for (n, raw) in text.lines().enumerate() {
            let ln = n + 1;
            let line = raw.trim();
            if let Some(c) = line.strip_prefix("/*").and_then(|c| c.strip_suffix("*/")) {
                let c = c.trim();
                if !c.is_empty() && !c.contains('.') && !c.contains(':') {
                    section = c.to_string();
                }
                continue;
            }
            let Some(rest) = line.strip_prefix("MCC_API ") else {
                continue;
            };
            let rest = rest
                .strip_suffix(';')
                .ok_or_else(|| err_at(file, ln, "prototype without ';'"))?;
            let (ret_s, after) = rest
                .split_once(" MCC_CALL ")
                .ok_or_else(|| err_at(file, ln, "prototype without MCC_CALL"))?;
            let open = after
                .find('(')
                .ok_or_else(|| err_at(file, ln, "prototype without '('"))?;
            let close = after
                .rfind(')')
                .ok_or_else(|| err_at(file, ln, "prototype without ')'"))?;
            let name = after[..open].trim().to_string();
            let ret = self
                .resolve(&words(ret_s))
                .map_err(|e| err_at(file, ln, e))?;
            let params = self
                .parse_params(&after[open + 1..close])
                .map_err(|e| err_at(file, ln, e))?;
            self.funcs.push(Func {
                name,
                ret,
                params,
                section: section.clone(),
            });
        }
        Ok(())
    }

    /// The struct called `name` (an alias gives the target's fields).
    pub fn find_struct(&self, name: &str) -> Option<&Struct> {
        self.structs.iter().find(|s| s.name == name)
    }

    /// The canonical name of a struct (`ENCODER_CONFIG` -> `SYS_ENCODER_CONFIG`).
    pub fn canonical<'a>(&'a self, name: &'a str) -> &'a str {
        self.aliases.get(name).map(String::as_str).unwrap_or(name)
    }
}

/// Platform rules for sizes and alignment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Target {
    /// Size of C `long`.
    pub clong: u8,
    /// Size of a pointer.
    pub ptr: u8,
    /// Largest member alignment (8 for C and .NET's default pack, 4 for VB6 UDTs).
    pub max_align: usize,
}

/// Windows x86/x64 C (MSVC /Zp8) with a 4-byte `long`: the vendor layout.
pub const WIN: Target = Target {
    clong: 4,
    ptr: 8,
    max_align: 8,
};

/// A member's size, alignment and offset.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Slot {
    /// Field name.
    pub name: String,
    /// Offset in bytes.
    pub offset: usize,
    /// Size in bytes (element size times count).
    pub size: usize,
}

/// The layout of a struct: slots in order and the total size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// Every field with its offset.
    pub slots: Vec<Slot>,
    /// `sizeof`.
    pub size: usize,
    /// Alignment of the whole struct.
    pub align: usize,
}

/// Sequential layout of `(name, element size, element alignment, count)` members.
pub fn layout(members: &[(String, usize, usize, usize)], max_align: usize) -> Layout {
    let mut off = 0usize;
    let mut align = 1usize;
    let mut slots = Vec::new();
    for (name, size, al, count) in members {
        let a = (*al).clamp(1, max_align);
        off = off.div_ceil(a) * a;
        slots.push(Slot {
            name: name.clone(),
            offset: off,
            size: size * count,
        });
        off += size * count;
        align = align.max(a);
    }
    Layout {
        slots,
        size: off.div_ceil(align) * align,
        align,
    }
}

impl Header {
    /// Size and alignment of one C type on `t`.
    pub fn size_align(&self, ty: &CType, t: Target) -> Result<(usize, usize), String> {
        Ok(match ty {
            CType::Void => return Err("void has no size".into()),
            CType::Int { bytes, .. } => (usize::from(*bytes), usize::from(*bytes)),
            CType::Bool => (4, 4),
            CType::Char => (1, 1),
            CType::CLong { .. } => (usize::from(t.clong), usize::from(t.clong)),
            CType::Float(b) => (usize::from(*b), usize::from(*b)),
            CType::Ptr(_) | CType::Callback(_) => (usize::from(t.ptr), usize::from(t.ptr)),
            CType::Struct(s) => {
                let l = self.struct_layout(s, t)?;
                (l.size, l.align)
            }
        })
    }

    /// The C layout of struct `name` on `t`.
    pub fn struct_layout(&self, name: &str, t: Target) -> Result<Layout, String> {
        let s = self
            .find_struct(name)
            .ok_or_else(|| format!("unknown struct {name}"))?;
        let mut m = Vec::new();
        for f in &s.fields {
            let (size, al) = self.size_align(&f.ty, t)?;
            m.push((f.name.clone(), size, al, f.count.unwrap_or(1)));
        }
        Ok(layout(&m, t.max_align))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expressions() {
        let mut c = BTreeMap::new();
        c.insert("A".to_string(), 12);
        assert_eq!(eval_expr("(A * 8)", &c), Ok(96));
        assert_eq!(eval_expr("(-1)", &c), Ok(-1));
        assert_eq!(eval_expr("0x10 | 1 << 2", &c), Ok(20));
        assert!(eval_expr("B", &c).is_err());
    }

    #[test]
    fn parses_types_and_protos() {
        let h = Header::parse(
            (
                "a.h",
                "#ifndef G\n#define G\n#ifndef X\n#define X __stdcall\n#endif\n#define N 2\n#define M (N * 4)\ntypedef uint16_t WORD;\ntypedef int BOOL;\ntypedef struct {\n  WORD w;\n  double d[M];\n} S;\ntypedef S T;\ntypedef void (MCC_CALLBACK *CB)(S*);\n#endif\n",
            ),
            (
                "b.h",
                "/* Sec */\nMCC_API int MCC_CALL F(S *p, WORD w MCC_DEFAULT(0), CB f, long *l, BOOL b);\n",
            ),
        )
        .unwrap();
        assert_eq!(h.consts.len(), 2);
        assert_eq!(h.consts[1].value, 8);
        assert_eq!(h.structs[0].fields[1].count, Some(8));
        assert_eq!(h.canonical("T"), "S");
        assert_eq!(h.struct_layout("T", WIN).unwrap().size, 72);
        let f = &h.funcs[0];
        assert_eq!(f.section, "Sec");
        assert_eq!(
            f.params[0].ty,
            CType::Ptr(Box::new(CType::Struct("S".into())))
        );
        assert_eq!(f.params[1].default.as_deref(), Some("0"));
        assert_eq!(f.params[2].ty, CType::Callback("CB".into()));
        assert!(f.has_clong());
        assert_eq!(f.params[4].ty, CType::Bool);
        assert_eq!(h.callbacks[0].params[0].name, "arg0");
    }

    /// A callback the header declares for C++ (a reference) and for C (a pointer) under
    /// `#ifdef __cplusplus`/`#else` is read once, in its C form.
    #[test]
    fn cpp_branch_is_skipped() {
        let h = Header::parse(
            (
                "a.h",
                "typedef uint32_t DWORD;\n#ifdef __cplusplus\ntypedef void (MCC_CALLBACK *K)(DWORD &p, int cpp);\n#else\ntypedef void (MCC_CALLBACK *K)(DWORD *p);\n#endif\ntypedef void (MCC_CALLBACK *L)(int n);\n",
            ),
            ("b.h", ""),
        )
        .unwrap();
        let names: Vec<&str> = h.callbacks.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["K", "L"]);
        assert_eq!(h.callbacks[0].params.len(), 1);
        assert_eq!(
            h.callbacks[0].params[0].ty,
            CType::Ptr(Box::new(CType::Int {
                bytes: 4,
                signed: false
            }))
        );
    }
}
