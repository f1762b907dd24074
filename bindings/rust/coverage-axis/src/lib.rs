//! coverage-axis: a safe Rust API over the coverage-axis C library (Coverage Axis medial
//! skeletons, Dou et al., EG 2022). Three steps, each a method of [`Context`]:
//! [`Context::candidates`] (surface -> samples + inner candidate balls), [`Context::select`]
//! (fewest dilated balls covering the samples), [`Context::connect`] (edges and faces between
//! them). Results own their C objects (freed on drop), are `Send + Sync`, outlive their context,
//! and lend their arrays as slices borrowed from themselves. Options start from the library's
//! own defaults (`ca_*_defaults`) and change through builder methods.
//!
//! ```no_run
//! use coverage_axis::*;
//! # fn main() -> Result<()> {
//! let v: Vec<[f64; 3]> = vec![/* x y z per vertex */];
//! let f: Vec<[u32; 3]> = vec![/* 0-based i j k per triangle */];
//! let ctx = Context::builder().threads(0).progress(|stage, t| { eprintln!("{} {:.0}%", stage, 100.0 * t); true }).build()?;
//! let surface = Surface::mesh(&v, &f);
//! let set = ctx.candidates(&surface, &CandidateOptions::new().cover_samples(1500))?;
//! let selection = ctx.select(&set, &SelectOptions::new().dilation(Dilation::Offset(0.02)))?;
//! let skeleton = ctx.connect(&set, &selection, &ConnectOptions::default())?;
//! for (c, r) in skeleton.centers().iter().zip(skeleton.radii()) { println!("{:?} {}", c, r); }
//! println!("{} edges, {} faces", skeleton.edges().len(), skeleton.faces().len());
//! # Ok(())
//! # }
//! ```
use coverage_axis_sys as sys;
use std::ffi::CStr;
use std::fmt;
use std::marker::PhantomData;
use std::os::raw::{c_char, c_void};
use std::ptr;
use std::sync::Arc;

pub use sys::{ca_bone_collider_stats as BoneColliderStats, ca_evaluation as Evaluation, ca_proxy_stats as ProxyStats,
              ca_select_stats as SelectStats, ca_skeleton_stats as SkeletonStats};

/// Why a call failed: the library's `ca_status` codes (`CA_ERROR_*`, pinned values) as an enum.
/// `Unknown` keeps a code this crate does not name (a newer library's).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Status {
    /// An option is out of range.
    InvalidArgument,
    /// A required pointer is NULL.
    NullPointer,
    /// A struct_size this library does not know.
    StructSize,
    /// NaN/Inf coordinate, out-of-range index, bad normal, an array whose length does not match.
    InvalidInput,
    /// Empty, zero area, too few distinct points, coplanar.
    DegenerateInput,
    /// Some samples are covered by no candidate ball.
    Uncoverable,
    /// The Delaunay / power diagram (Qhull) failed.
    Geometry,
    /// The set-cover solver (CBC) failed.
    Solver,
    /// The progress closure or a cancel request stopped the call.
    Cancelled,
    OutOfMemory,
    BufferTooSmall,
    /// A bug: please report it with the input.
    Internal,
    /// No inner candidate ball was found.
    NoCandidates,
    /// The context's time limit ran out.
    TimeLimit,
    /// `target_error` was not reached (`Context::select_best` still returns the best selection).
    TargetNotReached,
    Unknown(i32),
}

impl Status {
    /// The status of a `ca_status` code (not `CA_OK`, which is no error).
    pub fn from_code(code: i32) -> Status {
        match code {
            sys::CA_ERROR_INVALID_ARGUMENT => Status::InvalidArgument,
            sys::CA_ERROR_NULL_POINTER => Status::NullPointer,
            sys::CA_ERROR_STRUCT_SIZE => Status::StructSize,
            sys::CA_ERROR_INVALID_INPUT => Status::InvalidInput,
            sys::CA_ERROR_DEGENERATE_INPUT => Status::DegenerateInput,
            sys::CA_ERROR_UNCOVERABLE => Status::Uncoverable,
            sys::CA_ERROR_GEOMETRY => Status::Geometry,
            sys::CA_ERROR_SOLVER => Status::Solver,
            sys::CA_ERROR_CANCELLED => Status::Cancelled,
            sys::CA_ERROR_OUT_OF_MEMORY => Status::OutOfMemory,
            sys::CA_ERROR_BUFFER_TOO_SMALL => Status::BufferTooSmall,
            sys::CA_ERROR_INTERNAL => Status::Internal,
            sys::CA_ERROR_NO_CANDIDATES => Status::NoCandidates,
            sys::CA_ERROR_TIME_LIMIT => Status::TimeLimit,
            sys::CA_ERROR_TARGET_NOT_REACHED => Status::TargetNotReached,
            other => Status::Unknown(other),
        }
    }

    /// The `ca_status` code.
    pub fn code(self) -> i32 {
        match self {
            Status::InvalidArgument => sys::CA_ERROR_INVALID_ARGUMENT,
            Status::NullPointer => sys::CA_ERROR_NULL_POINTER,
            Status::StructSize => sys::CA_ERROR_STRUCT_SIZE,
            Status::InvalidInput => sys::CA_ERROR_INVALID_INPUT,
            Status::DegenerateInput => sys::CA_ERROR_DEGENERATE_INPUT,
            Status::Uncoverable => sys::CA_ERROR_UNCOVERABLE,
            Status::Geometry => sys::CA_ERROR_GEOMETRY,
            Status::Solver => sys::CA_ERROR_SOLVER,
            Status::Cancelled => sys::CA_ERROR_CANCELLED,
            Status::OutOfMemory => sys::CA_ERROR_OUT_OF_MEMORY,
            Status::BufferTooSmall => sys::CA_ERROR_BUFFER_TOO_SMALL,
            Status::Internal => sys::CA_ERROR_INTERNAL,
            Status::NoCandidates => sys::CA_ERROR_NO_CANDIDATES,
            Status::TimeLimit => sys::CA_ERROR_TIME_LIMIT,
            Status::TargetNotReached => sys::CA_ERROR_TARGET_NOT_REACHED,
            Status::Unknown(code) => code,
        }
    }
}

