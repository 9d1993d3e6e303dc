# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""The Python bindings against librdc: errors, handles, registers,
batches, frames, pins, history, traces, VCD, scripts and rdcd."""

import ctypes
import os
import subprocess

import pytest

import rdc
from rdc import _lib
from rdc_testutil import TOP


def draw(dev, colour=0xFF8000):
    dev.mode_set("320x200", "xrgb8888")
    with rdc.Batch() as b:
        b.fg(0x000000).fill_rect(0, 0, 320, 200)
        b.fg(colour).fill_rect(10, 20, 30, 40)
        b.fg(0x00FF00).line(0, 0, 319, 199)
        dev.submit(b)
    dev.finish()
    dev.frame_wait()


# ---- errors and handles ----------------------------------------------------

def test_error_carries_code_and_detail():
    with pytest.raises(rdc.BadURI) as e:
        rdc.open("nonsense:")
    err = e.value
    assert isinstance(err, rdc.Error)
    assert err.code == rdc.E_URI == -4
    assert err.name == "RDC_E_URI"
    assert err.message == rdc.strerror(rdc.E_URI)
    assert "nonsense:" in err.detail
    assert "nonsense:" in str(err)


def test_transport_error_names_the_socket(tmp_path):
    path = str(tmp_path / "none.sock")
    with pytest.raises(rdc.TransportError) as e:
        rdc.open("unix:" + path)
    assert e.value.code == rdc.E_IO and path in e.value.detail


def test_device_error_carries_the_device_code(sim):
    bad = (0xEE << 24)  # an opcode the display processor does not have
    sim.submit([bad])
    with pytest.raises(rdc.DeviceError) as e:
        sim.finish()
    assert e.value.dev_code == rdc.ERR_OPCODE
    assert e.value.dev_name == "OPCODE"
    assert e.value.dev_info == bad
    # reading it cleared it
    assert sim.dev_error()[0] == rdc.ERR_NONE
    sim.finish()


def test_handles_are_context_managers():
    with rdc.open() as dev, rdc.Batch() as b:
        b.nop()
        dev.submit(b)
    assert dev._h is None and b._h is None
    with pytest.raises(ValueError):
        dev.reg_read(rdc.REG_ID)
    with pytest.raises(ValueError):
        b.nop()
    dev.close()  # twice: harmless


def test_script_error_has_line_and_result(sim):
    with pytest.raises(rdc.ParseError) as e:
        sim.script_run("mode 320x200\nfill-rect 0 0 8 8\nno-such-thing 1\n")
    assert e.value.result.error_line == 3
    assert "line 3" in str(e.value)
    res = sim.script_run("no-such-thing\n", check=False)
    assert res.status == rdc.E_PARSE and res.error_line == 1


# ---- constants and registers ------------------------------------------------

def test_constants_agree_with_the_library():
    regs = rdc.reg_names()
    assert regs["LINE_COMPARE"] == rdc.REG_LINE_COMPARE
    assert regs["FIFO_LOWWATER"] == rdc.REG_FIFO_LOWWATER
    for name, off in regs.items():
        assert getattr(rdc, "REG_" + name) == off, name
    assert rdc.preset_by_name("640x480") == rdc.PRESET_640x480_60
    assert rdc.preset_size(rdc.PRESET_1024x768_60) == (1024, 768)
    assert rdc.op_name(rdc.OP_FILL_RECT) == "fill-rect"
    assert rdc.version() == (rdc.VERSION_MAJOR, rdc.VERSION_MINOR,
                             rdc.VERSION_PATCH)
    assert rdc.__version__ == "%d.%d.%d" % rdc.version()


def test_registers_by_name_and_offset(sim):
    assert sim.reg_read("ID") == rdc.ID_VALUE
    sim.reg_write("LINE_COMPARE", 123)
    assert sim.reg_read(rdc.REG_LINE_COMPARE) == 123
    assert sim.reg_read("RDC_REG_LINE_COMPARE") == 123
    with pytest.raises(rdc.InvalidArgument):
        sim.reg_read("NO_SUCH_REGISTER")


def test_struct_layouts_match_c(tmp_path):
    """Every structure the bindings share with librdc has C's offsets."""
    cc = os.environ.get("CC", "cc")
    structs = {"rdc_stats": _lib.Stats, "rdc_pin_edge": _lib.PinEdge,
               "rdc_script_result": _lib.ScriptResult,
               "rdc_event": _lib.Event,
               "rdc_replay_result": _lib.ReplayResult,
               "rdc_history_entry": _lib.HistoryEntry,
               "rdc_history_write": _lib.HistoryWrite,
               "rdc_found": _lib.Found}
    lines = ["#include <stdio.h>", "#include <stddef.h>",
             '#include "rdc.h"', "int main(void)", "{"]
    want = []
    for cname, cls in structs.items():
        lines.append('printf("%s size %%zu\\n", sizeof(struct %s));'
                     % (cname, cname))
        want.append("%s size %d" % (cname, ctypes.sizeof(cls)))
        for field, _ in cls._fields_:
            lines.append('printf("%s %s %%zu\\n", offsetof(struct %s, %s));'
                         % (cname, field, cname, field))
            want.append("%s %s %d" % (cname, field,
                                      getattr(cls, field).offset))
    lines += ["return 0;", "}"]
    src = tmp_path / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp_path / "layout"
    try:
        subprocess.run([cc, "-I" + os.path.join(TOP, "userspace/include"),
                        "-I" + os.path.join(TOP, "hw-sim"), str(src), "-o",
                        str(exe)], check=True)
    except FileNotFoundError:
        pytest.skip("no C compiler (%s) to compare layouts with" % cc)
    got = subprocess.run([str(exe)], check=True, stdout=subprocess.PIPE,
                         universal_newlines=True).stdout.split("\n")[:-1]
    assert got == want


