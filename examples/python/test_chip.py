# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""The RDC-1 tested as a user of the chip would test it, with pytest.

    PYTHONPATH=python pytest examples/python        # from the source tree
    pytest examples/python --rdc-uri unix:/tmp/rdc.sock   # against rdcd

Each test gets a fresh chip from the rdc_sim fixture, in the mode its
rdc_mode marker names (docs/python.md).
"""

import os

import pytest

import rdc

BLACK, WHITE, RED, BLUE = 0x000000, 0xFFFFFF, 0xFF0000, 0x0000FF


def rows(frame):
    """[(first row, colour)] for a frame of uniformly coloured rows."""
    out = []
    for y in range(frame.height):
        row = set(frame.row(y))
        assert len(row) == 1, "row %d is not one colour: %s" % (
            y, sorted(hex(c) for c in row)[:4])
        colour = row.pop()
        if not out or out[-1][1] != colour:
            out.append((y, colour))
    return out


def fill(dev, colour):
    with rdc.Batch() as b:
        dev.submit(b.fg(colour).fill_rect(0, 0, 640, 480))


@pytest.mark.rdc_mode("640x480", "xrgb8888")
def test_line_interrupt_fires_at_programmed_line(rdc_sim):
    dev = rdc_sim
    dev.reg_write(rdc.REG_LINE_COMPARE, 240)
    dev.irq_clear()
    res = dev.wait_irq(rdc.IRQ_LINE)
    assert res.irq & rdc.IRQ_LINE
    assert dev.pins_get() & rdc.PIN_IRQ
    # write one to clear: the pin falls with the status bit
    dev.irq_clear(rdc.IRQ_LINE)
    dev.reg_write(rdc.REG_IRQ_ENABLE, 0)
    assert not dev.reg_read(rdc.REG_IRQ_STATUS) & rdc.IRQ_LINE
    assert not dev.pins_get() & rdc.PIN_IRQ


@pytest.mark.rdc_sim_only
@pytest.mark.rdc_mode("640x480", "xrgb8888")
def test_line_interrupt_cycle_exact(rdc_sim):
    """The IRQ pin rises in the cycle the beam starts line 240: a second
    chip, given the same writes, is on line 239 one cycle before the edge
    with IRQ low, and on line 240 at it with IRQ high."""
    def program(dev):
        dev.reg_write(rdc.REG_LINE_COMPARE, 240)
        dev.irq_clear()
        dev.reg_write(rdc.REG_IRQ_ENABLE, rdc.IRQ_LINE)

    program(rdc_sim)
    edge = rdc_sim.pins_wait_edge(rdc.PIN_IRQ, rdc.EDGE_RISING)
    assert edge.pins == rdc.PIN_IRQ and edge.time is not None

    with rdc.open("sim:") as twin:
        # what rdc_sim did for the rdc_mode marker
        twin.mode_set("640x480", "xrgb8888")
        twin.frame_wait()
        program(twin)
        twin.sim_run_until(edge.time - 1)
        assert twin.sim_time() == edge.time - 1
        assert not twin.pins_get() & rdc.PIN_IRQ
        assert twin.sim_beam()[1] == 239
        twin.sim_run_until(edge.time)
        assert twin.pins_get() & rdc.PIN_IRQ
        assert twin.sim_beam()[1] == 240
        assert twin.reg_read(rdc.REG_IRQ_STATUS) & rdc.IRQ_LINE


@pytest.mark.rdc_mode("640x480", "xrgb8888")
def test_drawing_across_the_beam_tears(rdc_sim):
    dev = rdc_sim
    fill(dev, BLACK)
    dev.finish()
    dev.frame_wait()
    # start a full-screen fill while the beam scans line 200: the lines
    # the beam fetched before the fill reached them stay black in this
    # frame, the rest are white
    start = dev.wait_line(200)
    fill(dev, WHITE)
    done = dev.finish()
    dev.vblank_wait()
    bands = rows(dev.frame_grab())
    assert len(bands) == 2, bands
    (top, top_colour), (tear, bottom_colour) = bands
    assert (top, top_colour, bottom_colour) == (0, BLACK, WHITE)
    if start.line is not None and done.line is not None:
        assert start.line < tear <= done.line
    # the next frame is whole
    dev.vblank_wait()
    assert rows(dev.frame_grab()) == [(0, WHITE)]


@pytest.mark.rdc_mode("640x480", "xrgb8888")
def test_drawing_presented_on_te_does_not_tear(rdc_sim):
    dev = rdc_sim
    fill(dev, WHITE)
    dev.finish()
    dev.frame_wait()
    dev.wait_line(200)
    with rdc.Batch() as b:
        b.fg(RED).fill_rect(0, 0, 640, 480)
        edge = dev.pins_present(b)
    assert edge.levels & rdc.PIN_TE
    dev.finish()
    dev.vblank_wait()
    assert rows(dev.frame_grab()) == [(0, RED)]


@pytest.mark.rdc_mode("640x480", "i8")
def test_clut_raster_split(rdc_sim):
    """One CLUT entry, two colours on screen: the display processor
    rewrites entry 1 at the start of each frame and at line 240."""
    dev = rdc_sim
    with rdc.Batch() as b:
        dev.submit(b.fg(1).fill_rect(0, 0, 640, 480))
    dev.finish()
    with rdc.Batch() as b:
        for _ in range(2):
            b.wait_vblank().load_clut(1, [BLUE])
            b.wait_line(240).load_clut(1, [RED])
        dev.submit(b)
    dev.finish()
    dev.vblank_wait()
    bands = rows(dev.frame_grab())
    assert [c for _, c in bands] == [BLUE, RED], bands
    # the entry changes while line 240 is on screen: that line shows the
    # old colour or the new one, no line above it the new one
    assert bands[1][0] in (240, 241)
    # and the entry keeps the last colour written once the list stops
    dev.reg_write(rdc.REG_CLUT_INDEX, 1)
    assert dev.reg_read(rdc.REG_CLUT_DATA) & 0xFFFFFF == RED


@pytest.mark.rdc_mode("640x480", "xrgb8888")
def test_fifo_low_water_interrupt(rdc_sim):
    dev = rdc_sim
    depth = rdc.FIFO_DEPTH
    low = 16
    dev.reg_write(rdc.REG_FIFO_LOWWATER, low)
    dev.irq_clear()
    dev.reg_write(rdc.REG_IRQ_ENABLE, rdc.IRQ_FIFO_LOW)
    with rdc.Batch() as b:
        for n in range(100):
            b.fg(n * 0x020202).fill_rect(0, 0, 640, 480)
        assert len(b) > depth  # more than the FIFO holds: back-pressure
        dev.submit(b)
    # the FIFO is full or nearly so: no interrupt yet
    assert depth - dev.reg_read(rdc.REG_FIFO_FREE) > low
    assert not dev.reg_read(rdc.REG_IRQ_STATUS) & rdc.IRQ_FIFO_LOW
    res = dev.wait_irq()
    assert res.irq & rdc.IRQ_FIFO_LOW
    assert depth - dev.reg_read(rdc.REG_FIFO_FREE) <= low
    dev.finish()


def golden(name):
    """A golden scene's path and its line in tests/golden/golden.txt:
    (path, crc32, total cycles), or a skip outside the source tree."""
    top = os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))
    if not os.path.exists(os.path.join(top, "tests/golden/golden.txt")):
        pytest.skip("the golden scenes are in rdc's source tree")
    with open(os.path.join(top, "tests/golden/golden.txt")) as f:
        for line in f:
            fields = line.split()
            if fields and fields[0] == name:
                return (os.path.join(top, "tests/golden/scenes",
                                     name + ".rdl"),
                        int(fields[1], 16), int(fields[2]))
    pytest.fail("%s is not in tests/golden/golden.txt" % name)


def test_golden_scene_crc(rdc_sim, frame_equal):
    path, crc, cycles = golden("example_demo")
    res = rdc_sim.script_run_file(path)
    if rdc_sim.uri.startswith("sim"):
        assert rdc_sim.sim_time() == cycles
    rdc_sim.script_frame_wait(res)
    frame_equal(rdc_sim, crc)
