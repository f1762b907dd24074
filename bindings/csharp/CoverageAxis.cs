// CoverageAxis.cs: the C# binding of the coverage-axis C ABI (include/coverage_axis.h, ABI 3).
// Native: P/Invoke declarations and the C structs, field for field (checked against the C layout
// by tests/TestCoverageAxis.cs). Above it: SafeHandle subclasses that destroy the C objects,
// CoverageAxisException with the status and message, option classes that start from the
// library's defaults (ca_*_defaults), a Context with a Progress event and CancellationToken
// parameters, and result classes whose arrays are copied out of the C objects.
using System;
using System.Runtime.InteropServices;
using System.Threading;

namespace CoverageAxis
{
    /// <summary>The pinned status codes of the C ABI.</summary>
    public enum Status
    {
        Ok = 0, InvalidArgument = 1, NullPointer = 2, StructSize = 3, InvalidInput = 4,
        DegenerateInput = 5, Uncoverable = 6, Geometry = 7, Solver = 8, Cancelled = 9,
        OutOfMemory = 10, BufferTooSmall = 11, Internal = 12, NoCandidates = 13, TimeLimit = 14,
        TargetNotReached = 15,
    }

    public enum Generator { Voronoi = 0, Random = 1 }
    public enum Dilation { Offset = 0, Scale = 1 }
    public enum Solver { Exact = 0, Greedy = 1, Capp = 2 }
    public enum Effort { Fast = 0, Prove = 1 }
    public enum ConnectMethod { Power = 0, Medial = 1, Auto = 2 }

    /// <summary>P/Invoke declarations; struct and field names are the header's.</summary>
    public static class Native
    {
        const string Lib = "coverage_axis";
        /// <summary>The ABI version whose layouts these declarations follow.</summary>
        public const uint AbiVersion = 3;

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void LogFn(IntPtr user, int level, IntPtr message);
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate int ProgressFn(IntPtr user, IntPtr stage, double fraction);

