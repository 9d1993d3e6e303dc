# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""The Python code of the tree is laid out as PEP 8 says (pycodestyle)."""

import glob
import os

import pytest

from rdc_testutil import TOP


def test_pep8():
    pycodestyle = pytest.importorskip(
        "pycodestyle", reason="pycodestyle not installed (Debian: "
        "pycodestyle)")
    files = [f for d in ("python", "tests/python", "examples/python")
             for f in sorted(glob.glob(os.path.join(TOP, d, "**", "*.py"),
                                       recursive=True))]
    assert files
    style = pycodestyle.StyleGuide(quiet=False)
    report = style.check_files(files)
    assert report.total_errors == 0, "pycodestyle: %d problems (above)" % (
        report.total_errors)
