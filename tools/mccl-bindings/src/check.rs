//! The bindings checker: parses `MCCL.cs`, `MCCLPCI_IMP.bas` and `MCCL.vb` on its own (it
//! shares no code with the generator's writers) and verifies every declaration against the
//! C header model and the library's exported symbols:
//!
//! * every `MCC_*` function of the header and every exported `MCC_*` symbol is declared,
//!   under its entry point, in a library called `MCCLPCI_IMP`, and is callable by its name;
//! * parameter count, order, by-value/by-reference and width (and int/float class) of every
//!   parameter, and the return width; a C `long` must be covered by a 4-byte and an 8-byte
//!   extern in the .NET files (Windows and LP64 Linux), and is 4 bytes in VB6 (Win32);
//! * struct field order, names, element widths, array lengths, offsets and sizes, computed
//!   with each language's layout rule (pack 8 for .NET, 4 for VB6 UDTs) against the C layout
//!   and a table of known vendor sizes;
//! * delegate signatures against the callback typedefs, and constant values.

use crate::model::{CType, Header, WIN};
use std::collections::BTreeMap;

/// The sizes of the vendor structs (INTERFACE.md §3.2-3.3, Windows layout).
pub const KNOWN_SIZES: &[(&str, usize)] = &[
    ("SYS_MAC_PARAM", 72),
    ("SYS_MAC_PARAM_EX", 72),
    ("SYS_ENCODER_CONFIG", 16),
    ("ENCODER_CONFIG", 16),
    ("SYS_PULSE_CONFIG", 8),
    ("PULSE_CONFIG", 8),
    ("SYS_HOME_CONFIG", 56),
    ("SYS_HOME_CONFIG_EX", 88),
    ("SYS_COMP_PARAM", 2056),
    ("SYS_CARD_CONFIG", 8),
    ("HOME_CONFIG", 16),
    ("SYS_MACH_PARAM", 104),
    ("SYS_GROUP_INFO", 36),
    ("SYS_GROUP_CONFIG", 3840),
    ("COMMAND_INFO", 104),
    ("LIOINT", 24),
    ("ENCINT", 16),
    ("PCLINT", 16),
    ("ADCINT", 10),
    ("RIOINT", 8),
    ("TMRINT", 1),
    ("HSKINT", 1),
];

/// Which binding file is being checked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    /// `MCCL.cs`.
    CSharp,
    /// `MCCLPCI_IMP.bas` (VB6: 32-bit Windows only).
    Vb6,
    /// `MCCL.vb`.
    VbNet,
}

/// What a pointer points to, as far as the ABI can tell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Pointee {
    /// An integer of this width.
    Int(u8),
    /// A float of this width.
    Float(u8),
    /// A struct (canonical name).
    Struct(String),
    /// A function (delegate or callback typedef name).
    Func(String),
    /// Anything (`IntPtr`, `As Any`, `void*`).
    Any,
}

/// The ABI shape of a parameter or return value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Abi {
    /// No value (`void`, `Sub`).
    Void,
    /// An integer passed by value, of this width.
    Int(u8),
    /// A float passed by value, of this width.
    Float(u8),
    /// A struct passed by value.
    Struct(String),
    /// A pointer (by reference, array, string buffer, delegate).
    Ptr(Pointee),
    /// Something that cannot cross the C ABI as declared (reason).
    Bad(String),
}

/// One parameter as the binding declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BParam {
    /// Declared name.
    pub name: String,
    /// ABI shape.
    pub abi: Abi,
}

/// An extern declaration (`DllImport` method or `Declare`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Extern {
    /// The method name in the binding.
    pub name: String,
    /// The native symbol it binds (`EntryPoint`/`Alias`, else the name).
    pub entry: String,
    /// The library name.
    pub lib: String,
    /// Whether callers can use it directly.
    pub public: bool,
    /// Parameters.
    pub params: Vec<BParam>,
    /// Return value.
    pub ret: Abi,
    /// An explicit calling convention, if any.
    pub conv: Option<String>,
    /// Line in the file.
    pub line: usize,
}

/// A public non-extern method (the wrappers around C `long` functions).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Method {
    /// Name.
    pub name: String,
    /// Parameter count.
    pub nparams: usize,
    /// Line in the file.
    pub line: usize,
}

/// Element type of a struct field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Elem {
    /// Integer of this width.
    Int(u8),
    /// Float of this width.
    Float(u8),
    /// A nested struct (binding name).
    Struct(String),
    /// Cannot be laid out inline (reason).
    Bad(String),
}

/// One struct field as the binding declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BField {
    /// Field name.
    pub name: String,
    /// Element type.
    pub elem: Elem,
    /// Array length (`SizeConst`, VB6 bounds).
    pub count: Option<usize>,
}

/// A struct / `Type` / `Structure`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BStruct {
    /// Name.
    pub name: String,
    /// Fields in order.
    pub fields: Vec<BField>,
    /// Whether it is declared with a sequential layout (always true for VB6 `Type`).
    pub sequential: bool,
    /// Line in the file.
    pub line: usize,
}

/// A delegate type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BDelegate {
    /// Name.
    pub name: String,
    /// Parameters.
    pub params: Vec<BParam>,
    /// Return value.
    pub ret: Abi,
    /// An explicit calling convention, if any.
    pub conv: Option<String>,
    /// Line in the file.
    pub line: usize,
}

/// Everything parsed out of one binding file.
#[derive(Debug, Clone, Default)]
pub struct Binding {
    /// Extern declarations.
    pub externs: Vec<Extern>,
    /// Public wrapper methods.
    pub methods: Vec<Method>,
    /// Structs.
    pub structs: Vec<BStruct>,
    /// Delegates.
    pub delegates: Vec<BDelegate>,
    /// Integer constants (name, value, line).
    pub consts: Vec<(String, i64, usize)>,
}

/// The outcome of checking one file.
#[derive(Debug, Default)]
pub struct Report {
    /// Problems, each `file:line: message`.
    pub problems: Vec<String>,
    /// Functions checked.
    pub functions: usize,
    /// Extern declarations checked (overloads and width variants included).
    pub externs: usize,
    /// Parameters checked.
    pub params: usize,
    /// Structs checked.
    pub structs: usize,
    /// Struct fields checked.
    pub fields: usize,
    /// Delegates checked.
    pub delegates: usize,
    /// Constants checked.
    pub consts: usize,
}

impl Report {
    /// One line: the counts and the verdict.
    pub fn summary(&self) -> String {
        format!(
            "{} functions ({} externs, {} parameters), {} structs ({} fields), {} delegates, {} constants checked: {}",
            self.functions,
            self.externs,
            self.params,
            self.structs,
            self.fields,
            self.delegates,
            self.consts,
            if self.problems.is_empty() {
                "OK".to_string()
            } else {
                format!("{} problem(s)", self.problems.len())
            }
        )
    }
}

// ----------------------------------------------------------------------------------------
// Lexing helpers shared by the parsers.

/// A token with the line it starts on.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Tok {
    s: String,
    line: usize,
}

