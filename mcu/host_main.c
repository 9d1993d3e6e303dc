// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The firmware's twin on the host: the same scenes (mcu_scenes.c) and the
 * same replay (replay.c), built with the normal compiler and flags, print
 * the lines the firmware prints, for the test to compare (mcu/check.sh).
 */
#include <stdio.h>
#include <stdlib.h>

#include "scene.h"

int main(void)
{
	struct mcu_chip *c = calloc(1, sizeof(*c));
	char line[MCU_LINE_MAX];
	int bad = 0;

	if (c) {
		c->vram = malloc(MCU_VRAM_CAP);
		c->frame[0] = malloc(MCU_FRAME_CAP * sizeof(uint32_t));
		c->frame[1] = malloc(MCU_FRAME_CAP * sizeof(uint32_t));
	}
	if (!c || !c->vram || !c->frame[0] || !c->frame[1]) {
		fprintf(stderr, "mcu-host: out of memory\n");
		return 1;
	}
	for (uint32_t i = 0; i < mcu_nscenes; i++) {
		struct mcu_result r;

		mcu_replay(c, &mcu_scenes[i], &r);
		mcu_format(line, sizeof(line), &mcu_scenes[i], &r);
		printf("%s\n", line);
		bad |= r.error || r.mismatches;
	}
	printf("scenes %u\n", mcu_nscenes);
	free(c->vram);
	free(c->frame[0]);
	free(c->frame[1]);
	free(c);
	return bad;
}
