# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""Every golden scene through the bindings gives what the C API gives:
the same CRC-32, total cycles, frame size and cycles per command class
from Python (rdc_script_run_file through ctypes) as from `rdcctl run`."""

import glob
import os
import re
import subprocess

import pytest

import rdc
from rdc_testutil import TOP

SCENES = sorted(glob.glob(os.path.join(TOP, "tests/golden/scenes/*.rdl")))


def rdcctl_run(rdcctl, scene, cwd):
    out = subprocess.run([rdcctl, "run", scene], cwd=cwd, check=True,
                         stdout=subprocess.PIPE, universal_newlines=True)
    res = {"classes": {}}
    in_table = False
    for line in out.stdout.splitlines():
        f = line.split()
        if f[:3] == ["class", "commands", "cycles"]:
            in_table = True
        elif f[0] == "total":
            in_table = False
            res["total"] = int(f[1])
        elif f[0] == "frame":
            res["size"] = tuple(int(v) for v in f[1].split("x"))
        elif f[0] == "crc32":
            res["crc"] = int(f[1], 16)
        elif f[:2] == ["readback", "crc32"]:
            res["readback"] = (int(f[2], 16),
                               int(re.sub(r"\D", "", f[3])))
        elif in_table:
            res["classes"][f[0]] = (int(f[1]), int(f[2]))
    assert {"total", "size", "crc"} <= set(res), out.stdout
    return res


def test_scenes_found():
    assert len(SCENES) > 10


@pytest.mark.parametrize("scene", SCENES, ids=lambda p: os.path.basename(
    p)[:-len(".rdl")])
def test_golden_scene_as_rdcctl(scene, rdcctl, tmp_path, monkeypatch):
    (tmp_path / "c").mkdir()
    (tmp_path / "py").mkdir()
    want = rdcctl_run(rdcctl, scene, tmp_path / "c")
    monkeypatch.chdir(tmp_path / "py")  # where `screenshot` writes
    with rdc.open("sim:") as dev:
        res = dev.script_run_file(scene)
        total = dev.sim_time()
        dev.script_frame_wait(res)
        frame = dev.frame_grab()
        crc = dev.frame_crc()
    classes = {name: (res.counts[name], res.cycles[name])
               for name in res.counts}
    assert crc == want["crc"]
    assert total == want["total"]
    assert (frame.width, frame.height) == want["size"]
    assert classes == want["classes"]
    # the bytes librdc wrote into Python's buffer are the frame it hashed
    assert frame.crc() == crc
    if "readback" in want:
        assert (res.readback_crc, res.readback_words) == want["readback"]
