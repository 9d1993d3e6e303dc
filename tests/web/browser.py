#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""The web page in a real browser: rdcd --web, headless Chromium driven
through chromedriver's WebDriver (W3C) HTTP interface, Python's standard
library only.

rdcd runs a scene (tests/web/scene.rdl) and `rdcctl run -o` keeps the frame
it scanned out; the page's screenshot must show that frame, pixel for
pixel, in the canvas (one canvas pixel per screen pixel: the page does not
scale).  Then tests/web/draw.rdl changes part of the picture and the
screenshot must follow.  The status table must name the mode.

usage: browser.py BINDIR   (BINDIR holds rdcd and rdcctl)
RDC_WEB_SHOT=FILE.png also keeps the last screenshot (docs/web.png).
Exit 0: passed; 77: skipped (the reason on stdout); anything else: failed.
"""
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request
import zlib

SKIP = 77
# How long a step may take before the test fails (a loaded host, ASan).
DEADLINE_S = 60


def skip(why):
    print("SKIP: " + why)
    sys.exit(SKIP)


def fail(why):
    print("FAIL: " + why)
    sys.exit(1)


def unfilter(f, line, prev, bpp):
    """Undo one row's PNG filter (RFC 2083, 6), in place where it can."""
    n = len(line)
    if f == 1:
        for i in range(bpp, n):
            line[i] = (line[i] + line[i - bpp]) & 255
    elif f == 2:
        line = bytearray((x + u) & 255 for x, u in zip(line, prev))
    elif f == 3:
        for i in range(n):
            a = line[i - bpp] if i >= bpp else 0
            line[i] = (line[i] + ((a + prev[i]) >> 1)) & 255
    elif f == 4:
        for i in range(bpp):
            line[i] = (line[i] + prev[i]) & 255
        for i in range(bpp, n):
            a, b, c = line[i - bpp], prev[i], prev[i - bpp]
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - c - c)
            if pa <= pb and pa <= pc:
                line[i] = (line[i] + a) & 255
            elif pb <= pc:
                line[i] = (line[i] + b) & 255
            else:
                line[i] = (line[i] + c) & 255
    elif f != 0:
        raise ValueError("PNG filter %d" % f)
    return line


def png_decode(data):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA
    PNG, not interlaced: what rdcctl and Chromium write."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, hdr = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    w, h, depth, ctype, _, _, interlace = hdr
    if depth != 8 or ctype not in (2, 6) or interlace:
        raise ValueError("PNG type %d depth %d not handled" % (ctype, depth))
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(idat)
    stride = w * bpp
    prev = bytearray(stride)
    rows = []
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = unfilter(f, bytearray(raw[y * (stride + 1) + 1:
                                         (y + 1) * (stride + 1)]),
                        prev, bpp)
        rows.append([tuple(line[j:j + 3]) for j in range(0, stride, bpp)])
        prev = line
    return w, h, rows


