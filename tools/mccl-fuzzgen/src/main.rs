//! mccl-fuzzgen: writes the dispatch table of the random-call fuzzer (`c-tests/fuzz/`)
//! from the prototypes of the headers the library exports.
//!
//! `mccl-fuzzgen OUT.c include/*.h` reads every header given, collects its typedefs
//! (integer aliases, structs, callback types) and its function prototypes, and writes a C
//! file with, for every function, a caller that draws each argument from a generator
//! chosen by the parameter's type (and, to reach deeper code more often, by its name:
//! `wGroupIndex` draws group indices, `cAxis` axis letters, ...), logs the call, makes it
//! and checks the result (canaries around every pointer argument, the vendor's
//! `RUN_TIME_ERR`). Callback parameters get a routine that counts its deliveries and calls
//! back into the library. A new export is covered without editing the fuzzer; a parameter
//! type the generator does not know fails the build, so nothing is skipped silently.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::process::ExitCode;

/// A scalar C type as the fuzzer draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Prim {
    /// Integer of this many bits, signed or not.
    Int(u32, bool),
    /// `char` (drawn from letters and edge bytes).
    Char,
    /// `bool` / `_Bool`.
    Bool,
    /// `float`.
    F32,
    /// `double`.
    F64,
}

/// The base type of a parameter or field (pointers counted apart).
#[derive(Clone, Debug, PartialEq)]
enum Base {
    Void,
    Prim(Prim),
    Struct(String),
    Callback(String),
}

/// A parameter or struct field.
#[derive(Clone, Debug)]
struct Decl {
    /// The C spelling of the type without the name (`const int *`).
    cty: String,
    /// The C spelling of the base type (`int`, `SYS_MAC_PARAM`).
    cbase: String,
    base: Base,
    ptr: usize,
    is_const: bool,
    name: String,
    /// Array length of a struct field (`int32_t nForwardTable[256]`).
    array: Option<usize>,
}

/// How a function's return value is checked.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Codes {
    /// Vendor codes (`MCCL.h`): `RUN_TIME_ERR` is a failure (a caught panic).
    Vendor,
    /// MC3B library codes (`MCL_*`, 0..7): anything else is a failure.
    Mcl,
    /// Unknown convention: not checked.
    None,
}

#[derive(Debug)]
struct Func {
    ret: Decl,
    name: String,
    params: Vec<Decl>,
    header: String,
    codes: Codes,
}

/// A callback typedef: `RET (CONV *NAME)(ARGS)`.
struct CbSig {
    /// Calling-convention macro text.
    conv: String,
    /// The pointee of a routine's one argument (`LIOINT`), `void` for none; for a
    /// callback with several arguments, its whole parameter list.
    arg: String,
    /// Return type.
    ret: String,
    /// Several (or named) arguments (`int nGroup, const double *p, ...`): the routine
    /// declares them as written, hands none to the runtime, and returns 1 (`TRUE`) if
    /// it returns anything.
    several: bool,
}

#[derive(Default)]
struct Model {
    aliases: BTreeMap<String, String>,
    structs: BTreeMap<String, Vec<Decl>>,
    /// Callback typedef name -> its signature.
    callbacks: BTreeMap<String, CbSig>,
    funcs: Vec<Func>,
    headers: Vec<String>,
    /// Integer macros (`#define NAME 16`), for array lengths given by name.
    defines: BTreeMap<String, usize>,
}

fn strip_comments(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'/' && i + 1 < b.len() && b[i + 1] == b'*' {
            match s[i + 2..].find("*/") {
                Some(e) => i += e + 4,
                None => break,
            }
            out.push(' ');
        } else if b[i] == b'/' && i + 1 < b.len() && b[i + 1] == b'/' {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else {
            out.push(b[i] as char);
            i += 1;
        }
    }
    out
}

/// Removes `NAME(...)` macro uses (balanced parentheses) from a prototype.
fn strip_macro_calls(s: &str, macro_name: &str) -> String {
    let mut s = s.to_string();
    while let Some(p) = s.find(macro_name) {
        let after = p + macro_name.len();
        let rest = &s[after..];
        let open = match rest.find('(') {
            Some(o) if rest[..o].trim().is_empty() => after + o,
            _ => break,
        };
        let mut depth = 0;
        let mut end = open;
        for (k, c) in s[open..].char_indices() {
            match c {
                '(' => depth += 1,
                ')' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + k;
                        break;
                    }
                }
                _ => {}
            }
        }
        s.replace_range(p..=end, "");
    }
    s
}

