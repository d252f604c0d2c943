//! The model of small headers written for the test, and of the project's own.

use crate::syntax::{parse_declaration, parse_prototype, Declaration};
use crate::*;
use std::collections::BTreeMap;

fn ws(s: &str) -> Vec<String> {
    s.split_whitespace().map(String::from).collect()
}

fn int(bytes: u8, signed: bool) -> CType {
    CType::Int { bytes, signed }
}

fn ptr(t: CType) -> CType {
    CType::Ptr(Box::new(t))
}

#[test]
fn expressions() {
    let mut c = BTreeMap::new();
    c.insert("A".to_string(), 12);
    assert_eq!(eval_expr("(A * 8)", &c), Ok(96));
    assert_eq!(eval_expr("(-1)", &c), Ok(-1));
    assert_eq!(eval_expr("0x10 | 1 << 2", &c), Ok(20));
    assert!(eval_expr("B", &c).is_err());
}

/// Each form a declaration takes in the headers, cbindgen's output and the vendor table.
#[test]
fn declarations_as_written() {
    let d = |s| parse_declaration(s).unwrap();
    assert_eq!(
        d("const double *pdfFrom"),
        Declaration {
            ty: ws("const double *"),
            name: Some("pdfFrom".into()),
            array: None,
            default: None,
        }
    );
    // Unnamed: a pointer, a type of several keywords, a typedef name, `const` and a name.
    assert_eq!(d("LIOINT*").ty, ws("LIOINT *"));
    assert_eq!(d("LIOINT*").name, None);
    assert_eq!(d("unsigned long").name, None);
    assert_eq!(d("const WORD").name, None);
    assert_eq!(
        d("BOOL* AbortThisCommand").name.as_deref(),
        Some("AbortThisCommand")
    );
    // The C++ reference of the kinematics callbacks.
    let r = d("DWORD &dwPosture");
    assert_eq!(
        (r.ty, r.name.as_deref()),
        (ws("DWORD &"), Some("dwPosture"))
    );
    // An array with its length as written.
    let a = d("uint64_t ullBucket[MCCL_SIM_CLOCK_BUCKETS]");
    assert_eq!(a.array.as_deref(), Some("MCCL_SIM_CLOCK_BUCKETS"));
    assert_eq!(a.name.as_deref(), Some("ullBucket"));
    // Default arguments in the three spellings.
    for s in [
        "WORD wCardIndex MCC_DEFAULT(0)",
        "WORD wCardIndex = 0",
        "WORD wCardIndex MCL_DEFAULT(0)",
    ] {
        assert_eq!(d(s).default.as_deref(), Some("0"), "{s}");
        assert_eq!(d(s).name.as_deref(), Some("wCardIndex"), "{s}");
    }
    assert!(parse_declaration("").is_err());
    assert!(parse_declaration("int [4]").is_err());
}

#[test]
fn prototypes_as_written() {
    let p = parse_prototype(
        "MCC_API int MCC_CALL MCC_SetMacParam(SYS_MAC_PARAM *pstMacParam, WORD wCardIndex MCC_DEFAULT(IMP_AXIS_ALL));",
    )
    .unwrap();
    assert_eq!(p.ret, ws("int"));
    assert_eq!(p.conv, ws("MCC_API MCC_CALL"));
    assert_eq!(p.name, "MCC_SetMacParam");
    assert!(!p.pointer);
    assert_eq!(p.params[0].ty, ws("SYS_MAC_PARAM *"));
    assert_eq!(p.params[1].default.as_deref(), Some("IMP_AXIS_ALL"));
    // `()` and `(void)` take nothing; a pointer return keeps its `*`.
    assert!(parse_prototype("int MCC_CloseAllGroups()")
        .unwrap()
        .params
        .is_empty());
    let q = parse_prototype("char *f(void);").unwrap();
    assert_eq!((q.ret, q.params.len()), (ws("char *"), 0));
    // A function pointer type, its C++ reference parameter kept as written.
    let f = parse_prototype(
        "BOOL (MCC_CALLBACK *FWDKINEFUN)(int nGroup, const double *pdfFrom, DWORD &dwPosture, void*)",
    )
    .unwrap();
    assert!(f.pointer);
    assert_eq!(
        (f.ret, f.conv, f.name.as_str()),
        (ws("BOOL"), ws("MCC_CALLBACK"), "FWDKINEFUN")
    );
    assert_eq!(f.params[2].ty, ws("DWORD &"));
    assert_eq!(f.params[3].name, None);
    let g = parse_prototype("void (*CB)(LIOINT*)").unwrap();
    assert!(g.conv.is_empty() && g.pointer);
    for bad in ["int f", "int (f)(int)", "f(int x)", "int f(int x"] {
        assert!(parse_prototype(bad).is_err(), "{bad}");
    }
}

