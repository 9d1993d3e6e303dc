# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
"""Where `make install` puts the rdc Python package for PREFIX:
    python3 scripts/python-sitedir.py PREFIX

Debian's python3 reads /usr/lib/python3/dist-packages (the packages' own,
the "deb_system" scheme) and /usr/local/lib/python3.X/dist-packages (what
is installed by hand, "posix_local"); sysconfig's default scheme names
neither for a PREFIX given as base.  Any other PREFIX gets the upstream
layout, PREFIX/lib/python3.X/site-packages, which PYTHONPATH must name.
"""
import sys
import sysconfig

prefix = sys.argv[1].rstrip("/") if len(sys.argv) > 1 else "/usr/local"
schemes = sysconfig.get_scheme_names()
if prefix == "/usr" and "deb_system" in schemes:
    path = sysconfig.get_path("purelib", "deb_system", vars={"base": "/usr"})
elif prefix == "/usr/local" and "posix_local" in schemes:
    path = sysconfig.get_path("purelib", "posix_local", vars={"base": "/usr"})
else:
    path = sysconfig.get_path("purelib", "posix_prefix",
                              vars={"base": prefix})
print(path)
