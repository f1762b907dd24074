//! bones.rs: bone colliders through the safe API. A 2 x 1 x 1 box whose x = 0 end is weighted to
//! joint 0 and x = 2 end to joint 1 (a child turned about z and moved by its inverse bind): one
//! collider per joint, each holding its half's corners in its joint's frame (checked with this
//! file's own distance to the placed capsule); a skip list, stats, and bad skins refused.
use coverage_axis::*;

const V: [[f64; 3]; 8] =
    [[0., 0., 0.], [2., 0., 0.], [2., 1., 0.], [0., 1., 0.], [0., 0., 1.], [2., 0., 1.], [2., 1., 1.], [0., 1., 1.]];
const F: [[u32; 3]; 12] = [
    [0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6],
    [3, 0, 4], [3, 4, 7],
];
const IB: [[f64; 16]; 2] = [
    [1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.],
    [0., -1., 0., 0., 1., 0., 0., 0., 0., 0., 1., 0., -1., 2., 0.5, 1.],
];

/// Distance from x (joint frame) to the collider as placed: ternary search along its axis.
fn distance(c: &BoneCollider, x: [f64; 3]) -> f64 {
    let at = |t: f64| {
        let mut d = 0.0;
        for k in 0..3 {
            let p = c.center[k] + (t - 0.5) * c.height * c.axis[k];
            d += (x[k] - p) * (x[k] - p);
        }
        d.sqrt() - (c.radius_bottom + t * (c.radius_top - c.radius_bottom))
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..200 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if at(m1) <= at(m2) {
            hi = m2
        } else {
            lo = m1
        }
    }
    at(0.0).min(at(1.0)).min(at(0.5 * (lo + hi)))
}

#[test]
fn bone_colliders_hold_their_parts_in_their_joints_frames() {
    let ctx = Context::new().unwrap();
    let set = ctx
        .candidates(&Surface::mesh(&V, &F), &CandidateOptions::new().cover_samples(300).voronoi_samples(800))
        .unwrap();
    let joints: Vec<u32> = V.iter().flat_map(|v| if v[0] == 0.0 { [0, 1] } else { [1, 0] }).collect();
    let weights: Vec<f64> = V.iter().flat_map(|_| [1.0, 0.0]).collect();
    let parents = [-1, 0];
    let skin = Skin { parents: &parents, inverse_bind: Some(&IB), influences: 2, vertex_joints: &joints, vertex_weights: &weights };
    let bc = ctx.bone_colliders(&set, &skin, &BoneColliderOptions::new()).unwrap();
    let cs = bc.colliders();
    assert_eq!(cs.iter().map(|c| c.joint).collect::<Vec<_>>(), vec![0, 1]);
    let stats = bc.stats();
    assert_eq!(stats.contained_fraction, 1.0);
    assert_eq!(stats.joints_with_collider, 2);
    for c in &cs {
        let m = &IB[c.joint as usize];
        let x0 = if c.joint == 0 { 0.0 } else { 1.0 };
        for corner in 0..8 {
            let x = [x0 + (corner & 1) as f64, ((corner >> 1) & 1) as f64, ((corner >> 2) & 1) as f64];
            let y: Vec<f64> = (0..3).map(|r| m[r] * x[0] + m[4 + r] * x[1] + m[8 + r] * x[2] + m[12 + r]).collect();
            assert!(distance(c, [y[0], y[1], y[2]]) <= 1e-9, "joint {} corner {:?}", c.joint, x);
        }
        assert_eq!(c.contained, 1.0);
    }
    let skipped = ctx.bone_colliders(&set, &skin, &BoneColliderOptions::new().skip_joints(&[0])).unwrap();
    assert_eq!(skipped.colliders().iter().map(|c| c.joint).collect::<Vec<_>>(), vec![1]);
    // a cycle, a NaN weight, a sheared inverse bind, lengths that disagree
    let cycle = [1, 0];
    let e = ctx.bone_colliders(&set, &Skin { parents: &cycle, ..skin }, &BoneColliderOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::InvalidInput);
    let mut nan = weights.clone();
    nan[0] = f64::NAN;
    let e = ctx.bone_colliders(&set, &Skin { vertex_weights: &nan, ..skin }, &BoneColliderOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::InvalidInput);
    let mut shear = IB;
    shear[1][5] = 0.3;
    let e = ctx.bone_colliders(&set, &Skin { inverse_bind: Some(&shear), ..skin }, &BoneColliderOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::InvalidInput);
    let e = ctx.bone_colliders(&set, &Skin { vertex_weights: &weights[1..], ..skin }, &BoneColliderOptions::new()).err().unwrap();
    assert_eq!(e.status, Status::InvalidInput);
    let e = ctx
        .bone_colliders(&set, &skin, &BoneColliderOptions::new().mode(ProxyMode::Inscribed).min_share(2.0))
        .err()
        .unwrap();
    assert_eq!(e.status, Status::InvalidArgument);
}
