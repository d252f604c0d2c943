//! The C# parser of the checker (`MCCL.cs`).

use super::*;

/// Reads `[...]` attribute groups at `t[i..]`; returns them and the index after them.
pub(super) fn cs_attrs(t: &[Tok], mut i: usize) -> (Vec<Attr>, usize) {
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
pub(super) fn cs_params(
    t: &[Tok],
    structs: &[String],
    delegates: &[String],
) -> Result<Vec<BParam>, String> {
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

pub(super) fn net_ret(ty: &str, attrs: &[Attr], structs: &[String]) -> Abi {
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
pub(super) fn cs_names(t: &[Tok]) -> (Vec<String>, Vec<String>) {
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

pub(super) fn net_elem(ty: &str, attrs: &[Attr], structs: &[String]) -> Elem {
    match net_scalar(ty, attrs) {
        Some(Abi::Int(w)) => Elem::Int(w),
        Some(Abi::Float(w)) => Elem::Float(w),
        _ if structs.iter().any(|s| s == ty) => Elem::Struct(ty.to_string()),
        _ => Elem::Bad(format!("type {ty} has no fixed inline layout")),
    }
}