fn prim_of(name: &str) -> Option<Prim> {
    Some(match name {
        "char" => Prim::Char,
        "signed char" | "int8_t" => Prim::Int(8, true),
        "unsigned char" | "uint8_t" => Prim::Int(8, false),
        "short" | "int16_t" => Prim::Int(16, true),
        "unsigned short" | "uint16_t" => Prim::Int(16, false),
        "int" | "int32_t" => Prim::Int(32, true),
        "unsigned" | "unsigned int" | "uint32_t" => Prim::Int(32, false),
        "long" | "long long" | "int64_t" => Prim::Int(64, true),
        "unsigned long" | "unsigned long long" | "uint64_t" => Prim::Int(64, false),
        "bool" | "_Bool" => Prim::Bool,
        "float" => Prim::F32,
        "double" => Prim::F64,
        _ => return None,
    })
}

impl Model {
    fn resolve(&self, name: &str) -> Result<Base, String> {
        let mut n = name.to_string();
        for _ in 0..16 {
            if n == "void" {
                return Ok(Base::Void);
            }
            if let Some(p) = prim_of(&n) {
                return Ok(Base::Prim(p));
            }
            if self.structs.contains_key(&n) {
                return Ok(Base::Struct(n));
            }
            if self.callbacks.contains_key(&n) {
                return Ok(Base::Callback(n));
            }
            match self.aliases.get(&n) {
                Some(t) => n = t.clone(),
                None => return Err(format!("unknown type `{name}`")),
            }
        }
        Err(format!("typedef loop at `{name}`"))
    }

    /// Parses `const int *name[4]` (name optional) into a declaration.
    fn decl(&self, text: &str, want_name: bool) -> Result<Decl, String> {
        let text = text.trim();
        let (text, array) = match text.find('[') {
            Some(p) => {
                let len = text[p + 1..].trim_end_matches(']').trim();
                let n = match self.defines.get(len) {
                    Some(&n) => n,
                    None => len
                        .parse::<usize>()
                        .map_err(|e| format!("array length in `{text}`: {e}"))?,
                };
                (&text[..p], Some(n))
            }
            None => (text, None),
        };
        let spaced = text.replace('*', " * ");
        let mut toks: Vec<&str> = spaced.split_whitespace().collect();
        let mut name = String::new();
        if want_name && toks.len() >= 2 {
            let last = toks[toks.len() - 1];
            if last != "*" && prim_of(last).is_none() && !self.is_type_word(last) {
                name = last.to_string();
                toks.pop();
            }
        }
        let is_const = toks.contains(&"const");
        let ptr = toks.iter().filter(|t| **t == "*").count();
        let base_words: Vec<&str> = toks
            .iter()
            .copied()
            .filter(|t| *t != "*" && *t != "const" && *t != "struct")
            .collect();
        let cbase = base_words.join(" ");
        let base = self.resolve(&cbase)?;
        let cty = {
            let mut s = String::new();
            if is_const {
                s.push_str("const ");
            }
            s.push_str(&cbase);
            if ptr > 0 {
                s.push(' ');
                s.push_str(&"*".repeat(ptr));
            }
            s
        };
        Ok(Decl {
            cty,
            cbase,
            base,
            ptr,
            is_const,
            name,
            array,
        })
    }

    fn is_type_word(&self, w: &str) -> bool {
        matches!(w, "long" | "int" | "short" | "char" | "unsigned" | "signed")
            || self.aliases.contains_key(w)
            || self.structs.contains_key(w)
            || self.callbacks.contains_key(w)
    }

