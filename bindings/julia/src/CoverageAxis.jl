# CoverageAxis.jl: the Julia binding of the coverage-axis C ABI (include/coverage_axis.h, ABI 3),
# the module of the package in bindings/julia (Project.toml; tests in test/runtests.jl).
# ccall wrappers over libcoverage_axis; the C structs are declared field for field (checked
# against the C compiler's layout by tests/abi_layout/check_julia_layout.py, since Julia is not
# packaged in Debian 12 and cannot run in this project's CI). The lengths of the arrays passed in
# are checked before each call (CoverageAxisError with CA_ERROR_INVALID_INPUT). Results are mutable objects with
# finalizers that destroy the C object; their arrays are zero-copy `unsafe_wrap`s inside an
# `OwnedArray` that keeps the owning result alive. Options are keyword arguments applied on top of
# the library's defaults (ca_*_defaults). Indices (triangles in, edges and faces out) are 0-based,
# as in C.
module CoverageAxis

export Context, candidates, select, connect, skeletonize, evaluate, cancel!, clear_cancel!,
       centers, radii, dilated_radii, indices, uncovered, samples, edges, faces, stats, CoverageAxisError,
       TargetNotReachedError, SearchStoppedError

# The library's path: COVERAGE_AXIS_LIBRARY, else the loader's search path.
const libcoverage_axis = get(ENV, "COVERAGE_AXIS_LIBRARY", "libcoverage_axis")
const ABI_VERSION = 3  # the ABI whose layouts are declared below
const CA_OK = Int32(0)
const CA_ERROR_TARGET_NOT_REACHED = Int32(15)
const CA_ERROR_INVALID_INPUT = Int32(4)
const CA_ERROR_CANCELLED = Int32(9)
const CA_ERROR_TIME_LIMIT = Int32(14)

# ---- the C structs (names: the header's without ca_, in CamelCase) ----------------------------
struct ContextDesc
    struct_size::UInt32
    alloc::Ptr{Cvoid}
    free::Ptr{Cvoid}
    alloc_user::Ptr{Cvoid}
    log::Ptr{Cvoid}
    log_user::Ptr{Cvoid}
    progress::Ptr{Cvoid}
    progress_user::Ptr{Cvoid}
    threads::Int32
    progress_interval_s::Float64  # ABI 2
    time_limit_s::Float64  # ABI 2, appended after progress_interval_s
end

struct SurfaceView
    struct_size::UInt32
    positions::Ptr{Float64}
    vertex_count::Csize_t
    position_stride::Csize_t
    triangles::Ptr{UInt32}
    triangle_count::Csize_t
    triangle_stride::Csize_t
    normals::Ptr{Float64}
    normal_stride::Csize_t
    point_normals::Int32  # ABI 2
    normal_count::Csize_t  # ABI 3
end

struct CandidateOptions
    struct_size::UInt32
    generator::Int32
    cover_samples::UInt32
    voronoi_samples::UInt32
    random_candidates::UInt32
    seed::UInt64
    connect_samples::UInt32
    reserved_abi2_tail::UInt32   # ABI 3: the ABI 2 layout's tail padding
    volumetric_only::Int32       # ABI 3
end

struct SelectOptions
    struct_size::UInt32
    dilation::Int32
    delta::Float64
    scale::Float64
    solver::Int32
    time_limit_s::Float64
    skip_uncoverable::Int32
    ignorable_samples::Ptr{UInt8}
    forced_in::Ptr{UInt8}
    forced_out::Ptr{UInt8}
    target_count::UInt32
    target_tolerance::Float64
    divide_threshold::UInt32
    effort::Int32
    target_error::Float64     # ABI 2
    probe_fit::Int32          # ABI 2 (appended after target_error)
    ignorable_samples_count::Csize_t  # ABI 3
    forced_in_count::Csize_t
    forced_out_count::Csize_t
end

struct SelectStats
    struct_size::UInt32
    proven_optimal::Int32
    solver::Int32
    objective::Float64
    lower_bound::Float64
    gap::Float64
    delta_absolute::Float64
    time_reduce_s::Float64
    time_solve_s::Float64
    time_total_s::Float64
    rows_before::UInt64
    cols_before::UInt64
    rows_after::UInt64
    cols_after::UInt64
    forced::UInt64
    components::UInt64
    probes::UInt64
    parts::UInt64
    scale_used::Float64
    time_coverage_s::Float64  # ABI 2
    cbc_components::UInt64    # ABI 2
    rowgen_rounds::UInt64     # ABI 2
    hd_reached::Float64       # ABI 2
