#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""What web viewers cost rdcd's other clients (docs/web.md).

    python3 bench/web_viewers.py BUILD_DIR [N ...]

BUILD_DIR/rdcd runs paced at 1024x768@60 with --listen unix: and --web
on a loopback port.  A drawing client changes a 64x64 patch of the
screen every 10 ms, so every frame has damage for the viewers.  For each
N (default: 0 and 200), N WebSocket viewers (a child process that reads
everything it is sent) connect and each gets its first picture; then
an observer on the unix: socket reads a register 5,000 times (median,
99th percentile and worst round trip, in microseconds), and one more
viewer connects with the N watching (`newcomer_in`: it got its first
status message within 5 s).  One JSON line per N; `viewer_kib_s` is
what each viewer received a second meanwhile (the damage reached them).
"""
import base64
import json
import os
import selectors
import signal
import socket
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

READS = 5000
PATCH_EVERY_S = 0.010


def ws_connect(port, timeout=10.0):
    """A WebSocket to rdcd's page server, upgraded; the socket."""
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    key = base64.b64encode(os.urandom(16)).decode()
    s.sendall(("GET /ws HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n"
               "Upgrade: websocket\r\nConnection: Upgrade\r\n"
               "Sec-WebSocket-Key: %s\r\nSec-WebSocket-Version: 13\r\n\r\n"
               % (port, key)).encode())
    head = b""
    while b"\r\n\r\n" not in head:
        got = s.recv(4096)
        if not got:
            raise OSError("closed before the upgrade")
        head += got
    if not head.startswith(b"HTTP/1.1 101"):
        raise OSError("no upgrade: " + head.split(b"\r\n")[0].decode())
    # a viewer's first message is its token: empty, masked, as rdc.js
    s.sendall(b"\x81\x80" + os.urandom(4))
    return s, head.split(b"\r\n\r\n", 1)[1]


def first_message(s, rest, timeout):
    """Wait for the first whole WebSocket message after the upgrade."""
    s.settimeout(timeout)
    buf = rest
    while True:
        if len(buf) >= 2:
            n = buf[1] & 0x7F
            off = 2
            if n == 126:
                off = 4
                n = int.from_bytes(buf[2:4], "big") if len(buf) >= 4 else -1
            elif n == 127:
                off = 10
                n = int.from_bytes(buf[2:10], "big") if len(buf) >= 10 else -1
            if n >= 0 and len(buf) >= off + n:
                return True
        got = s.recv(65536)
        if not got:
            return False
        buf += got


def viewers_main(port, n, ready_fd):
    """Child: n viewers that read everything; b'1' on ready_fd once each
    has had a first message, then read until killed."""
    sel = selectors.DefaultSelector()
    for _ in range(n):
        s, rest = ws_connect(port)
        if not first_message(s, rest, 10.0):
            os.write(ready_fd, b"0")
            return
        s.setblocking(False)
        sel.register(s, selectors.EVENT_READ)
    os.write(ready_fd, b"1")
    total = [0]

    def report(*_):
        os.write(ready_fd, b"%d\n" % total[0])
        os._exit(0)
    signal.signal(signal.SIGTERM, report)
    while True:
        for key, _ in sel.select():
            try:
                got = key.fileobj.recv(1 << 20)
                if not got:
                    sel.unregister(key.fileobj)
                total[0] += len(got)
            except BlockingIOError:
                pass


def drawer_main(uri):
    """Child: a 64x64 patch in a new colour every PATCH_EVERY_S."""
    import rdc
    dev = rdc.open(uri)
    i = 0
    while True:
        i += 1
        x, y = (i * 37) % 960, (i * 23) % 704
        dev.submit(rdc.Batch().fg(0xff000000 | (i * 0x10101) & 0xffffff)
                   .fill_rect(x, y, 64, 64))
        time.sleep(PATCH_EVERY_S)


def spawn(fn, *args):
    pid = os.fork()
    if pid == 0:
        try:
            fn(*args)
        finally:
            os._exit(0)
    return pid


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def rtt(dev, reg):
    lat = []
    for _ in range(READS):
        t0 = time.perf_counter()
        dev.reg_read(reg)
        lat.append(time.perf_counter() - t0)
    lat.sort()
    return (lat[len(lat) // 2] * 1e6, lat[len(lat) * 99 // 100] * 1e6,
            lat[-1] * 1e6)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build = sys.argv[1]
    counts = [int(a) for a in sys.argv[2:]] or [0, 200]
    os.environ.setdefault("RDC_LIBRARY", os.path.join(build, "librdc.so"))
    import rdc
    tmp = tempfile.mkdtemp(prefix="rdc-webv-")
    sock = os.path.join(tmp, "rdc.sock")
    uri = "unix:" + sock
    port = free_port()
    daemon = subprocess.Popen(
        [os.path.join(build, "rdcd"), "--listen", uri, "--mode", "1024x768",
         "--web", "127.0.0.1:%d" % port],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    kids = []
    try:
        for _ in range(100):
            if os.path.exists(sock):
                break
            time.sleep(0.05)
        kids.append(spawn(drawer_main, uri))
        time.sleep(0.5)  # the drawer controls the device
        obs = rdc.open(uri + "?observe")
        reg = rdc.reg_by_name("FRAME_COUNT")
        for n in counts:
            r, w = os.pipe()
            pid = spawn(viewers_main, port, n, w)
            os.close(w)
            ok = os.read(r, 1) == b"1"
            t0 = time.monotonic()
            med, p99, worst = rtt(obs, reg)
            try:
                s, rest = ws_connect(port, 5.0)
                newcomer = first_message(s, rest, 5.0)
                s.close()
            except OSError:
                newcomer = False
            os.kill(pid, signal.SIGTERM)
            got = b""
            while ok and not got.endswith(b"\n"):
                more = os.read(r, 64)
                if not more:
                    break
                got += more
            secs = time.monotonic() - t0
            os.close(r)
            os.waitpid(pid, 0)
            per = int(got or 0) / max(n, 1) / secs if n else 0
            print(json.dumps({"bench": "web_viewers", "viewers": n,
                              "all_in": ok, "rtt_median_us": round(med, 1),
                              "rtt_p99_us": round(p99, 1),
                              "rtt_worst_us": round(worst, 1),
                              "viewer_kib_s": round(per / 1024, 1),
                              "newcomer_in": newcomer}), flush=True)
            time.sleep(0.5)
        obs.close()
    finally:
        for pid in kids:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
        daemon.terminate()
        daemon.wait()


if __name__ == "__main__":
    main()