    /// An alias (`typedef uint16_t WORD`) or a callback type
    /// (`typedef void (MCC_CALLBACK *LIOISR)(LIOINT*)`).
    fn typedef(&mut self, file: &str, stmt: &str) -> Result<(), String> {
        let t = &stmt["typedef ".len()..];
        if let Some(star) = t.find('(') {
            let ret = t[..star].trim().to_string();
            let inner_end = t[star..].find(')').ok_or("bad callback typedef")? + star;
            let inner = &t[star + 1..inner_end];
            let (conv, nm) = inner.split_once('*').ok_or("bad callback typedef")?;
            let args = t[inner_end + 1..]
                .trim()
                .trim_start_matches('(')
                .trim_end_matches(')');
            // A named parameter (`void *pvExtension`) is declared as written too.
            let named = args
                .rsplit_once('*')
                .is_some_and(|(_, n)| !n.trim().is_empty());
            let several = args.contains(',') || named;
            if !several && ret != "void" {
                return Err(format!(
                    "{file}: callback `{stmt}`: one argument and a result"
                ));
            }
            let arg = if several {
                args.trim().to_string()
            } else {
                args.replace('*', "").trim().to_string()
            };
            self.callbacks.insert(
                nm.trim().to_string(),
                CbSig {
                    conv: conv.trim().to_string(),
                    arg,
                    ret,
                    several,
                },
            );
        } else {
            let toks: Vec<&str> = t.split_whitespace().collect();
            if let Some((n, ty)) = toks.split_last() {
                self.aliases.insert(n.to_string(), ty.join(" "));
            }
        }
        Ok(())
    }

    fn read_header(&mut self, path: &str) -> Result<(), String> {
        let raw = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
        let file = std::path::Path::new(path)
            .file_name()
            .and_then(|f| f.to_str())
            .unwrap_or(path)
            .to_string();
        let text = strip_comments(&raw);
        let codes = if text.contains("#include \"MCCL.h\"") || text.contains("RUN_TIME_ERR") {
            Codes::Vendor
        } else if text.contains("MCL_NO_ERROR") {
            Codes::Mcl
        } else {
            Codes::None
        };
        // Drop preprocessor lines and C++ linkage braces.
        let mut body = String::new();
        for line in text.lines() {
            if line.trim_start().starts_with('#') {
                let words: Vec<&str> = line.split_whitespace().collect();
                if let ["#define", name, value] = words[..] {
                    if let Ok(n) = value.parse::<usize>() {
                        self.defines.insert(name.to_string(), n);
                    }
                }
                continue;
            }
            body.push_str(line);
            body.push('\n');
        }
        let body = body.replace("extern \"C\" {", " ");
        // typedef struct { ... } NAME;
        let mut rest = body.as_str();
        let mut flat = String::new();
        let mut raw_structs = Vec::new();
        while let Some(p) = rest.find("typedef struct") {
            flat.push_str(&rest[..p]);
            let open = rest[p..].find('{').ok_or("typedef struct without {")? + p;
            let close = rest[open..].find('}').ok_or("typedef struct without }")? + open;
            let semi = rest[close..].find(';').ok_or("typedef struct without ;")? + close;
            let name = rest[close + 1..semi].trim().to_string();
            self.structs.insert(name.clone(), Vec::new());
            raw_structs.push((name, rest[open + 1..close].to_string()));
            rest = &rest[semi + 1..];
        }
        flat.push_str(rest);
        // Typedefs first (a struct's fields may use an alias defined after it).
        for stmt in flat.split(';') {
            let stmt = stmt.replace('}', " ");
            let stmt = stmt.split_whitespace().collect::<Vec<_>>().join(" ");
            if stmt.starts_with("typedef ") {
                self.typedef(&file, &stmt)?;
            }
        }
        for (name, body) in raw_structs {
            let mut fields = Vec::new();
            for f in body.split(';') {
                if f.trim().is_empty() {
                    continue;
                }
                let d = self
                    .decl(f, true)
                    .map_err(|e| format!("{file}: struct {name}: {e}"))?;
                fields.push(d);
            }
            self.structs.insert(name, fields);
        }
        for stmt in flat.split(';') {
            let stmt = stmt.replace('}', " ");
            let stmt = stmt.split_whitespace().collect::<Vec<_>>().join(" ");
            if stmt.is_empty() {
                continue;
            }
            if stmt.starts_with("typedef ") {
                continue;
            }
            if !stmt.contains('(') || !stmt.ends_with(')') {
                continue;
            }
            let stmt = strip_macro_calls(&stmt, "MCC_DEFAULT");
            let stmt = strip_macro_calls(&stmt, "MCL_DEFAULT");
            let stmt = stmt.replace("MCC_API", " ").replace("MCC_CALL", " ");
            let open = stmt.find('(').ok_or("no (")?;
            let head = stmt[..open].trim();
            let params_txt = &stmt[open + 1..stmt.len() - 1];
            let (ret_txt, name) = head
                .rsplit_once([' ', '*'])
                .ok_or_else(|| format!("{file}: cannot read prototype `{stmt}`"))?;
            let ret_txt = if head[..head.len() - name.len()].ends_with('*') {
                format!("{ret_txt}*")
            } else {
                ret_txt.to_string()
            };
            let ret = self
                .decl(&ret_txt, false)
                .map_err(|e| format!("{file}: {name}: return type: {e}"))?;
            if ret.ptr > 0 {
                return Err(format!(
                    "{file}: {name}: pointer return types are not fuzzed"
                ));
            }
            let mut params = Vec::new();
            if params_txt.trim() != "void" && !params_txt.trim().is_empty() {
                for p in params_txt.split(',') {
                    let d = self
                        .decl(p, true)
                        .map_err(|e| format!("{file}: {name}: parameter `{p}`: {e}"))?;
                    if d.base == Base::Void && d.ptr == 0 {
                        return Err(format!("{file}: {name}: void parameter"));
                    }
                    if d.ptr > 1 {
                        return Err(format!("{file}: {name}: `{p}`: pointer to pointer"));
                    }
                    if matches!(d.base, Base::Callback(_)) && d.ptr > 0 {
                        return Err(format!("{file}: {name}: `{p}`: pointer to callback"));
                    }
                    params.push(d);
                }
            }
            self.funcs.push(Func {
                ret,
                name: name.to_string(),
                params,
                header: file.clone(),
                codes,
            });
        }
        self.headers.push(file);
        Ok(())
    }
}

