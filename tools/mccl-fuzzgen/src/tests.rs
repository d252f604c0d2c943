//! The fuzzer's view of small headers and what it generates from them.

use crate::view::{Base, Codes, Model, Prim};
use mccl_header_model::Header;

const TYPES: &str = "#ifndef T\n#define T\n#define N 2\n#define RUN_TIME_ERR (-14)\ntypedef uint16_t WORD;\ntypedef int BOOL;\ntypedef struct {\n  WORD w[N];\n  double d;\n} S;\ntypedef S S2;\ntypedef void (MCC_CALLBACK *ONE)(S*);\ntypedef BOOL (MCC_CALLBACK *MANY)(int, const double*, void *pvExtension);\ntypedef void (MCC_CALLBACK *NONE)(void);\n#endif\n";

fn model(funcs: &str) -> Result<Model, String> {
    let h = Header::parse(&[
        ("MCCL.h", TYPES),
        ("F.h", &format!("#include \"MCCL.h\"\n{funcs}")),
        (
            "mcl.h",
            "#define MCL_NO_ERROR 0\nint mcl_f(bool b, long l);\n",
        ),
    ])
    .map_err(|e| e.to_string())?;
    Model::of(&h)
}

#[test]
fn parameters_keep_their_spelling_and_draw_by_kind() {
    let m = model("MCC_API int MCC_CALL MCC_F(const S2 *pst, WORD wCardIndex MCC_DEFAULT(0), ONE f, BOOL b, MANY g);\n").unwrap();
    let f = &m.funcs[0];
    assert_eq!(f.codes, Codes::Vendor);
    let p = &f.params;
    // An alias of a struct fills the struct; its spelling stays the alias.
    assert_eq!(
        (p[0].cty.as_str(), p[0].cbase.as_str()),
        ("const S2 *", "S2")
    );
    assert_eq!(
        (p[0].base.clone(), p[0].ptr, p[0].is_const),
        (Base::Struct("S".into()), 1, true)
    );
    assert_eq!(
        (p[1].cty.as_str(), &p[1].base),
        ("WORD", &Base::Prim(Prim::Int(16, false)))
    );
    assert_eq!(p[2].base, Base::Callback("ONE".into()));
    // BOOL is an int; C99 bool a boolean; long 64 bits.
    assert_eq!(p[3].base, Base::Prim(Prim::Int(32, true)));
    let mcl = &m.funcs[1];
    assert_eq!(mcl.codes, Codes::Mcl);
    assert_eq!(mcl.params[0].base, Base::Prim(Prim::Bool));
    assert_eq!(mcl.params[1].base, Base::Prim(Prim::Int(64, true)));
    // Struct fields with their array lengths; the alias is not a second struct.
    assert_eq!(m.structs.keys().collect::<Vec<_>>(), ["S"]);
    assert_eq!(m.structs["S"][0].array, Some(2));
    // Routines: one pointee, several arguments as written (one named), none.
    assert_eq!(m.callbacks["ONE"].arg, "S");
    assert!(m.callbacks["ONE"].several.is_none());
    let many = m.callbacks["MANY"].several.as_ref().unwrap();
    assert_eq!(many, &["int", "const double *", "void *"]);
    assert_eq!(m.callbacks["MANY"].ret, "BOOL");
    assert_eq!(m.callbacks["NONE"].arg, "void");
    assert_eq!(m.headers, ["MCCL.h", "F.h", "mcl.h"]);
}

#[test]
fn what_cannot_be_called_fails_the_build() {
    for (proto, msg) in [
        (
            "char *MCC_F(void);",
            "F.h: MCC_F: pointer return types are not fuzzed",
        ),
        (
            "int MCC_F(WORD **pp);",
            "F.h: MCC_F: `WORD * * pp`: pointer to pointer",
        ),
        (
            "int MCC_F(ONE *pf);",
            "F.h: MCC_F: `ONE * pf`: pointer to callback",
        ),
        ("int MCC_F(UNKNOWN u);", "F.h:2: unknown type \"UNKNOWN\""),
    ] {
        match model(proto) {
            Ok(_) => panic!("{proto}: accepted"),
            Err(e) => assert_eq!(e, msg, "{proto}"),
        }
    }
}

#[test]
fn generated_callers_and_routines() {
    let m = model("MCC_API int MCC_CALL MCC_SetOne(ONE f, WORD wCardIndex MCC_DEFAULT(0));\nMCC_API double MCC_CALL MCC_GetX(double *pdfX, WORD wGroupIndex);\n").unwrap();
    let c = crate::gen::gen(&m).unwrap();
    for want in [
        "#include \"MCCL.h\"\n#include \"F.h\"\n#include \"mcl.h\"\n",
        "static BOOL MCC_CALLBACK fz_cb_MANY(int a0, const double * a1, void * a2)\n{\n    (void)a0;\n    (void)a1;\n    (void)a2;\n    fz_routine(0, NULL, 0);\n    return 1;\n}",
        "static void MCC_CALLBACK fz_cb_ONE(S *p)\n{\n    fz_routine(2, p, sizeof(*p));\n}",
        "    {\"ONE\", \"S\", (void (*)(void))fz_cb_ONE, 1, 0},",
        "    WORD a1;\n    a1 = (WORD)fz_int(z, FZ_H_CARD, 16, 0);",
        // An output double gets a finite sentinel; the result is a real.
        "        t = (double)12345.5;",
        "    double r = (double)MCC_GetX(a0, a1);\n    fz_end_real(z, 1, r, FZ_CODES_VENDOR);",
        "    {\"MCC_SetOne\", \"F.h\", fz_call_MCC_SetOne, FZ_F_ROUTINE_SETTER},",
        "fz_end_int(z, 0, (long long)MCC_SetOne((ONE)fz_cbs[2].fn, (WORD)card), FZ_CODES_VENDOR);",
        "for (int i = 0; i < 2; i++) {\n    v->w[i] = (WORD)fz_int(z, FZ_H_ANY, 16, 0);",
    ] {
        assert!(c.contains(want), "missing:\n{want}\nin:\n{c}");
    }
}

#[test]
fn the_command_line() {
    let a = |args: &[&str]| crate::args(lexopt::Parser::from_args(args));
    let (out, headers) = a(&["t.c", "MCCL.h", "mcl.h"]).unwrap().unwrap();
    assert_eq!(
        (out.as_str(), headers),
        ("t.c", vec!["MCCL.h".to_string(), "mcl.h".into()])
    );
    assert_eq!(a(&["--help"]), Ok(None));
    assert!(a(&["t.c"]).is_err());
    assert!(a(&["t.c", "--frob", "MCCL.h"])
        .unwrap_err()
        .contains("--frob"));
}
