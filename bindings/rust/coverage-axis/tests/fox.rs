//! fox.rs: the safe API against the CLI and the library's contracts. Skeletonizes
//! tests/data/fox.obj and compares ball count, centres, radii, edge and face counts with the .ma
//! the CLI writes for the same file (CA_CLI: the coverage-axis tool, CA_TEST_DATA: tests/data);
//! checks errors, defaults, progress, cancellation and lifetimes.
use coverage_axis::*;
use std::path::PathBuf;
use std::process::Command;

fn data(name: &str) -> PathBuf {
    PathBuf::from(std::env::var("CA_TEST_DATA").expect("CA_TEST_DATA: the tests/data folder")).join(name)
}

/// v and f lines of an OBJ (1-based indices, "i/t/n" forms take the first number).
fn read_obj(path: &PathBuf) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let text = std::fs::read_to_string(path).unwrap();
    let (mut v, mut f) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let mut it = line.split_whitespace();
        match it.next() {
            Some("v") => {
                let p: Vec<f64> = it.take(3).map(|s| s.parse().unwrap()).collect();
                v.push([p[0], p[1], p[2]]);
            }
            Some("f") => {
                let i: Vec<u32> = it.map(|s| s.split('/').next().unwrap().parse::<u32>().unwrap() - 1).collect();
                for k in 1..i.len() - 1 {
                    f.push([i[0], i[k], i[k + 1]]);
                }
            }
            _ => {}
        }
    }
    (v, f)
}

/// The CLI's skeleton of `model`: ([x y z r] per ball, edge count, face count).
fn cli_skeleton(model: &PathBuf) -> (Vec<[f64; 4]>, usize, usize) {
    let cli = std::env::var("CA_CLI").expect("CA_CLI: the coverage-axis tool");
    let out = std::env::temp_dir().join(format!("coverage_axis_rust_{}.ma", std::process::id()));
    let status = Command::new(cli).arg(model).arg("-o").arg(&out).arg("--quiet").status().unwrap();
    assert!(status.success());
    let text = std::fs::read_to_string(&out).unwrap();
    std::fs::remove_file(&out).unwrap();
    let mut lines = text.lines();
    let counts: Vec<usize> = lines.next().unwrap().split(' ').map(|s| s.parse().unwrap()).collect();
    let balls: Vec<[f64; 4]> = lines
        .filter(|l| l.starts_with("v "))
        .map(|l| {
            let x: Vec<f64> = l[2..].split(' ').map(|s| s.parse().unwrap()).collect();
            [x[0], x[1], x[2], x[3]]
        })
        .collect();
    assert_eq!(balls.len(), counts[0]);
    (balls, counts[1], counts[2])
}

/// The .ma has 9 significant digits.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-7 * b.abs().max(1.0)
}

#[test]
fn fox_matches_the_cli() {
    let model = data("fox.obj");
    let (v, f) = read_obj(&model);
    let ctx = Context::builder().threads(2).build().unwrap();
    let skeleton = ctx.skeletonize(&Surface::mesh(&v, &f)).unwrap();
    let (balls, edges, faces) = cli_skeleton(&model);
    assert!(balls.len() > 10);
    assert_eq!(skeleton.len(), balls.len());
    for ((c, r), b) in skeleton.centers().iter().zip(skeleton.radii()).zip(&balls) {
        assert!(close(c[0], b[0]) && close(c[1], b[1]) && close(c[2], b[2]) && close(*r, b[3]),
                "ball {:?} {} vs the CLI's {:?}", c, r, b);
    }
    assert_eq!(skeleton.edges().len(), edges);
    assert_eq!(skeleton.faces().len(), faces);
    let stats = skeleton.stats();
    assert_eq!(stats.vertices as usize, balls.len());
    let evaluation = ctx.evaluate(&Surface::mesh(&v, &f), &skeleton, &EvaluateOptions::new().surface_samples(2000)
                                  .envelope_samples(2000)).unwrap();
    assert!(evaluation.hd_two_sided > 0.0 && evaluation.hd_two_sided < 20.0, "{:?}", evaluation);
    println!("fox: {} balls, {} edges, {} faces match the CLI", balls.len(), edges, faces);
}