# ---- VRAM, batches, frames --------------------------------------------------

def test_vram_round_trip_without_copies(sim):
    data = bytes(range(256)) * 4
    sim.vram_write(0x1000, data)
    assert sim.vram_read(0x1000, len(data)) == data
    buf = bytearray(16)
    assert sim.vram_read(0x1010, into=buf) is buf
    assert buf == data[16:32]
    sim.vram_write(0x2000, memoryview(bytearray(b"\x01\x02\x03\x04")))
    assert sim.vram_read(0x2000, 4) == b"\x01\x02\x03\x04"


def test_batch_words_are_the_encoders(sim):
    with rdc.Batch() as b:
        b.fg(0x123456).pixel(3, -2)
        hdr_fg = (rdc.OP_SET_FG << 24) | 1
        hdr_px = (rdc.OP_PIXEL << 24) | 1
        assert b.words() == [hdr_fg, 0x123456, hdr_px,
                             (3 & 0xFFFF) | ((-2 & 0xFFFF) << 16)]
        b.reset()
        assert len(b) == 0
        paired = b.polyline([(0, 0), (5, 5), (9, 0)]).words()
        b.reset()
        flat = b.polyline([0, 0, 5, 5, 9, 0]).words()
        assert paired == flat
        assert flat[0] == (rdc.OP_POLYLINE << 24) | 3
        b.text(0, 0, "A")
        words = b.words()
    sim.mode_set("320x200")
    sim.submit(words)
    sim.finish()


def test_frame_is_the_crc_librdc_computes(sim):
    draw(sim)
    frame = sim.frame_grab()
    assert (frame.width, frame.height) == (320, 200)
    assert frame.crc() == sim.frame_crc()
    assert frame.pixel(10, 20) == 0xFF8000
    assert frame.pixel(9, 20) == 0x000000
    assert frame.pixel(0, 0) == 0x00FF00
    assert bytes(frame)[:4] == b"\x00\xff\x00\x00"  # B, G, R, X
    # grabbing again into the same buffer: no new one
    again = sim.frame_grab(into=frame.data)
    assert again.data is frame.data and again == frame


def test_frame_as_numpy_shares_memory(sim):
    np = pytest.importorskip("numpy")
    draw(sim)
    frame = sim.frame_grab()
    a = frame.array()
    assert a.shape == (200, 320) and a.dtype == np.dtype("<u4")
    assert np.shares_memory(a, np.frombuffer(frame.data, dtype=np.uint8))
    assert a[20, 10] & 0xFFFFFF == 0xFF8000
    assert tuple(frame.rgb()[20, 10]) == (0xFF, 0x80, 0x00)
    # straight into a numpy array
    out = np.zeros((200, 320), dtype=np.uint32)
    f2 = sim.frame_grab(into=out)
    assert f2.data is out and (out == a).all()
    assert f2 == frame and f2.crc() == frame.crc()
    assert f2.pixel(10, 20) == 0xFF8000 and f2.row(20) == frame.row(20)