/// A failed call: the library's status and its message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    pub status: Status,
    pub message: String,
}

impl Error {
    fn new(status: Status, message: String) -> Error {
        Error { status, message }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.message, status_string(self.status.code()))
    }
}

impl std::error::Error for Error {}

pub type Result<T> = std::result::Result<T, Error>;

/// The library's static name of a status, e.g. "CA_ERROR_NULL_POINTER: a required pointer is NULL".
pub fn status_string(status: i32) -> String {
    // SAFETY: ca_status_string returns a static NUL-terminated string for any value
    unsafe { cstr(sys::ca_status_string(status)) }
}

/// The linked library's version number (major * 10000 + minor * 100 + patch).
pub fn version() -> u32 {
    unsafe { sys::ca_version() }
}

unsafe fn cstr(p: *const c_char) -> String {
    if p.is_null() {
        String::new()
    } else {
        CStr::from_ptr(p).to_string_lossy().into_owned()
    }
}

/// A status without a context: the message is the status's name.
fn check(status: i32) -> Result<()> {
    if status == sys::CA_OK {
        Ok(())
    } else {
        Err(Error::new(Status::from_code(status), status_string(status)))
    }
}

/// A slice of `count` items of `N` values each from a getter pointer (empty: not read).
unsafe fn items<'a, T, const N: usize>(p: *const T, count: usize) -> &'a [[T; N]] {
    if count == 0 || p.is_null() {
        &[]
    } else {
        std::slice::from_raw_parts(p as *const [T; N], count)
    }
}

unsafe fn values<'a, T>(p: *const T, count: usize) -> &'a [T] {
    if count == 0 || p.is_null() {
        &[]
    } else {
        std::slice::from_raw_parts(p, count)
    }
}

/// Fills a struct with the library's defaults for this crate's layout of it.
macro_rules! defaults {
    ($ty:ty, $fn:path) => {{
        let mut raw = std::mem::MaybeUninit::<$ty>::zeroed();
        // SAFETY: the library writes at most size_of::<$ty>() bytes (the size passed)
        let status = unsafe { $fn(raw.as_mut_ptr(), std::mem::size_of::<$ty>() as u32) };
        assert_eq!(status, sys::CA_OK, "the linked library does not know this crate's {} (ABI {})",
                   stringify!($ty), sys::CA_ABI_VERSION);
        unsafe { raw.assume_init() }
    }};
}