end

struct ConnectOptions
    struct_size::UInt32
    method::Int32
    remove_outside::Int32
    fill_holes::Int32
    reconnect::Int32
    fit::Int32             # ABI 2
    fit_iterations::Int32
end

struct SkeletonStats
    struct_size::UInt32
    vertices::UInt64
    edges::UInt64
    faces::UInt64
    components::UInt64
    isolated::UInt64
    betti1::Int64
    time_s::Float64
    method::Int32
    fit_time_s::Float64    # ABI 2
    fit_error_before::Float64
    fit_error_after::Float64
    fit_uncovered::UInt64
    fitted::Int32
    genus::Int64           # ABI 2 (appended after fitted)
    thin_handles::UInt64
    medial_balls::UInt64   # ABI 3
    surface_balls::UInt64
    open_parts::UInt64
end

struct SkeletonView
    struct_size::UInt32
    centers::Ptr{Float64}
    radii::Ptr{Float64}
    vertex_count::Csize_t
    edges::Ptr{UInt32}
    edge_count::Csize_t
    faces::Ptr{UInt32}
    face_count::Csize_t
end

struct EvaluateOptions
    struct_size::UInt32
    surface_samples::UInt32
    envelope_samples::UInt32
    seed::UInt64
end

struct Evaluation
    struct_size::UInt32
    hd_surface_to_recon::Float64
    mean_surface_to_recon::Float64
    hd_recon_to_surface::Float64
    mean_recon_to_surface::Float64
    hd_two_sided::Float64
    diagonal::Float64
    surface_samples_used::UInt64
    envelope_samples_used::UInt64
    time_s::Float64
end

struct CorrespondenceOptions
    struct_size::UInt32
    smoothing::Float64
end

struct RigOptions
    struct_size::UInt32
    root::Int64
    max_joints::UInt32
    joint_spacing::Float64
    min_branch::Float64
    smoothing::Float64
end

struct ProxyOptions
    struct_size::UInt32
    shapes::Int32
    mode::Int32
    count::UInt32
    surface_samples::UInt32
    evaluate_samples::UInt32
    volume_samples::UInt32
    seed::UInt64
end

struct ProxyStats
    struct_size::UInt32
    hd_surface_to_proxies::Float64
    mean_surface_to_proxies::Float64
    hd_proxies_to_surface::Float64
    mean_proxies_to_surface::Float64
    hd_two_sided::Float64
    outside_bound::Float64
    skeleton_outside::Float64
    union_volume::Float64
    outside_volume::Float64
    radius_change::Float64
    diagonal::Float64
    candidates::UInt64
    surface_cells::UInt64
    time_s::Float64
end

struct ProxyPlacement
    struct_size::UInt32
    kind::Int32
    center::NTuple{3, Float64}
    rotation::NTuple{4, Float64}
    axis::NTuple{3, Float64}
    radius_top::Float64
    radius_bottom::Float64
    height::Float64
    half_extents::NTuple{3, Float64}
end

struct SkinView
    struct_size::UInt32
    joint_count::Csize_t
    parents::Ptr{Int32}
    inverse_bind::Ptr{Float64}
    vertex_count::Csize_t
    influences::UInt32
    vertex_joints::Ptr{UInt32}
    vertex_weights::Ptr{Float64}
end

struct BoneColliderOptions
    struct_size::UInt32
    mode::Int32
    shapes::Int32
    min_share::Float64
    min_size::Float64
    skip_joints::Ptr{UInt32}
    skip_count::Csize_t
    surface_samples::UInt32
    evaluate_samples::UInt32
    seed::UInt64
end

struct BoneColliderStats
    struct_size::UInt32
    contained_fraction::Float64
    union_volume::Float64
    outside_volume::Float64
    neighbour_overlap::Float64
    joints_with_collider::UInt64
    joints_skipped::UInt64
    time_s::Float64
end

# ---- errors, defaults -------------------------------------------------------------------------
"""A failed call: the library's status code and its message."""
struct CoverageAxisError <: Exception
    status::Int32
    message::String
end
Base.showerror(io::IO, e::CoverageAxisError) = print(io, "CoverageAxisError(", e.status, "): ", e.message)