def test_readback_equals_the_frame(sim):
    draw(sim)
    frame = sim.frame_grab()
    data = sim.readback(8, 18, 6, 4)
    words = memoryview(bytes(data)).cast("I")
    for y in range(4):
        for x in range(6):
            assert words[y * 6 + x] & 0xFFFFFF == frame.pixel(8 + x, 18 + y)


SCENE = """mode 320x200 xrgb8888
fg #000000
fill-rect 0 0 320 200
fg #ff8000
fill-rect 10 20 30 40
fg #00ff00
line 0 0 319 199
text 100 100 "rdc"
fill-polygon 200 10 260 60 180 70
"""


def test_batches_draw_what_the_script_draws(sim, rdcctl, tmp_path,
                                            frame_equal):
    """The same drawing through Batch and through an .rdl script that
    `rdcctl run -o` renders from C: frame_equal against its PNG."""
    (tmp_path / "s.rdl").write_text(SCENE)
    png = tmp_path / "s.png"
    subprocess.run([rdcctl, "run", str(tmp_path / "s.rdl"), "-o",
                    str(png)], check=True, stdout=subprocess.DEVNULL)
    draw(sim)
    with rdc.Batch() as b:
        b.text(100, 100, "rdc").fill_polygon([(200, 10), (260, 60),
                                              (180, 70)])
        sim.submit(b)
    sim.finish()
    sim.frame_wait()
    assert frame_equal(sim, png)


def test_png_round_trip(sim, tmp_path):
    draw(sim)
    frame = sim.frame_grab()
    frame.save_png(tmp_path / "f.png")
    back = rdc.png_read(tmp_path / "f.png")
    assert (back.width, back.height) == (320, 200)
    for x, y in ((0, 0), (10, 20), (319, 199), (100, 100)):
        assert back.pixel(x, y) == frame.pixel(x, y)


def test_image_encode_decode_round_trip(sim):
    """A frame's samples, encoded on the host (rdc_image_encode), decoded
    back by the display processor (DECODE): the same frame."""
    draw(sim)
    want = sim.frame_grab()
    samples = rdc.image_samples(want, 3)
    assert samples[(20 * 320 + 10) * 3:(20 * 320 + 10) * 3 + 3] == \
        b"\xff\x80\x00"
    stream = rdc.image_encode(rdc.IMG_RLE, samples, 320, 200, 3)
    assert int.from_bytes(stream[:4], "little") == rdc.IMG_MAGIC
    assert len(stream) < len(samples)  # a picture of flat areas
    addr = 0x100000
    sim.vram_write(addr, stream)
    with rdc.Batch() as b:
        b.fg(0).fill_rect(0, 0, 320, 200)
        b.cmd(rdc.OP_DECODE, 0, [addr, len(stream), 0])
        sim.submit(b)
    sim.finish()
    sim.frame_wait()
    assert sim.frame_grab() == want


def test_host_blit(sim):
    sim.mode_set("320x200", "xrgb8888")
    sim.finish()
    px = (0x00112233).to_bytes(4, "little") * 16
    sim.host_blit(5, 6, 4, 4, px, 16)
    sim.finish()
    sim.frame_wait()
    frame = sim.frame_grab()
    assert frame.pixel(5, 6) == 0x112233 and frame.pixel(8, 9) == 0x112233
    assert frame.pixel(9, 9) != 0x112233


def test_mono_with_its_colours(sim):
    sim.mode_set("320x200", "xrgb8888")
    glyph = bytes([0x80, 0x01])  # 8x2: top-left and bottom-right set
    with rdc.Batch() as b:
        b.fg(0x111111).bg(0x222222)
        b.mono(4, 4, 8, 2, glyph, fg=0x00AA00, bg=0x0000BB)
        words = b.words()
        assert words[4] >> 24 == rdc.OP_MONO
        assert (words[4] >> 16) & 0xFF == rdc.MONO_COLORS
        assert words[7:9] == [0x00AA00, 0x0000BB]
        # the colours stay: a plain mono after it draws with them
        b.mono(20, 4, 8, 2, glyph)
        sim.submit(b.words())
    with pytest.raises(ValueError):
        rdc.Batch().mono(0, 0, 8, 1, b"\x00", fg=1)
    sim.finish()
    sim.frame_wait()
    f = sim.frame_grab()
    for x0 in (4, 20):
        assert f.pixel(x0, 4) == 0x00AA00 and f.pixel(x0 + 7, 5) == 0x00AA00
        assert f.pixel(x0 + 1, 4) == 0x0000BB and f.pixel(x0, 5) == 0x0000BB


