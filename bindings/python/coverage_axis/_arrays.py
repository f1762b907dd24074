"""_arrays.py: converts the caller's arrays into the (pointer, count, byte stride) views the C ABI
reads, and the library's result arrays into numpy arrays (when numpy is installed) or plain lists.

Inputs: numpy arrays of any float or integer dtype, or nested sequences. A float64 (n, 3) array
whose rows are packed doubles (C-contiguous, or rows of a wider array) and a contiguous uint32
index array are passed without a copy; anything else is converted once.
Outputs: read-only numpy arrays over the library's own memory (no copy), each keeping the result
object that owns that memory alive; without numpy, lists of tuples (copies)."""
import ctypes

from ._library import CA_ERROR_INVALID_INPUT, CoverageAxisError

try:
    import numpy as np
except ImportError:
    np = None

HAVE_NUMPY = np is not None
_UINT32_MAX = 0xFFFFFFFF


class Buffer:
    """A borrowed input: address, row count and row stride in bytes, plus what keeps it alive."""

    def __init__(self, address, count, stride, keep):
        self.address, self.count, self.stride, self.keep = address, count, stride, keep


def _is_empty(x):
    return x is None or (len(x) == 0 if np is None or not isinstance(x, np.ndarray) else x.size == 0)


def points(x, name, width=3, packed=False):
    """(n, width) coordinates as packed doubles per row (packed: and rows one after the other).
    Floats and integers of any dtype."""
    if np is not None:
        a = np.asarray(x)
        if a.size == 0:
            a = a.reshape(0, width)
        if a.ndim != 2 or a.shape[1] != width:
            raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: expected shape (n, %d), got %s" % (name, width, a.shape))
        if a.dtype.kind not in "fiu":
            raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: expected numbers, got dtype %s" % (name, a.dtype))
        if a.dtype != np.float64 or a.strides[1] != 8 or a.strides[0] < 8 * width or (packed and a.strides[0] != 8 * width):
            a = np.ascontiguousarray(a, dtype=np.float64)
        return Buffer(a.ctypes.data if a.size else None, a.shape[0], a.strides[0] if a.size else 0, a)
    rows = [tuple(r) for r in (x or [])]
    if any(len(r) != width for r in rows):
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: every row needs %d numbers" % (name, width))
    try:
        flat = (ctypes.c_double * (width * len(rows)))(*[float(c) for r in rows for c in r])
    except (TypeError, ValueError) as e:
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: %s" % (name, e))
    return Buffer(ctypes.addressof(flat) if rows else None, len(rows), 0, flat)


def indices(x, name, width):
    """(n, width) indices as uint32 (width 1: a flat list). Integers of any dtype, or integral floats;
    values outside [0, 2^32) are refused before the conversion could wrap them."""
    if _is_empty(x):
        return Buffer(None, 0, 0, None)
    if np is not None:
        a = np.asarray(x)
        shape_ok = a.ndim == 1 if width == 1 else (a.ndim == 2 and a.shape[1] == width)
        if not shape_ok:
            want = "(n,)" if width == 1 else "(n, %d)" % width
            raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: expected shape %s, got %s" % (name, want, a.shape))
        if a.dtype != np.uint32:
            if a.dtype.kind == "f":
                if not np.all(np.isfinite(a)) or not np.all(a == np.floor(a)):
                    raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: indices must be whole numbers" % name)
            elif a.dtype.kind not in "iub":
                raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: expected integers, got dtype %s" % (name, a.dtype))
            if a.min() < 0 or a.max() > _UINT32_MAX:
                raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: indices must be in [0, 2^32)" % name)
        a = np.ascontiguousarray(a, dtype=np.uint32)
        return Buffer(a.ctypes.data, a.shape[0], 0, a)
    rows = [(r,) if width == 1 else tuple(r) for r in x]
    if any(len(r) != width for r in rows):
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: every row needs %d indices" % (name, width))
    flat = []
    for r in rows:
        for i in r:
            if i != int(i) or not 0 <= int(i) <= _UINT32_MAX:
                raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: indices must be whole numbers in [0, 2^32)" % name)
            flat.append(int(i))
    arr = (ctypes.c_uint32 * len(flat))(*flat)
    return Buffer(ctypes.addressof(arr), len(rows), 0, arr)


def mask(x, name, count):
    """A flag per item (non-zero = set) as uint8, exactly `count` long (else CA_ERROR_INVALID_INPUT, as
    the library says of a mask whose count does not match); None stays None."""
    if x is None:
        return None
    flags = [1 if f else 0 for f in (x.tolist() if np is not None and isinstance(x, np.ndarray) else x)]
    if len(flags) != count:
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "%s: %d flags, expected %d" % (name, len(flags), count))
    return (ctypes.c_uint8 * count)(*flags)


def view(address, count, width, ctype, owner):
    """The library's array at `address` (count rows of width items of ctype) as a read-only numpy
    array that keeps `owner` alive, or a list (of tuples when width > 1) without numpy."""
    n = count * width
    if np is None:
        if n == 0:
            return []
        flat = (ctype * n).from_address(address)
        return list(flat) if width == 1 else [tuple(flat[i:i + width]) for i in range(0, n, width)]
    dtype = {ctypes.c_double: np.float64, ctypes.c_int32: np.int32}.get(ctype, np.uint32)
    shape = (count,) if width == 1 else (count, width)
    if n == 0:
        return np.zeros(shape, dtype=dtype)
    raw = (ctype * n).from_address(address)
    raw._owner = owner  # the numpy array's base is raw, so the result lives as long as any view
    a = np.frombuffer(raw, dtype=dtype).reshape(shape)
    a.flags.writeable = False
    return a
