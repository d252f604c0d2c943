//! The checker must accept the generated bindings and reject each kind of mistake.

use super::*;
use crate::gen;
use crate::model::Header;
use std::path::Path;

fn root() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn real_header_text() -> (String, String) {
    let r = root();
    (
        std::fs::read_to_string(r.join("include/MCCL.h")).unwrap(),
        std::fs::read_to_string(r.join("include/MCCL_Fun.h")).unwrap(),
    )
}

fn header(a: &str, b: &str) -> Header {
    Header::parse(&[("MCCL.h", a), ("MCCL_Fun.h", b)]).unwrap()
}

fn real() -> Header {
    let (a, b) = real_header_text();
    header(&a, &b)
}

fn exports_of(h: &Header) -> Vec<String> {
    h.funcs.iter().map(|f| f.name.clone()).collect()
}

fn run(lang: Lang, text: &str, h: &Header, exports: &[String]) -> Report {
    verify(lang, "test", text, h, exports)
}

fn generated(lang: Lang, h: &Header) -> String {
    match lang {
        Lang::CSharp => gen::csharp(h),
        Lang::Vb6 => gen::vb6(h),
        Lang::VbNet => gen::vbnet(h),
    }
    .unwrap()
}

/// Replaces exactly one occurrence (so a test cannot silently mutate nothing).
fn replace_once(text: &str, from: &str, to: &str) -> String {
    assert_eq!(
        text.matches(from).count(),
        1,
        "{from:?} must occur exactly once"
    );
    text.replacen(from, to, 1)
}

fn assert_reports(r: &Report, needle: &str) {
    assert!(
        r.problems.iter().any(|p| p.contains(needle)),
        "expected a problem containing {needle:?}, got {:#?}",
        r.problems
    );
}

const ALL: [Lang; 3] = [Lang::CSharp, Lang::Vb6, Lang::VbNet];

#[test]
fn generated_bindings_pass() {
    let h = real();
    let ex = exports_of(&h);
    for lang in ALL {
        let r = run(lang, &generated(lang, &h), &h, &ex);
        assert!(r.problems.is_empty(), "{lang:?}: {:#?}", r.problems);
        assert_eq!(r.functions, h.funcs.len());
        assert_eq!(r.structs, h.structs.len());
        assert!(r.params > 50 && r.fields > 190, "{}", r.summary());
    }
}

#[test]
fn committed_files_pass() {
    let h = real();
    let ex = exports_of(&h);
    for (lang, path) in [
        (Lang::CSharp, "csharp/MCCL.cs"),
        (Lang::Vb6, "vb-bindings/MCCLPCI_IMP.bas"),
        (Lang::VbNet, "vb-bindings/MCCL.vb"),
    ] {
        let text = std::fs::read_to_string(root().join(path)).unwrap();
        let r = run(lang, &text, &h, &ex);
        assert!(r.problems.is_empty(), "{path}: {:#?}", r.problems);
    }
}

#[test]
fn known_struct_sizes_hold_in_the_c_model() {
    let h = real();
    for (name, size) in KNOWN_SIZES {
        assert_eq!(h.struct_layout(name, WIN).unwrap().size, *size, "{name}");
    }
}

// ---- C#

#[test]
fn cs_missing_function() {
    let h = real();
    let text = generated(Lang::CSharp, &h);
    let text = replace_once(
        &text,
        "    [DllImport(\"MCCLPCI_IMP.dll\", EntryPoint = \"MCC_CloseGroup\")]\n    public static extern int MCC_CloseGroup(int nGroupIndex);\n",
        "",
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(&r, "MCC_CloseGroup is missing");
    assert_eq!(r.problems.len(), 1, "{:#?}", r.problems);
}

#[test]
fn cs_wrong_width() {
    let h = real();
    let text = generated(Lang::CSharp, &h).replacen(
        "MCC_SetMacParam(ref SYS_MAC_PARAM pstMacParam, ushort wChannel",
        "MCC_SetMacParam(ref SYS_MAC_PARAM pstMacParam, int wChannel",
        1,
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "MCC_SetMacParam: parameter 2 (wChannel): declared as 4-byte integer by value, C has 2-byte integer by value",
    );
    // A double where C has a DWORD, and a wrong return width.
    let text = generated(Lang::CSharp, &h)
        .replacen(
            "MCC_TimeDelay(uint dwTime)",
            "MCC_TimeDelay(double dwTime)",
            1,
        )
        .replacen(
            "public static extern double MCC_GetSysMaxSpeed",
            "public static extern float MCC_GetSysMaxSpeed",
            1,
        );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "parameter 1 (dwTime): declared as 8-byte float by value, C has 4-byte integer",
    );
    assert_reports(
        &r,
        "MCC_GetSysMaxSpeed: return: declared as 4-byte float by value, C has 8-byte float",
    );
}

