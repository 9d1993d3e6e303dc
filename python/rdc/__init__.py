# SPDX-License-Identifier: LGPL-2.1-or-later
# SPDX-FileCopyrightText: 2026 The rdc authors
"""rdc: librdc, the host library of the RDC-1, from Python.

    import rdc

    with rdc.open("sim:") as dev:
        dev.mode_set("640x480", rdc.FMT_XRGB8888)
        with rdc.Batch() as b:
            b.fg(0xff8000).fill_circle(320, 240, 100)
            dev.submit(b)
        dev.finish()
        dev.vblank_wait()
        frame = dev.frame_grab()     # frame.data: bytes, frame.array(): numpy
        print(hex(dev.frame_crc()))

Every call maps onto one of rdc.h's, which documents it; a failure raises
rdc.Error (a subclass per librdc error code) carrying the code, librdc's
description and detail, and for RDC_E_DEVICE the device's own error.
Constants are rdc_regs.h's and rdc.h's without RDC_: rdc.REG_LINE_COMPARE,
rdc.IRQ_LINE, rdc.FMT_I8, rdc.PRESET_640x480_60, rdc.PIN_TE ...
See docs/python.md.
"""

import ctypes
import zlib
from ctypes import byref, c_size_t, c_uint32, c_uint64, c_void_p

from . import _headers
from . import _lib
from ._lib import lib

try:
    import numpy
except ImportError:  # frames stay bytes
    numpy = None

globals().update(_headers.load())
# the release of the headers the package was installed (or is) with;
# version() is the library's
__version__ = "%d.%d.%d" % (VERSION_MAJOR, VERSION_MINOR, VERSION_PATCH)

__all__ = ["open", "Device", "Batch", "Frame", "Error", "Vcd", "History",
           "ScriptResult", "ReplayResult", "replay_file", "replay_history",
           "list_devices", "version", "strerror", "preset_by_name",
           "preset_size", "op_name", "reg_by_name", "reg_names", "png_read",
           "png_write", "crc32", "library"]


def library():
    """The path librdc.so.1 was loaded from (loading it if need be)."""
    lib.rdc_version
    return lib.path


# ---- Errors ----------------------------------------------------------------

class Error(Exception):
    """A librdc call failed: `code` (enum rdc_error, negative), `name`
    ("RDC_E_TIMEOUT"), `message` (rdc_strerror), `detail`
    (rdc_last_error_detail, may be ""), `call` (the C function), and for
    RDC_E_DEVICE `dev_code`, `dev_name` and `dev_info` (rdc_dev_error,
    which this reads and so clears on the device)."""

    def __init__(self, code, call="", detail="", dev_code=None,
                 dev_info=None):
        self.code = code
        self.call = call
        self.message = strerror(code)
        self.detail = detail
        self.name = _ERROR_NAMES.get(code, "RDC_E_%d" % -code)
        self.dev_code = dev_code
        self.dev_info = dev_info
        self.dev_name = (lib.rdc_dev_strerror(dev_code).decode()
                         if dev_code is not None else None)
        text = "%s: %s (%s)" % (call, self.message, self.name) if call \
            else "%s (%s)" % (self.message, self.name)
        if detail:
            text += ": " + detail
        if dev_code is not None:
            text += ": device error %s, info %#x" % (self.dev_name, dev_info)
        super().__init__(text)


_ERROR_NAMES = {}
_ERROR_CLASSES = {}
for _n, _doc in (("INVAL", "InvalidArgument"), ("NOMEM", "NoMemory"),
                 ("NOSYS", "NotSupported"), ("URI", "BadURI"),
                 ("IO", "TransportError"), ("TIMEOUT", "Timeout"),
                 ("DEVICE", "DeviceError"), ("HALTED", "Halted"),
                 ("RANGE", "RangeError"), ("PARSE", "ParseError"),
                 ("PROTO", "ProtocolError"), ("BUSY", "Busy"),
                 ("FILE", "FileError"), ("AUTH", "AuthError"),
                 ("GONE", "Gone"), ("RESET", "ResetError")):
    _code = globals()["E_" + _n]
    _ERROR_NAMES[_code] = "RDC_E_" + _n
    _ERROR_CLASSES[_code] = type(_doc, (Error,), {
        "__doc__": "RDC_E_%s as an exception." % _n})
    globals()[_doc] = _ERROR_CLASSES[_code]
    __all__.append(_doc)


def _raise(code, call, dev=None):
    detail = lib.rdc_last_error_detail(code)
    detail = detail.decode(errors="replace") if detail else ""
    dev_code = dev_info = None
    if code == E_DEVICE and dev is not None and dev._h:
        c, inf = c_uint32(), c_uint32()
        if lib.rdc_dev_error(dev._h, byref(c), byref(inf)) == 0:
            dev_code, dev_info = c.value, inf.value
    cls = _ERROR_CLASSES.get(code, Error)
    raise cls(code, call, detail, dev_code, dev_info)