/// The value class a parameter or field draws from (`FZ_H_*` in fuzz_rt.h), from the
/// function and the parameter's name. Unknown names draw from the whole type.
fn hint(func: &str, name: &str, p: Prim) -> &'static str {
    let real = matches!(p, Prim::F32 | Prim::F64);
    let has = |s: &str| name.contains(s);
    if func == "MCC_TimeDelay" {
        return "FZ_H_TIMEDELAY"; // bounded: the calling thread waits this long
    }
    if has("QueueSize") || func.contains("QueueSize") || has("StockNum") {
        return "FZ_H_QSIZE"; // capped: a size is reserved up front
    }
    if name == "com_port" {
        return "FZ_H_COMPORT";
    }
    if func == "MCC_DelayMotion" {
        return "FZ_H_DELAY";
    }
    if has("InterpolateTime") {
        return "FZ_H_INTERP";
    }
    if p == Prim::Char {
        if has("Axis") {
            return "FZ_H_AXISCHAR";
        }
        if has("AccType") || has("DecType") {
            return "FZ_H_ACCTYPE";
        }
        return "FZ_H_ANY";
    }
    if real {
        if has("Voltage") || has("fValue") || has("Input") {
            return "FZ_H_VOLT";
        }
        if has("Pitch") || has("GearRat") {
            return "FZ_H_RATIO";
        }
        if has("Speed") || has("Ratio") || has("Rate") || has("Feed") || has("Vel") {
            return "FZ_H_SPEED";
        }
        if has("Time") {
            return "FZ_H_TIMEMS";
        }
        if has("Limit") || has("Tolerance") {
            return "FZ_H_LIMIT";
        }
        return "FZ_H_POS";
    }
    if has("Group") {
        return "FZ_H_GROUP";
    }
    if has("CardNo") {
        return "FZ_H_CARDNO";
    }
    if has("CardType") {
        return "FZ_H_CARDTYPE";
    }
    if has("Card") {
        return "FZ_H_CARD";
    }
    if has("MapToCh") {
        return "FZ_H_MAPCH";
    }
    if has("Channel")
        || has("Point")
        || has("DigitalInput")
        || name == "wAxis"
        || name == "wCh"
        || name == "motor_id"
    {
        return "FZ_H_CHANNEL";
    }
    if name == "wSet" {
        return "FZ_H_SET";
    }
    if has("Slave") || has("Port") {
        return "FZ_H_SLAVE";
    }
    if has("Order") {
        return "FZ_H_ORDER";
    }
    if has("Mask") {
        return "FZ_H_MASK";
    }
    if has("CirDir") || has("Dir") || has("direction") {
        return "FZ_H_DIR";
    }
    if p == Prim::Bool
        || (name.starts_with('b') && name.chars().nth(1).is_some_and(|c| c.is_ascii_uppercase()))
    {
        return "FZ_H_BOOL";
    }
    if has("Level") || has("Sensor") || has("Output") || has("controller") {
        return "FZ_H_SMALL";
    }
    if has("PPR") || has("RPM") {
        return "FZ_H_PPR";
    }
    if has("Mode") || has("Type") || has("Rate") || has("Source") || has("Enable") {
        return "FZ_H_SMALL";
    }
    if has("Time") || has("Period") || name == "dwValue" {
        return "FZ_H_PERIOD";
    }
    "FZ_H_ANY"
}

