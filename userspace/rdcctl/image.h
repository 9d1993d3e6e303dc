/* SPDX-License-Identifier: GPL-2.0-only */
/* SPDX-FileCopyrightText: 2026 The rdc authors */
#ifndef RDCCTL_IMAGE_H
#define RDCCTL_IMAGE_H

/*
 * `rdcctl image encode ...`: returns the exit status, or -1 when argv is
 * not an image command (rdcctl's own parser takes it then).
 */
int rdcctl_image_main(int argc, char **argv);
/* The usage lines of the image command. */
extern const char rdcctl_image_usage[];

#endif