#[test]
fn cs_wrong_by_ref() {
    let h = real();
    let text = generated(Lang::CSharp, &h).replacen(
        "MCC_GetHomeConfig(ref SYS_HOME_CONFIG pstHomeConfig",
        "MCC_GetHomeConfig(SYS_HOME_CONFIG pstHomeConfig",
        1,
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "MCC_GetHomeConfig: parameter 1 (pstHomeConfig): declared as struct SYS_HOME_CONFIG by value, C has pointer to SYS_HOME_CONFIG",
    );
    let text = generated(Lang::CSharp, &h).replacen(
        "MCC_CloseGroup(int nGroupIndex)",
        "MCC_CloseGroup(ref int nGroupIndex)",
        1,
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "parameter 1 (nGroupIndex): declared as pointer to 4-byte integer",
    );
}

#[test]
fn cs_swapped_struct_fields() {
    let h = real();
    let text = generated(Lang::CSharp, &h);
    // SYS_HOME_CONFIG: nIndexCount (int @8) and dfAccTime (double @16) swapped.
    let text = replace_once(
        &text,
        "    public int nIndexCount;\n    public int nPaddel1;\n    public double dfAccTime;\n    public double dfDecTime;\n    public double dfHighSpeed;\n    public double dfLowSpeed;\n    public double dfOffset;\n}\n\n[StructLayout(LayoutKind.Sequential)]\npublic struct SYS_CARD_CONFIG",
        "    public double dfAccTime;\n    public int nPaddel1;\n    public int nIndexCount;\n    public double dfDecTime;\n    public double dfHighSpeed;\n    public double dfLowSpeed;\n    public double dfOffset;\n}\n\n[StructLayout(LayoutKind.Sequential)]\npublic struct SYS_CARD_CONFIG",
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "SYS_HOME_CONFIG: field 5 is dfAccTime, C has nIndexCount",
    );
    assert_reports(
        &r,
        "SYS_HOME_CONFIG.dfAccTime: element Float(8), C has Int(4)",
    );
    assert_reports(&r, "SYS_HOME_CONFIG.nPaddel1: offset 16, C has 12");
    // Two same-width fields swapped: only the names tell. (Anchored on the struct's
    // name: SYS_MACH_PARAM starts with the same two fields.)
    let text = replace_once(
        &generated(Lang::CSharp, &h),
        "public struct SYS_MAC_PARAM\n{\n    public ushort wPosToEncoderDir;\n    public ushort wRPM;",
        "public struct SYS_MAC_PARAM\n{\n    public ushort wRPM;\n    public ushort wPosToEncoderDir;",
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(&r, "SYS_MAC_PARAM: field 1 is wRPM, C has wPosToEncoderDir");
}

#[test]
fn cs_struct_array_without_size_const_and_wrong_length() {
    let h = real();
    let g = generated(Lang::CSharp, &h);
    let text = replace_once(
        &g,
        "    [MarshalAs(UnmanagedType.ByValArray, SizeConst = 8)]\n    public double[] dfPos;",
        "    public double[] dfPos;",
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(&r, "array without [MarshalAs(ByValArray, SizeConst)]");
    let text = g.replacen(
        "SizeConst = 256)]\n    public int[] nForwardTable",
        "SizeConst = 255)]\n    public int[] nForwardTable",
        1,
    );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "SYS_COMP_PARAM.nForwardTable: array length Some(255), C has Some(256)",
    );
    assert_reports(&r, "SYS_COMP_PARAM: size 2052, C has 2056");
}

#[test]
fn cs_not_exported_wrong_lib_wrong_convention() {
    let h = real();
    let mut ex = exports_of(&h);
    ex.retain(|s| s != "MCC_ResetMotion");
    ex.push("MCC_Extra".into());
    let text = generated(Lang::CSharp, &h)
        .replacen("[DllImport(\"MCCLPCI_IMP.dll\", EntryPoint = \"MCC_CloseSystem\")]", "[DllImport(\"MCCL_Client.dll\", EntryPoint = \"MCC_CloseSystem\")]", 1)
        .replacen("[DllImport(\"MCCLPCI_IMP.dll\", EntryPoint = \"MCC_UpdateParam\")]", "[DllImport(\"MCCLPCI_IMP.dll\", EntryPoint = \"MCC_UpdateParam\", CallingConvention = CallingConvention.Cdecl)]", 1)
        .replacen("[UnmanagedFunctionPointer(CallingConvention.Winapi)]\n    public delegate void ENCISR", "[UnmanagedFunctionPointer(CallingConvention.Cdecl)]\n    public delegate void ENCISR", 1)
        .replacen("EntryPoint = \"MCC_CheckDryRun\")]", "EntryPoint = \"MCC_CheckDryRunX\")]", 1);
    let r = run(Lang::CSharp, &text, &h, &ex);
    assert_reports(
        &r,
        "MCC_ResetMotion: entry point MCC_ResetMotion is not exported",
    );
    assert_reports(
        &r,
        "MCC_Extra is exported by the library but declared nowhere",
    );
    assert_reports(
        &r,
        "MCC_CloseSystem: library \"MCCL_Client.dll\" is not MCCLPCI_IMP",
    );
    assert_reports(&r, "MCC_UpdateParam: calling convention Cdecl");
    assert_reports(&r, "delegate ENCISR: calling convention Cdecl");
    assert_reports(
        &r,
        "entry point MCC_CheckDryRunX is not declared in MCCL_Fun.h",
    );
    assert_reports(&r, "MCC_CheckDryRun is missing");
}

#[test]
fn cs_delegate_and_constant_mismatch() {
    let h = real();
    let text = generated(Lang::CSharp, &h)
        .replacen(
            "public delegate void LIOISR(ref LIOINT value);",
            "public delegate void LIOISR(LIOINT value);",
            1,
        )
        .replacen(
            "public const int GMS_STOP = 1;",
            "public const int GMS_STOP = 2;",
            1,
        );
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(&r, "delegate LIOISR: parameter 1 (value): declared as struct LIOINT by value, C has pointer to LIOINT");
    assert_reports(&r, "constant GMS_STOP = 2, C has 1");
}

// ---- VB6

#[test]
fn vb6_mistakes() {
    let h = real();
    let ex = exports_of(&h);
    let g = generated(Lang::Vb6, &h);
    // Missing function.
    let text = g
        .lines()
        .filter(|l| !l.contains("Declare Function MCC_ResetMotion "))
        .collect::<Vec<_>>()
        .join("\n");
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "MCC_ResetMotion is missing",
    );
    // WORD declared as Long.
    let text = g.replacen(
        "MCC_GetConvFactor Lib \"MCCLPCI_IMP.dll\" (ByVal wChannel As Integer",
        "MCC_GetConvFactor Lib \"MCCLPCI_IMP.dll\" (ByVal wChannel As Long",
        1,
    );
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "MCC_GetConvFactor: parameter 1 (wChannel): declared as 4-byte integer by value, C has 2-byte integer",
    );
    // ByVal forgotten: VB6's default is ByRef.
    let text = g.replacen("(ByVal nGroupIndex As Long)", "(nGroupIndex As Long)", 1);
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "MCC_CloseGroup: parameter 1 (nGroupIndex): declared as pointer to 4-byte integer (by reference), C has 4-byte integer by value",
    );
    // A UDT ByVal.
    let text = g.replacen("(ByRef pstMacParam As SYS_MAC_PARAM, ByVal wChannel As Integer, Optional ByVal wCardIndex As Integer = 0) As Long\nPublic Declare Function MCC_GetMacParam", "(ByVal pstMacParam As SYS_MAC_PARAM, ByVal wChannel As Integer, Optional ByVal wCardIndex As Integer = 0) As Long\nPublic Declare Function MCC_GetMacParam", 1);
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "VB6 cannot pass a UDT by value",
    );
    // The tail padding removed: VB6 would make SYS_MAC_PARAM 68 bytes, C writes 72.
    let start = g.find("Public Type SYS_MAC_PARAM\n").unwrap();
    let pad = g[start..].find("    MCCL_pad0(0 To 3) As Byte").unwrap() + start;
    let end = g[pad..].find('\n').unwrap() + pad + 1;
    let text = format!("{}{}", &g[..pad], &g[end..]);
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "SYS_MAC_PARAM: size 68, C has 72",
    );
    // Swapped fields.
    let text = g.replacen(
        "    wCardType As Integer\n    wCardAddress As Integer",
        "    wCardAddress As Integer\n    wCardType As Integer",
        1,
    );
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "SYS_CARD_CONFIG: field 1 is wCardAddress, C has wCardType",
    );
    // Wrong return type.
    let text = g.replacen(
        "MCC_GetSysMaxSpeed Lib \"MCCLPCI_IMP.dll\" () As Double",
        "MCC_GetSysMaxSpeed Lib \"MCCLPCI_IMP.dll\" () As Single",
        1,
    );
    assert_reports(
        &run(Lang::Vb6, &text, &h, &ex),
        "MCC_GetSysMaxSpeed: return: declared as 4-byte float",
    );
}

