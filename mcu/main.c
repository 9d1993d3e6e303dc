// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The firmware: replays the golden scenes compiled into the image on the
 * RDC-1 model (hw-sim/ and firmware-model/, built for the Cortex-M) and
 * prints one line per scene over semihosting, then the memory figures:
 *   scene NAME vram N ops N total T ... (mcu_format, as host_main prints)
 *   mcu ram hw N dp N frame_cap N stack N of N
 *   scenes N
 */
#include "mcu.h"
#include "scene.h"

#define PSRAM __attribute__((section(".psram")))

static struct mcu_chip chip PSRAM;
static uint8_t vram[MCU_VRAM_CAP] PSRAM __attribute__((aligned(8)));
static uint32_t frame0[MCU_FRAME_CAP] PSRAM;
static uint32_t frame1[MCU_FRAME_CAP] PSRAM;

static char *put_u(char *p, const char *s, uint32_t v)
{
	char d[11];
	uint32_t i = sizeof(d) - 1;

	while (*s)
		*p++ = *s++;
	d[i] = '\0';
	do {
		d[--i] = (char)('0' + v % 10u);
		v /= 10u;
	} while (v);
	for (; d[i]; i++)
		*p++ = d[i];
	*p = '\0';
	return p;
}

int main(void)
{
	char line[MCU_LINE_MAX + 1];
	int bad = 0;
	char *p;

	chip.vram = vram;
	chip.frame[0] = frame0;
	chip.frame[1] = frame1;
	for (uint32_t i = 0; i < mcu_nscenes; i++) {
		struct mcu_result r;
		uint32_t n;

		mcu_replay(&chip, &mcu_scenes[i], &r);
		mcu_format(line, MCU_LINE_MAX, &mcu_scenes[i], &r);
		for (n = 0; line[n]; n++)
			;
		line[n] = '\n';
		line[n + 1] = '\0';
		mcu_puts(line);
		bad |= r.error || r.mismatches;
	}
	p = put_u(line, "mcu ram hw ", (uint32_t)sizeof(chip.hw));
	p = put_u(p, " dp ", (uint32_t)sizeof(chip.dp));
	p = put_u(p, " frame_cap ", MCU_FRAME_CAP);
	p = put_u(p, " stack ", mcu_stack_used());
	p = put_u(p, " of ", mcu_stack_size());
	p = put_u(p, "\nscenes ", mcu_nscenes);
	p[0] = '\n';
	p[1] = '\0';
	mcu_puts(line);
	return bad;
}
