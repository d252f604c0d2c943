//! The headers declare exactly the functions a built library exports: the `MCC_*`,
//! `mcl_*` and `MCCL_Sim*` prototypes of the four generated headers, read by the one
//! header model, against the library's exports ([`crate::exports`]); the library exports
//! nothing without one of its prefixes, and a Windows DLL's names are undecorated (no
//! leading `_`, no `@N`: what `GetProcAddress`, VB6 `Declare` and `.def` files use).

use std::collections::BTreeSet;

/// The prefixes of the functions the library exports and the headers declare.
const DECLARED_PREFIXES: [&str; 3] = ["MCC_", "mcl_", "MCCL_Sim"];

/// The prefixes any export of the library carries.
const EXPORT_PREFIXES: [&str; 3] = ["MCC_", "MCCL_", "mcl_"];

/// What [`compare`] found.
#[derive(Debug, Default, PartialEq)]
pub struct Report {
    /// Declared by a header, not exported.
    pub missing: Vec<String>,
    /// Exported with a declared prefix, not declared.
    pub undeclared: Vec<String>,
    /// Exported without any of the library's prefixes.
    pub stray: Vec<String>,
    /// Exported under a decorated name (`_f`, `f@8`).
    pub decorated: Vec<String>,
    /// Functions both declared and exported.
    pub matched: usize,
}

impl Report {
    /// The problems, one line each.
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (what, names) in [
            ("declared by a header, not exported", &self.missing),
            ("exported, not declared by a header", &self.undeclared),
            ("exported without a prefix of the library", &self.stray),
            ("exported under a decorated name", &self.decorated),
        ] {
            out.extend(names.iter().map(|n| format!("{what}: {n}")));
        }
        out
    }
}

/// Compares the functions the headers declare with a library's exports.
pub fn compare<'a>(
    declared: impl IntoIterator<Item = &'a str>,
    exported: impl IntoIterator<Item = &'a str>,
) -> Report {
    let declared: BTreeSet<&str> = declared
        .into_iter()
        .filter(|n| DECLARED_PREFIXES.iter().any(|p| n.starts_with(p)))
        .collect();
    let exported: BTreeSet<&str> = exported.into_iter().collect();
    let ours: BTreeSet<&str> = exported
        .iter()
        .copied()
        .filter(|n| DECLARED_PREFIXES.iter().any(|p| n.starts_with(p)))
        .collect();
    let owned = |s: std::collections::btree_set::Difference<'_, &str>| -> Vec<String> {
        s.map(|n| n.to_string()).collect()
    };
    Report {
        missing: owned(declared.difference(&ours)),
        undeclared: owned(ours.difference(&declared)),
        stray: exported
            .iter()
            .filter(|n| !EXPORT_PREFIXES.iter().any(|p| n.starts_with(p)))
            .map(|n| n.to_string())
            .collect(),
        decorated: exported
            .iter()
            .filter(|n| n.starts_with('_') || n.contains('@'))
            .map(|n| n.to_string())
            .collect(),
        matched: declared.intersection(&ours).count(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_each_kind_of_difference() {
        let declared = [
            "MCC_Line",
            "MCC_ArcXY",
            "mcl_init",
            "MCCL_SimGetMotor",
            "SOME_MACRO",
        ];
        let exported = [
            "MCC_Line",
            "mcl_init",
            "MCCL_SimGetMotor",
            "MCC_Secret",
            "rust_eh_personality",
            "_MCC_Old@8",
        ];
        let r = compare(declared, exported);
        assert_eq!(r.missing, ["MCC_ArcXY"]);
        assert_eq!(r.undeclared, ["MCC_Secret"]);
        assert_eq!(r.stray, ["_MCC_Old@8", "rust_eh_personality"]);
        assert_eq!(r.decorated, ["_MCC_Old@8"]);
        assert_eq!(r.matched, 3);
        assert_eq!(r.problems().len(), 5);
    }

    #[test]
    fn the_same_sets_are_no_problem() {
        let names = ["MCC_Line", "mcl_init", "MCCL_SimGetMotor"];
        let r = compare(names, names);
        assert!(r.problems().is_empty());
        assert_eq!(r.matched, 3);
    }
}