/// Elements a pointer parameter points to (one unless its role says otherwise).
fn count(d: &Decl) -> &'static str {
    if d.name.contains("CardConfig") {
        "MAX_CARD_NUM" // an array of wCardNo cards, at most MAX_CARD_NUM
    } else if d.name.starts_with("str") && matches!(d.base, Base::Prim(Prim::Char)) {
        "5" // MCC_GetVersion: the library documents 5 bytes ("6.00" and its NUL)
    } else if d.is_const {
        "128" // an input array (mcl_chained_synchronous_move_motor: at most 100 moves)
    } else {
        "1"
    }
}

fn c_ident(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

/// Statements that draw one scalar of type `p` into the lvalue `lv`.
fn draw_prim(out: &mut String, lv: &str, cty: &str, p: Prim, h: &str) {
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
fn log_prim(p: Prim, name: &str, v: &str) -> String {
    match p {
        Prim::Int(_, true) => format!("fz_log_i(z, \"{name}\", (long long)({v}))"),
        Prim::Int(_, false) | Prim::Bool => {
            format!("fz_log_u(z, \"{name}\", (unsigned long long)({v}))")
        }
        Prim::Char => format!("fz_log_c(z, \"{name}\", (int)({v}))"),
        Prim::F32 | Prim::F64 => format!("fz_log_r(z, \"{name}\", (double)({v}))"),
    }
}

fn gen(m: &Model) -> Result<String, String> {
    let mut o = String::new();
    o.push_str(
        "/* Generated by tools/mccl-fuzzgen from the library's headers at build time.\n * Do not edit: change the generator or the runtime (c-tests/fuzz/fuzz_rt.h). */\n",
    );
    o.push_str("#include \"fuzz_rt.h\"\n#include <string.h>\n");
    for h in &m.headers {
        let _ = writeln!(o, "#include \"{h}\"");
    }
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
                    draw_prim(&mut o, &lv, &d.cbase, *p, hint(name, &d.name, *p))
                }
                (Base::Prim(p), 0, Some(n)) => {
                    let _ = writeln!(o, "    for (int i = 0; i < {n}; i++) {{");
                    draw_prim(
                        &mut o,
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
    // Routines, one per callback type.
    let cb_index: BTreeMap<&String, usize> = m
        .callbacks
        .keys()
        .enumerate()
        .map(|(i, k)| (k, i))
        .collect();
    for (i, (name, cb)) in m.callbacks.iter().enumerate() {
        let (conv, arg) = (&cb.conv, &cb.arg);
        if cb.several {
            let ret = if cb.ret == "void" {
                String::new()
            } else {
                "\n    return 1;".to_string()
            };
            // Every parameter gets a name of ours (the header may name them or not) and
            // is marked unused.
            let params: Vec<String> = arg
                .split(',')
                .enumerate()
                .map(|(k, a)| format!("{} a{k}", param_type(a)))
                .collect();
            let unused: String = (0..params.len())
                .map(|k| format!("\n    (void)a{k};"))
                .collect();
            let _ = writeln!(
                o,
                "\nstatic {} {conv} fz_cb_{}({})\n{{{unused}\n    fz_routine({i}, NULL, 0);{ret}\n}}",
                cb.ret,
                c_ident(name),
                params.join(", ")
            );
            continue;
        }
        let (sig, size) = if arg == "void" || arg.is_empty() {
            ("void".to_string(), "0".to_string())
        } else {
            (format!("{arg} *p"), "sizeof(*p)".to_string())
        };
        let pass = if size == "0" { "NULL" } else { "p" };
        let _ = writeln!(
            o,
            "\nstatic void {conv} fz_cb_{}({sig})\n{{\n    fz_routine({i}, {pass}, {size});\n}}",
            c_ident(name)
        );
    }
    let _ = writeln!(o, "\nconst fz_cb_t fz_cbs[] = {{");
    for (name, cb) in &m.callbacks {
        let arg = if cb.several { "void" } else { cb.arg.as_str() };
        let setters = m
            .funcs
            .iter()
            .filter(|f| {
                f.params
                    .iter()
                    .any(|d| d.base == Base::Callback(name.clone()))
            })
            .count();
        let _ = writeln!(
            o,
            "    {{\"{name}\", \"{arg}\", (void (*)(void))fz_cb_{}, {setters}, {}}},",
            c_ident(name),
            i32::from(cb.several)
        );
    }
    let _ = writeln!(o, "}};\nconst int fz_ncbs = {};", m.callbacks.len());

    // Callers: the log line starts with the name; each argument is logged as drawn.
    for (fi, f) in m.funcs.iter().enumerate() {
        let _ = writeln!(o, "\nstatic void fz_call_{}(fz_t *z)\n{{", f.name);
        let _ = writeln!(o, "    fz_begin(z, {fi});");
        let mut args = Vec::new();
        let mut finite_checks = Vec::new();
        for (k, d) in f.params.iter().enumerate() {
            let a = format!("a{k}");
            args.push(a.clone());
            let pname = if d.name.is_empty() {
                format!("arg{k}")
            } else {
                d.name.clone()
            };
            match (&d.base, d.ptr) {
                (Base::Prim(p), 0) => {
                    let _ = writeln!(o, "    {} {a};", d.cty);
                    draw_prim(&mut o, &a, &d.cty, *p, hint(&f.name, &pname, *p));
                    let _ = writeln!(o, "    {};", log_prim(*p, &pname, &a));
                    if matches!(p, Prim::F32 | Prim::F64) {
                        let _ = writeln!(o, "    fz_arg_real(z, (double){a});");
                    }
                }
                (Base::Callback(cb), 0) => {
                    let _ = writeln!(
                        o,
                        "    {} {a} = ({})fz_callback(z, {});",
                        d.cty, d.cty, cb_index[cb]
                    );
                    let _ = writeln!(o, "    fz_log_cb(z, \"{pname}\", (void (*)(void)){a});");
                }
                (base, 1) => {
                    let elem = if d.cbase == "void" {
                        "1".to_string()
                    } else {
                        format!("sizeof({})", d.cbase)
                    };
                    let n = count(d);
                    let _ = writeln!(o, "    unsigned char *{a}_b = fz_ptr(z, {k}, {elem}, {n});");
                    let _ = writeln!(o, "    fz_log_p(z, \"{pname}\", {k});");
                    // Fill through an aligned temporary (the buffer may be misaligned).
                    match base {
                        Base::Struct(s) => {
                            let s_id = c_ident(s);
                            let _ = writeln!(
                                o,
                                "    if ({a}_b) for (int i = 0; i < {n}; i++) {{\n        {cb} t; fz_fill_{s_id}(z, &t); memcpy({a}_b + i * sizeof t, &t, sizeof t);\n        if (i == 0) {{ fz_log_raw(z, \"{{\"); fz_show_{s_id}(z, &t); fz_log_raw(z, \"}}\"); }}\n    }}",
                                cb = d.cbase
                            );
                        }
                        Base::Prim(p) => {
                            let _ = writeln!(
                                o,
                                "    if ({a}_b) for (int i = 0; i < {n}; i++) {{\n        {} t;",
                                d.cbase
                            );
                            let real_out = matches!(p, Prim::F32 | Prim::F64) && !d.is_const;
                            if real_out {
                                // An output: a finite sentinel, so that a non-finite
                                // value found after a successful call was written by it.
                                let _ = writeln!(o, "        t = ({})12345.5;", d.cbase);
                                finite_checks.push(format!(
                                    "fz_check_finite(z, {k}, {a}_b, {n}, {})",
                                    (*p == Prim::F32) as i32
                                ));
                            } else {
                                draw_prim(&mut o, "t", &d.cbase, *p, hint(&f.name, &pname, *p));
                            }
                            let _ = writeln!(
                                o,
                                "        memcpy({a}_b + i * sizeof t, &t, sizeof t);\n    }}"
                            );
                        }
                        Base::Void => {}
                        Base::Callback(_) => unreachable!("rejected by the parser"),
                    }
                    let _ = writeln!(o, "    {} {a} = ({}){a}_b;", d.cty, d.cty);
                }
                _ => return Err(format!("{}: parameter {pname} not supported", f.name)),
            }
        }
        let call = format!("{}({})", f.name, args.join(", "));
        let codes = match f.codes {
            Codes::Vendor => "FZ_CODES_VENDOR",
            Codes::Mcl => "FZ_CODES_MCL",
            Codes::None => "FZ_CODES_NONE",
        };
        let _ = writeln!(o, "    fz_call_start(z, {fi});");
        match &f.ret.base {
            Base::Void => {
                let _ = writeln!(o, "    {call};\n    fz_end_void(z, {fi});");
            }
            Base::Prim(Prim::F32) | Base::Prim(Prim::F64) => {
                let _ = writeln!(
                    o,
                    "    double r = (double){call};\n    fz_end_real(z, {fi}, r, {codes});"
                );
            }
            Base::Prim(_) => {
                let _ = writeln!(
                    o,
                    "    long long r = (long long){call};\n    fz_end_int(z, {fi}, r, {codes});"
                );
                // Doubles a successful call wrote must be finite.
                for c in &finite_checks {
                    let _ = writeln!(o, "    if (r == 0) {c};");
                }
            }
            _ => return Err(format!("{}: return type not supported", f.name)),
        }
        let _ = writeln!(o, "}}");
    }
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
    Ok(o)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 {
        eprintln!("usage: mccl-fuzzgen OUT.c HEADER.h...");
        return ExitCode::from(2);
    }
    let mut m = Model::default();
    // Headers that define types others use go first (MCCL.h before MCCL_Fun.h).
    let mut headers: Vec<&String> = args[1..].iter().collect();
    headers.sort_by_key(|h| !h.ends_with("/MCCL.h") && *h != "MCCL.h");
    for h in headers {
        if let Err(e) = m.read_header(h) {
            eprintln!("mccl-fuzzgen: {e}");
            return ExitCode::FAILURE;
        }
    }
    let code = match gen(&m) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("mccl-fuzzgen: {e}");
            return ExitCode::FAILURE;
        }
    };
    let out = &args[0];
    if let Err(e) = std::fs::write(out, code) {
        eprintln!("mccl-fuzzgen: {out}: {e}");
        return ExitCode::FAILURE;
    }
    eprintln!(
        "mccl-fuzzgen: {} functions, {} callback types, {} structs from {} headers",
        m.funcs.len(),
        m.callbacks.len(),
        m.structs.len(),
        m.headers.len()
    );
    ExitCode::SUCCESS
}

/// The type of one C parameter, without its name if it has one: `const double *pdfFrom`
/// gives `const double *`, `const double*` stays. A parameter is named when its last
/// token is neither `*` nor a type word (a C keyword or an all-capitals typedef).
fn param_type(p: &str) -> String {
    let spaced = p.replace('*', " * ");
    let toks: Vec<&str> = spaced.split_whitespace().collect();
    let is_type = |t: &str| {
        t == "*"
            || matches!(
                t,
                "int" | "double" | "void" | "char" | "long" | "short" | "unsigned" | "float"
            )
            || t.chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
    };
    match toks.split_last() {
        Some((last, rest)) if !is_type(last) && !rest.is_empty() => rest.join(" "),
        _ => toks.join(" "),
    }
}

#[cfg(test)]
mod tests {
    use super::param_type;

    /// Named and unnamed parameters of the vendor's callback typedefs (INTERP and
    /// FWDKINEFUN name theirs, the custom-motion ones do not).
    #[test]
    fn parameter_types_drop_only_names() {
        assert_eq!(param_type("int nGroup"), "int");
        assert_eq!(param_type("const double *pdfFrom"), "const double *");
        assert_eq!(param_type("DWORD *dwPosture"), "DWORD *");
        assert_eq!(param_type("BOOL* AbortThisCommand"), "BOOL *");
        assert_eq!(param_type("const double*"), "const double *");
        assert_eq!(param_type("int"), "int");
        assert_eq!(param_type("void*"), "void *");
        assert_eq!(param_type("unsigned long"), "unsigned long");
    }
}