#[test]
fn vb6_continuations_alias_and_bounds_parse() {
    let h = header(
        "#ifndef G\n#define G\ntypedef uint16_t WORD;\ntypedef struct {\n  WORD a;\n  double d[3];\n} S;\ntypedef void (MCC_CALLBACK *CB)(S*);\n#endif\n",
        "/* X */\nMCC_API int MCC_CALL MCC_F(S *p, WORD w, CB f);\nMCC_API void MCC_CALL MCC_G(void);\n",
    );
    let ex = exports_of(&h);
    let text = "Attribute VB_Name = \"M\"\nOption Explicit\nType S\n  a As Integer\n  pad(1 To 2) As Byte ' comment\n  d(2) As Double\nEnd Type\nDeclare Function MyF Lib \"mcclpci_imp\" Alias \"MCC_F\" _\n   (p As S, ByVal w As Integer, _\n    ByVal f As Long) As Long\nPrivate Declare Sub MCC_G Lib \"MCCLPCI_IMP.dll\" ()\n";
    let r = run(Lang::Vb6, text, &h, &ex);
    // MyF is callable only as MyF, and the struct has a 'pad' field VB6 added by hand.
    assert_reports(&r, "MCC_F: no public method of that name");
    assert_reports(&r, "MCC_G: no public method of that name");
    assert_reports(&r, "S: 3 fields, C has 2");
    assert!(
        !r.problems.iter().any(|p| p.contains("declared as")),
        "{:#?}",
        r.problems
    );
    assert_eq!(r.functions, 2);
    assert_eq!(r.params, 3);
}