#[test]
fn results_outlive_context_and_set() {
    let (v, f) = read_obj(&data("fox.obj"));
    let ctx = Context::new().unwrap();
    let set = ctx.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new().cover_samples(300)).unwrap();
    let candidates = set.len();
    let selection = ctx.select(&set, &SelectOptions::new().solver(Solver::Greedy)).unwrap();
    let skeleton = ctx.connect(&set, &selection, &ConnectOptions::default()).unwrap();
    drop(ctx);
    drop(set);
    let indices = selection.indices();
    assert_eq!(indices.len(), selection.len());
    assert!(indices.iter().all(|&i| (i as usize) < candidates));
    assert_eq!(selection.centers().len(), skeleton.len());
    assert!(selection.dilated_radii().iter().zip(selection.radii()).all(|(d, r)| d > r));
    assert_eq!(selection.stats().objective as usize, selection.len());
    // results are Send + Sync: read from another thread
    let n = std::thread::spawn(move || skeleton.centers().len()).join().unwrap();
    assert_eq!(n, selection.len());
}

#[test]
fn target_error_not_reached_keeps_the_best_selection() {
    let (v, f) = read_obj(&data("fox.obj"));
    let ctx = Context::new().unwrap();
    let set = ctx.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new().cover_samples(300)).unwrap();
    // a coarse bisection (default 1e-4): fewer probes, and no check depends on it
    let unreachable = SelectOptions::new().target_error(1e-4).target_tolerance(1e-2);
    let e = ctx.select(&set, &unreachable).err().unwrap();
    assert_eq!(e.status, Status::TargetNotReached);
    assert!(e.message.contains("not reached"), "{}", e);
    let (best, missed) = ctx.select_best(&set, &unreachable).unwrap();
    assert_eq!(missed.unwrap().status, Status::TargetNotReached);
    assert!(best.len() > 0 && best.stats().hd_reached > 1e-4);
    assert!(ctx.connect(&set, &best, &ConnectOptions::default()).unwrap().len() == best.len());
    let (_, reached) = ctx.select_best(&set, &SelectOptions::new().target_error(50.0)).unwrap();
    assert!(reached.is_none());
}

#[test]
fn defaults_come_from_the_library() {
    let o = SelectOptions::new();
    assert_eq!(o.raw().delta, 0.02);
    assert_eq!(o.raw().scale, 1.5);
    assert_eq!(o.raw().struct_size as usize, std::mem::size_of_val(o.raw()));
    assert_eq!(CandidateOptions::new().raw().cover_samples, 1500);
    assert_eq!(ConnectOptions::new().raw().method, ConnectMethod::Auto as i32);
    assert_eq!(EvaluateOptions::new().raw().surface_samples, 30000);
}

#[test]
fn errors_carry_status_and_message() {
    let ctx = Context::new().unwrap();
    let e = ctx.candidates(&Surface::mesh(&[], &[]), &CandidateOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::DegenerateInput);
    assert!(!e.message.is_empty());
    let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let e = ctx.candidates(&Surface::mesh(&v, &[[0, 1, 7]]), &CandidateOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::InvalidInput, "{}", e);
    let e = Context::builder().threads(-1).build().err().unwrap();
    assert_eq!(e.status, Status::InvalidArgument);
    assert_eq!(e.status.code(), coverage_axis_sys::CA_ERROR_INVALID_ARGUMENT);
    for code in 1..=15 {
        assert_eq!(Status::from_code(code).code(), code);
        assert_ne!(Status::from_code(code), Status::Unknown(code));
    }
    assert_eq!(Status::from_code(99), Status::Unknown(99));
}