def test_fg_next_is_carried_by_the_line(sim):
    sim.mode_set("320x200", "xrgb8888")
    with rdc.Batch() as b:
        b.fg_next(0x00C0FFEE).line(2, 3, 40, 3)
        words = b.words()
        assert len(words) == 4
        assert words[0] >> 24 == rdc.OP_LINE
        assert (words[0] >> 16) & 0xFF == rdc.DRAW_FG
        assert words[1] == 0x00C0FFEE
        sim.submit(words)
    sim.finish()
    sim.frame_wait()
    f = sim.frame_grab()
    assert f.pixel(2, 3) == 0xC0FFEE and f.pixel(40, 3) == 0xC0FFEE
    assert f.pixel(41, 3) != 0xC0FFEE


# ---- waits, pins, simulation ------------------------------------------------

def test_waits_report_time_and_beam(sim):
    sim.mode_set("640x480")
    t0 = sim.vblank_wait().time
    res = sim.wait_line(100)
    assert res.line == 100 and res.time > t0
    res = sim.vblank_wait()
    # in vertical blanking (the wait returns within a wait slice of it)
    assert res.line >= 480
    assert sim.reg_read(rdc.REG_STATUS) & rdc.STATUS_VBLANK
    with rdc.Batch() as b:
        sim.submit(b.fence(0x1234))
    res = sim.fence_wait(0x1234)
    assert sim.reg_read(rdc.REG_FENCE) == 0x1234
    assert sim.idle_wait().time >= res.time


def test_pins(sim):
    draw(sim, 0xFFFFFF)
    assert sim.pins_get() & rdc.PINS_IN == rdc.PINS_IN  # inputs start high
    sim.pins_set(rdc.PIN_BL_EN, 0)
    assert not sim.pins_get() & rdc.PIN_BL_EN
    sim.frame_wait()
    dark = sim.frame_grab()
    assert dark.crc() == rdc.crc32(bytes(len(dark) * 4))  # black
    sim.pins_set(rdc.PIN_BL_EN, rdc.PIN_BL_EN)
    sim.frame_wait()
    assert sim.frame_grab().pixel(10, 20) == 0xFFFFFF
    with pytest.raises(rdc.InvalidArgument):
        sim.pins_set(rdc.PIN_TE, 0)  # an output
    e1 = sim.pins_wait_edge(rdc.PIN_TE, rdc.EDGE_RISING)
    e2 = sim.pins_wait_edge(rdc.PIN_TE, rdc.EDGE_FALLING)
    assert e1.pins == e2.pins == rdc.PIN_TE
    assert e1.levels & rdc.PIN_TE and not e2.levels & rdc.PIN_TE
    assert e1.time < e2.time <= sim.sim_time()


def test_sim_step_and_stats(sim):
    t = sim.sim_time()
    sim.sim_step(1000)
    assert sim.sim_time() >= t + 1000
    sim.sim_run_until(t + 5000)
    assert sim.sim_time() >= t + 5000
    draw(sim)
    st = sim.stats()
    assert st.cmds > 0 and st.pixels >= 320 * 200 and st.busy > 0
    assert sim.sim_core_hz() == sim.reg_read("CORE_KHZ") * 1000


# ---- history, traces, waveforms ---------------------------------------------

def test_pixel_history(sim):
    sim.mode_set("320x200", "xrgb8888")
    sim.vblank_wait()
    with sim.history_open(10, 20, 2, 2) as hist:
        draw(sim)
        entries = hist.at(10, 20)
        assert [e.op for e in entries][-1] == "fill-rect"
        last = entries[-1]
        assert last.after & 0xFFFFFF == 0xFF8000 and last.fg == 0xFF8000
        assert all(0 <= e.x - 10 < 2 and 0 <= e.y - 20 < 2 for e in hist)
        assert hist.dropped == 0


