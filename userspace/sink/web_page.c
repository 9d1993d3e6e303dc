// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The web sink's page, web/index.html, web/rdc.js and web/rdc.css, built
 * into the library with the assembler's .incbin (the Makefile makes this
 * object depend on them), so that the server reads no file at a client's
 * request: these three paths are all it can answer.
 */
#include <string.h>

#include "web_proto.h"

#define WEB_INCBIN(name, file) \
	__asm__(".section .rodata\n" \
		".global " #name "_start\n" \
		".hidden " #name "_start\n" \
		".global " #name "_end\n" \
		".hidden " #name "_end\n" #name "_start:\n" \
		".incbin \"" file "\"\n" #name "_end:\n" \
		".previous\n"); \
	extern const uint8_t name##_start[] \
		__attribute__((visibility("hidden"))); \
	extern const uint8_t name##_end[] __attribute__((visibility("hidden")))

WEB_INCBIN(web_index_html, "web/index.html");
WEB_INCBIN(web_rdc_js, "web/rdc.js");
WEB_INCBIN(web_rdc_css, "web/rdc.css");

static const struct {
	const char *path, *type;
	const uint8_t *start, *end;
} web_files[] = {
	{ "/", "text/html; charset=utf-8", web_index_html_start,
	  web_index_html_end },
	{ "/rdc.js", "text/javascript; charset=utf-8", web_rdc_js_start,
	  web_rdc_js_end },
	{ "/rdc.css", "text/css; charset=utf-8", web_rdc_css_start,
	  web_rdc_css_end },
};

bool rdc_web_page_find(const char *path, struct web_file *f)
{
	if (!strcmp(path, "/index.html"))
		path = "/";
	for (size_t i = 0; i < sizeof(web_files) / sizeof(web_files[0]); i++)
		if (!strcmp(path, web_files[i].path)) {
			f->path = web_files[i].path;
			f->type = web_files[i].type;
			f->data = web_files[i].start;
			f->len =
				(size_t)(web_files[i].end - web_files[i].start);
			return true;
		}
	return false;
}
