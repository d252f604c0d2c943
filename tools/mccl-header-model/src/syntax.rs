//! One C declaration or prototype as written, before anything is known of the names it
//! uses: the forms of the generated headers (`WORD wCardIndex MCC_DEFAULT(0)`,
//! `MCC_API int MCC_CALL MCC_F(...)`, `BOOL (MCC_CALLBACK *F)(..., DWORD &dwPosture)`),
//! of cbindgen's output and of the vendor prototype table (`WORD wCardIndex = 0`).

/// The calling-convention and linkage macros a prototype may carry around its name.
pub const CONVENTION_MACROS: [&str; 3] = ["MCC_API", "MCC_CALL", "MCC_CALLBACK"];

/// The macros the headers write a C++ default argument with (`MCC_DEFAULT(v)`, empty in C).
const DEFAULT_MACROS: [&str; 2] = ["MCC_DEFAULT(", "MCL_DEFAULT("];

/// C keywords that name or qualify a type: a declaration whose last word is one of these
/// declares no name (`unsigned long`).
const TYPE_KEYWORDS: [&str; 14] = [
    "void", "char", "short", "int", "long", "float", "double", "signed", "unsigned", "bool",
    "_Bool", "const", "volatile", "struct",
];

/// Splits a C declaration into words, with `*`, `&`, `[`, `]` as words of their own; other
/// punctuation only separates words.
pub fn words(s: &str) -> Vec<String> {
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

/// Whether `w` is a C identifier that is not a type keyword (so it can be a declared name).
fn is_name(w: &str) -> bool {
    w.starts_with(|c: char| c.is_alphabetic() || c == '_') && !TYPE_KEYWORDS.contains(&w)
}

/// One declaration as written: a parameter, a struct field or a return type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Declaration {
    /// The type's words, `*` and `&` as words of their own: `["const", "double", "*"]`.
    pub ty: Vec<String>,
    /// The declared name, when there is one (`pdfFrom`).
    pub name: Option<String>,
    /// The array length as written, for `name[N]` (`MCCL_SIM_CLOCK_BUCKETS`).
    pub array: Option<String>,
    /// The C++ default argument as written: `= v` (the vendor table), `MCC_DEFAULT(v)` or
    /// `MCL_DEFAULT(v)` (the headers).
    pub default: Option<String>,
}

impl Declaration {
    /// The type as one string, its words separated by spaces (`const double *`).
    pub fn type_text(&self) -> String {
        self.ty.join(" ")
    }
}

/// Parses one declaration: `const double *pdfFrom`, `LIOINT*`, `uint64_t ullBucket[16]`,
/// `WORD wCardIndex MCC_DEFAULT(0)`, `WORD wCardIndex = 0`, `DWORD &dwPosture`. The last
/// word is the name when it is an identifier other than a type keyword and a type comes
/// before it (a typedef name cannot follow another type word in C).
pub fn parse_declaration(text: &str) -> Result<Declaration, String> {
    let (decl, default) = match DEFAULT_MACROS
        .iter()
        .find_map(|m| text.find(m).map(|at| (at, m)))
    {
        Some((at, m)) => {
            let rest = &text[at + m.len()..];
            let end = rest
                .rfind(')')
                .ok_or_else(|| format!("unclosed {m}...) in {text:?}"))?;
            (&text[..at], Some(rest[..end].trim().to_string()))
        }
        None => match text.split_once('=') {
            Some((d, v)) => (d, Some(v.trim().to_string())),
            None => (text, None),
        },
    };
    let mut decl = decl.trim();
    let mut array = None;
    if let Some(head) = decl.strip_suffix(']') {
        let open = head
            .rfind('[')
            .ok_or_else(|| format!("unbalanced ']' in {text:?}"))?;
        array = Some(head[open + 1..].trim().to_string());
        decl = head[..open].trim();
    }
    let mut ty = words(decl);
    let typed_before_last = ty.len() >= 2
        && ty[..ty.len() - 1]
            .iter()
            .any(|w| !matches!(w.as_str(), "const" | "volatile" | "*" | "&"));
    let name = match ty.last() {
        Some(last) if typed_before_last && is_name(last) => ty.pop(),
        _ => None,
    };
    if ty.is_empty() {
        return Err(format!("declaration without a type: {text:?}"));
    }
    if array.is_some() && name.is_none() {
        return Err(format!("array without a name: {text:?}"));
    }
    Ok(Declaration {
        ty,
        name,
        array,
        default,
    })
}

/// A function prototype, or the signature of a function pointer type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Prototype {
    /// The return type's words (`["double"]`).
    pub ret: Vec<String>,
    /// The calling-convention macros written with it, in order (`["MCC_API",
    /// "MCC_CALL"]`, `["MCC_CALLBACK"]`; see [`CONVENTION_MACROS`]).
    pub conv: Vec<String>,
    /// The function's (or the pointer type's) name.
    pub name: String,
    /// Whether it declares a pointer to a function, `RET (CONV *NAME)(PARAMS)`.
    pub pointer: bool,
    /// The parameters in order (none for `()` and `(void)`).
    pub params: Vec<Declaration>,
}

/// The index of the `(` that the `)` at `close` closes.
fn matching_open(s: &str, close: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in s[..=close].char_indices().rev() {
        match c {
            ')' => depth += 1,
            '(' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// Parses `RET NAME(PARAMS)` (with calling-convention macros anywhere before the name, as
/// `MCC_API int MCC_CALL MCC_F(...)`) or `RET (CONV *NAME)(PARAMS)`, without `typedef`; a
/// trailing `;` is allowed.
pub fn parse_prototype(text: &str) -> Result<Prototype, String> {
    let text = text.trim().trim_end_matches(';').trim_end();
    let close = text
        .len()
        .checked_sub(1)
        .filter(|&i| text[i..].starts_with(')'))
        .ok_or_else(|| format!("not a prototype (no final ')'): {text:?}"))?;
    let open = matching_open(text, close).ok_or_else(|| format!("unbalanced ')' in {text:?}"))?;
    let head = text[..open].trim();
    let inner = text[open + 1..close].trim();
    let (ret_text, declarator, pointer) = match head.strip_suffix(')') {
        Some(h) => {
            let p = h
                .rfind('(')
                .ok_or_else(|| format!("unbalanced ')' in {text:?}"))?;
            (&h[..p], &h[p + 1..], true)
        }
        None => ("", head, false),
    };
    let mut conv = Vec::new();
    let mut ret = Vec::new();
    for w in words(ret_text).into_iter().chain(words(declarator)) {
        if CONVENTION_MACROS.contains(&w.as_str()) {
            conv.push(w);
        } else {
            ret.push(w);
        }
    }
    if pointer && ret.len() >= 2 && ret[ret.len() - 2] == "*" {
        ret.remove(ret.len() - 2); // the `*` of `(CONV *NAME)`
    } else if pointer {
        return Err(format!("function pointer without its '*': {text:?}"));
    }
    let name = match ret.pop() {
        Some(n) if is_name(&n) => n,
        _ => return Err(format!("prototype without a name: {text:?}")),
    };
    if ret.is_empty() {
        return Err(format!("prototype without a return type: {text:?}"));
    }
    let params = if inner.is_empty() || inner == "void" {
        Vec::new()
    } else {
        inner
            .split(',')
            .map(parse_declaration)
            .collect::<Result<_, _>>()?
    };
    Ok(Prototype {
        ret,
        conv,
        name,
        pointer,
        params,
    })
}