// ---- VB.NET

#[test]
fn vbnet_mistakes() {
    let h = real();
    let ex = exports_of(&h);
    let g = generated(Lang::VbNet, &h);
    let text = g.replacen(
        "Public Function MCC_SetEncoderConfig(ByRef pstEncoderConfig",
        "Public Function MCC_SetEncoderConfig(ByVal pstEncoderConfig",
        1,
    );
    assert_reports(&run(Lang::VbNet, &text, &h, &ex), "MCC_SetEncoderConfig: parameter 1 (pstEncoderConfig): declared as struct SYS_ENCODER_CONFIG by value");
    let text = g.replacen(
        "Public Function MCC_GetMotionStatus(Optional ByVal wGroupIndex As UShort = 0)",
        "Public Function MCC_GetMotionStatus(Optional ByVal wGroupIndex As Integer = 0)",
        1,
    );
    assert_reports(
        &run(Lang::VbNet, &text, &h, &ex),
        "MCC_GetMotionStatus: parameter 1 (wGroupIndex): declared as 4-byte integer",
    );
    let text = g.replacen(
        "    <DllImport(\"MCCLPCI_IMP.dll\", EntryPoint:=\"MCC_EnableDryRun\")>\n    Public Function MCC_EnableDryRun() As Integer\n    End Function\n",
        "",
        1,
    );
    assert_reports(
        &run(Lang::VbNet, &text, &h, &ex),
        "MCC_EnableDryRun is missing",
    );
    let text = g.replacen(
        "    Public HOME0 As Byte\n    Public HOME1 As Byte",
        "    Public HOME1 As Byte\n    Public HOME0 As Byte",
        1,
    );
    assert_reports(
        &run(Lang::VbNet, &text, &h, &ex),
        "LIOINT: field 17 is HOME1, C has HOME0",
    );
    let text = g.replacen(
        "Public Delegate Sub ENCISR(ByRef value As ENCINT)",
        "Public Delegate Sub ENCISR(ByRef value As ENCINT, ByVal x As Integer)",
        1,
    );
    assert_reports(
        &run(Lang::VbNet, &text, &h, &ex),
        "delegate ENCISR: 2 parameters, the C prototype has 1",
    );
}