        [StructLayout(LayoutKind.Sequential)]
        public struct ContextDesc
        {
            public uint struct_size;
            public IntPtr alloc, free, alloc_user, log, log_user, progress, progress_user;
            public int threads;
            public double progress_interval_s; // ABI 2
            public double time_limit_s; // ABI 2, appended after progress_interval_s
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SurfaceView
        {
            public uint struct_size;
            public IntPtr positions;
            public UIntPtr vertex_count, position_stride;
            public IntPtr triangles;
            public UIntPtr triangle_count, triangle_stride;
            public IntPtr normals;
            public UIntPtr normal_stride;
            public int point_normals; // ABI 2
            public UIntPtr normal_count; // ABI 3
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct CandidateOptions
        {
            public uint struct_size;
            public int generator;
            public uint cover_samples, voronoi_samples, random_candidates;
            public ulong seed;
            public uint connect_samples;
            public uint reserved_abi2_tail;  // ABI 3: the ABI 2 layout's tail padding
            public int volumetric_only;      // ABI 3
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SelectOptions
        {
            public uint struct_size;
            public int dilation;
            public double delta, scale;
            public int solver;
            public double time_limit_s;
            public int skip_uncoverable;
            public IntPtr ignorable_samples, forced_in, forced_out;
            public uint target_count;
            public double target_tolerance;
            public uint divide_threshold;
            public int effort;
            public double target_error;     // ABI 2
            public int probe_fit;           // ABI 2 (appended after target_error)
            public UIntPtr ignorable_samples_count, forced_in_count, forced_out_count; // ABI 3
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SelectStats
        {
            public uint struct_size;
            public int proven_optimal, solver;
            public double objective, lower_bound, gap, delta_absolute, time_reduce_s, time_solve_s, time_total_s;
            public ulong rows_before, cols_before, rows_after, cols_after, forced, components, probes, parts;
            public double scale_used;
            public double time_coverage_s;  // ABI 2
            public ulong cbc_components;    // ABI 2
            public ulong rowgen_rounds;     // ABI 2
            public double hd_reached;       // ABI 2
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ConnectOptions
        {
            public uint struct_size;
            public int method, remove_outside, fill_holes, reconnect;
            public int fit, fit_iterations;   // ABI 2
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SkeletonStats
        {
            public uint struct_size;
            public ulong vertices, edges, faces, components, isolated;
            public long betti1;
            public double time_s;
            public int method;
            public double fit_time_s, fit_error_before, fit_error_after;   // ABI 2
            public ulong fit_uncovered;
            public int fitted;
            public long genus;           // ABI 2 (appended after fitted)
            public ulong thin_handles;
            public ulong medial_balls, surface_balls, open_parts;   // ABI 3
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SkeletonView
        {
            public uint struct_size;
            public IntPtr centers, radii;
            public UIntPtr vertex_count;
            public IntPtr edges;
            public UIntPtr edge_count;
            public IntPtr faces;
            public UIntPtr face_count;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct EvaluateOptions
        {
            public uint struct_size;
            public uint surface_samples, envelope_samples;
            public ulong seed;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct Evaluation
        {
            public uint struct_size;
            public double hd_surface_to_recon, mean_surface_to_recon, hd_recon_to_surface, mean_recon_to_surface;
            public double hd_two_sided, diagonal;
            public ulong surface_samples_used, envelope_samples_used;
            public double time_s;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct CorrespondenceOptions
        {
            public uint struct_size;
            public double smoothing;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct RigOptions
        {
            public uint struct_size;
            public long root;
            public uint max_joints;
            public double joint_spacing, min_branch, smoothing;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ProxyOptions
        {
            public uint struct_size;
            public int shapes, mode;
            public uint count, surface_samples, evaluate_samples, volume_samples;
            public ulong seed;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ProxyStats
        {
            public uint struct_size;
            public double hd_surface_to_proxies, mean_surface_to_proxies, hd_proxies_to_surface, mean_proxies_to_surface;
            public double hd_two_sided, outside_bound, skeleton_outside, union_volume, outside_volume;
            public double radius_change, diagonal;
            public ulong candidates, surface_cells;
            public double time_s;
        }

        [StructLayout(LayoutKind.Sequential)]
        public unsafe struct ProxyPlacement
        {
            public uint struct_size;
            public int kind;
            public fixed double center[3];
            public fixed double rotation[4];
            public fixed double axis[3];
            public double radius_top, radius_bottom, height;
            public fixed double half_extents[3];
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct SkinView
        {
            public uint struct_size;
            public UIntPtr joint_count;
            public IntPtr parents, inverse_bind;
            public UIntPtr vertex_count;
            public uint influences;
            public IntPtr vertex_joints, vertex_weights;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct BoneColliderOptions
        {
            public uint struct_size;
            public int mode, shapes;
            public double min_share, min_size;
            public IntPtr skip_joints;
            public UIntPtr skip_count;
            public uint surface_samples, evaluate_samples;
            public ulong seed;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct BoneColliderStats
        {
            public uint struct_size;
            public double contained_fraction, union_volume, outside_volume, neighbour_overlap;
            public ulong joints_with_collider, joints_skipped;
            public double time_s;
        }

        /// <summary>Every struct declared here, in header order (for the layout check).</summary>
        public static readonly Type[] Structs = {
            typeof(ContextDesc), typeof(SurfaceView), typeof(CandidateOptions), typeof(SelectOptions),
            typeof(SelectStats), typeof(ConnectOptions), typeof(SkeletonStats), typeof(SkeletonView),
            typeof(EvaluateOptions), typeof(Evaluation), typeof(CorrespondenceOptions), typeof(RigOptions),
            typeof(ProxyOptions), typeof(ProxyStats), typeof(ProxyPlacement),
            typeof(SkinView), typeof(BoneColliderOptions), typeof(BoneColliderStats),
        };

        [DllImport(Lib)] public static extern uint ca_version();
        [DllImport(Lib)] public static extern uint ca_abi_version();
        [DllImport(Lib)] public static extern IntPtr ca_status_string(int status);

        [DllImport(Lib)] public static extern int ca_context_desc_defaults(ref ContextDesc desc, uint size);
        [DllImport(Lib)] public static extern int ca_context_create(ref ContextDesc desc, out ContextHandle ctx);
        [DllImport(Lib)] public static extern void ca_context_destroy(IntPtr ctx);
        [DllImport(Lib)] public static extern void ca_context_request_cancel(ContextHandle ctx);
        [DllImport(Lib)] public static extern void ca_context_clear_cancel(ContextHandle ctx);
        [DllImport(Lib)] public static extern IntPtr ca_context_last_error(ContextHandle ctx);

        [DllImport(Lib)] public static extern int ca_surface_view_defaults(ref SurfaceView view, uint size);
        [DllImport(Lib)] public static extern int ca_candidate_options_defaults(ref CandidateOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_candidates(ContextHandle ctx, ref SurfaceView surface,
            ref CandidateOptions options, out CandidateSetHandle set);
        [DllImport(Lib)] public static extern void ca_candidate_set_destroy(IntPtr set);
        [DllImport(Lib)] public static extern UIntPtr ca_candidate_set_count(CandidateSetHandle set);
        [DllImport(Lib)] public static extern IntPtr ca_candidate_set_centers(CandidateSetHandle set);
        [DllImport(Lib)] public static extern IntPtr ca_candidate_set_radii(CandidateSetHandle set);
        [DllImport(Lib)] public static extern UIntPtr ca_candidate_set_sample_count(CandidateSetHandle set);
        [DllImport(Lib)] public static extern IntPtr ca_candidate_set_samples(CandidateSetHandle set);
        [DllImport(Lib)] public static extern double ca_candidate_set_reference_length(CandidateSetHandle set);
        [DllImport(Lib)] public static extern int ca_candidate_set_flipped(CandidateSetHandle set);
        [DllImport(Lib)] public static extern ulong ca_candidate_set_outlier_count(CandidateSetHandle set);

        [DllImport(Lib)] public static extern int ca_select_options_defaults(ref SelectOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_select(ContextHandle ctx, CandidateSetHandle set,
            ref SelectOptions options, out SelectionHandle selection);
        [DllImport(Lib)] public static extern void ca_selection_destroy(IntPtr selection);
        [DllImport(Lib)] public static extern UIntPtr ca_selection_count(SelectionHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_selection_indices(SelectionHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_selection_centers(SelectionHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_selection_radii(SelectionHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_selection_dilated_radii(SelectionHandle s);
        [DllImport(Lib)] public static extern UIntPtr ca_selection_uncovered_count(SelectionHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_selection_uncovered(SelectionHandle s);
        [DllImport(Lib)] public static extern int ca_selection_stats(SelectionHandle s, ref SelectStats stats);

        [DllImport(Lib)] public static extern int ca_connect_options_defaults(ref ConnectOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_connect(ContextHandle ctx, CandidateSetHandle set,
            SelectionHandle selection, ref ConnectOptions options, out SkeletonHandle skeleton);
        [DllImport(Lib)] public static extern void ca_skeleton_destroy(IntPtr skeleton);
        [DllImport(Lib)] public static extern UIntPtr ca_skeleton_vertex_count(SkeletonHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_skeleton_centers(SkeletonHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_skeleton_radii(SkeletonHandle s);
        [DllImport(Lib)] public static extern UIntPtr ca_skeleton_edge_count(SkeletonHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_skeleton_edges(SkeletonHandle s);
        [DllImport(Lib)] public static extern UIntPtr ca_skeleton_face_count(SkeletonHandle s);
        [DllImport(Lib)] public static extern IntPtr ca_skeleton_faces(SkeletonHandle s);
        [DllImport(Lib)] public static extern int ca_skeleton_stats_get(SkeletonHandle s, ref SkeletonStats stats);

        [DllImport(Lib)] public static extern int ca_skeleton_view_defaults(ref SkeletonView view, uint size);
        [DllImport(Lib)] public static extern int ca_skeleton_get_view(SkeletonHandle s, ref SkeletonView view);
        [DllImport(Lib)] public static extern int ca_evaluate_options_defaults(ref EvaluateOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_evaluate(ContextHandle ctx, ref SurfaceView surface,
            ref SkeletonView skeleton, ref EvaluateOptions options, ref Evaluation result);

        [DllImport(Lib)] public static extern int ca_correspondence_options_defaults(ref CorrespondenceOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_correspond(ContextHandle ctx, ref SurfaceView surface,
            ref SkeletonView skeleton, ref CorrespondenceOptions options, out CorrespondenceHandle result);
        [DllImport(Lib)] public static extern void ca_correspondence_destroy(IntPtr c);
        [DllImport(Lib)] public static extern UIntPtr ca_correspondence_vertex_count(CorrespondenceHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_correspondence_balls(CorrespondenceHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_correspondence_weights(CorrespondenceHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_correspondence_nearest_kinds(CorrespondenceHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_correspondence_nearest_indices(CorrespondenceHandle c);
        [DllImport(Lib)] public static extern int ca_rig_options_defaults(ref RigOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_rig_build(ContextHandle ctx, ref SurfaceView surface,
            ref SkeletonView skeleton, ref RigOptions options, out RigHandle result);
        [DllImport(Lib)] public static extern void ca_rig_destroy(IntPtr r);
        [DllImport(Lib)] public static extern UIntPtr ca_rig_joint_count(RigHandle r);
        [DllImport(Lib)] public static extern IntPtr ca_rig_joint_positions(RigHandle r);
        [DllImport(Lib)] public static extern IntPtr ca_rig_joint_parents(RigHandle r);
        [DllImport(Lib)] public static extern UIntPtr ca_rig_branch_count(RigHandle r);
        [DllImport(Lib)] public static extern UIntPtr ca_rig_vertex_count(RigHandle r);
        [DllImport(Lib)] public static extern IntPtr ca_rig_vertex_joints(RigHandle r);
        [DllImport(Lib)] public static extern IntPtr ca_rig_vertex_weights(RigHandle r);
        [DllImport(Lib)] public static extern IntPtr ca_rig_vertex_branches(RigHandle r);

        [DllImport(Lib)] public static extern int ca_proxy_options_defaults(ref ProxyOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_proxies(ContextHandle ctx, CandidateSetHandle set,
            ref SkeletonView skeleton, ref ProxyOptions options, out ProxySetHandle proxies);
        [DllImport(Lib)] public static extern void ca_proxy_set_destroy(IntPtr proxies);
        [DllImport(Lib)] public static extern UIntPtr ca_proxy_set_count(ProxySetHandle p);
        [DllImport(Lib)] public static extern IntPtr ca_proxy_set_kinds(ProxySetHandle p);
        [DllImport(Lib)] public static extern IntPtr ca_proxy_set_centers(ProxySetHandle p);
        [DllImport(Lib)] public static extern IntPtr ca_proxy_set_radii(ProxySetHandle p);
        [DllImport(Lib)] public static extern int ca_proxy_set_stats(ProxySetHandle p, ref ProxyStats stats);
        [DllImport(Lib)] public static extern int ca_proxy_set_placement(ProxySetHandle p, UIntPtr index, ref ProxyPlacement placement);

        [DllImport(Lib)] public static extern int ca_skin_view_defaults(ref SkinView v, uint size);
        [DllImport(Lib)] public static extern int ca_bone_collider_options_defaults(ref BoneColliderOptions o, uint size);
        [DllImport(Lib)] public static extern int ca_bone_colliders_build(ContextHandle ctx, CandidateSetHandle set,
            IntPtr skeleton, ref SkinView skin, ref BoneColliderOptions options, out BoneCollidersHandle colliders);
        [DllImport(Lib)] public static extern void ca_bone_colliders_destroy(IntPtr colliders);
        [DllImport(Lib)] public static extern UIntPtr ca_bone_colliders_count(BoneCollidersHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_bone_colliders_joints(BoneCollidersHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_bone_colliders_contained(BoneCollidersHandle c);
        [DllImport(Lib)] public static extern IntPtr ca_bone_colliders_overlap(BoneCollidersHandle c);
        [DllImport(Lib)] public static extern int ca_bone_colliders_stats(BoneCollidersHandle c, ref BoneColliderStats stats);
        [DllImport(Lib)] public static extern int ca_bone_colliders_placement(BoneCollidersHandle c, UIntPtr index, ref ProxyPlacement placement);

        public static uint SizeOf<T>() { return (uint)Marshal.SizeOf(typeof(T)); }

        /// <summary>Throws unless the library knows this binding's layout of a struct.</summary>
        public static void CheckDefaults(int status, string name)
        {
            if (status != 0)
                throw new CoverageAxisException((Status)status, "the linked library does not know this binding's " +
                    name + " (ABI " + AbiVersion + ")");
        }
    }

    /// <summary>A C object owned by a SafeHandle; subclasses name the destroy function.</summary>
    public abstract class OwnedHandle : SafeHandle
    {
        protected OwnedHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }
    }

    public sealed class ContextHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_context_destroy(handle); return true; }
    }

    public sealed class CandidateSetHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_candidate_set_destroy(handle); return true; }
    }

    public sealed class SelectionHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_selection_destroy(handle); return true; }
    }

    public sealed class SkeletonHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_skeleton_destroy(handle); return true; }
    }

    public sealed class CorrespondenceHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_correspondence_destroy(handle); return true; }
    }

    public sealed class RigHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_rig_destroy(handle); return true; }
    }

    public sealed class ProxySetHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_proxy_set_destroy(handle); return true; }
    }

    public sealed class BoneCollidersHandle : OwnedHandle
    {
        protected override bool ReleaseHandle() { Native.ca_bone_colliders_destroy(handle); return true; }
    }

    /// <summary>Pins managed arrays for the duration of one call.</summary>
    static class Pinning
    {
        public static GCHandle Pin(Array a) { return a == null ? default(GCHandle) : GCHandle.Alloc(a, GCHandleType.Pinned); }
        public static IntPtr Address(GCHandle h) { return h.IsAllocated ? h.AddrOfPinnedObject() : IntPtr.Zero; }
        public static void Free(GCHandle[] pins) { foreach (var p in pins) if (p.IsAllocated) p.Free(); }
    }

    /// <summary>A failed call: the library's status and its message.</summary>
    public class CoverageAxisException : Exception
    {
        public Status Status { get; private set; }
        public CoverageAxisException(Status status, string message) : base(message) { Status = status; }

        /// <summary>The library's static name of a status.</summary>
        public static string StatusString(Status status)
        {
            return Marshal.PtrToStringAnsi(Native.ca_status_string((int)status));
        }
    }

    /// <summary>Select with TargetError: no probe reached it. Selection is the selection of lowest
    /// HD found (its Stats' hd_reached); the caller disposes of it.</summary>
    public class TargetNotReachedException : CoverageAxisException
    {
        public Selection Selection { get; private set; }
        public TargetNotReachedException(string message, Selection selection) : base(Status.TargetNotReached, message)
        {
            Selection = selection;
        }
    }

    /// <summary>Select with TargetError or TargetCount: the context's time limit ended the search
    /// after a probe (Status.TimeLimit). Selection is the best selection so far (its Stats'
    /// hd_reached and probes); the caller disposes of it.</summary>
    public class SearchStoppedException : CoverageAxisException
    {
        public Selection Selection { get; private set; }
        public SearchStoppedException(string message, Selection selection) : base(Status.TimeLimit, message)
        {
            Selection = selection;
        }
    }

    /// <summary>A surface: a triangle mesh (x y z per vertex, i j k per triangle, 0-based) or an
    /// oriented point cloud (Triangles null, one outward normal per point, or Normals null). Arrays
    /// are read during a call only; their lengths are checked before it (Status.InvalidInput).</summary>
    public sealed class Surface
    {
        public double[] Positions;
        public uint[] Triangles;
        public double[] Normals;
        public static Surface Mesh(double[] positions, uint[] triangles)
        {
            return new Surface { Positions = positions, Triangles = triangles };
        }
        public static Surface Points(double[] positions, double[] normals)
        {
            return new Surface { Positions = positions, Normals = normals };
        }

        /// <summary>Throws Status.InvalidInput unless the arrays hold whole points and triangles and
        /// the normals, when given, one per point.</summary>
        internal void CheckLengths()
        {
            int values = Positions == null ? 0 : Positions.Length;
            if (values % 3 != 0)
                throw new CoverageAxisException(Status.InvalidInput, "Positions: " + values + " values, not x y z per point");
            if (Triangles != null && Triangles.Length % 3 != 0)
                throw new CoverageAxisException(Status.InvalidInput, "Triangles: " + Triangles.Length + " values, not i j k per triangle");
            if (Normals != null && Normals.Length != values)
                throw new CoverageAxisException(Status.InvalidInput, "Normals: " + Normals.Length / 3 + " normals (" +
                    Normals.Length + " values) for " + values / 3 + " points; one per point, or null");
        }

        /// <summary>Pins the arrays and calls f with their view.</summary>
        internal T With<T>(Func<Native.SurfaceView, T> f)
        {
            CheckLengths();
            var view = new Native.SurfaceView();
            Native.CheckDefaults(Native.ca_surface_view_defaults(ref view, Native.SizeOf<Native.SurfaceView>()), "ca_surface_view");
            var pins = new[] { Pinning.Pin(Positions), Pinning.Pin(Triangles), Pinning.Pin(Normals) };
            try
            {
                view.positions = Pinning.Address(pins[0]);
                view.vertex_count = (UIntPtr)(Positions == null ? 0 : Positions.Length / 3);
                view.triangles = Pinning.Address(pins[1]);
                view.triangle_count = (UIntPtr)(Triangles == null ? 0 : Triangles.Length / 3);
                view.normals = Pinning.Address(pins[2]);
                view.normal_count = (UIntPtr)(Normals == null ? 0 : Normals.Length / 3);
                return f(view);
            }
            finally
            {
                Pinning.Free(pins);
            }
        }
    }

    /// <summary>Options of Context.Candidates, starting from the library's defaults.</summary>
    public sealed class CandidateOptions
    {
        internal Native.CandidateOptions Raw;
        public CandidateOptions()
        {
            Native.CheckDefaults(Native.ca_candidate_options_defaults(ref Raw, Native.SizeOf<Native.CandidateOptions>()), "ca_candidate_options");
        }
        public Generator Generator { get { return (Generator)Raw.generator; } set { Raw.generator = (int)value; } }
        /// <summary>|S|, the surface samples to cover.</summary>
        public uint CoverSamples { get { return Raw.cover_samples; } set { Raw.cover_samples = value; } }
        public uint VoronoiSamples { get { return Raw.voronoi_samples; } set { Raw.voronoi_samples = value; } }
        public uint RandomCandidates { get { return Raw.random_candidates; } set { Raw.random_candidates = value; } }
        public ulong Seed { get { return Raw.seed; } set { Raw.seed = value; } }
        public uint ConnectSamples { get { return Raw.connect_samples; } set { Raw.connect_samples = value; } }
    }

    /// <summary>Options of Context.Select, starting from the library's defaults.</summary>
    public sealed class SelectOptions
    {
        internal Native.SelectOptions Raw;
        public SelectOptions()
        {
            Native.CheckDefaults(Native.ca_select_options_defaults(ref Raw, Native.SizeOf<Native.SelectOptions>()), "ca_select_options");
        }
        public Dilation Dilation { get { return (Dilation)Raw.dilation; } set { Raw.dilation = (int)value; } }
        /// <summary>Offset, a fraction of the longest bounding-box side.</summary>
        public double Delta { get { return Raw.delta; } set { Raw.delta = value; } }
        public double Scale { get { return Raw.scale; } set { Raw.scale = value; } }
        public Solver Solver { get { return (Solver)Raw.solver; } set { Raw.solver = (int)value; } }
        public Effort Effort { get { return (Effort)Raw.effort; } set { Raw.effort = (int)value; } }
        public double TimeLimitSeconds { get { return Raw.time_limit_s; } set { Raw.time_limit_s = value; } }
        public bool SkipUncoverable { get { return Raw.skip_uncoverable != 0; } set { Raw.skip_uncoverable = value ? 1 : 0; } }
        public uint TargetCount { get { return Raw.target_count; } set { Raw.target_count = value; } }
        public double TargetTolerance { get { return Raw.target_tolerance; } set { Raw.target_tolerance = value; } }
        /// <summary>ABI 2: the fewest balls within this two-sided Hausdorff distance (% of the bbox diagonal); 0 = off.</summary>
        public double TargetError { get { return Raw.target_error; } set { Raw.target_error = value; } }
        public uint DivideThreshold { get { return Raw.divide_threshold; } set { Raw.divide_threshold = value; } }
        /// <summary>Per sample, true: need not be covered (null = none).</summary>
        public byte[] IgnorableSamples;
        /// <summary>Per candidate ball, true: must be selected (null = none).</summary>
        public byte[] ForcedIn;
        /// <summary>Per candidate ball, true: must not be selected (null = none).</summary>
        public byte[] ForcedOut;
    }

    /// <summary>Options of Context.Connect, starting from the library's defaults.</summary>
    public sealed class ConnectOptions
    {
        internal Native.ConnectOptions Raw;
        public ConnectOptions()
        {
            Native.CheckDefaults(Native.ca_connect_options_defaults(ref Raw, Native.SizeOf<Native.ConnectOptions>()), "ca_connect_options");
        }
        public ConnectMethod Method { get { return (ConnectMethod)Raw.method; } set { Raw.method = (int)value; } }
        public bool RemoveOutside { get { return Raw.remove_outside != 0; } set { Raw.remove_outside = value ? 1 : 0; } }
        public bool FillHoles { get { return Raw.fill_holes != 0; } set { Raw.fill_holes = value ? 1 : 0; } }
        public bool Reconnect { get { return Raw.reconnect != 0; } set { Raw.reconnect = value ? 1 : 0; } }
    }

    /// <summary>Options of Context.Evaluate, starting from the library's defaults.</summary>
    public sealed class EvaluateOptions
    {
        internal Native.EvaluateOptions Raw;
        public EvaluateOptions()
        {
            Native.CheckDefaults(Native.ca_evaluate_options_defaults(ref Raw, Native.SizeOf<Native.EvaluateOptions>()), "ca_evaluate_options");
        }
        public uint SurfaceSamples { get { return Raw.surface_samples; } set { Raw.surface_samples = value; } }
        public uint EnvelopeSamples { get { return Raw.envelope_samples; } set { Raw.envelope_samples = value; } }
        public ulong Seed { get { return Raw.seed; } set { Raw.seed = value; } }
    }

    /// <summary>Options of Context.Rig (ca_rig_options; docs/rig.md): the library's defaults.</summary>
    public sealed class RigOptions
    {
        internal Native.RigOptions Raw;
        public RigOptions()
        {
            Native.CheckDefaults(Native.ca_rig_options_defaults(ref Raw, Native.SizeOf<Native.RigOptions>()), "ca_rig_options");
        }
        /// <summary>The root joint's ball; -1: the largest ball.</summary>
        public long Root { get { return Raw.root; } set { Raw.root = value; } }
        public uint MaxJoints { get { return Raw.max_joints; } set { Raw.max_joints = value; } }
        public double JointSpacing { get { return Raw.joint_spacing; } set { Raw.joint_spacing = value; } }
        public double MinBranch { get { return Raw.min_branch; } set { Raw.min_branch = value; } }
        public double Smoothing { get { return Raw.smoothing; } set { Raw.smoothing = value; } }
    }

    /// <summary>What engine proxies may be (CA_PROXY_SHAPES_*).</summary>
    public enum ProxyShapes { Spheres = 0, Capsules = 1 }
    /// <summary>Inscribed proxies stay inside the shape; conservative ones contain the whole surface.</summary>
    public enum ProxyMode { Inscribed = 0, Conservative = 1 }

    /// <summary>Options of Context.Proxies, starting from the library's defaults.</summary>
    public sealed class ProxyOptions
    {
        internal Native.ProxyOptions Raw;
        public ProxyOptions()
        {
            Native.CheckDefaults(Native.ca_proxy_options_defaults(ref Raw, Native.SizeOf<Native.ProxyOptions>()), "ca_proxy_options");
        }
        public ProxyShapes Shapes { get { return (ProxyShapes)Raw.shapes; } set { Raw.shapes = (int)value; } }
        public ProxyMode Mode { get { return (ProxyMode)Raw.mode; } set { Raw.mode = (int)value; } }
        /// <summary>At most this many primitives (at least 1).</summary>
        public uint Count { get { return Raw.count; } set { Raw.count = value; } }
        public uint SurfaceSamples { get { return Raw.surface_samples; } set { Raw.surface_samples = value; } }
        public uint EvaluateSamples { get { return Raw.evaluate_samples; } set { Raw.evaluate_samples = value; } }
        public uint VolumeSamples { get { return Raw.volume_samples; } set { Raw.volume_samples = value; } }
        public ulong Seed { get { return Raw.seed; } set { Raw.seed = value; } }
    }

    /// <summary>A skin over the candidate set's mesh (its bind pose): per joint its parent (-1 for a
    /// root) and optionally its inverse bind matrix (16 doubles, column-major); per vertex
    /// Influences joints and weights. Lengths are checked before the call (Status.InvalidInput).</summary>
    public sealed class Skin
    {
        public int[] Parents;
        public double[] InverseBind;
        public uint Influences;
        public uint[] VertexJoints;
        public double[] VertexWeights;
    }

    /// <summary>Options of Context.BoneColliders, starting from the library's defaults.</summary>
    public sealed class BoneColliderOptions
    {
        internal Native.BoneColliderOptions Raw;
        public BoneColliderOptions()
        {
            Native.CheckDefaults(Native.ca_bone_collider_options_defaults(ref Raw, Native.SizeOf<Native.BoneColliderOptions>()),
                                 "ca_bone_collider_options");
        }
        /// <summary>Conservative (default): each holds its whole part; inscribed: each stays inside.</summary>
        public ProxyMode Mode { get { return (ProxyMode)Raw.mode; } set { Raw.mode = (int)value; } }
        public ProxyShapes Shapes { get { return (ProxyShapes)Raw.shapes; } set { Raw.shapes = (int)value; } }
        public double MinShare { get { return Raw.min_share; } set { Raw.min_share = value; } }
        public double MinSize { get { return Raw.min_size; } set { Raw.min_size = value; } }
        /// <summary>Joints to give no collider.</summary>
        public uint[] SkipJoints;
        public uint SurfaceSamples { get { return Raw.surface_samples; } set { Raw.surface_samples = value; } }
        public uint EvaluateSamples { get { return Raw.evaluate_samples; } set { Raw.evaluate_samples = value; } }
        public ulong Seed { get { return Raw.seed; } set { Raw.seed = value; } }
    }

    public sealed class ProgressEventArgs : EventArgs
    {
        public string Stage { get; internal set; }
        public double Fraction { get; internal set; }
        /// <summary>Set to true to cancel the running call (it throws Status.Cancelled).</summary>
        public bool Cancel { get; set; }
    }

    /// <summary>Runs the three steps; used by one thread at a time. Results outlive it.</summary>
    public sealed class Context : IDisposable
    {
        readonly ContextHandle handle;
        // the delegate the library calls; held here so the GC keeps it while the context lives
        readonly Native.ProgressFn progress;

        /// <summary>Stage name and fraction in [0, 1], raised on the calling thread.</summary>
        public event EventHandler<ProgressEventArgs> Progress;

        /// <param name="threads">worker threads; 0 = all cores, 1 = serial</param>
        /// <param name="progressIntervalSeconds">least time between two Progress events within a stage</param>
        public Context(int threads = 0, double progressIntervalSeconds = 0)
        {
            var desc = new Native.ContextDesc();
            Native.CheckDefaults(Native.ca_context_desc_defaults(ref desc, Native.SizeOf<Native.ContextDesc>()), "ca_context_desc");
            desc.threads = threads;
            desc.progress_interval_s = progressIntervalSeconds;
            progress = OnProgress;
            desc.progress = Marshal.GetFunctionPointerForDelegate(progress);
            var status = Native.ca_context_create(ref desc, out handle);
            if (status != 0)
                throw new CoverageAxisException((Status)status, CoverageAxisException.StatusString((Status)status));
        }

        int OnProgress(IntPtr user, IntPtr stage, double fraction)
        {
            var handler = Progress;
            if (handler == null) return 0;
            var e = new ProgressEventArgs { Stage = Marshal.PtrToStringAnsi(stage), Fraction = fraction };
            try { handler(this, e); }
            catch (Exception) { return 1; } // an exception must not unwind into C: it cancels
            return e.Cancel ? 1 : 0;
        }

        public void Dispose() { handle.Dispose(); }

        /// <summary>Runs a call with the token's cancellation forwarded to the library.</summary>
        // hasResult: whether a failed call still returned its result (Select's time-limited search)
        T Run<T>(CancellationToken token, Func<int> call, Func<T> result, Func<bool> hasResult = null)
        {
            int status;
            using (token.Register(() => Native.ca_context_request_cancel(handle)))
                status = call();
            if (token.IsCancellationRequested) Native.ca_context_clear_cancel(handle);
            if (status == 0) return result();
            var message = Marshal.PtrToStringAnsi(Native.ca_context_last_error(handle));
            if (status == (int)Status.TargetNotReached)  // the failures with a result (Select's)
                throw new TargetNotReachedException(message, (Selection)(object)result());
            if (status == (int)Status.TimeLimit && hasResult != null && hasResult())
                throw new SearchStoppedException(message, (Selection)(object)result());
            if (status == (int)Status.Cancelled && token.IsCancellationRequested)
                throw new OperationCanceledException(message, token);
            throw new CoverageAxisException((Status)status, message);
        }

        /// <summary>Step 1: surface samples and inner candidate balls.</summary>
        public CandidateSet Candidates(Surface surface, CandidateOptions options = null,
                                       CancellationToken token = default(CancellationToken))
        {
            var o = (options ?? new CandidateOptions()).Raw;
            CandidateSetHandle h = null;
            return Run(token, () => surface.With(v => Native.ca_candidates(handle, ref v, ref o, out h)),
                       () => new CandidateSet(h));
        }

        /// <summary>Step 2: the fewest dilated candidate balls that cover every sample. A mask whose
        /// length is not the set's SampleCount (IgnorableSamples) or Count (ForcedIn, ForcedOut)
        /// throws Status.InvalidInput.</summary>
        public Selection Select(CandidateSet set, SelectOptions options = null,
                                CancellationToken token = default(CancellationToken))
        {
            options = options ?? new SelectOptions();
            CheckMask(options.IgnorableSamples, "IgnorableSamples", set.SampleCount, "sample");
            CheckMask(options.ForcedIn, "ForcedIn", set.Count, "candidate ball");
            CheckMask(options.ForcedOut, "ForcedOut", set.Count, "candidate ball");
            var o = options.Raw;
            var pins = new[] { Pinning.Pin(options.IgnorableSamples), Pinning.Pin(options.ForcedIn), Pinning.Pin(options.ForcedOut) };
            try
            {
                o.ignorable_samples = Pinning.Address(pins[0]);
                o.forced_in = Pinning.Address(pins[1]);
                o.forced_out = Pinning.Address(pins[2]);
                o.ignorable_samples_count = (UIntPtr)(options.IgnorableSamples == null ? 0 : options.IgnorableSamples.Length);
                o.forced_in_count = (UIntPtr)(options.ForcedIn == null ? 0 : options.ForcedIn.Length);
                o.forced_out_count = (UIntPtr)(options.ForcedOut == null ? 0 : options.ForcedOut.Length);
                SelectionHandle h = null;
                return Run(token, () => Native.ca_select(handle, set.Handle, ref o, out h), () => new Selection(h),
                           () => h != null && !h.IsInvalid);
            }
            finally
            {
                Pinning.Free(pins);
            }
        }

        static void CheckMask(byte[] mask, string name, int count, string per)
        {
            if (mask != null && mask.Length != count)
                throw new CoverageAxisException(Status.InvalidInput, name + ": " + mask.Length + " entries, the set needs one per " +
                    per + " (" + count + ")");
        }

        /// <summary>Step 3: edges and faces between the selected balls (set: the selection's own).</summary>
        public Skeleton Connect(CandidateSet set, Selection selection, ConnectOptions options = null,
                                CancellationToken token = default(CancellationToken))
        {
            var o = (options ?? new ConnectOptions()).Raw;
            SkeletonHandle h = null;
            return Run(token, () => Native.ca_connect(handle, set.Handle, selection.Handle, ref o, out h),
                       () => new Skeleton(h));
        }

        /// <summary>The three steps with default options.</summary>
        public Skeleton Skeletonize(Surface surface, CancellationToken token = default(CancellationToken))
        {
            using (var set = Candidates(surface, null, token))
            using (var selection = Select(set, null, token))
                return Connect(set, selection, null, token);
        }

        /// <summary>Hausdorff distances between the surface and the skeleton's reconstruction, in % of
        /// the bounding-box diagonal.</summary>
        public Native.Evaluation Evaluate(Surface surface, Skeleton skeleton, EvaluateOptions options = null,
                                          CancellationToken token = default(CancellationToken))
        {
            var o = (options ?? new EvaluateOptions()).Raw;
            var view = ViewOf(skeleton);
            var result = new Native.Evaluation { struct_size = Native.SizeOf<Native.Evaluation>() };
            var done = Run(token, () => surface.With(v => Native.ca_evaluate(handle, ref v, ref view, ref o, ref result)),
                           () => result);
            GC.KeepAlive(skeleton);
            return done;
        }

        Native.SkeletonView ViewOf(Skeleton skeleton)
        {
            var view = new Native.SkeletonView();
            Native.CheckDefaults(Native.ca_skeleton_view_defaults(ref view, Native.SizeOf<Native.SkeletonView>()), "ca_skeleton_view");
            Native.CheckDefaults(Native.ca_skeleton_get_view(skeleton.Handle, ref view), "ca_skeleton_view");
            return view;
        }

        /// <summary>Each surface vertex's nearest skeleton primitive and up to 4 ball weights that sum to 1
        /// (docs/rig.md); smoothing null keeps the library's default.</summary>
        public Correspondence Correspond(Surface surface, Skeleton skeleton, double? smoothing = null,
                                         CancellationToken token = default(CancellationToken))
        {
            var o = new Native.CorrespondenceOptions();
            Native.CheckDefaults(Native.ca_correspondence_options_defaults(ref o, Native.SizeOf<Native.CorrespondenceOptions>()),
                                 "ca_correspondence_options");
            if (smoothing.HasValue) o.smoothing = smoothing.Value;
            var view = ViewOf(skeleton);
            CorrespondenceHandle h = null;
            var done = Run(token, () => surface.With(v => Native.ca_correspond(handle, ref v, ref view, ref o, out h)),
                           () => new Correspondence(h));
            GC.KeepAlive(skeleton);
            return done;
        }

        /// <summary>The skeleton's curve skeleton as a tree of joints and each surface vertex's joint weights.</summary>
        public Rig Rig(Surface surface, Skeleton skeleton, RigOptions options = null,
                       CancellationToken token = default(CancellationToken))
        {
            var o = (options ?? new RigOptions()).Raw;
            var view = ViewOf(skeleton);
            RigHandle h = null;
            var done = Run(token, () => surface.With(v => Native.ca_rig_build(handle, ref v, ref view, ref o, out h)),
                           () => new Rig(h));
            GC.KeepAlive(skeleton);
            return done;
        }

        /// <summary>Engine proxies: at most options.Count spheres, or tapered capsules and spheres,
        /// chosen from the skeleton over the set's mesh (docs/proxies.md).</summary>
        public Proxies Proxies(CandidateSet set, Skeleton skeleton, ProxyOptions options = null,
                               CancellationToken token = default(CancellationToken))
        {
            var o = (options ?? new ProxyOptions()).Raw;
            var view = ViewOf(skeleton);
            ProxySetHandle h = null;
            var done = Run(token, () => Native.ca_proxies(handle, set.Handle, ref view, ref o, out h), () => new Proxies(h));
            GC.KeepAlive(skeleton);
            return done;
        }

        /// <summary>A tapered capsule or sphere per joint of the skin, fitted to the part of the set's
        /// mesh the joint dominates, in the joint's frame (docs/bone_colliders.md).</summary>
        public BoneColliders BoneColliders(CandidateSet set, Skin skin, BoneColliderOptions options = null,
                                           CancellationToken token = default(CancellationToken))
        {
            options = options ?? new BoneColliderOptions();
            int k = (int)skin.Influences;
            if (skin.Parents == null || skin.VertexJoints == null || skin.VertexWeights == null || k == 0 ||
                skin.VertexJoints.Length % k != 0 || skin.VertexWeights.Length != skin.VertexJoints.Length ||
                (skin.InverseBind != null && skin.InverseBind.Length != 16 * skin.Parents.Length))
                throw new CoverageAxisException(Status.InvalidInput,
                    "skin: Parents, VertexJoints and VertexWeights (Influences >= 1 per vertex) and 16 InverseBind values per joint");
            var o = options.Raw;
            var pins = new[] { Pinning.Pin(skin.Parents), Pinning.Pin(skin.InverseBind), Pinning.Pin(skin.VertexJoints),
                               Pinning.Pin(skin.VertexWeights), Pinning.Pin(options.SkipJoints) };
            try
            {
                var view = new Native.SkinView();
                Native.CheckDefaults(Native.ca_skin_view_defaults(ref view, Native.SizeOf<Native.SkinView>()), "ca_skin_view");
                view.joint_count = (UIntPtr)skin.Parents.Length;
                view.parents = Pinning.Address(pins[0]);
                view.inverse_bind = Pinning.Address(pins[1]);
                view.vertex_count = (UIntPtr)(skin.VertexJoints.Length / k);
                view.influences = skin.Influences;
                view.vertex_joints = Pinning.Address(pins[2]);
                view.vertex_weights = Pinning.Address(pins[3]);
                o.skip_joints = Pinning.Address(pins[4]);
                o.skip_count = (UIntPtr)(options.SkipJoints == null ? 0 : options.SkipJoints.Length);
                BoneCollidersHandle h = null;
                return Run(token, () => Native.ca_bone_colliders_build(handle, set.Handle, IntPtr.Zero, ref view, ref o, out h),
                           () => new BoneColliders(h));
            }
            finally
            {
                Pinning.Free(pins);
            }
        }
    }

    /// <summary>A result owning its C object through a SafeHandle; Dispose frees it (or the GC does).</summary>
    public abstract class OwnedResult<THandle> : IDisposable where THandle : OwnedHandle
    {
        internal readonly THandle Handle;
        internal OwnedResult(THandle h) { Handle = h; }
        public void Dispose() { Handle.Dispose(); }
    }

    /// <summary>Copies getter arrays out of the C objects.</summary>
    static class Copy
    {
        public static double[] Doubles(IntPtr p, ulong n)
        {
            var a = new double[n];
            if (n > 0) Marshal.Copy(p, a, 0, (int)n);
            return a;
        }
        public static uint[] UInts(IntPtr p, ulong n)
        {
            var tmp = new int[n];
            if (n > 0) Marshal.Copy(p, tmp, 0, (int)n);
            var a = new uint[n];
            Buffer.BlockCopy(tmp, 0, a, 0, tmp.Length * 4);
            return a;
        }
    }

    /// <summary>Samples and candidate balls (step 1). Selections keep the C object alive, so it
    /// may be disposed before them.</summary>
    public sealed class CandidateSet : OwnedResult<CandidateSetHandle>
    {
        internal CandidateSet(CandidateSetHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_candidate_set_count(Handle); } }
        /// <summary>The surface samples to cover.</summary>
        public int SampleCount { get { return (int)Native.ca_candidate_set_sample_count(Handle); } }
        /// <summary>x y z per ball.</summary>
        public double[] Centers { get { return Copy.Doubles(Native.ca_candidate_set_centers(Handle), 3 * (ulong)Count); } }
        public double[] Radii { get { return Copy.Doubles(Native.ca_candidate_set_radii(Handle), (ulong)Count); } }
        /// <summary>x y z per surface sample.</summary>
        public double[] Samples
        {
            get { return Copy.Doubles(Native.ca_candidate_set_samples(Handle), 3 * (ulong)Native.ca_candidate_set_sample_count(Handle)); }
        }
        public double ReferenceLength { get { return Native.ca_candidate_set_reference_length(Handle); } }
        public bool Flipped { get { return Native.ca_candidate_set_flipped(Handle) != 0; } }
        /// <summary>Point clouds: points dropped as outliers.</summary>
        public ulong Outliers { get { return Native.ca_candidate_set_outlier_count(Handle); } }
    }

    /// <summary>Balls chosen by step 2; outlives its candidate set and context.</summary>
    public sealed class Selection : OwnedResult<SelectionHandle>
    {
        internal Selection(SelectionHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_selection_count(Handle); } }
        /// <summary>Indices into the candidate set.</summary>
        public uint[] Indices { get { return Copy.UInts(Native.ca_selection_indices(Handle), (ulong)Count); } }
        public double[] Centers { get { return Copy.Doubles(Native.ca_selection_centers(Handle), 3 * (ulong)Count); } }
        public double[] Radii { get { return Copy.Doubles(Native.ca_selection_radii(Handle), (ulong)Count); } }
        public double[] DilatedRadii { get { return Copy.Doubles(Native.ca_selection_dilated_radii(Handle), (ulong)Count); } }
        public uint[] Uncovered
        {
            get { return Copy.UInts(Native.ca_selection_uncovered(Handle), (ulong)Native.ca_selection_uncovered_count(Handle)); }
        }
        public Native.SelectStats Stats
        {
            get
            {
                var s = new Native.SelectStats { struct_size = Native.SizeOf<Native.SelectStats>() };
                Native.CheckDefaults(Native.ca_selection_stats(Handle, ref s), "ca_select_stats");
                return s;
            }
        }
    }

    /// <summary>The medial skeleton (step 3); holds nothing of the other objects.</summary>
    public sealed class Skeleton : OwnedResult<SkeletonHandle>
    {
        internal Skeleton(SkeletonHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_skeleton_vertex_count(Handle); } }
        public double[] Centers { get { return Copy.Doubles(Native.ca_skeleton_centers(Handle), 3 * (ulong)Count); } }
        public double[] Radii { get { return Copy.Doubles(Native.ca_skeleton_radii(Handle), (ulong)Count); } }
        /// <summary>i j per edge, including the faces' edges.</summary>
        public uint[] Edges { get { return Copy.UInts(Native.ca_skeleton_edges(Handle), 2 * (ulong)Native.ca_skeleton_edge_count(Handle)); } }
        /// <summary>i j k per face.</summary>
        public uint[] Faces { get { return Copy.UInts(Native.ca_skeleton_faces(Handle), 3 * (ulong)Native.ca_skeleton_face_count(Handle)); } }
        public Native.SkeletonStats Stats
        {
            get
            {
                var s = new Native.SkeletonStats { struct_size = Native.SizeOf<Native.SkeletonStats>() };
                Native.CheckDefaults(Native.ca_skeleton_stats_get(Handle, ref s), "ca_skeleton_stats");
                return s;
            }
        }
    }

    /// <summary>Per surface vertex: 4 balls and weights (decreasing, sum 1; an unused slot has weight 0
    /// and repeats the first ball) and the nearest primitive (0 ball, 1 edge, 2 face; an index into the
    /// skeleton's balls, edges or faces).</summary>
    public sealed class Correspondence : OwnedResult<CorrespondenceHandle>
    {
        internal Correspondence(CorrespondenceHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_correspondence_vertex_count(Handle); } }
        public uint[] Balls { get { return Copy.UInts(Native.ca_correspondence_balls(Handle), 4 * (ulong)Count); } }
        public double[] Weights { get { return Copy.Doubles(Native.ca_correspondence_weights(Handle), 4 * (ulong)Count); } }
        public uint[] NearestKinds { get { return Copy.UInts(Native.ca_correspondence_nearest_kinds(Handle), (ulong)Count); } }
        public uint[] NearestIndices { get { return Copy.UInts(Native.ca_correspondence_nearest_indices(Handle), (ulong)Count); } }
    }

    /// <summary>A tree of joints (parents before children; joint 0 the root, parent -1) and per
    /// surface vertex 4 joints and weights (decreasing, sum 1).</summary>
    public sealed class Rig : OwnedResult<RigHandle>
    {
        internal Rig(RigHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_rig_joint_count(Handle); } }
        public int BranchCount { get { return (int)Native.ca_rig_branch_count(Handle); } }
        public int VertexCount { get { return (int)Native.ca_rig_vertex_count(Handle); } }
        /// <summary>x y z per joint.</summary>
        public double[] Positions { get { return Copy.Doubles(Native.ca_rig_joint_positions(Handle), 3 * (ulong)Count); } }
        public int[] Parents
        {
            get
            {
                var a = new int[Count];
                if (a.Length > 0) Marshal.Copy(Native.ca_rig_joint_parents(Handle), a, 0, a.Length);
                return a;
            }
        }
        public uint[] Joints { get { return Copy.UInts(Native.ca_rig_vertex_joints(Handle), 4 * (ulong)VertexCount); } }
        public double[] Weights { get { return Copy.Doubles(Native.ca_rig_vertex_weights(Handle), 4 * (ulong)VertexCount); } }
        public uint[] Branches { get { return Copy.UInts(Native.ca_rig_vertex_branches(Handle), (ulong)VertexCount); } }
    }

    /// <summary>Engine proxies (Context.Proxies); they hold nothing of the other objects.</summary>
    public sealed class Proxies : OwnedResult<ProxySetHandle>
    {
        internal Proxies(ProxySetHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_proxy_set_count(Handle); } }
        /// <summary>Per primitive: true for a tapered capsule, false for a sphere.</summary>
        public bool[] IsCapsule
        {
            get
            {
                var k = new int[Count];
                if (k.Length > 0) Marshal.Copy(Native.ca_proxy_set_kinds(Handle), k, 0, k.Length);
                return Array.ConvertAll(k, x => x == 1);
            }
        }
        /// <summary>Ball a then ball b, x y z each: 6 per primitive (a sphere's b is its a).</summary>
        public double[] Centers { get { return Copy.Doubles(Native.ca_proxy_set_centers(Handle), 6 * (ulong)Count); } }
        /// <summary>Radius of a, of b: 2 per primitive.</summary>
        public double[] Radii { get { return Copy.Doubles(Native.ca_proxy_set_radii(Handle), 2 * (ulong)Count); } }
        public Native.ProxyStats Stats
        {
            get
            {
                var s = new Native.ProxyStats { struct_size = Native.SizeOf<Native.ProxyStats>() };
                Native.CheckDefaults(Native.ca_proxy_set_stats(Handle, ref s), "ca_proxy_stats");
                return s;
            }
        }
    }

    /// <summary>One bone collider as an engine places it under its joint (the joint's frame): a node
    /// at Center turned by Rotation (x y z w) holding a sphere of RadiusTop, or a capsule along its
    /// +Y axis (Axis in the joint's frame), the ball of RadiusTop at +Height/2 and of RadiusBottom
    /// at -Height/2.</summary>
    public sealed class BoneCollider
    {
        public uint Joint;
        public bool IsCapsule;
        public double[] Center, Rotation, Axis;
        public double RadiusTop, RadiusBottom, Height;
    }

    /// <summary>Bone colliders (Context.BoneColliders), each in its joint's frame; they hold nothing
    /// of the other objects.</summary>
    public sealed class BoneColliders : OwnedResult<BoneCollidersHandle>
    {
        internal BoneColliders(BoneCollidersHandle h) : base(h) { }
        public int Count { get { return (int)Native.ca_bone_colliders_count(Handle); } }
        /// <summary>The joint of each collider, ascending.</summary>
        public uint[] Joints { get { return Copy.UInts(Native.ca_bone_colliders_joints(Handle), (ulong)Count); } }
        /// <summary>Per collider: the fraction of its part's fresh samples it holds.</summary>
        public double[] Contained { get { return Copy.Doubles(Native.ca_bone_colliders_contained(Handle), (ulong)Count); } }
        /// <summary>Per collider: its overlap volume with its parent joint's collider.</summary>
        public double[] Overlap { get { return Copy.Doubles(Native.ca_bone_colliders_overlap(Handle), (ulong)Count); } }
        /// <summary>Collider i as an engine places it under its joint (ca_proxy_placement's conventions).</summary>
        public Native.ProxyPlacement Placement(int i)
        {
            var p = new Native.ProxyPlacement { struct_size = Native.SizeOf<Native.ProxyPlacement>() };
            int status = Native.ca_bone_colliders_placement(Handle, (UIntPtr)i, ref p);
            if (status != 0) throw new CoverageAxisException((Status)status, "ca_bone_colliders_placement: index " + i);
            return p;
        }
        /// <summary>Every collider's placement, with its joint.</summary>
        public unsafe BoneCollider[] Colliders
        {
            get
            {
                var joints = Joints;
                var all = new BoneCollider[joints.Length];
                for (int i = 0; i < all.Length; ++i)
                {
                    var p = Placement(i);
                    all[i] = new BoneCollider {
                        Joint = joints[i], IsCapsule = p.kind == 1,
                        Center = new[] { p.center[0], p.center[1], p.center[2] },
                        Rotation = new[] { p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3] },
                        Axis = new[] { p.axis[0], p.axis[1], p.axis[2] },
                        RadiusTop = p.radius_top, RadiusBottom = p.radius_bottom, Height = p.height };
                }
                return all;
            }
        }
        public Native.BoneColliderStats Stats
        {
            get
            {
                var s = new Native.BoneColliderStats { struct_size = Native.SizeOf<Native.BoneColliderStats>() };
                Native.CheckDefaults(Native.ca_bone_colliders_stats(Handle, ref s), "ca_bone_collider_stats");
                return s;
            }
        }
    }
}
