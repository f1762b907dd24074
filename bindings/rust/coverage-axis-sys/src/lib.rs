//! coverage-axis-sys: raw declarations of the coverage-axis C ABI (`include/coverage_axis.h`,
//! ABI 3). Names, field order and types follow the header exactly; docs/abi.md gives the rules
//! (struct_size, defaults, ownership). Every struct is declared through `ca_struct!`, which also
//! records its layout (`layouts()`), so the test compares the declarations with the C compiler's
//! layout printed by tests/abi_layout.
#![allow(non_camel_case_types)]

use std::os::raw::{c_char, c_void};

/// The ABI version whose struct layouts this crate declares.
pub const CA_ABI_VERSION: u32 = 3;

pub type ca_status = i32;
pub const CA_OK: ca_status = 0;
pub const CA_ERROR_INVALID_ARGUMENT: ca_status = 1;
pub const CA_ERROR_NULL_POINTER: ca_status = 2;
pub const CA_ERROR_STRUCT_SIZE: ca_status = 3;
pub const CA_ERROR_INVALID_INPUT: ca_status = 4;
pub const CA_ERROR_DEGENERATE_INPUT: ca_status = 5;
pub const CA_ERROR_UNCOVERABLE: ca_status = 6;
pub const CA_ERROR_GEOMETRY: ca_status = 7;
pub const CA_ERROR_SOLVER: ca_status = 8;
pub const CA_ERROR_CANCELLED: ca_status = 9;
pub const CA_ERROR_OUT_OF_MEMORY: ca_status = 10;
pub const CA_ERROR_BUFFER_TOO_SMALL: ca_status = 11;
pub const CA_ERROR_INTERNAL: ca_status = 12;
pub const CA_ERROR_NO_CANDIDATES: ca_status = 13;
pub const CA_ERROR_TIME_LIMIT: ca_status = 14;
pub const CA_ERROR_TARGET_NOT_REACHED: ca_status = 15;

pub const CA_CANDIDATES_VORONOI: i32 = 0;
pub const CA_CANDIDATES_RANDOM: i32 = 1;
pub const CA_DILATE_OFFSET: i32 = 0;
pub const CA_DILATE_SCALE: i32 = 1;
pub const CA_SOLVER_EXACT: i32 = 0;
pub const CA_SOLVER_GREEDY: i32 = 1;
pub const CA_SOLVER_CAPP: i32 = 2;
pub const CA_EFFORT_FAST: i32 = 0;
pub const CA_EFFORT_PROVE: i32 = 1;
pub const CA_CONNECT_POWER: i32 = 0;
pub const CA_CONNECT_MEDIAL: i32 = 1;
pub const CA_CONNECT_AUTO: i32 = 2;
pub const CA_PROXY_SHAPES_SPHERES: i32 = 0;
pub const CA_PROXY_SHAPES_CAPSULES: i32 = 1;
pub const CA_PROXY_INSCRIBED: i32 = 0;
pub const CA_PROXY_CONSERVATIVE: i32 = 1;
pub const CA_PROXY_SPHERE: i32 = 0;
pub const CA_PROXY_CAPSULE: i32 = 1;