#[test]
fn vbnet_declare_form_parses() {
    let h = header(
        "#ifndef G\n#define G\ntypedef uint16_t WORD;\ntypedef struct {\n  WORD a;\n} S;\n#endif\n",
        "/* X */\nMCC_API int MCC_CALL MCC_F(S *p, WORD w);\n",
    );
    let ex = exports_of(&h);
    let ok = "<StructLayout(LayoutKind.Sequential)> _\nPublic Structure S\n  Public a As UShort\nEnd Structure\nModule M\n  Public Declare Ansi Function MCC_F Lib \"MCCLPCI_IMP.dll\" (ByRef p As S, ByVal w As UShort) As Integer\nEnd Module\n";
    let r = run(Lang::VbNet, ok, &h, &ex);
    assert!(r.problems.is_empty(), "{:#?}", r.problems);
    // VB.NET's default is ByVal, so a missing ByRef passes the struct by value.
    let bad = ok.replace("(ByRef p As S", "(p As S");
    assert_reports(
        &run(Lang::VbNet, &bad, &h, &ex),
        "declared as struct S by value",
    );
    // A Structure without StructLayout(Sequential) is not checked as C-compatible.
    let bad = ok.replace("<StructLayout(LayoutKind.Sequential)> _\n", "");
    assert_reports(
        &run(Lang::VbNet, &bad, &h, &ex),
        "S: not [StructLayout(LayoutKind.Sequential)]",
    );
}

// ---- C long, BOOL, char and other types the header will grow

const FUTURE_H: &str = "#ifndef G\n#define G\n#define BIG 0x80000000\ntypedef uint16_t WORD;\ntypedef uint32_t DWORD;\ntypedef int BOOL;\ntypedef struct {\n  WORD a;\n  double d;\n  WORD tail;\n} S;\ntypedef void (MCC_CALLBACK *CB)(S*);\n#endif\n";
const FUTURE_FUN: &str = "/* Encoder Control */\nMCC_API int MCC_CALL MCC_GetENCValue(long *plValue, WORD wChannel, WORD wCardIndex MCC_DEFAULT(0));\nMCC_API int MCC_CALL MCC_SetENCValue(long lValue, WORD wChannel, WORD wCardIndex MCC_DEFAULT(0));\nMCC_API long MCC_CALL MCC_GetLong(unsigned long *pu, long long *pll);\nMCC_API void MCC_CALL MCC_VoidLong(long l);\nMCC_API int MCC_CALL MCC_Hold(WORD wGroupIndex MCC_DEFAULT(0), BOOL bBlockEnd MCC_DEFAULT(0));\nMCC_API BOOL MCC_CALL MCC_IsOn(BOOL *pb, char c, void *pv, CB f, DWORD dwMask MCC_DEFAULT(255));\n";

#[test]
fn future_types_generate_and_pass() {
    let h = header(FUTURE_H, FUTURE_FUN);
    let ex = exports_of(&h);
    for lang in ALL {
        let text = generated(lang, &h);
        let r = run(lang, &text, &h, &ex);
        assert!(r.problems.is_empty(), "{lang:?}: {:#?}\n{text}", r.problems);
    }
    let cs = generated(Lang::CSharp, &h);
    assert!(cs.contains("public static int MCC_GetENCValue(ref int plValue, ushort wChannel, ushort wCardIndex = 0)"), "{cs}");
    assert!(
        cs.contains("private static extern int MCC_GetENCValue_L64(ref long plValue"),
        "{cs}"
    );
    assert!(
        cs.contains("MCC_GetLong_L64(ref ulong pu, ref long pll)"),
        "{cs}"
    );
    assert!(cs.contains("public static extern int MCC_Hold(ushort wGroupIndex = 0, [MarshalAs(UnmanagedType.Bool)] bool bBlockEnd = false);"), "{cs}");
    let bas = generated(Lang::Vb6, &h);
    assert!(
        bas.contains("(ByRef plValue As Long, ByVal wChannel As Integer"),
        "{bas}"
    );
    assert!(
        bas.contains("Public Const BIG As Long = &H80000000&"),
        "{bas}"
    );
    // VB6 pads S (a WORD, a double at 4 in VB6 but 8 in C, a WORD) to the C layout.
    assert!(bas.contains("    a As Integer\n    MCCL_pad0(0 To 5) As Byte\n    d As Double\n    tail As Integer\n    MCCL_pad1(0 To 5) As Byte"), "{bas}");
}

