"""_context.py: Context, the library's ca_context: worker threads, the progress callback, the
log, and cancel (which any thread may call while a step runs on another)."""
import ctypes
import threading

from ._library import LOG_FN, PROGRESS_FN, CoverageAxisError, _ContextDesc, fill_defaults, lib


class Context:
    """Settings and state shared by the steps run with it. Arguments left None keep the library's
    defaults (ca_context_desc_defaults).

    threads      worker threads for the parallel stages (0 = all cores, 1 = serial)
    progress     progress(stage, fraction) -> truthy to cancel; called on the thread running the step
    progress_interval_s  least time between two progress calls within a stage
    log          log(level, message); level 0 debug, 1 info, 2 warning

    A step runs on one thread at a time per context (concurrent calls wait for each other).
    cancel() may be called from any thread: the running step, and every later one until
    clear_cancel(), fails with CA_ERROR_CANCELLED. An exception raised by a callback cancels the
    step and is raised again from it."""

    def __init__(self, threads=None, progress=None, log=None, progress_interval_s=None):
        desc = fill_defaults("ca_context_desc_defaults", _ContextDesc)
        if threads is not None:
            desc.threads = threads
        if progress_interval_s is not None:
            desc.progress_interval_s = progress_interval_s
        self._progress, self._log = progress, log
        self._callback_error, self._cancelled_by_log, self._runner = None, False, None
        # the CFUNCTYPE objects must live as long as the context: the library keeps their addresses
        self._progress_fn = PROGRESS_FN(self._on_progress) if progress else None
        self._log_fn = LOG_FN(self._on_log) if log else None
        desc.progress = ctypes.cast(self._progress_fn, ctypes.c_void_p) if progress else None
        desc.log = ctypes.cast(self._log_fn, ctypes.c_void_p) if log else None
        self._lib = lib()
        self._ptr = ctypes.c_void_p()
        status = self._lib.ca_context_create(ctypes.byref(desc), ctypes.byref(self._ptr))
        if status:
            raise CoverageAxisError(status, "cannot create a context (threads=%r, progress_interval_s=%r)" %
                                    (desc.threads, desc.progress_interval_s))
        self.threads, self.progress_interval_s = desc.threads, desc.progress_interval_s
        self._busy = threading.Lock()

    def _on_progress(self, user, stage, fraction):
        try:
            return 1 if self._progress(stage.decode(), fraction) else 0
        except BaseException as e:  # noqa: B902 - carried across the C frames, raised again by run()
            self._callback_error = self._callback_error or e
            return 1

    def _on_log(self, user, level, message):
        try:
            self._log(level, message.decode(errors="replace"))
        except BaseException as e:  # noqa: B902
            self._callback_error = self._callback_error or e
            self._cancelled_by_log = True
            self._lib.ca_context_request_cancel(self._ptr)

    def cancel(self):
        """Asks the running step (and later ones) to stop; safe from any thread."""
        self._lib.ca_context_request_cancel(self._ptr)

    def clear_cancel(self):
        self._lib.ca_context_clear_cancel(self._ptr)

    def run(self, function, *args):
        """Calls a ca_* step with this context first; raises CoverageAxisError on failure."""
        if not self._ptr:
            raise RuntimeError("the context is closed")
        if self._runner == threading.get_ident():
            raise RuntimeError("a callback of this context called a step on the same context")
        with self._busy:
            self._runner, self._callback_error, self._cancelled_by_log = threading.get_ident(), None, False
            try:
                status = function(self._ptr, *args)
            finally:
                self._runner = None
            error, self._callback_error = self._callback_error, None
            if self._cancelled_by_log:  # the cancel was the binding's, not the caller's: lift it
                self._lib.ca_context_clear_cancel(self._ptr)
            if error is not None:
                raise error
            if status:
                raise CoverageAxisError(status, self._lib.ca_context_last_error(self._ptr).decode(errors="replace"))

    def close(self):
        if getattr(self, "_ptr", None):
            self._lib.ca_context_destroy(self._ptr)
            self._ptr = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()