def _check(ret, call, dev=None):
    if ret < 0:
        _raise(ret, call, dev)
    return ret


# ---- Buffers ----------------------------------------------------------------

def _in(data):
    """(pointer, byte length, keep-alive) for a read-only buffer, without a
    copy for bytes and for writable buffers (bytearray, numpy, array)."""
    if isinstance(data, bytes):
        return data, len(data), data
    mv = memoryview(data)
    if not mv.c_contiguous:
        raise ValueError("rdc: the buffer must be contiguous")
    mv = mv.cast("B")
    if mv.readonly:
        data = mv.tobytes()
        return data, len(data), data
    arr = (ctypes.c_char * mv.nbytes).from_buffer(mv)
    return arr, mv.nbytes, (arr, mv)


def _out(buf):
    """(pointer, byte length, keep-alive) for a writable buffer."""
    mv = memoryview(buf)
    if mv.readonly or not mv.c_contiguous:
        raise ValueError("rdc: the buffer must be writable and contiguous")
    mv = mv.cast("B")
    arr = (ctypes.c_char * mv.nbytes).from_buffer(mv)
    return arr, mv.nbytes, (arr, mv)


def _words(values, ctype=ctypes.c_uint32):
    if isinstance(values, (bytes, bytearray, memoryview)) or (
            numpy is not None and isinstance(values, numpy.ndarray)):
        p, n, keep = _in(values)
        return p, n // ctypes.sizeof(ctype), keep
    values = list(values)
    if ctype is ctypes.c_uint32:
        values = [v & 0xFFFFFFFF for v in values]
    arr = (ctype * len(values))(*values)
    return arr, len(values), arr


def _points(xy):
    """A flat or paired sequence of points as a C int array."""
    flat = []
    for v in xy:
        if isinstance(v, (tuple, list)):
            flat.extend(v)
        else:
            flat.append(v)
    if len(flat) % 2:
        raise ValueError("rdc: points need an even number of coordinates")
    return (ctypes.c_int * len(flat))(*flat), len(flat) // 2


# ---- Library-wide calls -----------------------------------------------------

def version():
    """The librdc release as (major, minor, patch)."""
    v = lib.rdc_version()
    return (v >> 16) & 0xFF, (v >> 8) & 0xFF, v & 0xFF


def strerror(code):
    s = lib.rdc_strerror(code)
    return s.decode() if s else "error %d" % code


def preset_by_name(name):
    """A preset by number or name ("640x480", "1080p"): its number."""
    if isinstance(name, int):
        return name
    p = lib.rdc_preset_by_name(name.encode())
    if p < 0:
        raise InvalidArgument(E_INVAL, "rdc_preset_by_name",
                              "unknown preset %r" % name)
    return p


def preset_size(preset):
    w, h = c_uint32(), c_uint32()
    _check(lib.rdc_preset_size(preset_by_name(preset), byref(w), byref(h)),
           "rdc_preset_size")
    return w.value, h.value


def format_by_name(fmt):
    """A format by number or name ("i8", "xrgb8888", "FMT_RGB565")."""
    if isinstance(fmt, int):
        return fmt
    key = fmt.upper()
    for k in (key, "FMT_" + key, key.replace("RDC_", "", 1)):
        if k.startswith("FMT_") and k in globals():
            return globals()[k]
    raise InvalidArgument(E_INVAL, "format", "unknown format %r" % fmt)


def op_name(op):
    s = lib.rdc_op_name(op)
    return s.decode() if s else None


def reg_names():
    """{name: offset} of every register, librdc's table."""
    out = {}
    off = c_uint32()
    for n in range(lib.rdc_reg_count()):
        s = lib.rdc_reg_info(n, byref(off))
        if s:
            out[s.decode()] = off.value
    return out


def reg_by_name(name):
    """A register by offset or name ("LINE_COMPARE", "RDC_REG_FENCE")."""
    if isinstance(name, int):
        return name
    off = c_uint32()
    _check(lib.rdc_reg_by_name(name.encode(), byref(off)), "rdc_reg_by_name")
    return off.value


def list_devices():
    """Every RDC-1 this machine reaches: [(uri, info)] (rdc_list)."""
    found = []

    def cb(f, _arg):
        found.append((f.contents.uri.decode(), f.contents.info.decode()))
    fn = _lib.FOUND_FN(cb)
    _check(lib.rdc_list(fn, None), "rdc_list")
    return found


def crc32(data):
    """CRC-32 (zlib) as rdc_frame_crc computes it over XRGB8888 bytes."""
    return zlib.crc32(data) & 0xFFFFFFFF


