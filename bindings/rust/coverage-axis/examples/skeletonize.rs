//! skeletonize.rs: Context::skeletonize at the defaults on a mesh given as plain numbers (the
//! vertex and triangle counts, then x y z per vertex, then 0-based i j k per triangle), printing
//! one ball per line, x y z r, exactly (Rust's shortest round-trip form). Run by
//! tests/bindings/skeletonize_agree.py, which compares every binding's skeletonize.
use coverage_axis::{Context, Surface};

fn main() {
    let path = std::env::args().nth(1).expect("usage: skeletonize MESH.txt");
    let text = std::fs::read_to_string(path).expect("the mesh file");
    let mut numbers = text.split_whitespace();
    let mut next = || numbers.next().expect("a number");
    let (nv, nf): (usize, usize) = (next().parse().unwrap(), next().parse().unwrap());
    let v: Vec<[f64; 3]> = (0..nv).map(|_| [0; 3].map(|_| next().parse().unwrap())).collect();
    let f: Vec<[u32; 3]> = (0..nf).map(|_| [0; 3].map(|_| next().parse().unwrap())).collect();
    let skeleton = Context::new().unwrap().skeletonize(&Surface::mesh(&v, &f)).unwrap();
    for (c, r) in skeleton.centers().iter().zip(skeleton.radii()) {
        println!("{:?} {:?} {:?} {:?}", c[0], c[1], c[2], r);
    }
}
