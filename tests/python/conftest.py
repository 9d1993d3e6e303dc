# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Fixtures of the tests of the Python bindings and the pytest plugin
# (tests/python/run.sh runs them).
import pytest

import rdc
from rdc_testutil import tool

pytest_plugins = ["pytester", "rdc.pytest_plugin"]


@pytest.fixture
def rdcctl():
    return tool("rdcctl")


@pytest.fixture
def sim():
    with rdc.open("sim:") as dev:
        yield dev
