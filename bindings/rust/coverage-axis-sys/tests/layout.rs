//! layout.rs: compares every struct this crate declares with the C compiler's layout printed by
//! tests/abi_layout (path in CA_ABI_LAYOUT): the same structs in the same order, and per struct
//! its sizeof and each field's name, offset and size.
use coverage_axis_sys::{layouts, StructLayout, CA_ABI_VERSION};
use std::process::Command;

fn printed() -> (u32, Vec<StructLayout>) {
    let exe = std::env::var("CA_ABI_LAYOUT").expect("CA_ABI_LAYOUT: path of the abi_layout printer");
    let out = Command::new(&exe).output().expect("run abi_layout");
    assert!(out.status.success(), "abi_layout failed");
    let text = String::from_utf8(out.stdout).unwrap();
    let mut abi = 0;
    let mut structs: Vec<StructLayout> = Vec::new();
    for line in text.lines() {
        let rec: Vec<&str> = line.split(' ').collect();
        // names are leaked to compare with the crate's &'static str names
        let name = |s: &str| -> &'static str { Box::leak(s.to_string().into_boxed_str()) };
        match rec[0] {
            "abi" => abi = rec[1].parse().unwrap(),
            "struct" => structs.push(StructLayout { name: name(rec[1]), size: rec[2].parse().unwrap(), fields: vec![] }),
            "field" => {
                let s = structs.last_mut().unwrap();
                assert_eq!(s.name, rec[1]);
                s.fields.push((name(rec[2]), rec[3].parse().unwrap(), rec[4].parse().unwrap()));
            }
            other => panic!("unknown abi_layout record {}", other),
        }
    }
    (abi, structs)
}

#[test]
fn declarations_match_the_c_layout() {
    let (abi, want) = printed();
    assert_eq!(abi, CA_ABI_VERSION, "the header's ABI differs from the crate's");
    let got = layouts();
    let names = |v: &[StructLayout]| v.iter().map(|s| s.name).collect::<Vec<_>>();
    assert_eq!(names(&got), names(&want));
    for (g, w) in got.iter().zip(want.iter()) {
        assert_eq!(g, w, "layout of {}", w.name);
    }
    println!("{} Rust structs match the printed layout", got.len());
}

#[test]
fn linked_library_has_this_abi() {
    assert!(unsafe { coverage_axis_sys::ca_abi_version() } >= CA_ABI_VERSION);
}
