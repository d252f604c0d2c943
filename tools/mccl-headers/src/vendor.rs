//! The vendor prototype table (`vendor_prototypes.txt`): the `MCC_*` prototypes of
//! MCCL_Fun.h by section, with the vendor's C++ default arguments; and the prototypes as C
//! writes them, compared and rendered.

use mccl_header_model::syntax::{parse_prototype, Prototype};
use std::fmt::Write as _;
use std::path::Path;

/// A prototype as cbindgen and the vendor table write it (`ret name(type name [= default],
/// ...)`), read with the header model's declaration syntax.
pub type Proto = Prototype;

/// Parses `ret name(params)` (a trailing `;` is allowed): a plain prototype whose every
/// parameter is named.
pub fn parse_proto(line: &str) -> Result<Proto, String> {
    let p = parse_prototype(line)?;
    if p.pointer || !p.conv.is_empty() {
        return Err(format!("not a plain prototype: {line:?}"));
    }
    if let Some(a) = p.params.iter().find(|a| a.name.is_none()) {
        return Err(format!(
            "parameter without a name: {:?} in {line:?}",
            a.type_text()
        ));
    }
    Ok(p)
}

/// The vendor prototype table: sections in order, each with its prototypes.
pub struct Vendor {
    /// The sections in order, each with its prototypes.
    pub sections: Vec<(String, Vec<Proto>)>,
}

impl Vendor {
    pub fn load(path: &Path) -> Result<Vendor, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let mut sections: Vec<(String, Vec<Proto>)> = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if let Some(s) = line.strip_prefix("# section:") {
                sections.push((s.trim().to_string(), Vec::new()));
            } else if line.is_empty() || line.starts_with('#') {
                continue;
            } else {
                let p =
                    parse_proto(line).map_err(|e| format!("{}:{}: {e}", path.display(), n + 1))?;
                match sections.last_mut() {
                    Some((_, v)) => v.push(p),
                    None => {
                        return Err(format!("{}: prototype before any section", path.display()))
                    }
                }
            }
        }
        Ok(Vendor { sections })
    }

    pub fn find(&self, name: &str) -> Option<&Proto> {
        self.sections
            .iter()
            .flat_map(|(_, v)| v.iter())
            .find(|p| p.name == name)
    }
}

pub fn check_against_vendor(p: &Proto, v: &Proto) -> Result<(), String> {
    let same_types = p.params.len() == v.params.len()
        && p.params
            .iter()
            .zip(&v.params)
            .all(|(a, b)| a.ty == b.ty && a.name == b.name);
    if p.ret != v.ret || !same_types {
        return Err(format!(
            "{}: the Rust signature does not match the vendor prototype\n  rust:   {}\n  vendor: {}",
            p.name,
            render(p, None),
            render(v, None)
        ));
    }
    Ok(())
}

/// Renders a prototype; with `defaults`, appends `MCC_DEFAULT(v)` where the vendor has one.
pub fn render(p: &Proto, defaults: Option<&Proto>) -> String {
    let params: Vec<String> = p
        .params
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let mut s = String::new();
            for t in &a.ty {
                let ptr = t == "*" || t == "&";
                if !s.is_empty() && !(ptr && (s.ends_with('*') || s.ends_with('&'))) {
                    s.push(' ');
                }
                s.push_str(t);
            }
            if !(s.ends_with('*') || s.ends_with('&')) {
                s.push(' ');
            }
            s.push_str(a.name.as_deref().unwrap_or_default());
            if let Some(d) = defaults
                .and_then(|v| v.params.get(i))
                .and_then(|v| v.default.as_ref())
            {
                let _ = write!(s, " MCC_DEFAULT({d})");
            }
            s
        })
        .collect();
    let params = if params.is_empty() {
        "void".to_string()
    } else {
        params.join(", ")
    };
    format!("{} {}({})", p.ret.join(" "), p.name, params)
}
