//! Lexing helpers shared by the C# and VB parsers: tokens, attributes, and the .NET
//! marshalling widths they imply.

use super::*;

/// A token with the line it starts on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Tok {
    pub(super) s: String,
    pub(super) line: usize,
}

/// Tokenizes C# source: identifiers (with `@` kept), numbers, strings (with quotes), and
/// single punctuation characters; comments and preprocessor lines are dropped.
pub(super) fn lex_cs(text: &str) -> Vec<Tok> {
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
pub(super) fn split_commas(t: &[Tok]) -> Vec<Vec<Tok>> {
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
pub(super) struct Attr {
    pub(super) name: String,
    pub(super) args: Vec<(Option<String>, String)>,
}

impl Attr {
    pub(super) fn named(&self, key: &str) -> Option<&str> {
        self.args
            .iter()
            .find(|(k, _)| k.as_deref().is_some_and(|k| k.eq_ignore_ascii_case(key)))
            .map(|(_, v)| v.as_str())
    }
    pub(super) fn positional(&self, i: usize) -> Option<&str> {
        self.args
            .iter()
            .filter(|(k, _)| k.is_none())
            .nth(i)
            .map(|(_, v)| v.as_str())
    }
}

/// Parses the tokens of one attribute (`Name(args)`, without the brackets); a leading
/// `return :` target is kept in the name as `return:Name`.
pub(super) fn parse_attr(t: &[Tok]) -> Attr {
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

pub(super) fn last_word(v: &str) -> &str {
    v.rsplit('.').next().unwrap_or(v)
}

/// `MarshalAs(UnmanagedType.X)` override of a boolean's width.
pub(super) fn bool_width(attrs: &[Attr]) -> u8 {
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
pub(super) fn net_scalar(t: &str, attrs: &[Attr]) -> Option<Abi> {
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

pub(super) fn ptr_to(a: Abi) -> Abi {
    match a {
        Abi::Int(w) => Abi::Ptr(Pointee::Int(w)),
        Abi::Float(w) => Abi::Ptr(Pointee::Float(w)),
        Abi::Struct(s) => Abi::Ptr(Pointee::Struct(s)),
        Abi::Ptr(_) => Abi::Ptr(Pointee::Int(8)),
        other => Abi::Bad(format!("pointer to {other:?}")),
    }
}

/// ABI of a .NET parameter type with its modifiers.
pub(super) fn net_param_abi(
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
