//! Gives the shared library an ELF SONAME (cargo sets none), so programs linked against
//! `libMCCLPCI_IMP.so` record that name and the dynamic loader finds it by it.
fn main() {
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os == "linux" || os == "android" || os.ends_with("bsd") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libMCCLPCI_IMP.so");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