/// An options type over the C struct `$c`: `default()` and `new()` give the library's defaults
/// (`$defaults`), `raw()` the C struct for reading the values; builder methods are added beside.
macro_rules! options_type {
    ($(#[$doc:meta])* $name:ident, $c:ty, $defaults:path) => {
        $(#[$doc])*
        #[derive(Clone, Copy)]
        pub struct $name {
            raw: $c,
        }

        impl Default for $name {
            fn default() -> Self {
                $name { raw: defaults!($c, $defaults) }
            }
        }

        impl $name {
            pub fn new() -> Self {
                Self::default()
            }
            /// The C struct, for reading the values.
            pub fn raw(&self) -> &$c {
                &self.raw
            }
        }
    };
}

/// A result type owning its C object: freed on drop, `Send + Sync`, with `len` (the getter
/// `$count`) and `is_empty`.
macro_rules! owned_result {
    ($(#[$doc:meta])* $name:ident, $c:ty, $destroy:path, $count:path) => {
        $(#[$doc])*
        pub struct $name {
            raw: *mut $c,
        }

        // SAFETY: results are immutable and may be read from several threads at once (docs/abi.md).
        unsafe impl Send for $name {}
        unsafe impl Sync for $name {}

        impl Drop for $name {
            fn drop(&mut self) {
                unsafe { $destroy(self.raw) }
            }
        }

        impl $name {
            pub fn len(&self) -> usize {
                unsafe { $count(self.raw) }
            }
            pub fn is_empty(&self) -> bool {
                self.len() == 0
            }
        }
    };
}

/// An output struct of this crate's layout (struct_size set) filled by `$getter(raw, extra..., &mut out)`
/// of a live result, which cannot fail but for a bug.
macro_rules! read_out {
    ($ty:ty, $getter:path, $raw:expr $(, $extra:expr)*) => {{
        let mut out = <$ty>::default();
        out.struct_size = std::mem::size_of::<$ty>() as u32;
        check(unsafe { $getter($raw $(, $extra)*, &mut out) }).expect(stringify!($getter));
        out
    }};
}

/// Builder methods that set the option field of the same name: `name: T` as given, or
/// `name: T => C` converted with `as C` (bools and enums to the C ints).
macro_rules! setters {
    ($($(#[$doc:meta])* $name:ident: $ty:ty $(=> $c:ty)?;)*) => {
        $(
            $(#[$doc])*
            pub fn $name(mut self, value: $ty) -> Self {
                self.raw.$name = value $(as $c)?;
                self
            }
        )*
    };
}

// ---- surface ---------------------------------------------------------------------------------

/// A borrowed input surface: a triangle mesh, or an oriented point cloud (one outward normal per
/// point). It is read during a call only.
#[derive(Clone, Copy)]
pub struct Surface<'a> {
    raw: sys::ca_surface_view,
    _data: PhantomData<&'a [f64]>,
}

impl<'a> Surface<'a> {
    /// A triangle mesh: x y z per vertex, 0-based i j k per triangle.
    pub fn mesh(positions: &'a [[f64; 3]], triangles: &'a [[u32; 3]]) -> Surface<'a> {
        let mut raw: sys::ca_surface_view = defaults!(sys::ca_surface_view, sys::ca_surface_view_defaults);
        raw.positions = positions.as_ptr() as *const f64;
        raw.vertex_count = positions.len();
        raw.triangles = triangles.as_ptr() as *const u32;
        raw.triangle_count = triangles.len();
        Surface { raw, _data: PhantomData }
    }

    /// A point cloud: positions and one normal per point, or no normals (an empty slice: estimated
    /// by the library). Normals of another length are `Status::InvalidInput`.
    pub fn points(positions: &'a [[f64; 3]], normals: &'a [[f64; 3]]) -> Result<Surface<'a>> {
        if !normals.is_empty() && normals.len() != positions.len() {
            return Err(Error::new(Status::InvalidInput,
                                  format!("{} normals for {} points (one per point, or none)", normals.len(),
                                          positions.len())));
        }
        let mut raw: sys::ca_surface_view = defaults!(sys::ca_surface_view, sys::ca_surface_view_defaults);
        raw.positions = positions.as_ptr() as *const f64;
        raw.vertex_count = positions.len();
        if !normals.is_empty() {
            raw.normals = normals.as_ptr() as *const f64;
            raw.normal_count = normals.len();
        }
        Ok(Surface { raw, _data: PhantomData })
    }
}

// ---- options ---------------------------------------------------------------------------------

/// Generator of the candidate balls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Generator {
    Voronoi = sys::CA_CANDIDATES_VORONOI as isize,
    Random = sys::CA_CANDIDATES_RANDOM as isize,
}

/// How the selected balls are dilated before covering the samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dilation {
    /// r' = r + delta * reference length (delta a fraction of the longest bbox side)
    Offset(f64),
    /// r' = r * scale
    Scale(f64),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Solver {
    Exact = sys::CA_SOLVER_EXACT as isize,
    Greedy = sys::CA_SOLVER_GREEDY as isize,
    Capp = sys::CA_SOLVER_CAPP as isize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Effort {
    Fast = sys::CA_EFFORT_FAST as isize,
    Prove = sys::CA_EFFORT_PROVE as isize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConnectMethod {
    Power = sys::CA_CONNECT_POWER as isize,
    Medial = sys::CA_CONNECT_MEDIAL as isize,
    Auto = sys::CA_CONNECT_AUTO as isize,
}

options_type!(
    /// Options of [`Context::candidates`]; `default()` is the library's defaults.
    CandidateOptions, sys::ca_candidate_options, sys::ca_candidate_options_defaults
);

impl CandidateOptions {
    setters! {
        generator: Generator => i32;
        /// |S|, the surface samples to cover.
        cover_samples: u32;
        voronoi_samples: u32;
        random_candidates: u32;
        seed: u64;
        connect_samples: u32;
    }
}

/// Options of [`Context::select`]; `default()` is the library's defaults. The masks are borrowed
/// until the call.
#[derive(Clone, Copy)]
pub struct SelectOptions<'a> {
    raw: sys::ca_select_options,
    _masks: PhantomData<&'a [u8]>,
}

impl<'a> Default for SelectOptions<'a> {
    fn default() -> Self {
        SelectOptions { raw: defaults!(sys::ca_select_options, sys::ca_select_options_defaults), _masks: PhantomData }
    }
}

fn mask(m: Option<&[u8]>) -> *const u8 {
    m.map_or(ptr::null(), |m| m.as_ptr())
}

impl<'a> SelectOptions<'a> {
    pub fn new() -> Self {
        Self::default()
    }
    pub fn dilation(mut self, dilation: Dilation) -> Self {
        match dilation {
            Dilation::Offset(delta) => {
                self.raw.dilation = sys::CA_DILATE_OFFSET;
                self.raw.delta = delta;
            }
            Dilation::Scale(scale) => {
                self.raw.dilation = sys::CA_DILATE_SCALE;
                self.raw.scale = scale;
            }
        }
        self
    }
    setters! {
        solver: Solver => i32;
        effort: Effort => i32;
        /// Exact solver wall-clock budget in seconds; <= 0: no limit.
        time_limit_s: f64;
        skip_uncoverable: bool => i32;
        /// At most this many balls with the smallest dilation achieving it (0 = off).
        target_count: u32;
        target_tolerance: f64;
        /// The fewest balls whose two-sided Hausdorff distance is at most this percent of the bbox
        /// diagonal, by a search over delta (0 = off); the stats' `hd_reached` gives the HD.
        target_error: f64;
        divide_threshold: u32;
    }
    /// One entry per sample; non-zero: need not be covered. [`Context::select`] checks the lengths.
    pub fn ignorable_samples(mut self, m: Option<&'a [u8]>) -> Self {
        self.raw.ignorable_samples = mask(m);
        self.raw.ignorable_samples_count = m.map_or(0, |m| m.len());
        self
    }
    /// One entry per candidate ball; non-zero: must be selected.
    pub fn forced_in(mut self, m: Option<&'a [u8]>) -> Self {
        self.raw.forced_in = mask(m);
        self.raw.forced_in_count = m.map_or(0, |m| m.len());
        self
    }
    /// One entry per candidate ball; non-zero: must not be selected.
    pub fn forced_out(mut self, m: Option<&'a [u8]>) -> Self {
        self.raw.forced_out = mask(m);
        self.raw.forced_out_count = m.map_or(0, |m| m.len());
        self
    }
    pub fn raw(&self) -> &sys::ca_select_options {
        &self.raw
    }
}

options_type!(
    /// Options of [`Context::connect`]; `default()` is the library's defaults.
    ConnectOptions, sys::ca_connect_options, sys::ca_connect_options_defaults
);

impl ConnectOptions {
    setters! {
        method: ConnectMethod => i32;
        remove_outside: bool => i32;
        fill_holes: bool => i32;
        reconnect: bool => i32;
    }
}

options_type!(
    /// Options of `Context::rig` (ca_rig_options; docs/rig.md); the library's defaults.
    RigOptions, sys::ca_rig_options, sys::ca_rig_options_defaults
);

impl RigOptions {
    setters! {
        /// The root joint's ball; -1: the largest ball.
        root: i64;
        max_joints: u32;
        joint_spacing: f64;
        min_branch: f64;
        smoothing: f64;
    }
}

options_type!(
    /// Options of [`Context::evaluate`]; `default()` is the library's defaults.
    EvaluateOptions, sys::ca_evaluate_options, sys::ca_evaluate_options_defaults
);

impl EvaluateOptions {
    setters! {
        surface_samples: u32;
        envelope_samples: u32;
        seed: u64;
    }
}

/// A skin over the candidate set's mesh (its bind pose): per joint its parent (-1 for a root) and
/// optionally its inverse bind matrix (16 doubles, column-major, the surface's frame to the
/// joint's); per vertex `influences` joints and weights (`vertex_joints`, `vertex_weights`, flat).
#[derive(Clone, Copy)]
pub struct Skin<'a> {
    pub parents: &'a [i32],
    pub inverse_bind: Option<&'a [[f64; 16]]>,
    pub influences: u32,
    pub vertex_joints: &'a [u32],
    pub vertex_weights: &'a [f64],
}

/// Options of [`Context::bone_colliders`]; `default()` is the library's defaults.
#[derive(Clone)]
pub struct BoneColliderOptions {
    raw: sys::ca_bone_collider_options,
    skip: Vec<u32>,
}

impl Default for BoneColliderOptions {
    fn default() -> Self {
        BoneColliderOptions {
            raw: defaults!(sys::ca_bone_collider_options, sys::ca_bone_collider_options_defaults),
            skip: Vec::new(),
        }
    }
}

impl BoneColliderOptions {
    pub fn new() -> Self {
        Self::default()
    }
    setters! {
        /// Conservative (default): each holds its whole part; inscribed: each stays inside the shape.
        mode: ProxyMode => i32;
        shapes: ProxyShapes => i32;
        /// A joint dominating less than this fraction of the surface's area gets no collider.
        min_share: f64;
        /// A collider whose larger radius is below this percent of the bbox diagonal is dropped.
        min_size: f64;
        surface_samples: u32;
        evaluate_samples: u32;
        seed: u64;
    }
    /// Joints to give no collider.
    pub fn skip_joints(mut self, joints: &[u32]) -> Self {
        self.skip = joints.to_vec();
        self
    }
}

/// What engine proxies may be: spheres only, or tapered capsules and spheres.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProxyShapes {
    Spheres = sys::CA_PROXY_SHAPES_SPHERES as isize,
    Capsules = sys::CA_PROXY_SHAPES_CAPSULES as isize,
}

/// Inscribed proxies stay inside the shape; conservative ones contain the whole surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProxyMode {
    Inscribed = sys::CA_PROXY_INSCRIBED as isize,
    Conservative = sys::CA_PROXY_CONSERVATIVE as isize,
}

options_type!(
    /// Options of [`Context::proxies`]; `default()` is the library's defaults.
    ProxyOptions, sys::ca_proxy_options, sys::ca_proxy_options_defaults
);

impl ProxyOptions {
    setters! {
        shapes: ProxyShapes => i32;
        mode: ProxyMode => i32;
        /// At most this many primitives (>= 1).
        count: u32;
        surface_samples: u32;
        evaluate_samples: u32;
        volume_samples: u32;
        seed: u64;
    }
}

// ---- context ---------------------------------------------------------------------------------

type ProgressFn = dyn FnMut(&str, f64) -> bool + Send;
type LogFn = dyn FnMut(i32, &str) + Send;

/// The closures a context calls back; boxed so their address stays fixed.
#[derive(Default)]
struct Callbacks {
    progress: Option<Box<ProgressFn>>,
    log: Option<Box<LogFn>>,
}

unsafe extern "C" fn progress_trampoline(user: *mut c_void, stage: *const c_char, fraction: f64) -> i32 {
    let callbacks = &mut *(user as *mut Callbacks);
    let stage = cstr(stage);
    match callbacks.progress.as_mut() {
        // a panic must not unwind into C: it cancels the call instead
        Some(f) => match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| f(&stage, fraction))) {
            Ok(true) => 0,
            _ => 1,
        },
        None => 0,
    }
}