class WebDriver:
    def __init__(self, port):
        self.base = "http://127.0.0.1:%d" % port
        self.sid = None

    def call(self, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else None
        req = urllib.request.Request(self.base + path, data=data,
                                     method=method)
        req.add_header("Content-Type", "application/json")
        try:
            with urllib.request.urlopen(req, timeout=DEADLINE_S) as r:
                return json.loads(r.read())["value"]
        except urllib.error.HTTPError as e:
            raise RuntimeError("%s %s: %s" % (method, path,
                                              e.read()[:300])) from None

    def session(self, chromium, profile):
        args = ["--headless=new", "--no-sandbox", "--disable-gpu",
                "--disable-dev-shm-usage", "--window-size=1200,800",
                "--force-device-scale-factor=1", "--hide-scrollbars",
                "--force-color-profile=srgb", "--no-first-run",
                "--user-data-dir=" + profile]
        caps = {"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium, "args": args}}}}
        self.sid = self.call("POST", "/session", caps)["sessionId"]

    def go(self, url):
        self.call("POST", "/session/%s/url" % self.sid, {"url": url})

    def js(self, script):
        return self.call("POST", "/session/%s/execute/sync" % self.sid,
                         {"script": script, "args": []})

    def screenshot(self):
        return base64.b64decode(
            self.call("GET", "/session/%s/screenshot" % self.sid))

    def capture(self, x, y, w, h):
        """The browser's own capture of a part of the page (Chromium's
        Page.captureScreenshot through chromedriver), at one device
        pixel per CSS pixel; optimizeForSpeed gives a PNG that is
        quick to decode here."""
        r = self.call("POST", "/session/%s/goog/cdp/execute" % self.sid,
                      {"cmd": "Page.captureScreenshot",
                       "params": {"format": "png", "optimizeForSpeed": True,
                                  "clip": {"x": x, "y": y, "width": w,
                                           "height": h, "scale": 1}}})
        return base64.b64decode(r["data"])

    def quit(self):
        if self.sid:
            try:
                self.call("DELETE", "/session/%s" % self.sid)
            except Exception:
                pass


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def wait_for(what, fn):
    end = time.monotonic() + DEADLINE_S
    while True:
        v = fn()
        if v:
            return v
        if time.monotonic() > end:
            fail("no %s in %d s" % (what, DEADLINE_S))
        time.sleep(0.1)


def mismatches(wd, expect):
    """Pixels of the canvas on screen that differ from the frame, or None
    while the canvas does not have the frame's size yet."""
    ew, eh, erows = expect
    r = wd.js("const r = document.getElementById('screen')"
              ".getBoundingClientRect();"
              "return [r.left, r.top, r.width, r.height,"
              " window.devicePixelRatio];")
    left, top, cw, ch, dpr = r
    if (cw, ch) != (ew, eh):
        return None
    if dpr != 1 or left != int(left) or top != int(top):
        fail("the canvas is scaled or off the pixel grid: %r" % (r,))
    sw, sh, srows = png_decode(wd.capture(int(left), int(top), ew, eh))
    if (sw, sh) != (ew, eh):
        fail("a %dx%d capture of the %dx%d canvas" % (sw, sh, ew, eh))
    bad = 0
    for y in range(eh):
        if srows[y] != erows[y]:
            bad += sum(1 for a, b in zip(srows[y], erows[y]) if a != b)
    return bad


def expect_page(wd, expect, what):
    last = [None]

    def ok():
        last[0] = mismatches(wd, expect)
        return last[0] == 0
    end = time.monotonic() + DEADLINE_S
    while not ok():
        if time.monotonic() > end:
            fail("%s: the page never showed the frame (last: %s pixels "
                 "differ)" % (what, last[0]))
        time.sleep(0.2)
    print("ok: %s: the canvas equals the %dx%d frame" %
          (what, expect[0], expect[1]))


def main():
    if len(sys.argv) != 2:
        fail("usage: browser.py BINDIR")
    bindir = sys.argv[1]
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if not chromium or not driver:
        skip("no chromium or chromedriver (Debian: chromium "
             "chromium-driver; scripts/deps.sh installs them)")
    for prog in ("rdcd", "rdcctl"):
        if not os.access(os.path.join(bindir, prog), os.X_OK):
            fail("no %s in %s (build it first)" % (prog, bindir))
    tmp = tempfile.mkdtemp(prefix="rdc-web-")
    procs = []
    wd = None
    try:
        log = open(os.path.join(tmp, "rdcd.log"), "w+")
        sock = os.path.join(tmp, "rdc.sock")
        procs.append(subprocess.Popen(
            [os.path.join(bindir, "rdcd"), "--listen", "unix:" + sock,
             "--web", "127.0.0.1:0"], stderr=log))

        def url():
            log.seek(0)
            for line in log.read().splitlines():
                if "web page at " in line:
                    return line.split("web page at ")[1].strip()
            if procs[0].poll() is not None:
                fail("rdcd exited: " + open(log.name).read())
            return None
        page = wait_for("web page line from rdcd", url)
        dport = free_port()
        procs.append(subprocess.Popen(
            [driver, "--port=%d" % dport], stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL))
        wd = WebDriver(dport)

        def ready():
            try:
                return wd.call("GET", "/status").get("ready")
            except Exception:
                return False
        wait_for("chromedriver", ready)
        try:
            wd.session(chromium, os.path.join(tmp, "profile"))
        except RuntimeError as e:
            skip("chromium does not start here: %s" % e)
        wd.go(page)

        ctl = [os.path.join(bindir, "rdcctl"), "--connect", "unix:" + sock]
        for what, script in (("scene.rdl", "tests/web/scene.rdl"),
                             ("draw.rdl over it", "tests/web/draw.rdl")):
            out = os.path.join(tmp, "frame.png")
            r = subprocess.run(ctl + ["run", script, "-o", out],
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, timeout=DEADLINE_S)
            if r.returncode:
                fail("rdcctl run %s: %s" % (script, r.stderr.decode()))
            with open(out, "rb") as f:
                expect = png_decode(f.read())
            expect_page(wd, expect, what)
        mode = wd.js("return document.getElementById('mode').textContent;")
        if not mode.startswith("640x480"):
            fail("the status table says mode %r, not 640x480" % mode)
        pins = wd.js("return document.getElementById('pins').textContent;")
        if "TE" not in pins or "RESET_N" not in pins:
            fail("the status table shows no pins: %r" % pins)
        print("ok: status: mode %r, pins %r" % (mode, pins))
        shot = os.environ.get("RDC_WEB_SHOT")
        if shot:
            with open(shot, "wb") as f:
                f.write(wd.screenshot())
    finally:
        if wd:
            wd.quit()
        for p in procs:
            p.terminate()
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
