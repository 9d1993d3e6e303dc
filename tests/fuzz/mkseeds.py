#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""Write the seed inputs of fuzz_rdcd (tests/fuzz/seeds/rdcd) in the record
format tests/fuzz/fuzz_rdcd.c reads, and the few scripts fuzz_script takes
beside examples/ and tests/golden/scenes/ (seeds/script: the statements
those never use).  Run from the top of the tree when the formats change;
the output is checked in."""
import os
import shutil
import struct

HELLO, REG_READ, REG_WRITE, VRAM_READ, VRAM_WRITE, SUBMIT, WAIT, STEP, \
    FRAME_GRAB, SUBSCRIBE, STATS, RESET, CLAIM, RELEASE, PING, PINS_SET, \
    HIST_OPEN, HIST_READ, HIST_END, HIST_SET = range(1, 21)
HIST_SET_LIMIT, HIST_SET_LINE = 1, 2
REG_STATUS, REG_IRQ_STATUS, REG_IRQ_ENABLE = 0x014, 0x018, 0x01c
REG_FB_FORMAT, REG_MODE_PRESET, REG_FRAME_COUNT = 0x130, 0x140, 0x13c
REG_FB_STRIDE = 0x12c
OP_SET_FG, OP_SET_DST, OP_FILL_RECT, OP_FENCE = 0x10, 0x14, 0x24, 0x01
OP_CALL, OP_JUMP = 0x06, 0x08


def u32(*v):
    return b"".join(struct.pack("<I", x & 0xffffffff) for x in v)


def cmd(op, *args):
    return u32(op << 24 | len(args), *args)


class Seed:
    def __init__(self, mode, vram256=False, token=False):
        self.b = bytearray([mode | (4 if vram256 else 0) | (8 if token else 0)])

    def connect(self, tcp=False):
        self.b.append(0x80 if tcp else 0)

    def hello(self, c, control=False, token=0):
        # token: 0 none, 2 right, 0x82 one byte short
        self.b += bytes([4 | c << 3, (1 if control else 0) | token])

    def msg(self, c, typ, pl=b""):
        assert len(pl) < 2048
        self.b += bytes([3 | c << 3 | (len(pl) >> 8) << 5, typ, len(pl) & 255])
        self.b += pl

    def raw(self, c, data):
        assert len(data) < 2048
        self.b += bytes([2 | c << 3 | (len(data) >> 8) << 5, len(data) & 255])
        self.b += data

    def time(self, units):
        self.b += bytes([5, units - 1])

    def turns(self, n):
        self.b += bytes([6 | (n - 1) << 3])

    def hangup(self, c):
        self.b += bytes([1 | c << 3])

    def drop(self, c):
        self.b += bytes([7 | c << 3])


def wait(budget, needs_dp=0, terms=()):
    t = list(terms) + [(0, 0, 0, 0)] * (2 - len(terms))
    return struct.pack("<QI", budget, needs_dp) + b"".join(u32(*x) for x in t)


def small_mode(s, c):
    s.msg(c, REG_WRITE, u32(REG_FB_FORMAT, 3))  # i8: 320x200 fits 64 KiB
    s.msg(c, REG_WRITE, u32(REG_MODE_PRESET, 0))
    s.msg(c, REG_WRITE, u32(REG_IRQ_ENABLE, 0xffffffff))


def draw(fg=5):
    return (cmd(OP_SET_DST, 0, 320, 200 << 16 | 320, 3) + cmd(OP_SET_FG, fg) +
            cmd(OP_FILL_RECT, 10 << 16 | 10, 40 << 16 | 50) +
            cmd(OP_FENCE, 7))


def seeds():
    out = {}
    for mode, name in ((2, "stepped"), (1, "fast"), (0, "paced")):
        s = Seed(mode)
        s.connect()
        s.hello(0, control=True)
        small_mode(s, 0)
        s.msg(0, SUBSCRIBE, u32(3, 1, 2))  # frames and IRQs, delta
        s.msg(0, SUBMIT, draw())
        s.msg(0, STEP, struct.pack("<Q", 2000000))
        s.time(255)
        s.time(255)
        s.msg(0, WAIT, wait(300000, 1))
        s.msg(0, WAIT, wait(1000000, 0, [(3, REG_FRAME_COUNT, 0xff, 3)]))
        s.time(255)
        s.time(200)
        s.msg(0, FRAME_GRAB, u32(1, 1 << 20))
        s.msg(0, FRAME_GRAB, u32(2, 100))
        s.msg(0, SUBMIT, draw(9))
        s.time(255)
        s.msg(0, STATS)
        s.msg(0, VRAM_WRITE, u32(0x100) + bytes(range(64)))
        s.msg(0, VRAM_READ, u32(0xf0, 96))
        s.msg(0, REG_READ, u32(REG_STATUS))
        s.msg(0, PINS_SET, u32(0, 0))
        s.msg(0, PINS_SET, u32(0xc, 0x4))
        s.msg(0, RESET, u32(0))
        s.msg(0, SUBSCRIBE, u32(1, 2, 1))
        s.time(255)
        s.msg(0, RESET, u32(1))
        s.msg(0, RELEASE)
        s.msg(0, CLAIM)
        s.msg(0, PING)
        out["single-" + name] = s.b

        s = Seed(mode, vram256=True)
        s.connect()
        s.connect()
        s.hello(0, control=True)
        s.hello(1)
        small_mode(s, 0)
        s.msg(1, REG_WRITE, u32(REG_IRQ_STATUS, 1))  # busy
        s.msg(1, SUBSCRIBE, u32(1, 1, 0))
        s.msg(0, SUBSCRIBE, u32(2, 0, 0))
        s.msg(0, SUBMIT, draw())
        s.msg(0, WAIT, wait(0, 1))
        s.time(100)
        s.msg(1, FRAME_GRAB, u32(0, 1 << 22))
        s.time(255)
        s.msg(1, CLAIM)
        s.msg(0, RELEASE)
        s.msg(1, CLAIM)
        s.msg(1, STEP, struct.pack("<Q", 100000))
        s.time(50)
        s.hangup(0)
        s.time(50)
        s.drop(1)
        s.connect()
        s.hello(0, control=True)
        s.turns(4)
        out["two-" + name] = s.b

    # a RESET read one request ahead of a pending STEP, WAIT or SUBMIT
    # (the SUBMIT calls a display list that jumps to itself)
    for mode, name in ((2, "stepped"), (1, "fast"), (0, "paced")):
        s = Seed(mode)
        s.connect()
        s.connect()
        s.hello(0, control=True)
        s.hello(1)
        s.msg(0, STEP, struct.pack("<Q", 900000))
        s.msg(0, RESET, u32(0))
        s.msg(0, WAIT, wait(2000000, 1))
        s.msg(1, PING)
        s.msg(0, RESET, u32(1))
        s.msg(0, VRAM_WRITE, u32(0x8000) + cmd(OP_JUMP, 0x8000))
        s.msg(0, SUBMIT, cmd(OP_CALL, 0x8000) + draw())
        s.msg(1, STATS)
        s.msg(0, RESET, u32(0))
        s.msg(0, SUBMIT, cmd(OP_CALL, 0x8000))
        s.time(10)
        s.msg(0, RESET, u32(1))
        s.time(10)
        out["reset-ahead-" + name] = s.b

    # pixel history: one client's, paged, busy for the other, while the
    # chip draws; bad requests of each kind; a client that leaves with one
    for mode, name in ((2, "stepped"), (1, "fast")):
        s = Seed(mode)
        s.connect()
        s.connect()
        s.hello(0, control=True)
        s.hello(1)
        small_mode(s, 0)
        s.msg(0, REG_WRITE, u32(REG_FB_STRIDE, 320))
        s.msg(1, HIST_OPEN, u32(10, 10, 8, 4, 0))
        s.msg(0, HIST_OPEN, u32(0, 0, 320, 200, 0))  # busy
        s.msg(1, HIST_SET, u32(HIST_SET_LIMIT, 20))
        s.msg(0, SUBMIT, draw())
        s.msg(1, HIST_SET, u32(HIST_SET_LINE, 7))
        s.msg(0, SUBMIT, draw(9))
        s.msg(0, STEP, struct.pack("<Q", 400000))
        s.time(100)
        s.msg(1, HIST_READ, struct.pack("<QI", 0, 0))
        s.msg(1, HIST_READ, struct.pack("<QI", 0, 16))
        s.msg(1, HIST_READ, struct.pack("<QI", 16, 16))
        s.msg(1, HIST_READ, struct.pack("<QI", 1 << 40, 1))  # range
        s.msg(1, HIST_READ, struct.pack("<QI", 0, 0xffffffff))  # range
        s.msg(1, HIST_READ, struct.pack("<Q", 0))  # malformed
        s.msg(1, HIST_SET, u32(HIST_SET_LIMIT, 0))
        s.msg(1, HIST_SET, u32(HIST_SET_LIMIT, 0xffffffff))
        s.msg(1, HIST_SET, u32(9, 1))
        s.msg(0, HIST_READ, struct.pack("<QI", 0, 16))  # not its own
        s.msg(0, HIST_END)
        s.msg(0, RESET, u32(1))  # the history follows the new chip
        s.msg(0, SUBMIT, draw())
        s.msg(0, STEP, struct.pack("<Q", 400000))
        s.time(50)
        s.msg(1, HIST_READ, struct.pack("<QI", 0, 8192))
        s.msg(1, HIST_END)
        s.msg(1, HIST_END)  # none open
        s.msg(0, HIST_OPEN, u32(0, 0, 0, 5, 0))  # empty
        s.msg(0, HIST_OPEN, u32(0, 0, 5, 5, 1))  # write log: not served
        s.msg(0, HIST_OPEN, u32(0, 0, 5, 5, 0x80))
        s.msg(0, HIST_OPEN, u32(0, 0, 5, 5))  # malformed
        s.msg(0, HIST_OPEN, u32(0, 0, 0xffffffff, 0xffffffff, 0))
        s.msg(0, SUBMIT, draw(3))
        s.hangup(0)  # with its history open
        s.time(20)
        s.msg(1, HIST_OPEN, u32(10, 10, 1, 1, 0))
        s.msg(1, PING)
        out["history-" + name] = s.b

    s = Seed(0, token=True)
    for _ in range(4):
        s.connect(tcp=True)
    s.hello(0, token=2, control=True)
    s.hello(1, token=0x82)
    s.hello(2)
    s.raw(3, u32(0x200000, HELLO << 0, 1, 0))  # too big
    s.msg(0, PING)
    s.msg(0, HELLO, u32(0x31434452, 1, 0, 0, 0))  # repeated
    s.turns(2)
    out["token"] = s.b

    s = Seed(1)
    s.connect()
    s.msg(0, PING)  # before HELLO
    hello = u32(20, HELLO, 1, 0) + u32(0x31434452, 1, 0x1f, 1, 0)
    s.raw(0, hello[:7])
    s.turns(1)
    s.raw(0, hello[7:])
    s.msg(0, 99, b"x")
    s.msg(0, REG_READ, u32(1))
    s.msg(0, REG_READ, u32(0x220))
    s.msg(0, WAIT, wait(100, 2))
    s.msg(0, WAIT, wait(100, 0, [(9, 0, 0, 0)]))
    s.msg(0, SUBMIT, b"abc")
    s.msg(0, VRAM_READ, u32(0xfff0, 64))
    s.msg(0, RESET, u32(5))
    s.raw(0, u32(8, STEP, 77, 0) + b"\xff" * 4)  # cut short
    s.hangup(0)
    out["malformed"] = s.b
    return out


SCRIPTS = {
    "host": """mode 320x200 i8
