#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Build rdcdrm.ko against the headers of kernel $1, in $2; print the
# .ko's path.  The top-level Kbuild builds rdcfb.ko and rdcdrm.ko
# together, so this is rdcfb.sh's build with the other module named.
# The harness copies the DRM modules rdcdrm depends on (drm,
# drm_kms_helper, drm_shmem_helper...) into the initramfs from its
# modinfo.
set -e
sh "$(dirname "$0")/rdcfb.sh" "$@" >/dev/null
echo "$2/rdcdrm.ko"