def test_history_writes_and_where_two_runs_part():
    def run(colour):
        dev = rdc.open()
        dev.mode_set("320x200", "xrgb8888")
        dev.vblank_wait()
        hist = dev.history_open(flags=rdc.HISTORY_WRITES)
        with rdc.Batch() as b:
            b.fg(0x0000FF).fill_rect(0, 0, 50, 50)
            b.fg(colour).fill_rect(100, 100, 20, 20)
            dev.submit(b)
        dev.finish()
        return dev, hist

    runs = [run(0xFF0000), run(0xFF0000), run(0x00FF00)]
    try:
        (_, a), (_, same), (_, other) = runs
        writes = a.writes()
        assert writes and writes[0].entry.op == "fill-rect"
        assert a.first_diff(same) is None
        part = a.first_diff(other)
        assert part is not None and part > 0
        # the blue square is drawn alike; the part is in the second fill
        assert writes[part].entry.fg == 0xFF0000
        assert other.writes()[part].entry.fg == 0x00FF00
    finally:
        for dev, hist in runs:
            hist.close()
            dev.close()


def test_record_and_replay(sim, tmp_path):
    trace = tmp_path / "t.trace"
    with sim.record_start(trace):
        draw(sim)
        crc = sim.frame_crc()
        t = sim.sim_time()
    res = rdc.replay_file(trace, keep_device=True)
    with res.device as dev:
        assert res.mismatches == 0 and not res.truncated
        assert res.frame_crc == crc
        assert dev.frame_crc() == crc and dev.sim_time() >= t
    hist, res2 = rdc.replay_history(trace, 10, 20, 1, 1)
    with hist:
        assert res2.frame_crc == crc
        assert hist[-1].after & 0xFFFFFF == 0xFF8000


def test_vcd_closed_with_its_device(tmp_path):
    path = tmp_path / "w.vcd"
    dev = rdc.open()
    vcd = dev.vcd_open(path)
    dev.mode_set("320x200")
    dev.frame_wait()
    dev.close()  # the dump first, then the device
    assert vcd._h is None
    assert "$enddefinitions" in path.read_text()


def test_vcd(sim, tmp_path):
    path = tmp_path / "w.vcd"
    with sim.vcd_open(path):
        sim.mode_set("320x200")
        sim.frame_wait()
    text = path.read_text()
    assert "$enddefinitions" in text
    assert " te " in text and " irq " in text
    assert len([ln for ln in text.splitlines() if ln.startswith("#")]) > 2


# ---- through rdcd -----------------------------------------------------------

def test_rdcd_draws_what_sim_draws(sim, rdcd):
    draw(sim)
    want = sim.frame_crc()
    with rdcd.open() as dev:
        draw(dev)
        assert dev.frame_crc() == want
        assert dev.frame_grab().crc() == want
        with rdcd.open(observe=True) as obs:
            with pytest.raises(rdc.Busy):
                obs.pins_set(rdc.PIN_BL_EN, 0)


def test_rdcd_irq_events(rdcd):
    with rdcd.open() as dev, rdcd.open(observe=True) as obs:
        obs.subscribe(rdc.EVENT_IRQ)
        dev.mode_set("320x200")
        dev.reg_write(rdc.REG_IRQ_ENABLE, rdc.IRQ_VBLANK)
        dev.vblank_wait()
        dev.vblank_wait()
        ev = obs.event_next(timeout_ms=10000)
        assert ev.type == rdc.EVENT_IRQ and ev.irq & rdc.IRQ_VBLANK


def test_rdcd_frame_events(rdcd):
    with rdcd.open() as dev, rdcd.open(observe=True) as obs:
        draw(dev)
        want = dev.frame_grab()
        obs.subscribe(rdc.EVENT_FRAME, 1, rdc.FRAME_RLE)
        buf = bytearray(320 * 200 * 4)
        for _ in range(3):
            dev.vblank_wait()
        ev = obs.event_next(timeout_ms=10000, into=buf)
        assert ev.type == rdc.EVENT_FRAME
        assert ev.frame.data is buf  # decoded straight into it
        assert ev.frame == want


@pytest.mark.rdcd_args("--listen", "tcp:127.0.0.1:0")
def test_rdcd_over_tcp(sim, rdcd):
    tcp = [u for u in rdcd.uris if u.startswith("tcp:")]
    assert len(tcp) == 1 and rdcd.uri in rdcd.uris
    draw(sim)
    with rdc.open(tcp[0]) as dev:
        draw(dev)
        assert dev.frame_crc() == sim.frame_crc()
