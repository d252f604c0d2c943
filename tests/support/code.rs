//! A source file's code as the tests that read the sources see it (`module_layers`,
//! `module_cycles`, `one_tick`, `core_purity`, `no_pub_fields`).

/// `text` without its unit tests (from `#[cfg(test)]\nmod tests {` on) and without
/// comments (lines that start with `//`, and what follows ` // ` on a line).
pub fn code_of(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests {") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .map(|l| l.split(" // ").next().unwrap_or(l))
        .collect::<Vec<_>>()
        .join("\n")
}