/// n points on the unit sphere (a Fibonacci spiral); each is its own outward normal.
fn sphere_points(n: usize) -> Vec<[f64; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).sqrt();
            [r * (golden * i as f64).cos(), r * (golden * i as f64).sin(), z]
        })
        .collect()
}

#[test]
fn wrong_lengths_are_errors_before_the_call() {
    let points = sphere_points(400);
    // normals of another length are refused, not dropped (which would estimate them instead)
    for normals in [&points[..10], &points[..399]] {
        let e = Surface::points(&points, normals).err().expect("wrong-length normals accepted");
        assert_eq!(e.status, Status::InvalidInput, "{}", e);
        assert!(e.message.contains(&format!("{} normals for 400 points", normals.len())), "{}", e);
    }
    let ctx = Context::builder().threads(1).build().unwrap();
    let options = CandidateOptions::new().cover_samples(100).voronoi_samples(400);
    let set = ctx.candidates(&Surface::points(&points, &points).unwrap(), &options).unwrap();
    assert!(ctx.candidates(&Surface::points(&points, &[]).unwrap(), &options).is_ok());  // no normals: estimated
    // masks: one entry per sample or candidate ball
    let short = vec![0u8; set.len() - 1];
    let e = ctx.select(&set, &SelectOptions::new().forced_in(Some(&short))).err().expect("short mask accepted");
    assert_eq!(e.status, Status::InvalidInput, "{}", e);
    assert!(e.message.contains("forced_in"), "{}", e);
    let long = vec![0u8; set.samples().len() + 1];
    let e = ctx.select(&set, &SelectOptions::new().ignorable_samples(Some(&long))).err().expect("long mask accepted");
    assert_eq!(e.status, Status::InvalidInput, "{}", e);
    let mut forced = vec![0u8; set.len()];
    forced[0] = 1;
    let selection = ctx.select(&set, &SelectOptions::new().forced_in(Some(&forced))).unwrap();
    assert!(selection.indices().contains(&0));
}

#[test]
fn progress_closure_and_cancel() {
    let (v, f) = read_obj(&data("fox.obj"));
    let seen = std::sync::Arc::new(std::sync::Mutex::new(Vec::<String>::new()));
    let log = seen.clone();
    let ctx = Context::builder().progress(move |stage, fraction| {
        assert!((0.0..=1.0).contains(&fraction));
        log.lock().unwrap().push(stage.to_string());
        true
    }).build().unwrap();
    ctx.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new().cover_samples(300)).unwrap();
    assert!(seen.lock().unwrap().iter().any(|s| s == "sampling"));

    // a closure returning false cancels the call
    let stop = Context::builder().progress(|_, _| false).build().unwrap();
    let e = stop.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::Cancelled);

    // a cancel handle sent to another thread; the request stays in force until cleared
    let handle = ctx.cancel_handle();
    std::thread::spawn(move || handle.cancel()).join().unwrap();
    let e = ctx.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::Cancelled);
    ctx.cancel_handle().clear();
    assert!(ctx.candidates(&Surface::mesh(&v, &f), &CandidateOptions::new().cover_samples(300)).is_ok());
}

