# SPDX-License-Identifier: LGPL-2.1-or-later
# SPDX-FileCopyrightText: 2026 The rdc authors
"""librdc.so.1 through ctypes: the library, its structures, its functions.

Which library, loaded at the first call: $RDC_LIBRARY if set (a path);
else, when the package sits in the source tree, the tree's
build/rel/librdc.so.1 if it has been built; else librdc.so.1 wherever the
dynamic loader finds it (an installed one).
"""

import ctypes
import os
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char, c_char_p, c_int,
                    c_int32, c_size_t, c_uint8, c_uint32, c_uint64, c_void_p)

from . import _headers

SONAME = "librdc.so.1"


def _find():
    path = os.environ.get("RDC_LIBRARY")
    if path:
        return path, "RDC_LIBRARY"
    top = _headers.source_tree()
    if top is not None:
        path = os.path.join(top, "build", "rel", SONAME)
        if os.path.exists(path):
            return path, "the source tree"
    return SONAME, "the dynamic loader"


def _mapped(name):
    """Where the loader found a library loaded by name (Linux)."""
    try:
        with open("/proc/self/maps") as f:
            for line in f:
                p = line.split(None, 5)[-1].strip()
                if os.path.basename(p).startswith(name):
                    return p
    except OSError:
        pass
    return name


def _load():
    path, how = _find()
    try:
        cdll = ctypes.CDLL(path)
        return cdll, path if "/" in path else _mapped(path)
    except OSError as e:
        hint = ""
        if how == "the dynamic loader" and _headers.source_tree():
            hint = " (build it with `make shared`, or set RDC_LIBRARY)"
        raise ImportError("rdc: cannot load %s from %s: %s%s"
                          % (path, how, e, hint)) from e


class Stats(Structure):
    _fields_ = [("size", c_uint32), ("time", c_uint64), ("busy", c_uint64),
                ("stall", c_uint64), ("pixels", c_uint64),
                ("cmds", c_uint32), ("last_cycles", c_uint32),
                ("last_opcode", c_uint32), ("frames", c_uint64)]


class PinEdge(Structure):
    _fields_ = [("size", c_uint32), ("pins", c_uint32),
                ("levels", c_uint32), ("time", c_uint64),
                ("wall_ns", c_uint64)]


class ScriptResult(Structure):
    _fields_ = [("size", c_uint32), ("op_cycles", c_uint64 * 256),
                ("op_count", c_uint64 * 256), ("error_line", c_uint32),
                ("error_col", c_uint32), ("error_msg", c_char * 160),
                ("readbacks", c_uint32), ("readback_crc", c_uint32),
                ("readback_words", c_uint32), ("frame_ready", c_uint32)]


class Event(Structure):
    _fields_ = [("size", c_uint32), ("type", c_uint32), ("irq", c_uint32),
                ("time", c_uint64), ("number", c_uint64),
                ("width", c_uint32), ("height", c_uint32),
                ("dropped", c_uint32)]


class ReplayResult(Structure):
    _fields_ = [("size", c_uint32), ("records", c_uint64),
                ("mismatches", c_uint64), ("time", c_uint64),
                ("frames", c_uint64), ("frame_crc", c_uint32),
                ("width", c_uint32), ("height", c_uint32),
                ("frames_crc", c_uint32), ("truncated", c_uint32),
                ("untimed", c_uint32)]


class HistoryEntry(Structure):
    _fields_ = [("size", c_uint32), ("x", c_uint32), ("y", c_uint32),
                ("format", c_uint32), ("before", c_uint32),
                ("after", c_uint32), ("cycle", c_uint64),
                ("frame", c_uint64), ("fetched", c_int32),
                ("opcode", c_uint32), ("cmd_index", c_uint32),
                ("source", c_uint32), ("line", c_uint32),
                ("cmd_addr", c_uint32), ("depth", c_uint32),
                ("calls", c_uint32 * 8), ("rop", c_uint32),
                ("alpha", c_uint32), ("colorkey", c_uint32),
                ("colorkey_on", c_uint32), ("pattern", c_uint32),
                ("fg", c_uint32), ("bg", c_uint32)]


class HistoryWrite(Structure):
    _fields_ = [("size", c_uint32), ("addr", c_uint32), ("len", c_uint32),
                ("count", c_uint32), ("stride", c_uint32),
                ("hash", c_uint64), ("entry", HistoryEntry)]


class Found(Structure):
    _fields_ = [("uri", c_char * 160), ("info", c_char * 160)]