#[test]
fn parses_types_and_protos() {
    let h = Header::parse(&[
        (
            "a.h",
            "#ifndef G\n#define G\n#ifndef X\n#define X __stdcall\n#endif\n#define N 2\n#define M (N * 4)\ntypedef uint16_t WORD;\ntypedef int BOOL;\ntypedef struct {\n  WORD w;\n  double d[M];\n} S;\ntypedef S T;\ntypedef void (MCC_CALLBACK *CB)(S*);\ntypedef CB CB2;\n#endif\n",
        ),
        (
            "b.h",
            "/* Generated.\n * Do not edit. */\n#include \"a.h\"\n/* Sec */\nMCC_API int MCC_CALL F(S *p, WORD w MCC_DEFAULT(0), CB2 f, long *l, BOOL b);\n",
        ),
    ])
    .unwrap();
    assert_eq!(h.consts.len(), 2);
    assert_eq!((h.consts[1].value, h.consts[1].header.as_str()), (8, "a.h"));
    assert_eq!(h.value("M"), Some(8));
    assert_eq!(h.structs[0].fields[1].count, Some(8));
    assert_eq!(h.structs[0].fields[0].written, ws("WORD"));
    assert_eq!(h.structs[0].fields[0].ty, int(2, false));
    assert_eq!(h.canonical("T"), "S");
    assert_eq!(h.struct_layout("T", WIN).unwrap().size, 72);
    assert_eq!(h.files[1].includes, ["a.h"]);
    let f = &h.funcs[0];
    assert_eq!((f.section.as_str(), f.header.as_str()), ("Sec", "b.h"));
    assert_eq!(f.params[0].ty, ptr(CType::Struct("S".into())));
    assert_eq!(f.params[1].default.as_deref(), Some("0"));
    // A callback type's alias resolves to the callback.
    assert_eq!(f.params[2].ty, CType::Callback("CB".into()));
    assert_eq!(f.params[2].written, ws("CB2"));
    assert!(f.has_clong());
    assert_eq!(f.params[4].ty, CType::Bool);
    let cb = &h.callbacks[0];
    assert_eq!(
        (cb.params[0].name.as_str(), cb.params[0].named),
        ("arg0", false)
    );
    assert_eq!(cb.conv, ws("MCC_CALLBACK"));
    assert_eq!(cb.params[0].ty.pointee(), (&CType::Struct("S".into()), 1));
}

