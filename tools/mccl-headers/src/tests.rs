//! The vendor table, the prototype checks and the pieces of the headers.

use crate::mccl_h::{in_type_order, posture_by_reference};
use crate::prototype_test::rust_fn_type;
use crate::vendor::{check_against_vendor, parse_proto, render, Vendor};
use std::path::Path;

#[test]
fn parses_defaults_and_pointers() {
    let p = parse_proto(
        "int MCC_SetMacParam(SYS_MAC_PARAM *pstMacParam, WORD wChannel, WORD wCardIndex = 0)",
    )
    .unwrap();
    assert_eq!(p.ret, ["int"]);
    assert_eq!(p.params.len(), 3);
    assert_eq!(p.params[0].ty, ["SYS_MAC_PARAM", "*"]);
    assert_eq!(p.params[2].default.as_deref(), Some("0"));
    assert_eq!(
        render(&p, Some(&p)),
        "int MCC_SetMacParam(SYS_MAC_PARAM *pstMacParam, WORD wChannel, WORD wCardIndex MCC_DEFAULT(0))"
    );
    let q = parse_proto("double MCC_GetSysMaxSpeed(void);").unwrap();
    assert!(q.params.is_empty());
    assert_eq!(render(&q, None), "double MCC_GetSysMaxSpeed(void)");
    // The table and cbindgen name every parameter, and write no calling convention.
    for bad in [
        "int MCC_F(WORD)",
        "int MCC_F(const double*)",
        "MCC_API int MCC_CALL MCC_F(WORD w)",
        "int (*F)(int n)",
        "int MCC_F(int n",
    ] {
        assert!(parse_proto(bad).is_err(), "{bad}");
    }
}

#[test]
fn mismatch_is_an_error() {
    let v = parse_proto("int MCC_CloseGroup(int nGroupIndex)").unwrap();
    let wrong_type = parse_proto("int MCC_CloseGroup(WORD nGroupIndex)").unwrap();
    let wrong_name = parse_proto("int MCC_CloseGroup(int nGroup)").unwrap();
    let wrong_ret = parse_proto("double MCC_CloseGroup(int nGroupIndex)").unwrap();
    let extra = parse_proto("int MCC_CloseGroup(int nGroupIndex, int x)").unwrap();
    for p in [wrong_type, wrong_name, wrong_ret, extra] {
        assert!(check_against_vendor(&p, &v).is_err(), "{p:?}");
    }
    assert!(check_against_vendor(&v, &v).is_ok());
}

#[test]
fn rust_types_of_prototypes() {
    let p = |s| rust_fn_type(&parse_proto(s).unwrap()).unwrap();
    assert_eq!(
        p("int MCC_SetPGain(WORD wGain0, WORD wCardIndex = 0)"),
        "extern \"system\" fn(WORD, WORD) -> c_int"
    );
    assert_eq!(
        p("int MCC_GetPulsePos(long *plX, long long *plY, void *pv, char c)"),
        "unsafe extern \"system\" fn(*mut c_long, *mut c_longlong, *mut c_void, c_char) -> c_int"
    );
    assert_eq!(
        p("void MCC_GetVersion(char *strVersion)"),
        "unsafe extern \"system\" fn(*mut c_char)"
    );
    assert_eq!(
        p("double MCC_GetSysMaxSpeed()"),
        "extern \"system\" fn() -> f64"
    );
    assert!(rust_fn_type(&parse_proto("int f(unsigned short w)").unwrap()).is_err());
}

#[test]
fn type_declarations_follow_the_given_order() {
    let body = "#define A 1\n\ntypedef struct {\n  T x;\n} S;\n\ntypedef uint16_t T;\n\ntypedef void (MCC_CALLBACK *F)(S *p);\n\n#define B 2";
    let order = ["T", "S", "F"].map(String::from);
    assert_eq!(
        in_type_order(body, &order).unwrap(),
        "#define A 1\n\ntypedef uint16_t T;\n\ntypedef struct {\n  T x;\n} S;\n\ntypedef void (MCC_CALLBACK *F)(S *p);\n\n#define B 2"
    );
    assert!(in_type_order(body, &order[..2]).is_err());
}

#[test]
fn posture_is_a_reference_in_cpp_and_a_pointer_in_c() {
    let body = "typedef void (MCC_CALLBACK *G)(int n);\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD *dwPosture, void *p);\n";
    assert_eq!(
        posture_by_reference(body),
        "typedef void (MCC_CALLBACK *G)(int n);\n#ifdef __cplusplus\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD &dwPosture, void *p);\n#else\ntypedef BOOL (MCC_CALLBACK *F)(int n, DWORD *dwPosture, void *p);\n#endif\n"
    );
}

#[test]
fn vendor_table_has_all_344_plus_one() {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let v = Vendor::load(&here.join("vendor_prototypes.txt")).unwrap();
    let n: usize = v.sections.iter().map(|(_, p)| p.len()).sum();
    assert_eq!(n, 345);
    let p = v.find("MCC_CreateGroupEx").unwrap();
    assert_eq!(p.params[9].default.as_deref(), Some("MOTION_QUEUE_SIZE"));
}

#[test]
fn the_command_line() {
    let f = |args: &[&str]| crate::check_flag(lexopt::Parser::from_args(args));
    assert_eq!(f(&[]), Ok(Some(false)));
    assert_eq!(f(&["--check"]), Ok(Some(true)));
    assert_eq!(f(&["--help"]), Ok(None));
    assert!(f(&["--chek"]).unwrap_err().contains("--chek"));
    assert!(f(&["x"]).is_err());
}