status_string(status) = unsafe_string(ccall((:ca_status_string, libcoverage_axis), Cstring, (Int32,), status))
version() = ccall((:ca_version, libcoverage_axis), UInt32, ())
abi_version() = ccall((:ca_abi_version, libcoverage_axis), UInt32, ())

function check(status::Int32)
    status == CA_OK || throw(CoverageAxisError(status, status_string(status)))
    nothing
end

# The library's defaults for this binding's layout of each input struct.
for (T, f) in ((ContextDesc, :ca_context_desc_defaults), (SurfaceView, :ca_surface_view_defaults),
               (CandidateOptions, :ca_candidate_options_defaults), (SelectOptions, :ca_select_options_defaults),
               (ConnectOptions, :ca_connect_options_defaults), (SkeletonView, :ca_skeleton_view_defaults),
               (EvaluateOptions, :ca_evaluate_options_defaults))
    @eval function defaults(::Type{$T})
        r = Ref{$T}()
        check(ccall(($(QuoteNode(f)), libcoverage_axis), Int32, (Ptr{$T}, UInt32), r, sizeof($T)))
        r[]
    end
end

# A copy of x with the named fields replaced (converted to the fields' types).
function with(x::T; fields...) where {T}
    for k in keys(fields)
        k in fieldnames(T) || throw(ArgumentError("$T has no option $k"))
    end
    T((haskey(fields, f) ? convert(fieldtype(T, f), fields[f]) : getfield(x, f) for f in fieldnames(T))...)
end

# An output struct: struct_size set, every other field zero.
zero_field(::Type{P}) where {P<:Ptr} = P(C_NULL)
zero_field(::Type{T}) where {T} = zero(T)
blank(::Type{T}) where {T} =
    with(T((zero_field(fieldtype(T, i)) for i in 1:fieldcount(T))...); struct_size=sizeof(T))

# ---- arrays that keep their owner alive -------------------------------------------------------
"""A zero-copy array over a result's memory; holds the result so it is not finalized first."""
struct OwnedArray{T,N} <: AbstractArray{T,N}
    data::Array{T,N}
    owner::Any
end
Base.size(a::OwnedArray) = size(a.data)
Base.IndexStyle(::Type{<:OwnedArray}) = IndexLinear()
Base.getindex(a::OwnedArray, i::Int) = a.data[i]
Base.unsafe_convert(::Type{Ptr{T}}, a::OwnedArray{T}) where {T} = pointer(a.data)

function owned(owner, p::Ptr{T}, dims::Tuple) where {T}
    # an empty array's pointer must not be read: give a fresh empty array
    prod(dims) == 0 && return OwnedArray(Array{T}(undef, dims), owner)
    OwnedArray(unsafe_wrap(Array, p, dims; own=false), owner)
end

# ---- context ----------------------------------------------------------------------------------
"""
    Context(; threads=0, progress=nothing, progress_interval_s=0)

Runs the three steps; one task at a time. `progress(stage::String, fraction::Float64)` is called
on the calling thread; returning `false` cancels the call (CoverageAxisError with status 9).
`cancel!(ctx)` may be called from any thread.
"""
mutable struct Context
    ptr::Ptr{Cvoid}
    progress::Any
    function Context(; threads::Integer=0, progress=nothing, progress_interval_s::Real=0)
        ctx = new(C_NULL, progress)
        desc = with(defaults(ContextDesc); threads=threads, progress_interval_s=progress_interval_s)
        if progress !== nothing
            desc = with(desc; progress=@cfunction(progress_trampoline, Int32, (Ptr{Cvoid}, Cstring, Float64)),
                        progress_user=pointer_from_objref(ctx))
        end
        out = Ref{Ptr{Cvoid}}(C_NULL)
        check(ccall((:ca_context_create, libcoverage_axis), Int32, (Ref{ContextDesc}, Ref{Ptr{Cvoid}}), desc, out))
        ctx.ptr = out[]
        finalizer(close, ctx)
    end
end

function progress_trampoline(user::Ptr{Cvoid}, stage::Cstring, fraction::Float64)::Int32
    ctx = unsafe_pointer_to_objref(user)::Context
    try
        return ctx.progress(unsafe_string(stage), fraction) === false ? Int32(1) : Int32(0)
    catch
        return Int32(1)  # an exception must not unwind into C: it cancels the call
    end
end