def png_read(path):
    """A PNG as a Frame of XRGB8888 pixels (rdc_image_png_read)."""
    px = ctypes.POINTER(c_uint32)()
    w, h = c_uint32(), c_uint32()
    _check(lib.rdc_image_png_read(str(path).encode(), byref(px), byref(w),
                                  byref(h)), "rdc_image_png_read")
    try:
        n = w.value * h.value * 4
        buf = bytearray(n)
        ctypes.memmove((ctypes.c_char * n).from_buffer(buf), px, n)
    finally:
        _lib.libc_free(ctypes.cast(px, c_void_p))
    return Frame(buf, w.value, h.value)


def png_write(path, frame):
    """Write a Frame (or anything with data, width, height) as an RGB PNG."""
    p, n, keep = _in(frame.data)
    if n < frame.width * frame.height * 4:
        raise ValueError("rdc: the frame's buffer is too small")
    _check(lib.rdc_png_write(str(path).encode(), p, frame.width,
                             frame.height, frame.width), "rdc_png_write")
    del keep


def image_encode(codec, pixels, width, height, channels, pitch=None):
    """A stream for the DECODE command (rdc_image_encode): bytes."""
    pitch = width * channels if pitch is None else pitch
    cap = lib.rdc_image_bound(codec, width, height, channels)
    if not cap:
        raise InvalidArgument(E_INVAL, "rdc_image_bound")
    p, _, keep = _in(pixels)
    out = bytearray(cap)
    o, _, okeep = _out(out)
    n = c_size_t()
    _check(lib.rdc_image_encode(codec, p, width, height, channels, pitch, o,
                                cap, byref(n)), "rdc_image_encode")
    del keep, okeep
    return bytes(out[:n.value])


def image_samples(frame, channels=3):
    """A frame's pixels as samples for image_encode (rdc_image_samples):
    R, G, B bytes (channels 3) or luma (1)."""
    out = bytearray(len(frame) * channels)
    p, _, keep = _in(frame.words())
    o, _, okeep = _out(out)
    _check(lib.rdc_image_samples(p, frame.width, frame.height, frame.width,
                                 channels, o), "rdc_image_samples")
    del keep, okeep
    return out


# ---- Frames -----------------------------------------------------------------

class Frame:
    """A scanned-out frame: width x height XRGB8888 pixels, each the
    little-endian word 0x00RRGGBB, in `data`, the buffer librdc wrote into
    directly (a bytearray, or the caller's: a numpy array ...).  array()
    views it as numpy, words() as a memoryview of ints (no copies)."""

    __slots__ = ("data", "width", "height", "_bytes")

    def __init__(self, data, width, height):
        self.data = data
        self.width = width
        self.height = height
        mv = memoryview(data).cast("B")
        if mv.nbytes < width * height * 4:
            raise ValueError("rdc: %d bytes hold no %dx%d frame"
                             % (mv.nbytes, width, height))
        self._bytes = mv[:width * height * 4]

    def __len__(self):
        return self.width * self.height

    def __bytes__(self):
        return self._bytes.tobytes()

    def __eq__(self, other):
        return (isinstance(other, Frame) and self.width == other.width and
                self.height == other.height and self._bytes == other._bytes)

    __hash__ = None

    def __repr__(self):
        return "<rdc.Frame %dx%d crc32 %08x>" % (
            self.width, self.height, self.crc())

    def crc(self):
        """CRC-32 of the pixels' bytes, as rdc_frame_crc's."""
        return crc32(self._bytes)

    def words(self):
        """The pixels as a memoryview of unsigned ints (0xXXRRGGBB)."""
        return self._bytes.cast("I")

    def pixel(self, x, y):
        """The pixel at (x, y) as 0x00RRGGBB."""
        if not (0 <= x < self.width and 0 <= y < self.height):
            raise IndexError("rdc: (%d, %d) outside %dx%d"
                             % (x, y, self.width, self.height))
        o = (y * self.width + x) * 4
        return int.from_bytes(self._bytes[o:o + 4], "little") & 0xFFFFFF

    def row(self, y):
        """Row y as a list of 0x00RRGGBB values."""
        o = y * self.width * 4
        mv = self._bytes[o:o + self.width * 4].cast("I")
        return [v & 0xFFFFFF for v in mv]

    def array(self):
        """The pixels as a (height, width) numpy array of uint32 sharing
        this frame's memory (numpy needed)."""
        if numpy is None:
            raise ImportError("rdc: Frame.array() needs numpy "
                              "(Debian: python3-numpy)")
        return numpy.frombuffer(self._bytes, dtype="<u4").reshape(
            self.height, self.width)

    def rgb(self):
        """(height, width, 3) uint8 numpy array R, G, B (a copy)."""
        a = self.array()
        return numpy.stack(((a >> 16) & 0xFF, (a >> 8) & 0xFF, a & 0xFF),
                           axis=-1).astype(numpy.uint8)

    def save_png(self, path):
        png_write(path, self)