/// Tokenizes C# source: identifiers (with `@` kept), numbers, strings (with quotes), and
/// single punctuation characters; comments and preprocessor lines are dropped.
fn lex_cs(text: &str) -> Vec<Tok> {
    let cs: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line, mut bol) = (0usize, 1usize, true);
    while i < cs.len() {
        let c = cs[i];
        if c == '\n' {
            line += 1;
            bol = true;
            i += 1;
            continue;
        }
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if bol && c == '#' {
            while i < cs.len() && cs[i] != '\n' {
                i += 1;
            }
            continue;
        }
        bol = false;
        if c == '/' && cs.get(i + 1) == Some(&'/') {
            while i < cs.len() && cs[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && cs.get(i + 1) == Some(&'*') {
            i += 2;
            while i < cs.len() && !(cs[i] == '*' && cs.get(i + 1) == Some(&'/')) {
                if cs[i] == '\n' {
                    line += 1;
                }
                i += 1;
            }
            i += 2;
        } else if c == '"' {
            let st = i;
            i += 1;
            while i < cs.len() && cs[i] != '"' {
                if cs[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push(Tok {
                s: cs[st..i.min(cs.len())].iter().collect(),
                line,
            });
        } else if c.is_alphanumeric() || c == '_' || c == '@' {
            let st = i;
            while i < cs.len() && (cs[i].is_alphanumeric() || cs[i] == '_' || cs[i] == '@') {
                i += 1;
            }
            out.push(Tok {
                s: cs[st..i].iter().collect(),
                line,
            });
        } else {
            out.push(Tok {
                s: c.to_string(),
                line,
            });
            i += 1;
        }
    }
    out
}

/// Splits tokens at top-level commas (nesting by `()`, `[]`, `<>`, `{}`).
fn split_commas(t: &[Tok]) -> Vec<Vec<Tok>> {
    let mut out = vec![Vec::new()];
    let mut depth = 0i32;
    for tok in t {
        match tok.s.as_str() {
            "(" | "[" | "{" | "<" => depth += 1,
            ")" | "]" | "}" | ">" => depth -= 1,
            "," if depth == 0 => {
                out.push(Vec::new());
                continue;
            }
            _ => {}
        }
        if let Some(last) = out.last_mut() {
            last.push(tok.clone());
        }
    }
    if out.len() == 1 && out[0].is_empty() {
        out.clear();
    }
    out
}

/// An attribute: its name and its arguments (`key` is `None` for positional ones).
#[derive(Debug, Clone, PartialEq, Eq)]
struct Attr {
    name: String,
    args: Vec<(Option<String>, String)>,
}

impl Attr {
    fn named(&self, key: &str) -> Option<&str> {
        self.args
            .iter()
            .find(|(k, _)| k.as_deref().is_some_and(|k| k.eq_ignore_ascii_case(key)))
            .map(|(_, v)| v.as_str())
    }
    fn positional(&self, i: usize) -> Option<&str> {
        self.args
            .iter()
            .filter(|(k, _)| k.is_none())
            .nth(i)
            .map(|(_, v)| v.as_str())
    }
}

/// Parses the tokens of one attribute (`Name(args)`, without the brackets); a leading
/// `return :` target is kept in the name as `return:Name`.
fn parse_attr(t: &[Tok]) -> Attr {
    let mut t = t;
    let mut prefix = String::new();
    if t.len() > 2 && t[0].s == "return" && t[1].s == ":" {
        prefix = "return:".into();
        t = &t[2..];
    }
    let name_end = t.iter().position(|x| x.s == "(").unwrap_or(t.len());
    let name: String = t[..name_end].iter().map(|x| x.s.as_str()).collect();
    let name = name
        .rsplit('.')
        .next()
        .unwrap_or_default()
        .trim_end_matches("Attribute")
        .to_string();
    let mut args = Vec::new();
    if name_end < t.len() {
        let inner = &t[name_end + 1..t.len().saturating_sub(1)];
        for a in split_commas(inner) {
            let eq = a.iter().position(|x| x.s == "=");
            let (k, v) = match eq {
                Some(p) => {
                    let k: String = a[..p]
                        .iter()
                        .map(|x| x.s.as_str())
                        .filter(|s| *s != ":")
                        .collect();
                    (Some(k), &a[p + 1..])
                }
                None => (None, &a[..]),
            };
            let v: String = v.iter().map(|x| x.s.as_str()).collect();
            args.push((k, v.trim_matches('"').to_string()));
        }
    }
    Attr {
        name: format!("{prefix}{name}"),
        args,
    }
}

fn last_word(v: &str) -> &str {
    v.rsplit('.').next().unwrap_or(v)
}

/// `MarshalAs(UnmanagedType.X)` override of a boolean's width.
fn bool_width(attrs: &[Attr]) -> u8 {
    match attrs
        .iter()
        .find(|a| a.name.ends_with("MarshalAs"))
        .and_then(|a| a.positional(0))
        .map(last_word)
    {
        Some("I1" | "U1") => 1,
        Some("VariantBool" | "I2" | "U2") => 2,
        _ => 4,
    }
}

/// The scalar ABI of a .NET type name, or `None` if it is not a scalar.
fn net_scalar(t: &str, attrs: &[Attr]) -> Option<Abi> {
    Some(match t.to_ascii_lowercase().as_str() {
        "byte" | "sbyte" | "system.byte" | "system.sbyte" => Abi::Int(1),
        // char marshals as one ANSI byte under the default CharSet.Ansi.
        "char" => Abi::Int(1),
        "short" | "ushort" | "int16" | "uint16" => Abi::Int(2),
        "int" | "uint" | "integer" | "uinteger" | "int32" | "uint32" => Abi::Int(4),
        "long" | "ulong" | "int64" | "uint64" => Abi::Int(8),
        "float" | "single" => Abi::Float(4),
        "double" => Abi::Float(8),
        "bool" | "boolean" => Abi::Int(bool_width(attrs)),
        _ => return None,
    })
}

fn ptr_to(a: Abi) -> Abi {
    match a {
        Abi::Int(w) => Abi::Ptr(Pointee::Int(w)),
        Abi::Float(w) => Abi::Ptr(Pointee::Float(w)),
        Abi::Struct(s) => Abi::Ptr(Pointee::Struct(s)),
        Abi::Ptr(_) => Abi::Ptr(Pointee::Int(8)),
        other => Abi::Bad(format!("pointer to {other:?}")),
    }
}

/// ABI of a .NET parameter type with its modifiers.
fn net_param_abi(
    ty: &str,
    by_ref: bool,
    array: bool,
    attrs: &[Attr],
    structs: &[String],
    delegates: &[String],
) -> Abi {
    let base = ty
        .trim_start_matches("System.Text.")
        .trim_start_matches("System.");
    let val = if let Some(s) = net_scalar(base, attrs) {
        s
    } else if base == "IntPtr" || base == "UIntPtr" {
        Abi::Ptr(Pointee::Any)
    } else if base == "string" || base == "String" || base == "StringBuilder" {
        // ANSI by default (CharSet.Ansi / VB Declare Ansi).
        if by_ref {
            return Abi::Bad(format!("ByRef/ref {base} is a pointer to a pointer"));
        }
        Abi::Ptr(Pointee::Int(1))
    } else if structs.iter().any(|s| s == base) {
        Abi::Struct(base.to_string())
    } else if delegates.iter().any(|d| d == base) {
        if by_ref || array {
            return Abi::Bad(format!("{base} by reference"));
        }
        Abi::Ptr(Pointee::Func(base.to_string()))
    } else {
        return Abi::Bad(format!("unknown type {ty}"));
    };
    if by_ref && array {
        return Abi::Bad("array by reference".into());
    }
    if by_ref || array {
        ptr_to(val)
    } else {
        val
    }
}

// ----------------------------------------------------------------------------------------
// C# parser

/// Reads `[...]` attribute groups at `t[i..]`; returns them and the index after them.
fn cs_attrs(t: &[Tok], mut i: usize) -> (Vec<Attr>, usize) {
    let mut out = Vec::new();
    while i < t.len() && t[i].s == "[" {
        let mut depth = 0;
        let st = i + 1;
        let mut j = i;
        while j < t.len() {
            match t[j].s.as_str() {
                "[" => depth += 1,
                "]" => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                _ => {}
            }
            j += 1;
        }
        for a in split_commas(&t[st..j.min(t.len())]) {
            let mut a = a;
            // `return: X` splits into its own tokens; keep it together.
            if a.len() > 1 && a[0].s == "return" && a[1].s == ":" {
                out.push(parse_attr(&a));
                continue;
            }
            if a.first().is_some_and(|x| x.s == "return") {
                a.remove(0);
            }
            out.push(parse_attr(&a));
        }
        i = j + 1;
    }
    (out, i)
}

/// A parsed C# parameter list: `(name, abi)` each.
fn cs_params(t: &[Tok], structs: &[String], delegates: &[String]) -> Result<Vec<BParam>, String> {
    let mut out = Vec::new();
    for p in split_commas(t) {
        let (attrs, mut i) = cs_attrs(&p, 0);
        let mut by_ref = false;
        while i < p.len() && matches!(p[i].s.as_str(), "ref" | "out" | "in" | "params" | "this") {
            by_ref |= p[i].s != "params" && p[i].s != "this";
            i += 1;
        }
        let eq = p.iter().position(|x| x.s == "=").unwrap_or(p.len());
        let decl = &p[i..eq];
        let name = decl
            .last()
            .map(|x| x.s.trim_start_matches('@').to_string())
            .ok_or("empty parameter")?;
        let ty_toks = &decl[..decl.len().saturating_sub(1)];
        let array = ty_toks.len() >= 2 && ty_toks[ty_toks.len() - 1].s == "]";
        let ty: String = ty_toks
            .iter()
            .filter(|x| x.s != "[" && x.s != "]")
            .map(|x| x.s.as_str())
            .collect();
        if ty.is_empty() {
            return Err(format!("parameter {name} without a type"));
        }
        out.push(BParam {
            abi: net_param_abi(&ty, by_ref, array, &attrs, structs, delegates),
            name,
        });
    }
    Ok(out)
}

fn net_ret(ty: &str, attrs: &[Attr], structs: &[String]) -> Abi {
    if ty == "void" {
        return Abi::Void;
    }
    let ret_attrs: Vec<Attr> = attrs
        .iter()
        .filter(|a| a.name.starts_with("return:"))
        .cloned()
        .collect();
    net_param_abi(ty, false, false, &ret_attrs, structs, &[])
}

/// Collects struct and delegate names first, so parameter types can be resolved.
fn cs_names(t: &[Tok]) -> (Vec<String>, Vec<String>) {
    let mut s = Vec::new();
    let mut d = Vec::new();
    for (i, tok) in t.iter().enumerate() {
        if tok.s == "struct" {
            if let Some(n) = t.get(i + 1) {
                s.push(n.s.clone());
            }
        } else if tok.s == "delegate" {
            // delegate RET NAME (
            if let Some(p) = t[i..].iter().position(|x| x.s == "(") {
                if p >= 1 {
                    d.push(t[i + p - 1].s.clone());
                }
            }
        }
    }
    (s, d)
}

/// Parses a C# binding file.
pub fn parse_cs(file: &str, text: &str) -> Result<Binding, String> {
    let t = lex_cs(text);
    let (snames, dnames) = cs_names(&t);
    let mut b = Binding::default();
    let mut i = 0;
    // Struct context: (name, fields, sequential, line, brace depth at open).
    let mut cur: Option<BStruct> = None;
    let mut depth = 0i32;
    let mut struct_depth = 0i32;
    while i < t.len() {
        if t[i].s == "}" {
            depth -= 1;
            if let Some(s) = cur.take() {
                if depth < struct_depth {
                    b.structs.push(s);
                } else {
                    cur = Some(s);
                }
            }
            i += 1;
            continue;
        }
        // One statement: up to ';' or '{' at this level.
        let (attrs, st) = cs_attrs(&t, i);
        let mut j = st;
        let mut paren = 0;
        while j < t.len() {
            match t[j].s.as_str() {
                "(" => paren += 1,
                ")" => paren -= 1,
                ";" | "{" | "}" if paren == 0 => break,
                _ => {}
            }
            j += 1;
        }
        let stmt = &t[st..j.min(t.len())];
        let end = t.get(j).map(|x| x.s.as_str()).unwrap_or(";");
        let line = stmt.first().map(|x| x.line).unwrap_or(0);
        let at = |m: &str| format!("{file}:{line}: {m}");
        let words: Vec<&str> = stmt.iter().map(|x| x.s.as_str()).collect();
        if end == "}" {
            i = j;
            continue;
        }
        i = j + 1;
        if end == "{" {
            depth += 1;
            if let Some(k) = words.iter().position(|w| *w == "struct") {
                let name = words
                    .get(k + 1)
                    .ok_or_else(|| at("struct without a name"))?;
                let sequential = attrs.iter().any(|a| {
                    a.name == "StructLayout"
                        && a.positional(0).map(last_word) == Some("Sequential")
                        && a.named("Pack").is_none_or(|p| p == "8" || p == "0")
                });
                cur = Some(BStruct {
                    name: name.to_string(),
                    fields: Vec::new(),
                    sequential,
                    line,
                });
                struct_depth = depth;
            } else if words.contains(&"(") && !words.contains(&"class") {
                // A method with a body: a public wrapper. Skip the body.
                let open = words.iter().position(|w| *w == "(").unwrap_or(0);
                let name = open
                    .checked_sub(1)
                    .and_then(|k| words.get(k))
                    .ok_or_else(|| at("method without a name"))?;
                let close = words.iter().rposition(|w| *w == ")").unwrap_or(open);
                if words.contains(&"public") {
                    b.methods.push(Method {
                        name: name.to_string(),
                        nparams: split_commas(&stmt[open + 1..close]).len(),
                        line,
                    });
                }
                let mut d = 1;
                while i < t.len() && d > 0 {
                    match t[i].s.as_str() {
                        "{" => d += 1,
                        "}" => d -= 1,
                        _ => {}
                    }
                    i += 1;
                }
                depth -= 1;
            }
            continue;
        }
        // ';'-terminated statements.
        if let Some(s) = cur.as_mut() {
            if words.is_empty() || words.contains(&"const") || words.contains(&"static") {
                continue;
            }
            // [attrs] public TYPE[[]] NAME
            let mut k = 0;
            while k < words.len()
                && matches!(words[k], "public" | "private" | "internal" | "readonly")
            {
                k += 1;
            }
            let name = words.last().ok_or_else(|| at("empty field"))?;
            let ty_words = &words[k..words.len() - 1];
            let array = ty_words.last() == Some(&"]");
            let ty: String = ty_words
                .iter()
                .filter(|w| **w != "[" && **w != "]")
                .copied()
                .collect();
            let size_const = attrs
                .iter()
                .find(|a| a.name == "MarshalAs")
                .and_then(|a| a.named("SizeConst"))
                .map(str::to_string);
            let count = match (array, size_const) {
                (true, Some(n)) => Some(
                    n.parse::<usize>()
                        .map_err(|_| at(&format!("SizeConst {n:?} is not a number")))?,
                ),
                (true, None) => None,
                (false, _) => None,
            };
            let elem = if array && count.is_none() {
                Elem::Bad("array without [MarshalAs(ByValArray, SizeConst)] is a reference".into())
            } else {
                net_elem(&ty, &attrs, &snames)
            };
            s.fields.push(BField {
                name: name.trim_start_matches('@').to_string(),
                elem,
                count,
            });
            continue;
        }
        if words.contains(&"const") {
            // public const T NAME = VALUE
            if let Some(eq) = words.iter().position(|w| *w == "=") {
                let name = words[eq - 1].to_string();
                let v: String = words[eq + 1..].concat();
                if let Ok(v) = v.parse::<i64>() {
                    b.consts.push((name, v, line));
                }
            }
            continue;
        }
        let Some(open) = words.iter().position(|w| *w == "(") else {
            continue;
        };
        let close = words.iter().rposition(|w| *w == ")").unwrap_or(open);
        let name = open
            .checked_sub(1)
            .and_then(|k| words.get(k))
            .ok_or_else(|| at("declaration without a name"))?
            .trim_start_matches('@')
            .to_string();
        let ret_ty: String = words[..open - 1]
            .iter()
            .filter(|w| {
                !matches!(
                    **w,
                    "public"
                        | "private"
                        | "internal"
                        | "static"
                        | "extern"
                        | "delegate"
                        | "unsafe"
                        | "new"
                )
            })
            .copied()
            .collect();
        let params = cs_params(&stmt[open + 1..close], &snames, &dnames).map_err(|e| at(&e))?;
        let conv_of = |attr: &str| {
            attrs
                .iter()
                .find(|a| a.name == attr)
                .and_then(|a| {
                    a.named("CallingConvention").or_else(|| {
                        if attr == "UnmanagedFunctionPointer" {
                            a.positional(0)
                        } else {
                            None
                        }
                    })
                })
                .map(|c| last_word(c).to_string())
        };
        if words.contains(&"delegate") {
            b.delegates.push(BDelegate {
                name,
                ret: net_ret(&ret_ty, &attrs, &snames),
                params,
                conv: conv_of("UnmanagedFunctionPointer"),
                line,
            });
        } else if words.contains(&"extern") {
            let dll = attrs
                .iter()
                .find(|a| a.name == "DllImport")
                .ok_or_else(|| at(&format!("extern {name} without [DllImport]")))?;
            b.externs.push(Extern {
                entry: dll.named("EntryPoint").unwrap_or(&name).to_string(),
                lib: dll.positional(0).unwrap_or_default().to_string(),
                public: words.contains(&"public"),
                ret: net_ret(&ret_ty, &attrs, &snames),
                params,
                conv: conv_of("DllImport"),
                name,
                line,
            });
        }
    }
    Ok(b)
}

fn net_elem(ty: &str, attrs: &[Attr], structs: &[String]) -> Elem {
    match net_scalar(ty, attrs) {
        Some(Abi::Int(w)) => Elem::Int(w),
        Some(Abi::Float(w)) => Elem::Float(w),
        _ if structs.iter().any(|s| s == ty) => Elem::Struct(ty.to_string()),
        _ => Elem::Bad(format!("type {ty} has no fixed inline layout")),
    }
}

// ----------------------------------------------------------------------------------------
// VB parsers (VB6 and VB.NET), line based.

/// Logical lines: comments removed (outside strings), `_` continuations joined.
fn vb_lines(text: &str) -> Vec<(usize, String)> {
    let mut out: Vec<(usize, String)> = Vec::new();
    let mut acc: Option<(usize, String)> = None;
    for (n, raw) in text.lines().enumerate() {
        let mut s = String::new();
        let mut in_str = false;
        for c in raw.chars() {
            if c == '"' {
                in_str = !in_str;
            }
            if c == '\'' && !in_str {
                break;
            }
            s.push(c);
        }
        let s = s.trim_end().to_string();
        let cont = s.ends_with(" _") || s == "_";
        let body = if cont {
            s[..s.len() - 1].to_string()
        } else {
            s
        };
        match acc.as_mut() {
            Some((_, a)) => {
                a.push(' ');
                a.push_str(body.trim());
            }
            None => acc = Some((n + 1, body.trim().to_string())),
        }
        if !cont {
            if let Some(l) = acc.take() {
                if !l.1.is_empty() {
                    out.push(l);
                }
            }
        }
    }
    if let Some(l) = acc {
        out.push(l);
    }
    out
}

/// Tokenizes one VB line (identifiers with `[...]` escapes unwrapped, strings, numbers,
/// `&H` hex, punctuation).
fn lex_vb(s: &str, line: usize) -> Vec<Tok> {
    let cs: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c.is_whitespace() {
            i += 1;
        } else if c == '"' {
            let st = i;
            i += 1;
            while i < cs.len() && cs[i] != '"' {
                i += 1;
            }
            i += 1;
            out.push(Tok {
                s: cs[st..i.min(cs.len())].iter().collect(),
                line,
            });
        } else if c == '&' && matches!(cs.get(i + 1), Some('H' | 'h')) {
            let st = i;
            i += 2;
            while i < cs.len() && (cs[i].is_ascii_hexdigit() || cs[i] == '&') {
                i += 1;
            }
            out.push(Tok {
                s: cs[st..i].iter().collect(),
                line,
            });
        } else if c == '[' {
            let st = i + 1;
            while i < cs.len() && cs[i] != ']' {
                i += 1;
            }
            out.push(Tok {
                s: cs[st..i.min(cs.len())].iter().collect(),
                line,
            });
            i += 1;
        } else if c.is_alphanumeric() || c == '_' {
            let st = i;
            while i < cs.len() && (cs[i].is_alphanumeric() || cs[i] == '_') {
                i += 1;
            }
            out.push(Tok {
                s: cs[st..i].iter().collect(),
                line,
            });
        } else {
            out.push(Tok {
                s: c.to_string(),
                line,
            });
            i += 1;
        }
    }
    out
}

fn eqi(a: &str, b: &str) -> bool {
    a.eq_ignore_ascii_case(b)
}

/// Reads `<...>` attribute groups at the start of a VB token list.
fn vb_attrs(t: &[Tok]) -> (Vec<Attr>, usize) {
    let mut out = Vec::new();
    let mut i = 0;
    while i < t.len() && t[i].s == "<" {
        let mut depth = 0;
        let mut j = i;
        while j < t.len() {
            match t[j].s.as_str() {
                "<" | "(" => depth += 1,
                ">" | ")" => {
                    depth -= 1;
                    if depth == 0 && t[j].s == ">" {
                        break;
                    }
                }
                _ => {}
            }
            j += 1;
        }
        for a in split_commas(&t[i + 1..j.min(t.len())]) {
            // VB named arguments are `Key:=Value`: drop the ':' so parse_attr sees '='.
            let a: Vec<Tok> = a.into_iter().filter(|x| x.s != ":").collect();
            out.push(parse_attr(&a));
        }
        i = j + 1;
    }
    (out, i)
}

fn vb6_type_abi(ty: &str, by_val: bool, structs: &[String]) -> Abi {
    let scalar = match ty.to_ascii_lowercase().as_str() {
        "byte" => Some(Abi::Int(1)),
        "integer" | "boolean" => Some(Abi::Int(2)),
        "long" => Some(Abi::Int(4)),
        "single" => Some(Abi::Float(4)),
        "double" => Some(Abi::Float(8)),
        "currency" | "date" => Some(Abi::Int(8)),
        _ => None,
    };
    match (scalar, by_val) {
        (Some(s), true) => s,
        (Some(s), false) => ptr_to(s),
        (None, _) if eqi(ty, "String") => {
            if by_val {
                Abi::Ptr(Pointee::Int(1))
            } else {
                Abi::Bad("ByRef String passes a BSTR pointer".into())
            }
        }
        (None, false) if eqi(ty, "Any") => Abi::Ptr(Pointee::Any),
        (None, _) if structs.iter().any(|s| eqi(s, ty)) => {
            if by_val {
                Abi::Bad(format!("ByVal {ty}: VB6 cannot pass a UDT by value"))
            } else {
                Abi::Ptr(Pointee::Struct(ty.to_string()))
            }
        }
        _ => Abi::Bad(format!("unknown VB6 type {ty}")),
    }
}

/// One VB parameter: `[<attrs>] [Optional] [ByVal|ByRef] [ParamArray] NAME[()] [As TYPE] [= d]`.
fn vb_param(
    p: &[Tok],
    vb6: bool,
    structs: &[String],
    delegates: &[String],
) -> Result<BParam, String> {
    let (attrs, mut i) = vb_attrs(p);
    let mut by_val = !vb6;
    while i < p.len() {
        match p[i].s.to_ascii_lowercase().as_str() {
            "optional" | "paramarray" => {}
            "byval" => by_val = true,
            "byref" => by_val = false,
            _ => break,
        }
        i += 1;
    }
    let name = p.get(i).ok_or("parameter without a name")?.s.clone();
    i += 1;
    let array = p.get(i).is_some_and(|x| x.s == "(");
    if array {
        i += 2;
    }
    let ty = match p.get(i) {
        Some(x) if eqi(&x.s, "As") => {
            let mut ty = String::new();
            let mut k = i + 1;
            while k < p.len() && p[k].s != "=" {
                ty.push_str(&p[k].s);
                k += 1;
            }
            ty
        }
        _ => "Variant".into(),
    };
    let abi = if vb6 {
        if array {
            Abi::Bad("VB6 array parameter passes a SAFEARRAY".into())
        } else {
            vb6_type_abi(&ty, by_val, structs)
        }
    } else {
        net_param_abi(&ty, !by_val, array, &attrs, structs, delegates)
    };
    Ok(BParam { name, abi })
}

/// Splits `NAME ( params ) [As TYPE]` at the top-level parentheses.
fn vb_sig(t: &[Tok]) -> Option<(usize, usize)> {
    let open = t.iter().position(|x| x.s == "(")?;
    let mut depth = 0;
    for (k, x) in t.iter().enumerate().skip(open) {
        match x.s.as_str() {
            "(" => depth += 1,
            ")" => {
                depth -= 1;
                if depth == 0 {
                    return Some((open, k));
                }
            }
            _ => {}
        }
    }
    None
}

fn vb_const(t: &[Tok]) -> Option<(String, i64)> {
    let k = t.iter().position(|x| eqi(&x.s, "Const"))?;
    let name = t.get(k + 1)?.s.clone();
    let eq = t.iter().position(|x| x.s == "=")?;
    let v: String = t[eq + 1..].iter().map(|x| x.s.as_str()).collect();
    let v = if let Some(h) = v.strip_prefix("&H").or_else(|| v.strip_prefix("&h")) {
        // VB6 `&H...&` is a 32-bit Long: reinterpret the bits as signed, as VB6 does.
        let u = u32::from_str_radix(h.trim_end_matches('&'), 16).ok()?;
        i64::from(u)
    } else {
        v.parse().ok()?
    };
    Some((name, v))
}

/// Parses a VB6 `.bas` module or a VB.NET `.vb` file.
pub fn parse_vb(file: &str, text: &str, vb6: bool) -> Result<Binding, String> {
    let lines = vb_lines(text);
    let toks: Vec<Vec<Tok>> = lines.iter().map(|(n, s)| lex_vb(s, *n)).collect();
    let option_base_1 = lines
        .iter()
        .any(|(_, s)| s.to_ascii_lowercase().replace(' ', "") == "optionbase1");
    // Names first.
    let mut snames = Vec::new();
    let mut dnames = Vec::new();
    for t in &toks {
        let (_, s) = vb_attrs(t);
        let w: Vec<String> = t[s..].iter().map(|x| x.s.to_ascii_lowercase()).collect();
        let kw = w
            .iter()
            .position(|x| x == "type" || x == "structure" || x == "delegate");
        if let Some(k) = kw {
            if k == 0
                || matches!(
                    w[k - 1].as_str(),
                    "public" | "private" | "friend" | "global"
                )
            {
                match w[k].as_str() {
                    "delegate" => {
                        if let Some(n) = t.get(s + k + 2) {
                            dnames.push(n.s.clone());
                        }
                    }
                    _ => {
                        if let Some(n) = t.get(s + k + 1) {
                            snames.push(n.s.clone());
                        }
                    }
                }
            }
        }
    }
    let mut b = Binding::default();
    let mut pending: Vec<Attr> = Vec::new();
    let mut cur: Option<BStruct> = None;
    let mut skip_until: Option<String> = None;
    for (t, (line, _)) in toks.iter().zip(&lines) {
        let line = *line;
        let at = |m: &str| format!("{file}:{line}: {m}");
        let (mut attrs, s) = vb_attrs(t);
        let t = &t[s..];
        if t.is_empty() {
            pending.append(&mut attrs);
            continue;
        }
        let mut all = std::mem::take(&mut pending);
        all.append(&mut attrs);
        let attrs = all;
        let w: Vec<String> = t.iter().map(|x| x.s.to_ascii_lowercase()).collect();
        if let Some(end) = &skip_until {
            if w.len() >= 2 && w[0] == "end" && &w[1] == end {
                skip_until = None;
            }
            continue;
        }
        if let Some(st) = cur.as_mut() {
            if w[0] == "end" {
                if let Some(s) = cur.take() {
                    b.structs.push(s);
                }
                continue;
            }
            // [Public|Dim] NAME[(bounds)] As TYPE
            let mut k = 0;
            while k < w.len() && matches!(w[k].as_str(), "public" | "dim" | "private") {
                k += 1;
            }
            let name = t.get(k).ok_or_else(|| at("empty field"))?.s.clone();
            let as_pos = w
                .iter()
                .position(|x| x == "as")
                .ok_or_else(|| at(&format!("field {name} without As")))?;
            let ty: String = t[as_pos + 1..].iter().map(|x| x.s.as_str()).collect();
            let bounds = &t[k + 1..as_pos];
            let mut count = None;
            if !bounds.is_empty() {
                let inner: Vec<&str> = bounds
                    .iter()
                    .map(|x| x.s.as_str())
                    .filter(|x| *x != "(" && *x != ")")
                    .collect();
                let n = match inner.as_slice() {
                    [lo, to, hi] if eqi(to, "To") => {
                        let lo: i64 = lo.parse().map_err(|_| at("bad lower bound"))?;
                        let hi: i64 = hi.parse().map_err(|_| at("bad upper bound"))?;
                        hi - lo + 1
                    }
                    [hi] if vb6 => {
                        let hi: i64 = hi.parse().map_err(|_| at("bad bound"))?;
                        if option_base_1 {
                            hi
                        } else {
                            hi + 1
                        }
                    }
                    [] if !vb6 => {
                        let sc = attrs
                            .iter()
                            .find(|a| a.name == "MarshalAs")
                            .and_then(|a| a.named("SizeConst"))
                            .ok_or_else(|| at(&format!("array {name} without SizeConst")))?;
                        sc.parse().map_err(|_| at("SizeConst is not a number"))?
                    }
                    _ => return Err(at(&format!("unsupported bounds for {name}"))),
                };
                count = Some(usize::try_from(n).map_err(|_| at("negative array size"))?);
            }
            let elem = if vb6 {
                match vb6_type_abi(&ty, true, &[]) {
                    Abi::Int(wd) => Elem::Int(wd),
                    Abi::Float(wd) => Elem::Float(wd),
                    _ if snames.iter().any(|s| eqi(s, &ty)) => Elem::Struct(ty.clone()),
                    _ => Elem::Bad(format!("type {ty} has no fixed inline layout")),
                }
            } else {
                net_elem(&ty, &attrs, &snames)
            };
            st.fields.push(BField { name, elem, count });
            continue;
        }
        let mut k = 0;
        let mut public = vb6; // VB6 module-level declarations are public by default
        while k < w.len()
            && matches!(
                w[k].as_str(),
                "public" | "private" | "friend" | "global" | "shared" | "overloads" | "static"
            )
        {
            if w[k] == "private" {
                public = false;
            } else if w[k] == "public" || w[k] == "global" {
                public = true;
            }
            k += 1;
        }
        let Some(kw) = w.get(k) else { continue };
        match kw.as_str() {
            "type" | "structure" => {
                let name = t
                    .get(k + 1)
                    .ok_or_else(|| at("Type without a name"))?
                    .s
                    .clone();
                let sequential = vb6
                    || attrs.iter().any(|a| {
                        a.name == "StructLayout"
                            && a.positional(0).map(last_word) == Some("Sequential")
                            && a.named("Pack").is_none_or(|p| p == "8" || p == "0")
                    });
                cur = Some(BStruct {
                    name,
                    fields: Vec::new(),
                    sequential,
                    line,
                });
            }
            "const" => {
                if let Some((n, v)) = vb_const(t) {
                    b.consts.push((n, v, line));
                }
            }
            "declare" | "function" | "sub" | "delegate" => {
                let mut k2 = k;
                let declare = kw == "declare";
                let delegate = kw == "delegate";
                if declare || delegate {
                    k2 += 1;
                    while k2 < w.len() && matches!(w[k2].as_str(), "ansi" | "unicode" | "auto") {
                        k2 += 1;
                    }
                }
                let is_sub = w.get(k2).map(String::as_str) == Some("sub");
                let name = t
                    .get(k2 + 1)
                    .ok_or_else(|| at("declaration without a name"))?
                    .s
                    .clone();
                let (open, close) = vb_sig(&t[k2..])
                    .map(|(a, c)| (a + k2, c + k2))
                    .ok_or_else(|| at(&format!("{name}: no parameter list")))?;
                let mut params = Vec::new();
                for p in split_commas(&t[open + 1..close]) {
                    params.push(vb_param(&p, vb6, &snames, &dnames).map_err(|e| at(&e))?);
                }
                let ret = if is_sub {
                    Abi::Void
                } else {
                    match w.get(close + 1).map(String::as_str) {
                        Some("as") => {
                            let (rattrs, rs) = vb_attrs(&t[close + 2..]);
                            let ty: String =
                                t[close + 2 + rs..].iter().map(|x| x.s.as_str()).collect();
                            if vb6 {
                                vb6_type_abi(&ty, true, &snames)
                            } else {
                                let ra: Vec<Attr> = rattrs;
                                net_param_abi(&ty, false, false, &ra, &snames, &[])
                            }
                        }
                        _ => Abi::Bad("function without As: returns a Variant".into()),
                    }
                };
                let conv = |attr: &str| {
                    attrs
                        .iter()
                        .find(|a| a.name == attr)
                        .and_then(|a| {
                            a.named("CallingConvention").or_else(|| {
                                if attr == "UnmanagedFunctionPointer" {
                                    a.positional(0)
                                } else {
                                    None
                                }
                            })
                        })
                        .map(|c| last_word(c).to_string())
                };
                if delegate {
                    b.delegates.push(BDelegate {
                        name,
                        params,
                        ret,
                        conv: conv("UnmanagedFunctionPointer"),
                        line,
                    });
                } else if declare {
                    let lib_pos = w
                        .iter()
                        .position(|x| x == "lib")
                        .ok_or_else(|| at(&format!("Declare {name} without Lib")))?;
                    let lib = t
                        .get(lib_pos + 1)
                        .map(|x| x.s.trim_matches('"').to_string())
                        .unwrap_or_default();
                    let entry = match w.iter().position(|x| x == "alias") {
                        Some(a) => t
                            .get(a + 1)
                            .map(|x| x.s.trim_matches('"').to_string())
                            .unwrap_or_default(),
                        None => name.clone(),
                    };
                    b.externs.push(Extern {
                        name,
                        entry,
                        lib,
                        public,
                        params,
                        ret,
                        conv: None,
                        line,
                    });
                } else if let Some(dll) = attrs.iter().find(|a| a.name == "DllImport") {
                    b.externs.push(Extern {
                        entry: dll.named("EntryPoint").unwrap_or(&name).to_string(),
                        lib: dll.positional(0).unwrap_or_default().to_string(),
                        public,
                        params,
                        ret,
                        conv: conv("DllImport"),
                        name,
                        line,
                    });
                    skip_until = Some(if is_sub { "sub" } else { "function" }.into());
                } else {
                    if public {
                        b.methods.push(Method {
                            name,
                            nparams: params.len(),
                            line,
                        });
                    }
                    skip_until = Some(if is_sub { "sub" } else { "function" }.into());
                }
            }
            _ => {}
        }
    }
    if let Some(s) = cur {
        return Err(format!("{file}:{}: Type {} not closed", s.line, s.name));
    }
    Ok(b)
}

// ----------------------------------------------------------------------------------------
// Verification

/// The ABI the C type has for a caller on a platform whose C `long` is `clong` bytes.
fn c_abi(h: &Header, t: &CType, clong: u8) -> Abi {
    let pointee = |t: &CType| match t {
        CType::Int { bytes, .. } => Pointee::Int(*bytes),
        CType::Bool => Pointee::Int(4),
        CType::Char => Pointee::Int(1),
        CType::CLong { .. } => Pointee::Int(clong),
        CType::Float(b) => Pointee::Float(*b),
        CType::Struct(s) => Pointee::Struct(h.canonical(s).to_string()),
        CType::Void => Pointee::Any,
        CType::Ptr(_) | CType::Callback(_) => Pointee::Int(8),
    };
    match t {
        CType::Void => Abi::Void,
        CType::Int { bytes, .. } => Abi::Int(*bytes),
        CType::Bool => Abi::Int(4),
        CType::Char => Abi::Int(1),
        CType::CLong { .. } => Abi::Int(clong),
        CType::Float(b) => Abi::Float(*b),
        CType::Struct(s) => Abi::Struct(h.canonical(s).to_string()),
        CType::Callback(c) => Abi::Ptr(Pointee::Func(c.clone())),
        CType::Ptr(inner) => Abi::Ptr(pointee(inner)),
    }
}

fn canon_abi(h: &Header, a: &Abi) -> Abi {
    match a {
        Abi::Struct(s) => Abi::Struct(h.canonical(&upper_struct(h, s)).to_string()),
        Abi::Ptr(Pointee::Struct(s)) => Abi::Ptr(Pointee::Struct(
            h.canonical(&upper_struct(h, s)).to_string(),
        )),
        a => a.clone(),
    }
}

/// VB names are case-insensitive: map a struct name to the header's spelling.
fn upper_struct(h: &Header, s: &str) -> String {
    h.structs
        .iter()
        .find(|x| eqi(&x.name, s))
        .map(|x| x.name.clone())
        .unwrap_or_else(|| s.to_string())
}

/// Whether the binding's `b` is an acceptable declaration of C's `c` in `lang`.
fn abi_ok(lang: Lang, c: &Abi, b: &Abi) -> bool {
    if c == b {
        return true;
    }
    match (c, b) {
        // IntPtr / As Any stand for any pointer, and void* accepts any pointer.
        (Abi::Ptr(_), Abi::Ptr(Pointee::Any)) | (Abi::Ptr(Pointee::Any), Abi::Ptr(_)) => true,
        // VB6 passes callbacks as `ByVal Long` (AddressOf; Win32 pointers are 4 bytes).
        (Abi::Ptr(Pointee::Func(_)), Abi::Int(4)) => lang == Lang::Vb6,
        _ => false,
    }
}

fn show(a: &Abi) -> String {
    match a {
        Abi::Void => "void".into(),
        Abi::Int(w) => format!("{w}-byte integer by value"),
        Abi::Float(w) => format!("{w}-byte float by value"),
        Abi::Struct(s) => format!("struct {s} by value"),
        Abi::Ptr(Pointee::Int(w)) => format!("pointer to {w}-byte integer (by reference)"),
        Abi::Ptr(Pointee::Float(w)) => format!("pointer to {w}-byte float (by reference)"),
        Abi::Ptr(Pointee::Struct(s)) => format!("pointer to {s} (by reference)"),
        Abi::Ptr(Pointee::Func(f)) => format!("function pointer {f}"),
        Abi::Ptr(Pointee::Any) => "pointer".into(),
        Abi::Bad(r) => format!("invalid ({r})"),
    }
}

/// Compares a binding signature with a C one; returns the differences.
fn sig_diff(
    h: &Header,
    lang: Lang,
    clong: u8,
    c_params: &[crate::model::Param],
    c_ret: &CType,
    params: &[BParam],
    ret: &Abi,
) -> Vec<String> {
    let mut d = Vec::new();
    if c_params.len() != params.len() {
        d.push(format!(
            "{} parameters, the C prototype has {}",
            params.len(),
            c_params.len()
        ));
        return d;
    }
    for (i, (cp, bp)) in c_params.iter().zip(params).enumerate() {
        let ca = c_abi(h, &cp.ty, clong);
        let ba = canon_abi(h, &bp.abi);
        if !abi_ok(lang, &ca, &ba) {
            d.push(format!(
                "parameter {} ({}): declared as {}, C has {}",
                i + 1,
                bp.name,
                show(&ba),
                show(&ca)
            ));
        }
    }
    let cr = c_abi(h, c_ret, clong);
    let br = canon_abi(h, ret);
    if !abi_ok(lang, &cr, &br) {
        d.push(format!(
            "return: declared as {}, C has {}",
            show(&br),
            show(&cr)
        ));
    }
    d
}

fn vb_eq(lang: Lang, c: &str, b: &str) -> bool {
    match lang {
        Lang::CSharp => c == b,
        Lang::Vb6 => eqi(c, b) || eqi(&format!("{c}_"), b),
        Lang::VbNet => eqi(c, b),
    }
}

/// A binding struct's layout: `(field name, offset, size)` per field, total size, alignment.
type BLayout = (Vec<(String, usize, usize)>, usize, usize);

/// Layout of a binding struct, computed from the binding's own declarations.
fn b_layout(
    lang: Lang,
    b: &Binding,
    name: &str,
    seen: &mut Vec<String>,
) -> Result<BLayout, String> {
    if seen.iter().any(|s| eqi(s, name)) {
        return Err(format!("{name} contains itself"));
    }
    let s = b
        .structs
        .iter()
        .find(|s| eqi(&s.name, name))
        .ok_or_else(|| format!("struct {name} is not declared"))?;
    let max_align = if lang == Lang::Vb6 { 4 } else { 8 };
    seen.push(name.to_string());
    let mut off = 0usize;
    let mut align = 1usize;
    let mut out = Vec::new();
    for f in &s.fields {
        let (size, al) = match &f.elem {
            Elem::Int(w) | Elem::Float(w) => (usize::from(*w), usize::from(*w)),
            Elem::Struct(n) => {
                let (_, sz, al) = b_layout(lang, b, n, seen)?;
                (sz, al)
            }
            Elem::Bad(r) => return Err(format!("{}.{}: {r}", s.name, f.name)),
        };
        let a = al.clamp(1, max_align);
        off = off.div_ceil(a) * a;
        let n = f.count.unwrap_or(1);
        out.push((f.name.clone(), off, size * n));
        off += size * n;
        align = align.max(a);
    }
    seen.pop();
    Ok((out, off.div_ceil(align) * align, align))
}

fn c_elem(h: &Header, t: &CType) -> Elem {
    match t {
        CType::Int { bytes, .. } => Elem::Int(*bytes),
        CType::Bool => Elem::Int(4),
        CType::Char => Elem::Int(1),
        CType::Float(b) => Elem::Float(*b),
        CType::Struct(s) => Elem::Struct(h.canonical(s).to_string()),
        other => Elem::Bad(format!("{other:?}")),
    }
}

fn is_pad(name: &str) -> bool {
    name.starts_with("MCCL_pad")
}

/// Checks one binding file against the header and the exported symbols.
pub fn verify(lang: Lang, file: &str, text: &str, h: &Header, exports: &[String]) -> Report {
    let mut r = Report::default();
    let b = match match lang {
        Lang::CSharp => parse_cs(file, text),
        Lang::Vb6 => parse_vb(file, text, true),
        Lang::VbNet => parse_vb(file, text, false),
    } {
        Ok(b) => b,
        Err(e) => {
            r.problems.push(e);
            return r;
        }
    };
    verify_binding(lang, file, &b, h, exports, &mut r);
    r
}

/// The checks on an already parsed binding.
pub fn verify_binding(
    lang: Lang,
    file: &str,
    b: &Binding,
    h: &Header,
    exports: &[String],
    r: &mut Report,
) {
    let mut p = |line: usize, m: String| r.problems.push(format!("{file}:{line}: {m}"));
    // --- functions
    let mut by_entry: BTreeMap<&str, Vec<&Extern>> = BTreeMap::new();
    for e in &b.externs {
        by_entry.entry(e.entry.as_str()).or_default().push(e);
        if !e.lib.to_ascii_lowercase().starts_with("mcclpci_imp") {
            p(
                e.line,
                format!("{}: library {:?} is not MCCLPCI_IMP", e.name, e.lib),
            );
        }
        if let Some(c) = &e.conv {
            if !matches!(c.as_str(), "Winapi" | "StdCall") {
                p(e.line, format!("{}: calling convention {c}; MCC_CALL is stdcall on Windows (use the default/Winapi)", e.name));
            }
        }
        if !exports.iter().any(|s| s == &e.entry) {
            p(
                e.line,
                format!(
                    "{}: entry point {} is not exported by the library",
                    e.name, e.entry
                ),
            );
        }
        if !h.funcs.iter().any(|f| f.name == e.entry) {
            p(
                e.line,
                format!(
                    "{}: entry point {} is not declared in MCCL_Fun.h",
                    e.name, e.entry
                ),
            );
        }
    }
    let mut n_externs = 0;
    let mut n_params = 0;
    for f in &h.funcs {
        r.functions += 1;
        let decls = by_entry.get(f.name.as_str()).cloned().unwrap_or_default();
        if decls.is_empty() {
            p(
                0,
                format!(
                    "{} is missing (declared in MCCL_Fun.h{})",
                    f.name,
                    if exports.contains(&f.name) {
                        ", exported by the library"
                    } else {
                        ""
                    }
                ),
            );
            continue;
        }
        let mut covered = [false, false]; // clong 4, clong 8
        for e in &decls {
            n_externs += 1;
            n_params += e.params.len();
            let d4 = sig_diff(h, lang, 4, &f.params, &f.ret, &e.params, &e.ret);
            let d8 = sig_diff(h, lang, 8, &f.params, &f.ret, &e.params, &e.ret);
            covered[0] |= d4.is_empty();
            covered[1] |= d8.is_empty();
            if d4.is_empty() || (d8.is_empty() && lang != Lang::Vb6) {
                continue;
            }
            let d = if lang == Lang::Vb6 || !f.has_clong() {
                d4
            } else {
                d8
            };
            for m in d {
                p(e.line, format!("{}: {m}", e.name));
            }
        }
        if f.has_clong() && lang != Lang::Vb6 {
            for (ok, w) in covered.iter().zip([4, 8]) {
                if !ok {
                    p(
                        decls[0].line,
                        format!(
                            "{}: no declaration for a {w}-byte C long (needed on {})",
                            f.name,
                            if w == 4 { "Windows" } else { "LP64 Linux" }
                        ),
                    );
                }
            }
        }
        // Callable by its own name with the C parameter count.
        let callable = decls
            .iter()
            .any(|e| e.public && vb_eq(lang, &f.name, &e.name) && e.params.len() == f.params.len())
            || b.methods
                .iter()
                .any(|m| vb_eq(lang, &f.name, &m.name) && m.nparams == f.params.len());
        if !callable {
            p(
                decls[0].line,
                format!(
                    "{}: no public method of that name with {} parameters",
                    f.name,
                    f.params.len()
                ),
            );
        }
    }
    for s in exports.iter().filter(|s| s.starts_with("MCC_")) {
        if !by_entry.contains_key(s.as_str()) && !h.funcs.iter().any(|f| &f.name == s) {
            p(
                0,
                format!("{s} is exported by the library but declared nowhere"),
            );
        }
    }
    // --- structs
    let mut n_structs = 0;
    let mut n_fields = 0;
    for cs in &h.structs {
        let Some(bs) = b.structs.iter().find(|s| vb_eq(lang, &cs.name, &s.name)) else {
            p(0, format!("struct {} is missing", cs.name));
            continue;
        };
        n_structs += 1;
        if !bs.sequential {
            p(
                bs.line,
                format!(
                    "{}: not [StructLayout(LayoutKind.Sequential)] with the default pack",
                    bs.name
                ),
            );
        }
        let named: Vec<&BField> = bs.fields.iter().filter(|f| !is_pad(&f.name)).collect();
        if named.len() != cs.fields.len() {
            p(
                bs.line,
                format!(
                    "{}: {} fields, C has {}",
                    bs.name,
                    named.len(),
                    cs.fields.len()
                ),
            );
        }
        for (i, (cf, bf)) in cs.fields.iter().zip(&named).enumerate() {
            n_fields += 1;
            if !vb_eq(lang, &cf.name, &bf.name) {
                p(
                    bs.line,
                    format!(
                        "{}: field {} is {}, C has {}",
                        bs.name,
                        i + 1,
                        bf.name,
                        cf.name
                    ),
                );
            }
            let ce = c_elem(h, &cf.ty);
            let be = match &bf.elem {
                Elem::Struct(s) => Elem::Struct(h.canonical(&upper_struct(h, s)).to_string()),
                e => e.clone(),
            };
            if ce != be {
                p(
                    bs.line,
                    format!("{}.{}: element {:?}, C has {:?}", bs.name, bf.name, be, ce),
                );
            }
            if cf.count != bf.count {
                p(
                    bs.line,
                    format!(
                        "{}.{}: array length {:?}, C has {:?}",
                        bs.name, bf.name, bf.count, cf.count
                    ),
                );
            }
        }
        match (
            b_layout(lang, b, &bs.name, &mut Vec::new()),
            h.struct_layout(&cs.name, WIN),
        ) {
            (Ok((slots, size, _)), Ok(cl)) => {
                let named: Vec<&(String, usize, usize)> =
                    slots.iter().filter(|s| !is_pad(&s.0)).collect();
                for (bsl, csl) in named.iter().zip(&cl.slots) {
                    if bsl.1 != csl.offset {
                        p(
                            bs.line,
                            format!(
                                "{}.{}: offset {}, C has {}",
                                bs.name, bsl.0, bsl.1, csl.offset
                            ),
                        );
                    }
                }
                if size != cl.size {
                    p(
                        bs.line,
                        format!("{}: size {size}, C has {}", bs.name, cl.size),
                    );
                }
                if let Some((_, known)) = KNOWN_SIZES.iter().find(|(n, _)| *n == cs.name) {
                    if cl.size != *known {
                        p(
                            bs.line,
                            format!(
                                "{}: the C header gives {} bytes, the vendor layout is {known}",
                                cs.name, cl.size
                            ),
                        );
                    }
                }
            }
            (Err(e), _) | (_, Err(e)) => p(bs.line, e),
        }
    }
    for bs in &b.structs {
        if !h.structs.iter().any(|c| vb_eq(lang, &c.name, &bs.name)) {
            p(bs.line, format!("struct {} is not in MCCL.h", bs.name));
        }
    }
    // --- delegates (not in VB6: callbacks are AddressOf Longs there)
    let mut n_delegates = 0;
    if lang != Lang::Vb6 {
        for cb in &h.callbacks {
            let Some(d) = b.delegates.iter().find(|d| vb_eq(lang, &cb.name, &d.name)) else {
                p(0, format!("delegate {} is missing", cb.name));
                continue;
            };
            n_delegates += 1;
            for m in sig_diff(h, lang, 4, &cb.params, &cb.ret, &d.params, &d.ret) {
                p(d.line, format!("delegate {}: {m}", d.name));
            }
            if let Some(c) = &d.conv {
                if !matches!(c.as_str(), "Winapi" | "StdCall") {
                    p(d.line, format!("delegate {}: calling convention {c}; MCC_CALLBACK is stdcall on Windows", d.name));
                }
            }
        }
    }
    // --- constants
    let mut n_consts = 0;
    for c in &h.consts {
        if lang == Lang::Vb6 && c.name.starts_with('_') {
            continue;
        }
        match b.consts.iter().find(|(n, _, _)| vb_eq(lang, &c.name, n)) {
            None => p(0, format!("constant {} is missing", c.name)),
            Some((n, v, line)) => {
                n_consts += 1;
                let same = *v == c.value
                    || (lang == Lang::Vb6
                        && u32::try_from(c.value).is_ok_and(|u| i64::from(u) == *v));
                if !same {
                    p(*line, format!("constant {n} = {v}, C has {}", c.value));
                }
            }
        }
    }
    r.externs = n_externs;
    r.params = n_params;
    r.structs = n_structs;
    r.fields = n_fields;
    r.delegates = n_delegates;
    r.consts = n_consts;
}

#[cfg(test)]
mod tests;
