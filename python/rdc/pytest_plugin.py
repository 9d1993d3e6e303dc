# SPDX-License-Identifier: LGPL-2.1-or-later
# SPDX-FileCopyrightText: 2026 The rdc authors
"""pytest fixtures for testing the RDC-1 (docs/python.md).

    rdc_sim      a fresh chip per test: an in-process sim: device, or the
                 device --rdc-uri names, reset; @pytest.mark.rdc_mode(
                 "640x480", "i8") sets its mode (in force, a frame of it
                 scanned, when the test starts); @pytest.mark.rdc_sim_only
                 skips a test that needs the simulator itself under
                 another --rdc-uri
    rdcd         rdcd --stepped on a socket of its own, stopped after the
                 test; .uri, .open(); @pytest.mark.rdcd_args(...) adds
                 options
    frame_equal  frame_equal(frame_or_device, expected): expected a PNG,
                 a CRC-32 or a Frame; on a difference it writes the
                 expected, actual and difference pictures and fails
                 naming the first differing pixel

Installed, pytest loads it by itself (the pytest11 entry point); from the
source tree: `-p rdc.pytest_plugin`, or pytest_plugins in a conftest.py.
"""

import os
import re
import shutil
import signal
import subprocess
import tempfile
import time

import pytest

import rdc


def pytest_addoption(parser):
    g = parser.getgroup("rdc", "RDC-1 hardware-model tests")
    g.addoption("--rdc-uri", default=os.environ.get("RDC_URI", "sim:"),
                help="device the rdc_sim fixture opens and resets "
                "(default $RDC_URI, else sim:): unix:PATH, tcp:HOST:PORT, "
                "fbdev:/dev/fbN, drm:/dev/dri/cardN, usb:")
    g.addoption("--rdcd", default=os.environ.get("RDC_RDCD"),
                help="the rdcd program of the rdcd fixture (default "
                "$RDC_RDCD, the source tree's build/rel/rdcd, then PATH)")
    g.addoption("--rdc-artifacts", default=None,
                help="directory for frame_equal's pictures (default: "
                "each test's tmp_path)")
    g.addoption("--rdc-bless", action="store_true",
                help="frame_equal writes the actual frame to an expected "
                "PNG that is missing or differs, instead of failing")


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "rdc_mode(preset, format='xrgb8888', base=0): the mode "
        "the rdc_sim fixture programs before the test")
    config.addinivalue_line(
        "markers", "rdc_sim_only: the test needs the in-process simulator "
        "(pixel history, VCD, exact edge times); skipped under another "
        "--rdc-uri")
    config.addinivalue_line(
        "markers", "rdcd_args(*args): more options for the rdcd fixture's "
        "daemon")


def _is_sim(uri):
    return uri in ("", "sim") or uri.startswith("sim:")


@pytest.fixture
def rdc_sim(request):
    """A fresh RDC-1: rdc.open(--rdc-uri), reset with RESET_N and BL_EN
    high unless it is a new sim:, in the mode of the test's rdc_mode
    marker; closed after the test."""
    uri = request.config.getoption("rdc_uri")
    if not _is_sim(uri) and request.node.get_closest_marker("rdc_sim_only"):
        pytest.skip("needs the in-process simulator, not %s" % uri)
    dev = rdc.open(uri)
    try:
        if not _is_sim(uri):
            # as a new chip: reset, and the inputs high (a pin keeps the
            # level the last test drove it to)
            dev.reset()
            try:
                dev.pins_set(rdc.PINS_IN, rdc.PINS_IN)
            except rdc.NotSupported:  # fbdev:, drm: built without libgpiod
                pass
        m = request.node.get_closest_marker("rdc_mode")
        if m is not None:
            dev.mode_set(*m.args, **m.kwargs)
            dev.frame_wait()  # latched, and a whole frame scanned in it
        yield dev
    finally:
        dev.close()