function Base.close(ctx::Context)
    ccall((:ca_context_destroy, libcoverage_axis), Cvoid, (Ptr{Cvoid},), ctx.ptr)
    ctx.ptr = C_NULL
    nothing
end

cancel!(ctx::Context) = ccall((:ca_context_request_cancel, libcoverage_axis), Cvoid, (Ptr{Cvoid},), ctx.ptr)
clear_cancel!(ctx::Context) = ccall((:ca_context_clear_cancel, libcoverage_axis), Cvoid, (Ptr{Cvoid},), ctx.ptr)

function check(ctx::Context, status::Int32)
    status == CA_OK && return nothing
    message = unsafe_string(ccall((:ca_context_last_error, libcoverage_axis), Cstring, (Ptr{Cvoid},), ctx.ptr))
    throw(CoverageAxisError(status, isempty(message) ? status_string(status) : message))
end

# ---- results ----------------------------------------------------------------------------------
"""Samples and candidate balls (step 1). Selections keep the C object alive."""
mutable struct CandidateSet
    ptr::Ptr{Cvoid}
    CandidateSet(ptr) = finalizer(close, new(ptr))
end
"""Balls chosen by step 2; it may outlive its candidate set and context."""
mutable struct Selection
    ptr::Ptr{Cvoid}
    Selection(ptr) = finalizer(close, new(ptr))
end
"""The medial skeleton (step 3); it holds nothing of the other objects."""
mutable struct Skeleton
    ptr::Ptr{Cvoid}
    Skeleton(ptr) = finalizer(close, new(ptr))
end

"""`select` with target_error: no probe reached it; `selection` is the one of lowest HD found."""
struct TargetNotReachedError <: Exception
    message::String
    selection::Selection
end
Base.showerror(io::IO, e::TargetNotReachedError) = print(io, "TargetNotReachedError: ", e.message)

"""`select` with target_error or target_count: the context's time limit ended the search after a
probe; `selection` is the best one so far."""
struct SearchStoppedError <: Exception
    message::String
    selection::Selection
end
Base.showerror(io::IO, e::SearchStoppedError) = print(io, "SearchStoppedError: ", e.message)

for (T, destroy) in ((CandidateSet, :ca_candidate_set_destroy), (Selection, :ca_selection_destroy),
                     (Skeleton, :ca_skeleton_destroy))
    @eval function Base.close(x::$T)
        ccall(($(QuoteNode(destroy)), libcoverage_axis), Cvoid, (Ptr{Cvoid},), x.ptr)
        x.ptr = C_NULL
        nothing
    end
end

# ccall needs constant names and return types, so each count and getter is generated.
for (f, T, cname) in ((:length, CandidateSet, :ca_candidate_set_count), (:length, Selection, :ca_selection_count),
                      (:length, Skeleton, :ca_skeleton_vertex_count),
                      (:sample_count, CandidateSet, :ca_candidate_set_sample_count),
                      (:uncovered_count, Selection, :ca_selection_uncovered_count),
                      (:edge_count, Skeleton, :ca_skeleton_edge_count), (:face_count, Skeleton, :ca_skeleton_face_count))
    name = f === :length ? :(Base.length) : f
    @eval $name(s::$T) = Int(ccall(($(QuoteNode(cname)), libcoverage_axis), Csize_t, (Ptr{Cvoid},), s.ptr))
end

# (function, owner, C getter, element type, rows (0: a vector), count): centers and samples are
# 3×n (one column per point), edges 2×m and faces 3×k with 0-based indices (edges include the
# faces' edges), radii undilated, indices 0-based into the candidate set.
for (f, T, cname, E, rows, n) in (
        (:centers, CandidateSet, :ca_candidate_set_centers, Float64, 3, length),
        (:radii, CandidateSet, :ca_candidate_set_radii, Float64, 0, length),
        (:samples, CandidateSet, :ca_candidate_set_samples, Float64, 3, sample_count),
        (:centers, Selection, :ca_selection_centers, Float64, 3, length),
        (:radii, Selection, :ca_selection_radii, Float64, 0, length),
        (:dilated_radii, Selection, :ca_selection_dilated_radii, Float64, 0, length),
        (:indices, Selection, :ca_selection_indices, UInt32, 0, length),
        (:uncovered, Selection, :ca_selection_uncovered, UInt32, 0, uncovered_count),
        (:centers, Skeleton, :ca_skeleton_centers, Float64, 3, length),
        (:radii, Skeleton, :ca_skeleton_radii, Float64, 0, length),
        (:edges, Skeleton, :ca_skeleton_edges, UInt32, 2, edge_count),
        (:faces, Skeleton, :ca_skeleton_faces, UInt32, 3, face_count))
    @eval function $f(s::$T)
        p = ccall(($(QuoteNode(cname)), libcoverage_axis), Ptr{$E}, (Ptr{Cvoid},), s.ptr)
        owned(s, p, $rows == 0 ? ($n(s),) : ($rows, $n(s)))
    end