#[test]
fn clong_needs_both_widths() {
    let h = header(FUTURE_H, FUTURE_FUN);
    let ex = exports_of(&h);
    let cs = generated(Lang::CSharp, &h);
    // Without the 8-byte extern the binding would corrupt memory on LP64 Linux.
    let start = cs.find("    [DllImport(\"MCCLPCI_IMP.dll\", EntryPoint = \"MCC_GetENCValue\")]\n    private static extern int MCC_GetENCValue_L64").unwrap();
    let end = start + cs[start..].find(";\n").unwrap() + 2;
    let text = format!("{}{}", &cs[..start], &cs[end..]);
    assert_reports(
        &run(Lang::CSharp, &text, &h, &ex),
        "MCC_GetENCValue: no declaration for a 8-byte C long (needed on LP64 Linux)",
    );
    // `ref int` alone (what vendor C# files do) is the Windows-only width.
    let text = cs.replacen(
        "private static extern int MCC_SetENCValue_L64(long lValue",
        "private static extern int MCC_SetENCValue_L64(int lValue",
        1,
    );
    assert_reports(
        &run(Lang::CSharp, &text, &h, &ex),
        "MCC_SetENCValue: no declaration for a 8-byte C long",
    );
    // VB6 is Win32: long is Long; Currency (8 bytes) is wrong there.
    let bas = generated(Lang::Vb6, &h).replacen(
        "(ByRef plValue As Long",
        "(ByRef plValue As Currency",
        1,
    );
    assert_reports(&run(Lang::Vb6, &bas, &h, &ex), "MCC_GetENCValue: parameter 1 (plValue): declared as pointer to 8-byte integer (by reference), C has pointer to 4-byte integer");
    // The public wrapper must exist.
    let vb = generated(Lang::VbNet, &h).replacen(
        "Public Function MCC_GetENCValue(",
        "Public Function MCC_GetENCValueX(",
        1,
    );
    assert_reports(
        &run(Lang::VbNet, &vb, &h, &ex),
        "MCC_GetENCValue: no public method of that name with 3 parameters",
    );
}

#[test]
fn dword_of_the_wrong_width_breaks_the_vendor_sizes() {
    // The header's own DWORD made 64-bit (the vendor's non-Windows `unsigned long` branch).
    let (a, b) = real_header_text();
    let a = replace_once(&a, "typedef uint32_t DWORD;", "typedef uint64_t DWORD;");
    let h = header(&a, &b);
    let text = gen::csharp(&h).unwrap();
    let r = run(Lang::CSharp, &text, &h, &exports_of(&h));
    assert_reports(
        &r,
        "SYS_MAC_PARAM: the C header gives 80 bytes, the vendor layout is 72",
    );
    assert_reports(
        &r,
        "SYS_COMP_PARAM: the C header gives 2064 bytes, the vendor layout is 2056",
    );
}