#[repr(C)]
pub struct ca_context {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_candidate_set {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_selection {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_skeleton {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_correspondence {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_rig {
    _opaque: [u8; 0],
}

/// Balls (joints) per vertex of a correspondence (rig).
pub const CA_INFLUENCES: usize = 4;
pub const CA_NEAREST_BALL: i32 = 0;
pub const CA_NEAREST_EDGE: i32 = 1;
pub const CA_NEAREST_FACE: i32 = 2;
#[repr(C)]
pub struct ca_proxy_set {
    _opaque: [u8; 0],
}
#[repr(C)]
pub struct ca_bone_colliders {
    _opaque: [u8; 0],
}

pub type ca_log_fn = Option<unsafe extern "C" fn(user: *mut c_void, level: i32, message: *const c_char)>;
pub type ca_progress_fn =
    Option<unsafe extern "C" fn(user: *mut c_void, stage: *const c_char, fraction: f64) -> i32>;
pub type ca_alloc_fn = Option<unsafe extern "C" fn(user: *mut c_void, size: usize) -> *mut c_void>;
pub type ca_free_fn = Option<unsafe extern "C" fn(user: *mut c_void, pointer: *mut c_void)>;

/// One struct's layout as this crate declares it: name, size, and (field, offset, size) in
/// declaration order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StructLayout {
    pub name: &'static str,
    pub size: usize,
    pub fields: Vec<(&'static str, usize, usize)>,
}

fn pointee_size<T>(_: *const T) -> usize {
    std::mem::size_of::<T>()
}

/// Declares a `#[repr(C)]` struct and a `layout()` that reports its fields' offsets and sizes
/// (taken from the declaration itself, so the layout test checks exactly what is compiled).
macro_rules! ca_struct {
    ($(#[$meta:meta])* $name:ident { $($(#[$fmeta:meta])* $field:ident : $ty:ty,)* }) => {
        $(#[$meta])*
        #[repr(C)]
        #[derive(Clone, Copy)]
        pub struct $name { $($(#[$fmeta])* pub $field: $ty,)* }

        impl $name {
            pub fn layout() -> StructLayout {
                let value = std::mem::MaybeUninit::<$name>::uninit();
                let base = value.as_ptr();
                let mut fields = Vec::new();
                $(
                    // SAFETY: addr_of! takes the field's address without reading it
                    let field = unsafe { std::ptr::addr_of!((*base).$field) };
                    fields.push((stringify!($field), field as usize - base as usize, pointee_size(field)));
                )*
                StructLayout { name: stringify!($name), size: std::mem::size_of::<$name>(), fields }
            }
        }
    };
}

ca_struct!(ca_context_desc {
    struct_size: u32,
    alloc: ca_alloc_fn,
    free: ca_free_fn,
    alloc_user: *mut c_void,
    log: ca_log_fn,
    log_user: *mut c_void,
    progress: ca_progress_fn,
    progress_user: *mut c_void,
    threads: i32,
    /// ABI 2
    progress_interval_s: f64,
    /// ABI 2, appended after progress_interval_s
    time_limit_s: f64,
});

ca_struct!(ca_surface_view {
    struct_size: u32,
    positions: *const f64,
    vertex_count: usize,
    position_stride: usize,
    triangles: *const u32,
    triangle_count: usize,
    triangle_stride: usize,
    normals: *const f64,
    normal_stride: usize,
    /// ABI 2: CA_POINT_NORMALS_*
    point_normals: i32,
    /// ABI 3: entries of normals (vertex_count when set)
    normal_count: usize,
});

ca_struct!(ca_candidate_options {
    struct_size: u32,
    generator: i32,
    cover_samples: u32,
    voronoi_samples: u32,
    random_candidates: u32,
    seed: u64,
    connect_samples: u32,
    /// ABI 3: the ABI 2 layout's tail padding
    reserved_abi2_tail: u32,
    /// ABI 3
    volumetric_only: i32,
});

ca_struct!(ca_select_options {
    struct_size: u32,
    dilation: i32,
    delta: f64,
    scale: f64,
    solver: i32,
    time_limit_s: f64,
    skip_uncoverable: i32,
    ignorable_samples: *const u8,
    forced_in: *const u8,
    forced_out: *const u8,
    target_count: u32,
    target_tolerance: f64,
    divide_threshold: u32,
    effort: i32,
    /// ABI 2
    target_error: f64,
    /// ABI 2 (appended after target_error)
    probe_fit: i32,
    /// ABI 3: entries of ignorable_samples (the set's sample count when set)
    ignorable_samples_count: usize,
    /// ABI 3: entries of forced_in (the set's ball count when set)
    forced_in_count: usize,
    /// ABI 3: entries of forced_out (the set's ball count when set)
    forced_out_count: usize,
});

ca_struct!(#[derive(Debug, Default)] ca_select_stats {
    struct_size: u32,
    proven_optimal: i32,
    solver: i32,
    objective: f64,
    lower_bound: f64,
    gap: f64,
    delta_absolute: f64,
    time_reduce_s: f64,
    time_solve_s: f64,
    time_total_s: f64,
    rows_before: u64,
    cols_before: u64,
    rows_after: u64,
    cols_after: u64,
    forced: u64,
    components: u64,
    probes: u64,
    parts: u64,
    scale_used: f64,
    /// ABI 2
    time_coverage_s: f64,
    /// ABI 2
    cbc_components: u64,
    /// ABI 2
    rowgen_rounds: u64,
    /// ABI 2
    hd_reached: f64,
});

ca_struct!(ca_connect_options {
    struct_size: u32,
    method: i32,
    remove_outside: i32,
    fill_holes: i32,
    reconnect: i32,
    /// ABI 2
    fit: i32,
    /// ABI 2
    fit_iterations: i32,
});

ca_struct!(#[derive(Debug, Default)] ca_skeleton_stats {
    struct_size: u32,
    vertices: u64,
    edges: u64,
    faces: u64,
    components: u64,
    isolated: u64,
    betti1: i64,
    time_s: f64,
    method: i32,
    /// ABI 2
    fit_time_s: f64,
    /// ABI 2
    fit_error_before: f64,
    /// ABI 2
    fit_error_after: f64,
    /// ABI 2
    fit_uncovered: u64,
    /// ABI 2
    fitted: i32,
    /// ABI 2 (appended after fitted)
    genus: i64,
    /// ABI 2
    thin_handles: u64,
    /// ABI 3
    medial_balls: u64,
    surface_balls: u64,
    open_parts: u64,
});

ca_struct!(ca_skeleton_view {
    struct_size: u32,
    centers: *const f64,
    radii: *const f64,
    vertex_count: usize,
    edges: *const u32,
    edge_count: usize,
    faces: *const u32,
    face_count: usize,
});

ca_struct!(ca_evaluate_options {
    struct_size: u32,
    surface_samples: u32,
    envelope_samples: u32,
    seed: u64,
});

ca_struct!(#[derive(Debug, Default)] ca_evaluation {
    struct_size: u32,
    hd_surface_to_recon: f64,
    mean_surface_to_recon: f64,
    hd_recon_to_surface: f64,
    mean_recon_to_surface: f64,
    hd_two_sided: f64,
    diagonal: f64,
    surface_samples_used: u64,
    envelope_samples_used: u64,
    time_s: f64,
});

ca_struct!(ca_correspondence_options {
    struct_size: u32,
    smoothing: f64,
});

ca_struct!(ca_rig_options {
    struct_size: u32,
    root: i64,
    max_joints: u32,
    joint_spacing: f64,
    min_branch: f64,
    smoothing: f64,
});

ca_struct!(ca_proxy_options {
    struct_size: u32,
    shapes: i32,
    mode: i32,
    count: u32,
    surface_samples: u32,
    evaluate_samples: u32,
    volume_samples: u32,
    seed: u64,
});

ca_struct!(#[derive(Debug, Default)] ca_proxy_stats {
    struct_size: u32,
    hd_surface_to_proxies: f64,
    mean_surface_to_proxies: f64,
    hd_proxies_to_surface: f64,
    mean_proxies_to_surface: f64,
    hd_two_sided: f64,
    outside_bound: f64,
    skeleton_outside: f64,
    union_volume: f64,
    outside_volume: f64,
    radius_change: f64,
    diagonal: f64,
    candidates: u64,
    surface_cells: u64,
    time_s: f64,
});

ca_struct!(#[derive(Debug, Default)] ca_proxy_placement {
    struct_size: u32,
    kind: i32,
    center: [f64; 3],
    rotation: [f64; 4],
    axis: [f64; 3],
    radius_top: f64,
    radius_bottom: f64,
    height: f64,
    half_extents: [f64; 3],
});

ca_struct!(ca_skin_view {
    struct_size: u32,
    joint_count: usize,
    parents: *const i32,
    inverse_bind: *const f64,
    vertex_count: usize,
    influences: u32,
    vertex_joints: *const u32,
    vertex_weights: *const f64,
});

ca_struct!(ca_bone_collider_options {
    struct_size: u32,
    mode: i32,
    shapes: i32,
    min_share: f64,
    min_size: f64,
    skip_joints: *const u32,
    skip_count: usize,
    surface_samples: u32,
    evaluate_samples: u32,
    seed: u64,
});

ca_struct!(#[derive(Debug, Default)] ca_bone_collider_stats {
    struct_size: u32,
    contained_fraction: f64,
    union_volume: f64,
    outside_volume: f64,
    neighbour_overlap: f64,
    joints_with_collider: u64,
    joints_skipped: u64,
    time_s: f64,
});

/// Every struct this crate declares, in header order.
pub fn layouts() -> Vec<StructLayout> {
    vec![
        ca_context_desc::layout(),
        ca_surface_view::layout(),
        ca_candidate_options::layout(),
        ca_select_options::layout(),
        ca_select_stats::layout(),
        ca_connect_options::layout(),
        ca_skeleton_stats::layout(),
        ca_skeleton_view::layout(),
        ca_evaluate_options::layout(),
        ca_evaluation::layout(),
        ca_correspondence_options::layout(),
        ca_rig_options::layout(),
        ca_proxy_options::layout(),
        ca_proxy_stats::layout(),
        ca_proxy_placement::layout(),
        ca_skin_view::layout(),
        ca_bone_collider_options::layout(),
        ca_bone_collider_stats::layout(),
    ]
}

extern "C" {
    pub fn ca_version() -> u32;
    pub fn ca_abi_version() -> u32;
    pub fn ca_status_string(status: ca_status) -> *const c_char;

    pub fn ca_context_desc_defaults(desc: *mut ca_context_desc, struct_size: u32) -> ca_status;
    pub fn ca_context_create(desc: *const ca_context_desc, out: *mut *mut ca_context) -> ca_status;
    pub fn ca_context_destroy(ctx: *mut ca_context);
    pub fn ca_context_request_cancel(ctx: *mut ca_context);
    pub fn ca_context_clear_cancel(ctx: *mut ca_context);
    pub fn ca_context_last_error(ctx: *const ca_context) -> *const c_char;

    pub fn ca_surface_view_defaults(view: *mut ca_surface_view, struct_size: u32) -> ca_status;

    pub fn ca_candidate_options_defaults(options: *mut ca_candidate_options, struct_size: u32) -> ca_status;
    pub fn ca_candidates(
        ctx: *mut ca_context,
        surface: *const ca_surface_view,
        options: *const ca_candidate_options,
        out: *mut *mut ca_candidate_set,
    ) -> ca_status;
    pub fn ca_candidates_from_arrays(
        ctx: *mut ca_context,
        samples: *const f64,
        sample_count: usize,
        sample_stride: usize,
        centers: *const f64,
        center_stride: usize,
        radii: *const f64,
        radius_stride: usize,
        ball_count: usize,
        reference_length: f64,
        out: *mut *mut ca_candidate_set,
    ) -> ca_status;
    pub fn ca_candidate_set_destroy(set: *mut ca_candidate_set);
    pub fn ca_candidate_set_count(set: *const ca_candidate_set) -> usize;
    pub fn ca_candidate_set_centers(set: *const ca_candidate_set) -> *const f64;
    pub fn ca_candidate_set_radii(set: *const ca_candidate_set) -> *const f64;
    pub fn ca_candidate_set_sample_count(set: *const ca_candidate_set) -> usize;
    pub fn ca_candidate_set_samples(set: *const ca_candidate_set) -> *const f64;
    pub fn ca_candidate_set_reference_length(set: *const ca_candidate_set) -> f64;
    pub fn ca_candidate_set_flipped(set: *const ca_candidate_set) -> i32;
    pub fn ca_candidate_set_outlier_count(set: *const ca_candidate_set) -> u64;
    pub fn ca_candidate_set_copy(
        set: *const ca_candidate_set,
        centers: *mut f64,
        radii: *mut f64,
        capacity: usize,
        count: *mut usize,
    ) -> ca_status;

    pub fn ca_select_options_defaults(options: *mut ca_select_options, struct_size: u32) -> ca_status;
    pub fn ca_select(
        ctx: *mut ca_context,
        set: *const ca_candidate_set,
        options: *const ca_select_options,
        out: *mut *mut ca_selection,
    ) -> ca_status;
    pub fn ca_selection_destroy(selection: *mut ca_selection);
    pub fn ca_selection_count(selection: *const ca_selection) -> usize;
    pub fn ca_selection_indices(selection: *const ca_selection) -> *const u32;
    pub fn ca_selection_centers(selection: *const ca_selection) -> *const f64;
    pub fn ca_selection_radii(selection: *const ca_selection) -> *const f64;
    pub fn ca_selection_dilated_radii(selection: *const ca_selection) -> *const f64;
    pub fn ca_selection_uncovered_count(selection: *const ca_selection) -> usize;
    pub fn ca_selection_uncovered(selection: *const ca_selection) -> *const u32;
    pub fn ca_selection_stats(selection: *const ca_selection, stats: *mut ca_select_stats) -> ca_status;

    pub fn ca_connect_options_defaults(options: *mut ca_connect_options, struct_size: u32) -> ca_status;
    pub fn ca_connect(
        ctx: *mut ca_context,
        set: *const ca_candidate_set,
        selection: *const ca_selection,
        options: *const ca_connect_options,
        out: *mut *mut ca_skeleton,
    ) -> ca_status;
    pub fn ca_skeleton_destroy(skeleton: *mut ca_skeleton);
    pub fn ca_skeleton_vertex_count(skeleton: *const ca_skeleton) -> usize;
    pub fn ca_skeleton_centers(skeleton: *const ca_skeleton) -> *const f64;
    pub fn ca_skeleton_radii(skeleton: *const ca_skeleton) -> *const f64;
    pub fn ca_skeleton_edge_count(skeleton: *const ca_skeleton) -> usize;
    pub fn ca_skeleton_edges(skeleton: *const ca_skeleton) -> *const u32;
    pub fn ca_skeleton_face_count(skeleton: *const ca_skeleton) -> usize;
    pub fn ca_skeleton_faces(skeleton: *const ca_skeleton) -> *const u32;
    pub fn ca_skeleton_stats_get(skeleton: *const ca_skeleton, stats: *mut ca_skeleton_stats) -> ca_status;

    pub fn ca_skeleton_view_defaults(view: *mut ca_skeleton_view, struct_size: u32) -> ca_status;
    pub fn ca_skeleton_get_view(skeleton: *const ca_skeleton, view: *mut ca_skeleton_view) -> ca_status;
    pub fn ca_evaluate_options_defaults(options: *mut ca_evaluate_options, struct_size: u32) -> ca_status;
    pub fn ca_evaluate(
        ctx: *mut ca_context,
        surface: *const ca_surface_view,
        skeleton: *const ca_skeleton_view,
        options: *const ca_evaluate_options,
        result: *mut ca_evaluation,
    ) -> ca_status;

    pub fn ca_correspondence_options_defaults(options: *mut ca_correspondence_options, struct_size: u32) -> ca_status;
    pub fn ca_correspond(
        ctx: *mut ca_context,
        surface: *const ca_surface_view,
        skeleton: *const ca_skeleton_view,
        options: *const ca_correspondence_options,
        out: *mut *mut ca_correspondence,
    ) -> ca_status;
    pub fn ca_correspondence_destroy(correspondence: *mut ca_correspondence);
    pub fn ca_correspondence_vertex_count(correspondence: *const ca_correspondence) -> usize;
    pub fn ca_correspondence_balls(correspondence: *const ca_correspondence) -> *const u32;
    pub fn ca_correspondence_weights(correspondence: *const ca_correspondence) -> *const f64;
    pub fn ca_correspondence_nearest_kinds(correspondence: *const ca_correspondence) -> *const i32;
    pub fn ca_correspondence_nearest_indices(correspondence: *const ca_correspondence) -> *const u32;

    pub fn ca_rig_options_defaults(options: *mut ca_rig_options, struct_size: u32) -> ca_status;
    pub fn ca_rig_build(
        ctx: *mut ca_context,
        surface: *const ca_surface_view,
        skeleton: *const ca_skeleton_view,
        options: *const ca_rig_options,
        out: *mut *mut ca_rig,
    ) -> ca_status;
    pub fn ca_rig_destroy(rig: *mut ca_rig);
    pub fn ca_rig_joint_count(rig: *const ca_rig) -> usize;
    pub fn ca_rig_joint_positions(rig: *const ca_rig) -> *const f64;
    pub fn ca_rig_joint_parents(rig: *const ca_rig) -> *const i32;
    pub fn ca_rig_joint_balls(rig: *const ca_rig) -> *const u32;
    pub fn ca_rig_joint_branches(rig: *const ca_rig) -> *const u32;
    pub fn ca_rig_branch_count(rig: *const ca_rig) -> usize;
    pub fn ca_rig_vertex_count(rig: *const ca_rig) -> usize;
    pub fn ca_rig_vertex_joints(rig: *const ca_rig) -> *const u32;
    pub fn ca_rig_vertex_weights(rig: *const ca_rig) -> *const f64;
    pub fn ca_rig_vertex_branches(rig: *const ca_rig) -> *const u32;
    pub fn ca_proxy_options_defaults(options: *mut ca_proxy_options, struct_size: u32) -> ca_status;
    pub fn ca_proxies(
        ctx: *mut ca_context,
        set: *const ca_candidate_set,
        skeleton: *const ca_skeleton_view,
        options: *const ca_proxy_options,
        out: *mut *mut ca_proxy_set,
    ) -> ca_status;
    pub fn ca_proxy_set_destroy(proxies: *mut ca_proxy_set);
    pub fn ca_proxy_set_count(proxies: *const ca_proxy_set) -> usize;
    pub fn ca_proxy_set_kinds(proxies: *const ca_proxy_set) -> *const i32;
    pub fn ca_proxy_set_centers(proxies: *const ca_proxy_set) -> *const f64;
    pub fn ca_proxy_set_radii(proxies: *const ca_proxy_set) -> *const f64;
    pub fn ca_proxy_set_stats(proxies: *const ca_proxy_set, stats: *mut ca_proxy_stats) -> ca_status;
    pub fn ca_proxy_set_placement(proxies: *const ca_proxy_set, index: usize, placement: *mut ca_proxy_placement) -> ca_status;
    pub fn ca_skin_view_defaults(view: *mut ca_skin_view, struct_size: u32) -> ca_status;
    pub fn ca_bone_collider_options_defaults(options: *mut ca_bone_collider_options, struct_size: u32) -> ca_status;
    pub fn ca_bone_colliders_build(
        ctx: *mut ca_context,
        set: *const ca_candidate_set,
        skeleton: *const ca_skeleton_view,
        skin: *const ca_skin_view,
        options: *const ca_bone_collider_options,
        out: *mut *mut ca_bone_colliders,
    ) -> ca_status;
    pub fn ca_bone_colliders_destroy(colliders: *mut ca_bone_colliders);
    pub fn ca_bone_colliders_count(colliders: *const ca_bone_colliders) -> usize;
    pub fn ca_bone_colliders_joints(colliders: *const ca_bone_colliders) -> *const u32;
    pub fn ca_bone_colliders_placement(
        colliders: *const ca_bone_colliders,
        index: usize,
        placement: *mut ca_proxy_placement,
    ) -> ca_status;
    pub fn ca_bone_colliders_stats(colliders: *const ca_bone_colliders, stats: *mut ca_bone_collider_stats) -> ca_status;
    pub fn ca_bone_colliders_contained(colliders: *const ca_bone_colliders) -> *const f64;
    pub fn ca_bone_colliders_overlap(colliders: *const ca_bone_colliders) -> *const f64;
}