/// A callback the header declares for C++ (a reference) and for C (a pointer) under
/// `#ifdef __cplusplus`/`#else` is read once, in its C form; a reference outside such a
/// pair is a pointer.
#[test]
fn cpp_branch_is_skipped_and_a_reference_is_a_pointer() {
    let h = Header::parse(&[(
        "a.h",
        "typedef uint32_t DWORD;\n#ifdef __cplusplus\ntypedef void (MCC_CALLBACK *K)(DWORD &p, int cpp);\n#else\ntypedef void (MCC_CALLBACK *K)(DWORD *p);\n#endif\ntypedef void (MCC_CALLBACK *L)(int n, DWORD &dwPosture);\n#ifdef __cplusplus\nextern \"C\" {\n#endif\nint f(bool b, unsigned long long n, const char *s);\n#ifdef __cplusplus\n} /* extern \"C\" */\n#endif\n",
    )])
    .unwrap();
    let names: Vec<&str> = h.callbacks.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["K", "L"]);
    assert_eq!(h.callbacks[0].params.len(), 1);
    assert_eq!(h.callbacks[0].params[0].ty, ptr(int(4, false)));
    assert_eq!(h.callbacks[1].params[1].ty, ptr(int(4, false)));
    assert_eq!(h.callbacks[1].params[1].written_text(), "DWORD &");
    let f = &h.funcs[0];
    assert_eq!(f.params[0].ty, CType::CBool);
    assert_eq!(f.params[1].ty, int(8, false));
    assert_eq!(f.params[2].ty, ptr(CType::Char));
    assert_eq!(f.params[2].written_text(), "const char *");
}

#[test]
fn what_the_model_does_not_know_is_an_error() {
    for (text, msg) in [
        ("int f(FOO x);\n", "a.h:1: unknown type \"FOO\""),
        (
            "\n\nstruct S { int a; };\n",
            "a.h:3: a line the header model does not know",
        ),
        ("typedef struct {\n  int a;\n", "a.h:1: struct not closed"),
        (
            "#define A (B + 1)\n",
            "a.h:1: #define A: unknown name \"B\"",
        ),
        (
            "typedef struct {\n  int a[-1];\n} S;\n",
            "a.h:2: negative array size",
        ),
    ] {
        let e = Header::parse(&[("a.h", text)]).unwrap_err();
        assert!(e.0.starts_with(msg), "{text:?}: {e}");
    }
}

/// The project's generated headers: every function, callback type and struct the tools
/// rely on, with the vendor's numbers.
#[test]
fn the_generated_headers() {
    let inc = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../include");
    let names = ["MCCL.h", "MCCL_Fun.h", "MCCL_Sim.h", "mccl.h", "mcl.h"];
    let texts: Vec<String> = names
        .iter()
        .map(|n| std::fs::read_to_string(inc.join(n)).unwrap())
        .collect();
    let files: Vec<(&str, &str)> = names
        .iter()
        .copied()
        .zip(texts.iter().map(String::as_str))
        .collect();
    let h = Header::parse(&files).unwrap();
    let in_file = |f: &str| h.funcs.iter().filter(|x| x.header == f).count();
    // The 345 vendor functions, the 19 of the MC3B library, the 7 of the simulation.
    assert_eq!(
        (
            in_file("MCCL_Fun.h"),
            in_file("mcl.h"),
            in_file("MCCL_Sim.h")
        ),
        (345, 19, 7)
    );
    assert_eq!(h.callbacks.len(), 20);
    assert_eq!(h.value("MAX_GROUP_NUM"), Some(96)); // MAX_CARD_NUM (12) * MAX_AXIS_NUM (8)
    assert_eq!(h.value("RUN_TIME_ERR"), Some(-14));
    let fwd = h.callbacks.iter().find(|c| c.name == "FWDKINEFUN").unwrap();
    assert_eq!(fwd.params[4].written_text(), "DWORD *"); // the C form
    let ex = h
        .funcs
        .iter()
        .find(|f| f.name == "MCC_CreateGroupEx")
        .unwrap();
    assert_eq!(ex.params[9].default.as_deref(), Some("MOTION_QUEUE_SIZE"));
    assert_eq!(ex.section, "System Management");
    let sm = h
        .funcs
        .iter()
        .find(|f| f.name == "mcl_synchronous_move_motor")
        .unwrap();
    assert_eq!(
        (&sm.params[7].ty, sm.params[7].default.as_deref()),
        (&CType::CBool, Some("true"))
    );
    assert_eq!(h.canonical("ENCODER_CONFIG"), "SYS_ENCODER_CONFIG");
    let stats = h.find_struct("MCCL_CLOCK_STATS").unwrap();
    assert_eq!(stats.fields.last().unwrap().count, Some(16));
}
