"""_structs.py: the ctypes mirrors of the C ABI's structs (include/coverage_axis.h, ABI 3 layouts).
Each class is named after its C struct (_SurfaceView = ca_surface_view); the abi_layout test
compares every one, field by field, with the offsets and sizes the C compiler prints."""
from ctypes import Structure, c_double, c_int32, c_int64, c_size_t, c_uint32, c_uint64, c_void_p

# ca_log_fn, ca_progress_fn, ca_alloc_fn and ca_free_fn are declared in _library.py as CFUNCTYPEs;
# the struct stores them as plain pointers so a NULL default needs no callback object.


class _ContextDesc(Structure):
    _fields_ = [("struct_size", c_uint32), ("alloc", c_void_p), ("free", c_void_p), ("alloc_user", c_void_p),
                ("log", c_void_p), ("log_user", c_void_p), ("progress", c_void_p), ("progress_user", c_void_p),
                ("threads", c_int32), ("progress_interval_s", c_double), ("time_limit_s", c_double)]


class _SurfaceView(Structure):
    _fields_ = [("struct_size", c_uint32), ("positions", c_void_p), ("vertex_count", c_size_t),
                ("position_stride", c_size_t), ("triangles", c_void_p), ("triangle_count", c_size_t),
                ("triangle_stride", c_size_t), ("normals", c_void_p), ("normal_stride", c_size_t),
                ("point_normals", c_int32), ("normal_count", c_size_t)]


class _CandidateOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("generator", c_int32), ("cover_samples", c_uint32),
                ("voronoi_samples", c_uint32), ("random_candidates", c_uint32), ("seed", c_uint64),
                ("connect_samples", c_uint32), ("reserved_abi2_tail", c_uint32), ("volumetric_only", c_int32)]


class _SelectOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("dilation", c_int32), ("delta", c_double), ("scale", c_double),
                ("solver", c_int32), ("time_limit_s", c_double), ("skip_uncoverable", c_int32),
                ("ignorable_samples", c_void_p), ("forced_in", c_void_p), ("forced_out", c_void_p),
                ("target_count", c_uint32), ("target_tolerance", c_double), ("divide_threshold", c_uint32),
                ("effort", c_int32), ("target_error", c_double),
                ("probe_fit", c_int32), ("ignorable_samples_count", c_size_t), ("forced_in_count", c_size_t),
                ("forced_out_count", c_size_t)]


class _SelectStats(Structure):
    _fields_ = [("struct_size", c_uint32), ("proven_optimal", c_int32), ("solver", c_int32), ("objective", c_double),
                ("lower_bound", c_double), ("gap", c_double), ("delta_absolute", c_double), ("time_reduce_s", c_double),
                ("time_solve_s", c_double), ("time_total_s", c_double), ("rows_before", c_uint64),
                ("cols_before", c_uint64), ("rows_after", c_uint64), ("cols_after", c_uint64), ("forced", c_uint64),
                ("components", c_uint64), ("probes", c_uint64), ("parts", c_uint64), ("scale_used", c_double),
                ("time_coverage_s", c_double), ("cbc_components", c_uint64), ("rowgen_rounds", c_uint64),
                ("hd_reached", c_double)]


class _ConnectOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("method", c_int32), ("remove_outside", c_int32), ("fill_holes", c_int32),
                ("reconnect", c_int32), ("fit", c_int32), ("fit_iterations", c_int32)]


class _SkeletonStats(Structure):
    _fields_ = [("struct_size", c_uint32), ("vertices", c_uint64), ("edges", c_uint64), ("faces", c_uint64),
                ("components", c_uint64), ("isolated", c_uint64), ("betti1", c_int64), ("time_s", c_double),
                ("method", c_int32), ("fit_time_s", c_double), ("fit_error_before", c_double),
                ("fit_error_after", c_double), ("fit_uncovered", c_uint64), ("fitted", c_int32),
                ("genus", c_int64), ("thin_handles", c_uint64), ("medial_balls", c_uint64),
                ("surface_balls", c_uint64), ("open_parts", c_uint64)]


class _SkeletonView(Structure):
    _fields_ = [("struct_size", c_uint32), ("centers", c_void_p), ("radii", c_void_p),
                ("vertex_count", c_size_t), ("edges", c_void_p), ("edge_count", c_size_t),
                ("faces", c_void_p), ("face_count", c_size_t)]


class _EvaluateOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("surface_samples", c_uint32), ("envelope_samples", c_uint32),
                ("seed", c_uint64)]


class _Evaluation(Structure):
    _fields_ = [("struct_size", c_uint32), ("hd_surface_to_recon", c_double), ("mean_surface_to_recon", c_double),
                ("hd_recon_to_surface", c_double), ("mean_recon_to_surface", c_double), ("hd_two_sided", c_double),
                ("diagonal", c_double), ("surface_samples_used", c_uint64), ("envelope_samples_used", c_uint64),
                ("time_s", c_double)]


class _CorrespondenceOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("smoothing", c_double)]


class _RigOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("root", c_int64), ("max_joints", c_uint32), ("joint_spacing", c_double),
                ("min_branch", c_double), ("smoothing", c_double)]


class _ProxyOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("shapes", c_int32), ("mode", c_int32), ("count", c_uint32),
                ("surface_samples", c_uint32), ("evaluate_samples", c_uint32), ("volume_samples", c_uint32),
                ("seed", c_uint64)]


class _ProxyStats(Structure):
    _fields_ = [("struct_size", c_uint32)] + [(name, c_double) for name in (
        "hd_surface_to_proxies", "mean_surface_to_proxies", "hd_proxies_to_surface", "mean_proxies_to_surface",
        "hd_two_sided", "outside_bound", "skeleton_outside", "union_volume", "outside_volume", "radius_change",
        "diagonal")] + [("candidates", c_uint64), ("surface_cells", c_uint64), ("time_s", c_double)]


class _ProxyPlacement(Structure):
    _fields_ = [("struct_size", c_uint32), ("kind", c_int32), ("center", c_double * 3), ("rotation", c_double * 4),
                ("axis", c_double * 3), ("radius_top", c_double), ("radius_bottom", c_double), ("height", c_double),
                ("half_extents", c_double * 3)]


class _SkinView(Structure):
    _fields_ = [("struct_size", c_uint32), ("joint_count", c_size_t), ("parents", c_void_p), ("inverse_bind", c_void_p),
                ("vertex_count", c_size_t), ("influences", c_uint32), ("vertex_joints", c_void_p),
                ("vertex_weights", c_void_p)]


class _BoneColliderOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("mode", c_int32), ("shapes", c_int32), ("min_share", c_double),
                ("min_size", c_double), ("skip_joints", c_void_p), ("skip_count", c_size_t),
                ("surface_samples", c_uint32), ("evaluate_samples", c_uint32), ("seed", c_uint64)]


class _BoneColliderStats(Structure):
    _fields_ = [("struct_size", c_uint32), ("contained_fraction", c_double), ("union_volume", c_double),
                ("outside_volume", c_double), ("neighbour_overlap", c_double), ("joints_with_collider", c_uint64),
                ("joints_skipped", c_uint64), ("time_s", c_double)]