palette 0 #000000 #ff0000 #00ff00
raw 0x10000001 2
cmd 0x24 0x000a000a 0x00100010
step 100000
run-until 3000000
wait-frame
finish
vsync
screenshot fuzz.png
reset
""",
    "lists": """mode 320x200 rgb565
list 0x40000
fill 0 0 10 10
call 0x40100
ret
end
list 0x40100
line 0 0 5 5 \\
  # continued
ret
end
call 0x40000
readback 0 0 4 4
list 0x40200
end
""",
}
# one error each (a script stops at its first)
for i, line in enumerate([
        "list 0x40001", "end", "list 0x40000\nlist 0x40004",
        "list 0x40000\nreadback 0 0 1 1", 'text 1 1 "unterminated',
        "fg #12345", "host-blit 0 0 2 2 data 1 2 3", "step 99999999999",
        "run-until -1", "screenshot", "raw", "list 0x40000\nfill 0 0 1 1"]):
    SCRIPTS["error%02d" % i] = "mode 320x200 xrgb8888\n" + line + "\n"


def main():
    d = "tests/fuzz/seeds/rdcd"
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    for name, b in seeds().items():
        with open(os.path.join(d, name), "wb") as f:
            f.write(b)
    # fuzz_script also reads examples/ and tests/golden/scenes/ (the
    # Makefile names them): here only what those never say
    d = "tests/fuzz/seeds/script"
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    for name, text in SCRIPTS.items():
        with open(os.path.join(d, name + ".rdl"), "w") as f:
            f.write(text)

if __name__ == "__main__":
    main()