end

reference_length(s::CandidateSet) =
    ccall((:ca_candidate_set_reference_length, libcoverage_axis), Float64, (Ptr{Cvoid},), s.ptr)

function stats(s::Selection)
    r = Ref(blank(SelectStats))
    check(ccall((:ca_selection_stats, libcoverage_axis), Int32, (Ptr{Cvoid}, Ptr{SelectStats}), s.ptr, r))
    r[]
end
function stats(s::Skeleton)
    r = Ref(blank(SkeletonStats))
    check(ccall((:ca_skeleton_stats_get, libcoverage_axis), Int32, (Ptr{Cvoid}, Ptr{SkeletonStats}), s.ptr, r))
    r[]
end

# ---- the steps --------------------------------------------------------------------------------
invalid_input(message) = throw(CoverageAxisError(CA_ERROR_INVALID_INPUT, message))

# A view of the caller's arrays (3×n positions, 3×m 0-based UInt32 triangles or nothing, 3×n
# normals or nothing); the arrays must be preserved around the call that reads it.
function surface_view(positions::Matrix{Float64}, triangles, normals)
    size(positions, 1) == 3 || invalid_input("positions must be 3×n, not $(size(positions, 1))×$(size(positions, 2))")
    triangles === nothing || size(triangles, 1) == 3 ||
        invalid_input("triangles must be 3×m, not $(size(triangles, 1))×$(size(triangles, 2))")
    normals === nothing || size(normals) == size(positions) ||
        invalid_input("normals: $(size(normals, 2)) for $(size(positions, 2)) points (3×n, one per point, or nothing)")
    with(defaults(SurfaceView); positions=pointer(positions), vertex_count=size(positions, 2),
         triangles=triangles === nothing ? Ptr{UInt32}(C_NULL) : pointer(triangles),
         triangle_count=triangles === nothing ? 0 : size(triangles, 2),
         normals=normals === nothing ? Ptr{Float64}(C_NULL) : pointer(normals),
         normal_count=normals === nothing ? 0 : size(normals, 2))
end

as_matrix(::Type{T}, a) where {T} = a === nothing ? nothing : a isa Matrix{T} ? a : Matrix{T}(a)

"""
    candidates(ctx, positions, triangles=nothing; normals=nothing, options...)

Step 1. positions 3×n; triangles 3×m 0-based (a mesh) or `nothing` with 3×n outward `normals`,
one per point, or `nothing` (a point cloud). Options: the fields of `ca_candidate_options`
(cover_samples, seed, ...). Arrays of other shapes throw `CoverageAxisError` (status 4,
CA_ERROR_INVALID_INPUT) before the library is called.
"""
function candidates(ctx::Context, positions, triangles=nothing; normals=nothing, options...)
    p, t, n = as_matrix(Float64, positions), as_matrix(UInt32, triangles), as_matrix(Float64, normals)
    o = with(defaults(CandidateOptions); options...)
    out = Ref{Ptr{Cvoid}}(C_NULL)
    GC.@preserve ctx p t n begin
        view = surface_view(p, t, n)
        check(ctx, ccall((:ca_candidates, libcoverage_axis), Int32,
                         (Ptr{Cvoid}, Ref{SurfaceView}, Ref{CandidateOptions}, Ref{Ptr{Cvoid}}), ctx.ptr, view, o, out))
    end
    CandidateSet(out[])
end

