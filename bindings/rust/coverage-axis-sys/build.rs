//! build.rs: finds libcoverage_axis and links its shared library.
//! COVERAGE_AXIS_DIR (a build folder or an install prefix holding libcoverage_axis.so, directly
//! or under lib/) wins; otherwise `pkg-config --variable=libdir coverage_axis` is asked; otherwise
//! the linker's default search path is used.
use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

fn from_env() -> Option<PathBuf> {
    let dir = PathBuf::from(env::var_os("COVERAGE_AXIS_DIR")?);
    [dir.join("lib"), dir.clone()]
        .into_iter()
        .find(|d| d.join("libcoverage_axis.so").exists())
        .or(Some(dir))
}

fn from_pkg_config() -> Option<PathBuf> {
    let out = Command::new("pkg-config")
        .args(["--variable=libdir", "coverage_axis"])
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    let dir = String::from_utf8(out.stdout).ok()?.trim().to_string();
    if dir.is_empty() {
        None
    } else {
        Some(PathBuf::from(dir))
    }
}

fn main() {
    println!("cargo:rerun-if-env-changed=COVERAGE_AXIS_DIR");
    println!("cargo:rerun-if-env-changed=PKG_CONFIG_PATH");
    if let Some(dir) = from_env().or_else(from_pkg_config) {
        let dir: &Path = &dir;
        println!("cargo:rustc-link-search=native={}", dir.display());
        // dependents read it as DEP_COVERAGE_AXIS_LIBDIR (e.g. for an rpath)
        println!("cargo:libdir={}", dir.display());
    }
    // the shared library carries its own dependencies (Qhull, CBC, the C++ runtime)
    println!("cargo:rustc-link-lib=dylib=coverage_axis");
}