# ---- Results ----------------------------------------------------------------

class _Result:
    """A C result structure's fields as attributes."""

    _skip = ()

    def __init__(self, st):
        for name, _ in st._fields_:
            if name == "size" or name in self._skip:
                continue
            v = getattr(st, name)
            if isinstance(v, bytes):
                v = v.decode(errors="replace")
            elif isinstance(v, ctypes.Array):
                v = list(v)
            setattr(self, name, v)

    def __repr__(self):
        return "<%s %s>" % (type(self).__name__, ", ".join(
            "%s=%r" % kv for kv in vars(self).items()
            if not isinstance(kv[1], (list, dict))))


class ScriptResult(_Result):
    """rdc_script_result: per command class (op name) `cycles` and
    `counts`, error_line, error_col, error_msg, readbacks, readback_crc,
    readback_words, frame_ready; `raw` keeps the C structure for
    Device.script_frame_wait."""

    _skip = ("op_cycles", "op_count")

    def __init__(self, st):
        super().__init__(st)
        self.raw = st
        self.cycles = {}
        self.counts = {}
        for op in range(256):
            if st.op_count[op] or st.op_cycles[op]:
                name = op_name(op) or "op-0x%02x" % op
                self.cycles[name] = st.op_cycles[op]
                self.counts[name] = st.op_count[op]


class ReplayResult(_Result):
    """rdc_replay_result: records, mismatches, time, frames, frame_crc,
    width, height, frames_crc, truncated, untimed."""


class Stats(_Result):
    """rdc_stats: time, busy, stall, pixels, cmds, last_cycles,
    last_opcode, frames."""


class PinEdge(_Result):
    """rdc_pin_edge: pins, levels, time (None when unknown), wall_ns."""

    def __init__(self, st):
        super().__init__(st)
        if self.time == PIN_TIME_NONE:
            self.time = None


class Event(_Result):
    """rdc_event: type, irq, time, number, width, height, dropped; for a
    FRAME event `frame` holds its pixels."""

    frame = None


class HistoryEntry(_Result):
    """rdc_history_entry (docs/history.md); `op` is the opcode's name."""

    def __init__(self, st):
        super().__init__(st)
        self.calls = self.calls[:max(self.depth - 1, 0)]
        self.op = ("host" if self.opcode == HISTORY_OP_HOST
                   else op_name(self.opcode))


class HistoryWrite(_Result):
    """rdc_history_write: addr, len, count, stride, hash, entry."""

    _skip = ("entry",)

    def __init__(self, st):
        super().__init__(st)
        self.entry = HistoryEntry(st.entry)


class WaitResult:
    """When a wait ended: `time` (core cycles; None where the backend does
    not know it), `beam` ((x, y), None likewise), and for wait_irq the
    `irq` status bits it found."""

    def __init__(self, time=None, beam=None, irq=None, edge=None):
        self.time = time
        self.beam = beam
        self.irq = irq
        self.edge = edge

    @property
    def line(self):
        return self.beam[1] if self.beam else None

    def __repr__(self):
        return "<rdc.WaitResult time=%r beam=%r irq=%r>" % (
            self.time, self.beam, self.irq)


# ---- Batches ----------------------------------------------------------------

