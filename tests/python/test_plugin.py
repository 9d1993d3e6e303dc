# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""The pytest plugin's fixtures, run on test files of their own through
pytest's pytester: what passes, what fails, and what a failure says and
leaves behind."""

import rdc

HEADER = """
import pytest
import rdc


def draw(dev, x, y, colour):
    dev.mode_set("320x200", "xrgb8888")
    with rdc.Batch() as b:
        b.fg(0).fill_rect(0, 0, 320, 200).fg(colour).pixel(x, y)
        dev.submit(b)
    dev.finish()
    dev.frame_wait()
"""


def run(pytester, body, *args):
    pytester.makepyfile(HEADER + body)
    return pytester.runpytest_inprocess("-p", "rdc.pytest_plugin",
                                        "-p", "no:cacheprovider", *args)


def test_rdc_mode_marker_sets_the_mode(pytester):
    res = run(pytester, """
@pytest.mark.rdc_mode("320x200", "i8")
def test_mode(rdc_sim):
    frame = rdc_sim.frame_grab()
    assert (frame.width, frame.height) == (320, 200)
    assert rdc_sim.reg_read(rdc.REG_FB_FORMAT) == rdc.FMT_I8

@pytest.mark.rdc_mode(preset="320x200", format="rgb565", base=0x1000)
def test_mode_keywords(rdc_sim):
    assert rdc_sim.reg_read(rdc.REG_FB_FORMAT) == rdc.FMT_RGB565
    assert rdc_sim.reg_read(rdc.REG_FB_BASE) == 0x1000

def test_fresh_chip_each_time(rdc_sim):
    assert rdc_sim.reg_read(rdc.REG_LINE_COMPARE) != 77
    rdc_sim.reg_write(rdc.REG_LINE_COMPARE, 77)

def test_fresh_chip_each_time_again(rdc_sim):
    assert rdc_sim.reg_read(rdc.REG_LINE_COMPARE) != 77
    rdc_sim.reg_write(rdc.REG_LINE_COMPARE, 77)
""")
    res.assert_outcomes(passed=4)


def test_frame_equal_passes_on_the_same_picture(pytester, tmp_path):
    png = tmp_path / "want.png"
    with rdc.open() as dev:
        dev.mode_set("320x200", "xrgb8888")
        with rdc.Batch() as b:
            b.fg(0).fill_rect(0, 0, 320, 200).fg(0xABCDEF).pixel(17, 9)
            dev.submit(b)
        dev.finish()
        dev.frame_wait()
        frame = dev.frame_grab()
        frame.save_png(png)
        crc = frame.crc()
    res = run(pytester, """
def test_png(rdc_sim, frame_equal):
    draw(rdc_sim, 17, 9, 0xABCDEF)
    assert frame_equal(rdc_sim, %r)

def test_crc(rdc_sim, frame_equal):
    draw(rdc_sim, 17, 9, 0xABCDEF)
    assert frame_equal(rdc_sim.frame_grab(), %d)
""" % (str(png), crc))
    res.assert_outcomes(passed=2)


def test_frame_equal_names_the_first_differing_pixel(pytester, tmp_path):
    art = tmp_path / "art"
    res = run(pytester, """
def test_diff(rdc_sim, frame_equal):
    draw(rdc_sim, 17, 9, 0xABCDEF)
    want = rdc_sim.frame_grab()
    draw(rdc_sim, 17, 9, 0x123456)
    frame = rdc_sim.frame_grab()
    rdc_sim.submit(rdc.Batch().fg(0xFFFFFF).pixel(300, 150))
    rdc_sim.finish()
    frame_equal(frame, want, name="first")
""", "--rdc-artifacts", str(art))
    res.assert_outcomes(failed=1)
    res.stdout.fnmatch_lines([
        "*first differing pixel (17, 9): expected #abcdef, actual #123456;"
        " 1 of 64000 pixels differ*"])
    exp = rdc.png_read(art / "first-expected.png")
    act = rdc.png_read(art / "first-actual.png")
    diff = rdc.png_read(art / "first-diff.png")
    assert exp.pixel(17, 9) == 0xABCDEF and act.pixel(17, 9) == 0x123456
    assert diff.pixel(17, 9) == 0xFF0000
    assert diff.pixel(18, 9) != 0xFF0000 and diff.pixel(0, 0) == 0


def test_frame_equal_against_a_png_and_a_crc_fails(pytester, tmp_path):
    png = tmp_path / "want.png"
    with rdc.open() as dev:
        dev.mode_set("320x200", "xrgb8888")
        dev.frame_wait()
        dev.frame_grab().save_png(png)  # black
    res = run(pytester, """