unsafe extern "C" fn log_trampoline(user: *mut c_void, level: i32, message: *const c_char) {
    let callbacks = &mut *(user as *mut Callbacks);
    let message = cstr(message);
    if let Some(f) = callbacks.log.as_mut() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| f(level, &message)));
    }
}

/// The C context, shared by the [`Context`] and its [`CancelHandle`]s; freed with the last.
struct RawContext(*mut sys::ca_context);

// SAFETY: the only call made through a shared RawContext from other threads is
// ca_context_request_cancel, which the library allows from any thread.
unsafe impl Send for RawContext {}
unsafe impl Sync for RawContext {}

impl Drop for RawContext {
    fn drop(&mut self) {
        unsafe { sys::ca_context_destroy(self.0) }
    }
}

/// Builds a [`Context`]: threads, progress closure, log closure, progress interval.
pub struct ContextBuilder {
    desc: sys::ca_context_desc,
    callbacks: Callbacks,
}

impl ContextBuilder {
    /// Worker threads of the parallel stages: 0 = all cores (the default), 1 = serial.
    pub fn threads(mut self, threads: i32) -> Self {
        self.desc.threads = threads;
        self
    }
    /// Least time between two progress calls within a stage (default 0: every update).
    pub fn progress_interval_s(mut self, seconds: f64) -> Self {
        self.desc.progress_interval_s = seconds;
        self
    }
    /// Called on the calling thread with a stage name and a fraction in [0, 1]; return false to
    /// cancel the running call (it fails with CA_ERROR_CANCELLED).
    pub fn progress<F: FnMut(&str, f64) -> bool + Send + 'static>(mut self, f: F) -> Self {
        self.callbacks.progress = Some(Box::new(f));
        self
    }
    /// Log messages: level 0 debug, 1 info, 2 warning.
    pub fn log<F: FnMut(i32, &str) + Send + 'static>(mut self, f: F) -> Self {
        self.callbacks.log = Some(Box::new(f));
        self
    }
    pub fn build(self) -> Result<Context> {
        let mut desc = self.desc;
        let callbacks = Box::into_raw(Box::new(self.callbacks));
        // SAFETY: callbacks stays valid until Context::drop, after the last call that uses it
        unsafe {
            if (*callbacks).progress.is_some() {
                desc.progress = Some(progress_trampoline);
                desc.progress_user = callbacks as *mut c_void;
            }
            if (*callbacks).log.is_some() {
                desc.log = Some(log_trampoline);
                desc.log_user = callbacks as *mut c_void;
            }
        }
        let mut raw = ptr::null_mut();
        let status = unsafe { sys::ca_context_create(&desc, &mut raw) };
        if status != sys::CA_OK {
            drop(unsafe { Box::from_raw(callbacks) });
            check(status)?;
        }
        Ok(Context { raw: Arc::new(RawContext(raw)), callbacks, _not_sync: PhantomData })
    }
}