class Batch:
    """A growable array of command words (rdc_batch).  Every encoder of
    rdc.h's rdc_batch_* is a method that returns the batch, so calls
    chain: Batch().fg(1).fill_rect(0, 0, 8, 8).  A context manager."""

    def __init__(self):
        self._h = lib.rdc_batch_new()
        if not self._h:
            raise NoMemory(E_NOMEM, "rdc_batch_new")

    def close(self):
        if self._h:
            lib.rdc_batch_free(self._h)
            self._h = None

    __del__ = close

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _handle(self):
        if not self._h:
            raise ValueError("rdc: the batch is closed")
        return self._h

    def reset(self):
        lib.rdc_batch_reset(self._handle())
        return self

    def words(self):
        """The command words so far, as a list of ints."""
        n = c_size_t()
        p = lib.rdc_batch_words(self._handle(), byref(n))
        return list(p[:n.value]) if n.value else []

    def __len__(self):
        n = c_size_t()
        lib.rdc_batch_words(self._handle(), byref(n))
        return n.value

    def _do(self, name, *args):
        _check(getattr(lib, "rdc_batch_" + name)(self._handle(), *args),
               "rdc_batch_" + name)
        return self

    def cmd(self, op, flags=0, args=()):
        p, n, keep = _words(args)
        self._do("cmd", op, flags, p, n)
        del keep
        return self

    def load_clut(self, first, rgb):
        p, n, keep = _words(rgb)
        return self._do("load_clut", first, p, n)

    def polyline(self, xy):
        p, n = _points(xy)
        return self._do("polyline", p, n)

    def polygon(self, xy):
        p, n = _points(xy)
        return self._do("polygon", p, n)

    def fill_polygon(self, xy, nonzero=False):
        p, n = _points(xy)
        return self._do("fill_polygon", p, n, int(nonzero))

    def bezier(self, xy, steps=0):
        p, n = _points(xy)
        return self._do("bezier", p, steps)

    def hermite(self, xy, steps=0):
        p, n = _points(xy)
        return self._do("hermite", p, steps)

    def bspline(self, xy, steps=0):
        p, n = _points(xy)
        return self._do("bspline", p, n, steps)

    def mono(self, x, y, w, h, bits, transparent=False, fg=None, bg=None):
        """A 1 bpp bitmap; with fg and bg, one command that also sets them
        (rdc_batch_mono_colors)."""
        p, _, keep = _in(bits)
        if fg is None and bg is None:
            return self._do("mono", x, y, w, h, p, int(transparent))
        if fg is None or bg is None:
            raise ValueError("mono: fg and bg go together")
        return self._do("mono_colors", x, y, w, h, p, fg, bg,
                        int(transparent))

    def text(self, x, y, s, transparent=False):
        s = s.encode("latin-1") if isinstance(s, str) else bytes(s)
        return self._do("text", x, y, s, len(s), int(transparent))

    def transform(self, m=None):
        arr = None if m is None else (ctypes.c_int32 * 9)(*m)
        return self._do("transform", arr)

    def pattern_mono(self, rows, transparent=False):
        arr = (ctypes.c_uint8 * 8)(*rows)
        return self._do("pattern_mono", arr, int(transparent))

    def pattern_color(self, px):
        arr = (c_uint32 * 64)(*px)
        return self._do("pattern_color", arr)

    def triangle(self, xy, colour, z=(0, 0, 0), gouraud=False):
        p, _ = _points(xy)
        c = (c_uint32 * 3)(*colour)
        zz = (c_uint32 * 3)(*z)
        return self._do("triangle", p, c, zz, int(gouraud))

    def colorkey(self, key, enable=True):
        return self._do("colorkey", key, int(enable))


def _simple_encoder(name):
    def enc(self, *args):
        return self._do(name, *args)
    enc.__name__ = name
    enc.__doc__ = "rdc_batch_%s (rdc.h)." % name
    return enc


for _name in _lib.BATCH_ENCODERS:
    if not hasattr(Batch, _name):
        setattr(Batch, _name, _simple_encoder(_name))


# ---- Devices ----------------------------------------------------------------

def open(uri="sim:"):
    """Open a device by URI (rdc_open): "sim:", "sim:vram=16M",
    "unix:PATH", "tcp:HOST:PORT", "usb:", "fbdev:/dev/fbN",
    "drm:/dev/dri/cardN".  A context manager closes it."""
    return Device(uri)