def test_png(rdc_sim, frame_equal):
    draw(rdc_sim, 5, 6, 0xFF0000)
    frame_equal(rdc_sim, %r)

def test_crc(rdc_sim, frame_equal):
    draw(rdc_sim, 5, 6, 0xFF0000)
    frame_equal(rdc_sim, 0x12345678)

def test_size(rdc_sim, frame_equal):
    rdc_sim.mode_set("640x480")
    rdc_sim.frame_wait()
    frame_equal(rdc_sim, %r)
""" % (str(png), str(png)))
    res.assert_outcomes(failed=3)
    res.stdout.fnmatch_lines([
        "*frame differs from %s: first differing pixel (5, 6): expected "
        "#000000, actual #ff0000*" % png,
        "*frame crc32 *, expected 12345678 (320x200)*",
        "*frame is 640x480, %s 320x200*" % png])


def test_frame_equal_bless_writes_a_missing_png(pytester, tmp_path):
    png = tmp_path / "new.png"
    body = """
def test_new(rdc_sim, frame_equal):
    draw(rdc_sim, 1, 2, 0x00FF00)
    frame_equal(rdc_sim, %r)
""" % str(png)
    res = run(pytester, body)
    res.assert_outcomes(failed=1)
    res.stdout.fnmatch_lines(["*no expected picture*--rdc-bless*"])
    assert not png.exists()
    res = run(pytester, body, "--rdc-bless")
    res.assert_outcomes(passed=1)
    assert rdc.png_read(png).pixel(1, 2) == 0x00FF00
    res = run(pytester, body)
    res.assert_outcomes(passed=1)


def test_rdcd_fixture_serves_a_stepped_chip(pytester):
    res = run(pytester, """
def test_daemon(rdcd):
    with rdcd.open() as dev:
        t = dev.sim_time()
        dev.sim_step(12345)
        assert dev.sim_time() == t + 12345   # stepped: time moves on steps
        draw(dev, 3, 4, 0x0000FF)
        assert dev.frame_grab().pixel(3, 4) == 0x0000FF

def test_sim_only_skipped_on_a_daemon(rdc_sim):
    pass

@pytest.mark.rdc_sim_only
def test_sim_only(rdc_sim):
    pass
""")
    res.assert_outcomes(passed=3)


def test_rdc_uri_points_rdc_sim_at_rdcd(pytester, rdcd):
    res = run(pytester, """
def test_uri(rdc_sim):
    assert rdc_sim.uri.startswith("unix:")
    draw(rdc_sim, 3, 4, 0x0000FF)
    assert rdc_sim.frame_grab().pixel(3, 4) == 0x0000FF

@pytest.mark.rdc_sim_only
def test_sim_only(rdc_sim):
    pass
""", "--rdc-uri", rdcd.uri)
    res.assert_outcomes(passed=1, skipped=1)


def test_rdc_sim_on_a_daemon_is_a_fresh_chip(pytester, rdcd):
    res = run(pytester, """
def test_dirty(rdc_sim):
    rdc_sim.reg_write(rdc.REG_LINE_COMPARE, 77)
    rdc_sim.pins_set(rdc.PIN_BL_EN, 0)

def test_clean(rdc_sim):
    assert rdc_sim.reg_read(rdc.REG_LINE_COMPARE) != 77
    assert rdc_sim.pins_get() & rdc.PINS_IN == rdc.PINS_IN
""", "--rdc-uri", rdcd.uri)
    res.assert_outcomes(passed=2)


def test_frame_compare_without_numpy(monkeypatch):
    """The pure-Python comparison finds what the numpy one finds."""
    from rdc import pytest_plugin as plugin
    with rdc.open() as dev:
        dev.mode_set("320x200", "xrgb8888")
        with rdc.Batch() as b:
            dev.submit(b.fg(0x102030).fill_rect(0, 0, 320, 200))
        dev.finish()
        dev.frame_wait()
        a = dev.frame_grab()
        with rdc.Batch() as b:
            dev.submit(b.fg(0xFFFFFF).pixel(7, 3).pixel(300, 150))
        dev.finish()
        dev.frame_wait()
        b = dev.frame_grab()
    results = []
    for np in ((rdc.numpy, None) if rdc.numpy is not None else (None,)):
        monkeypatch.setattr(rdc, "numpy", np)
        first, count = plugin._first_diff(a, b)
        d = plugin.diff_frame(a, b)
        results.append((first, count, bytes(d)))
        assert (first % 320, first // 320, count) == (7, 3, 2)
        assert d.pixel(7, 3) == d.pixel(300, 150) == 0xFF0000
        assert d.pixel(0, 0) == (0x102030 >> 2) & 0x3F3F3F
    assert all(r == results[0] for r in results)
