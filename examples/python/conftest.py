# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The rdc fixtures (rdc_sim, rdcd, frame_equal) for `pytest examples/python`
# in the source tree (PYTHONPATH=python); an installed python3-rdc
# registers them with pytest under the same name, and this line then
# changes nothing.
pytest_plugins = ["rdc.pytest_plugin"]