/// The rig and correspondence of the fox: the joint and branch counts of the CLI's report
/// (`--rig`), weights summing to 1 over at most 4 balls (joints), parents before children, and the
/// options checked.
#[test]
fn rig_and_correspondence() {
    let fox = data("fox.obj");
    let (v, f) = read_obj(&fox);
    let ctx = Context::new().unwrap();
    let surface = Surface::mesh(&v, &f);
    let skeleton = ctx.skeletonize(&surface).unwrap();
    let c = ctx.correspond(&surface, &skeleton, None).unwrap();
    assert_eq!(c.len(), v.len());
    for (balls, weights) in c.balls().iter().zip(c.weights()) {
        assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(balls.iter().all(|&b| (b as usize) < skeleton.len()));
    }
    assert!(c.nearest_kinds().iter().all(|&k| (0..3).contains(&k)));
    let rig = ctx.rig(&surface, &skeleton, &RigOptions::new()).unwrap();
    assert_eq!(rig.vertex_count(), v.len());
    assert_eq!(rig.parents()[0], -1);
    assert!(rig.parents().iter().enumerate().skip(1).all(|(j, &p)| p >= 0 && (p as usize) < j));
    for w in rig.weights() {
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    }
    // the CLI's report of the same rig
    let cli = std::env::var("CA_CLI").expect("CA_CLI: the coverage-axis tool");
    let dir = std::env::temp_dir();
    let out = Command::new(cli).arg(&fox).arg("-o").arg(dir.join(format!("coverage_axis_rust_rig_{}.ma", std::process::id())))
        .arg("--rig").arg(dir.join(format!("coverage_axis_rust_rig_{}.glb", std::process::id()))).arg("--json")
        .output().unwrap();
    assert!(out.status.success());
    let report = String::from_utf8(out.stdout).unwrap();
    let want = format!("\"rig\":{{\"joints\":{},\"branches\":{}}}", rig.len(), rig.branch_count());
    assert!(report.contains(&want), "{} not in {}", want, report);
    let few = ctx.rig(&surface, &skeleton, &RigOptions::new().max_joints(5)).unwrap();
    assert!(few.len() <= 5);
    let err = ctx.rig(&surface, &skeleton, &RigOptions::new().max_joints(0)).err().unwrap();
    assert_eq!(err.status, Status::InvalidArgument);
    let err = ctx.correspond(&surface, &skeleton, Some(0.0)).err().unwrap();
    assert_eq!(err.status, Status::InvalidArgument);
}

/// min over t of |x - c(t)| - r(t) (convex in t: ternary search), the test's own capsule distance.
fn capsule_distance(p: &Proxy, x: [f64; 3]) -> f64 {
    let f = |t: f64| {
        let d: Vec<f64> = (0..3).map(|k| x[k] - (p.a[k] + t * (p.b[k] - p.a[k]))).collect();
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - (p.radius_a + t * (p.radius_b - p.radius_a))
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..100 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if f(m1) <= f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    f(0.5 * (lo + hi)).min(f(0.0)).min(f(1.0))
}

#[test]
fn conservative_proxies_hold_the_vertices() {
    let (v, f) = read_obj(&data("fox.obj"));
    let ctx = Context::builder().threads(2).build().unwrap();
    let surface = Surface::mesh(&v, &f);
    let set = ctx.candidates(&surface, &CandidateOptions::new().cover_samples(400)).unwrap();
    let selection = ctx.select(&set, &SelectOptions::new()).unwrap();
    let skeleton = ctx.connect(&set, &selection, &ConnectOptions::new()).unwrap();
    let options = ProxyOptions::new().mode(ProxyMode::Conservative).count(6).evaluate_samples(2000).volume_samples(5000);
    let proxies = ctx.proxies(&set, &skeleton, &options).unwrap();
    drop(set);
    assert!(!proxies.is_empty() && proxies.len() <= 6);
    let primitives = proxies.primitives();
    for x in &v {
        let best = primitives.iter().map(|p| capsule_distance(p, *x)).fold(f64::INFINITY, f64::min);
        assert!(best <= 1e-9, "vertex {:?} outside every proxy ({})", x, best);
    }
    let stats = proxies.stats();
    assert!(stats.hd_two_sided > 0.0 && stats.outside_volume > 0.0, "{:?}", stats);
    let set = ctx.candidates(&surface, &CandidateOptions::new().cover_samples(400)).unwrap();
    let error = ctx.proxies(&set, &skeleton, &ProxyOptions::new().count(0)).err().unwrap();
    assert_eq!(error.status, Status::InvalidArgument);
    assert!(error.message.contains("count"), "{}", error.message);
}