/// A thread-safe handle that cancels the running (and every later) call of its context until
/// [`CancelHandle::clear`]. It keeps the C context alive, so it may outlive the [`Context`].
#[derive(Clone)]
pub struct CancelHandle {
    raw: Arc<RawContext>,
}

impl CancelHandle {
    pub fn cancel(&self) {
        unsafe { sys::ca_context_request_cancel(self.raw.0) }
    }
    pub fn clear(&self) {
        unsafe { sys::ca_context_clear_cancel(self.raw.0) }
    }
}

/// Runs the three steps. Used by one thread at a time (`Send`, not `Sync`); cancel from other
/// threads through [`Context::cancel_handle`].
pub struct Context {
    raw: Arc<RawContext>,
    callbacks: *mut Callbacks,
    // a context is not Sync: calls on it must not overlap
    _not_sync: PhantomData<std::cell::Cell<()>>,
}

// SAFETY: the context and its boxed Send closures may move to another thread as a whole.
unsafe impl Send for Context {}

impl Drop for Context {
    fn drop(&mut self) {
        // The C context may live on in a CancelHandle, but no call that could run a callback can
        // be made through one, so the closures may go now.
        drop(unsafe { Box::from_raw(self.callbacks) });
    }
}

impl Context {
    /// A context with the library's defaults (all cores, no callbacks).
    pub fn new() -> Result<Context> {
        Context::builder().build()
    }

    pub fn builder() -> ContextBuilder {
        ContextBuilder {
            desc: defaults!(sys::ca_context_desc, sys::ca_context_desc_defaults),
            callbacks: Callbacks::default(),
        }
    }

    pub fn cancel_handle(&self) -> CancelHandle {
        CancelHandle { raw: self.raw.clone() }
    }

    fn ptr(&self) -> *mut sys::ca_context {
        self.raw.0
    }

    /// Ok, or the status with the context's message for the failed call.
    fn check(&self, status: i32) -> Result<()> {
        if status == sys::CA_OK {
            return Ok(());
        }
        let message = unsafe { cstr(sys::ca_context_last_error(self.ptr())) };
        Err(Error::new(Status::from_code(status), if message.is_empty() { status_string(status) } else { message }))
    }

