//! Messages in the user's words: byte offsets to lines, offsets to key paths, toml and
//! serde errors rephrased. Generic over any TOML text (nothing here knows the keys).

use super::*;

/// The 1-based line holding byte `offset` of `text`.
pub(super) fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    1 + text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

/// The key path (`card[0]`, `channel[2]`, `limit_minus`) of the innermost key or value
/// whose span holds `offset`; empty when none does (top level).
pub(super) fn locate(root: &DeTable<'_>, offset: usize) -> Vec<String> {
    let mut path = Vec::new();
    locate_in(root, offset, &mut path);
    path
}

pub(super) fn locate_in(table: &DeTable<'_>, offset: usize, path: &mut Vec<String>) -> bool {
    for (key, value) in table.iter() {
        let name: &str = key.get_ref();
        if key.span().contains(&offset) {
            path.push(name.to_owned());
            return true;
        }
        match value.get_ref() {
            DeValue::Table(sub) => {
                path.push(name.to_owned());
                if locate_in(sub, offset, path) || value.span().contains(&offset) {
                    return true;
                }
                path.pop();
            }
            DeValue::Array(items) => {
                for item in items.iter() {
                    if let DeValue::Table(sub) = item.get_ref() {
                        path.push(format!("{name}[{}]", element_label(name, sub)));
                        if locate_in(sub, offset, path) || item.span().contains(&offset) {
                            return true;
                        }
                        path.pop();
                    }
                }
                if value.span().contains(&offset) {
                    path.push(name.to_owned());
                    return true;
                }
            }
            _ => {
                if value.span().contains(&offset) {
                    path.push(name.to_owned());
                    return true;
                }
            }
        }
    }
    false
}

/// How a path names an element of the array of tables `name`: `set,slave` for remote I/O
/// slaves, else its `index` (cards, channels); `?` where those are missing or not integers.
pub(super) fn element_label(name: &str, table: &DeTable<'_>) -> String {
    let int = |k: &str| -> String {
        table
            .get(k)
            .and_then(|v| v.get_ref().as_integer())
            .and_then(|i| i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok())
            .map_or_else(|| "?".to_owned(), |i| i.to_string())
    };
    if name == "rio" {
        format!("{},{}", int("set"), int("slave"))
    } else {
        int("index")
    }
}

/// A toml/serde error as `file:line: key: what is wrong`.
pub(super) fn toml_error(text: &str, file: &str, e: &toml::de::Error) -> String {
    let msg = e.message().trim();
    let Some(span) = e.span() else {
        return format!("{file}: {msg}");
    };
    let line = line_of(text, span.start);
    let Ok(root) = DeTable::parse(text) else {
        // A syntax error: no tree to name the key from; quote the text at the error.
        let near = text
            .get(span.clone())
            .map(str::trim)
            .filter(|s| !s.is_empty() && s.len() <= 60 && !s.contains('\n'))
            .map(|s| format!(" (at `{s}`)"))
            .unwrap_or_default();
        return format!("{file}:{line}: TOML syntax error: {msg}{near}");
    };
    let mut path = locate(root.get_ref(), span.start);
    if let Some(rest) = msg.strip_prefix("unknown field `") {
        let (key, tail) = rest.split_once('`').unwrap_or((rest, ""));
        if path.last().map(String::as_str) == Some(key) {
            path.pop();
        }
        let place = if path.is_empty() {
            "at the top level".to_owned()
        } else {
            format!("in {}", path.join("."))
        };
        let known = tail
            .trim_start_matches(", ")
            .trim_start_matches("expected ")
            .trim_start_matches("one of ")
            .replace('`', "");
        let known = if known.is_empty() || known == "there are no fields" {
            String::new()
        } else {
            format!(" (known keys: {known})")
        };
        return format!("{file}:{line}: unknown key \"{key}\" {place}{known}");
    }
    let what = if let Some(rest) = msg.strip_prefix("missing field `") {
        format!("missing required key \"{}\"", rest.trim_end_matches('`'))
    } else if let Some(rest) = msg.strip_prefix("invalid type: ") {
        format!("wrong type: {}", plain_words(rest))
    } else if let Some(rest) = msg.strip_prefix("invalid value: ") {
        format!("invalid value: {}", plain_words(rest))
    } else {
        plain_words(msg)
    };
    let hint = if !path.is_empty() && what.ends_with("found a table, expected an array") {
        // The header of an array of tables names the keys without element labels.
        let keys: Vec<&str> = path.iter().filter_map(|p| p.split('[').next()).collect();
        format!(" (write [[{}]] for each element)", keys.join("."))
    } else {
        String::new()
    };
    let path = if path.is_empty() {
        "(top level)".to_owned()
    } else {
        path.join(".")
    };
    format!("{file}:{line}: {path}: {what}{hint}")
}

/// serde's type words ("map, expected f64") as a TOML user reads them.
pub(super) fn plain_words(s: &str) -> String {
    let (found, expected) = s.split_once(", expected ").unwrap_or((s, ""));
    let found = match found {
        "map" => "a table".to_owned(),
        "sequence" => "an array".to_owned(),
        f => f.replace('`', ""),
    };
    let expected = match expected {
        "" => return format!("found {found}"),
        "f64" => "a number",
        "i64" => "an integer",
        "a sequence" => "an array",
        "a boolean" => "true or false",
        e if e.starts_with("struct ") => "a table",
        e => e,
    };
    format!("found {found}, expected {expected}")
}