FOUND_FN = CFUNCTYPE(None, POINTER(Found), c_void_p)

# Handles are opaque: plain pointers.
_dev = c_void_p
_p32 = POINTER(c_uint32)
_p64 = POINTER(c_uint64)
_vp = c_void_p
u32, u64, i = c_uint32, c_uint64, c_int

_PROTOS = {
    "rdc_version": (u32, []),
    "rdc_strerror": (c_char_p, [i]),
    "rdc_last_error_detail": (c_char_p, [i]),
    "rdc_dev_strerror": (c_char_p, [u32]),
    "rdc_open": (i, [c_char_p, POINTER(_dev)]),
    "rdc_list": (i, [FOUND_FN, _vp]),
    "rdc_close": (None, [_dev]),
    "rdc_reset": (i, [_dev]),
    "rdc_dev_error": (i, [_dev, _p32, _p32]),
    "rdc_reg_read": (i, [_dev, u32, _p32]),
    "rdc_reg_write": (i, [_dev, u32, u32]),
    "rdc_vram_read": (i, [_dev, u32, _vp, c_size_t]),
    "rdc_vram_write": (i, [_dev, u32, _vp, c_size_t]),
    "rdc_mode_set": (i, [_dev, u32, u32, u32]),
    "rdc_preset_size": (i, [u32, _p32, _p32]),
    "rdc_preset_by_name": (i, [c_char_p]),
    "rdc_submit": (i, [_dev, _vp, c_size_t]),
    "rdc_finish": (i, [_dev]),
    "rdc_fence_wait": (i, [_dev, u32]),
    "rdc_vblank_wait": (i, [_dev]),
    "rdc_idle_wait": (i, [_dev]),
    "rdc_readback": (i, [_dev, i, i, u32, u32, _vp, c_size_t]),
    "rdc_host_blit": (i, [_dev, i, i, u32, u32, _vp, c_size_t]),
    "rdc_frame_grab": (i, [_dev, _vp, c_size_t, _p32, _p32]),
    "rdc_frame_crc": (i, [_dev, _p32]),
    "rdc_frame_wait": (i, [_dev]),
    "rdc_batch_new": (_vp, []),
    "rdc_batch_free": (None, [_vp]),
    "rdc_batch_reset": (None, [_vp]),
    "rdc_batch_words": (_p32, [_vp, POINTER(c_size_t)]),
    "rdc_batch_submit": (i, [_dev, _vp]),
    "rdc_batch_cmd": (i, [_vp, u32, u32, _vp, c_size_t]),
    "rdc_pins_get": (i, [_dev, _p32]),
    "rdc_pins_set": (i, [_dev, u32, u32]),
    "rdc_pins_wait_edge_sized": (i, [_dev, u32, u32, u64,
                                     POINTER(PinEdge)]),
    "rdc_pins_present_sized": (i, [_dev, _vp, u64, POINTER(PinEdge)]),
    "rdc_sim_time": (i, [_dev, _p64]),
    "rdc_sim_step": (i, [_dev, u64]),
    "rdc_sim_run_until": (i, [_dev, u64]),
    "rdc_sim_beam": (i, [_dev, _p32, _p32]),
    "rdc_stats_get_sized": (i, [_dev, POINTER(Stats)]),
    "rdc_sim_core_hz": (i, [_dev, _p32]),
    "rdc_vcd_open": (i, [_dev, c_char_p, POINTER(_vp)]),
    "rdc_vcd_close": (i, [_vp]),
    "rdc_script_frame_wait": (i, [_dev, POINTER(ScriptResult)]),
    "rdc_script_run_sized": (i, [_dev, c_char_p, c_size_t,
                                 POINTER(ScriptResult)]),
    "rdc_script_run_file_sized": (i, [_dev, c_char_p,
                                      POINTER(ScriptResult)]),
    "rdc_op_name": (c_char_p, [u32]),
    "rdc_reg_count": (c_size_t, []),
    "rdc_reg_info": (c_char_p, [c_size_t, _p32]),
    "rdc_reg_by_name": (i, [c_char_p, _p32]),
    "rdc_subscribe": (i, [_dev, u32, u32, u32]),
    "rdc_event_next_sized": (i, [_dev, POINTER(Event), _vp, c_size_t, i]),
    "rdc_replay_file_sized": (i, [c_char_p, POINTER(ReplayResult),
                                  POINTER(_dev)]),
    "rdc_record_start": (i, [_dev, c_char_p]),
    "rdc_record_stop": (i, [_dev]),
    "rdc_image_bound": (c_size_t, [u32, u32, u32, u32]),
    "rdc_image_encode": (i, [u32, _vp, u32, u32, u32, c_size_t, _vp,
                             c_size_t, POINTER(c_size_t)]),
    "rdc_image_samples": (i, [_vp, u32, u32, c_size_t, u32, _vp]),
    "rdc_image_png_read": (i, [c_char_p, POINTER(_p32), _p32, _p32]),
    "rdc_history_open": (i, [_dev, u32, u32, u32, u32, u32,
                             POINTER(_vp)]),
    "rdc_history_set_limit": (i, [_vp, c_size_t]),
    "rdc_history_count": (c_size_t, [_vp]),
    "rdc_history_dropped": (u64, [_vp]),
    "rdc_history_get_sized": (i, [_vp, c_size_t, POINTER(HistoryEntry)]),
    "rdc_history_write_count": (c_size_t, [_vp]),
    "rdc_history_write_get_sized": (i, [_vp, c_size_t,
                                        POINTER(HistoryWrite)]),
    "rdc_history_first_diff": (i, [_vp, _vp, POINTER(c_size_t)]),
    "rdc_replay_history_sized": (i, [c_char_p, u32, u32, u32, u32, u32,
                                     POINTER(_vp), POINTER(ReplayResult),
                                     POINTER(_dev)]),
    "rdc_history_close": (None, [_vp]),
    "rdc_png_write": (i, [c_char_p, _vp, u32, u32, c_size_t]),
}

