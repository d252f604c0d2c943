//! Reading the generated headers into a [`Header`]: line by line, as the generator writes
//! them (preprocessor lines, one-line typedefs and prototypes, structs one field a line).

use crate::ctype::CType;
use crate::expr::eval_expr;
use crate::header::{Const, Field, File, Func, Header, Named, Struct};
use crate::syntax::{parse_declaration, parse_prototype};
use crate::{err_at, Error};

/// Where the reader is in the `#if` blocks of one header.
#[derive(Default)]
struct Conditionals {
    /// One entry per open `#if`: whether it is an `#ifdef __cplusplus` still in its C++
    /// branch. The model takes the C declarations: a type the header declares twice (a
    /// C++ form, then a C form under `#else`) is read once, in its C form.
    cpp_only: Vec<bool>,
}

impl Conditionals {
    /// Takes a conditional directive; false for any other line.
    fn take(&mut self, line: &str) -> bool {
        if line.starts_with("#if") {
            self.cpp_only.push(line == "#ifdef __cplusplus");
        } else if line.starts_with("#else") || line.starts_with("#elif") {
            if let Some(top) = self.cpp_only.last_mut() {
                *top = false;
            }
        } else if line.starts_with("#endif") {
            self.cpp_only.pop();
        } else {
            return false;
        }
        true
    }

    fn depth(&self) -> usize {
        self.cpp_only.len()
    }

    fn in_cpp_branch(&self) -> bool {
        self.cpp_only.contains(&true)
    }
}

/// One line without its comments; `in_comment` carries a `/* ... */` across lines.
fn code_of(line: &str, in_comment: &mut bool) -> String {
    let mut out = String::new();
    let mut rest = line;
    loop {
        if *in_comment {
            match rest.find("*/") {
                Some(e) => {
                    rest = &rest[e + 2..];
                    *in_comment = false;
                    out.push(' ');
                }
                None => return out,
            }
        }
        let block = rest.find("/*");
        let eol = rest.find("//");
        match (block, eol) {
            (Some(b), e) if e.is_none_or(|e| b < e) => {
                out.push_str(&rest[..b]);
                rest = &rest[b + 2..];
                *in_comment = true;
            }
            (_, Some(e)) => {
                out.push_str(&rest[..e]);
                return out;
            }
            _ => {
                out.push_str(rest);
                return out;
            }
        }
    }
}

/// The section title a line that is one whole comment gives (`/* System Management */`):
/// a comment without `.` or `:`, which a sentence or a file's description would have.
fn section_title(line: &str) -> Option<&str> {
    let c = line.strip_prefix("/*")?.strip_suffix("*/")?.trim();
    (!c.is_empty() && !c.contains("*/") && !c.contains('.') && !c.contains(':')).then_some(c)
}

impl Header {
    /// Reads the headers in order, each given as (name, text): a header's types must come
    /// before their use (`MCCL.h` first). The name is used in messages and in
    /// [`Func::header`](crate::Func::header).
    pub fn parse(files: &[(&str, &str)]) -> Result<Header, Error> {
        let mut h = Header::default();
        for (name, text) in files {
            h.read(name, text)?;
        }
        Ok(h)
    }

    /// Reads one more header.
    pub fn read(&mut self, file: &str, text: &str) -> Result<(), Error> {
        self.files.push(File {
            name: file.to_string(),
            includes: Vec::new(),
        });
        let mut ifs = Conditionals::default();
        let mut in_comment = false;
        let mut section = String::new();
        let mut open: Option<(usize, Vec<Field>)> = None;
        for (n, raw) in text.lines().enumerate() {
            let ln = n + 1;
            let trimmed = raw.trim();
            if !in_comment {
                if let Some(title) = section_title(trimmed) {
                    section = title.to_string();
                    continue;
                }
            }
            let code = code_of(raw, &mut in_comment);
            let line = code.trim();
            if line.is_empty() {
                continue;
            }
            if let Some((_, fields)) = open.as_mut() {
                if let Some(rest) = line.strip_prefix('}') {
                    let name = rest.trim().trim_end_matches(';').trim().to_string();
                    let (_, fields) = open.take().unwrap_or_default();
                    self.names.insert(name.clone(), Named::Struct(name.clone()));
                    self.structs.push(Struct { name, fields });
                } else {
                    let f = self.field(line).map_err(|e| err_at(file, ln, e))?;
                    fields.push(f);
                }
                continue;
            }
            if ifs.take(line) || ifs.in_cpp_branch() {
                continue;
            }
            let at = |e| err_at(file, ln, e);
            if let Some(rest) = line.strip_prefix('#') {
                self.directive(file, rest.trim(), ifs.depth()).map_err(at)?;
            } else if line == "typedef struct {" {
                open = Some((ln, Vec::new()));
            } else if let Some(rest) = line.strip_prefix("typedef ") {
                self.typedef(file, rest).map_err(at)?;
            } else if line.ends_with(");") {
                let f = self.function(file, line, &section).map_err(at)?;
                self.funcs.push(f);
            } else {
                return Err(at(format!(
                    "a line the header model does not know: {line:?}"
                )));
            }
        }
        if let Some((ln, _)) = open {
            return Err(err_at(file, ln, "struct not closed"));
        }
        Ok(())
    }