    /// Step 1: surface samples and inner candidate balls.
    pub fn candidates(&self, surface: &Surface<'_>, options: &CandidateOptions) -> Result<CandidateSet> {
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_candidates(self.ptr(), &surface.raw, &options.raw, &mut out) })?;
        Ok(CandidateSet { raw: out })
    }

    /// Step 1 from the caller's own samples and balls (radius = undilated medial radius);
    /// reference_length 0 = the longest bbox side of the samples.
    pub fn candidates_from_arrays(&self, samples: &[[f64; 3]], centers: &[[f64; 3]], radii: &[f64],
                                  reference_length: f64) -> Result<CandidateSet> {
        if centers.len() != radii.len() {
            return Err(Error::new(Status::InvalidInput, format!("{} centres but {} radii", centers.len(), radii.len())));
        }
        let mut out = ptr::null_mut();
        self.check(unsafe {
            sys::ca_candidates_from_arrays(self.ptr(), samples.as_ptr() as *const f64, samples.len(), 0,
                                           centers.as_ptr() as *const f64, 0, radii.as_ptr(), 0,
                                           centers.len(), reference_length, &mut out)
        })?;
        Ok(CandidateSet { raw: out })
    }

    /// Step 2: the fewest dilated candidate balls covering every sample. A mask whose length is
    /// not the set's sample count (ignorable_samples) or ball count (forced_in, forced_out) is
    /// `Status::InvalidInput`.
    pub fn select(&self, set: &CandidateSet, options: &SelectOptions<'_>) -> Result<Selection> {
        match self.select_best(set, options)? {
            (selection, None) => Ok(selection),
            (_, Some(missed)) => Err(missed),
        }
    }

    /// Step 2, keeping the result of a `target_error` search that did not reach its target (the
    /// selection of lowest HD found, with the `TargetNotReached` error beside it) or of a
    /// `target_error` or `target_count` search the time limit ended after a probe (the best so far,
    /// with the `TimeLimit` error beside it); `None` when neither happened. Other failures are
    /// errors as in `select`.
    pub fn select_best(&self, set: &CandidateSet, options: &SelectOptions<'_>) -> Result<(Selection, Option<Error>)> {
        let raw = &options.raw;
        let samples = unsafe { sys::ca_candidate_set_sample_count(set.raw) };
        for (name, array, count, want, per) in [
            ("ignorable_samples", raw.ignorable_samples, raw.ignorable_samples_count, samples, "sample"),
            ("forced_in", raw.forced_in, raw.forced_in_count, set.len(), "candidate ball"),
            ("forced_out", raw.forced_out, raw.forced_out_count, set.len(), "candidate ball"),
        ] {
            if !array.is_null() && count != want {
                return Err(Error::new(Status::InvalidInput,
                                      format!("{}: {} entries, the set needs one per {} ({})", name, count, per, want)));
            }
        }
        let mut out = ptr::null_mut();
        let status = unsafe { sys::ca_select(self.ptr(), set.raw, &options.raw, &mut out) };
        if (status == sys::CA_ERROR_TARGET_NOT_REACHED || status == sys::CA_ERROR_TIME_LIMIT) && !out.is_null() {
            // the failures with a result (a target not reached; a search the time limit ended:
            // its best so far): the selection is owned (and freed) like any other
            let missed = self.check(status).unwrap_err();
            return Ok((Selection { raw: out }, Some(missed)));
        }
        self.check(status)?;
        Ok((Selection { raw: out }, None))
    }

    /// Step 3: edges and faces between the selected balls (`set` is the selection's own set).
    pub fn connect(&self, set: &CandidateSet, selection: &Selection, options: &ConnectOptions) -> Result<Skeleton> {
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_connect(self.ptr(), set.raw, selection.raw, &options.raw, &mut out) })?;
        Ok(Skeleton { raw: out })
    }

    /// The three steps with default options.
    pub fn skeletonize(&self, surface: &Surface<'_>) -> Result<Skeleton> {
        let set = self.candidates(surface, &CandidateOptions::default())?;
        let selection = self.select(&set, &SelectOptions::default())?;
        self.connect(&set, &selection, &ConnectOptions::default())
    }

    /// Hausdorff distances between the surface and the skeleton's reconstruction, in % of the
    /// bounding-box diagonal.
    pub fn evaluate(&self, surface: &Surface<'_>, skeleton: &Skeleton, options: &EvaluateOptions) -> Result<Evaluation> {
        let view = skeleton.view()?;
        let mut result = Evaluation { struct_size: std::mem::size_of::<Evaluation>() as u32, ..Default::default() };
        self.check(unsafe { sys::ca_evaluate(self.ptr(), &surface.raw, &view, &options.raw, &mut result) })?;
        Ok(result)
    }

    /// Each surface vertex's nearest skeleton primitive and up to 4 ball weights that sum to 1
    /// (docs/rig.md); `smoothing` None keeps the library's default.
    pub fn correspond(&self, surface: &Surface<'_>, skeleton: &Skeleton, smoothing: Option<f64>) -> Result<Correspondence> {
        let view = skeleton.view()?;
        let mut options = defaults!(sys::ca_correspondence_options, sys::ca_correspondence_options_defaults);
        if let Some(width) = smoothing {
            options.smoothing = width;
        }
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_correspond(self.ptr(), &surface.raw, &view, &options, &mut out) })?;
        Ok(Correspondence { raw: out })
    }

    /// The skeleton's curve skeleton as a tree of joints and each surface vertex's joint weights.
    pub fn rig(&self, surface: &Surface<'_>, skeleton: &Skeleton, options: &RigOptions) -> Result<Rig> {
        let view = skeleton.view()?;
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_rig_build(self.ptr(), &surface.raw, &view, &options.raw, &mut out) })?;
        Ok(Rig { raw: out })
    }

    /// Engine proxies: at most `options.count` spheres, or tapered capsules and spheres, chosen
    /// from the skeleton over the set's mesh (docs/proxies.md).
    pub fn proxies(&self, set: &CandidateSet, skeleton: &Skeleton, options: &ProxyOptions) -> Result<Proxies> {
        let view = skeleton.view()?;
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_proxies(self.ptr(), set.raw, &view, &options.raw, &mut out) })?;
        Ok(Proxies { raw: out })
    }

    /// A tapered capsule or sphere per joint of the skin, fitted to the part of the set's mesh the
    /// joint dominates, in the joint's frame (docs/bone_colliders.md). Array lengths are checked
    /// here (`InvalidInput`); values by the library.
    pub fn bone_colliders(&self, set: &CandidateSet, skin: &Skin, options: &BoneColliderOptions) -> Result<BoneColliders> {
        let k = skin.influences as usize;
        if k == 0 || skin.vertex_joints.len() % k != 0 || skin.vertex_weights.len() != skin.vertex_joints.len() {
            return Err(Error {
                status: Status::InvalidInput,
                message: "skin: vertex_joints and vertex_weights need `influences` (>= 1) entries per vertex".into(),
            });
        }
        if let Some(ib) = skin.inverse_bind {
            if ib.len() != skin.parents.len() {
                return Err(Error { status: Status::InvalidInput, message: "skin: one inverse bind matrix per joint".into() });
            }
        }
        let mut view: sys::ca_skin_view = defaults!(sys::ca_skin_view, sys::ca_skin_view_defaults);
        view.joint_count = skin.parents.len();
        view.parents = skin.parents.as_ptr();
        view.inverse_bind = skin.inverse_bind.map_or(ptr::null(), |m| m.as_ptr() as *const f64);
        view.vertex_count = skin.vertex_joints.len() / k;
        view.influences = skin.influences;
        view.vertex_joints = skin.vertex_joints.as_ptr();
        view.vertex_weights = skin.vertex_weights.as_ptr();
        let mut raw = options.raw;
        raw.skip_joints = if options.skip.is_empty() { ptr::null() } else { options.skip.as_ptr() };
        raw.skip_count = options.skip.len();
        let mut out = ptr::null_mut();
        self.check(unsafe { sys::ca_bone_colliders_build(self.ptr(), set.raw, ptr::null(), &view, &raw, &mut out) })?;
        Ok(BoneColliders { raw: out })
    }
}

