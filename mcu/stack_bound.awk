# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# The firmware's worst-case stack depth from GCC's call graphs
# (-fcallgraph-info=su: one .ci file per object, every function's frame
# size and every call it makes):
#
#   awk -v root=rdc_mcu_reset -f stack_bound.awk *.ci
#
# prints "stack ROOT N bytes: f > g > ..." for the deepest chain and exits
# 0, or names the reason there is no bound and exits 1: a frame of
# dynamic size, recursion, or an indirect call not resolved below.
#
# Indirect calls, by the function making them:
#  - the chip's hooks (rdc_trace, rdc_port_poll, rdc_vram_hook_call in
#    hw-sim/hw_priv.h, the frame listener in rdc_crtc_catch_up) call
#    nothing in the firmware, which never sets them (the Makefile checks that rdc_hw_set_trace,
#    rdc_hw_set_poll and rdc_hw_set_frame_fn are not in the image);
#  - hw_run calls the DP's run, rdc_hw_reset its reset (dp.c's ops);
#  - dp_poly_scan calls its span callbacks (poly.c, tri.c).
# A function with no call graph (libgcc's helpers) counts extern_frame
# bytes.
BEGIN {
	extern_frame = 128
	resolve["hw_run"] = "dp_run"
	resolve["rdc_hw_reset"] = "dp_reset"
	resolve["dp_poly_scan"] = "fill_span_cb tri_span"
	resolve["rdc_crtc_catch_up"] = ""
	bad = 0
}

function short(t) {
	sub(/.*:/, "", t)
	return t
}

/^node: / {
	match($0, /title: "[^"]*"/)
	t = substr($0, RSTART + 8, RLENGTH - 9)
	if (t == "__indirect_call")
		next
	names[short(t)] = names[short(t)] " " t
	if (match($0, /\\n[0-9]+ bytes \([^)]*\)/)) {
		s = substr($0, RSTART + 2, RLENGTH - 2)
		split(s, f, " ")
		frame[t] = f[1] + 0
		if (s ~ /\(dynamic\)/) {
			print "stack: " t " has a frame of dynamic size"
			bad = 1
		}
	}
}

/^edge: / {
	match($0, /sourcename: "[^"]*"/)
	src = substr($0, RSTART + 13, RLENGTH - 14)
	match($0, /targetname: "[^"]*"/)
	dst = substr($0, RSTART + 13, RLENGTH - 14)
	match($0, /label: "[^"]*"/)
	site = substr($0, RSTART + 8, RLENGTH - 9)
	if (dst != "__indirect_call") {
		calls[src] = calls[src] " =" dst
		next
	}
	if (site ~ /^hw-sim\/hw_priv\.h:/)
		next
	if (!(short(src) in resolve)) {
		print "stack: indirect call in " src " at " site " not resolved"
		bad = 1
		next
	}
	n = split(resolve[short(src)], to, " ")
	for (i = 1; i <= n; i++)
		calls[src] = calls[src] " ~" to[i]
}

# the nodes a call names: "=title" (direct: the same object's static
# function if there is one, else the global) or "~name" (any with that name)
function targets(src, c, out,    n, i, cand, file) {
	if (substr(c, 1, 1) == "~") {
		n = split(names[substr(c, 2)], cand, " ")
		for (i = 1; i <= n; i++)
			out[i] = cand[i]
		return n
	}
	c = substr(c, 2)
	out[1] = c
	if (c in frame || c ~ /:/)
		return 1
	file = src
	if (sub(/:[^:]*$/, "", file) && ((file ":" c) in frame))
		out[1] = file ":" c
	return 1
}

function depth(t,    n, i, k, m, c, d, best, out, via) {
	if (t in memo)
		return memo[t]
	if (onpath[t]) {
		print "stack: recursion through " t
		bad = 1
		return 0
	}
	onpath[t] = 1
	best = 0
	via = ""
	n = split(calls[t], c, " ")
	for (i = 1; i <= n; i++) {
		delete out
		m = targets(t, c[i], out)
		for (k = 1; k <= m; k++) {
			d = depth(out[k])
			if (d > best) {
				best = d
				via = out[k]
			}
		}
	}
	onpath[t] = 0
	memo[t] = best + (t in frame ? frame[t] : extern_frame)
	next_in[t] = via
	return memo[t]
}

END {
	if (!(root in frame)) {
		print "stack: no function " root
		exit 1
	}
	total = depth(root)
	path = root
	for (t = next_in[root]; t != ""; t = next_in[t])
		path = path " > " short(t)
	if (bad)
		exit 1
	print "stack " root " " total " bytes: " path
}