    /// A preprocessor line other than a conditional (`#define`, `#include`), without `#`.
    fn directive(&mut self, file: &str, line: &str, depth: usize) -> Result<(), String> {
        if let Some(rest) = line.strip_prefix("include") {
            if let Some(inc) = rest.trim().strip_prefix('"') {
                let inc = inc.trim_end_matches('"').to_string();
                if let Some(f) = self.files.last_mut() {
                    f.includes.push(inc);
                }
            }
            return Ok(());
        }
        let Some(rest) = line.strip_prefix("define ") else {
            return Ok(()); // #undef, #pragma, #error: nothing declared
        };
        let (name, value) = match rest.split_once(char::is_whitespace) {
            Some((a, b)) => (a, b.trim()),
            None => (rest.trim(), ""),
        };
        // Macros inside nested #if blocks (calling conventions), value-less flags (include
        // guards, MULTI_CARD_SUPPORT) and function-like macros are not constants.
        if depth > 1 || value.is_empty() || name.contains('(') {
            return Ok(());
        }
        let v = eval_expr(value, &self.values).map_err(|e| format!("#define {name}: {e}"))?;
        self.values.insert(name.to_string(), v);
        self.consts.push(Const {
            name: name.to_string(),
            value: v,
            header: file.to_string(),
        });
        Ok(())
    }

    /// One struct field line, `TYPE name[N];`.
    fn field(&self, line: &str) -> Result<Field, String> {
        let decl = line.strip_suffix(';').ok_or("struct field without ';'")?;
        let d = parse_declaration(decl)?;
        let name = d.name.ok_or("struct field without a name")?;
        let count = match &d.array {
            Some(len) => {
                let v = eval_expr(len, &self.values)?;
                Some(usize::try_from(v).map_err(|_| "negative array size")?)
            }
            None => None,
        };
        Ok(Field {
            name,
            ty: self.resolve(&d.ty)?,
            count,
            written: d.ty,
        })
    }

    /// A `typedef` line other than a struct's, without `typedef `: a callback type
    /// (`RET (MCC_CALLBACK *NAME)(PARAMS);`) or an alias (`uint16_t WORD;`).
    fn typedef(&mut self, file: &str, rest: &str) -> Result<(), String> {
        let rest = rest.trim_end_matches(';');
        if rest.ends_with(')') {
            let p = parse_prototype(rest)?;
            if !p.pointer {
                return Err(format!("typedef of a function type: {rest:?}"));
            }
            let f = self.func_of(file, p, "")?;
            self.callbacks.push(f);
            return Ok(());
        }
        let d = parse_declaration(rest)?;
        let name = d.name.ok_or("typedef without a name")?;
        let target = if name == "BOOL" {
            CType::Bool
        } else {
            self.resolve(&d.ty)?
        };
        match target {
            CType::Struct(s) => {
                let fields = self
                    .find_struct(&s)
                    .map(|x| x.fields.clone())
                    .ok_or_else(|| format!("alias of unknown {s}"))?;
                self.aliases.insert(name.clone(), s.clone());
                self.names.insert(name.clone(), Named::Struct(s));
                self.structs.push(Struct { name, fields });
            }
            t => {
                self.names.insert(name, Named::Scalar(t));
            }
        }
        Ok(())
    }

    /// A function prototype line.
    fn function(&self, file: &str, line: &str, section: &str) -> Result<Func, String> {
        let p = parse_prototype(line)?;
        if p.pointer {
            return Err(format!("a function pointer outside a typedef: {line:?}"));
        }
        self.func_of(file, p, section)
    }

    fn func_of(
        &self,
        file: &str,
        p: crate::syntax::Prototype,
        section: &str,
    ) -> Result<Func, String> {
        let params = p
            .params
            .into_iter()
            .enumerate()
            .map(|(i, d)| self.param(i, d))
            .collect::<Result<_, _>>()?;
        Ok(Func {
            ret: self.resolve(&p.ret)?,
            ret_written: p.ret,
            conv: p.conv,
            name: p.name,
            params,
            section: section.to_string(),
            header: file.to_string(),
        })
    }
}
