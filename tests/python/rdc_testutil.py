# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# What the tests of the Python bindings share: the source tree and the
# build's programs.
import os
import shutil

import pytest

TOP = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


def tool(name):
    """The build's rdcctl or rdcd: $RDC_RDCCTL / $RDC_RDCD, else
    build/rel/NAME, else PATH; a skip if there is none."""
    exe = os.environ.get("RDC_" + name.upper())
    if not exe:
        exe = os.path.join(TOP, "build/rel", name)
        if not os.access(exe, os.X_OK):
            exe = shutil.which(name)
    if not exe:
        pytest.skip("%s not found (make, or $RDC_%s)" % (name, name.upper()))
    return exe