/// Compiles the generated C# (with C long wrappers) when mcs is installed.
#[test]
fn future_csharp_compiles_with_mcs() {
    let Ok(out) = std::process::Command::new("mcs").arg("--version").output() else {
        eprintln!("mcs not installed: compile check skipped");
        return;
    };
    assert!(out.status.success());
    let h = header(FUTURE_H, FUTURE_FUN);
    let dir = std::env::temp_dir().join(format!("mccl-bindings-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let src = dir.join("Future.cs");
    std::fs::write(&src, gen::csharp(&h).unwrap()).unwrap();
    let out = std::process::Command::new("mcs")
        .args(["-langversion:7.2", "-target:library", "-warnaserror+"])
        .arg(format!("-out:{}", dir.join("Future.dll").display()))
        .arg(&src)
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

const STUB_C: &str = r#"
#include <stdint.h>
typedef struct { uint16_t a; double d; uint16_t tail; } S;
typedef void (*CB)(S *);
int MCC_GetENCValue(long *p, uint16_t ch, uint16_t card) { *p = -123456789L - ch - card; return (int)sizeof(long); }
int MCC_SetENCValue(long v, uint16_t ch, uint16_t card) { return v == -7 ? (int)(ch + card) : -1; }
long MCC_GetLong(unsigned long *pu, long long *pll) { *pu = 4000000000UL; *pll = -(1LL << 40); return -2; }
static long last;
void MCC_VoidLong(long l) { last = l; }
int MCC_Hold(uint16_t g, int b) { return g * 10 + (b != 0) + (int)last * 100; }
int MCC_IsOn(int *pb, char c, void *pv, CB f, uint32_t mask) {
    S s = {7, 2.5, 9};
    *pb = 1;
    if (f) f(&s);
    return c == 'x' && pv == 0 && mask == 255 && s.a == 8 && s.tail == 9;
}
"#;

const STUB_CS: &str = r#"
using System;
public static class P {
    static int fails;
    static void Eq(object a, object b, string w) { if (!a.Equals(b)) { fails++; Console.WriteLine("FAIL " + w + ": " + a + " != " + b); } }
    static void Cb(ref S s) { s.a = (ushort)(s.a + 1); }
    public static int Main() {
        int v = 0;
        Eq(MCCL.MCC_GetENCValue(ref v, 1, 2), IntPtr.Size, "sizeof(long) seen by C");
        Eq(v, -123456792, "long* out through the int-shaped wrapper");
        Eq(MCCL.MCC_SetENCValue(-7, 3), 3, "long by value, default argument");
        uint u = 0; long ll = 0;
        Eq(MCCL.MCC_GetLong(ref u, ref ll), -2, "long return");
        Eq(u, 4000000000u, "unsigned long* out");
        Eq(ll, -(1L << 40), "long long* out");
        MCCL.MCC_VoidLong(5);
        Eq(MCCL.MCC_Hold(3, true), 531, "BOOL by value (and the earlier long)");
        bool b = false;
        MCCL.CB cb = Cb;
        Eq(MCCL.MCC_IsOn(ref b, (sbyte)'x', IntPtr.Zero, cb), true, "BOOL return, char, void*, callback writing through ref S");
        Eq(b, true, "BOOL* out");
        GC.KeepAlive(cb);
        Console.WriteLine(fails == 0 ? "OK" : "FAILED");
        return fails;
    }
}
"#;

/// Runs the generated C# for the future types (C long wrappers, BOOL, char, void*, callback)
/// under Mono against a C stub library, when cc, mcs and mono are installed.
#[test]
fn future_csharp_runs_under_mono_against_a_c_stub() {
    let have = |t: &str, a: &str| {
        std::process::Command::new(t)
            .arg(a)
            .output()
            .is_ok_and(|o| o.status.success())
    };
    if !(have("cc", "--version") && have("mcs", "--version") && have("mono", "--version")) {
        eprintln!("cc/mcs/mono not installed: runtime check skipped");
        return;
    }
    let h = header(FUTURE_H, FUTURE_FUN);
    let dir = std::env::temp_dir().join(format!("mccl-bindings-stub-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("stub.c"), STUB_C).unwrap();
    std::fs::write(dir.join("MCCL.cs"), gen::csharp(&h).unwrap()).unwrap();
    std::fs::write(dir.join("P.cs"), STUB_CS).unwrap();
    let run = |cmd: &mut std::process::Command| {
        let o = cmd.current_dir(&dir).output().unwrap();
        (
            o.status.success(),
            format!(
                "{}{}",
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            ),
        )
    };
    let (ok, log) = run(std::process::Command::new("cc").args([
        "-shared",
        "-fPIC",
        "-o",
        "libMCCLPCI_IMP.so",
        "stub.c",
    ]));
    assert!(ok, "{log}");
    let (ok, log) = run(std::process::Command::new("mcs").args([
        "-langversion:7.2",
        "-out:p.exe",
        "MCCL.cs",
        "P.cs",
    ]));
    assert!(ok, "{log}");
    let (ok, log) = run(std::process::Command::new("mono")
        .arg("p.exe")
        .env("LD_LIBRARY_PATH", &dir));
    let _ = std::fs::remove_dir_all(&dir);
    assert!(ok && log.contains("OK"), "{log}");
}
