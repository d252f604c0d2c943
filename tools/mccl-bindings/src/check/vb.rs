//! The VB parsers of the checker (VB6 `MCCLPCI_IMP.bas` and VB.NET `MCCL.vb`), line based.

use super::*;

/// Logical lines: comments removed (outside strings), `_` continuations joined.
pub(super) fn vb_lines(text: &str) -> Vec<(usize, String)> {
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
pub(super) fn lex_vb(s: &str, line: usize) -> Vec<Tok> {
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

pub(super) fn eqi(a: &str, b: &str) -> bool {
    a.eq_ignore_ascii_case(b)
}

/// Reads `<...>` attribute groups at the start of a VB token list.
pub(super) fn vb_attrs(t: &[Tok]) -> (Vec<Attr>, usize) {
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

pub(super) fn vb6_type_abi(ty: &str, by_val: bool, structs: &[String]) -> Abi {
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
pub(super) fn vb_param(
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
pub(super) fn vb_sig(t: &[Tok]) -> Option<(usize, usize)> {
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

pub(super) fn vb_const(t: &[Tok]) -> Option<(String, i64)> {
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