/// One bone collider as an engine places it under its joint (the joint's frame): a node at
/// `center` turned by `rotation` (x y z w) holding a sphere of `radius_top`, or a capsule along
/// its +Y axis (`axis` in the joint's frame) with the ball of `radius_top` at +`height`/2 and the
/// ball of `radius_bottom` at -`height`/2; `contained` is the fraction of its part's fresh samples
/// it holds, `overlap` its overlap volume with its parent joint's collider.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoneCollider {
    pub joint: u32,
    pub capsule: bool,
    pub center: [f64; 3],
    pub rotation: [f64; 4],
    pub axis: [f64; 3],
    pub radius_top: f64,
    pub radius_bottom: f64,
    pub height: f64,
    pub contained: f64,
    pub overlap: f64,
}

owned_result!(
    /// Bone colliders ([`Context::bone_colliders`]); they hold nothing of the other objects.
    BoneColliders, sys::ca_bone_colliders, sys::ca_bone_colliders_destroy, sys::ca_bone_colliders_count
);

impl BoneColliders {
    pub fn colliders(&self) -> Vec<BoneCollider> {
        let n = self.len();
        let joints = unsafe { values(sys::ca_bone_colliders_joints(self.raw), n) };
        let contained = unsafe { values(sys::ca_bone_colliders_contained(self.raw), n) };
        let overlap = unsafe { values(sys::ca_bone_colliders_overlap(self.raw), n) };
        (0..n)
            .map(|i| {
                let p = read_out!(sys::ca_proxy_placement, sys::ca_bone_colliders_placement, self.raw, i);
                BoneCollider {
                    joint: joints[i],
                    capsule: p.kind == sys::CA_PROXY_CAPSULE,
                    center: p.center,
                    rotation: p.rotation,
                    axis: p.axis,
                    radius_top: p.radius_top,
                    radius_bottom: p.radius_bottom,
                    height: p.height,
                    contained: contained[i],
                    overlap: overlap[i],
                }
            })
            .collect()
    }
    pub fn stats(&self) -> BoneColliderStats {
        read_out!(BoneColliderStats, sys::ca_bone_colliders_stats, self.raw)
    }
}

/// One engine proxy in the input's units: a sphere (`a`, `radius_a`; `b` equals `a`) or the
/// tapered capsule that is the convex hull of the balls (`a`, `radius_a`) and (`b`, `radius_b`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Proxy {
    pub capsule: bool,
    pub a: [f64; 3],
    pub radius_a: f64,
    pub b: [f64; 3],
    pub radius_b: f64,
}

owned_result!(
    /// Engine proxies ([`Context::proxies`]); they hold nothing of the other objects.
    Proxies, sys::ca_proxy_set, sys::ca_proxy_set_destroy, sys::ca_proxy_set_count
);

impl Proxies {
    pub fn primitives(&self) -> Vec<Proxy> {
        let n = self.len();
        let kinds = unsafe { values(sys::ca_proxy_set_kinds(self.raw), n) };
        let centers: &[[f64; 6]] = unsafe { items(sys::ca_proxy_set_centers(self.raw), n) };
        let radii: &[[f64; 2]] = unsafe { items(sys::ca_proxy_set_radii(self.raw), n) };
        (0..n)
            .map(|i| Proxy {
                capsule: kinds[i] == sys::CA_PROXY_CAPSULE,
                a: [centers[i][0], centers[i][1], centers[i][2]],
                radius_a: radii[i][0],
                b: [centers[i][3], centers[i][4], centers[i][5]],
                radius_b: radii[i][1],
            })
            .collect()
    }
    pub fn stats(&self) -> ProxyStats {
        read_out!(ProxyStats, sys::ca_proxy_set_stats, self.raw)
    }
}

// ---- results ---------------------------------------------------------------------------------

owned_result!(
    /// Surface samples and candidate balls (step 1). Selections made from it keep the C object
    /// alive, so it may be dropped before them.
    CandidateSet, sys::ca_candidate_set, sys::ca_candidate_set_destroy, sys::ca_candidate_set_count
);
owned_result!(
    /// Balls chosen by step 2; it may outlive its candidate set and context.
    Selection, sys::ca_selection, sys::ca_selection_destroy, sys::ca_selection_count
);
owned_result!(
    /// The medial skeleton (step 3); it holds nothing of the other objects.
    Skeleton, sys::ca_skeleton, sys::ca_skeleton_destroy, sys::ca_skeleton_vertex_count
);