"""
    select(ctx, set; options...)

Step 2: the fewest dilated balls covering every sample. Options: the fields of
`ca_select_options` (delta, solver, effort, time_limit_s, ...); masks as Vector{UInt8}, one entry
per sample (`ignorable_samples`) or candidate ball (`forced_in`, `forced_out`).
"""
function select(ctx::Context, set::CandidateSet; ignorable_samples=nothing, forced_in=nothing, forced_out=nothing,
                options...)
    masks = (ignorable_samples, forced_in, forced_out)
    for (name, m, n) in (("ignorable_samples", ignorable_samples, sample_count(set)),
                         ("forced_in", forced_in, length(set)), ("forced_out", forced_out, length(set)))
        m === nothing || length(m) == n || invalid_input("$name: $(length(m)) entries, the set needs $n")
    end
    ptrs = map(m -> m === nothing ? Ptr{UInt8}(C_NULL) : pointer(m::Vector{UInt8}), masks)
    counts = map(m -> m === nothing ? 0 : length(m), masks)
    o = with(defaults(SelectOptions); ignorable_samples=ptrs[1], forced_in=ptrs[2], forced_out=ptrs[3],
             ignorable_samples_count=counts[1], forced_in_count=counts[2], forced_out_count=counts[3], options...)
    out = Ref{Ptr{Cvoid}}(C_NULL)
    status = GC.@preserve ctx set masks begin
        ccall((:ca_select, libcoverage_axis), Int32,
              (Ptr{Cvoid}, Ptr{Cvoid}, Ref{SelectOptions}, Ref{Ptr{Cvoid}}), ctx.ptr, set.ptr, o, out)
    end
    if status == CA_ERROR_TARGET_NOT_REACHED && out[] != C_NULL  # a failure with a result
        message = unsafe_string(ccall((:ca_context_last_error, libcoverage_axis), Cstring, (Ptr{Cvoid},), ctx.ptr))
        throw(TargetNotReachedError(message, Selection(out[])))
    end
    if status == CA_ERROR_TIME_LIMIT && out[] != C_NULL  # a search the time limit ended: its best so far
        message = unsafe_string(ccall((:ca_context_last_error, libcoverage_axis), Cstring, (Ptr{Cvoid},), ctx.ptr))
        throw(SearchStoppedError(message, Selection(out[])))
    end
    check(ctx, status)
    Selection(out[])
end

"""
    connect(ctx, set, selection; options...)

Step 3: edges and faces between the selected balls (`set`: the selection's own set). Options: the
fields of `ca_connect_options` (method, remove_outside, fill_holes, reconnect).
"""
function connect(ctx::Context, set::CandidateSet, selection::Selection; options...)
    o = with(defaults(ConnectOptions); options...)
    out = Ref{Ptr{Cvoid}}(C_NULL)
    GC.@preserve ctx set selection begin
        check(ctx, ccall((:ca_connect, libcoverage_axis), Int32,
                         (Ptr{Cvoid}, Ptr{Cvoid}, Ptr{Cvoid}, Ref{ConnectOptions}, Ref{Ptr{Cvoid}}),
                         ctx.ptr, set.ptr, selection.ptr, o, out))
    end
    Skeleton(out[])
end

"""The three steps with default options."""
function skeletonize(ctx::Context, positions, triangles=nothing; normals=nothing)
    set = candidates(ctx, positions, triangles; normals=normals)
    connect(ctx, set, select(ctx, set))
end

"""
    evaluate(ctx, positions, triangles, skeleton; options...)

Hausdorff distances between the surface and the skeleton's reconstruction, in % of the
bounding-box diagonal (an `Evaluation`).
"""
function evaluate(ctx::Context, positions, triangles, skeleton::Skeleton; options...)
    p, t = as_matrix(Float64, positions), as_matrix(UInt32, triangles)
    o = with(defaults(EvaluateOptions); options...)
    result = Ref(blank(Evaluation))
    GC.@preserve ctx p t skeleton begin
        view = Ref(defaults(SkeletonView))
        check(ccall((:ca_skeleton_get_view, libcoverage_axis), Int32, (Ptr{Cvoid}, Ptr{SkeletonView}), skeleton.ptr, view))
        check(ctx, ccall((:ca_evaluate, libcoverage_axis), Int32,
                         (Ptr{Cvoid}, Ref{SurfaceView}, Ptr{SkeletonView}, Ref{EvaluateOptions}, Ptr{Evaluation}),
                         ctx.ptr, surface_view(p, t, nothing), view, o, result))
    end
    result[]
end

function __init__()
    abi_version() >= ABI_VERSION ||
        error("libcoverage_axis has ABI $(abi_version()); CoverageAxis.jl needs $ABI_VERSION")
end

end # module