class Device:
    """An open RDC-1 (rdc_dev).  Methods are rdc.h's rdc_* calls on it;
    registers, presets and formats may be given by name."""

    def __init__(self, uri="sim:", _handle=None):
        self.uri = uri
        self._h = None
        self._frame_size = None
        self._vcds = []
        if _handle is not None:
            self._h = _handle
            return
        h = c_void_p()
        _check(lib.rdc_open(uri.encode(), byref(h)), "rdc_open(%r)" % uri)
        self._h = h

    def close(self):
        """rdc_close, after the VCD dumps still open (newest first);
        closing twice is harmless."""
        if self._h:
            while self._vcds:
                self._vcds[-1].close()
            lib.rdc_close(self._h)
            self._h = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()

    def __repr__(self):
        return "<rdc.Device %s%s>" % (self.uri, "" if self._h else " closed")

    def _dev(self):
        if not self._h:
            raise ValueError("rdc: the device is closed")
        return self._h

    def _call(self, name, *args):
        return _check(getattr(lib, name)(self._dev(), *args), name, self)

    # device
    def reset(self):
        self._call("rdc_reset")

    def dev_error(self):
        """(code, info) of the device's error, read and cleared."""
        c, inf = c_uint32(), c_uint32()
        self._call("rdc_dev_error", byref(c), byref(inf))
        return c.value, inf.value

    def reg_read(self, reg):
        v = c_uint32()
        self._call("rdc_reg_read", reg_by_name(reg), byref(v))
        return v.value

    def reg_write(self, reg, value):
        self._call("rdc_reg_write", reg_by_name(reg), value & 0xFFFFFFFF)

    def vram_read(self, addr, length=None, into=None):
        """VRAM bytes at addr into a new bytearray of `length`, or into a
        writable buffer `into` (bytearray, numpy array ...)."""
        if into is None:
            into = bytearray(length)
        p, n, keep = _out(into)
        self._call("rdc_vram_read", addr, p, n)
        del keep
        return into

    def vram_write(self, addr, data):
        p, n, keep = _in(data)
        self._call("rdc_vram_write", addr, p, n)
        del keep

    def mode_set(self, preset, format=None, base=0):
        """rdc_mode_set; preset and format by number or name (format
        XRGB8888 unless given)."""
        fmt = FMT_XRGB8888 if format is None else format_by_name(format)
        self._call("rdc_mode_set", preset_by_name(preset), fmt, base)
        self._frame_size = None

    # commands
    def submit(self, words):
        """Command words (a Batch, a list of ints, or a buffer of
        little-endian 32-bit words) into the FIFO."""
        if isinstance(words, Batch):
            self._call("rdc_batch_submit", words._handle())
            return
        p, n, keep = _words(words)
        self._call("rdc_submit", p, n)
        del keep

    def _waited(self, irq=None, edge=None):
        t = beam = None
        tt, x, y = c_uint64(), c_uint32(), c_uint32()
        if lib.rdc_sim_time(self._dev(), byref(tt)) == 0:
            t = tt.value
        if lib.rdc_sim_beam(self._dev(), byref(x), byref(y)) == 0:
            beam = (x.value, y.value)
        return WaitResult(t, beam, irq, edge)

    def finish(self):
        """rdc_finish: every command submitted has completed."""
        self._call("rdc_finish")
        return self._waited()

    def fence_wait(self, value):
        self._call("rdc_fence_wait", value & 0xFFFFFFFF)
        return self._waited()

    def vblank_wait(self):
        self._call("rdc_vblank_wait")
        return self._waited()

    def idle_wait(self):
        self._call("rdc_idle_wait")
        return self._waited()

    def wait_line(self, line, fence=None):
        """Wait until the beam starts `line`: the display processor waits
        (WAIT_LINE), then runs a FENCE the host waits for, so commands
        submitted before run first.  rdc.h has no host-side line wait;
        this is the one every backend offers."""
        if fence is None:
            fence = (self.reg_read(REG_FENCE) + 1) & 0xFFFFFFFF
        with Batch() as b:
            b.wait_line(line).fence(fence)
            self.submit(b)
        return self.fence_wait(fence)

    def wait_irq(self, mask=None, timeout_us=0):
        """Wait for an interrupt: set IRQ_ENABLE to `mask` (RDC_IRQ_*
        bits) if given, wait for the IRQ pin's rising edge
        (rdc_pins_wait_edge) unless it is high already, and return the
        IRQ_STATUS bits found (WaitResult.irq), not cleared.  The pin's
        level is read again after each edge: one that is over already (a
        queued GPIO event on fbdev: and drm:) does not end the wait."""
        if mask is not None:
            self.reg_write(REG_IRQ_ENABLE, mask)
        edge = None
        while not self.pins_get() & PIN_IRQ:
            edge = self.pins_wait_edge(PIN_IRQ, EDGE_RISING, timeout_us)
        status = self.reg_read(REG_IRQ_STATUS)
        return self._waited(irq=status, edge=edge)

    def irq_clear(self, mask=None):
        """Write-one-to-clear IRQ_STATUS (all bits by default)."""
        self.reg_write(REG_IRQ_STATUS, IRQ_ALL if mask is None else mask)

    def readback(self, x, y, w, h, into=None):
        """Screen to host (rdc_readback): SRC-format rows, each padded to
        4 bytes, into a new bytearray or `into`."""
        if into is None:
            into = bytearray(h * ((w * 4 + 3) & ~3))
        p, n, keep = _out(into)
        got = self._call("rdc_readback", x, y, w, h, p, n)
        del keep
        return memoryview(into)[:got] if got < n else into

    def host_blit(self, x, y, w, h, pixels, pitch):
        p, _, keep = _in(pixels)
        self._call("rdc_host_blit", x, y, w, h, p, pitch)
        del keep

    # frames
    def frame_grab(self, into=None):
        """The last complete frame (rdc_frame_grab) as a Frame whose
        buffer librdc writes directly: a new bytearray, or `into` (a
        writable buffer: bytearray, numpy array, another Frame's data)."""
        w, h = c_uint32(), c_uint32()
        while True:
            if into is None and self._frame_size:
                fw, fh = self._frame_size
                buf = bytearray(fw * fh * 4)
            else:
                buf = into
            if buf is None:
                ret = lib.rdc_frame_grab(self._dev(), None, 0, byref(w),
                                         byref(h))
                if ret not in (0, E_RANGE):
                    _raise(ret, "rdc_frame_grab", self)
                self._frame_size = (w.value, h.value)
                continue
            p, n, keep = _out(buf)
            ret = lib.rdc_frame_grab(self._dev(), p, n // 4, byref(w),
                                     byref(h))
            del keep
            if ret == E_RANGE and into is None:
                self._frame_size = (w.value, h.value)
                continue
            _check(ret, "rdc_frame_grab", self)
            self._frame_size = (w.value, h.value)
            return Frame(buf, w.value, h.value)

    def frame_crc(self):
        crc = c_uint32()
        self._call("rdc_frame_crc", byref(crc))
        return crc.value

    def frame_wait(self):
        self._call("rdc_frame_wait")
        return self._waited()

    # pins
    def pins_get(self):
        v = c_uint32()
        self._call("rdc_pins_get", byref(v))
        return v.value

    def pins_set(self, mask, levels):
        self._call("rdc_pins_set", mask, levels)

    def pins_wait_edge(self, pins=PIN_TE, edges=EDGE_RISING, timeout_us=0):
        ev = _lib.PinEdge(size=ctypes.sizeof(_lib.PinEdge))
        self._call("rdc_pins_wait_edge_sized", pins, edges, timeout_us,
                   byref(ev))
        return PinEdge(ev)

    def pins_present(self, batch, timeout_us=0):
        ev = _lib.PinEdge(size=ctypes.sizeof(_lib.PinEdge))
        self._call("rdc_pins_present_sized", batch._handle(), timeout_us,
                   byref(ev))
        return PinEdge(ev)

    # simulation
    def sim_time(self):
        t = c_uint64()
        self._call("rdc_sim_time", byref(t))
        return t.value

    def sim_step(self, cycles):
        self._call("rdc_sim_step", cycles)

    def sim_run_until(self, t):
        self._call("rdc_sim_run_until", t)

    def sim_beam(self):
        x, y = c_uint32(), c_uint32()
        self._call("rdc_sim_beam", byref(x), byref(y))
        return x.value, y.value

    def sim_core_hz(self):
        hz = c_uint32()
        self._call("rdc_sim_core_hz", byref(hz))
        return hz.value

    def stats(self):
        st = _lib.Stats(size=ctypes.sizeof(_lib.Stats))
        self._call("rdc_stats_get_sized", byref(st))
        return Stats(st)

    # scripts
    def script_run(self, text, check=True):
        """Run .rdl text (rdc_script_run): a ScriptResult; a failing
        statement raises (the error's `result` is the ScriptResult) unless
        check is False."""
        data = text.encode() if isinstance(text, str) else bytes(text)
        res = _lib.ScriptResult(size=ctypes.sizeof(_lib.ScriptResult))
        ret = lib.rdc_script_run_sized(self._dev(), data, len(data),
                                       byref(res))
        return self._script_done(ret, res, "rdc_script_run", check)

    def script_run_file(self, path, check=True):
        res = _lib.ScriptResult(size=ctypes.sizeof(_lib.ScriptResult))
        ret = lib.rdc_script_run_file_sized(self._dev(), str(path).encode(),
                                            byref(res))
        return self._script_done(ret, res, "rdc_script_run_file(%s)" % path,
                                 check)

    def _script_done(self, ret, res, call, check):
        result = ScriptResult(res)
        result.status = ret
        if ret < 0 and check:
            try:
                _raise(ret, call + " line %d: %s" % (res.error_line,
                                                     result.error_msg), self)
            except Error as e:
                e.result = result
                raise
        return result

    def script_frame_wait(self, result):
        self._call("rdc_script_frame_wait", byref(result.raw))

    # events (unix:, tcp:, usb:)
    def subscribe(self, events, every=1, encoding=FRAME_RAW):
        self._call("rdc_subscribe", events, every, encoding)

    def event_next(self, timeout_ms=-1, into=None, max_pixels=None):
        """The next event (rdc_event_next): an Event; a frame event's
        pixels are written into `into` (a writable buffer a loop can
        reuse), else a new buffer of max_pixels, by default room for the
        largest frame the CRTC can scan (a frame that does not fit is
        lost: RDC_E_RANGE)."""
        ev = _lib.Event(size=ctypes.sizeof(_lib.Event))
        if into is None:
            if max_pixels is None:
                max_pixels = CRTC_MAX_DISPLAY * CRTC_MAX_DISPLAY
            into = bytearray(max_pixels * 4)
        p, n, keep = _out(into)
        self._call("rdc_event_next_sized", byref(ev), p, n // 4, timeout_ms)
        del keep
        out = Event(ev)
        if ev.type == EVENT_FRAME:
            out.frame = Frame(into, ev.width, ev.height)
        return out

    # recording, waveforms, history
    def record_start(self, path):
        """Record this handle's operations into a trace (rdc_record_start);
        the returned object stops it as a context manager."""
        self._call("rdc_record_start", str(path).encode())
        return _Recording(self)

    def record_stop(self):
        self._call("rdc_record_stop")

    def vcd_open(self, path):
        """Dump the chip's signals to a VCD file (sim: only): a Vcd, a
        context manager; closing the device closes it first."""
        h = c_void_p()
        self._call("rdc_vcd_open", str(path).encode(), byref(h))
        vcd = Vcd(h, self)
        self._vcds.append(vcd)
        return vcd

    def history_open(self, x=0, y=0, w=HISTORY_SCREEN, h=HISTORY_SCREEN,
                     flags=0):
        """Watch every VRAM write to a rectangle (sim: only): a History."""
        out = c_void_p()
        self._call("rdc_history_open", x, y, w, h, flags, byref(out))
        return History(out, self)


class _Recording:
    def __init__(self, dev):
        self.dev = dev

    def stop(self):
        if self.dev:
            dev, self.dev = self.dev, None
            dev.record_stop()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()


class Vcd:
    """A Value Change Dump being written (rdc_vcd)."""

    def __init__(self, handle, dev):
        self._h = handle
        self.dev = dev

    def close(self):
        """End the dump and close its file (before the device: the
        device's close does it for dumps still open)."""
        if self._h:
            h, self._h = self._h, None
            if self in self.dev._vcds:
                self.dev._vcds.remove(self)
            _check(lib.rdc_vcd_close(h), "rdc_vcd_close")

    def __del__(self):
        if self._h and self.dev._h:
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class History:
    """The writes to a watched rectangle (rdc_history): a sequence of
    HistoryEntry; writes() the write accesses (HISTORY_WRITES)."""

    def __init__(self, handle, dev=None):
        self._h = handle
        self.dev = dev

    def _handle(self):
        if not self._h:
            raise ValueError("rdc: the history is closed")
        return self._h

    def close(self):
        if self._h:
            lib.rdc_history_close(self._h)
            self._h = None

    __del__ = close

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def set_limit(self, n):
        _check(lib.rdc_history_set_limit(self._handle(), n),
               "rdc_history_set_limit")

    def __len__(self):
        return lib.rdc_history_count(self._handle())

    @property
    def dropped(self):
        return lib.rdc_history_dropped(self._handle())

    def __getitem__(self, n):
        if n < 0:
            n += len(self)
        if not 0 <= n < len(self):
            raise IndexError(n)
        e = _lib.HistoryEntry(size=ctypes.sizeof(_lib.HistoryEntry))
        _check(lib.rdc_history_get_sized(self._handle(), n, byref(e)),
               "rdc_history_get")
        return HistoryEntry(e)

    def at(self, x, y):
        """The entries of pixel (x, y), in order."""
        return [e for e in self if e.x == x and e.y == y]

    def writes(self):
        out = []
        for n in range(lib.rdc_history_write_count(self._handle())):
            w = _lib.HistoryWrite(size=ctypes.sizeof(_lib.HistoryWrite))
            w.entry.size = ctypes.sizeof(_lib.HistoryEntry)
            _check(lib.rdc_history_write_get_sized(self._handle(), n,
                                                   byref(w)),
                   "rdc_history_write_get")
            out.append(HistoryWrite(w))
        return out

    def first_diff(self, other):
        """Index of the first write access that differs, or None."""
        idx = c_size_t()
        r = _check(lib.rdc_history_first_diff(self._handle(),
                                              other._handle(), byref(idx)),
                   "rdc_history_first_diff")
        return idx.value if r else None


def replay_file(path, keep_device=False):
    """Play a trace on a fresh sim: device (rdc_replay_file): a
    ReplayResult, with .device the device afterwards if keep_device."""
    res = _lib.ReplayResult(size=ctypes.sizeof(_lib.ReplayResult))
    h = c_void_p()
    _check(lib.rdc_replay_file_sized(str(path).encode(), byref(res),
                                     byref(h) if keep_device else None),
           "rdc_replay_file(%s)" % path)
    out = ReplayResult(res)
    out.device = Device("sim:", _handle=h) if keep_device else None
    return out


def replay_history(path, x=0, y=0, w=HISTORY_SCREEN, h=HISTORY_SCREEN,
                   flags=0):
    """A trace replayed with a history open: (History, ReplayResult)."""
    res = _lib.ReplayResult(size=ctypes.sizeof(_lib.ReplayResult))
    hist = c_void_p()
    _check(lib.rdc_replay_history_sized(str(path).encode(), x, y, w, h,
                                        flags, byref(hist), byref(res),
                                        None),
           "rdc_replay_history(%s)" % path)
    return History(hist), ReplayResult(res)