impl CandidateSet {
    pub fn centers(&self) -> &[[f64; 3]] {
        unsafe { items(sys::ca_candidate_set_centers(self.raw), self.len()) }
    }
    pub fn radii(&self) -> &[f64] {
        unsafe { values(sys::ca_candidate_set_radii(self.raw), self.len()) }
    }
    pub fn samples(&self) -> &[[f64; 3]] {
        unsafe { items(sys::ca_candidate_set_samples(self.raw), sys::ca_candidate_set_sample_count(self.raw)) }
    }
    /// The length delta is a fraction of (the longest bbox side), in the input's units.
    pub fn reference_length(&self) -> f64 {
        unsafe { sys::ca_candidate_set_reference_length(self.raw) }
    }
    /// The input mesh faced inward and was flipped for the inside test.
    pub fn flipped(&self) -> bool {
        unsafe { sys::ca_candidate_set_flipped(self.raw) != 0 }
    }
    /// Point clouds: how many points were dropped as outliers.
    pub fn outlier_count(&self) -> u64 {
        unsafe { sys::ca_candidate_set_outlier_count(self.raw) }
    }
}

impl Selection {
    /// Indices into the candidate set.
    pub fn indices(&self) -> &[u32] {
        unsafe { values(sys::ca_selection_indices(self.raw), self.len()) }
    }
    pub fn centers(&self) -> &[[f64; 3]] {
        unsafe { items(sys::ca_selection_centers(self.raw), self.len()) }
    }
    /// Undilated radii.
    pub fn radii(&self) -> &[f64] {
        unsafe { values(sys::ca_selection_radii(self.raw), self.len()) }
    }
    pub fn dilated_radii(&self) -> &[f64] {
        unsafe { values(sys::ca_selection_dilated_radii(self.raw), self.len()) }
    }
    /// Samples no ball covers (with skip_uncoverable).
    pub fn uncovered(&self) -> &[u32] {
        unsafe { values(sys::ca_selection_uncovered(self.raw), sys::ca_selection_uncovered_count(self.raw)) }
    }
    pub fn stats(&self) -> SelectStats {
        read_out!(SelectStats, sys::ca_selection_stats, self.raw)
    }
}

impl Skeleton {
    pub fn centers(&self) -> &[[f64; 3]] {
        unsafe { items(sys::ca_skeleton_centers(self.raw), self.len()) }
    }
    pub fn radii(&self) -> &[f64] {
        unsafe { values(sys::ca_skeleton_radii(self.raw), self.len()) }
    }
    /// i j per edge, including the faces' edges.
    pub fn edges(&self) -> &[[u32; 2]] {
        unsafe { items(sys::ca_skeleton_edges(self.raw), sys::ca_skeleton_edge_count(self.raw)) }
    }
    pub fn faces(&self) -> &[[u32; 3]] {
        unsafe { items(sys::ca_skeleton_faces(self.raw), sys::ca_skeleton_face_count(self.raw)) }
    }
    pub fn stats(&self) -> SkeletonStats {
        read_out!(SkeletonStats, sys::ca_skeleton_stats_get, self.raw)
    }
    /// The library's view of the skeleton's arrays, for the calls that take a skeleton.
    fn view(&self) -> Result<sys::ca_skeleton_view> {
        let mut view: sys::ca_skeleton_view = defaults!(sys::ca_skeleton_view, sys::ca_skeleton_view_defaults);
        check(unsafe { sys::ca_skeleton_get_view(self.raw, &mut view) })?;
        Ok(view)
    }
}

owned_result!(
    /// Per surface vertex: 4 balls and weights (decreasing, sum 1; an unused slot has weight 0 and
    /// repeats the first ball) and the nearest primitive (`sys::CA_NEAREST_*`, an index into the
    /// skeleton's balls, edges or faces).
    Correspondence, sys::ca_correspondence, sys::ca_correspondence_destroy, sys::ca_correspondence_vertex_count
);
owned_result!(
    /// A tree of joints (parents before children; joint 0 the root, parent -1) and per surface
    /// vertex 4 joints and weights (decreasing, sum 1).
    Rig, sys::ca_rig, sys::ca_rig_destroy, sys::ca_rig_joint_count
);

impl Correspondence {
    pub fn balls(&self) -> &[[u32; 4]] {
        unsafe { items(sys::ca_correspondence_balls(self.raw), self.len()) }
    }
    pub fn weights(&self) -> &[[f64; 4]] {
        unsafe { items(sys::ca_correspondence_weights(self.raw), self.len()) }
    }
    pub fn nearest_kinds(&self) -> &[i32] {
        unsafe { values(sys::ca_correspondence_nearest_kinds(self.raw), self.len()) }
    }
    pub fn nearest_indices(&self) -> &[u32] {
        unsafe { values(sys::ca_correspondence_nearest_indices(self.raw), self.len()) }
    }
}

impl Rig {
    pub fn branch_count(&self) -> usize {
        unsafe { sys::ca_rig_branch_count(self.raw) }
    }
    pub fn positions(&self) -> &[[f64; 3]] {
        unsafe { items(sys::ca_rig_joint_positions(self.raw), self.len()) }
    }
    pub fn parents(&self) -> &[i32] {
        unsafe { values(sys::ca_rig_joint_parents(self.raw), self.len()) }
    }
    pub fn joint_balls(&self) -> &[u32] {
        unsafe { values(sys::ca_rig_joint_balls(self.raw), self.len()) }
    }
    pub fn vertex_count(&self) -> usize {
        unsafe { sys::ca_rig_vertex_count(self.raw) }
    }
    pub fn joints(&self) -> &[[u32; 4]] {
        unsafe { items(sys::ca_rig_vertex_joints(self.raw), self.vertex_count()) }
    }
    pub fn weights(&self) -> &[[f64; 4]] {
        unsafe { items(sys::ca_rig_vertex_weights(self.raw), self.vertex_count()) }
    }
    pub fn branches(&self) -> &[u32] {
        unsafe { values(sys::ca_rig_vertex_branches(self.raw), self.vertex_count()) }
    }
}