def _find_rdcd(config):
    exe = config.getoption("rdcd")
    if exe:
        return exe
    top = rdc._headers.source_tree()
    if top and os.access(os.path.join(top, "build/rel/rdcd"), os.X_OK):
        return os.path.join(top, "build/rel/rdcd")
    return shutil.which("rdcd")


class Rdcd:
    """A running rdcd: `uri` (its UNIX socket) to rdc.open, `uris` every
    address it listens on (as its --ready-file lists them: a tcp: one
    with the port the kernel picked for PORT 0), `process`, `log`."""

    def __init__(self, exe, args):
        self.dir = tempfile.mkdtemp(prefix="rdcd-")
        self.socket = os.path.join(self.dir, "rdc.sock")
        self.uri = "unix:" + self.socket
        self.log = os.path.join(self.dir, "rdcd.log")
        ready = os.path.join(self.dir, "ready")
        self.args = [exe, "--stepped", "--listen", self.uri,
                     "--ready-file", ready] + list(args)
        with open(self.log, "wb") as log:
            self.process = subprocess.Popen(self.args, stdout=log,
                                            stderr=subprocess.STDOUT)
        # not a measurement: how long to give a daemon that never comes up
        deadline = time.monotonic() + 30
        while not os.path.exists(ready):
            if self.process.poll() is not None or \
                    time.monotonic() > deadline:
                self.stop()
                raise RuntimeError("rdcd did not start (%s): %s"
                                   % (" ".join(self.args), self.output()))
            time.sleep(0.01)
        with open(ready, encoding="utf-8") as f:
            self.uris = f.read().split()

    def output(self):
        try:
            with open(self.log, encoding="utf-8", errors="replace") as f:
                return f.read()
        except OSError:
            return ""

    def open(self, observe=False):
        return rdc.open(self.uri + ("?observe" if observe else ""))

    def stop(self):
        """SIGTERM, then the exit status (None if it had to be killed)."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
                return None
        return self.process.returncode

    def cleanup(self):
        shutil.rmtree(self.dir, ignore_errors=True)


@pytest.fixture
def rdcd(request):
    """rdcd --stepped on a private UNIX socket for this test."""
    exe = _find_rdcd(request.config)
    if not exe:
        pytest.skip("rdcd not found (build it with make, or give --rdcd)")
    m = request.node.get_closest_marker("rdcd_args")
    d = Rdcd(exe, m.args if m else ())
    try:
        yield d
        rc = d.stop()
        if rc not in (0, -signal.SIGTERM):
            pytest.fail("rdcd exited with status %s: %s" % (rc, d.output()))
    finally:
        d.stop()
        d.cleanup()


# ---- frame_equal ------------------------------------------------------------

_MASK = 0xFFFFFF


def _pixels(frame):
    return frame.words()


def _first_diff(a, b):
    """(index, number of differing pixels) of two same-sized frames."""
    if rdc.numpy is not None:
        d = numpy_ne(a, b)
        idx = rdc.numpy.flatnonzero(d)
        return (int(idx[0]) if len(idx) else None), int(len(idx))
    pa, pb = _pixels(a), _pixels(b)
    first, count = None, 0
    w = a.width
    for y in range(a.height):
        ra, rb = pa[y * w:(y + 1) * w], pb[y * w:(y + 1) * w]
        if ra == rb:
            continue
        for x in range(w):
            if (ra[x] ^ rb[x]) & _MASK:
                count += 1
                if first is None:
                    first = y * w + x
    return first, count


def numpy_ne(a, b):
    return (a.array() & _MASK) != (b.array() & _MASK)


def diff_frame(expected, actual):
    """A picture of where two same-sized frames differ: red where they
    do, the actual frame at a quarter of its brightness elsewhere."""
    out = bytearray(len(actual) * 4)
    res = rdc.Frame(out, actual.width, actual.height)
    if rdc.numpy is not None:
        np = rdc.numpy
        dim = (actual.array() >> 2) & 0x3F3F3F
        res.array()[:] = np.where(numpy_ne(expected, actual),
                                  np.uint32(0xFF0000), dim)
        return res
    pe, pa = _pixels(expected), _pixels(actual)
    po = memoryview(out).cast("I")
    for n in range(len(actual)):
        po[n] = 0xFF0000 if (pe[n] ^ pa[n]) & _MASK else \
            (pa[n] >> 2) & 0x3F3F3F
    return res


class FrameMismatch(AssertionError):
    """frame_equal's failure: `first` ((x, y), or None), `expected_pixel`,
    `actual_pixel`, `count` of differing pixels and the `pictures` it
    wrote."""

    first = expected_pixel = actual_pixel = count = None
    pictures = ()


class FrameEqual:
    def __init__(self, request, outdir, bless):
        self.outdir = outdir
        self.bless = bless
        self.base = re.sub(r"[^\w.-]+", "_", request.node.name)
        self.calls = 0

    def _name(self, name):
        self.calls += 1
        if name:
            return name
        return self.base if self.calls == 1 else \
            "%s-%d" % (self.base, self.calls)

    def __call__(self, actual, expected, name=None):
        """Check a frame (or a device's frame, grabbed now) against a PNG
        path, a CRC-32 (int) or another Frame."""
        if isinstance(actual, rdc.Device):
            actual = actual.frame_grab()
        name = self._name(name)
        os.makedirs(self.outdir, exist_ok=True)
        stem = os.path.join(self.outdir, name)
        if isinstance(expected, int):
            crc = actual.crc()
            if crc == expected:
                return True
            actual.save_png(stem + "-actual.png")
            raise FrameMismatch(
                "frame crc32 %08x, expected %08x (%dx%d); the actual "
                "frame: %s-actual.png" % (crc, expected, actual.width,
                                          actual.height, stem))
        path = None
        if not isinstance(expected, rdc.Frame):
            path = os.fspath(expected)
            if not os.path.exists(path):
                if self.bless:
                    actual.save_png(path)
                    return True
                actual.save_png(stem + "-actual.png")
                raise FrameMismatch(
                    "no expected picture %s; the actual frame is in "
                    "%s-actual.png (--rdc-bless keeps it as the expected "
                    "one)" % (path, stem))
            expected = rdc.png_read(path)
        what = path or "the expected frame"
        if (expected.width, expected.height) != (actual.width,
                                                 actual.height):
            first, count = None, None
        else:
            first, count = _first_diff(expected, actual)
            if first is None:
                return True
        if self.bless and path:
            actual.save_png(path)
            return True
        pictures = [stem + "-expected.png", stem + "-actual.png"]
        expected.save_png(pictures[0])
        actual.save_png(pictures[1])
        if first is None:
            err = FrameMismatch(
                "frame is %dx%d, %s %dx%d; pictures: %s"
                % (actual.width, actual.height, what, expected.width,
                   expected.height, ", ".join(pictures)))
            err.first = err.expected_pixel = err.actual_pixel = None
            err.count = None
            err.pictures = pictures
            raise err
        pictures.append(stem + "-diff.png")
        diff_frame(expected, actual).save_png(pictures[2])
        x, y = first % actual.width, first // actual.width
        ev, av = expected.pixel(x, y), actual.pixel(x, y)
        err = FrameMismatch(
            "frame differs from %s: first differing pixel (%d, %d): "
            "expected #%06x, actual #%06x; %d of %d pixels differ; "
            "pictures: %s" % (what, x, y, ev, av, count, len(actual),
                              ", ".join(pictures)))
        err.first, err.expected_pixel, err.actual_pixel = (x, y), ev, av
        err.count, err.pictures = count, pictures
        raise err


@pytest.fixture
def frame_equal(request, tmp_path):
    """frame_equal(frame_or_device, expected, name=None): see FrameEqual.
    Pictures go to --rdc-artifacts, else the test's tmp_path."""
    outdir = request.config.getoption("rdc_artifacts") or str(tmp_path)
    return FrameEqual(request, outdir,
                      request.config.getoption("rdc_bless"))