# The batch encoders: (name, argument types after the batch).
_BATCH = {
    "nop": [], "fence": [u32], "wait_vblank": [], "wait_line": [u32],
    "reg_write": [u32, u32], "load_clut": [u32, _vp, c_size_t],
    "fg": [u32], "bg": [u32], "rop": [u32], "clip": [i, i, i, i],
    "fg_next": [u32],
    "dst": [u32, u32, u32, u32, u32], "src": [u32, u32, u32, u32, u32],
    "pixel": [i, i], "line": [i, i, i, i], "polyline": [_vp, c_size_t],
    "rect": [i, i, u32, u32], "fill_rect": [i, i, u32, u32],
    "circle": [i, i, u32], "fill_circle": [i, i, u32],
    "ellipse": [i, i, u32, u32], "fill_ellipse": [i, i, u32, u32],
    "blit": [i, i, i, i, u32, u32], "mono": [i, i, u32, u32, _vp, i],
    "mono_colors": [i, i, u32, u32, _vp, u32, u32, i],
    "text": [i, i, c_char_p, c_size_t, i], "pen": [u32, u32, u32],
    "dash": [u32, u32, u32], "polygon": [_vp, c_size_t],
    "arc": [i, i, u32, u32, u32, u32, u32], "bezier": [_vp, u32],
    "hermite": [_vp, u32], "bspline": [_vp, c_size_t, u32],
    "transform": [_vp], "viewport": [c_int32] * 4 + [i] * 4,
    "fill_polygon": [_vp, c_size_t, i], "flood": [i, i, u32, u32],
    "pattern_none": [], "pattern_mono": [_vp, i], "pattern_color": [_vp],
    "triangle": [_vp, _vp, _vp, i], "zbuf": [u32, u32, u32],
    "zbuf_off": [], "clear_z": [u32], "aa_line": [i, i, i, i],
    "aa_circle": [i, i, u32], "aa_ellipse": [i, i, u32, u32],
    "aa_ramp": [u32], "alpha": [u32], "colorkey": [u32, i],
    "call": [u32], "ret": [], "jump": [u32],
}
for _name, _args in _BATCH.items():
    _PROTOS["rdc_batch_" + _name] = (i, [_vp] + _args)


class _Library:
    """librdc, loaded and its prototypes set at the first call, so that
    importing rdc (pytest loads the plugin of an installed copy in every
    run) never fails for want of the library."""

    path = None

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        cdll = self.__dict__.get("_cdll")
        if cdll is None:
            cdll, self.path = _load()
            for fname, (res, args) in _PROTOS.items():
                fn = getattr(cdll, fname)
                fn.restype = res
                fn.argtypes = args
            self._cdll = cdll
        fn = getattr(cdll, name)
        setattr(self, name, fn)
        return fn


lib = _Library()

BATCH_ENCODERS = tuple(_BATCH)
libc_free = ctypes.CDLL(None).free
libc_free.argtypes = [c_void_p]
libc_free.restype = None
uint8_p = POINTER(c_uint8)
